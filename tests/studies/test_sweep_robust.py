"""Studies that survive their cases and their users (issues 13 and 14).

* A failing variant — invalid after --vary, a solver failure, a crash of the process that
  runs it — is recorded and the others finish (oracle: the same cases run alone).
* Varied names and values never steer file paths (``--vary name=../../x``): every file
  the study writes is inside it and named by index + sanitized label; the report reads
  results through the study's own case table (oracle: the file system after the study,
  and the result files read directly).
* The default engine follows its rule (serial in a child process for short cases, a local
  cluster when it pays, a running cluster from Dask's configuration or a scheduler file);
  a second study on the same directory is refused naming the first one's pid.
"""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from kanat.errors import KanatError
from kanat.io.results import read_result
from kanat.report.html_report import write_report
from kanat.sweep import cluster_pays, sweep
from kanat.sweep import engine, execution

from helpers import CTRL_C, short_case

CRASH = "crash-me"
_original_run_case = engine.run_case


def crashing_run_case(text, label, output, window=None):
    """run_case, except that a case named CRASH kills its process as a segfault would."""
    if f"name: {CRASH}" in text:
        os.kill(os.getpid(), signal.SIGKILL)
    return _original_run_case(text, label, output, window)


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    path = tmp_path_factory.mktemp("base") / "short.yaml"
    path.write_text(short_case(duration=20, segments=10))
    return path


def records(study):
    return {p.stem: json.loads(p.read_text()) for p in (study / "records").glob("*.json")}


def test_rule_starts_a_cluster_only_when_it_saves_more_than_its_cost():
    assert not cluster_pays(0.3, 6, 2, warm_up_s=0.7, startup_s=0.5)   # 1.8 s serial vs 0.9 s + 1.2 s
    assert cluster_pays(0.5, 6, 2, warm_up_s=0.7, startup_s=0.5)       # 3 s vs 1.5 s + 1.2 s
    assert cluster_pays(3.0, 6, 2, warm_up_s=0.7, startup_s=0.5)
    assert not cluster_pays(3.0, 1, 2)                                 # one case left: nothing to share
    assert not cluster_pays(100.0, 7, 1)                               # one core
    assert cluster_pays(1.0, 3, 4, startup_s=1.9) and not cluster_pays(1.0, 3, 4, startup_s=2.0)   # 3 - 1 = 2


def test_failures_are_recorded_and_the_others_finish(base, tmp_path, monkeypatch):
    """Default engine, serial by its rule: an invalid variant, a solver failure and a crash, among good cases."""
    monkeypatch.setattr(engine, "run_case", crashing_run_case)
    monkeypatch.setattr(execution, "CLUSTER_STARTUP_S", 1e9)             # the rule keeps it serial
    vary = {"name": ["good", CRASH, "also-good"], "simulation.scheme": ["generalized-alpha", "factorized"],
            "line_types.towcable.diameter": [0.0173, -1.0]}
    result = sweep(base, vary, tmp_path / "study")
    summary = result.summary
    status = dict(zip(summary["vary:name"].values + "/" + summary["simulation.scheme"].values + "/"
                      + summary["line_types.towcable.diameter"].values.astype(str), summary["status"].values))
    message = dict(zip(status, summary["message"].values))
    assert result.total == 12 and result.ran == 12 and result.failed == 10
    assert [k for k, v in status.items() if v == "ok"] == ["good/generalized-alpha/0.0173",
                                                           "also-good/generalized-alpha/0.0173"]
    assert all("line_types.towcable.diameter" in message[k] for k in status if k.endswith("/-1.0"))  # invalid
    assert "compression" in message["good/factorized/0.0173"] or "dt" in message["good/factorized/0.0173"]
    assert "died (killed by signal SIGKILL)" in message[f"{CRASH}/generalized-alpha/0.0173"]       # crash
    assert "serial in a child process" in result.engine
    ok = summary.isel(case=np.flatnonzero(summary["status"].values == "ok"))
    for name, top in zip(ok["name"].values, ok["tension_max"].values):       # the survivors are right
        direct = read_result(tmp_path / "study" / "results" / f"{name}.nc")
        assert float(top) == pytest.approx(float(direct["tension"].max()), rel=1e-12)
    pids = {r.get("worker", "").split(":")[-1] for r in records(tmp_path / "study").values() if r.get("worker")}
    assert str(os.getpid()) not in pids and len(pids) == 2     # one child, then a new one after the crash


