"""One run loop for every dynamic model, and the observers of its results (style rules 8, 11).

A *dynamic model* (the continuum model's :class:`kanat.continuum.adapter.ContinuumModel`,
the lumped model's :class:`kanat.lumped.adapter.LumpedModel`, or a user's own) is any
object that keeps this contract:

1. **Set up.** It is built from a validated case and a scheme, and has decided how it
   will step: attributes ``name`` (the model's name), ``scheme`` (a
   :class:`kanat.schemes.Scheme`), ``dt`` (the step [s]), ``output_interval`` [s],
   ``duration`` [s], ``notes`` (decisions taken for the user, as sentences), and
   ``layout()`` returning the :class:`kanat.io.schema.Layout` of its result (the
   time-independent variables, the names of its time series, the provenance).
2. **Initial state.** ``initial()`` returns the state at ``t = 0`` (or raises
   :class:`kanat.errors.SolverError` saying what was tried and what to do);
   ``save(state)`` returns a dict of arrays and ``restore(arrays)`` the state again,
   exactly, for checkpoints.
3. **Step.** ``advance(state, t_end)`` takes the steps from the state's time to the
   output time ``t_end`` and returns ``(state, Steps)``; when a step cannot be taken it
   raises :class:`StepFailure` with a message naming time, cable, node and what to try.
   States are values: the loop never looks inside them.
4. **Outputs.** ``outputs(state)`` returns the time series named in its layout, as arrays
   shaped as :mod:`kanat.io.schema` says.
5. **Status.** ``check(state, values)`` returns ``None`` when the output passes the
   model's own checks (strain within the line's range, no compression where the model
   needs tension, no node below the seabed beyond the contact model's penetration), else
   the failure message. The loop also refuses any non-finite output, and makes the
   checks of a steady state that ``check`` does not make on the initial state of a model
   built from a case (``model.case``): tension and reach
   (:data:`kanat.statics.steady_checks.LEFT_BY_DYNAMIC_MODELS`).
6. **Finish.** ``final(state)`` returns ``(variables, attributes)`` written once at the end
   (snap events, counters); variables as ``name -> (dims, values)``.

:func:`run` drives a model from its initial state (or a checkpoint) to its duration and
hands every output to its observers — :class:`kanat.io.stream.ResultStream` (the file),
:class:`Recorder` (in memory), :class:`Checkpointer`, :class:`Progress`, or any object
with ``start``, ``record``, ``flush`` and ``finish`` (an observer may stop the run by
raising :class:`StopRun`). A run that fails stops once, keeps
everything computed so far and says why in ``status``; a result is ``ok`` only when every
output passed the checks.
"""
from __future__ import annotations

import logging
import math
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Protocol, Sequence

import numpy as np

from kanat import jit
from kanat.errors import OutputWriteError, SolverError
from kanat.statics.budget import BudgetExceeded
from kanat.io.schema import Layout, to_dataset
from kanat.io.stream import Checkpoint
from kanat.statics.diagnose import steady_failure
from kanat.statics.steady_checks import LEFT_BY_DYNAMIC_MODELS, check_steady, nodes_by_cable
from kanat.schemes import label
from kanat.step_control import Steps

log = logging.getLogger(__name__)

CHECKPOINT_WALL_S = 5.0
"""Wall time between checkpoints [s] (every model; ``checkpoint_every`` counts outputs instead)."""


class StepFailure(SolverError):
    """A step that cannot be taken; the message says when, where and what to try."""


class StopRun(Exception):
    """Raised by an observer's ``record`` to stop a run (its message becomes the status)."""


class DynamicModel(Protocol):
    """The contract of the module docstring, for type checkers and readers."""

    name: str
    scheme: object
    dt: float
    output_interval: float
    duration: float
    notes: list

    def layout(self) -> Layout: ...
    def initial(self): ...
    def advance(self, state, t_end: float) -> tuple[object, Steps]: ...
    def outputs(self, state) -> dict: ...
    def check(self, state, values: dict) -> str | None: ...
    def save(self, state) -> dict: ...
    def restore(self, arrays: dict): ...
    def final(self, state) -> tuple[dict, dict]: ...


@dataclass(frozen=True)
class Point:
    """One output, as observers see it.

    Attributes
    ----------
    index : int
        Output number (0 is the initial state).
    time : float
        [s].
    values : dict of str to ndarray
        The model's outputs.
    state : object
        The model's state (opaque; for checkpoints and studies that look inside).
    steps : Steps
        Work done since the start of the run.
    model : DynamicModel
    """

    index: int
    time: float
    values: dict
    state: object
    steps: Steps
    model: object


@dataclass(frozen=True)
class RunSummary:
    """What a run did; the result (file or dataset) has the rest.

    Attributes
    ----------
    status : str
        ``ok``, or ``failed: <why, where, what to try>``, or ``interrupted ...``.
    model, scheme : str
    dt : float
        Step [s].
    steps, outputs : int
    step_cuts : int
    newton_iterations_mean : float or None
        Implicit schemes only.
    wall_time_s : float
        The whole run: set up, initial state, steps, outputs [s].
    setup_time_s : float
        Model set-up and initial state, compiling excluded [s].
    solver_time_s : float
        The time loop's steps, compiling excluded [s].
    compile_time_s : float
        Compiling (or loading cached) kernels [s].
    notes : tuple of str
    output : Path or None
    """

    status: str
    model: str
    scheme: str
    dt: float
    steps: int
    outputs: int
    step_cuts: int
    newton_iterations_mean: float | None
    wall_time_s: float
    setup_time_s: float
    solver_time_s: float
    compile_time_s: float
    notes: tuple = ()
    output: Path | None = None
    extra: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def attributes(self) -> dict:
        """The summary as result-file attributes."""
        out = {"wall_time_s": self.wall_time_s, "setup_time_s": self.setup_time_s,
               "solver_time_s": self.solver_time_s, "compile_time_s": self.compile_time_s,
               "steps": self.steps, "step_cuts": self.step_cuts, "notes": "; ".join(self.notes)}
        if self.newton_iterations_mean is not None:
            out["newton_iterations_mean"] = self.newton_iterations_mean
        return {**out, **self.extra}

    def summary(self) -> str:
        """A few lines for the terminal (the same for every model)."""
        newton = (f", {self.newton_iterations_mean:.2f} Newton iterations per step"
                  if self.newton_iterations_mean is not None else "")
        lines = [f"{self.model} model, scheme {self.scheme}, dt {self.dt:.4g} s: {self.steps} steps{newton}, "
                 f"{self.step_cuts} step cuts",
                 f"time: solver {self.solver_time_s:.2f} s, set-up {self.setup_time_s:.2f} s, compiling "
                 f"{self.compile_time_s:.2f} s; whole run {self.wall_time_s:.2f} s",
                 *(f"{k.replace('_', ' ')}: {v}" for k, v in self.extra.items()),
                 *(f"note: {n}" for n in self.notes),
                 f"status: {self.status}"]
        return "\n".join(lines)


class Recorder:
    """Observer keeping every output in memory; :meth:`dataset` is the result as the file holds it."""

    def __init__(self):
        self._layout: Layout | None = None
        self._times: list[float] = []
        self._values: list[dict] = []
        self._end: tuple[dict, dict] = ({}, {})

    def start(self, layout: Layout, resume_at: int | None = None) -> None:
        if resume_at is not None:
            raise SolverError("an in-memory run cannot resume; give an output file to resume from")
        self._layout = layout

    def record(self, point: Point) -> None:
        self._times.append(point.time)
        self._values.append(point.values)

    def flush(self) -> None:
        """Nothing to write."""

    def finish(self, status: str, final: dict, attrs: dict) -> None:
        self._end = (final, {**attrs, "status": status})

    def dataset(self):
        """The result as an ``xarray.Dataset`` (same names, coordinates and attributes as the file)."""
        layout = self._layout
        series = {name: (np.stack([v[name] for v in self._values]) if self._values
                         else np.zeros((0,) + _shape(layout, name)))
                  for name in layout.time_variables}
        final, attrs = self._end
        return to_dataset(layout, self._times, series, final, attrs)


def _shape(layout: Layout, name: str) -> tuple:
    from kanat.io.schema import VARIABLES

    sizes = layout.sizes()
    return tuple(sizes[d] for d in VARIABLES[name].dims)


class Progress:
    """Observer calling ``callback(t, info)`` after every output; ``info`` holds ``steps``,
    ``step_cuts`` and, for implicit schemes, ``newton_iterations`` (mean per step)."""

    def __init__(self, callback: Callable[[float, dict], None]):
        self.callback = callback

    def start(self, layout: Layout, resume_at: int | None = None) -> None:
        """Nothing to prepare."""

    def record(self, point: Point) -> None:
        s = point.steps
        info = {"steps": s.steps, "step_cuts": s.cuts}
        if s.iterations:
            info["newton_iterations"] = s.iterations / max(s.steps, 1)
        self.callback(point.time, info)

    def flush(self) -> None:
        """Nothing to write."""

    def finish(self, status: str, final: dict, attrs: dict) -> None:
        """Nothing to close."""


