"""Does a pitch stabilizer on the tow vessel calm the cable? (Gaisha's ship coupled to the tow)

:func:`compare_modes` runs one continuum case, whose ``vessel.pitch`` block sets the ship,
the sea and the stabilizer, once per stabilizer mode (:func:`kanat.api.run`). The
stern tow point follows the steady pitch of each mode
(:func:`kanat.vessel.pitch.motion.pitch_motion`). After the transient, the top tension gets
these statistics:

* mean, min, max, range (max - min) and standard deviation, over a window of whole wave periods
  that ends at the end of the run (:func:`statistics_window`);
* **snap events**: the top tension falls below ``SNAP_FRACTION`` (5 %) of its window mean,
  then rises above it again. Each completed return counts once. This is the near-slack analogue
  of the lumped model's slack -> taut event (:mod:`kanat.lumped.snap`). The continuum model
  must stay taut, so it cannot go fully slack: a run that would do so stops with its status.

The statistics also hold the tow point's kinematics over one period, computed from the track,
not from the cable: the pitch amplitude, and the range of the heave and of the vertical velocity.
One result file per mode is written (``DIR/<mode>.nc``), plus ``DIR/summary.nc``; the command
``kanat study pitch-tow CASE -o DIR`` also draws ``DIR/coupled.png``
(:func:`kanat.report.coupled_plot.plot_coupled`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.errors import KanatError

DEFAULT_MODES = ("off", "sinusoidal", "rectangular", "feedback", "optimal")
SNAP_FRACTION = 0.05
"""A snap event: the top tension falls below this fraction of its mean, then rises above it again."""
TRANSIENT_FRACTION = 1.0 / 3.0
"""Default transient: this fraction of the run's duration is left out of the statistics."""
KINEMATIC_SAMPLES = 400
"""Samples of one wave period for the tow point's kinematic ranges."""
KN = 1e3  # N per kN


@dataclass(frozen=True)
class TensionStatistics:
    """Top-tension statistics over a window ``[start, end]`` [s] (tensions in N).

    Attributes
    ----------
    start, end : float
    mean, minimum, maximum, std : float
    snap_times : ndarray, shape (k,)
        Times at which the tension rose back above ``threshold`` after falling below it [s].
    threshold : float
        ``SNAP_FRACTION * mean`` [N].
    """

    start: float
    end: float
    mean: float
    minimum: float
    maximum: float
    std: float
    snap_times: np.ndarray
    threshold: float

    @property
    def range(self) -> float:
        """``maximum - minimum`` [N]."""
        return self.maximum - self.minimum

    @property
    def snaps(self) -> int:
        """Number of snap events in the window."""
        return len(self.snap_times)


def snap_events(time, tension, threshold: float) -> np.ndarray:
    """Times at which ``tension`` rises back above ``threshold`` after a drop below it.

    Parameters
    ----------
    time, tension : array_like, shape (n,)
    threshold : float
        [N]. A drop that is still below the threshold at the end is not counted.

    Returns
    -------
    ndarray, shape (k,)
        The first sample back above the threshold, one per completed event [s].
    """
    below = np.asarray(tension) < threshold
    rises = np.flatnonzero(below[:-1] & ~below[1:]) + 1
    return np.asarray(time, dtype=float)[rises]


def tension_statistics(time, tension, start: float, end: float | None = None,
                       snap_fraction: float = SNAP_FRACTION) -> TensionStatistics:
    """Statistics of a tension history over ``start <= t <= end`` (default: to the end)."""
    time, tension = np.asarray(time, dtype=float), np.asarray(tension, dtype=float)
    end = time[-1] if end is None else end
    inside = (time >= start - 1e-9) & (time <= end + 1e-9)
    if inside.sum() < 2:
        raise KanatError(f"no tension samples in the window [{start:g}, {end:g}] s (the run ends at "
                         f"{time[-1]:g} s); shorten the transient or lengthen simulation.duration")
    window = tension[inside]
    mean = float(window.mean())
    threshold = snap_fraction * mean
    return TensionStatistics(float(start), float(end), mean, float(window.min()), float(window.max()),
                             float(window.std()), snap_events(time[inside], window, threshold), threshold)


def statistics_window(duration: float, period: float, transient: float | None = None) -> tuple[float, float]:
    """The statistics window: the most whole wave periods after ``transient`` that end at ``duration``.

    ``transient`` defaults to ``TRANSIENT_FRACTION * duration``.
    """
    transient = TRANSIENT_FRACTION * duration if transient is None else transient
    periods = math.floor((duration - transient) / period + 1e-9)
    if periods < 1:
        raise KanatError(f"the run ({duration:g} s) leaves less than one wave period ({period:g} s) after "
                         f"the transient ({transient:g} s); lengthen simulation.duration")
    return duration - periods * period, duration


