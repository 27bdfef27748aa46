"""The picture of an offset curve (``kanat offsets --plot``): restoring force and largest tension
against offset, the system and each coupled body alone.

Left: the horizontal restoring force along the offset direction, ``F . (cos theta, sin theta, 0)``
[kN], of the system curve (every vessel end and coupled body moved together) and, for a case with
several coupled bodies, of each body's own curve (that body moved alone, the others held; the
force on that body). Right: the largest tension over every cable end [kN] along the same curves.
Lines carry ``gid`` ``force/system``, ``force/BODY``, ``tension/system``, ``tension/BODY``.

Draws from the dataset of :func:`kanat.api.offsets` (names of :mod:`kanat.io.offsets_table`).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kanat.report.geometry import KN

__all__ = ["along", "offset_curves", "plot_offsets"]

DPI = 120
SYSTEM = "system"


def along(force: np.ndarray, direction_deg: float) -> np.ndarray:
    """The horizontal part of ``force`` (..., 3) along ``direction_deg`` (from x towards y) [same units]."""
    theta = math.radians(direction_deg)
    return force[..., 0] * math.cos(theta) + force[..., 1] * math.sin(theta)


def offset_curves(ds) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """What the picture draws: ``name -> (force along the direction, largest end tension)``, each
    shape (offsets,) [N]; ``system`` first, then each body of ``body_restoring_force``."""
    direction = float(ds.attrs.get("direction_deg", 0.0))
    found = {SYSTEM: (along(ds["restoring_force"].values, direction),
                      ds["end_tension"].values.reshape(ds.sizes["offset"], -1).max(axis=1))}
    if "body_restoring_force" in ds:
        for b, body in enumerate(ds["body"].values):
            found[str(body)] = (along(ds["body_restoring_force"].values[b], direction),
                                ds["body_end_tension"].values[b].reshape(ds.sizes["offset"], -1).max(axis=1))
    return found


def plot_offsets(ds, path=None) -> Figure:
    """Draw an offset curve (module docstring); save it to ``path`` (PNG) when given.

    Parameters
    ----------
    ds : xarray.Dataset
        What :func:`kanat.api.offsets` returns or ``kanat offsets`` writes to netCDF.
    path : path-like, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    direction = float(ds.attrs.get("direction_deg", 0.0))
    offset = ds["offset"].values
    fig = Figure(figsize=(12, 4.8), layout="constrained")
    force_ax, tension_ax = fig.subplots(1, 2)
    for k, (name, (force, tension)) in enumerate(offset_curves(ds).items()):
        label = "all moved together" if name == SYSTEM else f"{name} alone, the others held"
        style = {"color": f"C{k}", "lw": 2.2 if name == SYSTEM else 1.6, "ls": "-" if name == SYSTEM else "--",
                 "marker": "o", "ms": 3, "label": label}
        force_ax.plot(offset, force / KN, gid=f"force/{name}", **style)
        tension_ax.plot(offset, tension / KN, gid=f"tension/{name}", **style)
    force_ax.axhline(0.0, color="0.6", lw=0.8)
    force_ax.set(xlabel=f"offset along {direction:g} deg [m]", ylabel=f"restoring force along {direction:g} deg [kN]",
                 title="restoring force of the lines")
    tension_ax.set(xlabel=f"offset along {direction:g} deg [m]", ylabel="largest end tension [kN]",
                   title="largest tension over every cable end")
    for ax in (force_ax, tension_ax):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"{ds.attrs.get('case_name', '')}: offset curve")
    if path is not None:
        fig.savefig(Path(path), dpi=DPI)
    return fig
