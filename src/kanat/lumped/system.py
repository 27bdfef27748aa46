"""The lumped model's equations of motion: Lagrange's equations of the network (SPEC §5)
with the vessel, anchors, bodies, current and waves.

With ``q`` the free node positions, Lagrange's equations (seed 004 eqs. 3-4) read::

    (1)  M(q) q_ddot = F(t, q, q_dot) - M_qp a_p(t)

``M`` the lumped or consistent mass matrix with added mass on the normal relative
acceleration (:mod:`kanat.lumped.kernels` eqs. 8-9) plus body masses and added masses;
``F`` the element forces (kernels eqs. 1-7) plus the body loads::

    (2)  F_b = (B - W) z + F_ext + 1/2 rho C_D S |u_r| u_r + m_a,b a_w + F0 n_h + F_buoy

``u_r = u_w - R_dot`` the relative flow, ``n_h = (-sin psi, cos psi, 0)`` the horizontal
normal to the vessel heading ``psi`` (otter-board spreading force ``F0``, positive to port),
``F_buoy = rho g A_wp clip(eta(x, y, t) - z, 0, h_b) z`` the waterplane buoyancy of a
surface buoy whose node is its keel (lost when it leaves the water). Prescribed nodes
follow the vessel track (tow point) or stay put (anchors); ``a_p`` their acceleration
(only the consistent mass couples it in).
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import kernels
from kanat.physics.waves import sea_from_model
from kanat.vessel.track import VesselTrack


class LumpedSystem:
    """Right-hand side of eq. (1) for a network (the hot path; no per-node Python loops).

    Parameters
    ----------
    net : kanat.lumped.network.Network
    case : kanat.model.Case
        For the environment and the vessel track.
    mass_matrix : {"lumped", "consistent"}
    waves : bool
        False: the mean, wave-free surface (initial equilibrium).
    steady_velocity : ndarray, shape (3,), optional
        If given, every free node moves at this velocity and the vessel is frozen at
        ``t = 0`` (the steady frame of the initial equilibrium, SPEC §4).
    """

    def __init__(self, net, case, mass_matrix: str = "lumped", waves: bool = True, steady_velocity=None):
        env = case.environment
        self.net, self.case = net, case
        self.rho, self.g = env.water_density, env.gravity
        self.current = env.current
        self.sea = sea_from_model(env) if waves else None
        self.track = VesselTrack.from_model(case.vessel) if case.vessel.track else None
        self.consistent = mass_matrix == "consistent"
        self.steady_velocity = None if steady_velocity is None else np.asarray(steady_velocity, float)
        self.free_index = np.flatnonzero(net.free)
        self.node_mass = net.node_mass + net.node_added_mass
        n, m = net.n_nodes, net.n_elements
        self._F, self._M = np.zeros((n, 3)), np.zeros((n, 3, 3))
        self.tension, self.strain = np.zeros(m), np.zeros(m)
        self._uniform = env.current.profile is None and self.sea is None
        self._u_uniform = np.broadcast_to(env.current.at(0.0), (m, 3)).copy()
        self._zero_m3 = np.zeros((m, 3))
        self.evaluations = 0
        self.el_args = (net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, net.el_weight,
                        net.el_displaced, net.el_cn, net.el_ct, net.el_stretch_drag, net.el_damping, net.el_law,
                        net.law_kind, net.law_n, net.law_x, net.law_y)

    # --- prescribed motion and environment -------------------------------------------------
    def vessel(self, t: float):
        """Tow point ``(position, velocity, acceleration, heading)`` at ``t``."""
        if self.track is None:
            p = np.asarray(self.case.vessel.tow_point, float)
            return p, np.zeros(3), np.zeros(3), 0.0
        st = self.track.state(0.0 if self.steady_velocity is not None else t)
        if self.steady_velocity is not None:
            return st.position, st.velocity, np.zeros(3), st.heading
        return st.position, st.velocity, st.acceleration, st.heading

    def prescribed(self, t: float, x: np.ndarray, v: np.ndarray, a: np.ndarray | None = None) -> float:
        """Write the prescribed nodes' motion at ``t`` into ``x, v`` (and ``a``); return the heading."""
        net = self.net
        p, vel, acc, heading = self.vessel(t)
        x[net.vessel_nodes], v[net.vessel_nodes] = p, vel
        x[net.anchor_nodes], v[net.anchor_nodes] = net.anchor_position, 0.0
        if a is not None:
            a[net.vessel_nodes], a[net.anchor_nodes] = acc, 0.0
        return heading

    def water(self, t: float, points: np.ndarray):
        """Water velocity and acceleration (current + waves) at ``points`` (k, 3)."""
        if self._uniform:
            return np.broadcast_to(self._u_uniform[0], points.shape), np.zeros(points.shape)
        u = self.current.at(points[:, 2])
        if self.sea is None:
            return u, np.zeros_like(u)
        return u + self.sea.velocity(points, t), self.sea.acceleration(points, t)

    # --- loads, mass and acceleration ------------------------------------------------------
    def loads(self, t: float, x: np.ndarray, v: np.ndarray, heading: float):
        """Nodal forces ``F`` (n, 3) and lumped mass blocks ``M`` (n, 3, 3), eqs. (1)-(2)."""
        net = self.net
        if self._uniform:
            uw, aw = self._u_uniform, self._zero_m3
        else:
            uw, aw = self.water(t, 0.5 * (x[net.el_i] + x[net.el_j]))
        kernels.forces(x, v, uw, aw, net.node_force, self.node_mass, *self.el_args,
                       self._F, self._M, self.tension, self.strain)
        self.evaluations += 1
        if len(net.body_node):
            self._body_loads(t, x, v, heading)
        return self._F, self._M

    def _body_loads(self, t, x, v, heading):
        net, F = self.net, self._F
        nodes = net.body_node
        u, a = self.water(t, x[nodes])
        kernels.body_loads(x, v, np.ascontiguousarray(u), a, nodes, net.body_drag_area, net.body_spreading,
                           net.node_added_mass, self.rho, heading, F)
        if len(net.buoy_body):
            keel = x[nodes[net.buoy_body]]
            eta = self.sea.elevation(keel[:, 0], keel[:, 1], t) if self.sea is not None else 0.0
            immersion = np.clip(eta - keel[:, 2], 0.0, net.buoy_height)
            F[nodes[net.buoy_body], 2] += self.rho * self.g * net.buoy_area * immersion

    def solve_mass(self, x: np.ndarray, F: np.ndarray, M: np.ndarray, a: np.ndarray) -> np.ndarray:
        """Accelerations of the free nodes from ``M a = F`` (``a`` holds the prescribed ones)."""
        if self.consistent:
            B = np.empty((self.net.n_elements, 3, 3))
            kernels.consistent_blocks(x, self.net.el_i, self.net.el_j, self.net.el_length,
                                      self.net.el_mass, self.net.el_added_mass, B)
            kernels.consistent_solve(B, self.net.el_i, self.net.el_j, self.node_mass, F, self.net.free, a)
        else:
            kernels.lumped_solve(M, F, self.net.free, a)
        return a

    def full(self, t: float, xf: np.ndarray, vf: np.ndarray):
        """All nodes' ``x, v, a_prescribed`` (n, 3) from the free ones; and the heading."""
        n = self.net.n_nodes
        x, v, a = np.empty((n, 3)), np.empty((n, 3)), np.zeros((n, 3))
        x[self.free_index], v[self.free_index] = xf, vf
        heading = self.prescribed(t, x, v, a)
        if self.steady_velocity is not None:
            v[self.free_index] = self.steady_velocity
        return x, v, a, heading

    def acceleration(self, t: float, xf: np.ndarray, vf: np.ndarray) -> np.ndarray:
        """Free nodes' accelerations (n_free, 3) from eq. (1)."""
        x, v, a, heading = self.full(t, xf, vf)
        F, M = self.loads(t, x, v, heading)
        return self.solve_mass(x, F, M, a)[self.free_index]

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        """``dy/dt`` of the first-order form ``y = (q, q_dot)`` (flattened, free nodes)."""
        nf = len(self.free_index)
        xf, vf = y[: 3 * nf].reshape(nf, 3), y[3 * nf:].reshape(nf, 3)
        return np.concatenate([y[3 * nf:], self.acceleration(t, xf, vf).ravel()])
