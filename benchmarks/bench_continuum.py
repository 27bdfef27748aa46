"""Continuum-model timings (issue targets): solver time on one core, median of repeats.

1. 2-D: 1000 m cable, 100 segments, towed body, speed step 6 -> 10 kn, 600 s at dt = 1 s
   (target < 0.3 s; the established C code of the field: 0.37 s on this machine).
2. 3-D: the same cable through a 360 deg turn of radius 294.5 m at 6 kn, 1200 s at dt = 1 s
   (target < 2 s; the C code: 11.9 s).
3. Cost per step at 1000 segments vs 100 (target <= 12x), planar and spatial.
4. numba's disk cache: a second `kanat run` in a fresh process does not compile again.

Solver time = the time loop (steps and positions), without reading the case, the initial
statics or writing results; the whole-command times are printed too.
"""
from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from kanat.continuum.models import model_for
from kanat.continuum.schemes import GeneralizedAlpha
from kanat.io import parse_case

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
REPEATS = 3


def solver_time(case, steps=None):
    """Median wall time of the time loop over REPEATS runs [s], and the mean Newton iterations."""
    sim = case.simulation
    steps = steps or int(round(sim.duration / sim.dt))
    scheme = GeneralizedAlpha(sim.lambda_inf)
    times = []
    for _ in range(REPEATS):
        model = model_for(case)
        state = model.initial()
        iterations = 0
        start = time.perf_counter()
        for _ in range(steps):
            state, spent = scheme.step(model, state, sim.dt)
            iterations += spent
        times.append(time.perf_counter() - start)
    return statistics.median(times), iterations / steps


def command_time(case_path, cache_dir):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache_dir))
    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "kanat.cli", "run", str(case_path), "-o", f"{out}/r.nc"],
                       check=True, env=env, capture_output=True)
        return time.perf_counter() - start


def main():
    step_2d = parse_case((EXAMPLES / "speed_step_2d.yaml").read_text())
    turn_3d = parse_case((EXAMPLES / "turn_360_3d.yaml").read_text())
    print("| case | solver time [s] | Newton iterations / step | target |\n|---|---|---|---|")
    seconds, its = solver_time(step_2d)
    print(f"| 2-D speed step 6 -> 10 kn, 100 segments, 600 steps | {seconds:.3f} | {its:.2f} | < 0.3 s (C: 0.37 s) |")
    seconds, its = solver_time(turn_3d)
    print(f"| 3-D 360 deg turn r 294.5 m at 6 kn, 100 segments, 1200 steps | {seconds:.3f} | {its:.2f} "
          f"| < 2 s (C: 11.9 s) |")
    for name, case in (("2-D speed step", step_2d), ("3-D turn", turn_3d)):
        per_step = []
        for segments in (100, 1000):
            variant = parse_case((EXAMPLES / ("speed_step_2d.yaml" if "2-D" in name else "turn_360_3d.yaml"))
                                 .read_text().replace("segments: 100", f"segments: {segments}"))
            seconds, _ = solver_time(variant, steps=100)
            per_step.append(seconds / 100)
        print(f"| {name}: cost per step, 1000 vs 100 segments | {per_step[1] * 1e3:.2f} vs {per_step[0] * 1e3:.2f} ms "
              f"| ratio {per_step[1] / per_step[0]:.1f} | <= 12 |")
    with tempfile.TemporaryDirectory() as cache:
        first = command_time(EXAMPLES / "speed_step_2d.yaml", cache)
        second = command_time(EXAMPLES / "speed_step_2d.yaml", cache)
    print(f"| `kanat run speed_step_2d.yaml`, fresh numba cache then cached | {first:.1f} then {second:.1f} | | "
          "second run does not compile |")


if __name__ == "__main__":
    main()
