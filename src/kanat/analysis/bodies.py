"""Body depth excursions: how far each body rises and dives from where the window starts.

Depth is ``-z`` (``z = 0`` at the mean free surface, up positive; theory/index.md §1).
"""
from __future__ import annotations

import numpy as np
import xarray as xr

from kanat.analysis.select import time_window
from kanat.errors import KanatError


def body_depth_excursions(ds: xr.Dataset, window=None) -> xr.Dataset:
    """Depth excursions of every body over a time window.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic result.
    window : (float or None, float or None), optional
        Time window [s].

    Returns
    -------
    xarray.Dataset
        Over ``body`` [m unless noted]: ``initial_depth`` (at the window's start),
        ``min_depth``, ``max_depth``, ``excursion`` (max - min), ``rise`` (initial - min,
        >= 0), ``dive`` (max - initial, >= 0), ``time_of_min_depth`` and
        ``time_of_max_depth`` [s] (first occurrence).
    """
    if "time" not in ds.dims:
        raise KanatError("depth excursions need a dynamic result (a 'time' dimension)")
    part = time_window(ds, window)
    if "body" not in ds.dims or ds.sizes["body"] == 0:
        return xr.Dataset(coords={"body": np.array([], dtype=object)})
    time = part["time"].values
    depth = -part["body_position"].values[:, :, 2]
    shallowest, deepest = depth.argmin(axis=0), depth.argmax(axis=0)
    lo, hi, first = depth.min(axis=0), depth.max(axis=0), depth[0]
    data = {"initial_depth": first, "min_depth": lo, "max_depth": hi, "excursion": hi - lo,
            "rise": first - lo, "dive": hi - first}
    out = {k: ("body", v, {"units": "m"}) for k, v in data.items()}
    out["time_of_min_depth"] = ("body", time[shallowest], {"units": "s"})
    out["time_of_max_depth"] = ("body", time[deepest], {"units": "s"})
    return xr.Dataset(out, coords={"body": ds["body"].values},
                      attrs={"window": [float(time[0]), float(time[-1])]})