class Checkpointer:
    """Observer saving the model's state beside the result file, to resume a killed run.

    Every ``every`` outputs, or every :data:`CHECKPOINT_WALL_S` of wall time when ``every``
    is None. The observers in ``before`` (the result stream) are flushed first, so the
    file holds every output the checkpoint counts. A checkpoint records the case's hash
    and the scheme (name and parameters); resuming with another refuses.

    Parameters
    ----------
    path : path-like
        The result file; the checkpoint is ``PATH.ckpt.npz``.
    case_sha256 : str
        The case's hash, written into the checkpoints (:func:`kanat.io.provenance.case_sha256`).
    every : int, optional
    before : sequence of observers
    accepted : tuple of str
        Other hashes a checkpoint of the same case may carry (the form earlier releases wrote,
        :func:`kanat.io.provenance.case_hashes`).
    """

    def __init__(self, path, case_sha256: str, every: int | None = None, before=(), accepted=()):
        self.path, self.case_sha256, self.accepted = Path(path), case_sha256, tuple(accepted)
        self.every, self.before = every, tuple(before)
        self._last = time.perf_counter()
        self._saved_at: float | None = None

    def load(self, model) -> Checkpoint:
        """The checkpoint to resume ``model`` from (refusing another case or scheme)."""
        return Checkpoint.load(self.path, self.case_sha256, label(model.scheme), self.accepted)

    def start(self, layout: Layout, resume_at: int | None = None) -> None:
        self._last = time.perf_counter()

    def record(self, point: Point) -> None:
        if point.index == 0:
            return
        due = (point.index % self.every == 0) if self.every else (
            time.perf_counter() - self._last > CHECKPOINT_WALL_S)
        if not due:
            return
        for observer in self.before:
            observer.flush()
        s = point.steps
        Checkpoint(point.time, point.index + 1, self.case_sha256, label(point.model.scheme),
                   point.model.save(point.state),
                   {"steps": s.steps, "iterations": s.iterations, "cuts": s.cuts}).save(self.path)
        self._last = time.perf_counter()
        self._saved_at = point.time

    def kept(self) -> str:
        """Where a run stopped by a write error continues from, for its message."""
        path = Checkpoint.path_for(self.path)
        if self._saved_at is not None:
            return f"{path} the state at t = {self._saved_at:.6g} s"
        if path.exists():
            return f"{path} the state it held before this run"
        return "no checkpoint was written yet (--resume will start afresh)"

    def flush(self) -> None:
        """Nothing buffered."""

    def finish(self, status: str, final: dict, attrs: dict) -> None:
        """The stream removes the checkpoint of a run that ends ``ok``."""


class CompileClock:
    """Seconds numba has spent compiling since this clock was made: ``clock[0]``, read at any time
    (:data:`kanat.jit.COMPILE_SECONDS`; stays 0 in a run whose kernels were compiled at install)."""

    def __init__(self):
        self.start = jit.COMPILE_SECONDS[0]

    def __getitem__(self, index: int) -> float:
        if index != 0:
            raise IndexError(index)
        return jit.COMPILE_SECONDS[0] - self.start


@contextmanager
def compile_clock():
    """A :class:`CompileClock` for the block."""
    yield CompileClock()


