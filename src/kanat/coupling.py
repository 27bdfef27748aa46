"""Drive the lumped model from another program's time loop: :class:`Coupling`.

A host program (a floating-body integrator, a ship simulator, a controller study) moves the
points where the lines meet its structure and asks for the lines' forces on them, step by step,
as MoorDyn's coupling API does (``Init``, ``Step(x, xd, t, dt) -> forces``)::

    coupling = kanat.Coupling(case)
    forces = coupling.initialize(positions)            # the equilibrium with the points there
    for k in range(n):
        forces = coupling.step(t, dt, positions, velocities)    # the forces at t + dt
        ...                                            # the host moves its body with them

The driven points are the case's vessel points (``{vessel: [x, y, z]}`` ends, the tow point), in
:attr:`Coupling.points` order: a MoorDyn file's ``Coupled``/``Vessel`` points in file order (named
``pointN``), a YAML case's vessel ends in cable order (named ``CABLE.from`` / ``CABLE.to``, the
first end at each point). The host's positions replace the vessel's track and motion, which the
coupling does not use (:attr:`Coupling.notes` says so when the case has them).

Interpolation (MoorDyn's convention, its ``Point::updateFairlead``): over a step from ``t`` to
``t + dt`` each driven point moves at the given velocity from the given position::

    (1)  r(tau) = r_t + v_t (tau - t),   r_dot(tau) = v_t,    t <= tau <= t + dt

and the forces returned are the lines' forces on the points at ``t + dt``: the node's force of the
lumped model (element tensions, the half elements' weight, drag and seabed contact next to it),
positive as the lines pull the host. A host that knows its points at both ends of the step passes
``v_t = (r_t+dt - r_t) / dt``: the motion is then the straight line between them.

With ``rigid_vessel=True`` the host drives rigid bodies that carry the points, each by six
components (MoorDyn's coupled bodies): a MoorDyn file's ``Coupled`` bodies, in file order (named
``bodyN``), else the vessel as one body (``vessel``) whose reference point is the global origin.
``positions`` (N, 6) are each body's ``q = (x, y, z, roll, pitch, yaw)`` [m, rad]: its reference
point and the angles of ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (as in ``vessel.motion`` and a MoorDyn
body's row; at rest a MoorDyn body is at its row's ``X0 .. y0``, the vessel at zero), ``velocities``
their rates ``q_dot`` [m/s, rad/s]; each point at ``o`` in its body's axes (a MoorDyn body's point
row, the vessel's case position) follows::

    (2)  q(tau) = q_t + q_dot_t (tau - t),    r = (x, y, z) + R o,    r_dot = (x_dot, y_dot, z_dot) + w x R o

``w`` the angular velocity of the angle rates (:func:`kanat.physics.motion_samples.point_series`).
A MoorDyn file's bodies move as MoorDyn-C moves its coupled bodies (``Body::updateFairlead``,
``XYZQuat::fromVec6``): the angles are intrinsic x-y-z ones and their rates are taken as the angular
velocity about the global axes::

    (2b) r = (x, y, z) + Rx(roll) Ry(pitch) Rz(yaw) o,    r_dot = (x_dot, y_dot, z_dot) + q_dot[3:] x (r - (x, y, z))

(the same as eq. (2) to first order in the angles away from a heading; at a heading of 200 deg a
pitch of 1 deg turns about the global y axis here, about the body's own y axis in eq. (2)).
The forces (N, 6) are, body by body, the lines' resultant and moment about ``(x, y, z)``::

    (3)  F = sum_i F_i,    M = sum_i (r_i - (x, y, z)) x F_i      (the body's points i)

Inside a step the lumped model takes substeps of its own scheme (``simulation.scheme``, else the
cheapest safe one as for a run, :mod:`kanat.lumped.stepping`): the ``substep`` given, or
``simulation.dt`` if the case gives it, else the explicit scheme's safe step or the implicit
scheme's default step, cut to divide the coupling step exactly: the scheme and step a run of the
case takes (:func:`kanat.lumped.stepping.default_scheme`, the waves' cost and period counted). The
state after a step is what a run of the same case with the same motion and ``output_dt = dt`` has at
that output (tests/lumped/test_coupling.py). The implicit scheme's time-step error estimate is judged
after every step as a run judges it (:attr:`Coupling.time_error`); the start's step pair (eq. (3) of
:mod:`kanat.lumped.time_error`) moves the points on at the first step's velocities, eq. (1).
"""
from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass
from os import PathLike

