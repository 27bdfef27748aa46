"""One self-contained HTML page: sections, tables and interactive plotly figures.

The page carries plotly.js itself (from the installed ``plotly`` package, no CDN), one
plot template, the figures as JSON (NumPy arrays as base64 typed arrays, plotly's own
encoding) and any extra script, so it opens offline in any browser. Every figure is a
``<div class="plot" id="...">`` drawn by ``Plotly.newPlot`` when the page loads.
"""
from __future__ import annotations

import datetime as _dt
import html
import json
import os
from pathlib import Path

import numpy as np

import kanat

STYLE = """
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;margin:0;color:#1d2733;background:#f6f7f9}
header{background:#0b3954;color:#fff;padding:18px 32px}header h1{margin:0;font-size:1.5em}
header p{margin:4px 0 0;opacity:.85}nav{padding:6px 32px;background:#e6ecf1;font-size:.9em}
nav a{margin-right:14px;color:#0b3954;text-decoration:none}main{padding:0 32px 40px}
section{background:#fff;margin:18px 0;padding:12px 20px;border-radius:6px;box-shadow:0 1px 3px rgba(0,0,0,.08)}
h2{font-size:1.15em;color:#0b3954;margin:6px 0 10px}.plot{width:100%;min-height:380px}
table{border-collapse:collapse;font-size:.86em;margin:6px 0}th,td{border:1px solid #d5dde5;padding:3px 8px;
text-align:right}th{background:#eef2f6}td.text,th.text{text-align:left}.ok{color:#137333;font-weight:600}
.failed{color:#b3261e;font-weight:600}.note{color:#556;font-size:.88em}.scroll{max-height:420px;overflow:auto}
.controls{margin:6px 0;font-size:.9em}.controls label{margin-right:14px}button{font-size:.9em}
"""

BOOT = """
(function(){
  var figures = JSON.parse(document.getElementById('kanat-figures').textContent);
  var template = JSON.parse(document.getElementById('kanat-template').textContent);
  window.KANAT = {figures: figures, template: template, drawn: []};
  Object.keys(figures).forEach(function(id){
    var fig = figures[id]; fig.layout = fig.layout || {}; fig.layout.template = template;
    Plotly.newPlot(id, fig.data, fig.layout, {responsive: true, displaylogo: false});
    window.KANAT.drawn.push(id);
  });
})();
"""


def _template_json() -> str:
    import plotly.io as pio

    return json.dumps(pio.templates["plotly_white"].to_plotly_json())


def figure_json(fig) -> dict:
    """A plotly figure as plain JSON data (arrays base64-encoded by plotly), without its template."""
    import plotly.io as pio

    data = json.loads(pio.to_json(fig, validate=False))
    data.get("layout", {}).pop("template", None)
    return data


def script_json(value) -> str:
    """JSON safe inside ``<script>`` (no ``</`` sequence)."""
    return json.dumps(value, separators=(",", ":"), allow_nan=False, default=_default).replace("</", "<\\/")


def _default(value):
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"cannot write {type(value).__name__} to JSON")


def fmt(value, digits: int = 5) -> str:
    """A cell: numbers with ``digits`` significant figures, NaN as a dash, text escaped."""
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value)).lower()
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return "–" if not np.isfinite(value) else f"{float(value):.{digits}g}"
    return html.escape(str(value))


def table_html(header: list, rows: list, text_columns=(), row_classes=None, cls: str = "") -> str:
    """An HTML table; cells are formatted by :func:`fmt`, columns named in ``text_columns`` left-aligned."""
    head = "".join(f'<th class="{"text" if h in text_columns else ""}">{html.escape(str(h))}</th>' for h in header)
    body = []
    for k, row in enumerate(rows):
        cells = []
        for h, value in zip(header, row):
            klass = "text" if h in text_columns else ""
            if isinstance(value, str) and value in ("ok", "failed", "pass", "FAIL", "pass (not run)"):
                klass += " ok" if value in ("ok", "pass") else " failed"
            cells.append(f'<td class="{klass.strip()}">{fmt(value)}</td>')
        rc = f' class="{row_classes[k]}"' if row_classes else ""
        body.append(f"<tr{rc}>{''.join(cells)}</tr>")
    return f'<table class="{cls}"><thead><tr>{head}</tr></thead><tbody>{"".join(body)}</tbody></table>'


def frame_table(frame, text_columns=(), limit: int | None = None) -> str:
    """A pandas DataFrame (its index a column) as an HTML table, at most ``limit`` rows."""
    frame = frame.reset_index()
    shown = frame if limit is None else frame.head(limit)
    note = (f'<p class="note">first {limit} of {len(frame)} rows</p>' if limit is not None and len(frame) > limit
            else "")
    return table_html(list(shown.columns), shown.itertuples(index=False, name=None), text_columns) + note


class Page:
    """An HTML report under construction: add sections and figures, then :meth:`render`.

    Parameters
    ----------
    title : str
    subtitle : str
    """

    def __init__(self, title: str, subtitle: str = ""):
        self.title, self.subtitle = title, subtitle
        self.sections: list[tuple[str, str, str]] = []
        self.figures: dict[str, dict] = {}
        self.scripts: list[str] = []
        self.data: dict[str, object] = {}

    def figure(self, fig, plot_id: str, height: int | None = None) -> str:
        """Register a plotly figure; return its ``<div>``."""
        self.figures[plot_id] = figure_json(fig)
        style = f' style="height:{height}px"' if height else ""
        return f'<div class="plot" id="{plot_id}"{style}></div>'

    def section(self, section_id: str, title: str, body: str) -> None:
        self.sections.append((section_id, title, body))

    def script(self, js: str) -> None:
        self.scripts.append(js)

    def render(self) -> str:
        """The complete page (plotly.js embedded)."""
        from plotly.offline import get_plotlyjs

        nav = "".join(f'<a href="#{sid}">{html.escape(title)}</a>' for sid, title, _ in self.sections)
        body = "".join(f'<section id="{sid}"><h2>{html.escape(title)}</h2>{content}</section>'
                       for sid, title, content in self.sections)
        data = "".join(f'<script type="application/json" id="{html.escape(k)}">{script_json(v)}</script>'
                       for k, v in self.data.items())
        stamp = _dt.datetime.now().strftime("%Y-%m-%d %H:%M")
        template = _template_json().replace("</", "<\\/")
        scripts = "".join(f"<script>{s}</script>" for s in self.scripts)
        return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
                f'<meta name="viewport" content="width=device-width, initial-scale=1">'
                f"<title>{html.escape(self.title)}</title><style>{STYLE}</style>"
                f"<script>{get_plotlyjs()}</script></head><body>"
                f"<header><h1>{html.escape(self.title)}</h1><p>{html.escape(self.subtitle)}</p>"
                f'<p class="note" style="color:#cfe">kanat {kanat.__version__}, {stamp}</p></header>'
                f"<nav>{nav}</nav><main>{body}</main>"
                f'<script type="application/json" id="kanat-template">{template}'
                f'</script><script type="application/json" id="kanat-figures">{script_json(self.figures)}</script>'
                f"{data}<script>{BOOT}</script>{scripts}"
                f"</body></html>")

    def write(self, path) -> Path:
        """Write the page atomically; return its path."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(path.name + ".part")
        tmp.write_text(self.render(), encoding="utf-8")
        os.replace(tmp, path)
        return path