def run(build: Callable[[], DynamicModel], observers: Sequence = (), *, resume: Checkpointer | None = None,
        output: Path | None = None) -> RunSummary:
    """Run a dynamic model to its duration, handing every output to ``observers``.

    Parameters
    ----------
    build : callable
        ``build() -> DynamicModel`` (set-up is timed as part of the run).
    observers : sequence
        Objects with ``start(layout, resume_at)``, ``record(point)``, ``flush()`` and
        ``finish(status, final, attrs)``, called in order.
    resume : Checkpointer, optional
        Continue from this checkpointer's checkpoint instead of the initial state.
    output : Path, optional
        Recorded in the summary.

    Returns
    -------
    RunSummary
    """
    start = time.perf_counter()
    with compile_clock() as compiled:
        model = build()
        _log_setup(model)
        try:
            index, state, done = _first(model, resume)
        except (SolverError, BudgetExceeded) as error:
            return _failed_start(model, observers, error, start, compiled[0], output)
        layout = model.layout()
        log.info(("initial state found" if resume is None else
                  f"resumed from the checkpoint at t = {index * model.output_interval:.6g} s")
                 + f" ({_counts(layout)}) after {time.perf_counter() - start:.2f} s")
        for observer in observers:
            observer.start(layout, None if resume is None else index + 1)
        setup = time.perf_counter() - start
        setup_compile = compiled[0]
        solver, status = 0.0, "ok"
        last = int(round(model.duration / model.output_interval))
        try:
            with _interrupt_between_outputs() as interrupted:
                if resume is None:
                    status = _emit(model, layout, observers, Point(0, 0.0, _values(model, layout, state, Steps()),
                                                                   state, done, model))
                while status == "ok" and index < last:
                    if interrupted[0]:
                        raise KeyboardInterrupt
                    index += 1
                    t_end = index * model.output_interval
                    began, compiling = time.perf_counter(), compiled[0]
                    try:
                        state, work = model.advance(state, t_end)
                    except StepFailure as failure:
                        status = f"failed: {failure}"
                        break
                    finally:
                        solver += time.perf_counter() - began - (compiled[0] - compiling)
                    done = done + work
                    status = _emit(model, layout, observers, Point(index, t_end, _values(model, layout, state, work),
                                                                   state, done, model))
        except KeyboardInterrupt:
            summary = _summary(model, f"interrupted at t = {index * model.output_interval:.6g} s; continue with "
                               "--resume", done, index, start, setup - setup_compile, solver, compiled[0], output)
            _finish(observers, summary, {})
            raise
        except OutputWriteError as error:
            raise _write_failure(error, index * model.output_interval, observers) from None
        final, extra = model.final(state)
        summary = _summary(model, status, done, index, start, setup - setup_compile, solver, compiled[0], output,
                           extra)
    try:
        _finish(observers, summary, final)
    except OutputWriteError as error:
        raise _write_failure(error, model.duration, observers) from None
    return summary


@contextmanager
def _interrupt_between_outputs():
    """Ctrl-C (SIGINT) during a run, taken between two outputs: ``[True]`` once it came, and the run loop
    raises :class:`KeyboardInterrupt` at the next output. Python raises it wherever the signal lands
    otherwise, and where that is a finalizer (a weakref callback of h5py or numba) it is printed and
    dropped ("Exception ignored"), and the run went on to the end. Only the main thread can take
    signals; elsewhere nothing changes."""
    import signal
    import threading

    came = [False]
    if threading.current_thread() is not threading.main_thread():
        yield came
        return

    def note(signum, frame):
        came[0] = True

    previous = signal.signal(signal.SIGINT, note)
    try:
        yield came
    finally:
        signal.signal(signal.SIGINT, previous)


def _write_failure(error: OutputWriteError, t: float, observers) -> OutputWriteError:
    """The one sentence of a run stopped because its files could not be written: why, what the
    files keep, how to continue. Every observer's file is closed as a kill would leave it."""
    for observer in observers:
        abandon = getattr(observer, "abandon", None)
        if abandon is not None:
            abandon()
    kept = [observer.kept() for observer in observers if hasattr(observer, "kept")]
    return OutputWriteError(f"the run stopped at t = {t:.6g} s because {error}; " + " and ".join(kept)
                            + "; free some space and continue with --resume")


def _log_setup(model) -> None:
    """Log what the model decided: scheme, step, outputs, and its notes."""
    log.info(f"{model.name} model, scheme {label(model.scheme)}, dt {model.dt:.4g} s, an output every "
             f"{model.output_interval:g} s to t = {model.duration:g} s")
    for note in model.notes:
        log.info(f"note: {note}")


def _counts(layout: Layout) -> str:
    """``101 nodes, 1 body``: the sizes of a result's node, segment and body dimensions."""
    sizes = layout.sizes()
    plural = {"node": "nodes", "segment": "segments", "body": "bodies"}
    return ", ".join(f"{sizes[d]} {d if sizes[d] == 1 else plural[d]}" for d in plural if sizes.get(d))


def _first(model, resume: Checkpointer | None):
    """``(index, state, steps)`` to start from: the initial state or the checkpoint."""
    if resume is None:
        return 0, model.initial(), Steps()
    ckpt = resume.load(model)
    info = ckpt.info
    return ckpt.outputs - 1, model.restore(ckpt.state), Steps(info["steps"], info["iterations"], info["cuts"])


def _values(model, layout: Layout, state, work: Steps) -> dict:
    """The model's outputs, and the loop's own ``newton_iterations`` when the layout has it."""
    values = model.outputs(state)
    if "newton_iterations" in layout.time_variables:
        values["newton_iterations"] = work.iterations
    return values


