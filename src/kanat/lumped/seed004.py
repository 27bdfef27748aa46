"""Seed 004's towed spread: tension statistics before and after the speed step, the paper's
findings as computed checks, and one command for the figures and tables.

The three points of the paper's figures 1-3 (seed 004, "Чисельні результати") are the tow
point (``tow`` cable, s = 0), the otter-board attachment (``bridle_port`` at the board) and
the buoy attachment (``buoy_line`` at the buoy). Windows, with ``t_s`` the step time
(found from the vessel's speed) and ``t_e`` the end of the run::

    before     [t_s - BEFORE, t_s)       steady towing in waves at the old speed
    transient  [t_s, t_s + TRANSIENT)    the response to the step
    after      [t_s, t_e]                everything after the step
    settled    (t_e - SETTLED, t_e]      steady towing at the new speed

``mean`` and ``range = T_max - T_min`` (the paper's ``T_a``) of each; a *jerk* is a rise of
tension within ``JERK_WINDOW`` seconds; ``jerk_ratio`` compares the largest such rise after
the step with the largest in steady waves before it.

Command::

    python -m kanat.lumped.seed004 examples/seed004_*.yaml -o DIR [--reuse]

runs each case (or reuses ``DIR/<case>.nc``), writes ``DIR/<case>.png`` (figure like the
paper's) and ``DIR/<case>.md`` (the table and the findings) and prints them.
"""
from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

POINTS = (("tow point", "tow", 0), ("otter board", "bridle_port", -1), ("buoy", "buoy_line", -1))
BEFORE = 100.0          # s: steady window before the step (> 17 wave periods of 5.6 s)
TRANSIENT = 60.0        # s: the step's response (the buoy line's rise)
SETTLED = 100.0         # s: steady window at the end of the run
JERK_WINDOW = 1.0       # s: a jerk is a rise of tension within this time
JERK_FACTOR = 2.0       # a rise this many times the largest one in steady waves is a jerk
SLIGHTLY = 0.10         # "slightly above": within 10 % of the old mean


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


def step_statistics(ds, points=POINTS) -> list[PointStatistics]:
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


def _grows(s: PointStatistics) -> dict[str, bool]:
    return {"mean grows": s.after.mean > s.before.mean and s.settled.mean > s.before.mean,
            "range grows": s.after.range > s.before.range, "jerks": s.jerk_ratio > JERK_FACTOR}


def _figure1(tow, board, buoy) -> dict[str, bool]:
    """SPEC §5 (the paper's figure 1, and its general statement)."""
    out = {f"tow point: {k}": v for k, v in _grows(tow).items()}
    out.update({f"otter board: {k}": v for k, v in _grows(board).items()})
    rise, settle = buoy.transient.mean - buoy.before.mean, buoy.settled.mean - buoy.before.mean
    out["buoy: mean first rises strongly"] = rise > 2.0 * max(settle, 0.0) and rise > 0.05 * buoy.before.mean
    out["buoy: then settles slightly above"] = 0.0 < settle < SLIGHTLY * buoy.before.mean
    out["buoy: range grows"] = buoy.settled.range > buoy.before.range
    return out


def _figures23(tow, board, buoy, figure: int) -> dict[str, bool]:
    """The paper's statements on its figures 2 (following waves) and 3 (head waves of 8 s)."""
    out = {"tow point: mean grows": tow.settled.mean > tow.before.mean,
           "tow point: range grows" + (" strongly" if figure == 3 else ""):
               tow.settled.range > (2.0 if figure == 3 else 1.0) * tow.before.range,
           "otter board: mean grows slightly": 1.0 < board.settled.mean / board.before.mean < 1.0 + 2 * SLIGHTLY,
           "otter board: range falls markedly": board.settled.range < 0.75 * board.before.range}
    if figure == 3:
        out.update({"tow point: jerks": tow.jerk_ratio > JERK_FACTOR,
                    "otter board: jerks": board.jerk_ratio > JERK_FACTOR,
                    "buoy: mean falls slightly": 1.0 - SLIGHTLY < buoy.settled.mean / buoy.before.mean < 1.0,
                    "buoy: range grows": buoy.settled.range > buoy.before.range})
    else:
        out.update({"buoy: mean falls": buoy.settled.mean < buoy.before.mean,
                    "buoy: range grows slightly": 1.0 < buoy.settled.range / buoy.before.range < 1.0 + 2 * SLIGHTLY})
    return out


FIGURES = {"seed004-head-waves-5.6s-speed-1-to-4": 1, "seed004-following-waves-4.5s-speed-1-to-2": 2,
           "seed004-head-waves-8s-speed-1-to-2": 3}


def findings(stats: list[PointStatistics], figure: int = 1) -> dict[str, bool]:
    """The paper's findings on its ``figure`` (1, 2 or 3) as computed checks of ``stats``
    (tow point, otter board, buoy). Figure 1's are SPEC §5's: at the tow point and the otter
    board the mean tension and its range grow after the step, with jerks; at the buoy the
    mean first rises strongly, then settles slightly above its old value, while the range
    grows. Figures 2 and 3 (1 -> 2 m/s) state other trends at the otter board and the buoy."""
    tow, board, buoy = stats
    return _figure1(tow, board, buoy) if figure == 1 else _figures23(tow, board, buoy, figure)


def report(ds) -> str:
    """Table, snap events and findings of one result, as Markdown."""
    stats = step_statistics(ds)
    figure = FIGURES.get(ds.attrs.get("case_name", ""), 1)
    lines = [f"## {ds.attrs.get('case_name', '')}: speed step at {step_time(ds):g} s (paper's figure {figure})",
             "", "Tension [kN]:", "", table(stats), ""]
    snaps = snap_counts(ds)
    lines.append("Slack -> taut events (before / after the step): "
                 + (", ".join(f"{c} {a} / {b}" for c, (a, b) in snaps.items()) or "none"))
    lines += ["", "Findings of the paper reproduced:", ""]
    lines += [f"- {name}: {'yes' if ok else 'NO'}" for name, ok in findings(stats, figure).items()]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    """``python -m kanat.lumped.seed004 CASES -o DIR [--reuse]`` (module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m kanat.lumped.seed004", description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="+", type=Path, help="seed 004 case files (examples/seed004_*.yaml)")
    parser.add_argument("-o", "--output", type=Path, required=True, help="folder for .nc, .png and .md")
    parser.add_argument("--reuse", action="store_true", help="reuse DIR/<case>.nc when it exists")
    args = parser.parse_args(argv)
    from kanat.io import load_case
    from kanat.io.results import read_result
    from kanat.lumped.driver import run
    from kanat.report.lumped_plot import plot_seed004
    args.output.mkdir(parents=True, exist_ok=True)
    for path in args.cases:
        result = args.output / f"{path.stem}.nc"
        if not (args.reuse and result.exists()):
            summary = run(load_case(path), result)
            print(summary.summary())
            if not summary.ok:
                return 1
        ds = read_result(result)
        plot_seed004(ds, args.output / f"{path.stem}.png")
        text = report(ds)
        (args.output / f"{path.stem}.md").write_text(text)
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
