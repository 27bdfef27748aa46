"""The HTML report of one result file (``kanat report RESULT.nc -o report.html``).

Sections for a dynamic result: summary and provenance; statistics at the chosen nodes and
bodies; time histories; range graphs along every cable; snap events; tension spectra;
body depth excursions; the animated 3-D view. Statics and pitch results get their own
short pages (shape and tension; pitch per mode).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from kanat.analysis import (body_depth_excursions, body_statistics, cable_names, first_nodes, has_events,
                            node_statistics, range_graph, select_nodes, snap_events, snap_summary,
                            statistic_units, summary_statistics, tension_spectrum, time_window)
from kanat.errors import KanatError
from kanat.report.geometry import embedded_case
from kanat.report.html import Page, frame_table, header, macros, plot_text, shown, table, with_units
from kanat.report.html_animation import animation_section, thin
from kanat.report.kinds import body_histories, choose

STATISTICS = ("min", "max", "mean", "std", "mpm")
"""Columns of the node and body statistics tables (``mpm`` shown as MPM)."""
EVENT_UNITS = {"time": "s", "peak_tension": "N", "rise_rate": "N/s", "peak_tension_max": "N",
               "rise_rate_max": "N/s", "first_time": "s", "last_time": "s"}
"""Units of the snap-event tables' columns (:func:`kanat.analysis.snap_events`, ``snap_summary``)."""
MAX_HISTORY_POINTS = 5000
"""Samples per time-history trace (evenly thinned beyond)."""
EVENT_ROWS = 200


def default_nodes(ds: xr.Dataset) -> np.ndarray:
    """The first and last node of every cable."""
    cables = ds["cable"].values
    last = [int(np.flatnonzero(cables == name)[-1]) for name in cable_names(ds)]
    return np.unique(np.concatenate([first_nodes(ds), last]))


def _label(ds: xr.Dataset, i: int) -> str:
    return f"node {i} ({ds['cable'].values[i]}, s = {ds['s'].values[i]:.4g} m)"


def _provenance(ds: xr.Dataset, source: str):
    rows = [("file", source)] + [(k, v) for k, v in ds.attrs.items()]
    dims = ", ".join(f"{d} = {n}" for d, n in ds.sizes.items())
    return macros("result.html.j2").provenance(
        str(ds.attrs.get("status", "")), dims, table(["attribute", "value"], rows, text_columns=("attribute", "value")))


def summary_table(stats: dict):
    """The summary statistics, one row each with its unit (forces in kN)."""
    rows = [(name, *shown(value, statistic_units(name))) for name, value in stats.items()]
    return table(["statistic", "value", "unit"], rows, text_columns=("statistic", "unit"))


def _stats_table(first: str, labels, stats, unit: str):
    """Rows ``label, min, max, mean, std, MPM`` in the report's unit, the unit in every header."""
    rows = [(label, *(shown(stats[k].values[j], unit)[0] for k in STATISTICS)) for j, label in enumerate(labels)]
    to = shown(0.0, unit)[1]
    return table([first, *(header("MPM" if k == "mpm" else k, to) for k in STATISTICS)], rows, text_columns=(first,))


def _statistics(ds: xr.Dataset, chosen: xr.Dataset, nodes, window):
    """The summary statistics, the chosen nodes' tension and the bodies' depth statistics."""
    summary = summary_table(summary_statistics(ds, window))
    stats = node_statistics(chosen, "tension", nodes, window)
    node_table = _stats_table("node", [_label(chosen, int(i)) for i in stats["node"].values], stats, "N")
    bodies = body_statistics(chosen, window)
    body_table = None
    if "body" in bodies.coords:
        body_table = _stats_table("body", [str(b) for b in bodies["body"].values], bodies, "m")
    span = stats.attrs["window"]
    return macros("result.html.j2").statistics(summary, node_table, body_table, (f"{span[0]:g}", f"{span[1]:g}"))


