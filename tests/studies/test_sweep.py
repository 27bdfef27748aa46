"""Parameter studies (issue 7): a 2-worker cluster gives the serial answer, each variant is the
case edited by hand, a killed study resumes with every case exactly once, failures are recorded.

Oracles: the serial run of the same study (engine independence), and a case file edited by
hand and run directly with kanat.api.run (variant building).
"""
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from kanat.analysis import summary_statistics
from kanat.io import parse_case
from kanat.io.results import read_result
from kanat.sweep import read_summary, sweep

from helpers import EXAMPLES, run, short_case

SPEEDS = [7, 8, 9, 11]
DRAGS = [1.2, 1.5]
VARY = {"vessel.track[1].to_speed_kn": "7,8,9,11", "line_types.towcable.drag_normal": DRAGS}
STATS = ("tension_max", "tension_min", "top_tension_mean", "top_tension_std", "top_tension_mpm", "depth_max_sled")


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    path = tmp_path_factory.mktemp("base") / "short.yaml"
    path.write_text(short_case())
    return path


@pytest.fixture(scope="module")
def client():
    from kanat.sweep.cluster import local_cluster

    with local_cluster(2) as c:
        yield c


@pytest.fixture(scope="module")
def serial(base, tmp_path_factory):
    out = tmp_path_factory.mktemp("serial")
    return sweep(base, VARY, out, scheduler="serial")


def table(summary):
    return {name: summary[name].values for name in STATS}


@pytest.mark.slow
def test_cluster_study_gives_the_serial_summary(base, serial, client, tmp_path):
    assert len(client.scheduler_info()["workers"]) == 2
    result = sweep(base, VARY, tmp_path, scheduler=client)
    assert result.total == 8 and result.ran == 8 and result.failed == 0
    assert list(result.summary["case"].values) == list(range(8))
    np.testing.assert_array_equal(result.summary["vessel.track[1].to_speed_kn"].values, np.repeat(SPEEDS, 2))
    np.testing.assert_array_equal(result.summary["line_types.towcable.drag_normal"].values, np.tile(DRAGS, 4))
    for name, values in table(serial.summary).items():
        np.testing.assert_allclose(result.summary[name].values, values, rtol=1e-12, err_msg=name)
    workers = {json.loads(p.read_text())["worker"] for p in (tmp_path / "records").glob("*.json")}
    assert len(workers) == 2                                # both workers took cases
    again, keys, stats = read_summary(tmp_path)
    assert keys == list(VARY) and "top_tension_max" in stats
    np.testing.assert_array_equal(again["tension_max"].values, result.summary["tension_max"].values)


def test_each_variant_is_the_case_edited_by_hand(serial, tmp_path):
    """Case 5 (9 kn, C_n 1.5): the same YAML edited by hand and run directly."""
    text = short_case().replace("to_speed_kn: 10", "to_speed_kn: 9").replace("drag_normal: 1.5", "drag_normal: 1.5")
    assert run(parse_case(text), tmp_path / "direct.nc").ok
    direct = summary_statistics(read_result(tmp_path / "direct.nc"))
    row = serial.summary.sel(case=5)
    assert str(row["name"].values) == "case005_to_speed_kn=9_drag_normal=1.5"
    for name in STATS:
        assert float(row[name]) == pytest.approx(direct[name], rel=1e-12), name
    stored = read_result(serial.out_dir / "results" / "case005_to_speed_kn=9_drag_normal=1.5.nc")
    assert stored.attrs["case_sha256"] == read_result(tmp_path / "direct.nc").attrs["case_sha256"]


TIMING = ("wall_time_s", "setup_time_s", "solver_time_s", "compile_time_s")


def _wait_for_the_lock(study, seconds=60.0):
    """Until the killed study's lock on ``study`` is free: the kernel releases it when the last process
    holding it has exited, and a worker the kill reached only through its parent may outlive it briefly."""
    from kanat.errors import KanatError
    from kanat.io.outputs import OutputLock

    deadline = time.monotonic() + seconds
    while True:
        try:
            OutputLock(study).acquire().release()
            return
        except KanatError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.1)


