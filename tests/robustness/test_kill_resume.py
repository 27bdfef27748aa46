"""kill -9 at random moments of a run (before, during, right after a checkpoint), then --resume:
the result equals an uninterrupted run's bit for bit, for the continuum and the lumped model.

The kill times are drawn (seeded) over the whole process's measured duration, so some land
before the first checkpoint (the resume then finds none and the run starts afresh), some while
a checkpoint or an output block is being written, some right after.
"""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from kanat.io.results import read_result
from kanat.io.stream import Checkpoint, part_path

from helpers import EXAMPLES, short_case

CASES = {
    "continuum": short_case(duration=400, segments=40, before=50).replace("dt: 1.0\n", "dt: 0.5\n"),
    "lumped": (EXAMPLES / "trawl_head_8s_1to2.yaml").read_text().replace("duration: 600", "duration: 40"),
}


def kanat(*args):
    return [sys.executable, "-m", "kanat.cli", *map(str, args)]


def killed_then_resumed(case, out, delay, every) -> None:
    proc = subprocess.Popen(kanat("run", case, "-o", out, "--checkpoint-every", every),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(delay)
    if proc.poll() is None:
        os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    resume = ["--resume"] if Checkpoint.path_for(out).exists() else []
    if not resume:
        part_path(out).unlink(missing_ok=True)
    done = subprocess.run(kanat("run", case, "-o", out, *resume), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr


def kills(model, count, seed):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.2, 0.95, count)


@pytest.mark.parametrize("model, count", [
    pytest.param("continuum", 2, id="2-kills-continuum"),
    pytest.param("lumped", 2, id="2-kills-lumped"),
    # six kills of the continuum run only: a lumped process is mostly its equilibrium (3 s of 3.5),
    # so more kills there land before the first checkpoint again, at 3.5 s a process
    pytest.param("continuum", 6, id="6-kills-continuum"),
])
@pytest.mark.slow
def test_killed_runs_resume_bit_for_bit(model, count, tmp_path):
    case = tmp_path / f"{model}.yaml"
    case.write_text(CASES[model])
    whole = tmp_path / "whole.nc"
    began = time.perf_counter()
    subprocess.run(kanat("run", case, "-o", whole), check=True, capture_output=True, timeout=600)
    duration = time.perf_counter() - began
    reference = read_result(whole)
    for k, fraction in enumerate(kills(model, count, seed=count)):
        out = tmp_path / f"killed{k}.nc"
        killed_then_resumed(case, out, fraction * duration, every=7)
        result = read_result(out)
        assert result.attrs["status"] == "ok" and not part_path(out).exists()
        assert not Checkpoint.path_for(out).exists()
        for name in ("time", "position", "velocity", "tension"):
            np.testing.assert_array_equal(result[name].values, reference[name].values, err_msg=name)
        if "event_time" in reference:
            np.testing.assert_array_equal(result["event_time"].values, reference["event_time"].values)
