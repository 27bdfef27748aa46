"""Statistics of a tension record around a speed step: windows before and after it, the
largest quick rise (a *jerk*), and snap events before and after (theory/lumped.md §7, Bezverkhyi 2006).

With ``t_s`` the step time (found from the vessel's speed) and ``t_e`` the end of the run::

    before     [t_s - BEFORE, t_s)       steady towing in waves at the old speed
    transient  [t_s, t_s + TRANSIENT)    the response to the step
    after      [t_s, t_e]                everything after the step
    settled    (t_e - SETTLED, t_e]      steady towing at the new speed

``mean`` and ``range = T_max - T_min`` (Bezverkhyi's ``T_a``) of each; a *jerk* is a rise of
tension within ``JERK_WINDOW`` seconds.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

BEFORE = 100.0          # s: steady window before the step (> 17 wave periods of 5.6 s)
TRANSIENT = 60.0        # s: the step's response (the buoy line's rise)
SETTLED = 100.0         # s: steady window at the end of the run
JERK_WINDOW = 1.0       # s: a jerk is a rise of tension within this time


@dataclass(frozen=True)
class Window:
    """Mean and range of a tension record over a time window [N]."""

    mean: float
    range: float
    low: float
    high: float

    @classmethod
    def of(cls, values: np.ndarray) -> Window:
        return cls(float(np.mean(values)), float(np.ptp(values)), float(np.min(values)), float(np.max(values)))


@dataclass(frozen=True)
class PointStatistics:
    """Tension statistics of one point around the speed step."""

    name: str
    before: Window
    transient: Window
    after: Window
    settled: Window
    jerk_before: float
    jerk_after: float

    @property
    def jerk_ratio(self) -> float:
        return self.jerk_after / max(self.jerk_before, 1e-9)


def step_time(ds) -> float:
    """Time of the first change of the vessel's speed [s] (from ``vessel_position``)."""
    t = ds["time"].values
    speed = np.linalg.norm(np.diff(ds["vessel_position"].values, axis=0), axis=1) / np.diff(t)
    changed = np.flatnonzero(np.abs(speed - speed[0]) > 1e-6 * max(abs(speed[0]), 1.0))
    if len(changed) == 0:
        raise ValueError("the vessel's speed never changes in this result: no speed step to analyse")
    return float(t[changed[0]])


def point_tension(ds, cable: str, end: int) -> np.ndarray:
    """Tension record (time,) at the first (``end = 0``) or last (``-1``) node of ``cable``."""
    nodes = np.flatnonzero(ds["cable"].values == cable)
    if len(nodes) == 0:
        raise ValueError(f"no cable '{cable}' in this result (cables: {sorted(set(ds['cable'].values))})")
    return ds["tension"].values[:, nodes[end]]


def largest_rise(t: np.ndarray, values: np.ndarray, window: float = JERK_WINDOW) -> float:
    """Largest increase of ``values`` from any sample to one up to ``window`` later."""
    lag = max(1, int(round(window / np.median(np.diff(t)))))
    rises = [values[k:] - values[:-k] for k in range(1, lag + 1) if k < len(values)]
    return float(max(np.max(r) for r in rises)) if rises else 0.0


def step_statistics(ds, points) -> list[PointStatistics]:
    """Statistics of each point of ``points`` (name, cable, end) around the speed step."""
    t = ds["time"].values
    ts, te = step_time(ds), float(t[-1])
    windows = {"before": (t >= ts - BEFORE) & (t < ts), "transient": (t >= ts) & (t < ts + TRANSIENT),
               "after": t >= ts, "settled": t > te - SETTLED}
    out = []
    for name, cable, end in points:
        values = point_tension(ds, cable, end)
        stats = {k: Window.of(values[sel]) for k, sel in windows.items()}
        jerk_before = largest_rise(t[windows["before"]], values[windows["before"]])
        around = (t >= ts - JERK_WINDOW) & (t < ts + TRANSIENT)          # the last sample before the step too
        jerk_after = largest_rise(t[around], values[around])
        out.append(PointStatistics(name, **stats, jerk_before=jerk_before, jerk_after=jerk_after))
    return out


def table(stats: list[PointStatistics]) -> str:
    """The statistics as a Markdown table [kN]."""
    head = ("| point | mean before | range before | mean transient | range transient | mean after | "
            "range after | mean settled | range settled | largest 1-s rise before / after |")
    rows = [head, "|" + "---|" * 10]
    for s in stats:
        cells = [s.before.mean, s.before.range, s.transient.mean, s.transient.range, s.after.mean,
                 s.after.range, s.settled.mean, s.settled.range]
        rows.append(f"| {s.name} | " + " | ".join(f"{c / 1e3:.2f}" for c in cells)
                    + f" | {s.jerk_before / 1e3:.2f} / {s.jerk_after / 1e3:.2f} |")
    return "\n".join(rows)


def snap_counts(ds) -> dict[str, tuple[int, int]]:
    """Slack -> taut events per cable, ``(before, after)`` the speed step."""
    ts = step_time(ds)
    if "event_time" not in ds or ds.sizes.get("event", 0) == 0:
        return {}
    cables = ds["segment_cable"].values[ds["event_segment"].values]
    times = ds["event_time"].values
    return {c: (int(np.sum((cables == c) & (times < ts))), int(np.sum((cables == c) & (times >= ts))))
            for c in dict.fromkeys(cables)}