import numpy as np

from kanat.errors import CaseWarning, KanatError, SolverError
from kanat.lumped import stepping, time_error
from kanat.lumped.advance import advance, time_error_estimate
from kanat.lumped.equilibrium import STARTING_DIFFERENCE, equilibrium
from kanat.lumped.integrators import SCHEMES, state_positions
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.model.operations import VesselMotion
from kanat.model.simulation import Simulation
from kanat.model.support import require_supported
from kanat.physics.motion_samples import point_series
from kanat.schemes import get_scheme

TIME_TOLERANCE = 1e-9
"""A step must start at the coupling's time, to this fraction of the step (or of 1 s)."""


class DrivenSystem(LumpedSystem):
    """The lumped equations of motion with the vessel's points moved by the host, eq. (1).

    :meth:`drive` sets the motion of the step about to be taken; every sample of the vessel's
    points (the Python schemes' and the compiled steps', :func:`kanat.lumped.advance.track_samples`)
    comes from it. With ``bodies`` the host drives rigid bodies that carry the points, eq. (2).
    """

    def drive(self, t: float, positions: np.ndarray, velocities: np.ndarray, bodies=None) -> None:
        """Eq. (1) from ``t`` for ``positions``, ``velocities`` (p, 3) of the vessel nodes; or, given the
        :class:`DrivenBodies` that carry them, eq. (2) for each body's ``(x, y, z, roll, pitch, yaw)`` and
        rates (N, 6)."""
        self._t0 = float(t)
        self._r0, self._v0 = np.array(positions, float), np.array(velocities, float)
        self._bodies = bodies

    def driven(self) -> tuple:
        """The motion set by :meth:`drive`: ``(t, positions, velocities, bodies)`` (copies)."""
        return self._t0, self._r0.copy(), self._v0.copy(), self._bodies

    def vessel_points(self, times, arms=None):
        """Positions, velocities (k, p, 3) and heading (k,) of the driven points at ``times`` (k,),
        eq. (1) or (2); ``arms`` must be None (the driven points are the vessel nodes)."""
        if arms is not None:
            raise KanatError("a coupled system's vessel has no lever arms: its points are driven")
        times = np.atleast_1d(np.asarray(times, dtype=float))
        late = (times - self._t0)[:, None, None]
        q = self._r0[None] + self._v0[None] * late
        v = np.broadcast_to(self._v0, q.shape).copy()
        if self._bodies is not None:
            q, v = self._bodies.placed(q, v)
        return q, v, np.zeros(len(times))

    def reference(self, t: float) -> np.ndarray:
        """Each driven body's ``(x, y, z, roll, pitch, yaw)`` (N, 6) at ``t``, eq. (2)."""
        return self._r0 + self._v0 * (t - self._t0)