def with_stabilizer_mode(case, mode: str):
    """A copy of ``case`` whose vessel pitches with the stabilizer in ``mode``."""
    from kanat.model.problems import STABILIZER_MODES

    if mode not in STABILIZER_MODES:
        raise KanatError(f"unknown stabilizer mode '{mode}'; known: {', '.join(STABILIZER_MODES)}")
    return case.replace({"vessel.pitch.stabilizer.mode": mode, "name": f"{case.name}-{mode}" if case.name else mode})


def rest_phase_deg(block) -> float:
    """The first wave phase, at or after ``block.phase_deg``, at which the steady pitch rate is zero [deg].

    Started there, the tow point is momentarily at rest vertically (at a crest or a trough of
    its heave), so the run's initial steady tow matches the tow point's motion.
    """
    from scipy.optimize import brentq

    from kanat.vessel.pitch.motion import pitch_motion

    motion = pitch_motion(block)
    times = np.linspace(0.0, motion.period, KINEMATIC_SAMPLES + 1)
    rate = motion.evaluate(times)[1]
    if abs(rate[0]) <= 1e-12 * np.ptp(rate):
        return float(block.phase_deg)
    change = np.flatnonzero(np.sign(rate[:-1]) != np.sign(rate[1:]))
    if not len(change):
        return float(block.phase_deg)                 # no pitch motion: any phase is at rest
    i = change[0]
    zero = brentq(lambda t: motion.evaluate(t)[1], times[i], times[i + 1], xtol=1e-12)
    return float(block.phase_deg + 360.0 * zero / motion.period)


def with_phase(case, phase_deg: float):
    """A copy of ``case`` whose vessel pitch starts at wave phase ``phase_deg``."""
    return case.replace({"vessel.pitch.phase_deg": phase_deg})


@dataclass(frozen=True)
class TowPointKinematics:
    """The stern tow point's vertical motion over one wave period (from the track).

    Attributes
    ----------
    pitch_amplitude : float
        Half the peak-to-peak pitch [rad] (the pitch solver's).
    pitch_rate_range : float
        Peak-to-peak pitch rate [rad/s].
    heave_range, vertical_velocity_range : float
        Peak-to-peak height [m] and vertical velocity [m/s] of the tow point.
    """

    pitch_amplitude: float
    pitch_rate_range: float
    heave_range: float
    vertical_velocity_range: float


def tow_point_kinematics(vessel, start: float = 0.0) -> TowPointKinematics:
    """Kinematics of ``vessel``'s tow point over the wave period from ``start`` [s]."""
    from kanat.vessel.track import VesselTrack

    track = VesselTrack.from_model(vessel)
    if track.pitch is None:
        raise KanatError("the vessel has no pitch block (vessel.pitch)")
    times = start + np.linspace(0.0, track.pitch.period, KINEMATIC_SAMPLES + 1)
    states = [track.state(t) for t in times]
    z = np.array([s.position[2] for s in states])
    w = np.array([s.velocity[2] for s in states])
    rate = track.pitch.evaluate(times)[1]
    return TowPointKinematics(track.pitch.amplitude, float(np.ptp(rate)), float(np.ptp(z)), float(np.ptp(w)))


@dataclass(frozen=True)
class ModeRun:
    """One stabilizer mode's coupled run.

    Attributes
    ----------
    mode, status : str
    path : Path
        Its result file.
    time, top_tension, vessel_pitch : ndarray, shape (n,)
        The output history [s, N, rad].
    statistics : TensionStatistics or None
        ``None`` when the run did not reach the end of the window.
    kinematics : TowPointKinematics
    phase_deg : float
        Wave phase at the run's ``t = 0`` (``vessel.pitch.phase_deg`` of the run).
    """

    mode: str
    status: str
    path: Path
    time: np.ndarray
    top_tension: np.ndarray
    vessel_pitch: np.ndarray
    statistics: TensionStatistics | None
    kinematics: TowPointKinematics
    phase_deg: float


@dataclass(frozen=True)
class Comparison:
    """The coupled runs of every mode, with their common window."""

    case_name: str
    runs: dict[str, ModeRun]
    window: tuple[float, float]
    period: float
    snap_fraction: float = SNAP_FRACTION

    def table(self) -> str:
        """Side-by-side table of the top-tension statistics and the tow point kinematics."""
        return comparison_table(self)

    def dataset(self, case) -> xr.Dataset:
        """The summary as a dataset (``summary.nc``)."""
        return summary_dataset(self, case)


def run_modes(case, out_dir, modes=DEFAULT_MODES, *, transient: float | None = None,
              start_at_rest: bool = True, progress=None) -> Comparison:
    """Run ``case`` once per stabilizer mode and measure each run (see the module docstring).

    Parameters
    ----------
    case : kanat.model.Case
        ``model: continuum`` with a ``vessel.pitch`` block.
    out_dir : path-like
        Gets ``<mode>.nc`` per mode.
    modes : sequence of str
    transient : float, optional
        Seconds left out before the window [s]; default ``TRANSIENT_FRACTION`` of the duration.
    start_at_rest : bool
        Start each mode's run at the first phase, from the case's ``phase_deg`` on, where its
        pitch rate is zero (:func:`rest_phase_deg`). The run starts from the steady tow, and a
        tow point already moving vertically at ``t = 0`` would start a long transient (the
        body's depth settles over minutes). The steady statistics over whole periods do not
        depend on the phase. False: every mode starts at the case's ``phase_deg``.
    progress : callable, optional
        ``progress(mode, run_summary)`` after each run.
    """
    from kanat import api

    _check_case(case)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    period = case.vessel.pitch.wave_period
    window = statistics_window(case.simulation.duration, period, transient)
    runs = {}
    for mode in dict.fromkeys(modes):
        moded = with_stabilizer_mode(case, mode)
        if start_at_rest:
            moded = with_phase(moded, rest_phase_deg(moded.vessel.pitch))
        path = out_dir / f"{mode}.nc"
        outcome = api.run(moded, output=path)
        summary, ds = outcome.summary, outcome.dataset
        if progress is not None:
            progress(mode, summary)
        time, top = ds["time"].values, ds["tension"].values[:, 0]
        reached = summary.ok and time[-1] >= window[1] - 1e-9
        stats = tension_statistics(time, top, *window) if reached else None
        runs[mode] = ModeRun(mode, summary.status, path, time, top, ds["vessel_pitch"].values, stats,
                             tow_point_kinematics(moded.vessel, window[0]), moded.vessel.pitch.phase_deg)
    return Comparison(case.name or "", runs, window, period)


def compare_modes(case, out_dir, modes=DEFAULT_MODES, *, transient: float | None = None,
                  start_at_rest: bool = True) -> tuple[Comparison, xr.Dataset]:
    """Run ``case`` per stabilizer mode; write the results and the summary.

    Writes ``out_dir/<mode>.nc`` (each run's result file) and ``out_dir/summary.nc``
    (:func:`summary_dataset`). ``transient`` and ``start_at_rest`` as in :func:`run_modes`.

    Returns
    -------
    (Comparison, xarray.Dataset)
        The comparison (its ``table()`` is the side-by-side text) and the summary dataset.
    """
    from kanat.io.results import write_result

    comparison = run_modes(case, out_dir, modes, transient=transient, start_at_rest=start_at_rest)
    summary = comparison.dataset(case)
    write_result(summary, Path(out_dir) / "summary.nc")
    return comparison, summary


def _check_case(case) -> None:
    if case.model != "continuum":
        raise KanatError(f"the coupled comparison runs model: continuum cases (this one is '{case.model}')")
    if case.vessel.pitch is None:
        raise KanatError("the case has no vessel.pitch block: the vessel does not pitch, so there is no "
                         "stabilizer to compare (see docs/pitch.md, 'Coupling to the tow')")
    if not case.cables or case.cables[0].from_.kind != "vessel":
        raise KanatError("the first cable must start at the vessel (from: vessel) to feel its pitch")


def _ratio(a: float, b: float) -> float:
    return a / b if b else math.inf


