"""Running planar continuum cases: steady tow, settling, grid convergence, failure and resume."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from scipy.constants import knot
from typer.testing import CliRunner

from kanat.cli import app
from kanat.io import parse_case
from kanat.io.results import read_result
from kanat.statics import solve_statics

from helpers import EXAMPLES, plain, run
from helpers import step_case_text as case_text


def test_steady_tow_from_static_state_stays_steady(tmp_path):
    case = parse_case(case_text(duration=100, before=200))
    summary = run(case, tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    relative = ds.body_position.isel(body=0) - ds.vessel_position
    drift = np.abs(relative - relative.isel(time=0)).max() / 1000.0
    tension = np.abs(ds.tension - ds.tension.isel(time=0)).max() / ds.tension.max()
    assert summary.ok and summary.steps == 100
    assert float(drift) < 1e-6 and float(tension) < 1e-6


def test_speed_step_settles_on_the_new_static_state(tmp_path):
    summary = run(parse_case(case_text()), tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    fast = solve_statics(parse_case((EXAMPLES / "towed_body.yaml").read_text().replace("speed_kn: 6", "speed_kn: 10")))
    body = ds.body_position.isel(body=0, time=-1).values - ds.vessel_position.isel(time=-1).values
    assert summary.ok
    assert np.allclose(body, fast.bodies["sled"], atol=0.3)      # box discretization at 100 segments: 0.13 m
    assert ds.tension.values[-1, 0] == pytest.approx(fast.cables["tow"].tension[0], rel=2e-3)
    assert ds.tension.values[:, 0].max() > 1.2 * ds.tension.values[-1, 0]          # the jerk overshoots
    assert ds.body_position.values[-1, 0, 2] > ds.body_position.values[0, 0, 2] + 100   # the body rises


def test_grid_convergence_in_space_is_second_order(tmp_path):
    """Body depth and top tension 20 s after the speed step on 10 to 80 segments (dt 0.1 s fixed).

    The step launches a discontinuous longitudinal front, so the tension converges a little
    slower than the depth (measured: depth 2.39 then 2.20, tension 1.96 then 1.79).
    """
    values = []
    for segments in (10, 20, 40, 80):
        run(parse_case(case_text(duration=40, dt=0.1, segments=segments, before=20)), tmp_path / f"{segments}.nc")
        ds = read_result(tmp_path / f"{segments}.nc")
        values.append((ds.body_position.values[-1, 0, 2], ds.tension.values[-1, 0]))
    values = np.array(values)
    for column in range(2):
        d = np.abs(np.diff(values[:, column]))
        orders = np.log2(d[:-1] / d[1:])
        assert orders[-1] == pytest.approx(2.0, abs=0.3), orders


def test_failure_stops_once_keeps_results_and_explains(tmp_path):
    """A tow stopped dead (10 kn to 0 in one step) drives the top into compression: with
    ``simulation.slack: stop`` the run stops there (with the default ``continue`` it records the
    event and goes on: tests/continuum/test_continuum_slack.py)."""
    text = case_text(duration=60, before=20, to_kn=0).replace("speed_kn: 6", "speed_kn: 10").replace(
        "simulation:\n", "simulation:\n  slack: stop\n")
    assert "slack: stop" in text
    path = tmp_path / "stop.yaml"
    path.write_text(text)
    out = tmp_path / "stop.nc"
    result = CliRunner().invoke(app, ["run", str(path), "-o", str(out)])
    assert result.exit_code == 1
    words = plain(result.output)
    assert "compression" in words and "model: lumped" in words
    ds = read_result(out)
    assert ds.attrs["status"].startswith("failed:") and "compression" in ds.attrs["status"]
    assert 2 <= ds.sizes["time"] <= 22


def test_killed_run_resumes_to_the_same_answer(tmp_path):
    path = tmp_path / "case.yaml"
    path.write_text(case_text(duration=1200, dt=0.5, before=100))
    whole, killed = tmp_path / "whole.nc", tmp_path / "killed.nc"
    assert CliRunner().invoke(app, ["run", str(path), "-o", str(whole)]).exit_code == 0
    proc = subprocess.Popen([sys.executable, "-m", "kanat.cli", "run", str(path), "-o", str(killed),
                             "--checkpoint-every", "100"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    checkpoint = Path(str(killed) + ".ckpt.npz")
    deadline = time.time() + 120
    while not checkpoint.exists() and time.time() < deadline and proc.poll() is None:
        time.sleep(0.01)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    partial = read_result(str(killed) + ".part")
    assert partial.attrs["status"] == "running" and 0 < partial.sizes["time"] < 2401
    resumed = CliRunner().invoke(app, ["run", str(path), "-o", str(killed), "--resume"])
    assert resumed.exit_code == 0, resumed.output
    a, b = read_result(whole), read_result(killed)
    assert b.attrs["status"] == "ok" and a.sizes == b.sizes
    np.testing.assert_array_equal(a.tension.values, b.tension.values)
    np.testing.assert_array_equal(a.position.values, b.position.values)


ARRAY = (EXAMPLES / "towed_array.yaml").read_text()


@pytest.mark.parametrize("dims", [2, 3])
def test_free_tail_trails_at_the_critical_angle_and_stays_steady(tmp_path, dims):
    """At a free end T = 0, so its normal balance is w cos(phi) = R sin(phi)^2: the critical angle."""
    text = ARRAY.replace("speed_kn: 8, duration: 30", "speed_kn: 8, duration: 300").replace(
        "dimensions: 2", f"dimensions: {dims}").replace("duration: 200, dt", "duration: 50, dt")
    summary = run(parse_case(text), tmp_path / "a.nc")
    ds = read_result(tmp_path / "a.nc")
    assert summary.ok
    assert ds.tension.values[0, -1] == 0.0
    assert np.abs(ds.tension.values[-1] - ds.tension.values[0]).max() < 1e-6 * ds.tension.values[0, 0]
    tail = ds.position.values[0, -1] - ds.position.values[0, -2]
    angle = np.degrees(np.arctan2(-tail[2], -tail[0]))
    w, r = 2.0, 0.5 * 1025 * 0.08 * 1.2 * (8 * knot) ** 2
    critical = np.degrees(np.arccos((-w + np.sqrt(w * w + 4 * r * r)) / (2 * r)))
    assert angle == pytest.approx(critical, abs=0.05)


def test_slowing_array_sinks_and_unloads(tmp_path):
    summary = run(parse_case(ARRAY), tmp_path / "a.nc")
    ds = read_result(tmp_path / "a.nc")
    assert summary.ok
    assert ds.position.values[-1, -1, 2] < ds.position.values[0, -1, 2] - 5.0        # tail sinks
    assert ds.tension.values[-1, 0] < 0.5 * ds.tension.values[0, 0]                   # (5/8)^2 of the drag


def test_a_buoyant_towed_body_starts_from_its_statics(tmp_path):
    """The cable leaves the tow point downwards and reaches the body upwards: its angle passes
    through 180 deg, which the start must carry continuously."""
    text = case_text(duration=20).replace("net_buoyancy: -6686", "net_buoyancy: 3000")
    summary = run(parse_case(text), tmp_path / "b.nc")
    ds = read_result(tmp_path / "b.nc")
    static = solve_statics(parse_case(text))
    assert summary.ok, summary.status
    np.testing.assert_allclose(ds.body_position.values[0, 0], static.bodies["sled"], atol=0.5)


def test_no_initial_state_writes_a_result_that_says_why_and_what_to_do(tmp_path):
    text = case_text(duration=20).replace("net_buoyancy: -6686", "net_buoyancy: 0").replace(
        "drag_area: 0.3276", "drag_area: 0").replace("speed_kn: 6", "speed_kn: 0")
    summary = run(parse_case(text), tmp_path / "s.nc")
    ds = read_result(tmp_path / "s.nc")
    assert ds.attrs["status"] == summary.status and ds.sizes["time"] == 0
    assert summary.status.startswith("failed: no initial state") and "model: lumped" in summary.status


def test_a_result_marked_ok_with_a_nan_is_refused(tmp_path):
    import h5netcdf

    from kanat.errors import KanatError

    run(parse_case(case_text(duration=5)), tmp_path / "r.nc")
    with h5netcdf.File(tmp_path / "r.nc", "a") as f:
        f.variables["tension"][2, 3] = np.nan
    with pytest.raises(KanatError, match="status ok but its tension holds non-finite"):
        read_result(tmp_path / "r.nc")
