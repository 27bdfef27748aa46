"""6-DOF bodies in the linearised system (:mod:`kanat.frequency.linearize`).

A 6-DOF body's generalized coordinates are its reference point ``r`` and Euler angles ``Theta``
(:mod:`kanat.lumped.rigid`), whose rows of the time domain's forces hold the force and the moment
about ``r`` (global axes) of module eq. (2) there, solved with the 6 x 6 mass
``M6 = T (M_rb + A) T^T + sum_f J_f^T M_f J_f`` (``J_f = [I, -S(p_f)]``, ``p_f`` a fairlead's arm,
``M_f`` the lumped mass block of the line node riding on it). With ``w = E(Theta) Theta_dot``,
the generalized force of the Euler angles is ``E^T`` times the moment (virtual work
``M . E dTheta``), so their rows of ``K`` and ``C`` are ``E^T`` times the moment's Jacobian (the
term ``dE^T/dTheta M`` vanishes with the moment at the equilibrium), and the body's mass block
is::

    (1)  M_b = G^T M6 G,   G = diag(I, E),
         E = [[cos(pitch) cos(yaw), -sin(yaw), 0], [cos(pitch) sin(yaw), cos(yaw), 0], [-sin(pitch), 0, 1]]

(:func:`kanat.physics.motion.angular_velocity`). The angles' velocity-dependent terms of eq. (2)
there (``w x (I w)``, ``E_dot Theta_dot``) are of second order and vanish at rest.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from kanat.physics.motion import point_jacobian, rotation_matrix


def euler_rates_matrix(angles) -> np.ndarray:
    """``E`` (3, 3) of eq. (1): ``w = E Theta_dot`` for ``R = Rz(yaw) Ry(pitch) Rx(roll)``."""
    _, pitch, yaw = angles
    cp, sp_, cy, sy = np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    return np.array([[cp * cy, -sy, 0.0], [cp * sy, cy, 0.0], [-sp_, 0.0, 1.0]])


def body_mass(rigid, b: int, x: np.ndarray, blocks: np.ndarray) -> np.ndarray:
    """``M6`` (6, 6) of body ``b`` at positions ``x`` (n, 3); ``blocks`` (n, 3, 3) the lumped mass
    blocks of all nodes (the fairleads' line mass rides on the body)."""
    R = rotation_matrix(*x[rigid.rot_node[b]])
    T = np.kron(np.eye(2), R)
    M6 = T @ (rigid.mass6[b] + rigid.added6[b]) @ T.T
    for f in np.flatnonzero(rigid.fairlead_body == b):
        node = rigid.fairlead_node[f]
        J = point_jacobian(x[node] - x[rigid.ref_node[b]])
        M6 += J.T @ blocks[node] @ J
    return M6


def rigid_rows(rigid, free: np.ndarray, x: np.ndarray, blocks: np.ndarray, mass, damping, stiffness):
    """``(mass, damping, stiffness)`` with the 6-DOF bodies' rows as eq. (1) has them; ``free`` the
    free nodes in DOF order, the matrices over their 3 directions (csr)."""
    size = 3 * len(free)
    scale = sp.lil_matrix((size, size))
    scale.setdiag(1.0)
    mass = mass.tolil()
    for b in range(rigid.count):
        ref, rot = (3 * int(np.searchsorted(free, node)) + np.arange(3)
                    for node in (rigid.ref_node[b], rigid.rot_node[b]))
        E = euler_rates_matrix(x[rigid.rot_node[b]])
        scale[np.ix_(rot, rot)] = E.T
        G = np.eye(6)
        G[3:, 3:] = E
        dofs = np.r_[ref, rot]
        mass[np.ix_(dofs, dofs)] = G.T @ body_mass(rigid, b, x, blocks) @ G
    scale = scale.tocsr()
    return mass.tocsr(), (scale @ damping).tocsr(), (scale @ stiffness).tocsr()
