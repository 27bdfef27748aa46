"""Figures of lumped-model results: Bezverkhyi's tension records around the speed step."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kanat.analysis.step_response import BEFORE, SETTLED, TRANSIENT, point_tension, step_statistics, step_time
from kanat.studies.trawl import POINTS


def plot_trawl(ds, path=None, points=POINTS) -> Figure:
    """Tension against time at the tow point, the otter-board attachment and the buoy
    attachment (Bezverkhyi 2006, figures 1-3: curves 1, 2, 3), one panel each, with the speed
    step and the statistics windows marked and the mean and range of each window written
    in. Saved to ``path`` when given.

    Parameters
    ----------
    ds : xarray.Dataset
        A lumped result (case-format.md names) with a speed step.
    path : path-like, optional
    points : sequence of (label, cable, end)
        See :data:`kanat.studies.trawl.POINTS`.
    """
    t = ds["time"].values
    ts, te = step_time(ds), float(t[-1])
    stats = step_statistics(ds, points)
    fig = Figure(figsize=(11, 8), layout="constrained")
    axes = fig.subplots(len(points), 1, sharex=True)
    for k, (ax, (label, cable, end), s) in enumerate(zip(np.atleast_1d(axes), points, stats)):
        ax.plot(t, point_tension(ds, cable, end) / 1e3, lw=0.8, color=f"C{k}")
        for (a, b), w in (((ts - BEFORE, ts), s.before), ((ts, ts + TRANSIENT), s.transient),
                          ((te - SETTLED, te), s.settled)):
            ax.axvspan(a, b, color="0.9", zorder=0)
            ax.hlines(w.mean / 1e3, a, b, colors="k", linestyles="--", lw=1.0)
            ax.annotate(f"mean {w.mean / 1e3:.2f}\nrange {w.range / 1e3:.2f}", (0.5 * (a + b), w.high / 1e3),
                        ha="center", va="bottom", fontsize=7)
        ax.axvline(ts, color="r", lw=1.0)
        ax.set_ylabel("tension [kN]")
        ax.set_title(f"curve {k + 1}: {label} ({cable}, s = {'0' if end == 0 else 'L'})", fontsize=9, loc="left")
        ax.grid(alpha=0.3)
        ax.margins(y=0.25)
    np.atleast_1d(axes)[-1].set_xlabel("time [s]")
    fig.suptitle(f"{ds.attrs.get('case_name', '')}: speed step at {ts:g} s (red); windows shaded")
    if path is not None:
        fig.savefig(Path(path), dpi=110)
    return fig
