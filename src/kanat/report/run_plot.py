"""The picture of a dynamic result (``kanat run --plot``): histories and cable snapshots.

What is drawn depends on the kind of system (:mod:`kanat.report.kinds`). Top left: the
tensions that matter (towed systems and networks: the top tension, at the vessel; moored
systems: the fairlead tensions, never the anchor ends). Top right: the bodies' depth (towed
systems and networks) or their surge, heave and pitch (moored systems), each on its own axis
with a least span (:func:`kanat.report.geometry.at_least`). Bottom: the cables at a few evenly
spaced times in elevation (x–z) and, for a run that leaves the x–z plane, in plan (x–y), with
equal scales on both axes. A single cable is coloured by time; a system of several cables has
each cable in its own colour, named in the legend, the latest output solid and the earlier
ones faint. Positions are drawn in the global frame when the tow point stays put, and in a
frame translating with the tow point when it moves (so a long tow's snapshots overlay).

Every line carries a ``gid`` naming what it is (``tension/LABEL``, ``depth/BODY``,
``surge/BODY``, ``heave/BODY``, ``pitch/BODY``, ``elevation/CABLE/OUTPUT``,
``plan/CABLE/OUTPUT``, ``elevation-body/BODY/OUTPUT``), so a test can read back what was drawn.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib import colormaps
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
from kanat.report.kinds import Choice, body_histories, choose

DPI = 110
STYLES = ("-", "--", "-.", ":")
"""Line styles cycled with the colours, so that curves that coincide (two symmetric
otter boards) both show."""
SNAPSHOT_COLOURS = "viridis"
"""Colour map of the snapshot times (the history panels use the C0, C1, ... cycle per cable)."""
VIEWS = {"elevation": (0, 2), "plan": (0, 1)}
"""The projections drawn: name -> the two position components (x–z, x–y)."""
FADED = 0.35
"""Opacity of the earlier snapshots of a system drawn by cable (the latest is opaque)."""
MIN_ANGLE_SPAN = 2.0
"""Least span of an angle axis [deg]: a body that does not pitch stays a flat line."""


def _style(by_cable: bool, k: int, name: str, rank: int, count: int, latest: bool, t: float):
    """Colour and legend label of cable ``k`` at snapshot ``rank`` of ``count``."""
    if by_cable:
        return f"C{k}", (name if latest else None)
    return colormaps[SNAPSHOT_COLOURS](0.9 * rank / max(count - 1, 1)), (f"t = {t:g} s" if k == 0 else None)


def _tensions(ax, ds, choice: Choice) -> None:
    time, tension = ds["time"].values, ds["tension"].values
    for k, (label, node) in enumerate(choice.ends.items()):
        ax.plot(time, tension[:, node] / KN, lw=1.4, color=f"C{k}", ls=STYLES[k % len(STYLES)], label=label,
                gid=f"tension/{label}")
    at_least(ax, "y", tension[:, list(choice.ends.values())] / KN, relative=MIN_RELATIVE_SPAN)
    ax.set(xlabel="time [s]", ylabel="tension [kN]", title=choice.tension_title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")


def _body_history(ax, ds, quantity: str, unit: str, values, last: bool) -> None:
    """One body quantity (:func:`kanat.report.kinds.body_histories`) of every body against time."""
    for k, name in enumerate(ds["body"].values):
        ax.plot(ds["time"].values, values[:, k], lw=1.4, color=f"C{k}", ls=STYLES[k % len(STYLES)],
                label=str(name), gid=f"{quantity}/{name}")
    at_least(ax, "y", values, minimum=MIN_HEIGHT_SPAN if unit == "m" else MIN_ANGLE_SPAN)
    ax.set(ylabel=f"{quantity} [{unit}]", title=f"body {quantity}")
    if quantity == "depth":
        ax.invert_yaxis()
    ax.set_xlabel("time [s]" if last else "")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")


def draw_view(ax, ds, view: str, picks, frame, nodes, fixed, by_cable: bool = False) -> None:
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
    by_cable : bool
        Each cable its own colour, named in the legend, the latest output drawn solid and the
        earlier ones faint; else every cable in the colour of its output's time.
    """
    a, b = VIEWS[view]
    time, position = ds["time"].values, ds["position"].values
    bodies = ds["body"].values if "body" in ds.dims else []
    for rank, i in enumerate(picks):
        xyz = position[i] - frame.shift[i]
        latest = rank == len(picks) - 1
        for k, (name, index) in enumerate(nodes.items()):
            colour, label = _style(by_cable, k, name, rank, len(picks), latest, time[i])
            ax.plot(xyz[index, a], xyz[index, b], color=colour, lw=1.6 if latest or not by_cable else 0.9,
                    alpha=1.0 if latest or not by_cable else FADED, ls=STYLES[k % len(STYLES)] if by_cable else "-",
                    label=label, gid=f"{view}/{name}/{i}")
        for k, name in enumerate(bodies):
            at = ds["body_position"].values[i, k] - frame.shift[i]
            face = "white" if by_cable else colormaps[SNAPSHOT_COLOURS](0.9 * rank / max(len(picks) - 1, 1))
            ax.plot(at[a], at[b], "o", ms=7, mfc=face, mec="k", gid=f"{view}-body/{name}/{i}")
    if fixed["towed"]:
        tow = ds["vessel_position"].values[picks] - frame.shift[picks]
        ax.plot(tow[:, a], tow[:, b], "v", ms=9, color="k", label="tow point", gid=f"{view}-tow")
    if len(fixed["anchor"]) and not frame.moving:
        ax.plot(fixed["anchor"][:, a], fixed["anchor"][:, b], "^", ms=9, color="dimgray", label="anchor")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(alpha=0.3)