@dataclass(frozen=True, eq=False)
class DrivenBodies:
    """Rigid bodies carrying the driven points, eq. (2).

    Attributes
    ----------
    names : tuple of str
        The bodies, in the order of the host's arrays.
    owner : ndarray of int, shape (p,)
        The body of each vessel node.
    offsets : ndarray, shape (p, 3)
        Each vessel node in its body's axes, from the body's reference point [m].
    moordyn : bool
        MoorDyn-C's angles, eq. (2b), instead of ``vessel.motion``'s, eq. (2).
    """

    names: tuple
    owner: np.ndarray
    offsets: np.ndarray
    moordyn: bool = False

    def placed(self, q: np.ndarray, rates: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Positions and velocities (k, p, 3) of the points for the bodies' ``q`` and rates (k, N, 6),
        eq. (2) or (2b)."""
        r = np.empty((q.shape[0], len(self.owner), 3))
        u = np.empty_like(r)
        for b in range(len(self.names)):
            on = self.owner == b
            if self.moordyn:
                turned = np.einsum("kij,pj->kpi", moordyn_rotations(q[:, b, 3:]), self.offsets[on])
                r[:, on] = q[:, None, b, :3] + turned
                u[:, on] = rates[:, None, b, :3] + np.cross(rates[:, None, b, 3:], turned)
            else:
                displacement, velocity = point_series(self.offsets[on], q[:, b], rates[:, b])
                r[:, on], u[:, on] = self.offsets[on][None] + displacement, velocity
        return r, u


def moordyn_rotations(angles: np.ndarray) -> np.ndarray:
    """``Rx(roll) Ry(pitch) Rz(yaw)`` (k, 3, 3) of ``angles`` (k, 3) [rad]: MoorDyn-C's coupled bodies
    (intrinsic x-y-z Euler angles, eq. (2b))."""
    c, s = np.cos(angles), np.sin(angles)
    one, nil = np.ones(len(angles)), np.zeros(len(angles))
    Rx = np.stack([one, nil, nil, nil, c[:, 0], -s[:, 0], nil, s[:, 0], c[:, 0]], -1).reshape(-1, 3, 3)
    Ry = np.stack([c[:, 1], nil, s[:, 1], nil, one, nil, -s[:, 1], nil, c[:, 1]], -1).reshape(-1, 3, 3)
    Rz = np.stack([c[:, 2], -s[:, 2], nil, s[:, 2], c[:, 2], nil, nil, nil, one], -1).reshape(-1, 3, 3)
    return Rx @ Ry @ Rz


class Coupling:
    """A case's lines driven at their vessel points by a host program (module docstring).

    Parameters
    ----------
    case : kanat.model.Case or path-like
        Any case the lumped model runs (``model: lumped`` or ``statics``: a MoorDyn file without
        ``TMax`` couples as well); its ``simulation`` block gives the scheme and substep, if any.
    scheme : str or kanat.schemes.Scheme, optional
        Overrides ``simulation.scheme``.
    rigid_vessel : bool
        Drive rigid bodies instead of points, eq. (2): ``points`` is then a MoorDyn file's ``Coupled``
        bodies (``["body1", "body2", ...]``, each point on its body), else ``["vessel"]``, and every
        array (len(points), 6).
    substep : float, optional
        The lumped model's largest step inside a coupling step [s] (an explicit scheme's is also
        capped at its safe step); default ``simulation.dt`` (a MoorDyn file's ``dtM`` is read only with
        ``TMax``), else the scheme's own (module docstring).

    Attributes
    ----------
    points : list of str
        The driven points' names, in the order of every array (module docstring).
    notes : list of str
        Decisions taken for the user (scheme, parts of the case not used).
    time : float
        The time of the state [s] (None before :meth:`initialize`).
    time_error : dict
        The implicit scheme's time-step error estimate so far, as a run's ``time_error_*`` attributes
        (docs/lumped.md, "Time-step error estimate"); past its warning threshold a step adds a note and
        warns (:class:`kanat.errors.CaseWarning`), past its failure threshold it raises, as a run warns or fails.
    """

    def __init__(self, case: Case | str | PathLike, scheme=None, rigid_vessel: bool = False,
                 substep: float | None = None):
        if not isinstance(case, Case):
            from kanat.io import load_case

            case = load_case(case)
        require_supported(case, "lumped")
        if substep is not None and not substep > 0.0:
            raise KanatError(f"substep must be positive (got {substep!r} s)")
        self.notes: list[str] = []
        self._substep = substep
        self.case = self._held(case).with_seabed_contact()
        self.net = build_network(self.case)
        if not len(self.net.vessel_nodes):
            raise KanatError(f"case '{case.name}' has no vessel points to drive: give the lines' ends on "
                             "the host as {vessel: [x, y, z]} (MoorDyn: Coupled points)")
        self.points, self.net = driven_points(case, self.net)
        self.bodies = None
        if rigid_vessel:
            self.bodies = driven_bodies(case, self.net)
            self.points = list(self.bodies.names)
        sim = self.case.simulation
        self.system = DrivenSystem(self.net, self.case, sim.mass_matrix)
        self.scheme = self._choose(scheme)
        self._state = self._snaps = None
        self._T = np.zeros(self.net.n_elements)
        self._time_error_notes: dict[str, int] = {}           # cause -> its note's index

    def _held(self, case: Case) -> Case:
        """The case without the vessel's track and motion (the host moves the points), noted."""
        vessel = case.vessel
        for key, used in (("vessel.track", bool(vessel.track)), ("vessel.motion", vessel.motion != VesselMotion()),
                          ("vessel.pitch", vessel.pitch is not None)):
            if used:
                self.notes.append(f"{key} not used: the host moves the driven points")
        held = vessel.model_copy(update={"track": (), "motion": VesselMotion(), "pitch": None})
        simulation = case.simulation or Simulation(duration=1.0)     # a statics case: the defaults (no duration used)
        if self._substep is not None:
            simulation = simulation.model_copy(update={"dt": self._substep})
        return case.model_copy(update={"vessel": held, "simulation": simulation})

    def _choose(self, scheme):
        sim = self.case.simulation
        spec = scheme if scheme is not None else sim.scheme
        rigid = self.net.rigid.count > 0
        info = stepping.step_info(self.net, self.net.x_guess, sim.mass_matrix == "consistent",
                                  self.case.environment.seabed)
        self.info = info
        if spec is None:
            chosen = stepping.default_scheme(self.system, info, sim, SCHEMES, explicit_only=rigid)
            self.notes.append(f"no scheme named: chose {chosen.name} as the fastest safe one")
            spec = chosen.name
        chosen = get_scheme(spec, SCHEMES, lambda_inf=sim.lambda_inf)
        if rigid and not chosen.explicit:
            raise KanatError(f"scheme {chosen.name} does not take bodies with dof: 6 yet (body "
                             f"'{self.net.rigid.names[0]}'); use scheme abm4 or rk4")
        return chosen

    def inner_step(self, dt: float) -> float:
        """The lumped model's step [s] inside a coupling step ``dt`` (module docstring)."""
        sim = self.case.simulation
        if self.scheme.explicit:
            top = self.info.safe_step(self.scheme)
            top = min(top, sim.dt) if sim.dt is not None else top
        else:
            top = stepping.implicit_step(self.system, sim)
        return stepping.fit_step(min(top, dt), dt)

    # --- the host's calls ------------------------------------------------------------------
    def initialize(self, positions, velocities=None, t: float = 0.0) -> np.ndarray:
        """Start at the equilibrium with the driven points at ``positions``; return its forces.

        Parameters
        ----------
        positions : array_like, shape (len(points), 3)
            [m], global axes (z up, 0 at the mean surface).
        velocities : array_like, shape (len(points), 3), optional
            [m/s]. Given, the lines start with the quasi-static response to them (the central
            difference of the equilibria at ``positions -+ velocities * 0.01 s``, as a run under a
            prescribed motion starts: :func:`kanat.lumped.equilibrium.starting_state`); default at rest.
        t : float
            The time of the start [s].

        Returns
        -------
        ndarray, shape (len(points), 3)
            The lines' forces on the points [N] (rigid bodies: (N, 6), eq. (3)).

        Raises
        ------
        kanat.errors.SolverError
            When the equilibrium is not found (the message says where).
        """
        r = self._points_array(positions, "positions")
        v = np.zeros_like(r) if velocities is None else self._points_array(velocities, "velocities")
        start = self.case.model_copy(update={"environment": self.case.environment.at_start()})
        x = self._equilibrium(start, self._placed(r), None)
        speed = np.zeros_like(x)
        if np.any(v != 0.0):
            ahead = self._equilibrium(start, self._placed(r + STARTING_DIFFERENCE * v), x)
            behind = self._equilibrium(start, self._placed(r - STARTING_DIFFERENCE * v), x)
            speed = (ahead - behind) / (2.0 * STARTING_DIFFERENCE)
        free = self.system.free_index
        velocity = speed[free]
        velocity[np.searchsorted(free, self.net.rigid.rot_node)] = 0.0        # Euler angle rates
        self.system.drive(t, r, v, self.bodies)
        self._state = self.scheme.start(self.system, float(t), x[free], velocity, self.inner_step(1.0))
        self._snaps = SnapTracker(float(t), self._tensions(self._state))
        return self.forces()

    def _placed(self, q: np.ndarray) -> np.ndarray:
        """The vessel nodes' positions (p, 3) for the host's ``q``: the points themselves, or the rigid
        bodies' points, eq. (2)."""
        if self.bodies is None:
            return q
        return self.bodies.placed(q[None], np.zeros_like(q)[None])[0][0]

    def _equilibrium(self, case, positions, x0):
        net = dataclasses.replace(self.net, vessel_offset=positions)
        try:
            return equilibrium(net, case, x0=x0, friction=False)[0]
        except SolverError as error:
            raise SolverError(f"{error}. Tried: the lines' equilibrium with the driven points at the given "
                              "positions; give them near where the case file has them") from None

    def step(self, t: float, dt: float, positions, velocities) -> np.ndarray:
        """Advance from ``t`` to ``t + dt`` with the points moving by eq. (1); return the forces there.

        Parameters
        ----------
        t : float
            The coupling's time [s] (:attr:`time`).
        dt : float
            The coupling step [s], > 0.
        positions, velocities : array_like, shape (len(points), 3)
            The points at ``t`` [m, m/s].

        Returns
        -------
        ndarray, shape (len(points), 3)
            The lines' forces on the points at ``t + dt`` [N] (rigid bodies: (N, 6), eq. (3)).

        Raises
        ------
        kanat.errors.SolverError
            When a step cannot be taken (non-finite state), or the implicit scheme's time-step error
            estimate is past its failure threshold: the message says when.
        """
        if self._state is None:
            raise KanatError("call initialize(positions) before step(...)")
        if not dt > 0.0:
            raise KanatError(f"dt must be positive (got {dt!r} s)")
        now = self.time
        if abs(t - now) > TIME_TOLERANCE * max(dt, 1.0):
            raise KanatError(f"step(t = {t:.9g} s, ...): the coupling is at t = {now:.9g} s; step from there "
                             "(or restore() a state saved at t)")
        self.system.drive(now, self._points_array(positions, "positions"),
                          self._points_array(velocities, "velocities"), self.bodies)
        h = self.inner_step(dt)
        steps = int(round(dt / h))
        state, taken = advance(self.scheme, self.system, self._state, h, steps, self._snaps, self._tensions)
        if taken < steps or not np.all(np.isfinite(state_positions(state)[0])):
            raise SolverError(f"the lines' state became non-finite at t = {state.t:.6g} s (substep {h:.3g} s, "
                              f"{self.scheme.name}); the coupling stays at t = {self.time:.6g} s: pass a smaller "
                              "substep, or scheme='rk4'")
        self._judge_time_error(h)
        self._state = state
        return self.forces()

    def _judge_time_error(self, h: float) -> None:
        """The implicit scheme's time-step error estimate judged as a run judges it
        (:func:`kanat.lumped.time_error.findings`): past its failure threshold a :class:`SolverError` (the
        coupling stays where it was); past its warning threshold a :class:`CaseWarning` the first time for
        each cause (the steps, the start) and a note, kept at the cause's latest sentence."""
        if self.scheme.explicit:
            return
        system = self.system
        found = time_error.findings(time_error_estimate(system), h,
                                    lambda free: self.net.where(int(system.free_index[free])))
        for cause, (kind, sentence) in found.items():
            if kind == "failure":
                raise SolverError(f"{sentence}; the coupling stays at t = {self.time:.6g} s")
            if cause in self._time_error_notes:
                self.notes[self._time_error_notes[cause]] = sentence
                continue
            self._time_error_notes[cause] = len(self.notes)
            self.notes.append(sentence)
            warnings.warn(sentence, CaseWarning, stacklevel=3)

    # --- what the host may read -------------------------------------------------------------
    @property
    def time(self) -> float | None:
        return None if self._state is None else float(self._state.t)

    @property
    def time_error(self) -> dict:
        """The implicit scheme's time-step error estimate so far, as a run's ``time_error_*`` attributes
        (:func:`kanat.lumped.time_error.attributes`: eq. (2)'s largest value and time, a node's largest
        error in one step, eq. (3) of the start); empty for an explicit scheme."""
        if self.scheme.explicit:
            return {}
        return time_error.attributes(time_error_estimate(self.system))

    def forces(self) -> np.ndarray:
        """The lines' forces (len(points), 3) on the driven points at :attr:`time` [N]; for rigid
        bodies (N, 6), each body's sum and moment about its reference point [N, N m], eq. (3)."""
        x, v, _, heading = self.system.full(self.time, *state_positions(self._state))
        F = self.system.loads(self.time, x, v, heading)[0][self.net.vessel_nodes].copy()
        if self.bodies is None:
            return F
        owner = self.bodies.owner
        lever = x[self.net.vessel_nodes] - self.system.reference(self.time)[owner, :3]
        out = np.zeros((len(self.points), 6))
        np.add.at(out, owner, np.concatenate([F, np.cross(lever, F)], axis=1))
        return out

    def nodes(self) -> tuple[np.ndarray, np.ndarray]:
        """Positions and velocities (n, 3) of the cables' nodes at :attr:`time` [m, m/s], in a
        result file's ``node`` order."""
        x, v = self.system.full(self.time, *state_positions(self._state))[:2]
        return x[self.net.node_index], v[self.net.node_index]

    def state(self) -> dict:
        """Everything needed to continue exactly (copies): give it to :meth:`restore`."""
        if self._state is None:
            raise KanatError("nothing to save: call initialize(positions) first")
        return {"scheme": self._state.copy(), "snaps": _copied(self._snaps.state()),
                "drive": self.system.driven()}

    def restore(self, state: dict) -> None:
        """Continue from a :meth:`state` of this coupling (or of another of the same case)."""
        scheme = state["scheme"].copy()
        self._state = scheme
        self.system.drive(*state["drive"])
        self._snaps = SnapTracker(scheme.t, self._tensions(scheme), _copied(state["snaps"]))

    def _tensions(self, scheme_state) -> np.ndarray:
        from kanat.lumped import entries

        x, v = self.system.full(scheme_state.t, *state_positions(scheme_state))[:2]
        entries.tensions(x, v, self.system.el_args, self._T)
        return self._T

    def _points_array(self, values, what: str) -> np.ndarray:
        array = np.asarray(values, dtype=float)
        shape = (len(self.points), 3 if self.bodies is None else 6)
        if array.size != shape[0] * shape[1]:
            raise KanatError(f"{what} must have shape {shape} (points {', '.join(self.points)}); got "
                             f"{np.shape(values)}")
        array = array.reshape(shape)
        if not np.all(np.isfinite(array)):
            raise KanatError(f"{what} must be finite (got {array.tolist()})")
        return array


