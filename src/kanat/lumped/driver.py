"""Run a lumped case: equilibrium, time stepping, streamed results, checkpoints, resume.

:func:`run` is the model's entry point for ``kanat run`` (``model: lumped``). A run
starts from the network equilibrium (SPEC §4) with every node moving at the vessel's
initial velocity, steps with the chosen scheme, appends one result slice per output
interval, checkpoints its complete state (scheme history and snap tracker included) and,
on ``resume=True``, continues from the last checkpoint to the same answer as an
uninterrupted run. A failure (non-finite state, failed implicit solve, element stretched
beyond ``MAX_STRAIN``) stops the run once; the file keeps every slice written and its
``status`` says what happened, where, and what to try.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import KanatError, SolverError
from kanat.io.results import case_sha256, provenance
from kanat.io.stream import Checkpoint, ResultStream
from kanat.lumped import kernels, stepping
from kanat.lumped.advance import advance
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.integrators import state_positions
from kanat.lumped.network import build_network
from kanat.lumped.output import TIME_VARS, NodeTension, output_slice, static_dataset, write_events
from kanat.lumped.snap import SnapTracker
from kanat.lumped.system import LumpedSystem
from kanat.schemes import get_scheme, scheme_classes

MAX_STRAIN = 0.5               # an element stretched beyond 50 % stops the run
CHECKPOINT_WALL_S = 10.0       # wall time between checkpoints (and at the end of every run)


@dataclass
class RunSummary:
    """What a run did (the result file has the rest).

    Attributes
    ----------
    status : str
        ``ok`` or ``failed: <message>``.
    wall_time_s : float
    steps : int
        Time steps taken (all of them, across resumes).
    snap_events : int
    scheme : str
    dt : float
        Step used [s].
    axial_period : float
        Shortest axial nodal period at the start [s].
    notes : list of str
        Decisions taken for the user (scheme chosen, step reduced for stability).
    """

    status: str
    wall_time_s: float
    steps: int
    snap_events: int
    scheme: str
    dt: float
    axial_period: float
    output_path: str
    notes: list = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def summary(self) -> str:
        """A few lines for the terminal."""
        lines = [f"lumped run: {self.status}",
                 f"  scheme {self.scheme}, dt {self.dt:.4g} s (shortest axial nodal period "
                 f"{self.axial_period:.4g} s), {self.steps} steps in {self.wall_time_s:.3g} s",
                 f"  snap events (slack -> taut): {self.snap_events}",
                 *(f"  note: {n}" for n in self.notes), f"  results: {self.output_path}"]
        return "\n".join(lines)


def _choose(case, scheme, info, notes):
    sim = case.simulation
    spec = scheme if scheme is not None else sim.scheme
    if spec is None:
        chosen = stepping.choose_scheme(info, sim.step_or_default, scheme_classes("lumped"))
        chosen = get_scheme(chosen.name, "lumped", lambda_inf=sim.lambda_inf)
        notes.append(f"no scheme named: chose {chosen.name} as the fastest safe one")
        return chosen
    return get_scheme(spec, "lumped", lambda_inf=sim.lambda_inf)


def _step_size(case, scheme, info, notes) -> float:
    sim = case.simulation
    out = sim.output_interval
    if not scheme.explicit:
        if sim.dt is None:
            notes.append(f"{scheme.name}: no dt given; stepping at the default {sim.step_or_default:g} s")
        return stepping.fit_step(sim.step_or_default, out)
    safe = info.safe_step(scheme)
    if sim.dt is None:
        notes.append(f"{scheme.name}: no dt given; stepping at the safe step {safe:.3g} s")
        return stepping.fit_step(safe, out)
    h = stepping.fit_step(min(sim.dt, safe), out)
    if safe < sim.dt:
        notes.append(f"{scheme.name}: dt {sim.dt:g} s exceeds the safe step {safe:.3g} s "
                     f"({stepping.SAFETY} x stability limit / highest axial frequency, shortest axial nodal "
                     f"period {info.axial_period:.3g} s); stepping at {h:.4g} s")
    return h


def _check(system, x, T, t) -> str | None:
    """A failure message, or None when the state is sound."""
    net = system.net
    bad = ~np.all(np.isfinite(x), axis=1)
    if np.any(bad):
        return (f"the state became non-finite (NaN/inf) at t = {t:.6g} s at {net.where(int(np.flatnonzero(bad)[0]))}; "
                "reduce dt, use scheme generalized-alpha-lumped, or raise axial_damping")
    strain = np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1) / net.el_length - 1.0
    k = int(np.argmax(strain))
    if strain[k] > MAX_STRAIN:
        return (f"element stretched by {100 * strain[k]:.3g} % (> {100 * MAX_STRAIN:g} %) at t = {t:.6g} s in "
                f"{net.element_where(k)} (tension {T[k]:.4g} N); check axial_stiffness and the loads, "
                "or reduce dt")
    return None


class _Run:
    """State of one run (kept small: the loop lives in :func:`run`)."""

    def __init__(self, case, system, scheme, h):
        self.case, self.system, self.scheme, self.h = case, system, scheme, h
        net = system.net
        self.T = np.zeros(net.n_elements)
        self.node_tension = NodeTension(net)

    def tensions(self, state):
        s = self.system
        x, v, _, heading = s.full(state["t"], *state_positions(state))
        net = s.net
        kernels.tensions(x, v, net.el_i, net.el_j, net.el_length, net.el_damping, net.el_law, net.law_kind,
                         net.law_n, net.law_x, net.law_y, self.T)
        return x, v, heading

    def element_tensions(self, state):
        """Element tensions (m,) of a state."""
        self.tensions(state)
        return self.T

    def slice(self, state):
        x, v, heading = self.tensions(state)
        position = self.system.vessel(state["t"])[0]
        return output_slice(self.system.net, self.node_tension, x, v, self.T, position, heading), x


def _initial_state(case, net, system, scheme, h):
    sim = case.simulation
    x = equilibrium(net, case)[0] if sim.initial_state == "equilibrium" else net.x_guess.copy()
    velocity = system.vessel(0.0)[1]
    free = system.free_index
    return scheme.start(system, 0.0, x[free], np.broadcast_to(velocity, (len(free), 3)).copy(), h)


def _start(case, system, chosen, info, notes, output_path, case_hash, resume):
    """The state to step from: the initial equilibrium, or the checkpoint of a killed run.
    Returns ``(state, snap_state, h, steps, outputs, step_info)``."""
    net, sim = system.net, case.simulation
    if not resume:
        h = _step_size(case, chosen, info, notes)
        return _initial_state(case, net, system, chosen, h), None, h, 0, 0, info
    ckpt = Checkpoint.load(output_path, case_hash)
    state, snap = _restore(ckpt)
    info = stepping.step_info(net, system.full(state["t"], *state_positions(state))[0],
                              sim.mass_matrix == "consistent")
    h = _step_size(case, chosen, info, notes)
    system.evaluations = ckpt.info["evaluations"]
    return state, snap, h, ckpt.info["steps"], ckpt.outputs, info


def _save(path, case_hash, outputs, state, tracker, steps, evaluations):
    arrays = {f"scheme_{k}": np.asarray(v) for k, v in state.items()}
    arrays.update({f"snap_{k}": v for k, v in tracker.state().items()})
    Checkpoint(float(state["t"]), outputs, case_hash, arrays, {"steps": steps, "evaluations": evaluations}).save(path)


def _restore(ckpt):
    state = {k[7:]: (v.item() if v.ndim == 0 and k[7:] in ("t", "iterations") else v)
             for k, v in ckpt.state.items() if k.startswith("scheme_")}
    snap = {k[5:]: v for k, v in ckpt.state.items() if k.startswith("snap_")}
    return state, snap


def run(case, output_path, *, scheme=None, resume: bool = False, progress=None,
        checkpoint_every: int | None = None, stop_after: float | None = None) -> RunSummary:
    """Run a lumped case and stream its results to ``output_path`` (netCDF).

    Parameters
    ----------
    case : kanat.model.Case
        With ``model: lumped``.
    output_path : path-like
    scheme : str or kanat.schemes.Scheme, optional
        Overrides ``simulation.scheme``; None and none in the case: the fastest safe one.
    resume : bool
        Continue from the checkpoint beside ``output_path``.
    progress : callable, optional
        ``progress(t, info)`` after every output slice; ``info`` has ``step``, ``outputs``,
        ``snap_events``, ``max_tension``.
    checkpoint_every : int, optional
        Checkpoint every so many outputs (default: every ``CHECKPOINT_WALL_S`` of wall time).
    stop_after : float, optional
        Stop (as if killed) after this simulated time, leaving the checkpoint (for tests).

    Returns
    -------
    RunSummary
    """
    if case.model != "lumped" or case.simulation is None:
        raise KanatError(f"kanat.lumped.run needs a case with model: lumped and a simulation block "
                         f"(got model '{case.model}')")
    start_wall = time.perf_counter()
    sim, net = case.simulation, build_network(case)
    system = LumpedSystem(net, case, sim.mass_matrix)
    info = stepping.step_info(net, net.x_guess, sim.mass_matrix == "consistent")
    notes: list[str] = []
    chosen = _choose(case, scheme, info, notes)
    case_hash = case_sha256(case)
    outputs_total = int(round(sim.duration / sim.output_interval))
    state, snap, h, steps, outputs, info = _start(case, system, chosen, info, notes, output_path, case_hash,
                                                  resume)
    runner = _Run(case, system, chosen, h)
    attrs = provenance(case, model="lumped", scheme=chosen.name, wall_time_s=0.0, status="running",
                       dt=h, dt_case=sim.dt if sim.dt is not None else "", axial_period=info.axial_period, mass_matrix=sim.mass_matrix,
                       **{f"scheme_{k}": v for k, v in chosen.parameters().items()})
    stream = ResultStream(output_path, static_dataset(net, attrs), TIME_VARS,
                          resume_at=outputs if resume else None)
    first_slice, _ = runner.slice(state)
    tracker = SnapTracker(state["t"], runner.T, snap)
    if not resume:
        stream.append(0.0, **first_slice)
        outputs = 1
    per_output = int(round(sim.output_interval / h))
    status, last_ckpt = "ok", time.perf_counter()
    try:
        while outputs <= outputs_total:
            state, taken = advance(chosen, system, state, h, per_output, tracker,
                                   runner.element_tensions)
            steps += taken
            values, x = runner.slice(state)
            failure = _check(system, x, runner.T, state["t"])
            if failure:
                status = f"failed: {failure}"
                break
            stream.append(outputs * sim.output_interval, **values)
            outputs += 1
            if progress is not None:
                progress(state["t"], {"step": steps, "outputs": outputs, "snap_events": tracker.count,
                                      "max_tension": float(runner.T.max(initial=0.0))})
            due = (outputs % checkpoint_every == 0) if checkpoint_every else (
                time.perf_counter() - last_ckpt > CHECKPOINT_WALL_S)
            if due or outputs > outputs_total:
                _save(output_path, case_hash, outputs, state, tracker, steps, system.evaluations)
                last_ckpt = time.perf_counter()
            if stop_after is not None and state["t"] >= stop_after - 1e-9 and outputs <= outputs_total:
                stream.close("running")                   # as if killed: status stays 'running'
                return RunSummary("killed", time.perf_counter() - start_wall, steps, tracker.count,
                                  chosen.name, h, info.axial_period, str(output_path), notes)
    except SolverError as error:
        status = f"failed: {error}"
    wall = time.perf_counter() - start_wall
    extra = {"newton_iterations_mean": state["iterations"] / max(steps, 1)} if "iterations" in state else {}
    stream.close(status, wall_time_s=wall, steps=steps, force_evaluations=system.evaluations,
                 snap_events=tracker.count, notes="; ".join(notes), **extra)
    write_events(output_path, tracker.events())
    return RunSummary(status, wall, steps, tracker.count, chosen.name, h, info.axial_period,
                      str(output_path), notes)
