"""kanat's front door: load a case, solve its statics, simulate it, read a result.

Every model runs through one table, :data:`MODELS`: the steady models (``statics``,
``pitch``) return their dataset at once; the dynamic ones (``continuum``, ``lumped``) are
built here and driven by the one run loop of :mod:`kanat.dynamics`, their outputs going
to an in-memory recorder or streamed to a netCDF file with checkpoints. The command line
and the parameter studies call these functions and nothing below them.

Examples
--------
>>> import kanat
>>> case = kanat.load_case("examples/speed_step_2d.yaml")
>>> longer = case.replace({"cables[0].length": 1200})          # a validated new case
>>> ds = kanat.simulate(longer)                                  # in memory, no file
>>> ds.tension.sel(time=600).plot(x="s")                         # doctest: +SKIP
"""
from __future__ import annotations

import functools
import logging
import time
import warnings
from dataclasses import dataclass
from functools import cached_property
from os import PathLike
from pathlib import Path
from typing import Any, Callable, Mapping

from kanat import dynamics
from kanat.errors import CaseError, KanatError, Problem, SolverError
from kanat.model import Case
from kanat.model.support import require_supported
from kanat.schemes import registry
from kanat.version import __version__


class RunFailedWarning(UserWarning):
    """A simulation that stopped before its end; its result says why in ``attrs["status"]``."""


@dataclass(frozen=True)
class Outcome:
    """What running a case gave.

    Attributes
    ----------
    status : str
        ``ok`` or ``failed: ...`` (also the dataset's ``status`` attribute).
    text : str
        A few lines for the terminal: the run summary, or the statics or pitch table.
    dataset : xarray.Dataset
        The result, built on first use: from the steady models' :class:`kanat.io.result_table.ResultTable`
        (``held``), or read back from ``output`` when the run wrote it there.
    held : xarray.Dataset, kanat.io.result_table.ResultTable or None
        The result in memory, if any.
    output : Path or None
    summary : kanat.dynamics.RunSummary or None
        Dynamic models only.
    solution : object or None
        Steady models only: the solver's own result (:class:`kanat.statics.StaticsResult`,
        :class:`kanat.vessel.pitch.PitchResult`), for pictures.
    """

    status: str
    text: str
    held: Any
    output: Path | None = None
    summary: dynamics.RunSummary | None = None
    solution: Any = None

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @cached_property
    def dataset(self):
        """The result: held in memory, or read from ``output``."""
        if self.held is None:
            return read_result(self.output)
        return self.held.to_dataset() if hasattr(self.held, "to_dataset") else self.held


# --- the steady models ------------------------------------------------------------------

def _statics(case: Case, method: str = "auto"):
    """The statics of ``case`` as the table its file holds (no xarray: ``kanat statics`` writes it
    directly), the summary, and the solver's result. The table's ``status`` is that of the checks
    of a steady state (:mod:`kanat.statics.steady_checks`); their warnings end the summary and are kept in
    the table's ``warnings`` attribute."""
    from kanat.io.statics_table import statics_table
    from kanat.statics import NeedsLumped
    from kanat.statics import solve_statics as solve

    start = time.perf_counter()
    try:
        result = solve(case, method=method)
    except NeedsLumped as reason:        # a network in a current (the catenary carries no drag), bending
        result = _lumped_statics(case, str(reason))
    verdict = result.verdict
    text = "\n".join([result.summary(), *(f"warning: {w}" for w in verdict.warnings)])
    table = statics_table(result, wall_time_s=time.perf_counter() - start, status=verdict.status,
                          warnings=verdict.warnings)
    return table, text, result


