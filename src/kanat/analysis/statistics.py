"""Statistics of a result over a time window: per node, per body, and along the cable.

Each statistic is taken over the samples of the output time series inside the window
(both ends included): minimum, maximum, mean, standard deviation (population, ``ddof=0``)
and the most-probable maximum (MPM).

Most-probable maximum
---------------------
The estimator is the Rayleigh MPM of a narrow-band Gaussian process (e.g. DNV-RP-C205
§3.3, Ochi 1990): the peaks of such a process above its mean are Rayleigh distributed with
scale ``sigma``, and the most probable largest of ``N`` peaks is, for large ``N``,

    MPM = mean + sigma * sqrt(2 ln N)

with ``N`` the number of zero up-crossings of ``x - mean`` in the window (one per cycle
of a narrow-band process). Given a longer ``duration`` (a 3-hour storm from a 20-minute
simulation), ``N`` is scaled by ``duration / window length``. A constant signal
(``sigma = 0``) has MPM = mean; a window with fewer than 2 up-crossings gives NaN (no
narrow-band estimate). The estimator assumes narrow-band Gaussian response: for snatch
loads, strongly non-linear or broad-band tension, read the sample maximum instead.
"""
from __future__ import annotations

import numpy as np
import xarray as xr

from kanat.analysis.select import select_nodes, time_window
from kanat.errors import KanatError

STATISTICS = ("min", "max", "mean", "std", "mpm")
"""The statistics every function here returns, in this order."""


def upcrossings(values: np.ndarray) -> np.ndarray:
    """Number of zero up-crossings of ``values - mean`` along axis 0.

    Parameters
    ----------
    values : ndarray, shape (n_time, ...)

    Returns
    -------
    ndarray, shape (...)
    """
    centred = values - values.mean(axis=0)
    return np.count_nonzero((centred[:-1] < 0.0) & (centred[1:] >= 0.0), axis=0)


def most_probable_maximum(values: np.ndarray, window_s: float, duration: float | None = None) -> np.ndarray:
    """Rayleigh most-probable maximum of each series (module docstring).

    Parameters
    ----------
    values : ndarray, shape (n_time, ...)
        Samples over the window.
    window_s : float
        Length of the window [s].
    duration : float, optional
        Exposure duration to extrapolate to [s] (default: the window itself).

    Returns
    -------
    ndarray, shape (...)
        MPM in the units of ``values``.
    """
    values = np.asarray(values, dtype=float)
    mean, sigma = values.mean(axis=0), values.std(axis=0)
    count = upcrossings(values).astype(float)
    if duration is not None:
        if window_s <= 0:
            raise KanatError("the window holds a single instant; cannot extrapolate its maximum to a duration")
        count = count * (duration / window_s)
    with np.errstate(divide="ignore", invalid="ignore"):
        spread = sigma * np.sqrt(2.0 * np.log(np.where(count >= 2.0, count, np.nan)))
    return np.where(sigma == 0.0, mean, mean + spread)


def series_statistics(values: np.ndarray, window_s: float, duration: float | None = None) -> dict:
    """min, max, mean, std and MPM of each series along axis 0 (``{name: ndarray}``)."""
    values = np.asarray(values, dtype=float)
    if values.shape[0] == 0:
        raise KanatError("the time window holds no output sample; widen it")
    return {"min": values.min(axis=0), "max": values.max(axis=0), "mean": values.mean(axis=0),
            "std": values.std(axis=0), "mpm": most_probable_maximum(values, window_s, duration)}


def _window_length(ds: xr.Dataset) -> float:
    time = ds["time"].values
    return float(time[-1] - time[0]) if time.size else 0.0


def _needs_time(ds: xr.Dataset, what: str) -> None:
    if "time" not in ds.dims:
        raise KanatError(f"{what} needs a dynamic result (a 'time' dimension); this result is "
                         f"'{ds.attrs.get('model', '?')}' without one")


def node_statistics(ds: xr.Dataset, variable: str = "tension", nodes=None, window=None,
                    duration: float | None = None) -> xr.Dataset:
    """Statistics of a node variable at chosen nodes over a time window.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic result (case-format.md).
    variable : str
        A ``(time, node)`` variable, e.g. ``tension``.
    nodes : sequence of int or str, optional
        Node indices or ``CABLE@S`` selectors (:func:`kanat.analysis.select_nodes`);
        default every node.
    window : (float or None, float or None), optional
        Start and end time [s]; default the whole run.
    duration : float, optional
        Exposure duration for the MPM [s].

    Returns
    -------
    xarray.Dataset
        Variables ``min, max, mean, std, mpm`` over ``node``, with coordinates ``s`` and
        ``cable``; attribute ``window`` (start, end) [s].
    """
    _needs_time(ds, "node statistics")
    if variable not in ds or ds[variable].dims != ("time", "node"):
        raise KanatError(f"'{variable}' is not a (time, node) variable of this result; "
                         f"those are: {', '.join(v for v in ds.data_vars if ds[v].dims == ('time', 'node'))}")
    part = time_window(ds, window)
    index = select_nodes(ds, nodes)
    stats = series_statistics(part[variable].values[:, index], _window_length(part), duration)
    units = ds[variable].attrs.get("units", "")
    return xr.Dataset({k: ("node", v, {"units": units}) for k, v in stats.items()},
                      coords={"node": index, "s": ("node", ds["s"].values[index]),
                              "cable": ("node", ds["cable"].values[index])},
                      attrs={"variable": variable, "window": _span(part)})


def _span(part: xr.Dataset) -> list[float]:
    time = part["time"].values
    return [float(time[0]), float(time[-1])]


def body_statistics(ds: xr.Dataset, window=None, duration: float | None = None) -> xr.Dataset:
    """Statistics of each body's depth (``-z``) over a time window.

    Returns
    -------
    xarray.Dataset
        Variables ``min, max, mean, std, mpm`` of the depth [m] over ``body`` (the MPM is
        that of the greatest depth).
    """
    _needs_time(ds, "body statistics")
    part = time_window(ds, window)
    if "body" not in ds.dims or ds.sizes["body"] == 0:
        return xr.Dataset(attrs={"window": _span(part)})
    depth = -part["body_position"].values[:, :, 2]
    stats = series_statistics(depth, _window_length(part), duration)
    return xr.Dataset({k: ("body", v, {"units": "m"}) for k, v in stats.items()},
                      coords={"body": ds["body"].values}, attrs={"quantity": "depth", "window": _span(part)})


def range_graph(ds: xr.Dataset, variable: str = "tension", window=None) -> xr.Dataset:
    """Range graph along the cables: per node, the min, max, mean and std over the window.

    Returns
    -------
    xarray.Dataset
        Over ``node`` with coordinates ``s`` (arclength in its cable) and ``cable``;
        plot each cable's ``min``/``max``/``mean`` against ``s``.
    """
    stats = node_statistics(ds, variable, None, window)
    return stats.drop_vars("mpm")
