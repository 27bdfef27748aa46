"""The lumped model behind the run loop's contract (:mod:`kanat.dynamics`).

:class:`LumpedModel` starts from the network equilibrium (theory/moorings.md §1) with every node moving
at the vessel's initial velocity, steps with the chosen scheme — between two outputs in
one compiled call where :mod:`kanat.lumped.advance` can — and tracks every snap event.
A case that names no scheme gets the fastest safe one, and a case without ``dt`` a
documented step (:mod:`kanat.lumped.stepping`); both decisions are in ``notes``. Its checks
of every output: no element stretched beyond the line's strain limit, no node below the
seabed beyond the contact model's penetration (or below it at all without contact).

Outputs beyond the node and element series (case-format.md): ``seabed_contact_length(cable)``
(unstretched length of each cable whose nodes touch the seabed: half an element per node in
contact), ``anchor_force(anchor)`` (the total force on the prescribed anchor node: the end
element's tension and the half element's loads — uplift is its +z part), ``body_force(body)``
(the force the line ends exert on each point body, eq. (O1) of :mod:`kanat.lumped.mooring_outputs`,
or the forces of a 6-DOF body's fairleads' elements) and ``body_attitude(body)`` (roll, pitch, yaw;
zeros for point bodies).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from kanat.dynamics import StepFailure, Steps
from kanat.errors import CaseError, CaseWarning, Problem, SolverError
from kanat.io.provenance import provenance
from kanat.io.schema import Layout
from kanat.lumped import entries, stepping, time_error
from kanat.lumped.advance import HALVING, advance, time_error_estimate
from kanat.lumped.equilibrium import relaxation_note, starting_state, starting_state_info
from kanat.lumped.network import build_network, given_positions
from kanat.lumped.output import NodeTension
from kanat.lumped.snap import SnapTracker, significant
from kanat.model.run_cost import check_node_steps
from kanat.lumped.system import LumpedSystem
from kanat.lumped.integrators import SCHEMES, SchemeState, state_positions
from kanat.lumped.mooring_outputs import (
    MooringOutputs,
    allowed_penetration,
    anchors_on_seabed,
    attitudes,
    held_under_water,
    out_of_water,
)
from kanat.physics.contact import PENETRATION_FLOOR, PENETRATION_MARGIN
from kanat.physics.seabed import seabed_of
from kanat.schemes import get_scheme

TIME_VARIABLES = ("position", "velocity", "tension", "segment_tension", "body_position", "vessel_position",
                  "vessel_heading", "vessel_pitch", "seabed_contact_length", "anchor_force", "body_force",
                  "body_attitude")


@dataclass
class LumpedState:
    """The scheme's state (``t``, positions, velocities, history) and the snap events so far."""

    scheme: SchemeState
    snaps: SnapTracker