def _lumped_statics(case: Case, reason: str):
    """Network statics by the lumped model's equilibrium (statics may not import the lumped model)."""
    from kanat.lumped.equilibrium import equilibrium, relaxation_note
    from kanat.lumped.mooring_outputs import (anchor_forces, anchors_on_seabed, attitudes, contact_length,
                                              out_of_water)
    from kanat.lumped.network import build_network
    from kanat.statics.network_result import result_from_positions
    from kanat.statics.steady_checks import LUMPED_EQUILIBRIUM

    net = build_network(case)
    x, info = equilibrium(net, case)
    floating = out_of_water(case, net, x, None, 0.0)
    if floating is not None:
        raise SolverError(f"no steady state: {floating}")
    cables = {name: x[net.node_index[net.node_cable == name]] for name in net.cable_names}
    bodies = {name: x[node] for name, node in zip(net.body_names, net.body_node)}
    points = {name: x[node] for name, node in net.names.items() if name in case.points}
    seabed = case.environment.seabed
    on_seabed = anchors_on_seabed(net, case.environment)
    grounded = contact_length(net, info["normal_force"], on_seabed)
    anchors = anchor_forces(net, info["loads"], info["normal_force"], on_seabed,
                            0.0 if seabed is None else seabed.friction)
    return result_from_positions(case, cables, bodies, points, LUMPED_EQUILIBRIUM, info["iterations"],
                                 [f"solved by the lumped model's equilibrium: {reason}; with the segments the "
                                  "case gives, whose tensions converge as the segments are refined (rerun with "
                                  "more to check)",
                                  *([relaxation_note(info)] if "fallback" in info else [])],
                                 grounded=dict(zip(net.cable_names, grounded)),
                                 anchor_forces=dict(zip(net.anchor_names, anchors)),
                                 attitudes=dict(zip(net.body_names, attitudes(net, x))))


def _pitch_dataset(case: Case, method: str = "auto"):
    from kanat.io.results import pitch_dataset
    from kanat.vessel.pitch import solve_pitch

    if case.pitch is None:
        raise KanatError(f"case '{case.name}' has no 'pitch' block; the pitch model solves model: pitch cases")
    start = time.perf_counter()
    result = solve_pitch(case.pitch, name=case.name)
    return pitch_dataset(result, case, wall_time_s=time.perf_counter() - start), result.table(), result


def _continuum(case: Case, scheme=None, start=None):
    from kanat.continuum.adapter import ContinuumModel

    if start is not None and not isinstance(start, Case):
        raise CaseError([Problem("start", "the continuum model starts from a case's steady state (start=case); "
                                 "from a result's last output, only the lumped model does")])
    return ContinuumModel(case, scheme, start_from=start)


def _frequency(case: Case, method: str = "auto"):
    """The linear response of ``simulation.method: frequency`` (:func:`kanat.frequency.solve_frequency`)."""
    from kanat.frequency.solve import solve_frequency

    ds = solve_frequency(case)
    text = (f"frequency domain: {ds.sizes['frequency']} frequency(ies), {ds.attrs['iterations']} drag "
            f"iteration(s); largest tension std {float(ds.tension_std.max()):.4g} N; {ds.attrs['notes']}")
    return ds, text, None


def _lumped(case: Case, scheme=None, start=None):
    from kanat.lumped.adapter import LumpedModel

    return LumpedModel(case, scheme, start_from=start)


@dataclass(frozen=True)
class Steady:
    """A model solved at once: ``solve(case, method) -> (result, text, solution)``, the result an
    ``xarray.Dataset`` or a :class:`kanat.io.result_table.ResultTable` (written without xarray)."""

    solve: Callable


@dataclass(frozen=True)
class Dynamic:
    """A model run by :func:`kanat.dynamics.run`: ``build(case, scheme, start) -> DynamicModel``
    (``start``: None, or what :func:`run` documents)."""

    build: Callable


MODELS: dict[str, Steady | Dynamic] = {
    "statics": Steady(_statics),
    "pitch": Steady(_pitch_dataset),
    "continuum": Dynamic(_continuum),
    "lumped": Dynamic(_lumped),
}
"""Every model by its case-file name (``model:``). Each entry imports its model when it is
used, so a statics solve does not load the dynamic models' compiled kernels."""

FREQUENCY = Steady(_frequency)
"""A dynamic case with ``simulation.method: frequency``: its lumped model linearised about the
equilibrium and solved per frequency (docs/frequency.md)."""


