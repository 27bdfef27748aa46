"""The command line: exit codes, one-paragraph failures, --version, --debug."""

import pytest
from typer.testing import CliRunner

import kanat
from kanat.cli import app
from kanat.io.results import read_result

from helpers import EXAMPLES, plain

runner = CliRunner()


def test_version():
    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0 and kanat.__version__ in result.output


def test_validate_reports_errors_with_line_and_exits_non_zero(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text((EXAMPLES / "towed_body.yaml").read_text().replace("line_type: towcable", "line_type: towcabel"))
    result = runner.invoke(app, ["validate", str(bad)])
    assert result.exit_code == 1
    assert "towcabel" in result.output and "towcable" in result.output
    assert "Traceback" not in result.output


def test_statics_failure_is_explained_writes_status_and_exits_non_zero(tmp_path):
    case = tmp_path / "slack.yaml"
    text = (EXAMPLES / "towed_body.yaml").read_text()
    text = text.replace("net_buoyancy: -6686", "net_buoyancy: 0").replace("drag_area: 0.3276", "drag_area: 0")
    text = text.replace("speed_kn: 6", "speed_kn: 0")
    case.write_text(text)
    out = tmp_path / "out.nc"
    result = runner.invoke(app, ["statics", str(case), "-o", str(out)])
    assert result.exit_code == 1
    assert "slack" in plain(result.output) and "Traceback" not in result.output
    assert read_result(out).attrs["status"].startswith("failed:")


def test_debug_shows_the_exception(tmp_path):
    case = tmp_path / "slack.yaml"
    text = (EXAMPLES / "towed_body.yaml").read_text()
    case.write_text(text.replace("net_buoyancy: -6686", "net_buoyancy: 0").replace("drag_area: 0.3276", "drag_area: 0")
                    .replace("speed_kn: 6", "speed_kn: 0"))
    result = runner.invoke(app, ["statics", str(case), "-o", str(tmp_path / "o.nc"), "--debug"])
    assert result.exit_code != 0 and result.exception is not None


def test_run_refuses_models_this_build_lacks_and_says_what_to_do(tmp_path, monkeypatch):
    from kanat import api

    monkeypatch.setattr(api, "MODELS", {k: v for k, v in api.MODELS.items() if k != "continuum"})
    case = tmp_path / "dyn.yaml"
    text = (EXAMPLES / "towed_body.yaml").read_text().replace("model: statics", "model: continuum")
    case.write_text(text + "simulation: {duration: 10, dt: 1, output_dt: 1}\n")
    result = runner.invoke(app, ["run", str(case), "-o", str(tmp_path / "o.nc")])
    assert result.exit_code == 1
    assert "run: kanat statics" in plain(result.output)


@pytest.mark.parametrize("method", ["shooting", "collocation"])
def test_statics_method_option(method, tmp_path):
    out = tmp_path / "o.nc"
    result = runner.invoke(app, ["statics", str(EXAMPLES / "towed_body.yaml"), "-o", str(out), "--method", method])
    assert result.exit_code == 0, result.output
    assert read_result(out).attrs["method_tow"] == method


def test_a_second_run_on_the_same_output_is_refused_and_the_first_completes(tmp_path):
    import subprocess
    import sys
    import time

    from helpers import short_case

    case = tmp_path / "case.yaml"
    case.write_text(short_case(duration=600, segments=60))
    out = tmp_path / "same.nc"
    first = subprocess.Popen([sys.executable, "-m", "kanat.cli", "run", str(case), "-o", str(out)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    lock = tmp_path / ".same.nc.lock"
    deadline = time.time() + 60
    while not lock.exists() and time.time() < deadline and first.poll() is None:
        time.sleep(0.02)
    second = runner.invoke(app, ["run", str(case), "-o", str(out)])
    stdout, stderr = first.communicate(timeout=600)
    assert second.exit_code == 1 and "in use by another kanat run" in plain(second.output)
    assert first.returncode == 0, stdout + stderr
    assert read_result(out).attrs["status"] == "ok" and not lock.exists()


def test_an_output_that_is_the_input_is_refused(tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text((EXAMPLES / "towed_body.yaml").read_text())
    result = runner.invoke(app, ["statics", str(case), "-o", str(case)])
    assert result.exit_code == 1 and case.read_text().startswith("#")
    assert "Traceback" not in result.output
