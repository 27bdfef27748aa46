"""The validation report page (``kanat validate-suite -o validation.html``).

One row per check: its group (the numbering of the documentation's validation page), what
is checked, the oracle and its source, the tolerance, the measured and expected values,
pass/fail and the time taken; a plot of each check's error as a fraction of its tolerance;
the validation cases left out of the fast suite.
"""
from __future__ import annotations

import numpy as np

from kanat.report.html import Page, macros, table


GROUPS = {1: "Naumov & Agievich's sphere", 2: "the time schemes", 3: "wave speeds and natural frequencies",
          4: "the steady tow", 5: "the elastic catenary", 6: "model against model",
          7: "Kaliukh & Vusatiuk's factorized schemes", 8: "Zhang, Zhang & Liu's turn", 9: "Gaisha's pitch",
          10: "the lumped model and Bezverkhyi 2006"}
"""The groups of ``docs/validation.md`` by number; a check's case ``7.N`` is in group ``N``."""


def _group(case: str) -> str:
    """The group a case number belongs to, as the documentation names it (``7.3`` -> ``3 wave speeds ...``)."""
    number = case.rsplit(".", 1)[-1]
    name = GROUPS.get(int(number)) if number.isdigit() else None
    return f"{number} {name}" if name else case


def _spec_key(result) -> tuple:
    return tuple(int(p) for p in result.spec.split(".") if p.isdigit())


def _usage(result) -> float:
    """|measured - expected| as a fraction of the allowed deviation (<= 1 passes)."""
    allowed = result.tolerance.abs + result.tolerance.rel * abs(result.expected)
    if result.error or not np.isfinite(result.measured):
        return float("nan")
    deviation = abs(result.measured - result.expected)
    return deviation / allowed if allowed > 0 else (0.0 if deviation == 0 else float("inf"))


def validation_report(results, output):
    """Write the validation page for ``results`` (:class:`kanat.validation.CheckResult` list)."""
    import plotly.graph_objects as go

    from kanat.validation.core import NOT_IN_SUITE

    results = sorted(results, key=_spec_key)
    passed = sum(r.passed for r in results)
    page = Page("kanat validation report", f"{passed} of {len(results)} checks pass (fast suite)")
    rows = [(_group(r.spec), r.check_id, r.title, r.oracle, str(r.tolerance), r.units,
             r.measured if not r.error else r.error.splitlines()[0], r.expected, "pass" if r.passed else "FAIL",
             r.seconds) for r in results]
    header = ["group", "check", "what", "oracle (source)", "tolerance", "units", "measured", "expected", "result",
              "time [s]"]
    page.section("checks", "Checks", table(header, rows, text_columns=("group", "check", "what", "oracle (source)",
                                                                      "tolerance", "units")))
    usage = [_usage(r) for r in results]
    fig = go.Figure(go.Bar(x=[r.check_id for r in results], y=[u if np.isfinite(u) else None for u in usage],
                           marker={"color": ["#137333" if r.passed else "#b3261e" for r in results]}))
    fig.add_hline(y=1.0, line_dash="dash", annotation_text="tolerance")
    fig.update_layout(title={"text": "deviation from the oracle as a fraction of the tolerance"},
                      yaxis_type="log", yaxis_title="|measured - expected| / allowed", height=420)
    parts = macros("validation.html.j2")
    page.section("margins", "Margins", parts.margins(page.figure(fig, "plot-validation-margins")))
    failures = [(r.check_id, r.error) for r in results if r.error]
    if failures:
        page.section("errors", "Checks that could not run", parts.errors(failures))
    page.section("not-run", "Validation cases not in the fast suite",
                 table(["group", "case", "checked by"], [(_group(a), b, c) for a, b, c in NOT_IN_SUITE],
                       text_columns=("group", "case", "checked by")))
    return page.write(output)
