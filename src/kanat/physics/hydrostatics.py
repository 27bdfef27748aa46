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

Weight ``W`` at the centre of gravity ``c`` and buoyancy ``B`` at the centre of buoyancy ``b``
(body axes) turn with the body; a metacentric height holds their levers along the body's vertical
at the reference, ``k_0``, so with ``h = 1`` when ``C`` restores the tilt (0 otherwise)::

    (3)  M_WB = (R m) x (-e_z),   m = W (c - h (c . k_0) k_0) - B (b - h (b . k_0) k_0)

:func:`weight_buoyancy_moment`, shared by both models. Without tilt restoring in ``C`` (no
hydrostatics, or a heave spring only: MoorPy's ``AWP`` body) eq. (3) is the moment of the turning
weight and buoyancy, which restores a body whose centre of buoyancy is above its centre of
gravity. With it (``metacentric_heights``: ``C44 = B GM``, and ``GM`` is the distance from the
centre of gravity to the metacentre, the vertical levers of weight and buoyancy included), only
the centres' offsets across ``k_0`` act: at the reference attitude they give the moment of the
weight and buoyancy there (the trim moment of a centre of gravity off the axis, as the net
buoyancy is the heave force there), and they turn with the body, so the moment follows its
heading. For a level reference and ``C44 = C55`` eqs. (1) + (3) are MoorPy's body with its
buoyancy at the metacentre ``r_M = (b_x, b_y, (C44 + W c_z) / B)``: ``(R r_c) x (-W e_z) + (R r_M)
x (B e_z)`` exactly, at any tilt.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.jit import inner

__all__ = ["restoring_displacement", "restoring_load", "weight_buoyancy_moment", "weight_buoyancy_load"]


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


@inner
def weight_buoyancy_moment(R, k0, cog, cob, weight, buoyancy, held, out):
    """Add the moment of module eq. (3) about the reference point (global axes) to ``out`` (3,).

    The moment is linear in ``R``: given ``dR/dangle`` for ``R`` it adds the moment's derivative.

    Parameters
    ----------
    R : ndarray, shape (3, 3)
        The body's rotation (body axes to global), or its derivative.
    k0 : ndarray, shape (3,)
        The vertical in body axes at the reference attitude, ``R_0^T e_z``.
    cog, cob : ndarray, shape (3,)
        Centres of gravity and buoyancy in body axes from the reference point [m].
    weight, buoyancy : float
        ``W = m g`` and ``B`` [N].
    held : float
        ``h``: 1 when the hydrostatic stiffness restores roll or pitch (it holds the centres'
        levers along ``k0``), 0 otherwise.
    out : ndarray, shape (3,)
    """
    along_g = held * (cog[0] * k0[0] + cog[1] * k0[1] + cog[2] * k0[2])
    along_b = held * (cob[0] * k0[0] + cob[1] * k0[1] + cob[2] * k0[2])
    m0 = weight * (cog[0] - along_g * k0[0]) - buoyancy * (cob[0] - along_b * k0[0])
    m1 = weight * (cog[1] - along_g * k0[1]) - buoyancy * (cob[1] - along_b * k0[1])
    m2 = weight * (cog[2] - along_g * k0[2]) - buoyancy * (cob[2] - along_b * k0[2])
    p0 = R[0, 0] * m0 + R[0, 1] * m1 + R[0, 2] * m2
    p1 = R[1, 0] * m0 + R[1, 1] * m1 + R[1, 2] * m2
    out[0] -= p1                                            # (R m) x (-e_z) = (-p_y, p_x, 0)
    out[1] += p0


def weight_buoyancy_load(R, dR, k0, cog, cob, weight, buoyancy, held) -> tuple[np.ndarray, np.ndarray]:
    """The moment of module eq. (3) and its derivative with respect to roll, pitch, yaw (3, 3).

    Parameters as :func:`weight_buoyancy_moment`; ``dR`` the three ``dR/dangle`` (3, 3).
    """
    args = (np.asarray(k0, dtype=float), np.asarray(cog, dtype=float), np.asarray(cob, dtype=float),
            float(weight), float(buoyancy), float(held))
    moment, jacobian = np.zeros(3), np.zeros((3, 3))
    weight_buoyancy_moment.py_func(R, *args, moment)
    for j in range(3):
        column = np.zeros(3)
        weight_buoyancy_moment.py_func(dR[j], *args, column)
        jacobian[:, j] = column
    return moment, jacobian
