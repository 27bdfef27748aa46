"""No hangs: the statics solvers stop within their budget, and Ctrl-C ends any run keeping its file.

Reproducers of the audit (each an example with one or two keys changed, which ran for more than
900 s and ignored Ctrl-C): a cable whose two ends are the same anchor in a current, and a current
profile with a 1000 m/s vertical row. The oracles: the message, and the wall clock against the
budget (:mod:`kanat.statics.budget`); for Ctrl-C, the exit status, the file's status, and a
resumed run equal, bit for bit, to an uninterrupted one.
"""
import math
import os
import re
import signal
import subprocess
import time

import numpy as np
import pytest
import yaml

import kanat
from kanat import api
from kanat.errors import KanatError, SolverError
from kanat.io.results import read_result
from kanat.io.stream import part_path
from kanat.statics import budget

from helpers import CTRL_C, EXAMPLES, kanat_command, short_case


def example(name: str, **changes) -> dict:
    """An example's data with dotted keys (``cables.0.to``) set."""
    data = yaml.safe_load((EXAMPLES / name).read_text())
    for key, value in changes.items():
        *parents, last = key.split(".")
        node = data
        for part in parents:
            node = node[int(part)] if isinstance(node, list) else node[part]
        node[int(last) if isinstance(node, list) else last] = value
    return data


SAME_ANCHOR = example("subsurface_buoy.yaml", **{"cables.0.to": "anchor:[0, 0, -500]"})
VERTICAL_CURRENT = example("mooring_current.yaml", **{
    "environment.current.profile": [[0, 1.0, 0, 0], [-50, 0.7, 0, 1000], [-150, 0.2, 0, 0]]})


def test_a_cable_from_an_anchor_back_to_it_is_refused_at_once():
    case = kanat.load_case(SAME_ANCHOR)
    start = time.perf_counter()
    with pytest.raises(SolverError, match=r"both ends of the cable are at the same point \(x = 0 m, z = -500 m\)"):
        kanat.solve_statics(case)
    assert time.perf_counter() - start < 5.0


def test_the_same_anchor_in_still_water_is_the_line_on_the_seabed():
    """Without a current the catenary solves it: the whole line lies on the seabed, slack."""
    data = example("subsurface_buoy.yaml", **{"cables.0.to": "anchor:[0, 0, -500]"})
    del data["environment"]["current"], data["bodies"]
    result = kanat.solve_statics(kanat.load_case(data))
    np.testing.assert_allclose(result["position"].sel(xyz="z").values, -500.0, atol=1e-9)
    assert float(result["seabed_contact_length"][0]) == pytest.approx(400.0)
    np.testing.assert_allclose(result["tension"].values, 0.0, atol=1e-6)


def test_a_1000_m_s_vertical_current_ends_within_the_time_budget(monkeypatch, tmp_path):
    monkeypatch.setenv(budget.SECONDS_ENV, "2")
    case = kanat.load_case(VERTICAL_CURRENT)
    out = tmp_path / "steady.nc"
    start = time.process_time()
    with pytest.raises(budget.BudgetExceeded, match=r"the statics of cable 'mooring' gave up after 2(\.\d+)? s of "
                                                    r"CPU \(the limit is 2 s;"):
        api.run(case, output=out, model="statics")
    assert time.process_time() - start < 2.0 + 3.0        # the limit (CPU), one clock reading late at most
    status = read_result(out).attrs["status"]
    assert status.startswith("failed: the statics of cable 'mooring' gave up") and "no steady state" in status


def test_a_dynamic_run_whose_initial_statics_makes_no_progress_fails_within_the_budget(monkeypatch):
    monkeypatch.setenv(budget.SECONDS_ENV, "2")
    case = kanat.load_case(example("surface_mooring_waves.yaml", **{
        "environment.current": {"profile": [[0, 0.5, 0, 0], [-50, 0.5, 0, 1000], [-100, 0.5, 0, 0]]}}))
    start = time.process_time()
    with pytest.warns(api.RunFailedWarning):
        outcome = api.run(case)
    assert time.process_time() - start < 2.0 + 8.0                   # the budget (CPU), and the model's set-up
    assert re.match(r"failed: no initial state: the statics of cable 'mooring' \(the initial state of the run\) "
                    r"gave up after 2(\.\d+)? s of CPU \(the limit is 2 s", outcome.status), outcome.status


def test_the_lumped_equilibrium_has_the_time_budget(monkeypatch):
    monkeypatch.setenv(budget.SECONDS_ENV, "0.01")
    with pytest.warns(api.RunFailedWarning):
        outcome = api.run(kanat.load_case(EXAMPLES / "trawl_head_8s_1to2.yaml"))
    assert re.match(r"failed: no initial state: the equilibrium of the lumped network gave up after "
                    r"[0-9.]+ s of CPU \(the limit is 0.01 s\)", outcome.status), outcome.status


def test_the_budget_counts_evaluations_and_time():
    counted = budget.Budget(seconds=math.inf, evaluations=100)
    for _ in range(100):
        counted.charge()
    with pytest.raises(budget.BudgetExceeded, match="after 101 evaluations"):
        counted.charge()
    timed = budget.Budget(seconds=0.0, evaluations=10**9)
    for _ in range(budget.CLOCK_EVERY - 1):
        timed.charge()
    with pytest.raises(budget.BudgetExceeded, match=f"{budget.CLOCK_EVERY} evaluations"):
        timed.charge()


def test_the_examples_stay_far_from_the_budget():
    """Every statics example's evaluations, counted against the limit (the budget's margin)."""
    for name in ("subsurface_mooring.yaml", "subsurface_buoy.yaml", "towed_body.yaml"):
        with budget.budget("measured") as spent:
            kanat.solve_statics(kanat.load_case(EXAMPLES / name))
        assert 0 < spent.used < budget.MAX_EVALUATIONS / 50, name


@pytest.mark.parametrize("text", ["soon", "0", "-5", "inf", "nan"])
def test_a_bad_time_limit_in_the_environment_is_named(monkeypatch, text):
    monkeypatch.setenv(budget.SECONDS_ENV, text)
    with pytest.raises(KanatError, match=f"{budget.SECONDS_ENV}='{text}' is not a number of seconds"):
        budget.seconds_limit()


def _interrupt_when(proc, ready, delay: float) -> None:
    """SIGINT to ``proc`` ``delay`` s after ``ready()`` holds (within 60 s)."""
    deadline = time.monotonic() + 60
    while not ready() and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(delay)
    assert proc.poll() is None, "the run ended before it could be interrupted"
    proc.send_signal(signal.SIGINT)


@pytest.mark.slow
def test_ctrl_c_ends_a_hopeless_statics_and_says_so_in_its_file(tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text(yaml.safe_dump(VERTICAL_CURRENT))
    out = tmp_path / "steady.nc"
    env = {**os.environ, budget.SECONDS_ENV: "600"}
    proc = subprocess.Popen(kanat_command("statics", case, "-o", out), env=env, **CTRL_C,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    _interrupt_when(proc, lambda: True, 6.0)               # imports, then well into the search
    sent = time.monotonic()
    text, _ = proc.communicate(timeout=30)
    assert proc.returncode == 130, text
    assert time.monotonic() - sent < 5.0
    assert "interrupted" in text and "Traceback" not in text
    assert read_result(out).attrs["status"].startswith("failed: interrupted after")


@pytest.mark.slow
def test_ctrl_c_ends_a_run_keeping_its_file_and_resume_is_bit_identical(tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text(short_case(duration=3000, segments=40, before=50).replace("dt: 1.0\n", "dt: 0.5\n"))
    whole, out = tmp_path / "whole.nc", tmp_path / "interrupted.nc"
    subprocess.run(kanat_command("run", case, "-o", whole), check=True, capture_output=True, timeout=600)
    proc = subprocess.Popen(kanat_command("run", case, "-o", out, "--checkpoint-every", 50), **CTRL_C,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    _interrupt_when(proc, part_path(out).exists, 1.0)
    text, _ = proc.communicate(timeout=60)
    assert proc.returncode == 130, text
    assert "interrupted" in text and "Traceback" not in text
    kept = read_result(out)
    assert kept.attrs["status"].startswith("interrupted at t = ") and 0 < kept.time.size
    done = subprocess.run(kanat_command("run", case, "-o", out, "--resume"), capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    result, reference = read_result(out), read_result(whole)
    assert result.attrs["status"] == "ok"
    for name in ("time", "position", "velocity", "tension"):
        np.testing.assert_array_equal(result[name].values, reference[name].values, err_msg=name)


def test_checkpoint_every_0_is_refused(tmp_path):
    case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml")
    with pytest.raises(KanatError, match=r"checkpoint_every must be a whole number of outputs, at least 1 \(got 0\)"):
        api.run(case, output=tmp_path / "out.nc", checkpoint_every=0)
    assert not (tmp_path / "out.nc").exists() and not part_path(tmp_path / "out.nc").exists()
    done = subprocess.run(kanat_command("run", EXAMPLES / "speed_step_2d.yaml", "-o", tmp_path / "out.nc",
                                        "--checkpoint-every", 0), capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "--checkpoint-every" in done.stderr and ">= 1" in done.stderr.replace(
        "greater than or equal to", ">=")
