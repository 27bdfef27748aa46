"""Streaming results and checkpoints: a killed run's file is readable; resume truncates exactly;
the file and the in-memory recorder hold the same dataset."""
import numpy as np
import pytest
import xarray as xr

from kanat.dynamics import Point, Recorder, Steps
from kanat.errors import KanatError
from kanat.io.results import read_result
from kanat.io.schema import Layout
from kanat.io.stream import Checkpoint, ResultStream, part_path


def layout():
    return Layout({"s": (("node",), np.arange(4.0)), "cable": (("node",), ["a"] * 4)},
                  {"xyz": ("x", "y", "z"), "body": []}, ("tension", "position"), {"case_name": "t"})


def point(k, t, value):
    return Point(k, t, {"tension": np.full(4, float(value)), "position": np.full((4, 3), float(value))}, None,
                 Steps(), None)


def test_stream_appends_and_unclosed_file_is_readable(tmp_path):
    path = tmp_path / "r.nc"
    stream = ResultStream(path)
    stream.start(layout())
    for k in range(3):
        stream.record(point(k, 0.5 * k, k))
    stream.flush()
    ds = read_result(part_path(path))                       # readable while the run is alive
    assert ds.sizes["time"] == 3 and ds.attrs["status"] == "running" and not path.exists()
    stream.finish("ok", {}, {"wall_time_s": 1.5})
    ds = read_result(path)
    assert not part_path(path).exists()
    np.testing.assert_array_equal(ds["time"].values, [0.0, 0.5, 1.0])
    np.testing.assert_array_equal(ds["tension"].values[:, 0], [0, 1, 2])
    assert ds["tension"].attrs["units"] == "N" and ds["position"].dims == ("time", "node", "xyz")
    assert "s" in ds.coords and "cable" in ds.coords and list(ds.xyz.values) == ["x", "y", "z"]
    assert ds.attrs["status"] == "ok" and ds.attrs["wall_time_s"] == 1.5


def test_the_recorder_holds_what_the_file_holds(tmp_path):
    path, recorder, stream = tmp_path / "r.nc", Recorder(), ResultStream(tmp_path / "r.nc")
    for observer in (recorder, stream):
        observer.start(layout())
        for k in range(4):
            observer.record(point(k, 0.25 * k, 10 * k))
        observer.finish("ok", {"event_time": (("event",), np.array([0.3]))}, {"steps": 7})
    xr.testing.assert_identical(recorder.dataset(), read_result(path))


def test_resume_truncates_to_the_checkpoint_and_continues(tmp_path):
    path = tmp_path / "r.nc"
    stream = ResultStream(path)
    stream.start(layout())
    for k in range(5):
        stream.record(point(k, k, k))
        if k == 2:
            stream.flush()
            Checkpoint(float(k), 3, "abc", "rk4()", {"y": np.arange(3.0)}, {"steps": 20}).save(path)
    stream.flush()
    stream.abandon()                                        # killed: never closed properly
    ckpt = Checkpoint.load(path, "abc", "rk4()")
    assert ckpt.time == 2.0 and ckpt.outputs == 3 and ckpt.info == {"steps": 20}
    np.testing.assert_array_equal(ckpt.state["y"], [0.0, 1.0, 2.0])
    stream = ResultStream(path)
    stream.start(layout(), resume_at=ckpt.outputs)
    stream.record(point(3, 3.0, 30))
    stream.finish("ok", {}, {})
    np.testing.assert_array_equal(read_result(path)["tension"].values[:, 0], [0, 1, 2, 30])


def test_a_kill_loses_only_the_unflushed_outputs(tmp_path):
    path = tmp_path / "r.nc"
    stream = ResultStream(path)
    stream.start(layout())
    stream.record(point(0, 0.0, 0))
    stream.flush()
    stream.record(point(1, 1.0, 1))                         # buffered, not yet written
    stream.abandon()
    ds = read_result(part_path(path))
    assert ds.sizes["time"] == 1 and ds.attrs["status"] == "running"


def test_checkpoint_refuses_another_case_another_scheme_and_a_missing_file(tmp_path):
    path = tmp_path / "r.nc"
    with pytest.raises(KanatError, match="no checkpoint"):
        Checkpoint.load(path, "abc", "rk4()")
    Checkpoint(0.0, 1, "abc", "rk4()", {}, {}).save(path)
    with pytest.raises(KanatError, match="different case"):
        Checkpoint.load(path, "xyz", "rk4()")
    with pytest.raises(KanatError, match="written by scheme rk4"):
        Checkpoint.load(path, "abc", "abm4()")


def test_a_finished_run_removes_its_checkpoint_a_failed_one_keeps_it(tmp_path):
    for status, kept in (("ok", False), ("failed: Newton did not converge", True)):
        path = tmp_path / f"{kept}.nc"
        stream = ResultStream(path)
        stream.start(layout())
        stream.record(point(0, 0.0, 0))
        stream.flush()
        Checkpoint(0.0, 1, "abc", "rk4()", {}, {}).save(path)
        stream.finish(status, {}, {})
        assert Checkpoint.path_for(path).exists() == kept and read_result(path).attrs["status"] == status