class LumpedModel:
    """A ``model: lumped`` case ready to run (the contract of :mod:`kanat.dynamics`).

    Parameters
    ----------
    case : kanat.model.Case
    scheme : str or kanat.schemes.Scheme, optional
        Overrides ``simulation.scheme``; None and none in the case: the fastest safe one.
    start_from : kanat.model.Case or xarray.Dataset, optional
        Start from this case's initial state (its equilibrium: the same network in another current,
        say) or from the last output of this result of the lumped model (:func:`start_state`),
        instead of the case's own.
    """

    name = "lumped"

    def __init__(self, case, scheme=None, start_from=None):
        sim = case.simulation
        self.given = case                           # as written: the result's provenance
        case = case.with_seabed_contact()           # depth alone: the default seabed, as in every model
        self.case, self.net = case, build_network(case)
        self.system = LumpedSystem(self.net, case, sim.mass_matrix)
        self.info = stepping.step_info(self.net, self.net.x_guess, sim.mass_matrix == "consistent",
                                       case.environment.seabed)
        self.notes: list[str] = []
        self.scheme = self._choose(scheme)
        self.dt = self._step_size()
        self.output_interval, self.duration = sim.output_interval, sim.duration
        self._check_length()
        self.node_tension = NodeTension(self.net)
        self.max_strain = np.array([case.line_types[name].strain_limit() for name in self.net.el_type])
        self._T = np.zeros(self.net.n_elements)
        self._seen = None                  # (t, free nodes' x, all nodes' x, strains) of the last outputs()
        self.penetration = allowed_penetration(self.net, case.environment)
        self._friction = case.environment.seabed.friction if case.environment.seabed is not None else 0.0
        self._mooring = MooringOutputs(self.net, anchors_on_seabed(self.net, case.environment), case)
        self._held = held_under_water(case, self.net)
        cable_node = np.zeros(self.net.n_nodes, dtype=bool)
        cable_node[self.net.node_index] = True
        self._cable_nodes = np.flatnonzero(cable_node)                  # the nodes the seabed check watches
        self._cable_penetration = self.penetration[self._cable_nodes]
        self._seabed = seabed_of(case.environment)
        self.start_from = start_from

    def _choose(self, scheme):
        sim = self.case.simulation
        spec = scheme if scheme is not None else sim.scheme
        rigid = self.net.rigid.count > 0
        if spec is None:
            chosen = stepping.default_scheme(self.system, self.info, sim, SCHEMES, explicit_only=rigid)
            self.notes.append(f"no scheme named: chose {chosen.name} as the fastest safe one")
            spec = chosen.name
        chosen = get_scheme(spec, SCHEMES, lambda_inf=sim.lambda_inf)
        if rigid and not chosen.explicit:
            raise CaseError([Problem("simulation.scheme", f"scheme {chosen.name} does not take bodies with dof: 6 "
                                     f"yet (body '{self.net.rigid.names[0]}'); use simulation.scheme: abm4 or rk4")])
        return chosen

    def _step_size(self) -> float:
        sim, info, scheme = self.case.simulation, self.info, self.scheme
        out = sim.output_interval
        if not scheme.explicit:
            if sim.dt is not None:
                return stepping.fit_step(sim.dt, out)
            h = stepping.fit_step(stepping.implicit_default(self.system, sim.step_or_default), out)
            self.notes.append(f"{scheme.name}: no dt given; stepping at {h:.4g} s (the default {sim.step_or_default:g} s, "
                              f"or {stepping.STEPS_PER_PERIOD:g} steps per period of the shortest excitation)")
            return h
        safe = info.safe_step(scheme)
        if sim.dt is None and math.isinf(safe):
            self.notes.append(f"{scheme.name}: no dt given and nothing moves of itself (every node prescribed); "
                              f"stepping at the output interval {out:g} s")
            return out
        if sim.dt is None:
            self.notes.append(f"{scheme.name}: no dt given; stepping at the safe step {safe:.3g} s")
            return stepping.fit_step(safe, out)
        h = stepping.fit_step(min(sim.dt, safe), out)
        if safe < sim.dt:
            self.notes.append(f"{scheme.name}: dt {sim.dt:g} s exceeds the safe step {safe:.3g} s "
                              f"({stepping.SAFETY} x stability limit / highest axial frequency, shortest axial "
                              f"nodal period {info.axial_period:.3g} s); stepping at {h:.4g} s")
        return h

    def _check_length(self) -> None:
        """Refuse a run whose exact step count is past the limits, before anything is allocated
        for its steps (``kanat validate`` estimates it; :mod:`kanat.model.run_cost`)."""
        why = (f"{self.scheme.name}'s safe step, from the shortest axial nodal period "
               f"{self.info.axial_period:.3g} s" if self.scheme.explicit else "dt")
        refused = check_node_steps(self.duration / self.dt, self.net.n_nodes, self.dt, why)
        if refused:
            raise CaseError([Problem("simulation.duration", f"duration {self.duration:g} s is {refused}")])

    # 1. set up ------------------------------------------------------------------------
    def layout(self) -> Layout:
        net, sim = self.net, self.case.simulation
        attrs = provenance(self.given, model=self.name, scheme=self.scheme.name, dt=self.dt,
                           dt_case=sim.dt if sim.dt is not None else "", axial_period=self.info.axial_period,
                           mass_matrix=sim.mass_matrix, output_interval=self.output_interval,
                           **{f"scheme_{k}": v for k, v in self.scheme.parameters().items()})
        static = {"s": (("node",), net.node_s), "cable": (("node",), net.node_cable.astype(str)),
                  "segment_cable": (("segment",), net.segment_cable.astype(str)),
                  "segment_length": (("segment",), net.el_length),
                  "cable_name": (("cable",), np.array(net.cable_names, dtype=str))}
        labels = {"xyz": ("x", "y", "z"), "body": list(net.body_names), "anchor": list(net.anchor_names)}
        return Layout(static, labels, TIME_VARIABLES, attrs)

    # 2. initial state and checkpoints ------------------------------------------------------
    def initial(self) -> LumpedState:
        sim, system = self.case.simulation, self.system
        free = system.free_index
        if self.start_from is not None:
            x, v = start_state(self.net, self.start_from, sim.mass_matrix)
            velocity = v[free]
        elif sim.initial_state == "equilibrium":
            try:
                start = self.case.model_copy(update={"environment": self.case.environment.at_start()})
                x, v, info = starting_state_info(self.net, start, system)
                if "fallback" in info:
                    self.notes.append(relaxation_note(info))
            except SolverError as error:
                raise SolverError(f"{error}. Tried: the network equilibrium at the initial tow speed. "
                                  "Give bodies and points a position near where they settle (a guess), or start "
                                  "from the given geometry with simulation.initial_state: as_given") from None
            velocity = v[free]
        else:
            x = given_positions(self.net, self.case)
            velocity = np.broadcast_to(system.frame_velocity(), (len(free), 3)).copy()
        velocity[np.searchsorted(free, self.net.rigid.rot_node)] = 0.0         # Euler angle rates
        state = self.scheme.start(system, 0.0, x[free], velocity, self.dt)
        return LumpedState(state, SnapTracker(0.0, self._tensions(state)))

    def save(self, state: LumpedState) -> dict:
        arrays = {f"scheme_{k}": np.asarray(v) for k, v in state.scheme.arrays().items()}
        arrays.update({f"snap_{k}": v for k, v in state.snaps.state().items()})
        arrays["evaluations"] = np.array(self.system.evaluations)
        return arrays

    def restore(self, arrays: dict) -> LumpedState:
        scheme = self.scheme.state_type.from_arrays({k[7:]: v for k, v in arrays.items() if k.startswith("scheme_")})
        snaps = {k[5:]: v for k, v in arrays.items() if k.startswith("snap_")}
        self.system.evaluations = int(arrays["evaluations"])
        x = self.system.full(scheme.t, *state_positions(scheme))[0]
        self.info = stepping.step_info(self.net, x, self.case.simulation.mass_matrix == "consistent",
                                       self.case.environment.seabed)
        return LumpedState(scheme, SnapTracker(scheme.t, self._tensions(scheme), snaps))

    # 3. step -----------------------------------------------------------------------------
    def advance(self, state: LumpedState, t_end: float):
        steps = int(round((t_end - state.scheme.t) / self.dt))
        try:
            scheme_state, taken = advance(self.scheme, self.system, state.scheme, self.dt, steps, state.snaps,
                                          self._tensions)
        except SolverError as error:
            raise StepFailure(str(error)) from None
        iterations = _count(scheme_state, "iterations") - _count(state.scheme, "iterations")
        cuts = _count(scheme_state, "cuts") - _count(state.scheme, "cuts")
        return LumpedState(scheme_state, state.snaps), Steps(taken, iterations, cuts)

    def _tensions(self, scheme_state) -> np.ndarray:
        """Element tensions (m,) of a scheme state (a view of one work array)."""
        return self._element_tensions(*self.system.full(scheme_state.t, *state_positions(scheme_state))[:2])

    def _element_tensions(self, x, v) -> np.ndarray:
        """Element tensions (m,) of all nodes' ``x, v`` (a view of one work array)."""
        entries.tensions(x, v, self.system.el_args, self._T)
        return self._T

    def _positions(self, state: LumpedState) -> tuple[np.ndarray, np.ndarray]:
        """All nodes' positions (n, 3) of ``state`` and the element strains there: those :meth:`outputs`
        found for the same time and free nodes' positions (the strains of its force evaluation,
        eq. (1)'s ``|d| / L0 - 1``), else worked out here."""
        scheme = state.scheme
        positions = state_positions(scheme)[0]
        seen = self._seen
        if seen is not None and seen[0] == scheme.t and np.array_equal(seen[1], positions):
            return seen[2], seen[3]
        net, x = self.net, self.system.full(scheme.t, *state_positions(scheme))[0]
        d = x[net.el_j] - x[net.el_i]
        return x, np.sqrt(np.add.reduce(d * d, axis=1)) / net.el_length - 1.0     # np.linalg.norm's own sum

    # 4. outputs ------------------------------------------------------------------------
    def outputs(self, state: LumpedState) -> dict:
        system, net = self.system, self.net
        t = state.scheme.t
        x, v, a, heading = system.full(t, *state_positions(state.scheme))
        pitch = system.track.pitch(t)[0] if system.track is not None and system.track.pitch is not None else 0.0
        idx = net.node_index
        accelerations = len(self._mooring.point_bodies) > 0      # eq. (O1) of mooring_outputs needs them
        F, M, T = system.output_loads(t, x, v, heading, masses=accelerations)
        T = T.copy()
        self._seen = (t, state_positions(state.scheme)[0].copy(), x.copy(), system.strain.copy())   # for check()
        if accelerations:
            a = system.solve_mass(x, F, M, a)
        return {"position": x[idx], "velocity": v[idx], "tension": self.node_tension(T), "segment_tension": T,
                "body_position": x[net.body_node].reshape(-1, 3), "vessel_position": system.vessel(t)[0],
                "vessel_heading": heading, "vessel_pitch": pitch,
                "seabed_contact_length": self._mooring.contact_length(system.normal_force),
                "anchor_force": self._mooring.anchor_forces(F, system.normal_force, self._friction),
                "body_force": self._mooring.line_forces(system, t, x, v, a, heading, T),
                "body_attitude": attitudes(net, x)}

    # 5. status ---------------------------------------------------------------------------
    def check(self, state: LumpedState, values: dict) -> str | None:
        net, t = self.net, state.scheme.t
        x, strain = self._positions(state)
        k = int(np.argmax(strain - self.max_strain))
        if strain[k] > self.max_strain[k]:
            return (f"element stretched by {100 * strain[k]:.3g} % (> {100 * self.max_strain[k]:g} %) at t = "
                    f"{t:.6g} s in {net.element_where(k)} (tension {values['segment_tension'][k]:.4g} N); check "
                    "axial_stiffness and the loads, or reduce dt, or set line_types.<name>.max_strain")
        return (self._below_seabed(x, t) or out_of_water(self.case, self.net, x, self.system.sea, t, self._held)
                or self._time_error("failure"))

    def _time_error(self, kind: str) -> str | None:
        """The implicit scheme's local error estimate's sentence when it is a ``kind`` ("warning" or
        "failure") of :func:`kanat.lumped.time_error.verdict`; None otherwise and for explicit schemes."""
        if self.scheme.explicit:
            return None
        system = self.system
        found = time_error.verdict(time_error_estimate(system), self.dt,
                                   lambda free: self.net.where(int(system.free_index[free])))
        return found[1] if found is not None and found[0] == kind else None

    def _below_seabed(self, x, t) -> str | None:
        seabed = self._seabed
        if seabed is None:
            return None
        net, nodes = self.net, self._cable_nodes
        if not len(nodes):
            return None
        depth = seabed.penetration(x[nodes])
        excess = depth - self._cable_penetration
        k = int(np.argmax(excess))
        if excess[k] <= 0.0:
            return None
        depth, worst = depth[k], int(nodes[k])
        return (f"a node is {depth:.4g} m below the seabed at t = {t:.6g} s ({net.where(worst)}), more "
                f"than the contact allows ({self.penetration[worst]:.3g} m: {PENETRATION_MARGIN:g} x its weight in "
                f"water, if any, / (stiffness x contact area) + {PENETRATION_FLOOR * 1e3:g} mm); raise "
                "environment.seabed.stiffness or damping, or reduce dt")

    def _slack_with_bending(self, elements) -> str | None:
        """A note when elements of a line type with bending stiffness went slack and snapped taut past the
        floor of :func:`kanat.lumped.snap.significant` (but for those at a free end, which carry next to
        nothing anyway): they carry no compression, which the beam they model
        would (a steep jumper with EI 2e7 N m^2, driven, parts from MoorDyn's run after its sag goes
        slack: docs/lumped.md)."""
        net = self.net
        at_free_end = (net.kinds[net.el_i] == "free") | (net.kinds[net.el_j] == "free")   # no pull there anyway
        types = sorted({net.el_type[k] for k in set(np.asarray(elements).tolist())    # np.unique imports numpy.ma
                        if not at_free_end[k] and self.case.line_types[net.el_type[k]].bending_stiffness > 0.0
                        and net.el_compression[k] == 0.0})
        if not types:
            return None
        return (f"elements of line type '{types[0]}' (bending stiffness) went slack: the lumped model's elements "
                "carry no compression, so a compressed part of a line with EI is no beam there (it shortens "
                "freely; the line type's compression_stiffness makes its elements bars); the snap events list them")

    def _unresolved_snaps(self, events) -> str | None:
        """A note when the implicit scheme stepped through snap loads (``events``, those past the floor of
        :func:`kanat.lumped.snap.significant`) at a step longer than the shortest
        axial nodal period: an element that pulls taut rises to its peak within about a quarter of its
        axial period, so a longer step does not follow the rise and the peak is not converged in the
        step. Measured: a released 20 m wire (axial period 3.6 ms) falling through its own slack peaks
        at 2.16 kN with rk4 at 10 ms and with the implicit scheme at 2 ms, at 25 kN with the implicit
        scheme at 10 ms, its top node 10 m from rk4's (``tests/lumped/test_lumped_snap_step.py``); the
        slack free end of WHOI's breaking tow stepped at 0.25 s (axial period 23 ms) falls 10 % deeper in
        300 s than rk4's (``tests/whoi/test_whoi_events.py``)."""
        if self.scheme.explicit or not len(events["time"]) or self.dt <= self.info.axial_period:
            return None
        k = int(np.argmax(events["peak_tension"]))
        return (f"{len(events['time'])} snap load(s) (slack elements pulled taut; the largest, "
                f"{events['peak_tension'][k]:.4g} N at t = {events['time'][k]:.4g} s in "
                f"{self.net.element_where(int(events['element'][k]))}) under {self.scheme.name} at dt "
                f"{self.dt:.4g} s, longer than the shortest axial nodal period {self.info.axial_period:.3g} s: "
                "snap peaks are not converged in the step (they can be several times too high or too low) "
                f"and the motion after them may differ (a slack free end by several per cent); rerun with dt <= {self.info.axial_period:.3g} s or "
                "scheme rk4 to resolve them")

    # 6. finish ---------------------------------------------------------------------------
    def final(self, state: LumpedState) -> tuple[dict, dict]:
        events = state.snaps.events()
        variables = {"event_time": (("event",), events["time"]),
                     "event_segment": (("event",), events["element"]),
                     "event_peak_tension": (("event",), events["peak_tension"]),
                     "event_rise_rate": (("event",), events["rise_rate"])}
        found = significant(events, self.net.el_weight * self.net.el_length)       # snap.py eq. (1)
        slack_bent = self._slack_with_bending(found["element"])
        if slack_bent:
            self.notes.append(slack_bent)
        unresolved = self._unresolved_snaps(found)
        if unresolved:
            self.notes.append(unresolved)
        explicit = _count(state.scheme, "explicit")
        if explicit:
            self.notes.append(HALVING.fallback_note(explicit, "rk4"))
        attrs = {"snap_events": len(events["time"]), "force_evaluations": self.system.evaluations,
                 "explicit_steps": explicit}
        if not self.scheme.explicit:
            attrs.update(time_error.attributes(time_error_estimate(self.system)))
            unresolved = self._time_error("warning")
            if unresolved:
                self.notes.append(unresolved)
                warnings.warn(unresolved, CaseWarning, stacklevel=2)
        return variables, attrs


