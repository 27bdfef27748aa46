"""The picture of a steady state (``kanat statics --plot``): cable shapes and tensions.

Left: the cables in elevation (x–z) with the bodies, the tow point, the anchors, the mean
surface and the seabed, equal scales on both axes; below it the plan (x–y) when the system
leaves the x–z plane. Right: the tension along the unstretched arclength of every cable.
A Naumov & Agievich result (a sphere on two cables) is drawn as the paper's figures 4 and 5
(:func:`kanat.report.sphere_plot.plot_sphere`).

Draws from a result dataset (what ``kanat statics`` writes, or reads back), or from a
:class:`kanat.statics.StaticsResult`, turned into that dataset first. Lines carry ``gid``
``elevation/CABLE``, ``plan/CABLE``, ``tension/CABLE``, ``elevation-body/BODY``.
"""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
from matplotlib.figure import Figure

from kanat.report.geometry import (KN, MIN_RELATIVE_SPAN, at_least, cable_nodes, fixed_points, is_planar, speed_text,
                                   surface_and_seabed)

DPI = 120


def as_dataset(result):
    """A statics result as its dataset (a dataset passes through)."""
    if hasattr(result, "data_vars"):
        return result
    from kanat.io.results import statics_dataset

    return statics_dataset(result)


def _sphere_solution(ds) -> SimpleNamespace:
    """What :func:`kanat.report.sphere_plot.plot_sphere` reads, from a Naumov & Agievich dataset."""
    attrs = ds.attrs
    groups = SimpleNamespace(**{k[len("group_"):]: float(v) for k, v in attrs.items() if k.startswith("group_")})
    x, y = ds["x"].values, ds["y"].values
    return SimpleNamespace(x=x, y=y, x_A=float(x[0]), y_A=float(y[0]), sigma=ds["sigma"].values,
                           alpha=ds["alpha"].values, groups=groups, convention=attrs.get("convention", ""))


def _view(ax, ds, nodes, fixed, a: int, b: int, view: str) -> None:
    position = ds["position"].values
    for k, (name, index) in enumerate(nodes.items()):
        ax.plot(position[index, a], position[index, b], lw=1.8, color=f"C{k}", label=name, gid=f"{view}/{name}")
    if "body" in ds.dims:
        for k, name in enumerate(ds["body"].values):
            at = ds["body_position"].values[k]
            ax.plot(at[a], at[b], "o", ms=9, mfc="white", mec="k", mew=1.5, gid=f"{view}-body/{name}",
                    label="bodies" if k == 0 else None)
    if "vessel_position" in ds and fixed["towed"]:
        tow = ds["vessel_position"].values
        ax.plot(tow[a], tow[b], "v", ms=10, color="k", label="tow point")
    if len(fixed["anchor"]):
        ax.plot(fixed["anchor"][:, a], fixed["anchor"][:, b], "^", ms=9, color="dimgray", label="anchor")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(alpha=0.3)


def plot_statics(result, path=None) -> Figure:
    """Draw a steady state (module docstring); save it to ``path`` (PNG) when given.

    Parameters
    ----------
    result : xarray.Dataset or kanat.statics.StaticsResult
    path : path-like, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    if getattr(result, "sphere", None) is not None:
        from kanat.report.sphere_plot import plot_sphere

        return plot_sphere([result.sphere], path)
    ds = as_dataset(result)
    if "alpha" in ds and "sigma" in ds:
        from kanat.report.sphere_plot import plot_sphere

        return plot_sphere([_sphere_solution(ds)], path)
    nodes, fixed, planar = cable_nodes(ds), fixed_points(ds), is_planar(ds)
    fig = Figure(figsize=(12, 5 if planar else 8.5), layout="constrained")
    grid = fig.add_gridspec(1 if planar else 2, 2, width_ratios=[1.6, 1])
    elevation = fig.add_subplot(grid[0, 0])
    tension = fig.add_subplot(grid[:, 1])
    _view(elevation, ds, nodes, fixed, 0, 2, "elevation")
    z = ds["position"].values[:, 2]
    surface_and_seabed(elevation, fixed["depth"], float(z.min()), float(np.ptp(z)))
    elevation.legend(fontsize=8, loc="best")
    speed = float(np.hypot(*ds["velocity"].values[0, :2])) if "velocity" in ds else 0.0
    elevation.set(xlabel="x [m]", ylabel="z [m]",
                  title="elevation (x–z)" + (f", tow speed {speed_text(ds, speed)}" if speed else ""))
    if not planar:
        plan = fig.add_subplot(grid[1, 0])
        _view(plan, ds, nodes, fixed, 0, 1, "plan")
        plan.legend(fontsize=8, loc="best")
        plan.set(xlabel="x [m]", ylabel="y [m] (port)", title="plan (x–y), seen from above")
    s, values = ds["s"].values, ds["tension"].values
    for k, (name, index) in enumerate(nodes.items()):
        tension.plot(s[index], values[index] / KN, lw=1.8, color=f"C{k}", label=name, gid=f"tension/{name}")
    at_least(tension, "y", values / KN, relative=MIN_RELATIVE_SPAN)
    tension.set(xlabel="s [m] (unstretched, from the first end)", ylabel="effective tension [kN]",
                title="tension along each cable")
    tension.grid(alpha=0.3)
    tension.legend(fontsize=8)
    fig.suptitle(ds.attrs.get("case_name", "") or "statics")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig
