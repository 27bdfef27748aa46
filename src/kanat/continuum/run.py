"""Running a planar continuum case: initial state, time loop, streamed results, checkpoints.

The run starts from the discrete steady state of the box equations for the initial
vessel velocity (found by Newton from the statics solution), so a run at constant speed
stays steady to round-off. Each output step appends to the result file; a checkpoint of
the full state is written beside it at most every ``CHECKPOINT_WALL_S`` seconds of wall
time, and ``resume=True`` continues a killed run from its last checkpoint to the same
answer. A step whose Newton iteration fails is cut in halves (up to
:data:`kanat.continuum.stepper.MAX_CUTS` levels); a run that still fails stops once, writes
its status and keeps everything computed so far.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.continuum.models import model_for
from kanat.continuum.schemes import ContinuumScheme
from kanat.continuum.stepper import MAX_CUTS, NewtonFailure, State
from kanat.errors import CaseError, Problem
from kanat.io.results import case_sha256, provenance
from kanat.io.stream import Checkpoint, ResultStream
from kanat.schemes import get_scheme

CHECKPOINT_WALL_S = 2.0
TIME_VARS = {"position": (("node", "xyz"), "m"), "velocity": (("node", "xyz"), "m/s"),
             "tension": (("node",), "N"), "body_position": (("body", "xyz"), "m"),
             "vessel_position": (("xyz",), "m"), "vessel_heading": ((), "rad"), "vessel_pitch": ((), "rad"),
             "newton_iterations": ((), "1")}


@dataclass(frozen=True)
class RunSummary:
    """What a run did: status, cost and Newton statistics."""

    status: str
    output: Path
    wall_time_s: float
    steps: int
    newton_iterations_mean: float
    step_cuts: int
    final: State | None = None

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def summary(self) -> str:
        return (f"{self.steps} steps in {self.wall_time_s:.2f} s wall time, {self.newton_iterations_mean:.2f} "
                f"Newton iterations per step, {self.step_cuts} step cuts; status: {self.status}")


def run(case, output, *, scheme=None, resume: bool = False, progress=None,
        checkpoint_every: int | None = None) -> RunSummary:
    """Run a ``model: continuum`` case, writing its result file as it goes (case-format.md).

    Parameters
    ----------
    case : kanat.model.Case
    output : path-like
        Result file (netCDF); its checkpoint is ``OUTPUT.ckpt.npz``.
    scheme : str or ContinuumScheme, optional
        Overrides ``simulation.scheme`` (default ``generalized-alpha``).
    resume : bool
        Continue a killed run from its checkpoint.
    progress : callable, optional
        ``progress(t, info)`` after every output step.
    checkpoint_every : int, optional
        Checkpoint every this many output steps (default: every ``CHECKPOINT_WALL_S`` of wall time).
    """
    sim = case.simulation
    if sim.dt is None:
        raise CaseError([Problem("simulation.dt", "the continuum model needs a time step dt [s]")])
    scheme = _scheme(case, scheme)
    model = model_for(case)
    dt, every = sim.dt, max(1, int(round(sim.output_interval / sim.dt)))
    total = int(round(sim.duration / dt))
    sha = case_sha256(case)
    start = time.perf_counter()
    if resume:
        ckpt = Checkpoint.load(output, sha)
        state = model.restore(ckpt.time, ckpt.state)
        done, iterations, cuts = ckpt.info["steps"], ckpt.info["iterations"], ckpt.info["cuts"]
        stream = ResultStream(output, None, TIME_VARS, resume_at=ckpt.outputs)
    else:
        state = model.initial()
        done, iterations, cuts = 0, 0, 0
        stream = ResultStream(output, _static(case, model, scheme), TIME_VARS)
        _write(stream, case, model, state, 0.0)
    status, last_checkpoint = "ok", time.perf_counter()
    try:
        while done < total:
            try:
                state, spent, cut = _advance(scheme, model, state, dt, 0)
            except NewtonFailure as failure:
                status = _failure_message(failure, state, model.cable, dt)
                break
            done, iterations, cuts = done + 1, iterations + spent, cuts + cut
            if done % every:
                continue
            _write(stream, case, model, state, spent)
            if progress is not None:
                progress(state.t, {"newton_iterations": iterations / done, "step_cuts": cuts})
            due = (done // every) % checkpoint_every == 0 if checkpoint_every else \
                time.perf_counter() - last_checkpoint > CHECKPOINT_WALL_S
            if due or done == total:
                stream.flush()
                Checkpoint(state.t, stream.count, sha, model.save(state),
                           {"steps": done, "iterations": iterations, "cuts": cuts}).save(output)
                last_checkpoint = time.perf_counter()
    except KeyboardInterrupt:
        stream.close(f"interrupted at t = {state.t:.6g} s; continue with --resume", steps=done)
        raise
    wall = time.perf_counter() - start
    mean = iterations / max(done, 1)
    stream.close(status, wall_time_s=wall, newton_iterations_mean=mean, step_cuts=cuts, steps=done)
    return RunSummary(status, Path(output), wall, done, mean, cuts, state)


def _advance(scheme, model, state, dt, level):
    """One step of ``dt``, cut into halves recursively when Newton fails (returns iterations, cuts)."""
    try:
        new, spent = scheme.step(model, state, dt)
        return new, spent, 0
    except NewtonFailure:
        if level >= MAX_CUTS:
            raise
    half, spent_a, cuts_a = _advance(scheme, model, state, dt / 2, level + 1)
    new, spent_b, cuts_b = _advance(scheme, model, half, dt / 2, level + 1)
    return new, spent_a + spent_b, 1 + cuts_a + cuts_b


def _failure_message(failure: NewtonFailure, state, cable, dt: float) -> str:
    message = (f"{failure} at t = {state.t:.6g} s on cable '{cable.name}' near node {failure.node} "
               f"(s = {failure.node * cable.ds:.4g} m), even with the step cut to dt/{2 ** MAX_CUTS}; ")
    lowest = int(np.argmin(state.y[:, 0]))
    if state.y[lowest, 0] < 0.0:
        return message + (f"the cable went into compression (T = {state.y[lowest, 0]:.4g} N at node {lowest}), "
                          "which a cable cannot carry: the continuum model needs it taut. Slack and snapping "
                          "cables run with model: lumped; or soften the manoeuvre")
    return message + (f"try a smaller dt (now {dt:g} s), a more dissipative scheme (lambda_inf closer to 0) "
                      "or more segments")


def _scheme(case, scheme) -> ContinuumScheme:
    sim = case.simulation
    chosen = get_scheme(scheme or sim.scheme or "generalized-alpha", "continuum",
                        lambda_inf=sim.lambda_inf, gamma=sim.gamma)
    return chosen


def _static(case, model, scheme) -> xr.Dataset:
    cable = model.cable
    bodies = [case.cables[0].to.name] if case.cables[0].to.kind == "body" else []
    attrs = provenance(case, model="continuum", scheme=scheme.name, wall_time_s=0.0, status="running",
                       dt=case.simulation.dt, dimensions=model.dimensions,
                       **{f"scheme_{k}": v for k, v in scheme.parameters().items()})
    return xr.Dataset({"s": ("node", cable.s), "cable": ("node", np.array([cable.name] * len(cable.s), dtype=object))},
                      coords={"xyz": ["x", "y", "z"], "body": np.array(bodies, dtype=object)}, attrs=attrs)


def _write(stream: ResultStream, case, model, state, iterations: int) -> None:
    values = model.outputs(state)
    vessel = model.track.state(state.t)
    body = values["position"][-1:] if case.cables[0].to.kind == "body" else np.zeros((0, 3))
    pitch = model.track.pitch(state.t)[0] if model.track.pitch is not None else 0.0
    stream.append(state.t, **values, body_position=body, vessel_position=vessel.position,
                  vessel_heading=vessel.heading, vessel_pitch=pitch, newton_iterations=iterations)
