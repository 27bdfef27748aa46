"""The lumped model's equations of motion: Lagrange's equations of the network (theory/lumped.md §1)
with the vessel, anchors, bodies, seabed, current and waves.

With ``q`` the free node positions, Lagrange's equations (Bezverkhyi 2006, eqs. 3-4) read::

    (1)  M(q) q_ddot = F(t, q, q_dot) - M_qp a_p(t)

``M`` the lumped or consistent mass matrix with added mass on the relative acceleration
(:mod:`kanat.lumped.kernels` eqs. 8-9) plus body masses and added masses; ``F`` the element
forces (kernels eqs. 1-7, with the wetted fraction of elements crossing the surface), the
seabed contact (:mod:`kanat.physics.contact`) and the body loads::

    (2)  F_b = (B - W) z + F_ext + 1/2 rho C_D S |u_r| u_r + m_a,b a_w + F0 n_h + F_buoy

``u_r = u_w - R_dot`` the relative flow, ``n_h = (-sin psi, cos psi, 0)`` the horizontal
normal to the vessel heading ``psi`` (otter-board spreading force ``F0``, positive to port),
``F_buoy = rho g A_wp clip(eta(x, y, t) - z, 0, h_b) z`` the waterplane buoyancy of a
surface buoy whose node is its keel (lost when it leaves the water). 6-DOF bodies follow
:mod:`kanat.lumped.rigid`. Prescribed nodes: the vessel's points (tow point and fairleads,
lever arms ``r`` in vessel axes) at the track's point ``r`` plus the prescribed motion
``Rz(psi) [(surge, sway, heave) + R(roll, pitch, yaw) r - r]`` (:mod:`kanat.physics.motion`),
anchors fixed, body fairleads on their bodies; ``a_p`` their acceleration (only the
consistent mass couples it in).
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import entries, kernels
from kanat.lumped.bending import bending_forces
from kanat.physics import contact
from kanat.physics.immersion import sphere_fractions
from kanat.physics.motion import Harmonics, compile_motion
from kanat.physics.motion_samples import motion_series, point_series
from kanat.physics.seabed import seabed_of
from kanat.physics.ramp import ramp_factor
from kanat.physics.waves import sea_from_model
from kanat.vessel.track import VesselTrack

YAW_RATE_STEP = 1e-4      # s, central difference of the track's heading for its yaw rate
ANCHOR_ON_SEABED = 1e-6   # of the depth: an anchor at most this far above the seabed lies on it (laid_lines)
UNPACKED = np.array(kernels.PACKED)
"""Columns of a packed mass block (:data:`kanat.lumped.kernels.PACKED`) in the order of the 3 x 3 block's entries."""


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
        ``t = 0`` (the steady frame of the initial equilibrium, theory/moorings.md §1); seabed friction then
        takes its equilibrium form (:mod:`kanat.physics.contact`), and the vessel's points sit
        where the prescribed motion has them at ``t = 0`` (a motion that starts at rest then
        starts the run smoothly: a harmonic with ``phase_deg: -90``).
    steady_time : float
        The time of the prescribed motion's place in the steady frame (default 0): the run's
        start takes equilibria a little before and after ``t = 0`` for its nodes' velocities
        (:func:`kanat.lumped.equilibrium.starting_state`).
    friction : bool
        False: the seabed's friction left out (the run's starting equilibrium, in which velocity-
        regularized friction vanishes at rest).
    """

    def __init__(self, net, case, mass_matrix: str = "lumped", waves: bool = True, steady_velocity=None,
                 steady_time: float = 0.0, friction: bool = True):
        env = case.environment
        self.net, self.case = net, case
        self.rho, self.g = env.water_density, env.gravity
        self.current = env.current
        self.sea = sea_from_model(env) if waves else None
        self.track = VesselTrack.from_model(case.vessel) if case.vessel.track else None
        self.motion = compile_motion(case.vessel.motion, env)
        self._translational = translational(self.motion)
        self._harmonics = None      # a translational harmonic motion as entries.harmonic_points takes it
        if self._translational and isinstance(self.motion, Harmonics):
            m = self.motion
            on = np.asarray(m.dof) < 3                                  # rotations' harmonics have no amplitude
            self._harmonics = (np.ascontiguousarray(np.asarray(m.dof)[on], np.int64),
                               *(np.ascontiguousarray(np.asarray(value, float)[on]) for value in
                                 (m.amplitude, m.omega, m.phase)), float(m.ramp))
        self.consistent = mass_matrix == "consistent"
        self.steady_velocity = None if steady_velocity is None else np.asarray(steady_velocity, float)
        self.steady_time, self.friction = float(steady_time), friction
        self.free_index = np.flatnonzero(net.free)
        self.node_mass = net.node_mass + net.node_added_mass
        n, m = net.n_nodes, net.n_elements
        self._F, self._M, self._packed = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros((n, 6))
        self.tension, self.strain = np.zeros(m), np.zeros(m)
        self.wet = np.ones(m)
        self._uniform = env.current.profile is None and self.sea is None and env.current.ramp == 0.0
        self._u_uniform = np.broadcast_to(env.current.at(0.0), (m, 3)).copy()
        self._zero_m3 = np.zeros((m, 3))
        self._u_loads = np.broadcast_to(env.current.at(0.0), (len(net.load_node), 3)).copy()   # read-only for the kernel
        self._zero_loads = np.zeros((len(net.load_node), 3))
        self.eta_bound = float(np.sum(self.sea.amplitude)) if self.sea is not None else 0.0
        self.evaluations = 0
        self.el_args = net.elements()           # kanat.lumped.entries.Elements
        self.contact = self._contact(case, net)
        self.normal_force, self._tangent = np.zeros(n), np.zeros((n, 3))
        self.rig = net.rigid.arrays()
        self.rigid_acc = np.zeros((net.rigid.count, 2, 3))
        self._steady_points: dict = {}
        self._steady_vessel = None
        self._last_motion: tuple | None = None      # (t, q, q_dot) of the last single-time sample
        self._outputs = None                        # entries.OutputLoads, made on the first output

    def _contact(self, case, net) -> entries.Contact | None:
        """The seabed contact :func:`kanat.physics.contact.contact_forces` takes
        (:class:`kanat.lumped.entries.Contact`), None without a seabed."""
        block = case.environment.seabed
        if block is None:
            return None
        static = self.steady_velocity is not None
        bed = contact.bed_of(seabed_of(case.environment))
        laid = laid_lines(net, bed) if static else nowhere(net.n_nodes)
        law = contact.contact_law(block, equilibrium=static, friction=self.friction)
        return entries.Contact(area=net.node_contact_area, seabed=bed, law=law, laid=laid)

    # --- prescribed motion and environment -------------------------------------------------
    def vessel_points(self, times, arms=None):
        """Position, velocity (k, p, 3) and heading (k,) of vessel points ``arms`` (p, 3) in vessel
        axes (default: the vessel nodes') at ``times`` (k,): the track's point plus the
        prescribed motion turned by the heading (module docstring)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        if self.steady_velocity is not None:             # frozen at t = 0: computed once
            key = None if arms is None else tuple(np.ravel(arms))
            cached = self._steady_points.get(key)
            if cached is None:
                cached = self._vessel_points(np.full(1, self.steady_time), arms)
                self._steady_points[key] = cached
            pos, vel, heading = cached
            k = len(times)
            return np.repeat(pos, k, 0), np.repeat(vel, k, 0), np.repeat(heading, k)
        return self._vessel_points(times, arms)

    def _vessel_points(self, times, arms):
        arms = self.net.vessel_offset if arms is None else np.asarray(arms, float).reshape(-1, 3)
        k, p = len(times), len(arms)
        if self.track is None and self._translational:
            return self._translated_points(times, arms)
        pos, vel, heading = np.empty((k, p, 3)), np.zeros((k, p, 3)), np.zeros(k)
        if self.track is None:
            pos[:] = arms
        else:
            for j, arm in enumerate(arms):
                pos[:, j], vel[:, j], heading[:] = self.track_series(times, arm)
        if self.motion is not None and p:
            q, qd = self._motion(times)
            if self.steady_velocity is not None:        # the equilibrium: at the motion's t = 0 place
                qd = np.zeros_like(qd)
            disp, dvel = point_series(arms, q, qd)
            c, s = np.cos(heading)[:, None], np.sin(heading)[:, None]
            turned = np.stack([c * disp[..., 0] - s * disp[..., 1], s * disp[..., 0] + c * disp[..., 1],
                               disp[..., 2]], -1)
            rate = self._yaw_rate(times)[:, None]
            pos += turned
            vel[..., 0] += c * dvel[..., 0] - s * dvel[..., 1] - rate * turned[..., 1]
            vel[..., 1] += s * dvel[..., 0] + c * dvel[..., 1] + rate * turned[..., 0]
            vel[..., 2] += dvel[..., 2]
        return pos, vel, heading

    def _translated_points(self, times, arms):
        """:meth:`_vessel_points` without a track and without rotations (``R = I``, ``w = 0``,
        heading 0): the same numbers, points at ``arms + (q + r - r)`` moving at ``q_dot``, in a
        few array operations, or for harmonics one compiled call (:func:`kanat.lumped.fast.harmonic_points`:
        a driven run samples the vessel thousands of times)."""
        k, p = len(times), len(arms)
        if self._harmonics is not None and self.steady_velocity is None and p:
            pos, vel = np.empty((k, p, 3)), np.empty((k, p, 3))
            entries.harmonic_points(np.ascontiguousarray(times, float), *self._harmonics,
                                    np.ascontiguousarray(arms, float), pos, vel)
            return pos, vel, np.zeros(k)
        pos, vel = np.empty((k, p, 3)), np.zeros((k, p, 3))
        pos[:] = arms
        if self.motion is not None and p:
            q, qd = self._motion(times)
            if self.steady_velocity is not None:
                qd = np.zeros_like(qd)
            pos += (q[:, None, :3] + arms) - arms
            vel += qd[:, None, :3]
        return pos, vel, np.zeros(k)

    def _motion(self, times):
        """The prescribed motion's ``q, q_dot`` (k, 6) at ``times`` (k,) (:func:`motion_series`; not to be
        modified). A single time's sample is kept: an output samples the vessel nodes and the tow
        point at the same time, and the result's numbers are the same either way."""
        if len(times) != 1:
            return motion_series(self.motion, times)
        last = self._last_motion
        if last is None or last[0] != times[0]:
            last = self._last_motion = (float(times[0]), *motion_series(self.motion, times))
        return last[1], last[2]

    def track_series(self, times, arm):
        """Position, velocity (k, 3) and heading (k,) of the vessel point ``arm`` along the track:
        compiled (:func:`kanat.lumped.fast.track_states`) unless the vessel pitches."""
        k = len(times)
        pos, vel, heading = np.empty((k, 3)), np.empty((k, 3)), np.empty(k)
        if self.track.pitch is None:
            if getattr(self, "_phases", None) is None:
                self._phases = phase_table(self.track)
            entries.track_states(np.ascontiguousarray(times, float), self._phases, np.asarray(arm, float), pos, vel,
                              heading)
            return pos, vel, heading
        for i, t in enumerate(times):
            st = self.track.state(float(t), arm)
            pos[i], vel[i], heading[i] = st.position, st.velocity, st.heading
        return pos, vel, heading

    def _yaw_rate(self, times):
        if self.track is None:
            return np.zeros(len(times))
        ahead = self.track_series(times + YAW_RATE_STEP, np.zeros(3))[2]
        behind = self.track_series(times - YAW_RATE_STEP, np.zeros(3))[2]
        return (ahead - behind) / (2 * YAW_RATE_STEP)

    def frame_velocity(self) -> np.ndarray:
        """The steady frame's velocity (3,): the tow point's along the track at ``t = 0``, without the
        prescribed motion (an oscillation about the track is no steady flow); zero without a track."""
        return self.track.state(0.0).velocity if self.track is not None else np.zeros(3)

    def vessel(self, t: float):
        """Tow point ``(position, velocity, acceleration, heading)`` at ``t`` (acceleration of the
        track; the prescribed motion's is left out: only the consistent mass uses it). In the
        steady frame (the equilibrium) it is the one at t = 0, worked out once."""
        if self.steady_velocity is not None:
            if self._steady_vessel is None:
                self._steady_vessel = self._vessel(self.steady_time)
            return self._steady_vessel
        return self._vessel(t)

    def _vessel(self, t: float):
        if self.track is None:
            pos, vel, heading = self.vessel_points([t], self.case.vessel.tow_point)
            return pos[0, 0], vel[0, 0], np.zeros(3), 0.0
        st = self.track.state(t)
        pos, vel, heading = self.vessel_points([t], self.case.vessel.tow_point)
        acc = np.zeros(3) if self.steady_velocity is not None else st.acceleration
        return pos[0, 0], vel[0, 0], acc, heading[0]

    def prescribed(self, t: float, x: np.ndarray, v: np.ndarray, a: np.ndarray | None = None) -> float:
        """Write the prescribed nodes' motion at ``t`` into ``x, v`` (and ``a``); return the heading.
        6-DOF bodies' fairleads follow their bodies' pseudo-nodes, which ``x, v`` must hold."""
        net = self.net
        heading = 0.0
        if len(net.vessel_nodes):
            pos, vel, head = self.vessel_points([t])
            x[net.vessel_nodes], v[net.vessel_nodes], heading = pos[0], vel[0], head[0]
            if a is not None:                     # the track's acceleration: none without a track
                a[net.vessel_nodes] = self.vessel(t)[2] if self.track is not None else 0.0
        elif self.track is not None:
            heading = self.track.state(self.steady_time if self.steady_velocity is not None else t).heading
        x[net.anchor_nodes], v[net.anchor_nodes] = net.anchor_position, 0.0
        if a is not None:
            a[net.anchor_nodes] = 0.0
        if net.rigid.count:
            entries.place_fairleads(x, v, self.rig)
        return heading

    def water(self, t: float, points: np.ndarray):
        """Water velocity and acceleration (current + waves) at ``points`` (k, 3)."""
        if self._uniform:
            return np.broadcast_to(self._u_uniform[0], points.shape), np.zeros(points.shape)
        u = self.current.at(points[:, 2]) * ramp_factor(t, self.current.ramp)
        if self.sea is None:
            return u, np.zeros_like(u)
        return u + self.sea.velocity(points, t), self.sea.acceleration(points, t)

    def wetted(self, t: float, x: np.ndarray) -> np.ndarray:
        """Wetted fraction of every element (kernels.wetted_fraction) into ``self.wet``."""
        net = self.net
        zi, zj, half = x[net.el_i, 2], x[net.el_j, 2], 0.5 * net.el_diameter
        top, low = np.maximum(zi, zj) + half, np.minimum(zi, zj) - half
        near = top >= -self.eta_bound
        self.wet[:] = 1.0
        if np.any(near):
            mid = 0.5 * (x[net.el_i[near]] + x[net.el_j[near]])
            eta = self.sea.elevation(mid[:, 0], mid[:, 1], t) if self.sea is not None else np.zeros(len(mid))
            span = np.maximum(top[near] - low[near], 1e-300)
            self.wet[near] = np.clip((eta - low[near]) / span, 0.0, 1.0)
        return self.wet

    # --- loads, mass and acceleration ------------------------------------------------------
    def loads(self, t: float, x: np.ndarray, v: np.ndarray, heading: float, masses: bool = True):
        """Nodal forces ``F`` (n, 3) and lumped mass blocks ``M`` (n, 3, 3), eqs. (1)-(2); with
        ``masses=False`` the blocks are left as they were (an output that needs only forces).

        :func:`kanat.lumped.kernels.forces`'s kernel called directly: its water kinematics and
        wetted fractions as C-ordered writable arrays, the packed blocks unpacked only when asked."""
        net = self.net
        uw, aw = self._midpoint_water(t, x)
        entries.element_forces(x, v, uw, aw, self.wetted(t, x), net.node_force, self.node_mass, self.el_args,
                               self._F, self._packed, self.tension, self.strain)
        if masses or net.rigid.count:                      # 6-DOF bodies read the blocks (_rigid)
            self._M[:] = self._packed[:, UNPACKED]
        self.evaluations += 1
        if len(net.bend[1]):
            bending_forces(x, *net.bend[:4], self._F)
        seabed = self.contact
        if seabed is not None:
            entries.contact_forces(x, v, net.el_i, net.el_j, seabed.area, seabed.seabed, seabed.law, seabed.laid,
                                   self._tangent, self._F, self.normal_force)
        self._other_loads(t, x, v, heading)
        return self._F, self._M

    def output_loads(self, t: float, x: np.ndarray, v: np.ndarray, heading: float, masses: bool = False):
        """:meth:`loads` for an output, with the element tensions of :func:`kanat.lumped.kernels.tensions`:
        ``F`` (n, 3), ``M`` (n, 3, 3) (left as they were unless ``masses``) and the tensions (m,), the
        same numbers as ``loads`` and ``tensions`` to the last bit in one compiled call
        (:func:`kanat.lumped.output_loads.output_loads`; the bodies' loads after it, as in ``loads``)."""
        net, out = self.net, self._outputs
        if out is None:
            out = self._outputs = entries.OutputLoads(
                calm=self.sea is None, node_force=net.node_force, node_mass=self.node_mass,
                water_velocity=self._u_uniform if self._uniform else np.zeros((net.n_elements, 3)),
                water_acceleration=self._zero_m3 if self._uniform else np.zeros((net.n_elements, 3)),
                wet=self.wet, force=self._F, mass=self._packed, tension=self.tension, strain=self.strain,
                line_tension=np.zeros(net.n_elements), tangent=self._tangent, normal_force=self.normal_force)
        if not self._uniform:
            out.water_velocity[:], out.water_acceleration[:] = self._midpoint_water(t, x)
        if not out.calm:
            self.wetted(t, x)
        entries.output_loads(x, v, self.el_args, self.contact, out)
        if masses or net.rigid.count:                      # 6-DOF bodies read the blocks (_rigid)
            self._M[:] = self._packed[:, UNPACKED]
        self.evaluations += 1
        self._other_loads(t, x, v, heading)
        return self._F, self._M, out.line_tension

    def _midpoint_water(self, t: float, x: np.ndarray):
        """Water velocity and acceleration (m, 3) at the element midpoints, C-ordered and writable (those
        of a uniform current set up once)."""
        if self._uniform:
            return self._u_uniform, self._zero_m3
        net = self.net
        return tuple(np.require(part, np.float64, ("C", "W")) for part in
                     self.water(t, 0.5 * (x[net.el_i] + x[net.el_j])))

    def _other_loads(self, t, x, v, heading):
        """The loads of bodies, floats and 6-DOF bodies added to ``F`` (eq. 2; :mod:`kanat.lumped.rigid`)."""
        net = self.net
        if len(net.load_node):
            self._body_loads(t, x, v, heading)
        if len(net.float_body):
            self._float_loads(t, x)
        if net.rigid.count:
            self._rigid(t, x, v)

    def _body_loads(self, t, x, v, heading):
        net, F = self.net, self._F
        nodes = net.load_node
        if self._uniform:                                   # the uniform current, as C-ordered arrays once
            u, a = self._u_loads, self._zero_loads
        else:
            u, a = (np.ascontiguousarray(part) for part in self.water(t, x[nodes]))
        kernels.body_loads(x, v, u, a, nodes, net.load_drag_area, net.load_spreading, net.node_fluid_inertia,
                           self.rho, heading, F)
        if len(net.buoy_body):
            keel = x[net.body_node[net.buoy_body]]
            eta = self.sea.elevation(keel[:, 0], keel[:, 1], t) if self.sea is not None else 0.0
            immersion = np.clip(eta - keel[:, 2], 0.0, net.buoy_height)
            F[net.body_node[net.buoy_body], 2] += self.rho * self.g * net.buoy_area * immersion

    def _float_loads(self, t, x):
        """Spherical inline floats: the buoyancy ``(1 - f) B`` they lose out of the water off ``F``
        (``f`` of :func:`kanat.physics.immersion.sphere_fractions`, eq. 1; ``net.node_force`` holds
        ``net_buoyancy``, the fully submerged one)."""
        net = self.net
        nodes = net.body_node[net.float_body]
        centre = x[nodes]
        eta = self.sea.elevation(centre[:, 0], centre[:, 1], t) if self.sea is not None else 0.0
        share = sphere_fractions(centre[:, 2], eta, net.float_diameter)
        np.subtract.at(self._F[:, 2], nodes, (1.0 - share) * net.float_buoyancy)

    def _rigid(self, t, x, v):
        """6-DOF bodies (:mod:`kanat.lumped.rigid`): accelerations into ``rigid_acc``, their rows of
        ``F`` and ``M`` set."""
        ref = self.net.rigid.ref_node
        points = np.ascontiguousarray(x[ref])
        u, a = self.water(t, points)
        eta = self.sea.elevation(points[:, 0], points[:, 1], t) if self.sea is not None else np.zeros(len(ref))
        packed = self._M[:, [0, 1, 2, 0, 0, 1], [0, 1, 2, 1, 2, 2]].copy()
        entries.rigid_accelerations(x, v, self._F, packed, np.array(u, dtype=float), np.array(a, dtype=float),
                                  np.asarray(eta, float), self.rho, self.rig, self.rigid_acc)
        self._M[:] = packed[:, np.array(kernels.PACKED)]

    def solve_mass(self, x: np.ndarray, F: np.ndarray, M: np.ndarray, a: np.ndarray) -> np.ndarray:
        """Accelerations of the free nodes from ``M a = F`` (``a`` holds the prescribed ones)."""
        if self.consistent:
            B = np.empty((self.net.n_elements, 3, 3))
            kernels.consistent_blocks(x, self.net.el_i, self.net.el_j, self.net.el_length,
                                      self.net.el_mass, self.net.el_added_mass, B)
            kernels.consistent_solve(B, self.net.el_i, self.net.el_j, self.node_mass, F, self.net.free, a)
        else:
            entries.lumped_solve(M, F, self.net.free, a)
        if self.net.rigid.count:
            a[self.net.rigid.ref_node], a[self.net.rigid.rot_node] = self.rigid_acc[:, 0], self.rigid_acc[:, 1]
        return a

    def full(self, t: float, xf: np.ndarray, vf: np.ndarray):
        """All nodes' ``x, v, a_prescribed`` (n, 3) from the free ones; and the heading."""
        n = self.net.n_nodes
        x, v, a = np.empty((n, 3)), np.empty((n, 3)), np.zeros((n, 3))
        x[self.free_index], v[self.free_index] = xf, vf
        if self.steady_velocity is not None:
            v[self.free_index] = self.steady_velocity
            v[self.net.rigid.rot_node] = 0.0
        heading = self.prescribed(t, x, v, a)
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


def translational(motion) -> bool:
    """Whether a compiled vessel motion (:func:`kanat.physics.motion.compile_motion`) leaves roll,
    pitch and yaw at zero for all time (no motion counts)."""
    if motion is None:
        return True
    if isinstance(motion, Harmonics):
        return bool(np.all((np.asarray(motion.dof) < 3) | (np.asarray(motion.amplitude) == 0.0)))
    return bool(np.all(np.asarray(motion.values)[:, 3:] == 0.0))


def phase_table(track) -> np.ndarray:
    """A track's phases as rows (start, duration, x, y, heading, speed, acceleration, yaw rate)."""
    fields = ("start", "duration", "x", "y", "heading", "speed", "acceleration", "yaw_rate")
    return np.array([[getattr(ph, f) for f in fields] for ph in track.phases], float)


def nowhere(n: int) -> entries.Laid:
    """``n`` nodes laid nowhere (no direction: no equilibrium friction, :class:`kanat.lumped.entries.Laid`)."""
    return entries.Laid(origin=np.zeros((n, 3)), direction=np.zeros((n, 3)), distance=np.zeros(n))


def laid_lines(net, bed) -> entries.Laid:
    """Where each cable node lay for the equilibrium's seabed friction (:mod:`kanat.physics.contact`):
    from the cable's anchor on the seabed (its first such end), straight along the seabed towards the
    other end's first guess; nodes of cables without an anchor on the seabed, and cable ends, get no
    direction. An anchor above the seabed (a fixed point in the water a line hangs from) lays nothing:
    taken as the start of a line laid on the seabed, it made the equilibrium of 150 m of chain hung from
    ``anchor:[0, 0, 0]`` in 100 m of water with friction 0.6 hold its laid part 30 m off where it fell,
    pulled out by 25 kN of friction at the top (none belongs there: in still water the laid part carries
    nothing)."""
    n = net.n_nodes
    ref, direction, s = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(n)
    anchors = set(int(a) for a in net.anchor_nodes
                  if (-bed.depth + bed.tan_slope * net.x_guess[a, 0] - net.x_guess[a, 2]) * bed.cos_slope
                  > -ANCHOR_ON_SEABED * bed.depth)
    normal = np.array([-bed.sin_slope, 0.0, bed.cos_slope])
    for c, name in enumerate(net.cable_names):
        rows = np.flatnonzero(net.node_cable == name)
        nodes = net.node_index[rows]
        if int(nodes[0]) in anchors:
            start, other, arc = nodes[0], nodes[-1], net.node_s[rows]
        elif int(nodes[-1]) in anchors:
            start, other, arc = nodes[-1], nodes[0], net.node_s[rows][-1] - net.node_s[rows]
        else:
            continue
        d = net.x_guess[other] - net.x_guess[start]
        d = d - (d @ normal) * normal
        if np.linalg.norm(d) == 0.0:
            continue
        d /= np.linalg.norm(d)
        inner = nodes[1:-1]
        ref[inner], direction[inner], s[inner] = net.x_guess[start], d, arc[1:-1]
    return entries.Laid(origin=ref, direction=direction, distance=s)
