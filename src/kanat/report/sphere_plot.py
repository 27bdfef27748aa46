"""Figures of the Naumov & Agievich sphere equilibrium (the paper's figs. 4 and 5).

Built on :class:`matplotlib.figure.Figure` directly (no pyplot state), so it works
under any backend, ``Agg`` included.
"""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

#: Size of the figure [inch] and resolution of the saved PNG [dpi].
FIGSIZE, DPI = (11.0, 5.0), 150


def _default_label(solution) -> str:
    g = solution.groups
    return f"Ψ = {g.Psi:g}, QkL = {g.QkL:g}, RkL = {g.RkL:g} ({solution.convention})"


def _draw_shape(ax, solution, color, label) -> None:
    """Cable AOB, sphere A, dashed line AC and anchor C of one solution (fig. 4)."""
    x_c = solution.groups.x_C
    ax.plot(solution.x, solution.y, color=color, lw=2, label=label)
    ax.plot([solution.x_A, x_c], [solution.y_A, 0.0], ls="--", color=color, lw=1.2)
    ax.plot(solution.x_A, solution.y_A, "o", ms=13, mfc="white", mec=color, mew=2, zorder=5)
    ax.annotate("A", (solution.x_A, solution.y_A), xytext=(9, 6),
                textcoords="offset points", color=color, fontsize=10)
    ax.plot(x_c, 0.0, "^", ms=10, color="0.25", zorder=5)


def _decorate_shape(ax, solutions) -> None:
    """Bottom, anchors B and C, flow arrow, axes of the shape panel."""
    x_c = solutions[0].groups.x_C
    ax.plot(0.0, 0.0, "^", ms=10, color="0.25", zorder=5)
    ax.annotate("B", (0.0, 0.0), xytext=(6, -14), textcoords="offset points")
    ax.annotate("C", (x_c, 0.0), xytext=(6, -14), textcoords="offset points")
    xs = np.concatenate([np.r_[s.x, s.groups.x_C] for s in solutions])
    lo, hi = xs.min() - 0.15, xs.max() + 0.25
    ax.axhspan(-0.08, 0.0, color="0.85", zorder=0)
    ax.axhline(0.0, color="0.4", lw=1)
    top = max(s.y_A for s in solutions)
    ax.annotate("", xy=(lo + 0.45, top + 0.12), xytext=(lo + 0.05, top + 0.12),
                arrowprops={"arrowstyle": "->", "color": "0.3"})
    ax.text(lo + 0.5, top + 0.12, "flow on the cable", va="center", fontsize=9, color="0.3")
    ax.set_xlim(lo, hi)
    ax.set_ylim(-0.08, top + 0.25)
    ax.set_aspect("equal")
    ax.set_xlabel("x = X / L")
    ax.set_ylabel("y = Y / L")
    ax.set_title("Cable shape (paper fig. 4); dashed: line AC")


def _draw_angle(ax, solutions, colors) -> None:
    """Cable angle alpha [deg] along sigma (fig. 5)."""
    for sol, color in zip(solutions, colors):
        ax.plot(sol.sigma, np.degrees(sol.alpha), color=color, lw=2)
    ax.set_xlim(0.0, 1.0)
    ax.set_xlabel("σ = S / L   (A at 0, B at 1)")
    ax.set_ylabel("α [deg]")
    ax.set_title("Cable angle along the cable (paper fig. 5)")
    ax.grid(True, lw=0.5, color="0.85")


def plot_sphere(solutions, path=None, labels=None) -> Figure:
    """Shape and angle of one or several sphere equilibria, side by side.

    Parameters
    ----------
    solutions : SphereSolution or sequence of SphereSolution
        From :func:`kanat.statics.sphere_solvers.solve_sphere`; overlaid in one figure.
    path : str or path-like, optional
        Where to save the figure as PNG.
    labels : sequence of str, optional
        Legend entries, one per solution; default: the groups and convention.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if not isinstance(solutions, (list, tuple)):
        solutions = [solutions]
    if labels is None:
        labels = [_default_label(s) for s in solutions]
    if len(labels) != len(solutions):
        raise ValueError(f"{len(labels)} labels for {len(solutions)} solutions")
    colors = [f"C{i}" for i in range(len(solutions))]
    fig = Figure(figsize=FIGSIZE, layout="constrained")
    ax_shape, ax_angle = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.35, 1.0]})
    for sol, color, label in zip(solutions, colors, labels):
        _draw_shape(ax_shape, sol, color, label)
    _decorate_shape(ax_shape, solutions)
    _draw_angle(ax_angle, solutions, colors)
    fig.legend(loc="outside lower center", ncols=min(len(solutions), 2), fontsize=9,
               frameon=False)
    if path is not None:
        fig.savefig(path, dpi=DPI)
    return fig
