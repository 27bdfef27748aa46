"""Snap events (slack -> taut, theory/lumped.md §7) as tables.

A lumped run writes its events on the ``event`` dimension: ``event_time``,
``event_segment``, ``event_peak_tension``, ``event_rise_rate`` (:mod:`kanat.lumped.output`).
Results without them (continuum runs: a continuum cable stays taut) give empty tables.
"""
from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr


EVENT_COLUMNS = ("time", "segment", "cable", "peak_tension", "rise_rate")
SUMMARY_COLUMNS = ("cable", "events", "peak_tension_max", "rise_rate_max", "first_time", "last_time")


def has_events(ds: xr.Dataset) -> bool:
    """True when the result records snap events (even if none happened)."""
    return "event_time" in ds


def snap_events(ds: xr.Dataset, window=None) -> pd.DataFrame:
    """Every snap event, sorted by time.

    Parameters
    ----------
    ds : xarray.Dataset
    window : (float or None, float or None), optional
        Keep the events with ``start <= time <= end`` [s].

    Returns
    -------
    pandas.DataFrame
        Columns ``time`` [s], ``segment`` (global index), ``cable`` (its cable's name, when
        the result has ``segment_cable``), ``peak_tension`` [N], ``rise_rate`` [N/s].
    """
    if not has_events(ds) or ds.sizes.get("event", 0) == 0:
        return pd.DataFrame({c: pd.Series(dtype=object if c == "cable" else float) for c in EVENT_COLUMNS})
    segment = ds["event_segment"].values.astype(int)
    cable = (ds["segment_cable"].values[segment].astype(str) if "segment_cable" in ds
             else np.array([""] * len(segment)))
    table = pd.DataFrame({"time": ds["event_time"].values, "segment": segment, "cable": cable,
                          "peak_tension": ds["event_peak_tension"].values,
                          "rise_rate": ds["event_rise_rate"].values})
    if window is not None:
        lo, hi = window
        keep = np.ones(len(table), bool)
        if lo is not None:
            keep &= table["time"].values >= lo - 1e-9
        if hi is not None:
            keep &= table["time"].values <= hi + 1e-9
        table = table[keep]
    return table.sort_values(["time", "segment"], kind="stable").reset_index(drop=True)


def snap_summary(ds: xr.Dataset, window=None) -> pd.DataFrame:
    """Snap events per cable: count, largest peak tension and rise rate, first and last time."""
    events = snap_events(ds, window)
    rows = []
    for cable, group in events.groupby("cable", sort=False):
        rows.append({"cable": cable, "events": len(group), "peak_tension_max": group["peak_tension"].max(),
                     "rise_rate_max": group["rise_rate"].max(), "first_time": group["time"].min(),
                     "last_time": group["time"].max()})
    return pd.DataFrame(rows, columns=list(SUMMARY_COLUMNS))
