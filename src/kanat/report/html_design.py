"""The page of a design check (``DIR/report.html`` of ``kanat design``): the verdict, the
conditions that could not be checked, the utilisation table and the fatigue life along every
line (a range graph of the damage per year against the arclength)."""
from __future__ import annotations

from pathlib import Path

from markupsafe import Markup, escape

from .html import Page, table


def _paragraph(text: str) -> Markup:
    return Markup("<p>{}</p>").format(escape(text))


def _verdict(result) -> Markup:
    design = result.case.design
    failed = int((~result.utilisation["ok"].astype(bool)).sum())
    lines = [f"Standard {design.standard}, {design.analysis} analysis; most probable maximum "
             f"({design.extremes}) over {design.storm_duration:g} s from {design.seeds} seed(s) per "
             f"sea state; {len(design.sea_state_rows)} sea state(s).",
             f"{len(result.utilisation)} line checks, {failed} failing." if failed else
             f"All {len(result.utilisation)} line checks pass."]
    if design.fatigue is not None and len(result.fatigue):
        shortest = result.fatigue.loc[result.fatigue["life_years"].idxmin()]
        verdict = "passes" if shortest["life_years"] >= design.fatigue.design_life else "fails"
        lines.append(f"Shortest fatigue life {shortest['life_years']:.4g} years ({shortest['line']} at "
                     f"s = {shortest['s']:g} m, {design.fatigue.curve}): {verdict} the design life of "
                     f"{design.fatigue.design_life:g} years.")
    return Markup("").join(_paragraph(text) for text in lines)


def _utilisation(frame) -> Markup:
    shown = frame.copy()
    shown["mpm_tension"] = shown["mpm_tension"] * 1e-3
    shown["mbl"] = shown["mbl"] * 1e-3
    shown["ok"] = shown["ok"].map({True: "ok", False: "failed"})
    shown = shown.rename(columns={"mpm_tension": "mpm_tension [kN]", "mbl": "mbl [kN]"})
    return Markup("").join([table(list(shown.columns), shown.itertuples(index=False, name=None),
                                  text_columns=("condition", "sea_state", "line", "ok"))])


def _fatigue(page: Page, frame) -> Markup:
    import plotly.graph_objects as go

    fig = go.Figure()
    for line, rows in frame.groupby("line", sort=False):
        fig.add_trace(go.Scatter(x=rows["s"], y=rows["damage_per_year"], mode="lines+markers", name=str(line)))
    fig.update_layout(xaxis_title="s [m]", yaxis_title="damage per year [-]", yaxis_type="log")
    place = page.figure(fig, "fatigue-range", height=380)
    return Markup("").join([place, table(list(frame.columns), frame.itertuples(index=False, name=None),
                                         text_columns=("line",))])


def _excursions(frame) -> Markup:
    shown = frame.copy()
    shown["unit"] = shown["quantity"].map({"offset": "m", "uplift": "kN"})
    shown.loc[shown["quantity"] == "uplift", "largest"] *= 1e-3
    note = _paragraph("The largest value in the runs (not an extreme-value estimate): a body's horizontal "
                      "offset from its intact statics position, an anchor's upward line force (negative: "
                      "pressed down throughout).")
    return Markup("").join([note, table(list(shown.columns), shown.itertuples(index=False, name=None),
                                        text_columns=("condition", "sea_state", "item", "quantity", "unit"))])


def design_page(result, path) -> Path:
    """Write the page of a :class:`kanat.design_checks.DesignResult` to ``path``."""
    page = Page(f"Design check: {result.case.name}", "utilisation and fatigue of the mooring lines")
    page.section("verdict", "Verdict", _verdict(result))
    if result.failures:
        page.section("failures", "Not checked",
                     Markup("").join(_paragraph(f"{name}: {why}") for name, why in result.failures.items()))
    page.section("utilisation", "Utilisation", _utilisation(result.utilisation))
    if result.excursions is not None and len(result.excursions):
        page.section("excursions", "Offsets and anchor uplift", _excursions(result.excursions))
    if len(result.fatigue):
        page.section("fatigue", "Fatigue", _fatigue(page, result.fatigue))
    return page.write(path)