def _histories(page: Page, ds: xr.Dataset, nodes):
    """The tensions at the chosen nodes; then what matters for the kind of system
    (:mod:`kanat.report.kinds`, as ``kanat run --plot``): its key tensions, the bodies'
    depth or surge, heave and pitch, and the vessel's speed."""
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots

    keep = thin(ds.sizes["time"], MAX_HISTORY_POINTS)
    t = ds["time"].values[keep]
    tension = go.Figure()
    for i in nodes:
        tension.add_trace(go.Scatter(x=t, y=ds["tension"].values[keep, i] / 1e3, name=plot_text(_label(ds, int(i))),
                                     mode="lines"))
    tension.update_layout(title={"text": "tension at the chosen nodes"}, xaxis_title="time [s]",
                          yaxis_title="tension [kN]", height=400)
    first = page.figure(tension, "plot-tension-history")
    choice = choose(ds)
    histories = body_histories(ds, choice.kind)
    case = embedded_case(ds)
    to_unit, unit = case.vessel.speed_as_given(1.0) if case is not None else (1.0, "m/s")
    titles = (f"{choice.tension_title} [kN]", *(f"body {q} [{u}]" for q, (u, _) in histories.items()),
              f"vessel speed over ground [{unit}]")
    motion = make_subplots(rows=1, cols=len(titles), subplot_titles=titles)
    for label, node in choice.ends.items():
        motion.add_trace(go.Scatter(x=t, y=ds["tension"].values[keep, node] / 1e3, name=plot_text(label)), 1, 1)
    for col, (quantity, (_, values)) in enumerate(histories.items(), start=2):
        for k, name in enumerate(ds["body"].values):
            motion.add_trace(go.Scatter(x=t, y=values[keep, k], name=plot_text(f"{name} {quantity}")), 1, col)
        if quantity == "depth":
            motion.update_yaxes(autorange="reversed", row=1, col=col)
    v = ds["vessel_position"].values
    speed = np.hypot(*np.gradient(v[:, :2], ds["time"].values, axis=0).T) if len(v) > 1 else np.zeros(len(v))
    motion.add_trace(go.Scatter(x=t, y=speed[keep] * to_unit, name="vessel speed"), 1, len(titles))
    motion.update_xaxes(title_text="time [s]")
    motion.update_layout(height=380, title={"text": f"what matters for a {choice.kind} system"})
    return macros("result.html.j2").plots([first, page.figure(motion, "plot-body-history")])


def _range_graphs(page: Page, ds: xr.Dataset, window):
    import plotly.graph_objects as go

    rg = range_graph(ds, "tension", window)
    fig = go.Figure()
    for k, name in enumerate(cable_names(ds)):
        sel = rg["cable"].values == name
        s, color, label = rg["s"].values[sel], f"hsl({(210 + 67 * k) % 360},60%,40%)", plot_text(name)
        fig.add_trace(go.Scatter(x=s, y=rg["max"].values[sel] / 1e3, name=f"{label} max", line={"color": color},
                                 legendgroup=label))
        fig.add_trace(go.Scatter(x=s, y=rg["min"].values[sel] / 1e3, name=f"{label} min", fill="tonexty",
                                 line={"color": color, "dash": "dot"}, legendgroup=label))
        fig.add_trace(go.Scatter(x=s, y=rg["mean"].values[sel] / 1e3, name=f"{label} mean",
                                 line={"color": color, "width": 1}, legendgroup=label))
    fig.update_layout(title={"text": "tension range along the cables"}, xaxis_title="s, arclength in its cable [m]",
                      yaxis_title="tension [kN]", height=420)
    return page.figure(fig, "plot-range-graph")


def _events(page: Page, ds: xr.Dataset, window):
    import plotly.graph_objects as go

    parts = macros("result.html.j2")
    if not has_events(ds):
        return parts.events(False)
    events = snap_events(ds, window)
    if not len(events):
        return parts.events(True)
    marker = {"size": 7, "color": events["segment"], "colorscale": "Viridis", "showscale": True,
              "colorbar": {"title": {"text": "segment"}}}
    fig = go.Figure(go.Scatter(x=events["time"], y=events["peak_tension"] / 1e3, mode="markers",
                               text=[plot_text(c) for c in events["cable"]], marker=marker))
    fig.update_layout(title={"text": f"{len(events)} snap events"}, xaxis_title="time [s]",
                      yaxis_title="peak tension [kN]", height=380)
    return parts.events(True, page.figure(fig, "plot-snap-events"),
                        frame_table(with_units(snap_summary(ds, window), EVENT_UNITS).set_index("cable"),
                                    text_columns=("cable",)),
                        frame_table(with_units(events, EVENT_UNITS), text_columns=("cable",), limit=EVENT_ROWS))


def _spectra(page: Page, ds: xr.Dataset, nodes, window):
    import plotly.graph_objects as go

    spectrum = tension_spectrum(ds, nodes, window)
    fig = go.Figure()
    for j, i in enumerate(spectrum["node"].values):
        fig.add_trace(go.Scatter(x=spectrum["frequency"].values[1:], y=spectrum["psd"].values[1:, j],
                                 name=plot_text(_label(ds, int(i)))))
    fig.update_layout(title={"text": "tension spectra (Welch)"}, xaxis_title="frequency [Hz]",
                      yaxis_title="PSD [N²/Hz]", yaxis_type="log", height=380)
    return macros("result.html.j2").spectra(page.figure(fig, "plot-spectra"), f"{spectrum.attrs['segment_s']:g}")


def _excursions(ds: xr.Dataset, window):
    ex = body_depth_excursions(ds, window)
    if not ex.sizes.get("body", 0):
        return macros("result.html.j2").excursions(None)
    frame = with_units(ex.to_dataframe(), {name: ex[name].attrs.get("units", "") for name in ex.data_vars})
    frame.index = frame.index.astype(str)
    return macros("result.html.j2").excursions(frame_table(frame, text_columns=("body",)))


def select_bodies(ds: xr.Dataset, bodies) -> xr.Dataset:
    """The result restricted to the named bodies (all when None)."""
    if bodies is None or not ds.sizes.get("body", 0):
        return ds
    names = [str(b) for b in ds["body"].values]
    unknown = [b for b in bodies if b not in names]
    if unknown:
        raise KanatError(f"no body {', '.join(map(repr, unknown))} in this result; "
                         f"bodies: {', '.join(names) or 'none'}")
    return ds.isel(body=[names.index(b) for b in bodies])


