"""Cable ends released at a time (``cables[].end_a/end_b: {release_at: SECONDS}``) in the lumped model.

A release splits a run into phases at the release times. Each phase is the case with the ends
released so far turned ``free`` (a free node of the same network: the node count does not
change) and its ``duration`` the phase's length; it starts from the last output of the phase
before (:func:`kanat.lumped.adapter.start_state`: every node's position and velocity), so the
end lets go with the place and velocity it had. :func:`phases` plans them and :func:`join`
puts their results back on the run's own clock; ``kanat.run`` runs them one after the other.

The equations of motion do not change at a release: the prescribed node's row becomes a free
node's, eq. (1) of :mod:`kanat.lumped.system`, with the end's half element's mass and loads.
"""
from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.io.provenance import case_sha256, case_yaml
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem

TIME_RTOL = 1e-9      # relative tolerance of a release time on the output grid
VESSEL_VARIABLES = ("vessel_position", "vessel_heading", "vessel_pitch")
SUMMED_ATTRIBUTES = ("steps", "step_cuts", "force_evaluations", "explicit_steps", "snap_events", "wall_time_s",
                     "solver_time_s", "setup_time_s", "compile_time_s")


@dataclass(frozen=True)
class Phase:
    """One stretch of a run between releases.

    Attributes
    ----------
    start : float
        The run's time at the phase's start [s] (the phase's own clock starts at 0).
    changes : dict
        The phase's changes to the case (:meth:`kanat.model.Case.replace`): the ends released
        before ``start`` made ``free``, ``duration`` the phase's length.
    released : tuple of str
        The ends let go at ``start`` (``"cable 'tow' end_b (vessel)"``), for the run's notes.
    """

    start: float
    changes: dict
    released: tuple[str, ...] = ()


def releases(case) -> list[tuple[float, int, str]]:
    """``(time, cable index, "end_a" | "end_b")`` of every end the case releases, in time order."""
    found = [(getattr(cable, key).release_at, i, key) for i, cable in enumerate(case.cables)
             for key in ("end_a", "end_b") if getattr(cable, key).release_at is not None]
    return sorted(found)


def phases(case) -> list[Phase]:
    """The phases of a run with releases (one phase, the case itself, without any), each with the
    case it runs before its start state is known (:func:`phase_case` places its bodies).

    Raises
    ------
    kanat.errors.CaseError
        When a release is not on the output grid or not within the run, or the case has forcing
        that depends on time after a release (waves, a ramped current, a moving vessel still
        holding a cable): a phase's clock starts at 0, so it would start that forcing over.
    """
    events = releases(case)
    if not events:
        return [Phase(0.0, {})]
    _check(case, events)
    times = sorted({t for t, _, _ in events})
    out, start = [], 0.0
    edits = {f"cables[{i}].{key}": {} for _, i, key in events}      # each phase runs without releases
    for t in [*times, case.simulation.duration]:
        if t > start:
            let_go = tuple(_label(case, i, key) for tr, i, key in events if tr == start)
            out.append(Phase(start, {**edits, "simulation.duration": t - start}, let_go))
        for tr, i, key in events:
            if tr == t:
                edits[f"cables[{i}].{'from' if key == 'end_a' else 'to'}"] = "free"
        start = t
    return out


def phase_case(case, phase: Phase, before=None):
    """The case of ``phase``: ``case`` with the phase's changes, and every 3-DOF body and every point
    placed where ``before`` (the result of the phase before; None for the first) last had it, so
    that a network no end of which is held any more still has a first guess.

    Parameters
    ----------
    case : kanat.model.Case
    phase : Phase
    before : xarray.Dataset or None
    """
    changes = dict(phase.changes)
    if before is not None:
        last = before.isel(time=-1)
        for k, name in enumerate(last.body.values if "body" in last.dims else ()):
            if str(name) in case.bodies and case.bodies[str(name)].dof == 3:
                changes[f"bodies.{name}.position"] = [float(c) for c in last.body_position.values[k]]
    with warnings.catch_warnings():              # the case's own checks warned once already
        warnings.simplefilter("ignore")
        return case.replace(changes) if changes else case


def _label(case, i: int, key: str) -> str:
    cable = case.cables[i]
    end = cable.from_ if key == "end_a" else cable.to
    return f"cable '{cable.name}' {key} ({end})"


def _check(case, events) -> None:
    sim, env = case.simulation, case.environment
    problems = []
    for t, i, key in events:
        where = ("cables", i, key, "release_at")
        steps = t / sim.output_interval
        if t >= sim.duration:
            problems.append(Problem(where, f"release_at {t:g} s is not before the run's end "
                                           f"(simulation.duration {sim.duration:g} s)"))
        elif abs(steps - round(steps)) > TIME_RTOL * max(steps, 1.0):
            problems.append(Problem(where, f"release_at {t:g} s is not a multiple of the output interval "
                                           f"{sim.output_interval:g} s; release on an output time"))
    first = events[0][0]
    rigid = [name for name, body in case.bodies.items() if body.dof == 6]
    if rigid:
        problems.append(Problem(("bodies", rigid[0], "dof"), "a body with dof: 6 and a release: a phase starts "
                                "from the last output of the one before, which does not keep a rigid body's "
                                "rotation rates"))
    if env.waves is not None:
        problems.append(Problem(("environment", "waves"), "waves with a release: a phase after a release "
                                "would start the waves over; leave the waves out or the release"))
    if env.current.ramp > 0.0:
        problems.append(Problem(("environment", "current", "ramp"), "a ramped current with a release: a phase "
                                "after a release would start the ramp over; set the ramp to 0"))
    moving = case.vessel.motion is not None or case.vessel.track
    held = [c.name for c in case.cables for end, fix in ((c.from_, c.end_a), (c.to, c.end_b))
            if end.kind == "vessel" and (fix.release_at is None or fix.release_at > first)]
    if moving and held:
        problems.append(Problem(("vessel",), f"a moving vessel still holds cable '{held[0]}' after the release "
                                f"at t = {first:g} s: a phase after a release would start its track and motion "
                                "over; release every vessel end at the same time or hold the vessel still"))
    if problems:
        raise CaseError(problems)