def schemes() -> dict:
    """Every time scheme of every dynamic model, by its case-file name (``simulation.scheme``):
    the continuum registry (:data:`kanat.continuum.schemes.SCHEMES`) and the lumped one
    (:data:`kanat.lumped.integrators.SCHEMES`)."""
    from kanat.continuum.schemes import SCHEMES as CONTINUUM
    from kanat.lumped.integrators import SCHEMES as LUMPED

    return registry(*CONTINUUM.values(), *LUMPED.values())


def __getattr__(name):
    if name == "SCHEMES":                    # kanat.api.SCHEMES, built on first use
        return schemes()
    raise AttributeError(f"module 'kanat.api' has no attribute {name!r}")


# --- the front door ---------------------------------------------------------------------

def load_case(source: str | PathLike | Mapping, *, max_output_bytes: float | str | None = None,
              solver: str | None = None) -> Case:
    """A validated case from a file, YAML text or a mapping.

    Parameters
    ----------
    source : path-like, str or mapping
        A case file (YAML, or a MoorDyn input file), the YAML text of a case, or the case
        as nested dicts and lists (the YAML structure).
    max_output_bytes : float or str, optional
        The largest result a dynamic run may write (``"8G"``); default the environment
        variable ``KANAT_MAX_OUTPUT_BYTES``, else 2 GiB (docs/limits.md).
    solver : str, optional
        Check what this model supports instead of the case's own ``model`` (``"statics"``:
        the steady state of a dynamic case, as ``kanat statics`` does).

    Returns
    -------
    kanat.model.Case

    Raises
    ------
    kanat.errors.CaseError
        Every problem at once, with file, line and key path.

    Warns
    -----
    kanat.io.CaseWarning
        For a case that runs but probably not as meant.
    """
    from kanat.io import parse_case
    from kanat.io import load_case as load_file

    limit = {"max_output_bytes": max_output_bytes, "solver": solver}
    if isinstance(source, Mapping):
        import yaml

        return parse_case(yaml.safe_dump(dict(source), sort_keys=False), file="<dict>", **limit)
    if isinstance(source, str) and ("\n" in source or ":" in source and not Path(source).suffix):
        return parse_case(source, file="<text>", **limit)
    return load_file(source, **limit)


def _naming_its_file(function):
    """``function(case, ...)``, its case errors naming the case's file (:meth:`kanat.errors.CaseError.located`):
    problems found when a model is built from a case read earlier name no file of their own."""
    @functools.wraps(function)
    def front_door(case, *args, **kwargs):
        try:
            return function(case, *args, **kwargs)
        except CaseError as error:
            raise error.located(getattr(case, "source", None)) from None
    return front_door


@_naming_its_file
def solve_statics(case: Case, method: str = "auto"):
    """The steady state of a case, as the dataset ``kanat statics`` writes.

    Parameters
    ----------
    case : kanat.model.Case
        Any case with cables (its vessel's initial speed sets the flow), or a Naumov & Agievich
        ``sphere_two_cables`` problem.
    method : str
        ``auto``, ``shooting``, ``collocation`` or ``catenary``.

    Returns
    -------
    xarray.Dataset
        Positions, tensions and angles at the nodes, no ``time`` dimension.

    Raises
    ------
    kanat.errors.SolverError
        When no steady state is found (the message says what was tried).

    Warns
    -----
    RunFailedWarning
        When the steady state fails the checks of :mod:`kanat.statics.steady_checks`: the
        dataset is returned with ``attrs["status"]`` = ``failed: <check>: ...``.
    """
    require_supported(case, "statics")
    table = _statics(case, method)[0]
    _warn_failed(table.attrs["status"])
    return table.to_dataset()


def offset_table(case: Case, direction: float, to: float, steps: int = 20, each_body: bool = True):
    """The offset curves of ``case`` (:func:`offsets`) as the table ``kanat offsets`` writes, the
    system curve and each coupled body's own (dict by name, empty unless ``each_body`` and the case
    has several coupled bodies)."""
    from kanat.io.offsets_table import offsets_table
    from kanat.statics import NeedsLumped
    from kanat.statics.offsets import body_offset_curves, offset_curve

    require_supported(case, "statics")
    start = time.perf_counter()
    try:
        curve = offset_curve(case, direction, to, steps)
        bodies = body_offset_curves(case, direction, to, steps) if each_body else {}
    except NeedsLumped as reason:
        raise SolverError(f"offsets re-solve the catenary network statics, which this case is beyond: {reason}; "
                          "remove the current and the lines' bending stiffness for the offset curve") from None
    return offsets_table(curve, case, wall_time_s=time.perf_counter() - start, bodies=bodies), curve, bodies


@_naming_its_file
def offsets(case: Case, direction: float, to: float, steps: int = 20, each_body: bool = True):
    """Restoring force and line tensions of a moored vessel against its offset.

    The vessel (every cable end ``{vessel: [x, y, z]}``, and every coupled body of a MoorDyn
    file) moves rigidly by ``steps`` even steps from 0 to ``to`` metres along ``direction``
    degrees (from x towards y); the network statics is solved again at each offset
    (:mod:`kanat.statics.offsets`). With several coupled bodies, each body is also moved alone,
    the others held (MoorPy's ``setPosition`` of one body and ``solveEquilibrium``).

    Parameters
    ----------
    case : kanat.model.Case
        A network in still water with cables ending at the vessel.
    direction : float
        [deg].
    to : float
        Largest offset [m].
    steps : int
    each_body : bool
        Also each coupled body's own curve when the case has several (``steps + 1`` statics
        solutions per body); False: the system curve only.

    Returns
    -------
    xarray.Dataset
        ``restoring_force(offset, xyz)`` [N], ``restoring_moment(offset, xyz)`` [N m] about
        the vessel's moved origin, ``end_tension(offset, cable, end)`` [N]; with several
        coupled bodies, each body alone offset: ``body_restoring_force(body, offset, xyz)``,
        ``body_restoring_moment(body, offset, xyz)`` about its moved reference point,
        ``body_end_tension(body, offset, cable, end)``.

    Examples
    --------
    >>> case = kanat.load_case("examples/moordyn/three_leg_vessel_v1.dat")   # doctest: +SKIP
    >>> ds = kanat.offsets(case, direction=0.0, to=30.0, steps=15)         # doctest: +SKIP
    >>> ds.restoring_force.sel(xyz="x").plot(x="offset")                   # doctest: +SKIP
    >>> two = kanat.load_case("examples/moordyn/shared_two_bodies.dat")      # doctest: +SKIP
    >>> kanat.offsets(two, 0.0, 20.0).body_restoring_force.sel(body="body2", xyz="x")  # doctest: +SKIP
    """
    return offset_table(case, direction, to, steps, each_body)[0].to_dataset()


@_naming_its_file
def dynamic_model(case: Case, scheme=None, start=None):
    """The dynamic model of ``case`` from :data:`MODELS`, set up with ``scheme`` (and ``start``, as
    :func:`run` takes it).

    Raises
    ------
    kanat.errors.CaseError
        When the case uses a key the model does not support (:mod:`kanat.model.support`).
    """
    entry = MODELS.get(case.model)
    if not isinstance(entry, Dynamic):
        dynamic = ", ".join(k for k, v in MODELS.items() if isinstance(v, Dynamic))
        raise KanatError(f"model '{case.model}' is not a dynamic model; dynamic models: {dynamic}")
    require_supported(case, case.model)
    return entry.build(case, scheme, start)