def dynamic_page(ds: xr.Dataset, source: str, nodes=None, window=None, bodies=None) -> Page:
    """The report page of a dynamic result (``bodies``: names for the body plots and tables)."""
    index = default_nodes(ds) if nodes is None else select_nodes(ds, nodes)
    window = None if window is None else tuple(window)
    chosen = select_bodies(ds, bodies)
    part = time_window(chosen, window)
    page = Page(f"kanat report: {ds.attrs.get('case_name', '') or Path(source).stem}",
                f"{ds.attrs.get('model', '')} model, scheme {ds.attrs.get('scheme', '')}, "
                f"{float(ds['time'].values[-1]):g} s simulated")
    page.section("summary", "Case summary and provenance", _provenance(ds, source))
    page.section("statistics", "Statistics", _statistics(ds, chosen, index, window))
    page.section("histories", "Time histories", _histories(page, part, index))
    page.section("range", "Range graphs", _range_graphs(page, ds, window))
    page.section("events", "Snap events", _events(page, ds, window))
    if part.sizes["time"] >= 16:
        page.section("spectra", "Tension spectra", _spectra(page, ds, index, window))
    page.section("excursions", "Body depth excursions", _excursions(chosen, window))
    page.section("animation", "3-D view", animation_section(page, ds))
    return page


def static_page(ds: xr.Dataset, source: str) -> Page:
    """The report page of a statics or pitch result (no time)."""
    import plotly.graph_objects as go

    page = Page(f"kanat report: {ds.attrs.get('case_name', '') or Path(source).stem}", f"{ds.attrs.get('model', '')}")
    page.section("summary", "Case summary and provenance", _provenance(ds, source))
    if "pitch" in ds and "mode" in ds.dims:
        fig = go.Figure([go.Scatter(x=ds["time"].values, y=ds["pitch"].values[k], name=plot_text(m))
                         for k, m in enumerate(ds["mode"].values)])
        fig.update_layout(title={"text": "steady pitch over one wave period"}, xaxis_title="time [s]",
                          yaxis_title="pitch [rad]")
        page.section("pitch", "Pitch", page.figure(fig, "plot-pitch"))
    elif "position" in ds and "tension" in ds:
        fig = go.Figure()
        for name in cable_names(ds):
            sel = ds["cable"].values == name
            hover = [f"T = {t / 1e3:.4g} kN" for t in ds["tension"].values[sel]]
            fig.add_trace(go.Scatter(x=ds["position"].values[sel, 0], y=ds["position"].values[sel, 2],
                                     name=plot_text(name), text=hover))
        fig.update_layout(title={"text": "shape (hover: tension)"}, xaxis_title="x [m]", yaxis_title="z [m]",
                          yaxis_scaleanchor="x")
        page.section("shape", "Shape and tension", page.figure(fig, "plot-shape"))
    elif "restoring_force" in ds and "offset" in ds.dims:
        page.section("offsets", "Offset curve", _offset_curve(page, ds))
    page.section("statistics", "Summary", summary_table(summary_statistics(ds)))
    return page


def _offset_curve(page: Page, ds: xr.Dataset):
    """Restoring force along the offset direction against offset, the system curve and each coupled
    body's own (:func:`kanat.report.offsets_plot.offset_curves`, as ``kanat offsets --plot``)."""
    import plotly.graph_objects as go

    from kanat.report.offsets_plot import SYSTEM, offset_curves

    direction = float(ds.attrs.get("direction_deg", 0.0))
    fig = go.Figure([go.Scatter(x=ds["offset"].values, y=force / 1e3, mode="lines+markers",
                                name="all moved together" if name == SYSTEM else f"{name} alone, the others held")
                     for name, (force, _) in offset_curves(ds).items()])
    fig.update_layout(title={"text": "restoring force of the lines"}, xaxis_title=f"offset along {direction:g} deg [m]",
                      yaxis_title=f"restoring force along {direction:g} deg [kN]")
    return page.figure(fig, "plot-offsets")


def result_report(ds: xr.Dataset, output, source: str = "", nodes=None, window=None, bodies=None) -> Path:
    """Write the HTML report of one result.

    Parameters
    ----------
    ds : xarray.Dataset
        A result (case-format.md).
    output : path-like
        The HTML file.
    source : str
        Where the result came from (shown in the provenance).
    nodes : sequence of int or str, optional
        Nodes for time histories, statistics and spectra (indices or ``CABLE@S``);
        default the first and last node of every cable.
    window : (float or None, float or None), optional
        Time window of the statistics, range graphs, spectra and events [s].
    bodies : sequence of str, optional
        Bodies for the depth histories and tables; default every body.
    """
    page = dynamic_page(ds, source, nodes, window, bodies) if "time" in ds.dims and "position" in ds \
        else static_page(ds, source)
    return page.write(output)