def _copied(state: dict) -> dict:
    return {k: (np.array(v) if isinstance(v, np.ndarray) else v) for k, v in state.items()}


def driven_points(case: Case, net):
    """The names of the driven points (module docstring) and ``net`` with its vessel nodes in their
    order: a MoorDyn file's coupled points by number (``pointN``) in file order, else the first cable
    end at each (``CABLE.from``, ``CABLE.to``) in cable order (the network's own)."""
    arms = np.asarray(net.vessel_offset, float)
    names: list[str | None] = [None] * len(arms)
    from kanat.io.moordyn_coupled import coupled_points

    coupled = coupled_points(case)
    for name, xyz in coupled:
        hit = np.flatnonzero(np.all(np.isclose(arms, xyz, rtol=0.0, atol=1e-9), axis=1))
        if len(hit) and names[hit[0]] is None:
            names[hit[0]] = name
    if coupled and all(names):
        rank = {name: k for k, (name, _) in enumerate(coupled)}
        order = np.argsort([rank[name] for name in names], kind="stable")
        net = dataclasses.replace(net, vessel_nodes=net.vessel_nodes[order], vessel_offset=arms[order])
        return [names[k] for k in order], net
    names = [None] * len(arms)
    for cable in case.cables:
        for label, end in ((f"{cable.name}.from", cable.from_), (f"{cable.name}.to", cable.to)):
            if end.kind != "vessel":
                continue
            arm = np.asarray(case.vessel.tow_point if end.offset is None else end.offset, float)
            hit = np.flatnonzero(np.all(arms == arm, axis=1))
            if len(hit) and names[hit[0]] is None:
                names[hit[0]] = label
    return [name or f"vessel{k}" for k, name in enumerate(names)], net


