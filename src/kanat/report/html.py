"""One self-contained HTML page: sections, tables and interactive plotly figures.

The page carries plotly.js itself (from the installed ``plotly`` package, no CDN), one
plot template, the figures as JSON (NumPy arrays as base64 typed arrays, plotly's own
encoding) and the page's scripts, so it opens offline in any browser. Every figure is a
``<div class="plot" id="...">`` drawn by ``Plotly.newPlot`` when the page loads.

All markup lives in Jinja2 templates (``kanat/report/templates``) rendered with
autoescaping: any text that comes from a user — file names, case and cable names, varied
keys and values, attributes, failure messages — is escaped where it lands, whatever it
contains. JSON embedded in ``<script>`` elements has ``<``, ``>``, ``&`` and ``'`` written
as ``\\u003c``-style escapes (:func:`script_json`), and text handed to plotly, which reads
a few HTML tags in labels, passes through :func:`plot_text`. Only kanat's own static
files (CSS, scripts) and plotly.js are inserted unescaped.
"""
from __future__ import annotations

import datetime as _dt
import functools
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from markupsafe import Markup

import kanat

SHOWN_UNITS = {"N": ("kN", 1e-3), "N/s": ("kN/s", 1e-3)}
"""Units shown in another unit, and the factor to it: forces in kN, as in the plots and on the
terminal (docs/concepts.md)."""


def shown(value, unit: str):
    """``(value, unit)`` as the report shows them: a force in N as kN (:data:`SHOWN_UNITS`)."""
    if unit not in SHOWN_UNITS:
        return value, unit
    to, factor = SHOWN_UNITS[unit]
    return value * factor, to


def header(name: str, unit: str) -> str:
    """A column header with its unit, ``max [kN]`` (the name alone without a unit, or for a count)."""
    return f"{name} [{unit}]" if unit and unit not in ("1", "-") else name


def with_units(frame, units: dict):
    """A DataFrame's columns named in ``units`` (``column -> unit`` as stored, ``N``) shown in the
    report's units with the unit in the header (:func:`shown`, :func:`header`)."""
    frame = frame.copy()
    names = {}
    for column, unit in units.items():
        if column in frame.columns:
            frame[column], to = shown(frame[column], unit)
            names[column] = header(column, to)
    return frame.rename(columns=names)


STATUS_CELLS = {"ok": "ok", "pass": "ok", "failed": "failed", "FAIL": "failed", "pass (not run)": "failed"}
"""Cells with these texts are coloured (class ``ok`` or ``failed``)."""


@functools.lru_cache(maxsize=1)
def environment():
    """The Jinja2 environment of the report templates (autoescaping on, undefined names an error)."""
    import jinja2

    return jinja2.Environment(loader=jinja2.PackageLoader("kanat.report", "templates"), autoescape=True,
                              undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)


def template(name: str):
    """A report template; its macros are attributes of ``template(name).module``."""
    return environment().get_template(name)


def macros(name: str):
    """The macros of template ``name`` as callables returning escaped markup."""
    return template(name).module


def static(name: str) -> Markup:
    """A static file of the templates directory (CSS, a script), inserted as it is."""
    source, _, _ = environment().loader.get_source(environment(), name)
    return Markup(source)


def script_json(value) -> Markup:
    """JSON for a ``<script type="application/json">`` element, safe whatever its strings hold.

    ``<``, ``>``, ``&`` and ``'`` are written as ``\\u003c``, ``\\u003e``, ``\\u0026``,
    ``\\u0027`` (valid JSON, read back unchanged by ``JSON.parse``), so no text inside can
    close the element or open a comment; NaN is refused (``allow_nan=False``).
    """
    text = json.dumps(value, separators=(",", ":"), allow_nan=False, default=_default)
    for char, code in (("<", "\\u003c"), (">", "\\u003e"), ("&", "\\u0026"), ("'", "\\u0027")):
        text = text.replace(char, code)
    return Markup(text)


def plot_text(value) -> str:
    """User text for a plotly label or trace name, shown as written.

    Plotly reads ``<b>``, ``<br>``, ``<a href>`` ... in labels as formatting; its own
    entity decoding turns ``&lt;`` back into ``<`` on screen, so escaping ``&``, ``<``
    and ``>`` shows the text exactly (and makes no tag of it).
    """
    return str(value).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _default(value):
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"cannot write {type(value).__name__} to JSON")


def figure_json(fig) -> dict:
    """A plotly figure as plain JSON data (arrays base64-encoded by plotly), without its template."""
    import plotly.io as pio

    data = json.loads(pio.to_json(fig, validate=False))
    data.get("layout", {}).pop("template", None)
    return data


