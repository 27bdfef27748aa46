"""The HTML report of a parameter study (``kanat report STUDY_DIR -o report.html``).

Sections: the study (base case, varied keys and values, failed cases with their messages);
the summary table; any statistic against any varied parameter, one line per value of a
third (chosen in the page); a map of a statistic over two parameters; and the tension at
the first node of every case against time.

Result files are found through the study's own case table (``study.json``: index ->
case name, checked by :meth:`kanat.sweep.store.StudyStore.result_file`), never through a
name or value read from the summary, so a varied ``name`` cannot point the report at a file.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.analysis import first_nodes, statistic_units
from kanat.io.results import read_result
from kanat.report.html import Page, frame_table, macros, plot_text, shown, table, with_units
from kanat.report.html_animation import thin

MAX_OVERLAY_CASES = 60
OVERLAY_POINTS = 1000

def _json_column(values: np.ndarray) -> list:
    if values.dtype.kind in "fiu":
        return [None if not np.isfinite(v) else float(v) for v in values.astype(float)]
    return [str(v) for v in values]


def study_data(summary: xr.Dataset, keys: list, stats: list) -> dict:
    """The summary as columns for the page's explorer script (forces in kN)."""
    keys = [k for k in keys if k in summary]
    numeric = [s for s in stats if s in summary and summary[s].dtype.kind in "fiu"
               and np.isfinite(summary[s].values).any()]
    columns = {name: _json_column(summary[name].values) for name in ["name", "status", *keys]}
    units = {}
    for name in numeric:
        values, units[name] = shown(summary[name].values, statistic_units(name))
        columns[name] = _json_column(np.asarray(values))
    preferred = next((s for s in ("top_tension_max", "tension_max") if s in numeric), numeric[0] if numeric else "")
    return {"keys": keys, "stats": numeric, "columns": columns, "units": units, "preferred": preferred}


def _manifest(study_dir: Path) -> dict:
    path = study_dir / "study.json"
    try:
        manifest = json.loads(path.read_text(encoding="utf-8")) if path.exists() else {}
    except (OSError, ValueError):
        manifest = {}
    return manifest if isinstance(manifest, dict) else {}


def _definition(summary: xr.Dataset, manifest: dict):
    vary = manifest.get("vary", {}) if isinstance(manifest.get("vary"), dict) else {}
    rows = [(k, len(v), ", ".join(f"{x:.6g}" if isinstance(x, float) else str(x) for x in v)) for k, v in vary.items()]
    status = summary["status"].values
    total = len(manifest.get("cases", [])) or summary.sizes["case"]
    failed = [(str(n), str(m)) for n, s, m in zip(summary["name"].values, status, summary["message"].values)
              if s != "ok"]
    return macros("study.html.j2").definition(
        manifest.get("base_case", summary.attrs.get("base_case", "")), total, int(np.sum(status == "ok")),
        int(np.sum(status != "ok")), total - summary.sizes["case"],
        table(["key", "values", "list"], rows, text_columns=("key", "list")),
        table(["case", "message"], failed, text_columns=("case", "message")) if failed else None)


def _overlay(page: Page, summary: xr.Dataset, study_dir: Path):
    """Tension at the first node against time for the ok cases, read through the study's case table."""
    import plotly.graph_objects as go

    from kanat.sweep.store import StudyStore

    store = StudyStore(study_dir)
    names = store.case_table()
    fig, count = go.Figure(), 0
    for index, status in zip(summary["case"].values, summary["status"].values):
        if status != "ok" or int(index) not in names or count >= MAX_OVERLAY_CASES:
            continue
        name = names[int(index)]
        path = store.result_file(name)
        if not path.is_file():
            continue
        ds = read_result(path)
        if "time" not in ds.dims or "tension" not in ds:
            return None
        keep = thin(ds.sizes["time"], OVERLAY_POINTS)
        fig.add_trace(go.Scatter(x=ds["time"].values[keep], y=ds["tension"].values[keep, first_nodes(ds)[0]] / 1e3,
                                 name=plot_text(name), mode="lines", line={"width": 1.2}))
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
    parts = macros("study.html.j2")
    page = Page(f"kanat study: {study_dir.resolve().name}", f"{summary.sizes['case']} cases, varying {', '.join(keys)}")
    page.data["kanat-study"] = study_data(summary, keys, stats)
    page.section("study", "Study", _definition(summary, _manifest(study_dir)))
    page.section("explorer", "Statistics against the varied parameters", parts.explorer(len(keys) >= 2))
    frame = with_units(summary.to_dataframe().drop(columns=["message"]), {s: statistic_units(s) for s in stats})
    page.section("table", "Summary table", parts.scroll(frame_table(frame, text_columns=("name", "status"))))
    overlay = _overlay(page, summary, study_dir)
    if overlay:
        page.section("histories", "Time histories of every case", overlay)
    page.script("explorer.js")
    return page.write(output)
