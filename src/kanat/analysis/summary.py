"""One row of numbers per result: the summary statistics a parameter study tabulates.

Names (every value a float; NaN where the result does not have it):

=========================  ====  =========================================================
``tension_max``            N     largest tension anywhere, any time in the window
``tension_min``            N     smallest tension anywhere
``top_tension_mean``       N     mean tension at the first node of the first cable (the
                                 tow point of a towed cable; ``top`` below means that node)
``top_tension_std``        N     its standard deviation
``top_tension_max``        N     its largest value
``top_tension_mpm``        N     its Rayleigh most-probable maximum
                                 (:mod:`kanat.analysis.statistics`)
``depth_mean_BODY``        m     mean depth of body ``BODY``
``depth_max_BODY``         m     greatest depth of ``BODY``
``depth_excursion_BODY``   m     greatest minus least depth of ``BODY``
``snap_events``            1     snap events in the window (lumped results; NaN if the
                                 result records none, e.g. a continuum run)
``snap_peak_tension_max``  N     largest snap peak tension (NaN without events)
``wall_time_s``            s     computing time of the run
=========================  ====  =========================================================

Statics results give ``tension_max``, ``tension_min``, ``top_tension_mean`` and
``depth_mean_BODY``; pitch results ``pitch_amplitude_MODE`` and ``pitch_max_abs_MODE`` [rad].
"""
from __future__ import annotations

import numpy as np
import xarray as xr

from kanat.analysis.events import has_events, snap_events
from kanat.analysis.select import first_nodes, time_window
from kanat.analysis.statistics import body_statistics, series_statistics

UNITS = {"tension": "N", "top_tension": "N", "depth": "m", "snap_events": "1", "snap_peak": "N",
         "wall_time": "s", "pitch": "rad"}


def statistic_units(name: str) -> str:
    """Units of a summary statistic by its name (``""`` when unknown)."""
    return next((u for prefix, u in sorted(UNITS.items(), key=lambda kv: -len(kv[0]))
                 if name.startswith(prefix)), "")


def summary_statistics(ds: xr.Dataset, window=None, duration: float | None = None) -> dict:
    """The summary statistics of one result (module docstring).

    Parameters
    ----------
    ds : xarray.Dataset
        Any kanat result (dynamic, statics or pitch).
    window : (float or None, float or None), optional
        Time window of a dynamic result [s].
    duration : float, optional
        Exposure duration for the most-probable maximum [s].

    Returns
    -------
    dict of str to float
    """
    stats: dict[str, float] = {}
    if "pitch" in ds and "mode" in ds.dims:
        for k, mode in enumerate(ds["mode"].values):
            stats[f"pitch_amplitude_{mode}"] = float(ds["amplitude"].values[k])
            stats[f"pitch_max_abs_{mode}"] = float(ds["max_abs"].values[k])
    elif "tension" in ds and "time" in ds.dims:
        stats.update(_dynamic(ds, window, duration))
    elif "tension" in ds:
        stats.update(_static(ds))
    stats["wall_time_s"] = float(ds.attrs.get("wall_time_s", np.nan))
    return stats


def _dynamic(ds: xr.Dataset, window, duration) -> dict:
    part = time_window(ds, window)
    time = part["time"].values
    tension = part["tension"].values
    top = series_statistics(tension[:, first_nodes(ds)[:1]], float(time[-1] - time[0]), duration)
    stats = {"tension_max": float(tension.max()), "tension_min": float(tension.min()),
             **{f"top_tension_{k}": float(top[k][0]) for k in ("mean", "std", "max", "mpm")}}
    bodies = body_statistics(ds, window, duration)
    for k, body in enumerate(bodies["body"].values if "body" in bodies.coords else []):
        stats[f"depth_mean_{body}"] = float(bodies["mean"].values[k])
        stats[f"depth_max_{body}"] = float(bodies["max"].values[k])
        stats[f"depth_excursion_{body}"] = float(bodies["max"].values[k] - bodies["min"].values[k])
    if has_events(ds):
        events = snap_events(ds, (float(time[0]), float(time[-1])))
        stats["snap_events"] = float(len(events))
        stats["snap_peak_tension_max"] = float(events["peak_tension"].max()) if len(events) else np.nan
    else:
        stats["snap_events"] = stats["snap_peak_tension_max"] = np.nan
    return stats


def _static(ds: xr.Dataset) -> dict:
    tension = ds["tension"].values
    stats = {"tension_max": float(tension.max()), "tension_min": float(tension.min()),
             "top_tension_mean": float(tension[first_nodes(ds)[0]])}
    if "body" in ds.dims:
        for k, body in enumerate(ds["body"].values):
            stats[f"depth_mean_{body}"] = float(-ds["body_position"].values[k, 2])
    return stats