@_naming_its_file
def run(case: Case, *, scheme=None, output=None, resume: bool = False, progress=None,
        checkpoint_every: int | None = None, observers=(), method: str = "auto", model: str | None = None,
        start=None) -> Outcome:
    """Run any case with a model of :data:`MODELS`; the command line's ``kanat run``.

    Parameters
    ----------
    case : kanat.model.Case
    scheme : str or kanat.schemes.Scheme, optional
        Dynamic models: overrides ``simulation.scheme``.
    output : path-like, optional
        Result file (netCDF). Dynamic runs stream into it as they go (``OUT.nc.part`` until
        they end) and checkpoint beside it; None keeps the result in memory only.
    resume : bool
        Continue a killed dynamic run from its checkpoint (needs ``output``).
    progress : callable, optional
        ``progress(t, info)`` after every output of a dynamic run.
    checkpoint_every : int, optional
        Checkpoint every so many outputs (default: every few seconds of wall time).
    observers : sequence, optional
        More observers of the dynamic run loop (:mod:`kanat.dynamics`).
    method : str
        Statics only: the statics method.
    model : str, optional
        Run the case with this model instead of its own (``statics`` for the steady state of
        a dynamic case).
    start : kanat.model.Case or xarray.Dataset, optional
        Dynamic models: start from this instead of the case's own initial state. A case: its
        steady (initial) state, which must have the same cables and grid (the same line in another
        current: the run is then the response to the change). A result of the lumped model of the
        same network: its last output's positions and velocities (a run continued in a changed
        sea, say). The run's time starts at 0 all the same.

    Returns
    -------
    Outcome

    Examples
    --------
    >>> calm = kanat.load_case("examples/subsurface_mooring.yaml")           # doctest: +SKIP
    >>> storm = calm.replace({"environment.current.profile": doubled})     # doctest: +SKIP
    >>> kanat.run(storm, start=calm)                                       # doctest: +SKIP
    """
    name = model or case.model
    entry = MODELS.get(name)
    if model is None and isinstance(entry, Dynamic) and _frequency_method(case):
        entry = FREQUENCY
    if entry is None:
        hint = (" To get the steady (initial) state of this case, run: kanat statics CASE -o OUT.nc"
                if "statics" in MODELS else "")
        raise KanatError(f"model '{name}' is not available in kanat {__version__} (available: "
                         f"{', '.join(MODELS)}).{hint}")
    require_supported(case, name)
    _check_checkpoint_every(checkpoint_every)
    if resume and output is None:
        raise KanatError("resume needs the result file of the run to continue (output)")
    if start is not None and not isinstance(entry, Dynamic):
        raise KanatError(f"start: model '{name}' solves a steady state; start applies to dynamic runs")
    if isinstance(start, Case):
        require_supported(start, name)
    if name == "lumped" and any(fix.release_at is not None for c in case.cables for fix in (c.end_a, c.end_b)):
        if entry is FREQUENCY:
            raise KanatError("simulation.method: frequency linearises about one equilibrium; a release_at "
                             "changes the system during the run: use method: time")
        if resume:
            raise KanatError("resume: a run with release_at writes its result at the end and keeps no "
                             "checkpoint; run it again")
        return _run_released(case, scheme, output, progress, observers, start)
    build = functools.partial(entry.build, start=start) if isinstance(entry, Dynamic) else None
    entry = Dynamic(build) if build is not None else entry
    if output is None:
        return _run(entry, case, name, None, scheme, resume, progress, checkpoint_every, observers, method)
    from kanat.io.outputs import OutputLock, check_output_file

    output = check_output_file(output)
    with OutputLock(output):                    # a second run on this output is refused, not interleaved
        return _run(entry, case, name, output, scheme, resume, progress, checkpoint_every, observers, method)


def _run_released(case: Case, scheme, output, progress, observers, start) -> Outcome:
    """:func:`run` of a lumped case with ends released at a time: its phases one after the other,
    each from the last output of the one before (:mod:`kanat.lumped.release`), joined on the run's
    clock. The joined result is written to ``output`` at the end (no checkpoints, no resume); the
    ``observers`` and the returned summary see each phase on its own clock (``progress`` is told
    the run's time)."""
    from kanat.lumped import release

    release.refuse_start(start)
    parts, texts, summary = [], [], None
    for phase in release.phases(case):
        start = parts[-1][1] if parts else None
        outcome = run(release.phase_case(case, phase, start), scheme=scheme, progress=_shifted(progress, phase.start),
                      observers=observers, start=start)
        summary = outcome.summary
        parts.append((phase, outcome.dataset))
        let_go = f" after releasing {', '.join(phase.released)} at t = {phase.start:g} s" if phase.released else ""
        texts.append(f"phase from t = {phase.start:g} s{let_go}: {release.on_run_clock(outcome.status, phase.start)}")
        if not outcome.ok:
            break
    dataset = release.join(case, parts)
    dataset.attrs["release_phases"] = "; ".join(texts)
    status = dataset.attrs.get("status", summary.status)
    if output is not None:
        from kanat.io.results import write_result

        write_result(dataset, output)
    text = "\n".join([*texts, release.on_run_clock(summary.summary(), parts[-1][0].start)])
    return Outcome(status, text, dataset, None if output is None else Path(output), summary)


