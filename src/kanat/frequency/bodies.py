"""6-DOF bodies in waves in the frequency domain: their wave force and moment, and their drag.

A 6-DOF body's degrees of freedom are ``q = (u, Theta)``, its reference point's displacement and
its Euler angles (:mod:`kanat.frequency.rigid`). With ``R`` its rotation at the equilibrium,
``T = diag(R, R)``, ``E`` of :func:`kanat.frequency.rigid.euler_rates_matrix` and ``G = diag(I, E)``,
its velocity in body axes is ``nu = T^T G q_dot``, and a force and moment ``F6`` about the
reference point (global axes) does the work of the generalized force ``G^T F6``.

The time domain (:mod:`kanat.lumped.rigid` eq. 3) loads the body at its reference point ``r`` with
the water's acceleration ``a_w``, velocity ``u_w`` and elevation ``eta`` there::

    (1)  F6 = [(rho V I + A_tt) a_w; A_rt a_w] + s C_g[:, 2] eta - T f_d,
         f_d,j = 1/2 rho (C_D A)_j |nu_r,j| nu_r,j + sum_k B2_jk |nu_k| nu_k

``A = T A_b T^T`` the added mass and ``C_g = T C T^T`` the hydrostatic stiffness in global axes,
``s`` 1 for a surface-piercing body (its heave restoring measured from the wave surface) and 0
otherwise, ``nu_r`` the body-axes velocity relative to the water (translations; rotations
absolute). The first two terms are the waves' excitation, as complex amplitudes per unit wave
amplitude (:func:`wave_forces`): ``a_w = i omega u_w`` with ``u_w`` the Airy velocity at ``r``
(:func:`kanat.frequency.kinematics.water_velocity`) and ``eta = e^{-i psi}``.

The drag and quadratic damping are linearised by the rule the lines' drag takes
(:mod:`kanat.frequency.drag`: describing functions for harmonics, the stochastic rule for a sea),
each term ``c |v| v`` of one velocity component ``v = t . w`` being a *channel*: a
:class:`~kanat.frequency.drag.DragPairs` entry with only a tangential coefficient ``c`` along a
unit ``t``, whose 3-vector velocity ``w`` and force are mapped to and from the body's degrees of
freedom (:mod:`kanat.frequency.pairs`)::

    (2)  translation drag j:  w = u_w - u_dot                  t = R e_j,  w, f in global axes
         rotation drag j:     w = -R^T E Theta_dot             t = e_j,    f -> G^T T [0; R f]
         quadratic damping k: w = -(nu's translation or rotation part),  t = e_k',
                              f -> G^T T B2[:, k] (e_k' . f)

(``k' = k mod 3``), each velocity and water velocity projected on ``t``, so that a channel's
oscillation is along one line and its describing function exact. The channel's
``D = 2 c E|t . w| t t^T`` thus gives the force's slope ``2 c E|v|`` along its own component, as
the time domain's ``c |v| v`` has it.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.frequency.drag import DragPairs
from kanat.frequency.kinematics import water_velocity
from kanat.frequency.rigid import euler_rates_matrix
from kanat.physics.motion import rotation_matrix


@dataclass(frozen=True, eq=False)
class BodyWaves:
    """The 6-DOF bodies' wave excitation of eq. (1), per body ``b``.

    Attributes
    ----------
    dofs : ndarray of int, shape (nb, 6)
        The body's degrees of freedom in the linear system (reference point, then Euler angles).
    place : ndarray, shape (nb, 3)
        The reference point at the equilibrium [m], where the water's kinematics are taken.
    inertia : ndarray, shape (nb, 6, 3)
        ``G^T [rho V I + A_tt; A_rt]`` [kg, kg m]: the generalized force per unit water acceleration.
    heave : ndarray, shape (nb, 6)
        ``s G^T C_g[:, 2]`` [N/m, N]: the generalized force per unit wave elevation.
    """

    dofs: np.ndarray
    place: np.ndarray
    inertia: np.ndarray
    heave: np.ndarray

    @property
    def count(self) -> int:
        return len(self.dofs)


@dataclass(frozen=True, eq=False)
class Channels:
    """The bodies' drag and damping channels of eq. (2), with their maps to the linear system.

    Attributes
    ----------
    pairs : kanat.frequency.drag.DragPairs
    force, velocity : list of (ndarray of int, ndarray)
        Per channel, the degrees of freedom it acts on and the block (d, 3) mapping its 3-vector
        force to their generalized forces (``force``), or the block whose transpose maps their
        velocities to its velocity (``velocity``).
    flow : ndarray, shape (p, 3, 3)
        The projection of the water's velocity the channel feels: ``t t^T`` for a translation drag
        channel, zero for those on the body's absolute velocity.
    """

    pairs: DragPairs
    force: list
    velocity: list
    flow: np.ndarray


def body_frames(rigid, b: int, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``R`` (3, 3), ``T`` (6, 6) and ``G`` (6, 6) of body ``b`` at positions ``x`` (n, 3)."""
    angles = x[rigid.rot_node[b]]
    R = rotation_matrix(*angles)
    G = np.eye(6)
    G[3:, 3:] = euler_rates_matrix(angles)
    return R, np.kron(np.eye(2), R), G