@pytest.mark.slow
def test_a_crash_on_a_local_or_dask_cluster_is_recorded(base, tmp_path, monkeypatch):
    from kanat.sweep.cluster import local_cluster

    monkeypatch.setattr(engine, "run_case", crashing_run_case)   # forked children inherit it; Dask's workers
    #                                                              import it from this module by reference
    result = sweep(base, {"name": ["good", CRASH, "also-good"]}, tmp_path / "local", workers=2)
    assert list(result.summary["status"].values) == ["ok", "failed", "ok"]
    assert "died (killed by signal SIGKILL)" in str(result.summary["message"].values[1])
    assert result.engine == "a local cluster of 2 worker processes (--workers)"
    with local_cluster(2) as client:
        on_dask = sweep(base, {"name": ["good", CRASH, "also-good"]}, tmp_path / "dask", scheduler=client)
    assert list(on_dask.summary["status"].values) == ["ok", "failed", "ok"]
    assert "worker process running this case died" in str(on_dask.summary["message"].values[1])
    np.testing.assert_array_equal(on_dask.summary["tension_max"].values, result.summary["tension_max"].values)


HOSTILE = ["../../x", "/etc/passwd", "a/../../b", "..", "<img src=x onerror=alert(1)>", "x" * 400, "name"]


@pytest.mark.slow
def test_names_and_values_never_steer_paths(base, tmp_path):
    before = set(tmp_path.parent.rglob("*"))
    result = sweep(base, {"name": HOSTILE, "cables[0].name": ["../tow"]}, tmp_path / "study", scheduler="serial")
    created = set(tmp_path.parent.rglob("*")) - before
    study = (tmp_path / "study").resolve()
    assert all(p.resolve() == study or study in p.resolve().parents
               for p in created if p.resolve() != tmp_path.resolve())  # nothing written outside the study
    assert not (tmp_path.parent / "x.nc").exists() and not (tmp_path.parent.parent / "x.nc").exists()
    names = list(result.summary["name"].values)
    assert names == [f"case{i:03d}_" + names[i].split("_", 1)[1] for i in range(len(names))]
    for name in names:
        assert "/" not in name and len(name) < 140 and set(name) <= set(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._=+-")
        assert (study / "results" / f"{name}.nc").is_file()
    assert list(result.summary["vary:name"].values) == HOSTILE                          # the values, as given
    assert (result.summary["status"].values == "ok").all()

    html = write_report(study, tmp_path / "report.html").read_text()              # reads by the case table
    figures = json.loads(html.split('id="kanat-figures">', 1)[1].split("</script>", 1)[0])
    traces = figures["plot-study-histories"]["data"]
    assert len(traces) == len(names)
    first = read_result(study / "results" / f"{names[0]}.nc")
    assert traces[0]["name"] == names[0] and first.attrs["case_name"] == "../../x"
    for target in (study / "summary.nc", study / "results" / f"{names[0]}.nc"):   # the report keeps off the study
        with pytest.raises(KanatError, match="is also an input"):
            write_report(study, target)

    table = json.loads((study / "study.json").read_text())
    table["cases"][0]["name"] = "../../../outside"                                 # an edited study
    (study / "study.json").write_text(json.dumps(table))
    with pytest.raises(KanatError, match="is not the name of a study case"):
        write_report(study, tmp_path / "again.html")


@pytest.mark.slow
def test_default_engine_reuses_a_configured_or_named_cluster(base, tmp_path):
    import dask

    from kanat.sweep.cluster import local_cluster

    with local_cluster(2) as client:
        workers = {str(pid) for pid in client.run(os.getpid).values()}
        with dask.config.set({"scheduler-address": client.scheduler.address}):
            result = sweep(base, {"vessel.track[1].to_speed_kn": [8, 9, 10]}, tmp_path / "a")
        assert f"running Dask cluster at {client.scheduler.address} (configured)" in result.engine
        used = {r["worker"].split(":")[-1] for r in records(tmp_path / "a").values()}
        assert used <= workers                                                 # the cluster's own workers ran them
        file = tmp_path / "scheduler.json"
        file.write_text(json.dumps({"address": client.scheduler.address}))
        again = sweep(base, {"vessel.track[1].to_speed_kn": [8, 9, 10]}, tmp_path / "b", scheduler=str(file))
        assert "(named)" in again.engine
        np.testing.assert_array_equal(again.summary["tension_max"].values, result.summary["tension_max"].values)
    with dask.config.set({"scheduler-address": "tcp://127.0.0.1:9"}):              # configured but gone
        gone = sweep(base, {"vessel.track[1].to_speed_kn": [8, 9]}, tmp_path / "c")
    assert "serial in a child process" in gone.engine
    with pytest.raises(KanatError, match="scheduler file .*missing.json does not exist"):
        sweep(base, {"vessel.track[1].to_speed_kn": [8]}, tmp_path / "d", scheduler=str(tmp_path / "missing.json"))


@pytest.mark.slow
def test_default_engine_goes_parallel_when_the_cluster_pays(base, tmp_path, monkeypatch):
    monkeypatch.setattr(execution, "CLUSTER_STARTUP_S", -1e9)   # it always pays, however short the cases run
    result = sweep(base, {"vessel.track[1].to_speed_kn": [8, 9, 10, 11]}, tmp_path / "study")
    assert "a local cluster of 2 worker processes (a case" in result.engine
    assert result.failed == 0 and result.ran == 4
    serial = sweep(base, {"vessel.track[1].to_speed_kn": [8, 9, 10, 11]}, tmp_path / "serial", scheduler="serial")
    np.testing.assert_allclose(result.summary["tension_max"].values, serial.summary["tension_max"].values,
                               rtol=1e-12)


@pytest.mark.slow
def test_second_study_on_the_same_directory_is_refused(base, tmp_path):
    script = ("import sys; from kanat.sweep import sweep; "
              "sweep(sys.argv[1], {'vessel.track[1].to_speed_kn': [7, 8, 9, 10, 11, 12]}, sys.argv[2], "
              "scheduler='serial')")
    proc = subprocess.Popen([sys.executable, "-c", script, str(base), str(tmp_path / "study")], **CTRL_C,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not (tmp_path / "study" / "study.json").exists():
            time.sleep(0.05)
        assert proc.poll() is None
        with pytest.raises(KanatError, match=rf"study is in use by another kanat run \(pid {proc.pid} on"):
            sweep(base, {"vessel.track[1].to_speed_kn": [7, 8, 9, 10, 11, 12]}, tmp_path / "study",
                  scheduler="serial")
    finally:
        proc.wait(timeout=300)
    assert proc.returncode == 0
    again = sweep(base, {"vessel.track[1].to_speed_kn": [7, 8, 9, 10, 11, 12]}, tmp_path / "study")
    assert again.skipped == 6 and again.ran == 0                     # the lock is gone with its run


def test_bad_study_outputs_are_refused(base, tmp_path):
    with pytest.raises(KanatError, match="is also an input"):
        sweep(base, {"vessel.track[1].to_speed_kn": [8]}, base)
    (tmp_path / "file").write_text("")
    with pytest.raises(KanatError, match="exists and is not a directory"):
        sweep(base, {"vessel.track[1].to_speed_kn": [8]}, tmp_path / "file")
    with pytest.raises(KanatError, match="does not exist. Create it first"):
        sweep(base, {"vessel.track[1].to_speed_kn": [8]}, tmp_path / "missing" / "study")


@pytest.mark.slow
def test_ctrl_c_stops_the_workers_and_records_no_false_failure(base, tmp_path):
    script = ("import sys; from kanat.sweep import sweep; "
              "sweep(sys.argv[1], {'vessel.track[1].to_speed_kn': [7, 8, 9, 10, 11, 12]}, sys.argv[2], workers=2)")
    proc = subprocess.Popen([sys.executable, "-c", script, str(base), str(tmp_path / "study")], **CTRL_C,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    records = tmp_path / "study" / "records"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not (records.exists() and list(records.glob("*.json"))):
        time.sleep(0.02)
    proc.send_signal(signal.SIGINT)                                      # as Ctrl-C in a terminal would
    _, err = proc.communicate(timeout=60)
    assert proc.returncode != 0 and "KeyboardInterrupt" in err
    done = [json.loads(p.read_text()) for p in records.glob("*.json")]
    assert done and all(r["status"] == "ok" for r in done) and len(done) < 6   # interrupted cases: not recorded
    again = sweep(base, {"vessel.track[1].to_speed_kn": [7, 8, 9, 10, 11, 12]}, tmp_path / "study")
    assert again.skipped == len(done) and again.failed == 0 and again.ran == 6 - len(done)