def _shifted(progress, start: float):
    """``progress`` told the run's time in a phase that starts at ``start``."""
    if progress is None:
        return None
    return lambda t, info: progress(t + start, info)


def _frequency_method(case: Case) -> bool:
    """Whether a case asks for the frequency domain (``simulation.method: frequency``)."""
    return case.simulation is not None and case.simulation.method == "frequency"


def _check_checkpoint_every(every) -> None:
    """``checkpoint_every`` is None or a whole number of outputs, at least 1."""
    if every is None:
        return
    if isinstance(every, bool) or not isinstance(every, int) or every < 1:
        raise KanatError(f"checkpoint_every must be a whole number of outputs, at least 1 (got "
                         f"{every!r}); leave it out to checkpoint every "
                         f"{dynamics.CHECKPOINT_WALL_S:g} s of wall time")


def _run(entry, case, name, output, scheme, resume, progress, checkpoint_every, observers, method) -> Outcome:
    """:func:`run` once the output (if any) is checked and locked."""
    if isinstance(entry, Steady):
        return _steady(entry, case, name, output, method)
    from kanat.io.provenance import case_hashes
    from kanat.io.stream import ResultStream

    recorder = dynamics.Recorder() if output is None else None
    sinks = [recorder] if recorder is not None else [ResultStream(output)]
    checkpointer = None
    if output is not None:
        current, earlier = case_hashes(case)
        checkpointer = dynamics.Checkpointer(output, current, checkpoint_every, before=sinks, accepted=(earlier,))
        sinks.append(checkpointer)
    if progress is not None:
        sinks.append(dynamics.Progress(progress))
    def build():
        model = entry.build(case, scheme)
        _announce_compile(model)
        return model

    summary = dynamics.run(build, [*sinks, *observers],
                           resume=checkpointer if resume else None, output=output)
    dataset = recorder.dataset() if recorder is not None else None
    if not summary.ok:
        warnings.warn(f"the run stopped: {summary.status}", RunFailedWarning, stacklevel=2)
    return Outcome(summary.status, summary.summary(), dataset, None if output is None else Path(output), summary)


def _announce_compile(model) -> None:
    """Log "compiling ... kernels once, ~N s" before a run whose kernels are not cached yet
    (:func:`kanat.warmup.pending` reads numba's cache index: milliseconds)."""
    from kanat import warmup

    cable_model = getattr(model, "cable_model", None)
    grid = getattr(cable_model, "grid", None)
    family = warmup.family_name(model.scheme.name, getattr(cable_model, "dimensions", 2),
                                bending=grid is not None and grid.bending)
    estimate = warmup.pending(family)
    if estimate is not None:
        logging.getLogger("kanat").warning(
            f"compiling the {family} kernels once (cached for later runs; `kanat warmup` does it ahead), "
            f"~{estimate:.0f} s of CPU")


def simulate(case: Case, scheme=None, output=None, resume: bool = False, progress=None, start=None):
    """Run a case with its model and return its result.

    Parameters
    ----------
    case : kanat.model.Case
        Any model: ``continuum`` and ``lumped`` run in time; ``statics`` and ``pitch``
        solve their steady state.
    scheme : str or kanat.schemes.Scheme, optional
        Overrides ``simulation.scheme`` (a name of :func:`schemes`, or
        a scheme object such as ``GeneralizedAlpha(lambda_inf=-0.3)``).
    output : path-like, optional
        None: the result stays in memory and no file is written. A path: the run streams
        its result there as it goes, with checkpoints, and the dataset is read back.
    resume : bool
        Continue a killed run from its checkpoint beside ``output``.
    progress : callable, optional
        ``progress(t, info)`` after every output step.
    start : kanat.model.Case or xarray.Dataset, optional
        Start from another case's steady state or a lumped result's last output (:func:`run`).

    Returns
    -------
    xarray.Dataset
        The result of case-format.md; ``attrs["status"]`` is ``ok`` or says why the run
        stopped (then the outputs up to the failure are kept, and a
        :class:`RunFailedWarning` is issued).
    """
    return run(case, scheme=scheme, output=output, resume=resume, progress=progress, start=start).dataset