def join(case, parts) -> "xarray.Dataset":  # noqa: F821
    """The run's result from its phases' results, on the run's clock.

    Parameters
    ----------
    case : kanat.model.Case
        The case as written (with its releases).
    parts : list of (Phase, xarray.Dataset)
        Each phase and its result; the last may have stopped early.

    Returns
    -------
    xarray.Dataset
        Outputs of every phase, times shifted by the phase's start (a later phase's first output,
        at the release, is the earlier phase's last and is dropped); an anchor let go has no
        ``anchor_force`` (NaN) after its release; the vessel's outputs are the case's vessel at the
        run's times; snap events on the run's clock; the last phase's attributes but for the case
        itself (``case_yaml``, ``case_sha256``: the case as written, with its releases) and for the
        implicit scheme's error estimate (``time_error_*``), the phase's with the largest (eq. (3), of the
        phases' starts, apart).
    """
    import xarray as xr

    pieces, events = [], []
    for k, (phase, ds) in enumerate(parts):
        timed = ds[[v for v in ds.data_vars if "time" in ds[v].dims]].assign_coords(time=ds.time + phase.start)
        pieces.append(timed if k == 0 else timed.isel(time=slice(1, None)))
        untimed = ds[[v for v in ds.data_vars if "event" in ds[v].dims]]
        events.append(untimed.assign(event_time=untimed.event_time + phase.start))
    timed = xr.concat(pieces, "time", join="outer", data_vars="minimal", coords="minimal", compat="override")
    event = xr.concat(events, "event", join="outer", data_vars="minimal", coords="minimal", compat="override")
    first, last = parts[0][1], parts[-1][1]
    static = first[[v for v in first.data_vars if "time" not in first[v].dims and "event" not in first[v].dims]]
    out = xr.merge([static, timed, event], join="outer", compat="override")
    out = _vessel_outputs(case, out)
    out.attrs = {**last.attrs, "case_sha256": case_sha256(case), "case_yaml": case_yaml(case)}   # the run's case
    for key in ("status", "notes"):                # the last phase's sentences, on the run's clock
        if isinstance(out.attrs.get(key), str):
            out.attrs[key] = on_run_clock(out.attrs[key], parts[-1][0].start)
    for key in SUMMED_ATTRIBUTES:                  # counts and times of the whole run, not its last phase
        values = [ds.attrs.get(key) for _, ds in parts]
        if all(isinstance(v, (int, float, np.integer, np.floating)) for v in values):
            out.attrs[key] = sum(values)
    worst = max(parts, key=lambda part: part[1].attrs.get("time_error_estimate", -1.0))   # the implicit scheme's
    if "time_error_estimate" in worst[1].attrs:                                          # largest error estimate
        out.attrs.update({k: v for k, v in worst[1].attrs.items() if k.startswith("time_error_")})
        out.attrs["time_error_time"] = worst[1].attrs["time_error_time"] + worst[0].start
    start = max(parts, key=lambda part: part[1].attrs.get("time_error_start", -1.0))     # eq. (3): each phase's
    if "time_error_start" in start[1].attrs:                                            # start (a release's too)
        out.attrs["time_error_start"] = start[1].attrs["time_error_start"]
        out.attrs["time_error_start_time"] = start[1].attrs["time_error_start_time"] + start[0].start
    for name in ("s", "cable", "segment_cable", "segment_length", "cable_name"):
        if name in first.coords:
            out = out.assign_coords({name: first[name]})
    return out


CLOCK_TIME = re.compile(r"\bt = (-?[0-9]+(?:\.[0-9]*)?(?:e[+-]?[0-9]+)?) s\b")
"""A time in a model's sentence (``at t = 4 s``, as every run check writes one)."""


def on_run_clock(text: str, start: float) -> str:
    """A phase's sentence (its status, a note) with every ``t = X s`` moved to the run's clock: the
    phase's own clock starts at 0 at ``start`` [s]."""
    if not start:
        return text
    return CLOCK_TIME.sub(lambda found: f"t = {float(found.group(1)) + start:.6g} s", text)


def _vessel_outputs(case, ds):
    """The vessel's outputs at the run's times (a later phase's own clock started over)."""
    present = [v for v in VESSEL_VARIABLES if v in ds]
    if not present:
        return ds
    system = LumpedSystem(build_network(case), case)
    times = np.asarray(ds.time.values, float)
    states = [system.vessel(float(t)) for t in times]
    if "vessel_position" in ds:
        ds["vessel_position"] = (ds.vessel_position.dims, np.array([s[0] for s in states]))
    if "vessel_heading" in ds:
        ds["vessel_heading"] = (ds.vessel_heading.dims, np.array([s[3] for s in states], float))
    if "vessel_pitch" in ds and system.track is not None and system.track.pitch is not None:
        ds["vessel_pitch"] = (ds.vessel_pitch.dims, np.array([system.track.pitch(t)[0] for t in times]))
    return ds


def refuse_start(start) -> None:
    """A run with releases starts from its own initial state (the phases pass theirs on)."""
    if start is not None:
        raise CaseError([Problem("start", "a case with release_at starts from its own initial state")])