def body_dofs(rigid, free: np.ndarray) -> np.ndarray:
    """The bodies' degrees of freedom (nb, 6) in the linear system (``free`` the free nodes in DOF order)."""
    out = np.empty((rigid.count, 6), dtype=np.int64)
    for b in range(rigid.count):
        for k, node in enumerate((rigid.ref_node[b], rigid.rot_node[b])):
            out[b, 3 * k:3 * k + 3] = 3 * int(np.searchsorted(free, node)) + np.arange(3)
    return out


def body_waves(rigid, free: np.ndarray, x: np.ndarray) -> BodyWaves:
    """The :class:`BodyWaves` of the 6-DOF bodies at positions ``x`` (n, 3)."""
    nb = rigid.count
    inertia, heave = np.zeros((nb, 6, 3)), np.zeros((nb, 6))
    for b in range(nb):
        R, T, G = body_frames(rigid, b, x)
        added = T @ rigid.added6[b] @ T.T
        fluid = added[:, :3].copy()
        fluid[:3] += rigid.scalars[b, 2] * np.eye(3)          # rho V: the Froude-Krylov part
        inertia[b] = G.T @ fluid
        surface = rigid.scalars[b, 4] > 0.0
        heave[b] = G.T @ (T @ rigid.hydro[b] @ T.T)[:, 2] if surface else 0.0
    return BodyWaves(dofs=body_dofs(rigid, free), place=x[rigid.ref_node].reshape(-1, 3).copy(),
                     inertia=inertia, heave=heave)


def wave_forces(bodies: BodyWaves, sea, omega: np.ndarray, size: int) -> np.ndarray:
    """The generalized wave forces (nf, size) of eq. (1) per unit wave amplitude (``sea`` of unit
    amplitudes and zero phases at ``omega``, or None: still water)."""
    out = np.zeros((len(omega), size), complex)
    if sea is None or not bodies.count:
        return out
    u = water_velocity(sea, bodies.place)                                       # (nf, nb, 3)
    psi = np.multiply.outer(bodies.place[:, 0], sea.k * np.cos(sea.direction)) + np.multiply.outer(
        bodies.place[:, 1], sea.k * np.sin(sea.direction))                     # (nb, nf)
    force = np.einsum("bdr,fbr->fbd", bodies.inertia, 1j * omega[:, None, None] * u)
    force += bodies.heave[None] * np.exp(-1j * psi).T[:, :, None]
    np.add.at(out, (slice(None), bodies.dofs), force)
    return out


def channels(rigid, free: np.ndarray, x: np.ndarray, current, frame_velocity: np.ndarray, rho: float) -> Channels:
    """The bodies' drag and quadratic damping channels (eq. 2) at positions ``x`` (n, 3);
    ``current(points) -> (k, 3)`` [m/s], ``frame_velocity`` the steady frame's (3,) [m/s]."""
    dofs = body_dofs(rigid, free)
    rows, force, velocity = [], [], []
    for b in range(rigid.count):
        R, T, G = body_frames(rigid, b, x)
        ref, rot = dofs[b, :3], dofs[b, 3:]
        place = x[rigid.ref_node[b]]
        spin = G[3:, 3:].T @ R                                 # E^T R: body-axes angular velocity's map
        flow = np.asarray(current(place[None])).reshape(3) - frame_velocity
        for j, area in enumerate(rigid.drag[b]):
            if area <= 0.0:
                continue
            if j < 3:
                along = np.outer(R[:, j], R[:, j])
                rows.append((R[:, j], 0.5 * rho * area, flow, place, along))
                force.append((ref, np.eye(3)))
                velocity.append((ref, along))
            else:
                axis = np.eye(3)[j - 3]
                rows.append((axis, 0.5 * rho * area, np.zeros(3), place, np.zeros((3, 3))))
                force.append((rot, spin))
                velocity.append((rot, spin @ np.outer(axis, axis)))
        for k in range(6):
            column = rigid.quadratic[b][:, k]
            if not np.any(column):
                continue
            axis = np.eye(3)[k % 3]
            mean = -R.T @ frame_velocity if k < 3 else np.zeros(3)
            rows.append((axis, 1.0, mean, place, np.zeros((3, 3))))
            force.append((dofs[b], np.outer(G.T @ T @ column, axis)))
            velocity.append((ref, R @ np.outer(axis, axis)) if k < 3 else (rot, spin @ np.outer(axis, axis)))
    return Channels(pairs=_pairs(rows), force=force, velocity=velocity,
                    flow=np.array([row[4] for row in rows], float).reshape(-1, 3, 3))


def _pairs(rows: list) -> DragPairs:
    """:class:`DragPairs` of channels ``(tangent, coefficient, mean flow, place, flow)``."""
    k = len(rows)
    vectors = lambda i: np.array([row[i] for row in rows], float).reshape(k, 3)  # noqa: E731
    return DragPairs(node=-np.ones(k, dtype=np.int64), element=-np.ones(k, dtype=np.int64),
                     dof=-np.ones(k, dtype=np.int64), tangent=vectors(0), normal=np.zeros(k),
                     tangential=np.array([row[1] for row in rows], float), inertia_normal=np.zeros(k),
                     inertia_tangential=np.zeros(k), mean=vectors(2), middle=vectors(3), isotropic=np.zeros(k, bool))