@pytest.mark.slow
@pytest.mark.parametrize("after", [0, 3], ids=["while-the-first-cases-run", "after-3-records"])
def test_killed_study_resumes_with_every_case_once_bit_for_bit(after, base, serial, tmp_path):
    """kill -9 of the study and its workers while the first cases run (no record yet) or after
    3 records, then resume: every case once, every result file equal to the uninterrupted
    study's bit for bit (timings aside), the summary too."""
    script = ("import sys; from kanat.sweep import sweep; "
              f"sweep(sys.argv[1], {VARY!r}, sys.argv[2], workers=2)")
    log = (tmp_path.parent / f"{tmp_path.name}.log").open("w+")
    proc = subprocess.Popen([sys.executable, "-c", script, str(base), str(tmp_path)], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=log)
    records, results = tmp_path / "records", tmp_path / "results"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        done = len(list(records.glob("*.json"))) if records.exists() else 0
        running = results.exists() and any(results.glob("*.part"))
        if done >= after and (after > 0 or running):
            break
        time.sleep(0.02)
    assert proc.poll() is None, log.seek(0) or log.read()[-2000:]
    os.killpg(proc.pid, signal.SIGKILL)                    # the study and its worker processes
    proc.wait()
    log.close()
    _wait_for_the_lock(tmp_path)
    finished = len(list(records.glob("*.json")))
    assert after <= finished < 8
    if finished:
        partial, _, _ = read_summary(tmp_path)   # the summary kept up with the records (a kill may fall
        names = {p.stem for p in records.glob("*.json")}  # between a record and the summary's rewrite)
        assert set(partial["name"].values) <= names and partial.sizes["case"] >= finished - 1

    result = sweep(base, VARY, tmp_path, scheduler="serial")
    assert result.skipped == finished and result.ran == 8 - finished and result.failed == 0
    assert sorted(result.summary["case"].values) == list(range(8))
    assert len(list(records.glob("*.json"))) == 8
    files = sorted(results.glob("*.nc"))
    assert len(files) == 8 and not list(tmp_path.rglob("*.part"))
    for path in files:
        ds, reference = read_result(path), read_result(serial.out_dir / "results" / path.name)
        assert ds.attrs["status"] == "ok" and ds.sizes["time"] == 61
        xr.testing.assert_identical(ds.drop_attrs(), reference.drop_attrs())
        assert {k: v for k, v in ds.attrs.items() if k not in TIMING} == \
            {k: v for k, v in reference.attrs.items() if k not in TIMING}
    for name, values in table(serial.summary).items():
        np.testing.assert_array_equal(result.summary[name].values, values, err_msg=name)


@pytest.mark.slow
def test_failing_cases_are_recorded_and_the_others_complete(base, client, tmp_path):
    vary = {"simulation.scheme": ["generalized-alpha", "rk9"], "line_types.towcable.diameter": [0.0173, -1.0]}
    seen = []
    result = sweep(base, vary, tmp_path, scheduler=client.scheduler.address,      # a cluster by its address
                   progress=lambda p: seen.append((p.done, p.failed)))
    summary = result.summary
    assert list(summary["status"].values) == ["ok", "failed", "failed", "failed"]
    assert "unknown continuum scheme 'rk9'" in str(summary["message"].values[2])
    assert "line_types.towcable.diameter" in str(summary["message"].values[1])     # validation names the key
    assert result.failed == 3 and seen[-1] == (4, 3)
    ok = read_result(tmp_path / "results" / f"{summary['name'].values[0]}.nc")
    assert float(summary["tension_max"].values[0]) == pytest.approx(float(ok["tension"].max()), rel=1e-12)
    assert np.isnan(summary["tension_max"].values[1:]).all()
    again = sweep(base, vary, tmp_path, scheduler="serial")        # failed cases are finished: not rerun
    assert again.ran == 0 and again.skipped == 4