def _count(state: SchemeState, name: str) -> int:
    """The count ``name`` (``iterations``, ``cuts``, ``explicit``) an implicit state keeps; 0 for the others."""
    return int(getattr(state, name, 0))


def start_state(net, start, mass_matrix: str = "lumped") -> tuple[np.ndarray, np.ndarray]:
    """Positions and velocities (n, 3) of every node of ``net`` from another case's initial state or
    from a result's last output.

    Parameters
    ----------
    net : kanat.lumped.network.Network
    start : kanat.model.Case or xarray.Dataset
        A case of the same network (same cables, segments and ends; another current, say): its
        initial state (:func:`kanat.lumped.equilibrium.starting_state`). Or a lumped model's result
        of the same network whose status is ok: the positions and velocities of its last output.

    Raises
    ------
    kanat.errors.CaseError
        When the networks differ, the result failed, or holds 6-DOF bodies (whose attitude rates a
        result does not keep).
    """
    if hasattr(start, "data_vars"):
        return _result_state(net, start)
    start = start.with_seabed_contact()
    other = build_network(start)
    if other.n_nodes != net.n_nodes or not np.array_equal(other.free, net.free):
        raise CaseError([Problem("start", f"the case to start from ('{start.name}') must have the same "
                                 f"network (cables, segments, ends): {other.n_nodes} nodes against "
                                 f"{net.n_nodes}")])
    system = LumpedSystem(other, start, mass_matrix)
    at_start = start.model_copy(update={"environment": start.environment.at_start()})
    return starting_state(other, at_start, system)


