"""Cost per time step against the number of segments, 50 to 1600: planar and spatial continuum,
lumped (its default scheme and RK4), with the fitted exponent and the memory at 1600 segments.

Each (model, segments) runs in its own process (``kanat.api.run``, result in memory, one
output at the end so that stepping dominates): a short run first loads the compiled kernels,
then the measured run; cost per step = ``solver_time_s / steps`` (the time loop only), best of
``--repeats``. The exponent is the least-squares slope of log(cost) against log(segments);
1.0 is linear. Memory: the process's peak resident set (``ru_maxrss``), and its growth over the
50-segment run (what the model itself holds). Cases: ``examples/speed_step_2d.yaml`` (1000 m,
the 6 -> 10 kn step inside the window), ``examples/turn_360_3d.yaml`` (into the turn), and the
500 m towed cable of ``benchmarks/bench_lumped_towed.py`` (accelerating from rest).

Run: ``python benchmarks/bench_scaling.py [--repeats 3] [--segments 50 100 200 400 800 1600]``.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SEGMENTS = (50, 100, 200, 400, 800, 1600)
CASES = {        # label: (how to build the case in the child, simulated seconds measured)
    "continuum 2-D (speed step)": ("example", "speed_step_2d.yaml", {"simulation.duration": 80.0,
                                                                       "simulation.output_dt": 80.0}),
    "continuum 3-D (turn)": ("example", "turn_360_3d.yaml", {"simulation.duration": 120.0,
                                                              "simulation.output_dt": 120.0}),
    "lumped, default scheme (towed)": ("towed", None, {"simulation.duration": 20.0, "simulation.output_dt": 20.0}),
    "lumped, rk4 (towed)": ("towed", "rk4", {"simulation.duration": 0.5, "simulation.output_dt": 0.5}),
}

CHILD = r"""
import json, resource, sys
sys.path.insert(0, {here!r})
from kanat.api import load_case, run
kind, what, changes, segments = {kind!r}, {what!r}, {changes!r}, {segments!r}
if kind == "example":
    case = load_case({examples!r} + "/" + what)
else:
    import bench_lumped_towed as towed
    case = load_case(towed.case_dict(scheme=what))
case = case.replace({{"cables[0].segments": segments, **changes}})
short = case.replace({{"simulation.duration": case.simulation.output_interval}})
run(short)                                                  # load (or compile) the kernels
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
out = run(case)
s = out.summary
print(json.dumps(dict(status=out.status, steps=s.steps, solver=s.solver_time_s, scheme=s.scheme, dt=s.dt,
                      iterations=s.newton_iterations_mean,
                      rss_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, rss_before_mb=before / 1024)))
"""


def measure(kind, what, changes, segments) -> dict:
    code = CHILD.format(here=str(HERE), kind=kind, what=what, changes=changes, segments=segments,
                        examples=str(HERE.parent / "examples"))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=3600)
    if done.returncode != 0:
        raise RuntimeError(f"{kind} {what} {segments}: {done.stderr[-3000:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def exponent(segments, cost) -> float:
    return float(np.polyfit(np.log(segments), np.log(cost), 1)[0])


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--segments", type=int, nargs="+", default=list(SEGMENTS))
    parser.add_argument("--cases", nargs="+", default=list(CASES), choices=list(CASES))
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"load average before: {os.getloadavg()[0]:.2f}\n")
    head = " / ".join(str(n) for n in args.segments)
    print(f"| case | scheme, dt (at {args.segments[0]} segments) | cost per step [ms] at {head} segments | Newton iterations per step | "
          f"exponent | peak RSS at {args.segments[-1]} [MiB] | model memory at {args.segments[-1]} [MiB] |")
    print("|---|---|---|---|---|---|---|")
    for label in args.cases:
        kind, what, changes = CASES[label]
        rows = []
        for n in args.segments:
            runs = [measure(kind, what, changes, n) for _ in range(args.repeats)]
            bad = [r for r in runs if r["status"] != "ok"]
            if bad:
                raise RuntimeError(f"{label} at {n} segments: {bad[0]['status']}")
            best = min(runs, key=lambda r: r["solver"])
            rows.append(dict(best, cost=best["solver"] / best["steps"]))
        costs = [r["cost"] for r in rows]
        iterations = ", ".join(f"{r['iterations']:.2f}" for r in rows) if rows[0]["iterations"] else "–"
        grown = rows[-1]["rss_mb"] - rows[0]["rss_mb"]
        print(f"| {label} | {rows[0]['scheme']}, {rows[0]['dt']:.3g} s | "
              f"{' / '.join(f'{1e3 * c:.3g}' for c in costs)} | {iterations} | "
              f"{exponent(args.segments, costs):.2f} | {rows[-1]['rss_mb']:.0f} | {grown:+.0f} |", flush=True)
    print(f"\nload average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
