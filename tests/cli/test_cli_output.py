"""What the command line prints, and where: whole lines off a terminal, -q, -v, --log-file, status.

Subprocesses show the real standard error of a pipe (what a CI log or ``2>&1 | tee`` gets);
CliRunner is used where only the text matters. Oracles: the case files' own content (the
warning MoorDyn's import gives, the number of cables) and the run's result file.
"""
import os
import re
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from kanat.cli import app
from kanat.cli_common import setup_logging
from kanat.io.results import read_result

from helpers import DATA, EXAMPLES

TOWED = EXAMPLES / "towed_body.yaml"                     # one cable, statics, speed_kn: 6
NETWORK = EXAMPLES / "mooring_3leg.yaml"                 # three legs on a buoy, network statics
MOORDYN = DATA / "moordyn" / "float_surfaces.dat"   # long warnings, then a failing statics
LONG_WARNING = ("lateral seabed friction is not applied by model 'statics'", "supported by: continuum, lumped")
runner = CliRunner()


@pytest.fixture(autouse=True)
def default_logging():
    """Each test starts and ends with the default set-up (no -q left on the shared consoles)."""
    setup_logging()
    yield
    setup_logging()


def kanat(*args, width=60):
    """``kanat ARGS`` in a subprocess, standard output and error piped, a narrow console."""
    env = {**os.environ, "COLUMNS": str(width)}
    env.pop("FORCE_COLOR", None)
    return subprocess.run([sys.executable, "-m", "kanat.cli", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=600)


def test_piped_log_lines_are_whole_and_plain(tmp_path):
    done = kanat("statics", MOORDYN, "-o", tmp_path / "x.nc")
    assert done.returncode == 1
    lines = done.stderr.splitlines()
    assert all(line.startswith("kanat: ") for line in lines), done.stderr
    assert not [line for line in lines if line != line.rstrip()]               # no padding to a width
    long = [line for line in lines if LONG_WARNING[0] in line]
    assert len(long) == 1 and LONG_WARNING[1] in long[0] and len(long[0]) > 200   # one line, far past 60
    assert long[0].startswith("kanat: warning: ")
    assert lines[-1].startswith("kanat: error: statics failed: point 'point3' would float")


def test_piped_import_summary_is_one_line(tmp_path):
    done = kanat("import", MOORDYN, "-o", tmp_path / "case.yaml")
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("\n") == 1
    assert done.stdout.startswith(f"wrote {tmp_path / 'case.yaml'}: MoorDyn v")
    assert done.stdout.rstrip("\n").endswith("(listed in its header)")


def test_quiet_prints_nothing_for_a_successful_run(tmp_path):
    out = tmp_path / "o.nc"
    done = kanat("-q", "statics", TOWED, "-o", out)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")
    assert read_result(out).attrs["status"] == "ok"


def test_quiet_still_prints_errors_and_only_them(tmp_path):
    log = tmp_path / "run.log"
    done = kanat("-q", "--log-file", log, "statics", MOORDYN, "-o", tmp_path / "x.nc")
    assert done.returncode == 1 and done.stdout == ""
    assert [line.split(":")[1] for line in done.stderr.splitlines()] == [" error"]
    records = log.read_text()
    assert "WARNING kanat: " in records and "ERROR kanat: statics failed: point 'point3'" in records


def test_log_file_keeps_the_info_records_and_the_summary_even_with_quiet(tmp_path):
    log, out = tmp_path / "run.log", tmp_path / "o.nc"
    result = runner.invoke(app, ["-q", "--log-file", str(log), "statics", str(TOWED), "-o", str(out)])
    assert result.exit_code == 0 and result.output == ""
    text = log.read_text()
    stamped = re.compile(r"^\d{4}-\d\d-\d\d \d\d:\d\d:\d\d,\d{3} (INFO|DEBUG|WARNING|ERROR) kanat[\w.]*: ")
    records = [line for line in text.splitlines() if stamped.match(line)]
    assert any("case 'towed-body-6kn' is valid: model statics; 1 cable(s) of 100 segment(s)" in r for r in records)
    assert any("statics solved (method auto, 101 nodes): cable tow by shooting" in r for r in records)
    assert any(r.endswith("INFO kanat: status: ok") for r in records)
    assert records[-1].endswith(f"INFO kanat: wrote {out}")
    assert " DEBUG " not in text                                       # DEBUG only with -v


def test_log_file_with_verbose_has_debug_records(tmp_path):
    log = tmp_path / "run.log"
    result = runner.invoke(app, ["-v", "--log-file", str(log), "statics", str(TOWED), "-o", str(tmp_path / "o.nc")])
    assert result.exit_code == 0
    assert "DEBUG kanat.statics.driver: statics method auto: shooting" in log.read_text()


def test_verbose_shows_the_steps_and_the_default_does_not(tmp_path):
    loud = runner.invoke(app, ["-v", "statics", str(TOWED), "-o", str(tmp_path / "a.nc")])
    assert loud.exit_code == 0
    info = [line for line in loud.stderr.splitlines() if line.startswith("kanat: info: ")]
    assert any("is valid: model statics" in line for line in info)
    assert any("statics solved" in line and "cable tow by shooting" in line for line in info)
    assert not any("status:" in line or "wrote" in line for line in info)       # on standard output once
    plain = runner.invoke(app, ["statics", str(TOWED), "-o", str(tmp_path / "b.nc")])
    assert plain.exit_code == 0 and "info:" not in plain.stderr


@pytest.mark.parametrize("case, cables", [(TOWED, 1), (NETWORK, 3)], ids=["single-cable", "network"])
def test_statics_summary_ends_with_its_status(case, cables, tmp_path):
    out = tmp_path / "o.nc"
    result = runner.invoke(app, ["statics", str(case), "-o", str(out)])
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert lines[-2:] == ["status: ok", f"wrote {out}"]
    assert sum(line.startswith("cable ") for line in lines) == cables
    assert read_result(out).attrs["status"] == "ok"


def test_quiet_and_verbose_are_documented():
    result = runner.invoke(app, ["--help"])
    words = " ".join(result.output.split())
    assert "Print only errors" in words and "exit status" in words and "--log-file" in words
