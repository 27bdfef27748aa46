"""A static 3-D view of a system, as MoorPy's ``System.plot()``: cables, bodies, anchors,
the water surface and the seabed.

:func:`plot_overview` draws one state of a result (a statics result, or one output of a
dynamic run) in true proportions (equal scales on x, y and z), each cable its own line.
:func:`plot_layout` draws a case as written, before any model has solved it: every cable a
straight line between its ends where the case places them (anchors, vessel fairleads,
bodies and points with a ``position``), for cases no model runs yet (a MoorDyn file with
6-DOF bodies, say) -- its title says it is not an equilibrium.

Lines carry ``gid`` ``cable/NAME``; bodies ``body/NAME``.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kanat.report.geometry import cable_nodes, fixed_points

DPI = 110
PLANE_MARGIN = 0.1
"""The surface and seabed planes reach this fraction of the system's size beyond it."""


def _axes(fig: Figure):
    ax = fig.add_subplot(projection="3d")
    ax.set_xlabel("x [m]", labelpad=14)          # clear of the tick labels
    ax.set_ylabel("y [m] (port)", labelpad=14)
    ax.set_zlabel("z [m] (up)", labelpad=10)
    return ax


def _planes(ax, points: np.ndarray, depth: float) -> None:
    """The mean surface (z = 0) and the seabed (z = -depth) under the system."""
    low, high = points[:, :2].min(axis=0), points[:, :2].max(axis=0)
    pad = PLANE_MARGIN * max(float(np.max(high - low)), 1.0)
    x = np.array([low[0] - pad, high[0] + pad])
    y = np.array([low[1] - pad, high[1] + pad])
    gx, gy = np.meshgrid(x, y)
    ax.plot_surface(gx, gy, np.zeros_like(gx), color="tab:blue", alpha=0.12, linewidth=0)
    reach = float(points[:, 2].min()) - 0.3 * max(float(np.ptp(points)), 1.0)
    if np.isfinite(depth) and -depth > reach:
        ax.plot_surface(gx, gy, np.full_like(gx, -depth), color="saddlebrown", alpha=0.18, linewidth=0)


THIN_AXIS = 0.2
"""An axis spans at least this fraction of the largest one (a nearly planar system's thin axis
would otherwise collapse into a sliver of overlapping tick labels); limits and box grow
together, so the scales stay equal."""


def _equal(ax, points: np.ndarray) -> None:
    """Equal scales on the three axes around ``points``."""
    low, high = points.min(axis=0), points.max(axis=0)
    span = max(float(np.max(high - low)), 1.0)
    centre = 0.5 * (low + high)
    ranges = np.maximum(high - low, THIN_AXIS * span)
    for name, c, r in zip("xyz", centre, ranges):
        getattr(ax, f"set_{name}lim")(c - 0.55 * r, c + 0.55 * r)
    ax.set_box_aspect(tuple(ranges))


def plot_overview(ds, path=None, output: int = -1, title: str | None = None) -> Figure:
    """A 3-D view of one state of a result (module docstring).

    Parameters
    ----------
    ds : xarray.Dataset
        A statics or dynamic result.
    path : path-like, optional
        PNG to write.
    output : int
        Output index of a dynamic result (default: the last).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    pick = (lambda name: ds[name].values[output]) if "time" in ds.dims else (lambda name: ds[name].values)
    position = pick("position")
    fixed = fixed_points(ds)
    fig = Figure(figsize=(9, 7), layout="constrained")
    ax = _axes(fig)
    for k, (name, index) in enumerate(cable_nodes(ds).items()):
        xyz = position[index]
        ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], lw=1.8, color=f"C{k}", label=name, gid=f"cable/{name}")
    points = [position]
    if "body" in ds.dims and ds.sizes["body"]:
        bodies = pick("body_position").reshape(-1, 3)
        for name, at in zip(ds["body"].values, bodies):
            ax.scatter(*at, s=60, color="white", edgecolors="k", depthshade=False, gid=f"body/{name}")
            ax.text(*at, f"  {name}", fontsize=8)
        points.append(bodies)
    if len(fixed["anchor"]):
        ax.scatter(*fixed["anchor"].T, marker="^", s=60, color="dimgray", depthshade=False, label="anchor")
    points = np.concatenate(points)
    _planes(ax, np.vstack([points, [[points[:, 0].min(), points[:, 1].min(), 0.0]]]), fixed["depth"])
    _equal(ax, np.vstack([points, np.zeros((1, 3)) + [points[0, 0], points[0, 1], 0.0]]))
    when = f", t = {float(ds['time'].values[output]):g} s" if "time" in ds.dims else ""
    ax.set_title(title or f"{ds.attrs.get('case_name', '')}{when}")
    ax.legend(fontsize=8, loc="upper left")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig


def layout_lines(case) -> dict[str, np.ndarray]:
    """Straight lines between the ends a case places, by cable name (ends without a
    position -- a free end, a body without ``position`` -- leave their cable out).

    Returns
    -------
    dict of str to ndarray, shape (2, 3)
    """
    def where(end):
        if end.kind == "anchor":
            return np.asarray(end.position, dtype=float)
        if end.kind == "vessel":
            return np.asarray(end.offset if end.offset is not None else case.vessel.tow_point, dtype=float)
        owner = (case.bodies if end.kind == "body" else case.points).get(end.name) if end.name else None
        if owner is None or owner.position is None:
            return None
        return np.asarray(owner.position, dtype=float) + (np.asarray(end.offset) if end.offset is not None else 0.0)

    lines = {}
    for cable in case.cables:
        ends = [where(cable.from_), where(cable.to)]
        if all(e is not None for e in ends):
            lines[cable.name] = np.array(ends)
    return lines


def plot_layout(case, path=None, note: str = "") -> Figure:
    """A case as written: straight cables between their placed ends (module docstring)."""
    fig = Figure(figsize=(9, 7), layout="constrained")
    ax = _axes(fig)
    lines = layout_lines(case)
    for k, (name, xyz) in enumerate(lines.items()):
        ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], lw=1.5, ls="--", color=f"C{k}", label=name, gid=f"cable/{name}")
    placed = [np.asarray(b.position) for b in [*case.bodies.values(), *case.points.values()] if b.position is not None]
    for name, item in [*case.bodies.items(), *case.points.items()]:
        if item.position is not None:
            ax.scatter(*item.position, s=50, color="white", edgecolors="k", depthshade=False, gid=f"body/{name}")
            ax.text(*item.position, f"  {name}", fontsize=8)
    points = np.concatenate([*lines.values(), *(p[None] for p in placed)]) if lines or placed else np.zeros((1, 3))
    depth = case.environment.depth if case.environment.depth is not None else np.nan
    _planes(ax, points, depth)
    _equal(ax, np.vstack([points, [[points[0, 0], points[0, 1], 0.0]]]))
    ax.set_title(f"{case.name}: layout as written, straight lines between the ends (not an equilibrium)"
                 + (f"\n{note}" if note else ""), fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig
