"""Figure of the tow from a pitching vessel: top tension per stabilizer mode of the tow vessel.

Draws on a new :class:`matplotlib.figure.Figure` (no pyplot state) from the summary dataset
of :func:`kanat.studies.pitch_tow.summary_dataset`.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kanat.report.pitch_plot import STYLE

KN = 1e3  # N per kN
ZOOM_PERIODS = 3   # wave periods shown in the close-up


def plot_coupled(summary, path=None) -> Figure:
    """Top tension against time per mode, a close-up of the last periods, and the table's bars.

    Parameters
    ----------
    summary : xarray.Dataset
        ``summary.nc`` (``top_tension(mode, time)``, ``top_tension_range(mode)``, ...).
    path : path-like, optional
        PNG to write.

    Panels: (a) the whole run, the statistics window shaded; (b) the last ``ZOOM_PERIODS``
    wave periods; (c) tension range and standard deviation, with the snap events; (d) how
    many times each mode reduces the pitch amplitude, the tow point's vertical velocity
    range and the top-tension range, against ``off``.
    """
    fig = Figure(figsize=(13, 8.5), layout="constrained")
    (whole, close), (bars, ratios) = fig.subplots(2, 2)
    modes = [str(m) for m in summary["mode"].values]
    time = summary["time"].values
    start, end = summary.attrs["window_start_s"], summary.attrs["window_end_s"]
    near = time >= end - ZOOM_PERIODS * summary.attrs["wave_period_s"] - 1e-9
    for i, mode in enumerate(modes):
        colour, line, _ = STYLE.get(mode, ("gray", "-", mode))
        tension = summary["top_tension"].values[i] / KN
        whole.plot(time, tension, line, color=colour, lw=1.0, label=mode)
        close.plot(time[near], tension[near], line, color=colour, lw=1.5, label=mode)
    whole.axvspan(start, end, color="0.93", zorder=0, label="statistics window")
    whole.set(xlabel="time [s]", ylabel="top tension [kN]", title=f"(a) {summary.attrs.get('case_name', '')}")
    close.set(xlabel="time [s]", ylabel="top tension [kN]", title=f"(b) the last {ZOOM_PERIODS} wave periods")
    for ax in (whole, close):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper right")
    _bars_statistics(bars, summary, modes)
    _bars_ratios(ratios, summary, modes)
    if path is not None:
        fig.savefig(Path(path), dpi=110)
    return fig


def _bars_statistics(ax, summary, modes) -> None:
    x = np.arange(len(modes))
    rng, std = summary["top_tension_range"].values / KN, summary["top_tension_std"].values / KN
    ax.bar(x - 0.2, rng, 0.4, label="range (max - min)", color="tab:blue")
    ax.bar(x + 0.2, std, 0.4, label="standard deviation", color="tab:orange")
    for i, snaps in enumerate(summary["snap_events"].values):
        if np.isfinite(rng[i]):
            ax.annotate(f"{int(snaps)} snaps", (x[i], rng[i]), ha="center", va="bottom", fontsize=8)
    fraction = 100 * summary.attrs["snap_fraction"]
    ax.set(xticks=x, xticklabels=modes, ylabel="top tension [kN]",
           title=f"(c) after the transient (snap: below {fraction:g} % of the mean and back)")
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)


def _bars_ratios(ax, summary, modes) -> None:
    if "off" not in modes:
        ax.set_axis_off()
        return
    off = modes.index("off")
    x = np.arange(len(modes))
    for k, (name, label) in enumerate((("pitch_amplitude", "pitch amplitude"),
                                       ("tow_point_vertical_velocity_range", "tow point vertical velocity range"),
                                       ("top_tension_range", "top tension range"))):
        values = summary[name].values
        ax.bar(x + (k - 1) * 0.27, values[off] / values, 0.27, label=label, color=f"C{k + 2}")
    ax.axhline(1.0, color="black", lw=0.8)
    ax.set(xticks=x, xticklabels=modes, ylabel="off / mode", yscale="log",
           title="(d) reduction against no stabilizer")
    ax.grid(alpha=0.3, axis="y", which="both")
    ax.legend(fontsize=8)