def _geometry(ax_elevation, ax_plan, ds, snapshots: int, nodes, by_cable: bool) -> None:
    picks = snapshot_indices(ds.sizes["time"], snapshots)
    frame, fixed = tow_frame(ds), fixed_points(ds)
    draw_view(ax_elevation, ds, "elevation", picks, frame, nodes, fixed, by_cable)
    z = ds["position"].values[picks][..., 2]
    surface_and_seabed(ax_elevation, fixed["depth"], float(z.min()), float(np.ptp(z)))
    when = (f": t = {ds['time'].values[picks[-1]]:g} s solid, {len(picks) - 1} earlier outputs faint"
            if by_cable and len(picks) > 1 else "")
    ax_elevation.set(xlabel=frame.label("x"), ylabel="z [m] (up)", title=f"elevation (x–z){when}")
    ax_elevation.legend(fontsize=8, loc="best")
    if ax_plan is not None:
        draw_view(ax_plan, ds, "plan", picks, frame, nodes, fixed, by_cable)
        ax_plan.set(xlabel=frame.label("x"), ylabel=frame.label("y") + " (port)", title="plan (x–y), seen from above")
        if by_cable:
            ax_plan.legend(fontsize=8, loc="best")


def plot_run(ds, path=None, snapshots: int = 6) -> Figure:
    """Draw a result (module docstring); save it to ``path`` (PNG) when given.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic result (names of :mod:`kanat.io.schema`); a statics result (no ``time``)
        is drawn by :func:`kanat.report.statics_plot.plot_statics`, a frequency-domain one by
        :func:`kanat.report.frequency_plot.plot_frequency`, an offset curve (``kanat offsets``)
        by :func:`kanat.report.offsets_plot.plot_offsets`.
    path : path-like, optional
    snapshots : int
        Outputs drawn in the geometry views, evenly spaced, first and last included.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if "frequency" in ds.coords and "time" not in ds.dims:
        from kanat.report.frequency_plot import plot_frequency

        return plot_frequency(ds, path)
    if "offset" in ds.dims and "restoring_force" in ds:
        from kanat.report.offsets_plot import plot_offsets

        return plot_offsets(ds, path)
    if "time" not in ds.dims:
        from kanat.report.statics_plot import plot_statics

        return plot_statics(ds, path)
    nodes, choice = cable_nodes(ds), choose(ds)
    histories = body_histories(ds, choice.kind)
    planar = is_planar(ds)
    fig = Figure(figsize=(12, 8.5 if len(histories) < 2 else 10), layout="constrained")
    grid = fig.add_gridspec(2, 2, height_ratios=[1 if len(histories) < 2 else 1.4, 1.25])
    _tensions(fig.add_subplot(grid[0, 0] if histories else grid[0, :]), ds, choice)
    if histories:
        cells = grid[0, 1].subgridspec(len(histories), 1)
        axes = [fig.add_subplot(cells[k]) for k in range(len(histories))]
        for k, (ax, (quantity, (unit, values))) in enumerate(zip(axes, histories.items())):
            _body_history(ax, ds, quantity, unit, values, last=k == len(histories) - 1)
    ax_elevation = fig.add_subplot(grid[1, :] if planar else grid[1, 0])
    ax_plan = None if planar else fig.add_subplot(grid[1, 1])
    _geometry(ax_elevation, ax_plan, ds, snapshots, nodes, choice.by_cable)
    attrs = ds.attrs
    fig.suptitle(f"{attrs.get('case_name', '')} ({choice.kind}) — {attrs.get('model', '')}, "
                 f"{attrs.get('scheme', '')}, status {attrs.get('status', '?')}")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig
