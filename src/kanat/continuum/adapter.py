"""The continuum model behind the run loop's contract (:mod:`kanat.dynamics`).

:class:`ContinuumModel` wraps the planar or the spatial cable (:mod:`kanat.continuum.models`)
and a scheme of the generalized-α family or Kaliukh & Vusatiuk's factorized schemes. It steps
``dt`` at a time; a step whose Newton iteration fails is cut in halves (up to
:data:`kanat.continuum.stepper.MAX_CUTS` levels: :class:`kanat.step_control.Halving`, the step
control both models share) before the run stops with a message saying where and what to try. Its checks of every output:

* finite: a state or output holding NaN or inf fails, before the checks below (which compare
  numbers, and a NaN passes every comparison);
* compression: a perfectly flexible cable (``EI = 0``) cannot carry it; a line with bending
  stiffness is a rod and may, up to the Euler load of one segment ``pi^2 EI / (2 ds)^2``
  (beyond it the grid no longer resolves the buckled shape: :func:`rod_advice` says how fine a
  grid would, or that the line goes slack). With ``simulation.slack: continue`` (the default)
  a run goes on through compression and records every slack event after every step
  (:mod:`kanat.continuum.slack`): the result's ``slack_*`` variables, its ``slack_events``
  attribute and a note; with ``stop`` the check fails the run;
* strain within the line type's range;
* seabed: no node more than :data:`PENETRATION_FACTOR` times the contact model's static
  penetration ``w / (k_b d)`` below the seabed (a node falling through it);
* surface: no node of a buoyant interval wholly out of the water (:mod:`kanat.continuum.surface`:
  the model cannot float a line on the surface, so such a node stands in a column out of the sea).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.courant import check_step
from kanat.continuum.models import model_for
from kanat.continuum.outputs import end_forces, inline_forces, seabed_contact_length
from kanat.continuum.model2d import strain_of
from kanat.continuum.schemes import SCHEMES, ContinuumScheme, FamilyScheme
from kanat.continuum.slack import PULL_FRACTION, SlackLog, pulled_start
from kanat.continuum.stepper import MAX_CUTS, NewtonFailure
from kanat.continuum.surface import DryLength, dry_buoyant_node
from kanat.continuum.wetted import ROUND_OFF
from kanat.continuum.winch import material_stations
from kanat.dynamics import StepFailure
from kanat.errors import CaseError, Problem, SolverError
from kanat.io.provenance import provenance
from kanat.io.schema import Layout
from kanat.physics.immersion import heights
from kanat.schemes import get_scheme
from kanat.step_control import Halving, Steps, StepsExhausted

COMPRESSION_TOLERANCE = 1e-3
"""Compression beyond this fraction of the largest tension (or of the cable's weight) fails a run."""
REFINEMENT_REACH = 10.0
"""Finest grid a compression message suggests, as a divisor of the segment length: a compression beyond
the Euler load of a segment this many times shorter is a line going slack, not a grid too coarse."""
SLENDER_SEGMENT = 10.0
"""Shortest segment, in diameters, whose Euler load a compression message counts on: Euler's load is a
slender column's, and two segments of 10 diameters are 80 radii of gyration (d/4) long."""
PENETRATION_FACTOR = 10.0
"""A node deeper below the seabed than this many static penetrations (plus 1 mm) fails a run."""
HALVING = Halving(MAX_CUTS)
"""The step control: a step whose Newton iteration fails is retaken as 2, 4, 8, 16 sub-steps."""
TIME_VARIABLES = ("position", "velocity", "tension", "body_position", "vessel_position", "vessel_heading",
                  "vessel_pitch", "newton_iterations")


class ContinuumModel:
    """A ``model: continuum`` case ready to run (the contract of :mod:`kanat.dynamics`).

    Parameters
    ----------
    case : kanat.model.Case
    scheme : str or ContinuumScheme, optional
        Overrides ``simulation.scheme`` (default ``generalized-alpha``).
    start_from : kanat.model.Case, optional
        Start from the steady state of this case instead (the same cable and grid in another
        current, say): the run is then the response to the change, a current step for one.
    """

    name = "continuum"

    def __init__(self, case, scheme=None, start_from=None):
        sim = case.simulation
        if sim.dt is None:
            raise CaseError([Problem("simulation.dt", "the continuum model needs a time step dt [s]")])
        self.case = case
        self.scheme: ContinuumScheme = get_scheme(scheme or sim.scheme or "generalized-alpha", SCHEMES,
                                                  lambda_inf=sim.lambda_inf, gamma=sim.gamma)
        self.cable_model = model_for(case)
        self.start_from = None if start_from is None else model_for(start_from)
        self.notes: list[str] = []
        if start_from is None:
            self._start_slack_on_the_seabed(case)
        if self.start_from is not None and (self.start_from.dimensions != self.cable_model.dimensions or
                                            len(self.start_from.cable.s) != len(self.cable_model.cable.s)):
            raise CaseError([Problem("start_from", "the case to start from must have the same cable, grid and "
                                     "dimensions as the case run")])
        self.dt, self.output_interval, self.duration = sim.dt, sim.output_interval, sim.duration
        cable = self.cable_model.cable
        self.notes += list(cable.grid.notes) if cable.grid is not None else []
        self._refuse_for_factorized()
        self.max_strain = min(case.line_types[name].strain_limit() for name in case.cables[0].line_types)
        self.body = case.cables[0].to.kind == "body"
        self.anchor_ends = [label for label, end in (("from", case.cables[0].from_), ("to", case.cables[0].to))
                            if end.kind == "anchor"]
        self.attached = [name for _, name in cable.grid.junctions] if cable.grid is not None else []
        self.winch = cable.winch
        self.stations = (material_stations(case, cable.s, cable.winch, self.dt, self.duration)
                         if cable.winch is not None else None)
        self._own, self._winch_facts = RowFacts(cable.rows(), cable.seabed), None
        self.slack = SlackLog() if sim.slack == "continue" else None
        self.dry = DryLength()
        if cable.winch is not None:
            self.notes.append(f"winch: the grid grows from the winch (a node every {cable.winch.segment:.4g} m paid "
                              f"out); s is each node's arclength at t = 0 (negative: still on the drum, where "
                              "its outputs sit at the winch)")

    def _start_slack_on_the_seabed(self, case) -> None:
        """A line lying slack on the seabed under its body in still water starts from a small pull on the
        body, released at t = 0 (:func:`kanat.continuum.slack.pulled_start`), and says so."""
        pulled = pulled_start(case)
        if pulled is None:
            return
        start, pull = pulled
        self.start_from = model_for(start)
        self.notes.append(f"the line lies slack on the seabed in still water (no steady state of its own): the run "
                          f"starts from its steady state under a horizontal pull of {pull:.4g} N on body "
                          f"'{case.cables[0].to.name}' away from the anchor ({PULL_FRACTION:.0%} of the line's "
                          "weight in water), released at t = 0, so the body drifts back slowly")

    def _refuse_for_factorized(self) -> None:
        """Kaliukh & Vusatiuk's schemes step the uniform flexible cable of theory/continuum.md §1–2 only."""
        if isinstance(self.scheme, FamilyScheme):
            return
        case, cable = self.case, self.cable_model.cable
        used = []
        if len(case.cables[0].sections) > 1:
            used.append(("cables[0].sections", "a cable of several sections"))
        if case.cables[0].attachments:
            used.append(("cables[0].attachments", "inline bodies"))
        if cable.grid is not None and cable.grid.bending:
            used.append(("line_types", "bending stiffness"))
        if case.environment.waves is not None:
            used.append(("environment.waves", "waves"))
        if case.winch:
            used.append(("winch", "a winch"))
        if any(case.bodies[e.name].surface_buoy is not None for e in case.cables[0].ends if e.kind == "body"):
            used.append(("bodies", "a surface buoy"))
        if case.cables[0].from_.kind == "vessel" and case.vessel.tow_point[2] > ROUND_OFF:
            used.append(("vessel.tow_point", f"a tow point above the water surface ({case.vessel.tow_point[2]:g} m): "
                         "they take the whole cable as submerged"))
        if used:
            raise CaseError([Problem(key, f"{what}: scheme '{self.scheme.name}' (Kaliukh & Vusatiuk's factorized schemes) "
                                     "steps a uniform flexible cable only; use scheme: generalized-alpha")
                             for key, what in used])

    # 1. set up ------------------------------------------------------------------------
    def layout(self) -> Layout:
        cable, case = self.cable_model.cable, self.case
        bodies = ([case.cables[0].to.name] if self.body else []) + self.attached
        attrs = provenance(case, model=self.name, scheme=self.scheme.name, dt=self.dt,
                           dimensions=self.cable_model.dimensions, output_interval=self.output_interval,
                           **{f"scheme_{k}": v for k, v in self.scheme.parameters().items()})
        s = cable.s if self.stations is None else self.stations
        names = TIME_VARIABLES + (("winch_tension", "winch_length") if self.winch is not None else ())
        static = {"s": (("node",), s), "cable": (("node",), [cable.name] * len(s))}
        labels = {"xyz": ("x", "y", "z"), "body": bodies}
        if case.environment.depth is not None:             # a seabed: the line may rest on it
            names += ("seabed_contact_length",)
            static["cable_name"] = (("cable",), np.array([cable.name], dtype=str))
        if self.anchor_ends:                               # named by cable end, as the lumped model and statics
            names += ("anchor_force",)
            labels["anchor"] = [f"{cable.name}.{end}" for end in self.anchor_ends]
        if bodies:
            names += ("body_force",)
        return Layout(static, labels, names, attrs)

    # 2. initial state and checkpoints ------------------------------------------------------
    def initial(self):
        try:
            state = (self.start_from or self.cable_model).initial()
        except SolverError as error:
            raise SolverError(
                f"{error}. Tried: the case's statics, then Newton on the steady box equations from it. The "
                "continuum model needs a taut cable from the start: it starts from the steady shape of a "
                "perfectly flexible line, with or without bending stiffness (which carries compression only up "
                "to about the Euler load of one segment), so a slack line runs with model: lumped, whose "
                "equilibrium carries slack line (with simulation.slack: continue, the default, a line lying slack "
                "on the seabed under its body in still water starts from a small pull on the body)") from None
        check_step(self.scheme, self.cable_model, state, self.dt)     # Kaliukh & Vusatiuk's schemes: their known range
        return state

    def save(self, state) -> dict:
        slack = {} if self.slack is None else {"slack_events": self.slack.events}
        return {"t": np.array(state.t), **self.cable_model.save(state), **slack}

    def restore(self, arrays: dict):
        if self.slack is not None:
            self.slack = SlackLog(arrays.get("slack_events"))
        return self.cable_model.restore(float(arrays["t"]), arrays)

    # 3. step -----------------------------------------------------------------------------
    def advance(self, state, t_end: float):
        steps = int(round((t_end - state.t) / self.dt))
        done = Steps()
        for _ in range(steps):
            try:
                state, work = HALVING.take(self._attempt, state, self.dt)
            except StepsExhausted as exhausted:
                raise StepFailure(self._failure(exhausted.refusal, state)) from None
            done = done + work
            if self.slack is not None:
                self._observe_slack(state)
        return state, done

    def _attempt(self, state, dt: float):
        """One step of the scheme: ``(state, iterations)``; raises NewtonFailure (a refused step)."""
        return self.scheme.step(self.cable_model, state, dt)

    def _observe_slack(self, state) -> None:
        """Hand the step's nodal tensions to the slack log (with the tolerance of :meth:`_compression`)."""
        tension, cable = state.y[:, 0], self.cable_model.cable
        scale = max(float(np.max(np.abs(tension))), abs(cable.params[k.W0]) * cable.length, 1.0)
        self.slack.observe(state.t, tension, self._facts(state).euler[0], COMPRESSION_TOLERANCE * scale)

    def _s(self, state) -> np.ndarray:
        """Arclength of the state's nodes (with a winch: at t = 0)."""
        s = getattr(state, "s", None)
        return self.cable_model.cable.s if s is None else s

    def _failure(self, failure: NewtonFailure, state) -> str:
        cable = self.cable_model.cable
        s = self._s(state)
        node = min(max(failure.node, 0), len(s) - 1)
        message = (f"{failure} at t = {state.t:.6g} s on cable '{cable.name}' near node {node} "
                   f"(s = {s[node]:.4g} m), even with the step cut to dt/{2 ** MAX_CUTS}; ")
        rows = cable.rows() if getattr(state, "rows", None) is None else state.rows
        allowed = euler_loads(rows)[0]
        lowest = int(np.argmin(state.y[:, 0]))
        if state.y[lowest, 0] < 0.0 and allowed[lowest] == 0:
            return message + (f"the cable went into compression (T = {state.y[lowest, 0]:.4g} N at node "
                              f"{lowest}), which a cable cannot carry: the continuum model needs it taut (or "
                              "bending stiffness). Slack and snapping cables run with model: lumped; or soften the "
                              "manoeuvre")
        if state.y[lowest, 0] < 0.0:
            return message + (f"the cable was in compression (T = {state.y[lowest, 0]:.4g} N at node {lowest}), "
                              "which its bending stiffness carries only up to the Euler load of one segment "
                              f"({allowed[lowest]:.4g} N there): a line going slack runs with model: lumped, which "
                              f"carries slack; or soften the manoeuvre, or try a smaller dt (now {self.dt:g} s)")
        return message + (f"try a smaller dt (now {self.dt:g} s), a more dissipative scheme (lambda_inf closer "
                          "to 0) or more segments")

    # 4. outputs ------------------------------------------------------------------------
    def outputs(self, state) -> dict:
        values = self.cable_model.outputs(state)
        track = self.cable_model.track
        vessel = track.tow_state(state.t)
        pitch = track.pitch(state.t)[0] if track.pitch is not None else 0.0
        facts = self._facts(state)
        rows, junctions = facts.rows, facts.junctions
        ends = values["position"][-1:] if self.body else np.zeros((0, 3))
        inline = values["position"][junctions] if len(junctions) else np.zeros((0, 3))
        extra = {}
        seabed = self.cable_model.cable.seabed             # None also where the line cannot reach it: 0 m
        if self.case.environment.depth is not None:        # on the nodes in the water, before a winch's stations
            extra["seabed_contact_length"] = np.array([0.0 if seabed is None else seabed_contact_length(
                seabed.penetration(values["position"]), rows[:, k.DS], facts.penetration[0])])
        extra.update(self._forces(state, junctions))
        if self.winch is not None:
            extra.update({"winch_tension": values["tension"][0], "winch_length": float(np.sum(rows[:, k.DS]))})
            values = self._on_stations(state, values)
        return {**values, "body_position": np.vstack([ends, inline]), "vessel_position": vessel.position,
                "vessel_heading": vessel.heading, "vessel_pitch": pitch, **extra}

    def _forces(self, state, junctions: np.ndarray) -> dict:
        """``anchor_force`` and ``body_force`` (:mod:`kanat.continuum.outputs`), where the case has anchors
        or bodies: the end body first, then the inline bodies, as ``body_position``."""
        if not self.anchor_ends and not self.body and not len(junctions):
            return {}
        force = self.cable_model.line_force(state)
        out = {"anchor_force": end_forces(force, self.anchor_ends)} if self.anchor_ends else {}
        if self.body or len(junctions):
            out["body_force"] = np.vstack([end_forces(force, ["to"] if self.body else []),
                                           inline_forces(force, junctions)])
        return out

    def _facts(self, state) -> RowFacts:
        """What the outputs and checks read of the state's interval rows (the cable's own, or a winch's)."""
        rows = getattr(state, "rows", None)
        if rows is None:
            return self._own
        if self._winch_facts is None or self._winch_facts.rows is not rows:      # one output's outputs and checks
            self._winch_facts = RowFacts(rows, self.cable_model.cable.seabed)
        return self._winch_facts

    def _on_stations(self, state, values: dict) -> dict:
        """Nodal outputs on the fixed material stations of a run with a winch (:func:`material_stations`):
        the nodes in the water at their stations, the others (on the drum) at the winch."""
        slots = np.searchsorted(self.stations, state.s[1:] - 1e-9 * self.cable_model.cable.length)
        out = {}
        for name, array in values.items():
            full = np.repeat(array[:1], len(self.stations), axis=0)
            full[slots] = array[1:]
            out[name] = full
        return out

    # 5. status ---------------------------------------------------------------------------
    def check(self, state, values: dict) -> str | None:
        if self.winch is not None:                           # the checks look at the nodes in the water
            values = self.cable_model.outputs(state)
        finite = self._finite(state, values)
        if finite is not None:                               # the other checks compare numbers: NaN passes them
            return finite
        slack = self._compression(state, values) if self.slack is None else None
        return slack or self._strain(state, values) or self._seabed(state, values) or self._dry(state, values)

    def _dry(self, state, values) -> str | None:
        """A buoyant node out of the water (:mod:`kanat.continuum.surface`), or, for Kaliukh &
        Vusatiuk's factorized schemes, which take the whole cable as submerged, any part above it;
        else None."""
        cable = self.cable_model.cable
        height = heights(values["position"], cable.sea, state.t)       # one elevation per output, for both
        length = self.dry.observe(self._s(state), height, state.t)
        if not isinstance(self.scheme, FamilyScheme) and length > ROUND_OFF:
            return (f"{length:.4g} m of cable '{cable.name}' is above the water surface at t = {state.t:.6g} s: "
                    f"scheme '{self.scheme.name}' (Kaliukh & Vusatiuk's factorized schemes) takes the whole cable "
                    "as submerged, with its weight in water, drag and added mass there too; use scheme: "
                    "generalized-alpha, which weighs that part in air")
        dry = dry_buoyant_node(self._facts(state).rows, height)
        if dry is None:
            return None
        node, height = dry
        return (f"node {node} of cable '{cable.name}' (s = {self._s(state)[node]:.4g} m), on its buoyant part, is "
                f"{height:.6g} m above the water surface at t = {state.t:.6g} s: the continuum model cannot float "
                "a line on the surface (an interval along it is wet or dry as a whole); put the tow point deeper "
                "or shorten the buoyant part so that it stays under water")

    def _finite(self, state, values) -> str | None:
        """A message naming the first node whose state or outputs are not finite (NaN or inf), or None."""
        arrays = [np.asarray(state.y).reshape(len(state.y), -1)]
        arrays += [np.asarray(v).reshape(len(state.y), -1) for v in values.values()
                   if np.ndim(v) and len(v) == len(state.y)]
        bad = ~np.all(np.isfinite(np.hstack(arrays)), axis=1)
        if not np.any(bad):
            return None
        node = int(np.flatnonzero(bad)[0])
        return (f"the state is not finite (NaN or inf) at t = {state.t:.6g} s on cable "
                f"'{self.cable_model.cable.name}' at node {node} (s = {self._s(state)[node]:.4g} m); reduce dt, "
                "use a more dissipative scheme (lambda_inf closer to 0) or refine the grid")

    def _compression(self, state, values) -> str | None:
        cable = self.cable_model.cable
        tension, t = values["tension"], state.t
        scale = max(float(np.max(np.abs(tension))), abs(cable.params[k.W0]) * cable.length, 1.0)
        facts = self._facts(state)
        rows, (allowed, interval) = facts.rows, facts.euler
        low = int(np.argmin(tension + allowed))
        if tension[low] + allowed[low] >= -COMPRESSION_TOLERANCE * scale:
            return None
        where = (f"the cable went into compression (T = {tension[low]:.4g} N) at t = {t:.6g} s on cable "
                 f"'{cable.name}' at node {low} (s = {self._s(state)[low]:.4g} m), ")
        if allowed[low] == 0:
            return where + ("which a perfectly flexible cable cannot carry (give the line bending_stiffness to model "
                            "it as a rod); slack and snapping cables run with model: lumped, or refine the grid (more "
                            "segments) or soften the manoeuvre")
        excess = -tension[low] - COMPRESSION_TOLERANCE * scale
        return where + rod_advice(rows[interval[low]], excess, float(np.sum(rows[:, k.DS])))

    def _strain(self, state, values) -> str | None:
        cable = self.cable_model.cable
        tension = values["tension"]
        facts = self._facts(state)
        strain = np.zeros(len(facts.rows))
        for which, p in facts.sections:
            nodes = strain_of(tension, p)                        # elementwise: as on the interval ends
            strain[which] = np.maximum(nodes[which], nodes[which + 1])
        high = int(np.argmax(strain))
        if strain[high] > self.max_strain:
            return (f"strain {strain[high]:.4g} (tension {max(tension[high], tension[high + 1]):.4g} N) at "
                    f"t = {state.t:.6g} s on cable '{cable.name}' near node {high} (s = {self._s(state)[high]:.4g} m) "
                    f"exceeds the line's limit {self.max_strain:g}; check axial_stiffness and the loads (speeds, "
                    "bodies), or set line_types.<name>.max_strain")
        return None

    def _seabed(self, state, values) -> str | None:
        cable = self.cable_model.cable
        seabed = cable.seabed
        if seabed is None:
            return None
        static, limit = self._facts(state).penetration
        depth = seabed.penetration(values["position"])
        deep = int(np.argmax(depth))
        if depth[deep] > limit:
            s = self._s(state)
            return (f"node {deep} of cable '{cable.name}' (s = {s[deep]:.4g} m) is {depth[deep]:.4g} m below the "
                    f"seabed at t = {state.t:.6g} s, more than {PENETRATION_FACTOR:g} times the contact model's "
                    f"static penetration ({static:.3g} m); it fell through: reduce dt, or raise "
                    "environment.seabed.stiffness or damping"
                    + ("" if isinstance(self.scheme, FamilyScheme) else
                       f" (scheme '{self.scheme.name}' applies no seabed contact: use generalized-alpha)"))
        return None

    # 6. finish ---------------------------------------------------------------------------
    def final(self, state) -> tuple[dict, dict]:
        """The slack events (``simulation.slack: continue``) as variables on dimension ``slack_event``,
        their count as attribute ``slack_events``, and a note naming the worst; a note on the cable
        above the water surface, if any (:class:`kanat.continuum.surface.DryLength`)."""
        dry = self.dry.note(self.cable_model.cable.name)
        if dry is not None:
            self.notes.append(dry)
        if self.slack is None:
            return {}, {}
        events = self.slack.events
        note = self.slack.note(self._s(state), self.cable_model.cable.name)
        if note is not None:
            self.notes.append(note)
        variables = {f"slack_{name}": (("slack_event",), events[:, j] if name != "node" else events[:, j].astype(int))
                     for j, name in enumerate(("start", "end", "node", "tension"))}
        return variables, {"slack_events": len(events)}


class RowFacts:
    """What the outputs and checks of a run read of a grid's interval rows, worked out once.

    Parameters
    ----------
    rows : ndarray, shape (n - 1, P)
        The grid's parameter rows (:mod:`kanat.continuum.grid`).
    seabed : SeabedContact or None

    Attributes
    ----------
    junctions : ndarray of int
        Intervals that join two sections at an inline body.
    euler : tuple of ndarray
        :func:`euler_loads` of the rows.
    sections : list of (ndarray of int, ndarray)
        Each section's intervals and its parameter row (its elastic law).
    penetration : tuple of float or None
        The contact model's static penetration ``w / (k_b d)`` [m] (the largest of the cable's
        intervals) and the depth below the seabed that fails a run; None without a seabed.
    """

    def __init__(self, rows: np.ndarray, seabed):
        self.rows = rows
        self.junctions = np.flatnonzero(rows[:, k.KIND] == k.JUNCTION)
        self.euler = euler_loads(rows)
        self.sections = []
        for value in sorted(set(rows[:, k.SECTION].tolist())):     # np.unique would import numpy.ma
            which = np.flatnonzero(rows[:, k.SECTION] == value)
            self.sections.append((which, rows[which[0]]))
        self.penetration = None
        if seabed is not None:
            cable_rows = rows[rows[:, k.DS] > 0]
            static = float(np.max(np.abs(cable_rows[:, k.W0]) / (seabed.stiffness * cable_rows[:, k.DIAM])))
            self.penetration = static, PENETRATION_FACTOR * static + 1e-3


def euler_column(ds, diameter):
    """The segment length an Euler load counts on: ``ds``, at least :data:`SLENDER_SEGMENT` diameters."""
    return np.maximum(ds, SLENDER_SEGMENT * diameter)


def rod_advice(row: np.ndarray, excess: float, length: float) -> str:
    """What to do about a compression beyond the Euler load of a segment of a line with bending stiffness.

    More segments resolve a finer buckle, and so carry more compression, only within reason: when the
    segment whose Euler load ``pi^2 EI / (2 ds)^2`` is ``excess`` is more than :data:`REFINEMENT_REACH`
    times shorter than the grid's, or shorter than :data:`SLENDER_SEGMENT` diameters, the line is
    going slack (a tow stopping: kilonewtons against a few newtons) and the advice is the lumped model.

    Parameters
    ----------
    row : ndarray, shape (P,)
        The parameter row of the interval that sets the limit (:mod:`kanat.continuum.grid`).
    excess : float
        Compression beyond the tolerated [N], > 0.
    length : float
        Unstretched length of the cable [m].
    """
    ds, ei, diameter = row[k.DS], row[k.EI], row[k.DIAM]
    euler = np.pi**2 * ei / (2 * euler_column(ds, diameter)) ** 2
    finer = ds * np.sqrt(euler / excess)                           # the segment whose Euler load it is
    if ds / finer <= REFINEMENT_REACH and finer >= SLENDER_SEGMENT * diameter:
        return (f"beyond the Euler load of one segment ({euler:.4g} N): the grid no longer resolves the buckled "
                f"line; use more segments (at most {finer:.3g} m long, now {ds:.3g} m), or soften the manoeuvre; "
                "slack and snapping cables run with model: lumped")
    whole = np.pi**2 * ei / length**2
    short = f", a segment counted {SLENDER_SEGMENT:g} diameters long" if ds < SLENDER_SEGMENT * diameter else ""
    return (f"{excess / whole:.3g} times the Euler load of the whole line (pi^2 EI / L^2 = {whole:.3g} N), beyond "
            f"that of one segment ({euler:.4g} N{short}) and of any reasonable grid (it would take segments of "
            f"{finer:.3g} m, now {ds:.3g} m, diameter {diameter:.3g} m): the line goes slack, which bending "
            "stiffness does not carry and more segments cannot resolve; slack and snapping cables run with "
            "model: lumped, which carries slack, or soften the manoeuvre")


def euler_loads(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Compression each node may carry: the Euler load ``pi^2 EI / (2 ds)^2`` of the weaker of its two
    intervals (a junction's zero-length interval sets no limit), ``ds`` taken as at least
    :data:`SLENDER_SEGMENT` diameters: a finer grid carried a tow's stop (5.2 kN against a 200 m line's
    Euler load of 0.012 N) on 10 cm segments of a 17 mm cable and said ``ok``.

    Parameters
    ----------
    rows : ndarray, shape (n - 1, P)
        The grid's parameter rows (:mod:`kanat.continuum.grid`), one per interval.

    Returns
    -------
    allowed : ndarray, shape (n,)
        [N]; 0 at nodes of a line without bending stiffness.
    interval : ndarray of int, shape (n,)
        The interval that sets it.
    """
    n = len(rows) + 1
    ds = rows[:, k.DS]
    if not np.any(rows[:, k.EI] > 0):
        return np.zeros(n), np.minimum(np.arange(n), n - 2)
    column = euler_column(ds, rows[:, k.DIAM])
    load = np.where(ds > 0, np.pi**2 * rows[:, k.EI] / np.maximum(2 * column, 1e-300) ** 2, np.inf)
    after, before = np.append(load, np.inf), np.insert(load, 0, np.inf)
    interval = np.where(after <= before, np.arange(n), np.arange(n) - 1)
    allowed = np.minimum(after, before)
    return np.where(np.isfinite(allowed), allowed, 0.0), interval
