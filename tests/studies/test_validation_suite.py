"""The validation suite (theory/validation-cases.md, fast cases) and its report.

Oracles: the analytic values written out here independently of kanat.validation (Naumov & Agievich's
published numbers, sqrt(EA/m), sqrt(EA m) dV, sqrt(T/(m+m_a)), the pitch mean offset
M0/(2 I_y omega_0^2)); a deliberately wrong check must fail and be shown as failing.
"""
import math
import re

import pytest
from typer.testing import CliRunner

from kanat.errors import KanatError
from kanat.report.html_validation import validation_report as write_validation_report
from kanat.validation import REGISTRY, Tolerance, check, run_suite

EXPECTED = {                                   # independent oracles (theory/validation-cases.md)
    "sphere-alpha0": (46.9, 0.1),
    "sphere-tau0": (0.6066, 5e-4),
    "longitudinal-speed": (math.sqrt(1e6 / 1.0), 0.02 * 1000.0),
    "longitudinal-jump": (math.sqrt(1e6 * 1.0) * 0.1, 2.0),
    "transverse-speed": (math.sqrt(1000.0 / 1.6), 0.02 * 25.0),
    "pitch-rectangular-mean": (1e6 / (2 * 2e7 * 0.876**2), 1e-3 * 0.0326),
    "ga-order": (2.0, 0.15),
    "backward-euler-order": (1.0, 0.15),
}


@pytest.fixture(scope="module")
def results():
    return run_suite()


@pytest.mark.slow
def test_every_fast_check_passes_against_its_oracle(results):
    assert len(results) == len(REGISTRY) >= 15
    failed = [r.measured_text for r in results if not r.passed]
    assert not failed, failed
    by_id = {r.check_id: r for r in results}
    for check_id, (value, tolerance) in EXPECTED.items():
        assert by_id[check_id].expected == pytest.approx(value, rel=1e-9), check_id
        assert abs(by_id[check_id].measured - value) <= tolerance, check_id
    assert {r.spec for r in results} >= {"7.1", "7.2", "7.3", "7.4", "7.5", "7.9"}


@pytest.mark.slow
def test_report_renders_each_check(results, tmp_path):
    try:
        check("deliberately-wrong", "7.5", "a check that must fail", "1 = 2", Tolerance(abs=0.1))(lambda: (1.0, 2.0))
        check("raises", "7.5", "a check that cannot run", "none", Tolerance(abs=0.1))(lambda: 1 / 0)
        extra = run_suite(["deliberately-wrong", "raises"])
    finally:
        REGISTRY.pop("deliberately-wrong", None)
        REGISTRY.pop("raises", None)
    assert [r.passed for r in extra] == [False, False] and "ZeroDivisionError" in extra[1].error
    html = write_validation_report(results + extra, tmp_path / "v.html").read_text()
    for r in results:
        row = re.search(rf"<td class=\"text\">{re.escape(r.check_id)}</td>.*?</tr>", html, re.S).group(0)
        assert ">pass<" in row and f"{r.measured:.5g}" in row
    assert html.count(">FAIL<") == 2 and "ZeroDivisionError" in html
    assert f"{len(results)} of {len(results) + 2} checks pass" in html
    assert "Validation cases not in the fast suite" in html and "10 the lumped model and Bezverkhyi 2006" in html
    assert "SPEC §" not in html and "§7" not in html                # the documentation's groups, no outside references


def test_unknown_check_is_explained():
    with pytest.raises(KanatError, match="unknown check.*valid: "):
        run_suite(["no-such-check"])


def test_validate_suite_verb(tmp_path):
    from kanat.cli import app

    out = CliRunner().invoke(app, ["validate-suite", "-o", str(tmp_path / "v.html"), "--only", "sphere-alpha0",
                                     "--only", "longitudinal-jump"])
    assert out.exit_code == 0, out.output
    assert "2/2 checks pass" in out.output and (tmp_path / "v.html").exists()
