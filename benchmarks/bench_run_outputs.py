"""The run loop's work outside the steps, CPU seconds, two source trees side by side.

For MoorDyn's WD0050 chain with its fairlead driven (``bench_wd0050_moordyn.kanat_case``, an output
every 0.1 s): each tree runs in processes of its own, interleaved, with ``PYTHONPATH`` set to it:

* the run (``kanat.dynamics.run`` with the result file) after a short run that loads the kernels:
  ``time.process_time`` of the whole run, and its ``solver_time_s``;
* one output of the lumped model (``LumpedModel.outputs`` at a new time each call) and its checks
  (``LumpedModel.check``): best of 5 x 300 calls.

Run: ``python benchmarks/bench_run_outputs.py OLD_SRC NEW_SRC [--repeats 3] [--duration 200]``; each
tree's numba cache must be warm (run a case with it once: numba keys its cache by the source path).
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent

CHILD = """
import sys, tempfile, time, timeit, warnings
import numpy as np
warnings.simplefilter("ignore")
from kanat import dynamics
from kanat.io import load_case
from kanat.io.stream import ResultStream
from kanat.lumped.adapter import LumpedModel
case = load_case(sys.argv[1])
short = case.replace({"simulation.duration": 1.0})
dynamics.run(lambda: LumpedModel(short), [ResultStream(tempfile.mktemp(suffix=".nc"))])
start = time.process_time()
summary = dynamics.run(lambda: LumpedModel(case), [ResultStream(tempfile.mktemp(suffix=".nc"))])
run_cpu = time.process_time() - start
model = LumpedModel(short)
state, _ = model.advance(model.initial(), model.output_interval)
values = model.outputs(state)
times = iter(np.arange(1e7) * 0.1)
def output():
    object.__setattr__(state.scheme, "t", float(next(times)))
    return model.outputs(state)
per = [min(timeit.repeat(f, number=300, repeat=5, timer=time.process_time)) / 300
       for f in (output, lambda: model.check(state, values))]
print(run_cpu, summary.solver_time_s, *per)
"""


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--duration", type=float, default=200.0)
    args = parser.parse_args()
    sys.path[:0] = [args.new, str(HERE)]             # the case written by the new tree's kanat
    from bench_wd0050_moordyn import kanat_case

    folder = Path(tempfile.mkdtemp())
    case = kanat_case(folder, "default", args.duration)
    rows = {"old": [], "new": []}
    for _ in range(args.repeats):
        for name in ("old", "new"):
            env = dict(os.environ, PYTHONPATH=getattr(args, name))
            done = subprocess.run([sys.executable, "-c", CHILD, str(case)], env=env, capture_output=True, text=True)
            if done.returncode:
                raise SystemExit(f"{name}: {done.stderr.strip().splitlines()[-1]}")
            rows[name].append([float(v) for v in done.stdout.split()[-4:]])
    print(f"load average {os.getloadavg()[0]:.1f}")
    print("| tree | run CPU [s] | solver [s] | one output [us] | its checks [us] |\n|---|---|---|---|---|")
    for name, values in rows.items():
        med = np.median(np.array(values), axis=0)
        print(f"| {name} | {med[0]:.2f} | {med[1]:.2f} | {med[2] * 1e6:.0f} | {med[3] * 1e6:.0f} |")


if __name__ == "__main__":
    main()