def _result_state(net, ds) -> tuple[np.ndarray, np.ndarray]:
    """The last output of a lumped result ``ds`` as all nodes' positions and velocities (n, 3)."""
    status = ds.attrs.get("status", "ok")
    if ds.attrs.get("model") != "lumped" or "time" not in ds.dims:
        raise CaseError([Problem("start", "a result to start from must be a run of the lumped model "
                                 f"(this one is model '{ds.attrs.get('model')}')")])
    if status != "ok":
        raise CaseError([Problem("start", f"the result to start from did not finish: {status}")])
    if net.rigid.count:
        raise CaseError([Problem("start", "a result does not keep a 6-DOF body's attitude rates: start "
                                 f"from its case instead (body '{net.rigid.names[0]}')")])
    cables = np.asarray(ds.cable.values, dtype=str)
    if len(cables) != len(net.node_index) or not np.array_equal(cables, net.node_cable.astype(str)):
        raise CaseError([Problem("start", "the result to start from must have the same network (cables and "
                                 f"segments): {len(cables)} nodes against {len(net.node_index)}")])
    x, v = net.x_guess.copy(), np.zeros((net.n_nodes, 3))
    x[net.node_index], v[net.node_index] = ds.position.values[-1], ds.velocity.values[-1]
    return x, v