def read_result(path):
    """A result file as an ``xarray.Dataset`` (fully loaded, file closed).

    A file whose ``status`` is ``ok`` but which holds a non-finite value is refused: it
    cannot be a sound result.

    Parameters
    ----------
    path : path-like
        A netCDF file written by ``kanat run``, ``kanat statics``, :func:`simulate` or
        :func:`solve_statics` (names: ``docs/reference/case-format.md``, "Result file").

    Returns
    -------
    xarray.Dataset
        With coordinates ``time`` (dynamic results), ``s`` and ``cable`` (per node) and the
        case in ``attrs["case_yaml"]``.

    Raises
    ------
    kanat.errors.KanatError
        The file is missing, is not a kanat result, or is marked ``ok`` but holds a NaN.
    """
    from kanat.io.results import read_result as read

    return read(path)


def case_of(result) -> Case:
    """The case a result was computed from (its ``case_yaml`` attribute), validated again.

    Parameters
    ----------
    result : xarray.Dataset or path-like
        A result, or its file.

    Raises
    ------
    kanat.errors.KanatError
        When the result does not carry its case (written before kanat embedded it).
    """
    from kanat.io.provenance import same_case

    attrs = result.attrs if hasattr(result, "attrs") else read_result(result).attrs
    text = attrs.get("case_yaml")
    if not text:
        raise KanatError("this result does not carry its case (no case_yaml attribute); run its case file instead")
    case = load_case(text)
    if attrs.get("case_sha256") is not None and not same_case(attrs["case_sha256"], case):
        raise KanatError("the case embedded in this result does not match its case_sha256: the file was edited")
    return case


# --- helpers ----------------------------------------------------------------------------

def _steady(entry: Steady, case: Case, name: str, output, method: str) -> Outcome:
    from kanat.io.statics_table import failed_table

    start = time.perf_counter()
    try:
        result, text, solution = entry.solve(case, method)
    except KanatError as error:
        if output is not None and not isinstance(error, CaseError):
            _write_steady(failed_table(case, str(error), model=name, scheme=method,
                                       wall_time_s=time.perf_counter() - start), output)
        raise
    except KeyboardInterrupt:                   # Ctrl-C: the file says so, as a dynamic run's does
        if output is not None:
            elapsed = time.perf_counter() - start
            failed_table(case, f"interrupted after {elapsed:.1f} s, before a steady state was found",
                         model=name, scheme=method, wall_time_s=elapsed).write(output)
        raise
    if output is not None:
        _write_steady(result, output)
    status = getattr(result, "attrs", {}).get("status", "ok")
    _warn_failed(status)
    return Outcome(status, text, result, None if output is None else Path(output), solution=solution)


def _warn_failed(status: str) -> None:
    """A :class:`RunFailedWarning` for a steady result that failed its checks (it is returned all the same)."""
    if status != "ok":
        warnings.warn(f"the steady state failed its checks: {status}", RunFailedWarning, stacklevel=3)


def _write_steady(result, output) -> None:
    """Write a steady model's result (atomically: a write that fails leaves no file)."""
    from kanat.errors import OutputWriteError

    try:
        if hasattr(result, "write"):                 # a statics table: no xarray
            result.write(output)
        else:
            from kanat.io.results import write_result

            write_result(result, output)
    except OutputWriteError as error:
        raise OutputWriteError(f"{output} was not written: {error}; free some space and solve again") from None
    except OSError as error:
        raise OutputWriteError(f"{output} was not written ({error}); free some space and solve again") from error