def comparison_table(comparison: Comparison) -> str:
    """Plain-text table of a :class:`Comparison` (tensions in kN)."""
    start, end = comparison.window
    off = comparison.runs.get("off")
    lines = [(f"top tension of {comparison.case_name or 'the case'} over t in [{start:g}, {end:g}] s "
              f"({round((end - start) / comparison.period)} wave periods of {comparison.period:g} s)"),
             (f"{'mode':<12} {'pitch amp':>9} {'heave':>6} {'w range':>7} {'mean':>7} {'min':>7} {'max':>7} "
              f"{'range':>7} {'std':>6} {'snaps':>5} {'off/mode':>9} {'off/mode':>8} {'off/mode':>8}"),
             (f"{'':<12} {'[deg]':>9} {'[m]':>6} {'[m/s]':>7} {'[kN]':>7} {'[kN]':>7} {'[kN]':>7} "
              f"{'[kN]':>7} {'[kN]':>6} {'':>5} {'pitch amp':>9} {'w range':>8} {'T range':>8}")]
    for mode, r in comparison.runs.items():
        k, s = r.kinematics, r.statistics
        head = (f"{mode:<12} {math.degrees(k.pitch_amplitude):9.3f} {k.heave_range:6.2f} "
                f"{k.vertical_velocity_range:7.3f}")
        if s is None:
            lines.append(f"{head}  run stopped: {r.status}")
            continue
        ratios = ("", "", "")
        if off is not None and off.statistics is not None:
            ratios = (f"{_ratio(off.kinematics.pitch_amplitude, k.pitch_amplitude):9.2f}",
                      f"{_ratio(off.kinematics.vertical_velocity_range, k.vertical_velocity_range):8.2f}",
                      f"{_ratio(off.statistics.range, s.range):8.2f}")
        lines.append(f"{head} {s.mean / KN:7.2f} {s.minimum / KN:7.2f} {s.maximum / KN:7.2f} "
                     f"{s.range / KN:7.2f} {s.std / KN:6.2f} {s.snaps:5d} {ratios[0]:>9} {ratios[1]:>8} "
                     f"{ratios[2]:>8}")
    lines.append(f"heave, w range: peak-to-peak height and vertical velocity of the tow point; snaps: the top "
                 f"tension falls below {100 * comparison.snap_fraction:g} % of its mean, then rises above it")
    return "\n".join(lines)


STAT_VARS = {  # summary variable -> (TensionStatistics attribute, units, long name)
    "top_tension_mean": ("mean", "N", "mean top tension after the transient"),
    "top_tension_min": ("minimum", "N", "least top tension after the transient"),
    "top_tension_max": ("maximum", "N", "largest top tension after the transient"),
    "top_tension_range": ("range", "N", "top tension range (max - min) after the transient"),
    "top_tension_std": ("std", "N", "standard deviation of the top tension after the transient"),
    "snap_events": ("snaps", "1", "top tension below SNAP_FRACTION of its mean, then back above it"),
}
KINEMATIC_VARS = {
    "pitch_amplitude": ("pitch_amplitude", "rad", "steady pitch amplitude (half the peak-to-peak)"),
    "pitch_rate_range": ("pitch_rate_range", "rad/s", "peak-to-peak pitch rate"),
    "tow_point_heave_range": ("heave_range", "m", "peak-to-peak height of the tow point"),
    "tow_point_vertical_velocity_range": ("vertical_velocity_range", "m/s",
                                          "peak-to-peak vertical velocity of the tow point"),
}


def summary_dataset(comparison: Comparison, case) -> xr.Dataset:
    """``summary.nc``: per-mode statistics and the top tension and pitch histories ``(mode, time)``."""
    from kanat.io.provenance import provenance

    modes = list(comparison.runs)
    runs = comparison.runs.values()
    time = max((r.time for r in runs), key=len)

    def history(name):
        rows = np.full((len(modes), len(time)), np.nan)
        for i, r in enumerate(runs):
            rows[i, :len(r.time)] = getattr(r, name)
        return rows

    data = {"top_tension": (("mode", "time"), history("top_tension"), {"units": "N", "long_name": "top tension"}),
            "vessel_pitch": (("mode", "time"), history("vessel_pitch"),
                             {"units": "rad", "long_name": "vessel pitch, bow up positive"}),
            "status": ("mode", np.array([r.status for r in runs], dtype=object))}
    for name, (attr, units, long_name) in STAT_VARS.items():
        values = [np.nan if r.statistics is None else float(getattr(r.statistics, attr)) for r in runs]
        data[name] = ("mode", np.array(values), {"units": units, "long_name": long_name})
    for name, (attr, units, long_name) in KINEMATIC_VARS.items():
        data[name] = ("mode", np.array([getattr(r.kinematics, attr) for r in runs]),
                      {"units": units, "long_name": long_name})
    data["start_phase"] = ("mode", np.array([r.phase_deg for r in runs]),
                           {"units": "degree", "long_name": "wave phase at t = 0 of the run"})
    attrs = provenance(case, model="continuum", scheme=case.simulation.scheme or "generalized-alpha",
                       wall_time_s=0.0, status="ok" if all(r.statistics for r in runs) else "incomplete",
                       window_start_s=comparison.window[0], window_end_s=comparison.window[1],
                       wave_period_s=comparison.period, snap_fraction=comparison.snap_fraction,
                       snap_definition="top tension below snap_fraction * its window mean, then back above it",
                       result_files=" ".join(r.path.name for r in runs))
    return xr.Dataset(data, coords={"mode": np.array(modes, dtype=object), "time": time}, attrs=attrs)
