"""Figures of Kaliukh & Vusatiuk's studies: the stability map of a scheme and the three comparisons.

Plain functions from result tables to matplotlib Figures (saved when a path is given); no
computation beyond what a picture needs.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure


def _save(fig: Figure, path) -> Figure:
    if path is not None:
        fig.savefig(Path(path), dpi=110)
    return fig


def plot_stability_map(ds, path=None) -> Figure:
    """Stability map of a :func:`kanat.studies.stability.stability_sweep` dataset.

    Left: each run at its ``(sigma_long, sigma_tr)``, filled when bounded, crossed when not,
    coloured by its distance from the reference; the paper's stable band of ``sigma_long``
    ([2, 200]) shaded. Right: tension error against ``sigma_long``.
    """
    fig = Figure(figsize=(11, 4.5), layout="constrained")
    left, right = fig.subplots(1, 2)
    sl, st = ds["sigma_long"].values.astype(float), ds["sigma_tr"].values.astype(float)
    ok = ds["bounded"].values.astype(bool)
    error = ds["tension_error"].values.astype(float)
    left.axvspan(2.0, 200.0, color="0.9", label="Kaliukh & Vusatiuk 2018: stable sigma_long")
    if ok.any():
        shade = np.log10(np.maximum(error[ok], 1e-12))
        points = left.scatter(sl[ok], st[ok], c=shade, cmap="viridis", s=50, label="bounded")
        fig.colorbar(points, ax=left, label="log10 tension error")
    if (~ok).any():
        left.scatter(sl[~ok], st[~ok], marker="x", color="red", s=60, label="unbounded / failed")
    left.set(xscale="log", yscale="log", xlabel="sigma_long = c_l dt / ds", ylabel="sigma_tr = c_t dt / ds",
             title=f"{ds.attrs.get('scheme', '')} on {ds.attrs.get('case_name', '')}")
    left.legend(fontsize=8, loc="upper left")
    left.grid(alpha=0.3, which="both")
    right.loglog(sl[ok], np.maximum(error[ok], 1e-16), "o-", label="tension error (bounded runs)")
    for x in sl[~ok]:
        right.axvline(x, color="red", lw=0.8, ls="--")
    right.set(xlabel="sigma_long", ylabel=f"|T - T_ref| / max T_ref  (ref: {ds.attrs.get('reference', '')})",
              title="distance from the reference at the end")
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=8)
    return _save(fig, path)


def plot_accel(table, path=None) -> Figure:
    """Kaliukh & Vusatiuk 2018, figs. 1–2: the towed vehicle's depth and distance astern against time, per scheme."""
    fig = Figure(figsize=(11, 4.2), layout="constrained")
    depth, distance = fig.subplots(1, 2)
    for name, group in table.groupby("scheme", sort=False):
        depth.plot(group["time"], group["depth"], lw=1.5, label=name)
        distance.plot(group["time"], group["distance"], lw=1.5, label=name)
    depth.set(xlabel="time [s]", ylabel="depth h below the tow point [m]", title="vehicle depth (fig. 1)")
    distance.set(xlabel="time [s]", ylabel="distance X astern of the tow point [m]", title="vehicle distance (fig. 2)")
    depth.invert_yaxis()
    for axis in (depth, distance):
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    return _save(fig, path)


def plot_planar80(table, path=None) -> Figure:
    """Kaliukh & Vusatiuk 2018, table 1: tension and inclination along the cable at each time, full vs factorized."""
    fig = Figure(figsize=(11, 4.2), layout="constrained")
    tension, angle = fig.subplots(1, 2)
    factorized = next(c for c in table.columns if c.startswith("tension_") and c not in ("tension_full",
                                                                                       "tension_diff_pct"))
    name = factorized[len("tension_"):]
    for i, ((segments, t), group) in enumerate(table.groupby(["segments", "time"])):
        colour = f"C{i}"
        label = f"{segments} seg, t = {t:g} s"
        tension.plot(group["s"], group["tension_full"] / 1e3, "-", color=colour, label=f"full, {label}")
        tension.plot(group["s"], group[factorized] / 1e3, "o", color=colour, ms=4)
        angle.plot(group["s"], group["inclination_full"], "-", color=colour, label=f"full, {label}")
        angle.plot(group["s"], group[f"inclination_{name}"], "o", color=colour, ms=4)
    tension.set(xlabel="s [m]", ylabel="tension [kN]", title=f"lines: full, markers: {name}")
    angle.set(xlabel="s [m]", ylabel="inclination below horizontal [rad]", title="table 1")
    for axis in (tension, angle):
        axis.grid(alpha=0.3)
    tension.legend(fontsize=6)
    return _save(fig, path)


def plot_spatial100(table, history, path=None) -> Figure:
    """Kaliukh & Vusatiuk 2018, table 2 and its claim: deviation of each wave split from the full scheme in time."""
    fig = Figure(figsize=(12, 4.2), layout="constrained")
    axes = fig.subplots(1, 3)
    for (name, group), colour in zip(history.groupby("scheme", sort=False), ("C1", "C2", "C3")):
        axes[0].semilogy(group["time"], np.maximum(group["tension_error_pct"], 1e-8), color=colour, label=name)
        axes[1].semilogy(group["time"], np.maximum(group["w_error"], 1e-12), color=colour, label=name)
        axes[2].semilogy(group["time"], np.maximum(group["azimuth_error"], 1e-12), color=colour, label=name)
    for axis, label in zip(axes, ("max |T / T_full - 1| [%]", "max |w - w_full| [m/s]",
                                  "max |azimuth - azimuth_full| [rad]")):
        axis.set(xlabel="time [s]", ylabel=label)
        axis.grid(alpha=0.3, which="both")
        axis.legend(fontsize=8)
    axes[1].set_title("100 m tow, 45 deg turn: deviation from the full scheme")
    return _save(fig, path)
