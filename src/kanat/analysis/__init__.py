"""Analysis of result datasets (case-format.md names): each a function of the dataset.

Public API
----------
node_statistics(ds, variable="tension", nodes=None, window=None, duration=None)
    min, max, mean, std and Rayleigh most-probable maximum per node over a time window.
body_statistics(ds, window=None, duration=None)
    The same for each body's depth.
most_probable_maximum(values, window_s, duration=None)
    The MPM estimator (narrow-band Rayleigh; :mod:`.statistics` states it).
range_graph(ds, variable="tension", window=None)
    min/max/mean/std along every cable.
snap_events(ds, window=None), snap_summary(ds, window=None)
    Snap-event tables (pandas).
tension_spectrum(ds, nodes=None, window=None, segment_s=None)
    Welch power spectral density of tension.
body_depth_excursions(ds, window=None)
    Initial, least and greatest depth, rise and dive of each body.
summary_statistics(ds, window=None, duration=None)
    One row of numbers per result (used by :mod:`kanat.sweep`).
select_nodes(ds, nodes), time_window(ds, window)
    Node selectors (indices or ``CABLE@S``) and time windows.

Modules for any tension series (import them by name): :mod:`kanat.analysis.extremes`
(``mpm(series, time, duration, method)``: Rayleigh, Weibull, Gumbel most probable maxima)
and :mod:`kanat.analysis.fatigue` (``rainflow``, ``damage`` on API RP 2SK T-N curves,
``stress_damage`` on DNV-OS-E301 S-N curves).
"""
from kanat.analysis.bodies import body_depth_excursions
from kanat.analysis.events import has_events, snap_events, snap_summary
from kanat.analysis.select import cable_names, first_nodes, select_nodes, time_window
from kanat.analysis.spectra import spectral_peak, tension_spectrum
from kanat.analysis.statistics import (STATISTICS, body_statistics, most_probable_maximum, node_statistics,
                                       range_graph, series_statistics, upcrossings)
from kanat.analysis.summary import statistic_units, summary_statistics

__all__ = ["STATISTICS", "body_depth_excursions", "body_statistics", "cable_names", "first_nodes", "has_events",
           "most_probable_maximum", "node_statistics", "range_graph", "select_nodes", "series_statistics",
           "snap_events", "snap_summary", "spectral_peak", "statistic_units", "summary_statistics",
           "tension_spectrum", "time_window", "upcrossings"]
