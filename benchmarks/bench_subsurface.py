"""A 3-section subsurface mooring with an inline float, 300 nodes, 1200 s at dt = 0.5 s (issue 12).

Anchor - 10 m chain - 300 m wire - glass-ball float - 150 m nylon - top buoy in 500 m of water, in a
sheared current and regular waves (4 m, 10 s), so the line moves all the time. Measured:

1. solver time (the time loop, compiling excluded: the run's own ``solver_time_s``), its cost per
   node-step and Newton iterations per step, against WHOI Cable's recorded figure per node-step
   (docs/peers.md: 0.19 s CPU stepping for 100 nodes x 600 steps, 2-D, built with -O2 = 3.17 us);
2. the whole process (``kanat run CASE -o OUT.nc``: start-up, case, statics, steady state, steps,
   file), wall and CPU, with a warm numba cache; and once with a cold cache (compiling);
3. the same mooring in a current turning with depth (3-D).

Run: ``python benchmarks/bench_subsurface.py`` (prints a markdown table for RESULTS.md).
"""
from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import xarray as xr

WHOI_US_PER_NODE_STEP = 0.19 / (100 * 600) * 1e6
CASE = """
name: bench-subsurface-3-sections
model: continuum
environment:
  water_density: 1025
  depth: 500
  seabed: {{stiffness: 3.0e6, damping: 3.0e5}}
  current:
    profile:
      - [0, 0.6, {y0}, 0]
      - [-100, 0.45, {y1}, 0]
      - [-300, 0.2, 0.0, 0]
      - [-500, 0.05, 0.0, 0]
  waves: {{type: regular, height: 4.0, period: 10.0, heading_deg: 0}}
line_types:
  chain: {{diameter: 0.04, mass: 9.0, weight_in_water: 77.0, axial_stiffness: 8.0e7, added_mass: 1.3,
          drag_normal: 2.4, drag_tangential: 0.4}}
  wire: {{diameter: 0.0127, mass: 0.45, weight_in_water: 3.5, axial_stiffness: 1.0e7, added_mass: 0.13,
         drag_normal: 1.5, drag_tangential: 0.01}}
  nylon: {{diameter: 0.019, mass: 0.23, weight_in_water: 0.3, axial_stiffness: 1.5e6, added_mass: 0.29,
          drag_normal: 1.4, drag_tangential: 0.01}}
bodies:
  glass_balls: {{mass: 150, net_buoyancy: 1500, drag_area: 0.6, added_mass: 150}}
  top_buoy: {{mass: 600, net_buoyancy: 6000, drag_area: 0.55, added_mass: 900}}
cables:
  - name: mooring
    from: "anchor:[0, 0, -500]"
    to: top_buoy
    sections:
      - {{line_type: chain, length: 10, segments: 10}}
      - {{line_type: wire, length: 300, segments: 180}}
      - {{line_type: nylon, length: 150, segments: 108}}
    attachments:
      - {{body: glass_balls, s: 310}}
simulation: {{scheme: generalized-alpha, duration: 1200, dt: 0.5, output_dt: 5, dimensions: {dims}}}
"""


def run(case_path: Path, cache: Path) -> dict:
    """``kanat run`` in a fresh process: wall, CPU (children's user + system) and peak memory, and the
    result's own timings."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    with tempfile.TemporaryDirectory() as out:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "kanat.cli", "run", str(case_path), "-o", f"{out}/r.nc"],
                       check=True, env=env, capture_output=True)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        with xr.open_dataset(f"{out}/r.nc") as ds:
            attrs = dict(ds.attrs)
            nodes = ds.sizes["node"]
    return {"wall": wall, "cpu": after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime,
            "rss_mib": after.ru_maxrss / 1024, "nodes": nodes, **attrs}


def main():
    rows = []
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        for label, dims, y0, y1 in (("2-D, x current", 2, 0.0, 0.0), ("3-D, current turning with depth", 3, 0.3, 0.2)):
            path = work / f"case{dims}.yaml"
            path.write_text(CASE.format(dims=dims, y0=y0, y1=y1))
            cache = work / f"cache{dims}"
            cold = run(path, cache)
            warm = [run(path, cache) for _ in range(3)]
            best = min(warm, key=lambda r: r["solver_time_s"])
            steps = int(best["steps"])
            per = best["solver_time_s"] / (best["nodes"] * steps) * 1e6
            rows.append((label, best, cold, steps, per))
    print(f"| case | nodes x steps | solver [s] | per node-step [us] | WHOI Cable 2-D [us] | Newton / step "
          "| whole process warm: wall, CPU [s] | peak RSS [MiB] | cold cache: wall, compiling [s] | status |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for label, best, cold, steps, per in rows:
        print(f"| {label} | {best['nodes']} x {steps} | {best['solver_time_s']:.2f} | {per:.2f} | "
              f"{WHOI_US_PER_NODE_STEP:.2f} | {float(best['newton_iterations_mean']):.2f} | "
              f"{best['wall']:.2f}, {best['cpu']:.2f} | {best['rss_mib']:.0f} | {cold['wall']:.2f}, "
              f"{float(cold['compile_time_s']):.2f} | {best['status']} |")


if __name__ == "__main__":
    main()
