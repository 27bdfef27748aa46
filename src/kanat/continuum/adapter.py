"""The continuum model behind the run loop's contract (:mod:`kanat.dynamics`).

:class:`ContinuumModel` wraps the planar or the spatial cable (:mod:`kanat.continuum.models`)
and a scheme of the generalized-α family or seed 000's factorized schemes. It steps
``dt`` at a time; a step whose Newton iteration fails is cut in halves (up to
:data:`kanat.continuum.stepper.MAX_CUTS` levels) before the run stops with a message
saying where and what to try. Its checks of every output: no compression (the continuum
model needs a taut cable), strain within the line type's range, no node below the seabed
(the continuum model has no seabed contact yet).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.courant import check_step
from kanat.continuum.models import model_for
from kanat.continuum.model2d import strain_of
from kanat.continuum.schemes import SCHEMES, ContinuumScheme
from kanat.continuum.stepper import MAX_CUTS, NewtonFailure
from kanat.dynamics import StepFailure, Steps
from kanat.errors import CaseError, Problem, SolverError
from kanat.io.results import provenance
from kanat.io.schema import Layout
from kanat.schemes import get_scheme

COMPRESSION_TOLERANCE = 1e-3
"""Compression beyond this fraction of the largest tension (or of the cable's weight) fails a run."""
TIME_VARIABLES = ("position", "velocity", "tension", "body_position", "vessel_position", "vessel_heading",
                  "vessel_pitch", "newton_iterations")


class ContinuumModel:
    """A ``model: continuum`` case ready to run (the contract of :mod:`kanat.dynamics`).

    Parameters
    ----------
    case : kanat.model.Case
    scheme : str or ContinuumScheme, optional
        Overrides ``simulation.scheme`` (default ``generalized-alpha``).
    """

    name = "continuum"

    def __init__(self, case, scheme=None):
        sim = case.simulation
        if sim.dt is None:
            raise CaseError([Problem("simulation.dt", "the continuum model needs a time step dt [s]")])
        self.case = case
        self.scheme: ContinuumScheme = get_scheme(scheme or sim.scheme or "generalized-alpha", SCHEMES,
                                                  lambda_inf=sim.lambda_inf, gamma=sim.gamma)
        self.cable_model = model_for(case)
        self.dt, self.output_interval, self.duration = sim.dt, sim.output_interval, sim.duration
        self.notes: list[str] = []
        self.max_strain = case.line_types[case.cables[0].line_type].strain_limit()
        self.body = case.cables[0].to.kind == "body"

    # 1. set up ------------------------------------------------------------------------
    def layout(self) -> Layout:
        cable, case = self.cable_model.cable, self.case
        bodies = [case.cables[0].to.name] if self.body else []
        attrs = provenance(case, model=self.name, scheme=self.scheme.name, dt=self.dt,
                           dimensions=self.cable_model.dimensions, output_interval=self.output_interval,
                           **{f"scheme_{k}": v for k, v in self.scheme.parameters().items()})
        return Layout({"s": (("node",), cable.s), "cable": (("node",), [cable.name] * len(cable.s))},
                      {"xyz": ("x", "y", "z"), "body": bodies}, TIME_VARIABLES, attrs)

    # 2. initial state and checkpoints ------------------------------------------------------
    def initial(self):
        try:
            state = self.cable_model.initial()
        except SolverError as error:
            raise SolverError(
                f"{error}. Tried: the case's statics, then Newton on the steady box equations from it. The "
                "continuum model needs a taut cable from the start; a slack, grounded or compressed line runs "
                "with model: lumped, which carries slack (kanat statics CASE shows the steady shape)") from None
        check_step(self.scheme, self.cable_model, state, self.dt)
        return state

    def save(self, state) -> dict:
        return {"t": np.array(state.t), **self.cable_model.save(state)}

    def restore(self, arrays: dict):
        return self.cable_model.restore(float(arrays["t"]), arrays)

    # 3. step -----------------------------------------------------------------------------
    def advance(self, state, t_end: float):
        steps = int(round((t_end - state.t) / self.dt))
        done = Steps()
        for _ in range(steps):
            try:
                state, work = self._step(state, self.dt, 0)
            except NewtonFailure as failure:
                raise StepFailure(self._failure(failure, state)) from None
            done = done + work
        return state, done

    def _step(self, state, dt: float, level: int):
        """One step of ``dt``, cut into halves recursively when Newton fails."""
        try:
            new, spent = self.scheme.step(self.cable_model, state, dt)
            return new, Steps(1, spent, 0)
        except NewtonFailure:
            if level >= MAX_CUTS:
                raise
        half, first = self._step(state, dt / 2, level + 1)
        new, second = self._step(half, dt / 2, level + 1)
        return new, Steps(1, first.iterations + second.iterations, 1 + first.cuts + second.cuts)

    def _failure(self, failure: NewtonFailure, state) -> str:
        cable = self.cable_model.cable
        message = (f"{failure} at t = {state.t:.6g} s on cable '{cable.name}' near node {failure.node} "
                   f"(s = {failure.node * cable.ds:.4g} m), even with the step cut to dt/{2 ** MAX_CUTS}; ")
        lowest = int(np.argmin(state.y[:, 0]))
        if state.y[lowest, 0] < 0.0:
            return message + (f"the cable went into compression (T = {state.y[lowest, 0]:.4g} N at node "
                              f"{lowest}), which a cable cannot carry: the continuum model needs it taut. Slack "
                              "and snapping cables run with model: lumped; or soften the manoeuvre")
        return message + (f"try a smaller dt (now {self.dt:g} s), a more dissipative scheme (lambda_inf closer "
                          "to 0) or more segments")

    # 4. outputs ------------------------------------------------------------------------
    def outputs(self, state) -> dict:
        values = self.cable_model.outputs(state)
        track = self.cable_model.track
        vessel = track.state(state.t)
        pitch = track.pitch(state.t)[0] if track.pitch is not None else 0.0
        body = values["position"][-1:] if self.body else np.zeros((0, 3))
        return {**values, "body_position": body, "vessel_position": vessel.position,
                "vessel_heading": vessel.heading, "vessel_pitch": pitch}

    # 5. status ---------------------------------------------------------------------------
    def check(self, state, values: dict) -> str | None:
        cable = self.cable_model.cable
        tension, t = values["tension"], state.t
        scale = max(float(np.max(np.abs(tension))), abs(cable.params[k.W0]) * cable.length, 1.0)
        low = int(np.argmin(tension))
        if tension[low] < -COMPRESSION_TOLERANCE * scale:
            return (f"the cable went into compression (T = {tension[low]:.4g} N) at t = {t:.6g} s on cable "
                    f"'{cable.name}' at node {low} (s = {cable.s[low]:.4g} m), which the continuum model cannot "
                    "carry; slack and snapping cables run with model: lumped, or refine the grid (more "
                    "segments) or soften the manoeuvre")
        strain = strain_of(tension, cable.params)
        high = int(np.argmax(strain))
        if strain[high] > self.max_strain:
            return (f"strain {strain[high]:.4g} (tension {tension[high]:.4g} N) at t = {t:.6g} s on cable "
                    f"'{cable.name}' at node {high} (s = {cable.s[high]:.4g} m) exceeds the line's limit "
                    f"{self.max_strain:g}; check axial_stiffness and the loads (speeds, bodies), or set "
                    "line_types.<name>.max_strain")
        depth = self.case.environment.depth
        if depth is not None:
            z = values["position"][:, 2]
            deep = int(np.argmin(z))
            if z[deep] < -depth * (1.0 + 1e-9):
                return (f"node {deep} of cable '{cable.name}' (s = {cable.s[deep]:.4g} m) is {-depth - z[deep]:.4g} "
                        f"m below the seabed at t = {t:.6g} s; the continuum model has no seabed contact: run "
                        "moorings that touch the seabed with model: lumped")
        return None

    # 6. finish ---------------------------------------------------------------------------
    def final(self, state) -> tuple[dict, dict]:
        return {}, {}