def driven_bodies(case: Case, net) -> DrivenBodies:
    """The rigid bodies of ``rigid_vessel=True``: a MoorDyn file's ``Coupled`` bodies (file order, each
    point on its body, :mod:`kanat.io.moordyn_coupled`), else the one vessel about the global origin.

    Raises
    ------
    kanat.errors.KanatError
        When a vessel point of a MoorDyn file is on none of its coupled bodies.
    """
    from kanat.io.moordyn_coupled import coupled_bodies

    where = np.asarray(net.vessel_offset, float)
    bodies = coupled_bodies(case)
    if not bodies:
        return DrivenBodies(("vessel",), np.zeros(len(where), int), where.copy())
    owner, offsets = np.full(len(where), -1), np.zeros_like(where)
    for b, body in enumerate(bodies):
        for k, point in enumerate(body.points):
            hit = np.flatnonzero(np.all(np.isclose(where, point, rtol=0.0, atol=1e-9 * max(1.0, np.max(np.abs(point)))),
                                        axis=1))
            owner[hit], offsets[hit] = b, body.offsets[k]
    if np.any(owner < 0):
        loose = ", ".join(f"({x:.6g}, {y:.6g}, {z:.6g})" for x, y, z in where[owner < 0])
        raise KanatError(f"case '{case.name}': rigid_vessel=True drives the file's Coupled bodies, but the "
                         f"coupled point(s) at {loose} m are on none of them; drive the points instead "
                         "(rigid_vessel=False)")
    return DrivenBodies(tuple(body.name for body in bodies), owner, offsets, moordyn=True)