def fmt(value, digits: int = 5) -> str:
    """A cell's text: numbers with ``digits`` significant figures, NaN as a dash, anything else ``str``.

    The text is escaped by the template that shows it, never here.
    """
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value)).lower()
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return "–" if not np.isfinite(value) else f"{float(value):.{digits}g}"
    return str(value)


@dataclass(frozen=True)
class Cell:
    """One table cell: its text (escaped when shown) and CSS classes."""

    text: str
    css: str = ""


@dataclass(frozen=True)
class Table:
    """A table for the ``table`` macro of ``macros.html.j2``.

    Attributes
    ----------
    header : list of Cell
    rows : list of list of Cell
    css : str
        Classes of the ``<table>``.
    shown, total : int
        Rows shown and rows in the source (a note is added when fewer are shown).
    """

    header: list
    rows: list
    css: str = ""
    shown: int = 0
    total: int = 0

    def __html__(self) -> str:
        """Rendered by the ``table`` macro (so a Table can be placed in a template as it is)."""
        return str(macros("macros.html.j2").table(self))


def table(header: list, rows, text_columns=(), css: str = "", total: int | None = None) -> Table:
    """A table; cells are formatted by :func:`fmt`, columns named in ``text_columns`` left-aligned."""
    head = [Cell(str(h), "text" if h in text_columns else "") for h in header]
    body = []
    for row in rows:
        cells = []
        for h, value in zip(header, row):
            klass = "text" if h in text_columns else ""
            if isinstance(value, str) and value in STATUS_CELLS:
                klass += " " + STATUS_CELLS[value]
            cells.append(Cell(fmt(value), klass.strip()))
        body.append(cells)
    return Table(head, body, css, len(body), len(body) if total is None else total)


def frame_table(frame, text_columns=(), limit: int | None = None) -> Table:
    """A pandas DataFrame (its index a column) as a table, at most ``limit`` rows."""
    frame = frame.reset_index()
    shown = frame if limit is None else frame.head(limit)
    return table([str(c) for c in shown.columns], shown.itertuples(index=False, name=None), text_columns,
                 total=len(frame))


@dataclass(frozen=True)
class Plot:
    """A figure's place in the page: ``<div class="plot" id=...>`` (``plot`` macro)."""

    id: str
    height: int | None = None
    attributes: tuple = ()

    def __html__(self) -> str:
        return str(macros("macros.html.j2").plot(self))


@dataclass
class Section:
    id: str
    title: str
    body: Markup


@dataclass
class Page:
    """An HTML report under construction: add sections and figures, then :meth:`render`.

    Attributes
    ----------
    title, subtitle : str
        Shown in the header (escaped).
    sections : list of Section
    figures : dict
        Plot id -> figure JSON (:func:`figure_json`).
    scripts : list of str
        Names of static scripts (``templates/*.js``) run after the figures are drawn.
    data : dict
        Element id -> value, embedded as JSON for the scripts.
    """

    title: str
    subtitle: str = ""
    sections: list = field(default_factory=list)
    figures: dict = field(default_factory=dict)
    scripts: list = field(default_factory=list)
    data: dict = field(default_factory=dict)

    def figure(self, fig, plot_id: str, height: int | None = None, attributes: tuple = ()) -> Plot:
        """Register a plotly figure; return its place in the page."""
        self.figures[plot_id] = figure_json(fig)
        return Plot(plot_id, height, attributes)

    def section(self, section_id: str, title: str, body) -> None:
        """Add a section; ``body`` is markup from a template (plain text is escaped)."""
        self.sections.append(Section(section_id, title, Markup("").join([body]) if body is not None else Markup("")))

    def script(self, name: str) -> None:
        """Run the static script ``templates/NAME`` after the figures are drawn (once)."""
        if name not in self.scripts:
            self.scripts.append(name)

    def render(self) -> str:
        """The complete page (plotly.js embedded)."""
        import plotly.io as pio
        from plotly.offline import get_plotlyjs

        return template("page.html.j2").render(
            title=self.title, subtitle=self.subtitle, version=kanat.__version__,
            stamp=_dt.datetime.now().strftime("%Y-%m-%d %H:%M"), style=static("style.css"),
            plotly_js=Markup(get_plotlyjs()), sections=self.sections,
            template_json=script_json(pio.templates["plotly_white"].to_plotly_json()),
            figures_json=script_json(self.figures), data=[(k, script_json(v)) for k, v in self.data.items()],
            boot=static("boot.js"), scripts=[static(name) for name in self.scripts])

    def write(self, path) -> Path:
        """Write the page atomically (temporary file in the same directory, then renamed); return its path."""
        from kanat.io.outputs import write_text_atomic

        return write_text_atomic(path, self.render())
