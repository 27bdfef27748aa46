"""A disk that fills up during a run: one clear sentence, the partial result and the checkpoint
intact, and ``--resume`` once space is freed gives the uninterrupted run's result bit for bit.

The audit's reproducer ended in 66 h5py tracebacks, a SIGSEGV and a 0-byte checkpoint. Here the
disk is a small tmpfs (mounted by the test; skipped where mounting is not permitted), and, in
process, a disk whose free space runs out after a few blocks.
"""
import os
import shutil
import subprocess

import numpy as np
import pytest

import kanat
from kanat import api
from kanat.errors import OutputWriteError
from kanat.io import space
from kanat.io.results import read_result
from kanat.io.stream import Checkpoint, part_path

from helpers import kanat_command, short_case

CASE = short_case(duration=1500, segments=40, before=50).replace("dt: 1.0\n", "dt: 0.5\n").replace(
    "output_dt: 1.0", "output_dt: 0.5")                  # 3001 outputs of 41 nodes: 7 MB


def same_result(path, reference) -> None:
    result = read_result(path)
    assert result.attrs["status"] == "ok"
    for name in ("time", "position", "velocity", "tension"):
        np.testing.assert_array_equal(result[name].values, reference[name].values, err_msg=name)


def test_space_running_out_stops_cleanly_and_resume_is_bit_identical(tmp_path, monkeypatch):
    case = kanat.load_case(CASE.replace("duration: 1500", "duration: 200"))
    reference = api.run(case).dataset
    out = tmp_path / "out.nc"
    real = space._free_bytes
    calls = {"n": 0}

    def running_out(path):                              # room for the file and 6 blocks or checkpoints
        calls["n"] += 1
        return real(path) if calls["n"] <= 7 else 0.0
    monkeypatch.setattr(space, "_free_bytes", running_out)
    with pytest.raises(OutputWriteError) as stopped:
        api.run(case, output=out, checkpoint_every=50)
    message = str(stopped.value)
    assert message.startswith("the run stopped at t = ") and "because the disk holding" in message
    assert message.endswith("free some space and continue with --resume") and "\n" not in message
    kept = read_result(part_path(out))
    assert kept.attrs["status"] == "running" and f"keeps the outputs up to t = {float(kept.time[-1]):.6g} s" in message
    assert "out.nc.ckpt.npz the state at t = " in message and Checkpoint.path_for(out).stat().st_size > 0
    monkeypatch.setattr(space, "_free_bytes", real)
    api.run(case, output=out, resume=True)
    same_result(out, reference)


@pytest.fixture
def small_disk(tmp_path):
    """A 3 MiB tmpfs at ``tmp_path/disk`` (root only); grown to 20 MiB by ``grow()``."""
    disk = tmp_path / "disk"
    disk.mkdir()
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=3m", "tmpfs", str(disk)],
                             capture_output=True, text=True)
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.strip()}")

    def grow():
        subprocess.run(["mount", "-o", "remount,size=20m", str(disk)], check=True)
    try:
        yield disk, grow
    finally:
        subprocess.run(["umount", "-l", str(disk)], capture_output=True)


@pytest.mark.slow
def test_a_full_tmpfs_ends_the_run_in_one_sentence_and_resume_is_bit_identical(tmp_path, small_disk):
    disk, grow = small_disk
    case = tmp_path / "case.yaml"
    case.write_text(CASE)
    whole = tmp_path / "whole.nc"
    subprocess.run(kanat_command("run", case, "-o", whole), check=True, capture_output=True, timeout=600)
    out = disk / "out.nc"
    full = subprocess.run(kanat_command("run", case, "-o", out, "--checkpoint-every", 100),
                          capture_output=True, text=True, timeout=600)
    text = full.stdout + full.stderr
    assert full.returncode == 1, text
    assert "Traceback" not in text and "h5py" not in text
    errors = [line for line in text.splitlines() if "error" in line]
    assert len(errors) == 1 and "because the disk holding" in errors[0] and "continue with --resume" in errors[0]
    assert read_result(part_path(out)).attrs["status"] == "running"
    assert Checkpoint.path_for(out).stat().st_size > 0
    assert shutil.disk_usage(disk).free > 0
    grow()
    done = subprocess.run(kanat_command("run", case, "-o", out, "--resume"), capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    same_result(out, read_result(whole))


def test_a_steady_result_on_a_full_disk_is_not_written_and_says_so(tmp_path, monkeypatch):
    """Statics write their result whole or not at all (an HDF5 write that fails crashed the process)."""
    from helpers import EXAMPLES

    monkeypatch.setattr(space, "_free_bytes", lambda path: 1000.0)
    out = tmp_path / "steady.nc"
    with pytest.raises(OutputWriteError, match=r"steady.nc was not written: the disk holding .* is full "
                                               r"\(0.0 MiB free, 1.0 MiB needed for the result steady.nc\); "
                                               r"free some space and solve again"):
        api.run(kanat.load_case(EXAMPLES / "towed_body.yaml"), output=out, model="statics")
    assert list(tmp_path.iterdir()) == []