def _emit(model, layout: Layout, observers, point: Point) -> str:
    """Check an output and hand it to the observers: ``ok`` or the failure.

    An output that fails the model's checks is still recorded when it is finite (it shows
    what went wrong); a non-finite one is not.
    """
    non_finite = _non_finite(layout, point)
    problem = non_finite or model.check(point.state, point.values)
    if not problem and point.index == 0:
        problem = _initial_problem(model, layout, point.values)
    if not non_finite:
        try:
            for observer in observers:
                observer.record(point)
        except StopRun as stop:
            problem = problem or str(stop)
    return f"failed: {problem}" if problem else "ok"


def _initial_problem(model, layout: Layout, values: dict) -> str | None:
    """The checks of a steady state that a model's ``check`` does not make
    (:data:`kanat.statics.steady_checks.LEFT_BY_DYNAMIC_MODELS`) on the initial state of a model
    built from a case (``model.case``) whose outputs hold node positions and tensions; their
    warnings are logged. None when it passes (or the model has no case or no such outputs); the
    checks know a start ``as_given`` is no steady state (``check_steady(..., start=True)``)."""
    case = getattr(model, "case", None)
    if case is None or not {"position", "tension"} <= values.keys() or not {"s", "cable"} <= layout.static.keys():
        return None
    nodes = nodes_by_cable(layout.static["cable"][1], layout.static["s"][1], values["position"], values["tension"])
    names = [str(name) for name in layout.labels.get("body", ())]
    bodies = dict(zip(names, np.reshape(values.get("body_position", np.zeros((0, 3))), (-1, 3))))
    attitudes = dict(zip(names, np.reshape(values["body_attitude"], (-1, 3)))) if "body_attitude" in values else None
    verdict = check_steady(case, nodes, when="the initial state (t = 0)", only=LEFT_BY_DYNAMIC_MODELS,
                           bodies=bodies, attitudes=attitudes, start=True)
    for warning in verdict.warnings:
        log.warning(warning)
    return verdict.failure


def _non_finite(layout: Layout, point: Point) -> str | None:
    """A message naming the first non-finite output, or None."""
    for name, values in point.values.items():
        if _finite(values):
            continue
        values = np.asarray(values)
        where = ""
        if values.ndim and "s" in layout.static and len(values) == len(layout.static["s"][1]):
            node = int(np.flatnonzero(~np.all(np.isfinite(values.reshape(len(values), -1)), axis=1))[0])
            where = (f" at node {node} (cable '{layout.static['cable'][1][node]}', s = "
                     f"{layout.static['s'][1][node]:.4g} m)")
        return (f"the state became non-finite (NaN or inf) at t = {point.time:.6g} s in {name}{where}; "
                "reduce dt, use an implicit scheme, or refine the grid")
    return None


def _finite(values) -> bool:
    """Whether every entry of an output is finite: ``np.isfinite(...).all()`` of an array, ``math.isfinite``
    of a Python or NumPy scalar, without NumPy's function dispatch (every output of a run passes here)."""
    if type(values) is np.ndarray:
        return bool(np.isfinite(values).all())
    if isinstance(values, (float, int, np.floating, np.integer)):
        return math.isfinite(values)
    return bool(np.all(np.isfinite(np.asarray(values))))


def _summary(model, status, done: Steps, index, start, setup, solver, compiling, output, extra=None) -> RunSummary:
    iterations = done.iterations / max(done.steps, 1) if done.iterations else None
    return RunSummary(status, model.name, model.scheme.name, model.dt, done.steps, index + 1, done.cuts, iterations,
                      time.perf_counter() - start, setup, solver, compiling, tuple(model.notes),
                      None if output is None else Path(output), dict(extra or {}))


def _finish(observers, summary: RunSummary, final: dict) -> None:
    for observer in observers:
        observer.finish(summary.status, final, summary.attributes())


def _failed_start(model, observers, error, start, compiling, output) -> RunSummary:
    """A run whose initial state could not be found: a result with no time step, saying why."""
    layout = model.layout()
    for observer in observers:
        observer.start(layout, None)
    case = getattr(model, "case", None)
    why = steady_failure(case) if case is not None and not isinstance(error, BudgetExceeded) else None
    if why is not None:
        error = f"the case's steady state fails its checks ({why}); the {model.name} model's own start: {error}"
    summary = _summary(model, f"failed: no initial state: {error}", Steps(), -1, start,
                       time.perf_counter() - start - compiling, 0.0, compiling, output)
    _finish(observers, summary, {})
    return summary
