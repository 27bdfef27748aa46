"""The HTML report of a parameter study (``kanat report STUDY_DIR -o report.html``).

Sections: the study (base case, varied keys and values, failed cases with their messages);
the summary table; any statistic against any varied parameter, one line per value of a
third (chosen in the page); a map of a statistic over two parameters; and the tension at
the first node of every case against time.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.analysis import first_nodes, statistic_units
from kanat.io.results import read_result
from kanat.report.html import Page, frame_table, table_html
from kanat.report.html_animation import thin

MAX_OVERLAY_CASES = 60
OVERLAY_POINTS = 1000

EXPLORER = """
(function(){
  var S = JSON.parse(document.getElementById('kanat-study').textContent), T = window.KANAT.template;
  function sel(id){return document.getElementById(id);}
  function fill(id, names, extra){var e = sel(id); if (!e) return;
    (extra || []).concat(names).forEach(function(n){var o = document.createElement('option'); o.value = n;
      o.textContent = n + (S.units[n] ? ' [' + S.units[n] + ']' : ''); e.appendChild(o);});}
  fill('study-x', S.keys); fill('study-y', S.stats); fill('study-group', S.keys, ['(none)']);
  fill('map-z', S.stats); fill('map-x', S.keys); fill('map-y', S.keys);
  if (S.keys.length > 1){ sel('study-group').value = S.keys[1]; if (sel('map-y')) sel('map-y').value = S.keys[1]; }
  if (S.stats.indexOf(S.preferred) >= 0){
    sel('study-y').value = S.preferred; if (sel('map-z')) sel('map-z').value = S.preferred;}
  function col(n){return S.columns[n];}
  function ok(i){return S.columns.status[i] === 'ok';}
  function uniq(a){var seen = {}, out = []; a.forEach(function(v){var k = String(v);
    if (!(k in seen)){seen[k] = 1; out.push(v);}});
    return out.sort(function(p, q){return p < q ? -1 : p > q ? 1 : 0;});}
  function axis(n){return {title: {text: n + (S.units[n] ? ' [' + S.units[n] + ']' : '')}};}
  function drawLines(){
    var x = sel('study-x').value, y = sel('study-y').value, g = sel('study-group').value, n = col('name').length;
    var groups = g === '(none)' ? [null] : uniq(col(g)), traces = [];
    groups.forEach(function(v){
      var idx = []; for (var i = 0; i < n; i++) if (ok(i) && (v === null || col(g)[i] === v)) idx.push(i);
      idx.sort(function(a, b){return col(x)[a] < col(x)[b] ? -1 : col(x)[a] > col(x)[b] ? 1 : 0;});
      traces.push({x: idx.map(function(i){return col(x)[i];}), y: idx.map(function(i){return col(y)[i];}),
        text: idx.map(function(i){return col('name')[i];}), mode: 'lines+markers', type: 'scatter',
        name: v === null ? y : g + ' = ' + v});
    });
    Plotly.react('plot-study', traces, {template: T, xaxis: axis(x), yaxis: axis(y), height: 440,
      title: {text: y + ' against ' + x}});
  }
  function drawMap(){
    if (!sel('map-z')) return;
    var z = sel('map-z').value, x = sel('map-x').value, y = sel('map-y').value, n = col('name').length;
    var xs = uniq(col(x)), ys = uniq(col(y)), sum = ys.map(function(){return xs.map(function(){return 0;});});
    var cnt = ys.map(function(){return xs.map(function(){return 0;});});
    for (var i = 0; i < n; i++) if (ok(i) && col(z)[i] !== null){
      var a = ys.indexOf(col(y)[i]), b = xs.indexOf(col(x)[i]); sum[a][b] += col(z)[i]; cnt[a][b] += 1;}
    var grid = sum.map(function(r, a){return r.map(function(v, b){return cnt[a][b] ? v / cnt[a][b] : null;});});
    Plotly.react('plot-map', [{type: 'heatmap', x: xs.map(String), y: ys.map(String), z: grid, colorscale: 'Viridis',
      colorbar: {title: {text: z}}, texttemplate: '%{z:.4~g}'}],
      {template: T, xaxis: axis(x), yaxis: axis(y), height: 440, title: {text: z + ' (mean over other parameters)'}});
  }
  ['study-x', 'study-y', 'study-group'].forEach(function(id){sel(id).addEventListener('change', drawLines);});
  ['map-z', 'map-x', 'map-y'].forEach(function(id){if (sel(id)) sel(id).addEventListener('change', drawMap);});
  drawLines(); drawMap();
  window.KANAT.study = {drawLines: drawLines, drawMap: drawMap};
})();
"""


def _json_column(values: np.ndarray) -> list:
    if values.dtype.kind in "fiu":
        return [None if not np.isfinite(v) else float(v) for v in values.astype(float)]
    return [str(v) for v in values]


def study_data(summary: xr.Dataset, keys: list, stats: list) -> dict:
    """The summary as columns for the page's explorer script."""
    numeric = [s for s in stats if summary[s].dtype.kind in "fiu" and np.isfinite(summary[s].values).any()]
    columns = {name: _json_column(summary[name].values) for name in ["name", "status", *keys, *numeric]}
    preferred = next((s for s in ("top_tension_max", "tension_max") if s in numeric), numeric[0] if numeric else "")
    units = {s: statistic_units(s) for s in numeric}
    return {"keys": keys, "stats": numeric, "columns": columns, "units": units, "preferred": preferred}


def _definition(summary: xr.Dataset, study_dir: Path) -> str:
    manifest = json.loads((study_dir / "study.json").read_text()) if (study_dir / "study.json").exists() else {}
    vary = manifest.get("vary", {})
    rows = [(k, len(v), ", ".join(f"{x:.6g}" if isinstance(x, float) else str(x) for x in v)) for k, v in vary.items()]
    status = summary["status"].values
    total = len(manifest.get("cases", [])) or summary.sizes["case"]
    out = (f"<p>base case: <code>{manifest.get('base_case', summary.attrs.get('base_case', ''))}</code>; "
           f"{total} cases: <span class='ok'>{int(np.sum(status == 'ok'))} ok</span>, "
           f"<span class='failed'>{int(np.sum(status != 'ok'))} failed</span>, "
           f"{total - summary.sizes['case']} not finished</p>")
    out += table_html(["key", "values", "list"], rows, text_columns=("key", "list"))
    failed = [(str(n), str(m)) for n, s, m in zip(summary["name"].values, status, summary["message"].values)
              if s != "ok"]
    if failed:
        out += "<h3>failed cases</h3>" + table_html(["case", "message"], failed, text_columns=("case", "message"))
    return out


def _controls(keys: list) -> str:
    lines = ("<div class='controls'><label>x <select id='study-x'></select></label>"
             "<label>statistic <select id='study-y'></select></label>"
             "<label>one line per <select id='study-group'></select></label></div>"
             "<div class='plot' id='plot-study'></div>")
    if len(keys) < 2:
        return lines
    return lines + ("<h3>over two parameters</h3><div class='controls'><label>statistic <select id='map-z'></select>"
                    "</label><label>x <select id='map-x'></select></label><label>y <select id='map-y'></select>"
                    "</label></div><div class='plot' id='plot-map'></div>")


def _overlay(page: Page, summary: xr.Dataset, study_dir: Path) -> str | None:
    import plotly.graph_objects as go

    fig, count = go.Figure(), 0
    for name, status in zip(summary["name"].values, summary["status"].values):
        path = study_dir / "results" / f"{name}.nc"
        if status != "ok" or not path.exists() or count >= MAX_OVERLAY_CASES:
            continue
        ds = read_result(path)
        if "time" not in ds.dims or "tension" not in ds:
            return None
        keep = thin(ds.sizes["time"], OVERLAY_POINTS)
        fig.add_trace(go.Scatter(x=ds["time"].values[keep], y=ds["tension"].values[keep, first_nodes(ds)[0]] / 1e3,
                                 name=str(name), mode="lines", line={"width": 1.2}))
        count += 1
    if not count:
        return None
    fig.update_layout(title={"text": "tension at the first node of the first cable, every case"},
                      xaxis_title="time [s]", yaxis_title="tension [kN]", height=460)
    return page.figure(fig, "plot-study-histories")


def study_report(study_dir, output) -> Path:
    """Write the HTML report of a study directory (:mod:`kanat.sweep.store`).

    Parameters
    ----------
    study_dir : path-like
        A directory written by :func:`kanat.sweep.sweep`.
    output : path-like
        The HTML file.
    """
    from kanat.sweep.store import read_summary

    study_dir = Path(study_dir)
    summary, keys, stats = read_summary(study_dir)
    page = Page(f"kanat study: {study_dir.resolve().name}", f"{summary.sizes['case']} cases, varying {', '.join(keys)}")
    page.data["kanat-study"] = study_data(summary, keys, stats)
    page.section("study", "Study", _definition(summary, study_dir))
    page.section("explorer", "Statistics against the varied parameters", _controls(keys))
    frame = summary.to_dataframe().drop(columns=["message"])
    page.section("table", "Summary table", "<div class='scroll'>" + frame_table(
        frame, text_columns=("name", "status")) + "</div>")
    overlay = _overlay(page, summary, study_dir)
    if overlay:
        page.section("histories", "Time histories of every case", overlay)
    page.script(EXPLORER)
    return page.write(output)
