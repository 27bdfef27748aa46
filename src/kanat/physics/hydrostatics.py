"""Hydrostatic restoring of a 6-DOF body from its actual tilt (docs/theory/moorings.md eq. M17a).

A body with a hydrostatic stiffness ``C`` (6, 6; body axes, about its reference point) is
restored towards its given position ``r_0`` and orientation ``R_0`` (``R = Rz(yaw) Ry(pitch)
Rx(roll)``) by::

    (1)  [F; M] = -[H (C dxi)_t; R (C dxi)_r],   H = Rz(yaw)
    (2)  dxi = (H^T dr, k x k_0 + (yaw - yaw_0) k_0),   k = R^T e_z,   k_0 = R_0^T e_z

with ``dr = r - r_0`` (less the wave surface's height for a surface-piercing body). ``k x k_0``
is the tilt from the reference in body axes, of length the sine of the angle between the body's
vertical and the reference's: an axisymmetric body with ``C44 = C55 = B GM`` about a level
reference feels ``M = B GM (z_b x e_z)``, ``|M| = B GM sin(tilt)``, about the tilt axis whatever
its yaw; heave and surge act in the heading frame ``H`` (buoyancy stays vertical, so a pitched
body moved sideways feels no heave). Raw Euler-angle differences ``C (Theta - Theta_0)`` would
put a yawed body's roll restoring about the wrong axis (reversed at 180 deg).

:func:`restoring_displacement` (eq. 2) is the one form of ``dxi``: the lumped model's kernels
call it (:mod:`kanat.lumped.rigid`), and network statics through :func:`restoring_load`, which
adds eq. (1) and its derivatives with respect to the position and the Euler angles in plain
Python (its Python function, ``restoring_displacement.py_func``: statics loads no numba).
"""
from __future__ import annotations

import math

import numpy as np

from kanat.jit import inner

__all__ = ["restoring_displacement", "restoring_load"]


@inner
def restoring_displacement(R, R0, dr, yaw, yaw0, d):
    """``dxi`` (6,) of module eq. (2) into ``d``.

    Parameters
    ----------
    R, R0 : ndarray, shape (3, 3)
        The body's rotation and its reference's (body axes to global).
    dr : ndarray, shape (3,)
        Displacement of the reference point from ``r_0``, global axes [m].
    yaw, yaw0 : float
        The body's yaw and its reference's [rad].
    d : ndarray, shape (6,)
        Out: the displacement in the heading frame [m], then the tilt ``k x k_0`` and the yaw
        change along ``k_0``, body axes [rad].
    """
    cy, sy = math.cos(yaw), math.sin(yaw)
    d[0], d[1], d[2] = cy * dr[0] + sy * dr[1], -sy * dr[0] + cy * dr[1], dr[2]
    k0, k1, k2 = R[2, 0], R[2, 1], R[2, 2]                  # k = R^T e_z: the vertical in body axes
    q0, q1, q2 = R0[2, 0], R0[2, 1], R0[2, 2]               # k_0, the same at the reference
    turn_about = yaw - yaw0
    d[3] = k1 * q2 - k2 * q1 + q0 * turn_about
    d[4] = k2 * q0 - k0 * q2 + q1 * turn_about
    d[5] = k0 * q1 - k1 * q0 + q2 * turn_about


def restoring_load(stiffness, R, dR, R0, dr, yaw, yaw0) -> tuple[np.ndarray, np.ndarray]:
    """The restoring force and moment of module eq. (1) and their derivatives.

    Parameters
    ----------
    stiffness : ndarray, shape (6, 6)
        ``C`` in body axes about the reference point [N/m, N m/rad].
    R : ndarray, shape (3, 3)
        The body's rotation.
    dR : sequence of 3 ndarrays, shape (3, 3)
        ``dR/droll``, ``dR/dpitch``, ``dR/dyaw``.
    R0, dr, yaw, yaw0
        As :func:`restoring_displacement`.

    Returns
    -------
    load : ndarray, shape (6,)
        Force [N] and moment about the reference point [N m], global axes.
    jacobian : ndarray, shape (6, 6)
        ``d load / d(r, roll, pitch, yaw)``.
    """
    C = np.asarray(stiffness, dtype=float)
    d = np.empty(6)
    restoring_displacement.py_func(R, R0, np.asarray(dr, dtype=float), yaw, yaw0, d)
    cy, sy = math.cos(yaw), math.sin(yaw)
    H = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    dH = np.array([[-sy, -cy, 0.0], [cy, -sy, 0.0], [0.0, 0.0, 0.0]])
    k0 = R0[2]
    D = np.zeros((6, 6))                                    # d dxi / d(r, roll, pitch, yaw)
    D[:3, :3] = H.T
    D[:3, 5] = dH.T @ dr
    for j in range(3):
        D[3:, 3 + j] = np.cross(dR[j][2], k0)               # d k / d angle_j = (dR_j)^T e_z
    D[3:, 5] += k0
    body, d_body = -C @ d, -C @ D                           # the load in body axes and its derivative
    jacobian = np.vstack([H @ d_body[:3], R @ d_body[3:]])
    jacobian[:3, 5] += dH @ body[:3]                        # the heading frame and the body turn too
    for j in range(3):
        jacobian[3:, 3 + j] += dR[j] @ body[3:]
    return np.concatenate([H @ body[:3], R @ body[3:]]), jacobian
