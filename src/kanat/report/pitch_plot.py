"""Figures of the stabilized pitch (Gaisha): the paper's figs. 2–4, all modes, the
``omega_0`` band. Every function draws on a new :class:`matplotlib.figure.Figure` (no
pyplot state) and saves a PNG when given a path.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

STYLE = {  # colour, line style and the paper's curve number of each mode
    "off": ("black", "-", "1 – no stabilizer"),
    "sinusoidal": ("tab:blue", "--", "2 – sinusoidal (f₁)"),
    "rectangular": ("tab:red", "-", "3 – rectangular (f₂)"),
    "feedback": ("tab:green", "-.", "feedback (rate, one-sided)"),
    "optimal": ("tab:purple", ":", "optimal shape"),
}
MN = 1e6  # N m per MN m
FILES = {"period": "pitch_fig2_period.png", "sinusoidal": "pitch_fig3_sinusoidal.png",
         "rectangular": "pitch_fig4_rectangular.png", "modes": "pitch_modes.png",
         "band": "pitch_omega0_band.png"}


def _style(mode: str):
    return STYLE.get(mode, ("gray", "-", mode))


def _half_period(ax, period: float) -> None:
    ax.axvspan(0.0, period / 2, color="0.93", zorder=0)
    ax.set_xlim(0.0, period)
    ax.grid(alpha=0.3)


def _degrees_axis(ax) -> None:
    ax.secondary_yaxis("right", functions=(np.degrees, np.radians)).set_ylabel("pitch [deg]")


def _save(fig: Figure, path) -> Figure:
    if path is not None:
        fig.savefig(Path(path), dpi=130)
    return fig


def _title(result) -> str:
    s = result.system
    return (f"I_y = {s.inertia:.3g} kg m², ω₀ = {s.natural_frequency:.4g} rad/s, ω = "
            f"{s.wave_frequency:.4g} rad/s, ζ = {s.damping_ratio:.3g}, M_m = {s.wave_moment_amplitude / MN:.3g} "
            f"MN m, M0 = {result.max_moment / MN:.3g} MN m")


def plot_period(result, path=None, modes=("off", "sinusoidal", "rectangular")) -> Figure:
    """Paper fig. 2: the pitch over one steady period without stabilizer and in the
    sinusoidal and rectangular modes (curves 1, 2, 3), and the moments below.

    Parameters
    ----------
    result : kanat.vessel.pitch.PitchResult
    path : path-like, optional
        PNG to write.
    modes : sequence of str
        Modes to draw (those solved).
    """
    fig = Figure(figsize=(9, 7), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=[1.6, 1])
    period = result.system.period
    for mode in (m for m in modes if m in result.responses):
        r = result.responses[mode]
        color, ls, label = _style(mode)
        top.plot(r.time, r.pitch, color=color, ls=ls, lw=2,
                 label=f"{label}: amplitude {r.amplitude:.4f} rad, max |φ| {r.max_abs:.4f} rad")
        if mode != "off":
            bottom.plot(r.time, r.moment / MN, color=color, ls=ls, lw=2, label=f"f, {mode}")
    t = result.responses[next(iter(result.responses))].time
    bottom.plot(t, result.system.wave_moment(t) / MN, color="0.4", lw=1.2, label="wave moment M_m sin(ωt + π)")
    top.axhline(0.0, color="0.5", lw=0.8)
    bottom.axhline(0.0, color="0.5", lw=0.8)
    for ax in (top, bottom):
        _half_period(ax, period)
    _degrees_axis(top)
    top.set(ylabel="pitch φ [rad] (bow up +)", title="Pitch over one steady period (paper fig. 2)")
    top.legend(fontsize=8, loc="lower right")
    bottom.set(xlabel="t [s] (shaded: first half period, stabilizer active)", ylabel="moment [MN m]")
    bottom.legend(fontsize=8, loc="lower right")
    fig.suptitle(_title(result), fontsize=9)
    return _save(fig, path)


def plot_modes(result, path=None) -> Figure:
    """Every solved mode: pitch and stabilizer moment over one period, and bars of the
    amplitude and largest ``|phi|`` with their reduction against ``off``."""
    fig = Figure(figsize=(13, 6.5), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=[1.6, 1])
    pitch, moment = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[1, 0])
    bars = fig.add_subplot(grid[:, 1])
    for mode, r in result.responses.items():
        color, ls, label = _style(mode)
        pitch.plot(r.time, r.pitch, color=color, ls=ls, lw=2)
        moment.plot(r.time, r.moment / MN, color=color, ls=ls, lw=2, label=f"{label} ({r.method})")
    for ax in (pitch, moment):
        _half_period(ax, result.system.period)
    _degrees_axis(pitch)
    pitch.set(ylabel="pitch φ [rad]", title="Steady pitch, all modes")
    moment.set(xlabel="t [s]", ylabel="stabilizer moment f [MN m]")
    moment.legend(fontsize=8, loc="center", bbox_to_anchor=(0.68, 0.55))
    modes = list(result.responses)
    x = np.arange(len(modes))
    amp = [result.responses[m].amplitude for m in modes]
    top = [result.responses[m].max_abs for m in modes]
    bars.bar(x - 0.2, amp, 0.4, color=[_style(m)[0] for m in modes], label="amplitude (½ peak-to-peak)")
    bars.bar(x + 0.2, top, 0.4, color=[_style(m)[0] for m in modes], alpha=0.45, hatch="//",
             label="max |φ| (includes the trim)")
    if "off" in result.responses:
        for i, m in enumerate(modes):
            bars.annotate(f"÷{result.reduction(m):.3g}", (i - 0.2, amp[i]), ha="center", va="bottom", fontsize=8)
            bars.annotate(f"÷{result.reduction(m, 'max_abs'):.3g}", (i + 0.2, top[i]), ha="center",
                          va="bottom", fontsize=8)
    bars.set_xticks(x, modes, rotation=20)
    bars.set(ylabel="[rad]", title="Amplitude and max |φ| (÷: reduction vs off)")
    bars.set_ylim(0.0, 1.3 * max(max(amp), max(top)))
    bars.legend(fontsize=8, loc="upper left")
    bars.grid(alpha=0.3, axis="y")
    fig.suptitle(_title(result), fontsize=9)
    return _save(fig, path)


def plot_surface(times, max_moments, pitch, mode: str, max_moment: float | None = None,
                 path=None, figure_number: int | None = None) -> Figure:
    """Paper figs. 3 and 4: the pitch over time and ``M0``, as a surface and a map.

    Parameters
    ----------
    times : ndarray, shape (n,)
        [s].
    max_moments : ndarray, shape (k,)
        ``M0`` values [N m].
    pitch : ndarray, shape (k, n)
        ``phi(M0, t)`` [rad].
    mode : str
    max_moment : float, optional
        The case's ``M0``, marked on the map [N m].
    """
    fig = Figure(figsize=(14, 5.6), layout="constrained")
    grid = fig.add_gridspec(1, 2, width_ratios=[1.15, 1])
    surface = fig.add_subplot(grid[0, 0], projection="3d")
    t, m = np.meshgrid(times, max_moments / MN)
    limit = np.max(np.abs(pitch))
    surface.plot_surface(t, m, pitch, cmap="coolwarm", vmin=-limit, vmax=limit, rstride=1, cstride=2,
                         linewidth=0, antialiased=True)
    surface.set(xlabel="t [s]", ylabel="M0 [MN m]")
    surface.set_zlabel("φ [rad]", labelpad=12)
    surface.view_init(elev=25, azim=-60)
    flat = fig.add_subplot(grid[0, 1])
    filled = flat.contourf(times, max_moments / MN, pitch, levels=21, cmap="coolwarm", vmin=-limit, vmax=limit)
    flat.contour(times, max_moments / MN, pitch, levels=[0.0], colors="k", linewidths=0.8)
    fig.colorbar(filled, ax=flat, label="pitch φ [rad]")
    if max_moment is not None:
        row = np.array([np.interp(max_moment, max_moments, pitch[:, j]) for j in range(len(times))])
        surface.plot(times, np.full_like(times, max_moment / MN), row, color="k", lw=2, zorder=10)
        flat.axhline(max_moment / MN, color="k", ls="--", lw=1.2, label=f"case M0 = {max_moment / MN:.3g} MN m")
        flat.legend(fontsize=8, loc="upper right")
    flat.axvline(times[-1] / 2, color="0.3", lw=0.8, ls=":")
    flat.set(xlabel="t [s] (dotted: end of the active half period)", ylabel="M0 [MN m]",
             title=f"{mode}: pitch over one period and M0")
    number = f"fig. {figure_number}" if figure_number else "paper"
    fig.suptitle(f"Pitch against time and the largest stabilizer moment, {mode} mode ({number}); "
                 "black line / dashed: the case's M0")
    return _save(fig, path)


def plot_band(scan, band, system, path=None) -> Figure:
    """Amplitudes and reductions against ``omega_0``, with the band where the paper's
    claim holds (sinusoidal >= 2x, rectangular more) shaded."""
    fig = Figure(figsize=(10, 7), layout="constrained")
    amp, ratio = fig.subplots(2, 1, sharex=True)
    w = scan.natural_frequency
    for mode in scan.amplitude:
        color, ls, label = _style(mode)
        amp.semilogy(w, scan.amplitude[mode], color=color, ls=ls, lw=1.6, label=label)
        if mode != "off":
            ratio.semilogy(w, scan.ratio(mode), color=color, ls=ls, lw=1.6, label=f"{mode}: amplitude")
            ratio.semilogy(w, scan.ratio(mode, "max_abs"), color=color, ls=ls, lw=0.9, alpha=0.6,
                           label=f"{mode}: max |φ|")
    ratio.axhline(2.0, color="0.3", lw=1, ls="--")
    ratio.axhline(1.0, color="0.3", lw=0.6)
    for ax in (amp, ratio):
        for n in range(1, int(w[-1] / system.wave_frequency) + 1):
            ax.axvline(n * system.wave_frequency, color="0.6", lw=0.6, ls=":")
        if band is not None:
            ax.axvspan(*band, color="gold", alpha=0.25, zorder=0)
        ax.axvline(system.natural_frequency, color="k", lw=1.2, ls="--")
        ax.grid(alpha=0.3, which="both")
    amp.set(ylabel="amplitude [rad]", ylim=(1e-3, 3.0),
            title="Steady amplitude against ω₀ (dotted: n ω; dashed: the case's ω₀)")
    amp.legend(fontsize=8)
    text = "" if band is None else f"; shaded: claim holds, ω₀ ∈ [{band[0]:.3g}, {band[1]:.3g}] rad/s"
    ratio.set(xlabel="natural frequency ω₀ [rad/s]", ylabel="reduction off / mode", ylim=(0.1, 30.0),
              title="Reduction against no stabilizer" + text)
    ratio.legend(fontsize=8, ncol=2, loc="upper right")
    return _save(fig, path)


def figure_paths(target) -> dict[str, Path]:
    """Where :func:`plot_pitch_case` writes each figure.

    A directory gets the names of :data:`FILES`. A ``.png`` file (as ``kanat run CASE
    --plot OUT.png`` passes) gets fig. 2 itself, and the others go beside it as
    ``OUT_fig3_sinusoidal.png``, ``OUT_modes.png``, ...
    """
    target = Path(target)
    if target.suffix.lower() != ".png":
        return {key: target / name for key, name in FILES.items()}
    return {key: target if key == "period" else
            target.with_name(f"{target.stem}_{name.removeprefix('pitch_')}") for key, name in FILES.items()}


def plot_pitch_case(result, data, target) -> list[Path]:
    """Write every figure of a pitch case and return their paths.

    Parameters
    ----------
    result : kanat.vessel.pitch.PitchResult
    data : kanat.studies.pitch.FigureData
    target : path-like
        A directory, or a ``.png`` file for fig. 2 with the others beside it
        (:func:`figure_paths`).
    """
    paths = figure_paths(target)
    paths["period"].parent.mkdir(parents=True, exist_ok=True)
    plot_period(result, paths["period"])
    for number, mode in ((3, "sinusoidal"), (4, "rectangular")):
        plot_surface(data.times, data.max_moments, data.surfaces[mode], mode, result.max_moment,
                     paths[mode], figure_number=number)
    plot_modes(result, paths["modes"])
    plot_band(data.scan, data.band, result.system, paths["band"])
    return list(paths.values())
