"""Streaming results and checkpoints: a killed run's file is readable; resume truncates exactly."""
import numpy as np
import pytest
import xarray as xr

from kanat.errors import KanatError
from kanat.io.results import read_result
from kanat.io.stream import Checkpoint, ResultStream


def static():
    return xr.Dataset({"s": ("node", np.arange(4.0)), "cable": ("node", np.array(["a"] * 4, dtype=object))},
                      coords={"xyz": ["x", "y", "z"]}, attrs={"case_name": "t", "status": "running"})


TIME_VARS = {"tension": (("node",), "N"), "position": (("node", "xyz"), "m")}


def test_stream_appends_and_unclosed_file_is_readable(tmp_path):
    path = tmp_path / "r.nc"
    stream = ResultStream(path, static(), TIME_VARS)
    for k in range(3):
        stream.append(0.5 * k, tension=np.full(4, k), position=np.full((4, 3), k))
    stream.flush()
    ds = read_result(path)                                  # readable while the run is alive
    assert ds.sizes["time"] == 3 and ds.attrs["status"] == "running"
    stream.close("ok", wall_time_s=1.5)
    ds = read_result(path)
    np.testing.assert_array_equal(ds["time"].values, [0.0, 0.5, 1.0])
    np.testing.assert_array_equal(ds["tension"].values[:, 0], [0, 1, 2])
    assert ds["tension"].attrs["units"] == "N" and ds["position"].dims == ("time", "node", "xyz")
    assert ds.attrs["status"] == "ok" and ds.attrs["wall_time_s"] == 1.5


def test_resume_truncates_to_the_checkpoint_and_continues(tmp_path):
    path = tmp_path / "r.nc"
    stream = ResultStream(path, static(), TIME_VARS)
    for k in range(5):
        stream.append(k, tension=np.full(4, k), position=np.zeros((4, 3)))
        if k == 2:
            stream.flush()
            Checkpoint(float(k), 3, "abc", {"y": np.arange(3.0)}, {"steps": 20}).save(path)
    stream.flush()
    stream._file.close()                                    # killed: never closed properly
    ckpt = Checkpoint.load(path, "abc")
    assert ckpt.time == 2.0 and ckpt.outputs == 3 and ckpt.info == {"steps": 20}
    np.testing.assert_array_equal(ckpt.state["y"], [0.0, 1.0, 2.0])
    stream = ResultStream(path, static(), TIME_VARS, resume_at=ckpt.outputs)
    stream.append(3.0, tension=np.full(4, 30), position=np.zeros((4, 3)))
    stream.close()
    np.testing.assert_array_equal(read_result(path)["tension"].values[:, 0], [0, 1, 2, 30])


def test_checkpoint_refuses_another_case_and_a_missing_file(tmp_path):
    path = tmp_path / "r.nc"
    with pytest.raises(KanatError, match="no checkpoint"):
        Checkpoint.load(path, "abc")
    Checkpoint(0.0, 1, "abc", {}, {}).save(path)
    with pytest.raises(KanatError, match="different case"):
        Checkpoint.load(path, "xyz")


def test_a_finished_run_removes_its_checkpoint_a_failed_one_keeps_it(tmp_path):
    for status, kept in (("ok", False), ("Newton did not converge", True)):
        path = tmp_path / f"{kept}.nc"
        stream = ResultStream(path, static(), TIME_VARS)
        stream.append(0.0, tension=np.zeros(4), position=np.zeros((4, 3)))
        stream.flush()
        Checkpoint(0.0, 1, "abc", {}, {}).save(path)
        stream.close(status)
        assert Checkpoint.path_for(path).exists() == kept
