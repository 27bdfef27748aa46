"""What the command line and the public API say: every problem at once, the missing case first,
the schemes listed in the help, and ``kanat.report`` a plain function.

Oracles: the case files written here with known mistakes (each one must be reported at its key
and line), the scheme registries themselves (:func:`kanat.api.schemes`), and Python's own type
of a function.
"""
import subprocess
import sys
import types
from pathlib import Path

import pytest
from typer.testing import CliRunner

from kanat.cli import app

from helpers import ROOT

DECAY = ROOT / "examples" / "mooring_buoy_decay.yaml"


def _case(tmp_path, *replacements) -> Path:
    text = DECAY.read_text()
    for old, new in replacements:
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / "case.yaml"
    path.write_text(text)
    return path


def _line(path: Path, text: str) -> int:
    return next(k for k, line in enumerate(path.read_text().splitlines(), start=1) if text in line)


def test_validate_reports_a_bad_scheme_next_to_a_bad_duration(tmp_path):
    from kanat.io import check_case

    path = _case(tmp_path, ("duration: 120", "duration: -5"), ("scheme: rk4", "scheme: bogus"))
    problems = {p.key: p for p in check_case(path) if p.severity == "error"}
    assert set(problems) == {"simulation.duration", "simulation.scheme"}
    assert problems["simulation.duration"].line == _line(path, "duration: -5")
    assert problems["simulation.scheme"].line == _line(path, "scheme: bogus")
    assert "valid: abm4, generalized-alpha-lumped, rk4" in problems["simulation.scheme"].message
    result = CliRunner().invoke(app, ["validate", str(path)])
    assert result.exit_code == 1
    assert "2 error(s)" in result.output


def test_keys_set_aside_raise_no_error_of_their_own(tmp_path):
    """The stand-in for a bad required number is no one's value: only the two real errors show,
    and a bad key with a default (output_dt) is dropped, not replaced."""
    from kanat.io import check_case

    path = _case(tmp_path, ("duration: 120", "duration: -5"), ("output_dt: 1.0", "output_dt: -1.0"))
    keys = sorted(p.key for p in check_case(path) if p.severity == "error")
    assert keys == ["simulation.duration", "simulation.output_dt"]


def test_a_valid_case_still_has_no_problem_and_a_single_error_stays_single(tmp_path):
    from kanat.io import check_case

    assert [p for p in check_case(DECAY) if p.severity == "error"] == []
    path = _case(tmp_path, ("duration: 120", "duration: -5"))
    assert [p.key for p in check_case(path) if p.severity == "error"] == ["simulation.duration"]


def test_run_without_a_case_names_the_case_first():
    result = CliRunner().invoke(app, ["run"])
    assert result.exit_code == 2
    assert "Missing argument 'CASE'" in result.output
    assert "'-o'" not in result.output


def test_run_with_a_case_and_no_output_names_the_output(tmp_path):
    result = CliRunner().invoke(app, ["run", str(DECAY)])
    assert result.exit_code == 2
    assert "Missing option '-o' / '--output'" in result.output


def test_scheme_help_lists_every_registered_scheme():
    from kanat.api import schemes

    registered = schemes()
    result = CliRunner().invoke(app, ["run", "-h"], terminal_width=400)
    assert result.exit_code == 0
    help_text = " ".join(result.output.split())
    assert len(registered) >= 10
    for name, cls in registered.items():
        assert name in help_text, name
    for model in {cls.model for cls in registered.values()}:
        names = ", ".join(sorted(n for n, c in registered.items() if c.model == model))
        assert f"{model}: {names}" in help_text


@pytest.mark.parametrize("first", ["import kanat", "import kanat.report.run_plot; import kanat",
                                   "from kanat.report import html_report; import kanat"])
def test_kanat_report_is_a_plain_function_whatever_was_imported_first(first):
    code = (f"{first}; import types, sys; from kanat.report.geometry import at_least; "
            "sys.exit(0 if isinstance(kanat.report, types.FunctionType) else 1)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr


def test_kanat_report_writes_a_page(tmp_path):
    import kanat
    from helpers_results import network_result

    assert isinstance(kanat.report, types.FunctionType)
    page = kanat.report(network_result(), tmp_path / "network.html")
    assert page == tmp_path / "network.html"
    assert "tension at the chosen nodes" in page.read_text()


def test_a_check_that_reads_a_stand_in_is_left_out(tmp_path):
    """A diameter of 0 is set aside with two stand-ins far apart: the strain check, which reads
    the drag of the stand-in diameter, says something else each time and is not reported; the
    bad scheme, which reads no diameter, is."""
    from kanat.io import check_case

    path = _case(tmp_path, ("diameter: 0.137", "diameter: 0"), ("scheme: rk4", "scheme: bogus"))
    keys = sorted(p.key for p in check_case(path) if p.severity == "error")
    assert keys == ["line_types.chain76.diameter", "simulation.scheme"]
