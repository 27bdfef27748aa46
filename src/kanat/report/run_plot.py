"""The picture of a dynamic result (``kanat run --plot``): histories and cable snapshots.

Top: the tension at the first node (``s = 0``) of every cable against time, and the height
of every body, each on its own axis with a least span (:func:`kanat.report.geometry.at_least`).
Bottom: the cables at a few evenly spaced times in elevation (x–z) and, for a run that
leaves the x–z plane, in plan (x–y), each cable its own line, bodies marked, equal scales
on both axes. Positions are drawn in the global frame when the tow point stays put, and in
a frame translating with the tow point when it moves (so a long tow's snapshots overlay).

Every line that shows geometry carries a ``gid`` naming what it is
(``elevation/CABLE/OUTPUT``, ``plan/CABLE/OUTPUT``, ``elevation-body/BODY/OUTPUT``), so a
test can read back what was drawn.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kanat.report.geometry import (
    KN,
    MIN_HEIGHT_SPAN,
    MIN_RELATIVE_SPAN,
    at_least,
    cable_nodes,
    fixed_points,
    is_planar,
    snapshot_indices,
    surface_and_seabed,
    tow_frame,
)

DPI = 110
STYLES = ("-", "--", "-.", ":")
"""Line styles cycled with the colours, so that curves that coincide (two symmetric
otter boards) both show."""
SNAPSHOT_COLOURS = "viridis"
"""Colour map of the snapshot times (the history panels use the C0, C1, ... cycle per cable)."""
VIEWS = {"elevation": (0, 2), "plan": (0, 1)}
"""The projections drawn: name -> the two position components (x–z, x–y)."""


def _histories(ax_tension, ax_height, ds, nodes) -> None:
    time = ds["time"].values
    tension = ds["tension"].values
    for k, (name, index) in enumerate(nodes.items()):
        ax_tension.plot(time, tension[:, index[0]] / KN, lw=1.4, color=f"C{k}", ls=STYLES[k % len(STYLES)],
                        label=f"{name} at s = 0",
                        gid=f"tension/{name}")
    at_least(ax_tension, "y", tension[:, [i[0] for i in nodes.values()]] / KN, relative=MIN_RELATIVE_SPAN)
    ax_tension.set(xlabel="time [s]", ylabel="tension [kN]", title="tension at the first end of each cable")
    ax_tension.grid(alpha=0.3)
    ax_tension.legend(fontsize=8, loc="best")
    if ax_height is None:
        return
    heights = ds["body_position"].values[:, :, 2]
    for k, name in enumerate(ds["body"].values):
        ax_height.plot(time, heights[:, k], lw=1.4, color=f"C{k}", ls=STYLES[k % len(STYLES)], label=str(name),
                       gid=f"height/{name}")
    at_least(ax_height, "y", heights, minimum=MIN_HEIGHT_SPAN)
    ax_height.set(xlabel="time [s]", ylabel="z [m] (up; 0 at the mean surface)", title="body height")
    ax_height.grid(alpha=0.3)
    ax_height.legend(fontsize=8, loc="best")


def draw_view(ax, ds, view: str, picks, frame, nodes, fixed) -> None:
    """Cables, bodies, tow point and anchors of outputs ``picks`` projected on ``view``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    ds : xarray.Dataset
        A dynamic result.
    view : {"elevation", "plan"}
    picks : sequence of int
        Output indices to draw (one colour each).
    frame : kanat.report.geometry.Frame
    nodes : dict of str to ndarray
        :func:`kanat.report.geometry.cable_nodes`.
    fixed : dict
        :func:`kanat.report.geometry.fixed_points`.
    """
    a, b = VIEWS[view]
    time, position = ds["time"].values, ds["position"].values
    bodies = ds["body"].values if "body" in ds.dims else []
    from matplotlib import colormaps

    colours = colormaps[SNAPSHOT_COLOURS](np.linspace(0.0, 0.9, len(picks)))
    for colour, i in zip(colours, picks):
        xyz = position[i] - frame.shift[i]
        for k, (name, index) in enumerate(nodes.items()):
            ax.plot(xyz[index, a], xyz[index, b], color=colour, lw=1.3,
                    label=f"t = {time[i]:g} s" if k == 0 else None, gid=f"{view}/{name}/{i}")
        for k, name in enumerate(bodies):
            at = ds["body_position"].values[i, k] - frame.shift[i]
            ax.plot(at[a], at[b], "o", ms=7, mfc=colour, mec="k", gid=f"{view}-body/{name}/{i}")
    if fixed["towed"]:
        tow = ds["vessel_position"].values[picks] - frame.shift[picks]
        ax.plot(tow[:, a], tow[:, b], "v", ms=9, color="k", label="tow point", gid=f"{view}-tow")
    if len(fixed["anchor"]) and not frame.moving:
        ax.plot(fixed["anchor"][:, a], fixed["anchor"][:, b], "^", ms=9, color="dimgray", label="anchor")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(alpha=0.3)


def _geometry(ax_elevation, ax_plan, ds, snapshots: int, nodes) -> None:
    picks = snapshot_indices(ds.sizes["time"], snapshots)
    frame, fixed = tow_frame(ds), fixed_points(ds)
    draw_view(ax_elevation, ds, "elevation", picks, frame, nodes, fixed)
    z = ds["position"].values[picks][..., 2]
    surface_and_seabed(ax_elevation, fixed["depth"], float(z.min()), float(np.ptp(z)))
    ax_elevation.set(xlabel=frame.label("x"), ylabel="z [m] (up)", title="elevation (x–z)")
    ax_elevation.legend(fontsize=8, loc="best")
    if ax_plan is not None:
        draw_view(ax_plan, ds, "plan", picks, frame, nodes, fixed)
        ax_plan.set(xlabel=frame.label("x"), ylabel=frame.label("y") + " (port)", title="plan (x–y), seen from above")


def plot_run(ds, path=None, snapshots: int = 6) -> Figure:
    """Draw a result (module docstring); save it to ``path`` (PNG) when given.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic result (names of :mod:`kanat.io.schema`); a statics result (no ``time``)
        is drawn by :func:`kanat.report.statics_plot.plot_statics`.
    path : path-like, optional
    snapshots : int
        Outputs drawn in the geometry views, evenly spaced, first and last included.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if "time" not in ds.dims:
        from kanat.report.statics_plot import plot_statics

        return plot_statics(ds, path)
    nodes = cable_nodes(ds)
    has_bodies = "body" in ds.dims and ds.sizes["body"] > 0
    planar = is_planar(ds)
    fig = Figure(figsize=(12, 8.5), layout="constrained")
    grid = fig.add_gridspec(2, 2, height_ratios=[1, 1.25])
    ax_tension = fig.add_subplot(grid[0, 0] if has_bodies else grid[0, :])
    ax_height = fig.add_subplot(grid[0, 1]) if has_bodies else None
    ax_elevation = fig.add_subplot(grid[1, :] if planar else grid[1, 0])
    ax_plan = None if planar else fig.add_subplot(grid[1, 1])
    _histories(ax_tension, ax_height, ds, nodes)
    _geometry(ax_elevation, ax_plan, ds, snapshots, nodes)
    attrs = ds.attrs
    fig.suptitle(f"{attrs.get('case_name', '')} — {attrs.get('model', '')}, {attrs.get('scheme', '')}, "
                 f"status {attrs.get('status', '?')}")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig
