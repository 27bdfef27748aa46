"""Parameter-study and report timings (issues 7 and 13).

1. The same 8-case study (speed_step_2d.yaml at 4 step speeds x 2 normal drag coefficients,
   100 segments, dt = 0.1 s, 600 s: 6000 steps a case), **whole process** as a user runs it
   (``kanat sweep ...``, imports, cluster start and shut-down included), interleaved
   serial / 2 workers / default engine, ``REPEATS`` rounds, median of each:

   * ``--scheduler serial``: one case after another in the ``kanat`` process;
   * ``--workers 2``: a local cluster of 2 worker processes started by the study
     (kanat's own, forked: ``kanat.sweep.processes``);
   * no option: the default engine's rule (``kanat.sweep.execution``);
   * for comparison, a Dask ``LocalCluster`` of 2 workers started by the study
     (``kanat.sweep.cluster.local_cluster``, fork-server workers, profiler off), from a
     ``python -c`` process that does what ``kanat sweep`` does.

   Target: the 2-worker study at least 1.7x faster than serial. The load average before
   each run is printed; other processes on the machine skew the ratio. For a shared
   machine the table also gives a projection from CPU times, which the load barely
   changes: the process tree's CPU time outside the cases (imports, planning, the
   summary, the engine) plus the busiest worker's case CPU time — what the wall time
   would be with the cores to itself (pessimistic: it counts the parent's work during
   the cases as if it held up a worker).
2. The HTML report of a synthetic 1000-node, 1000-step result (read + analyse + write);
   target: under 10 s and under 20 MB.

Run: ``python benchmarks/bench_sweep.py`` (after ``pip install -e .``); prints markdown rows.
"""
from __future__ import annotations

import json
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.io.results import write_result
from kanat.report.html_report import write_report

sys.path.insert(0, str(Path(__file__).resolve().parent))
from studies import kanat_command, timed_process  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
VARY = ["vessel.track[1].to_speed_kn=8,9,10,11", "line_types.towcable.drag_normal=1.2,1.5"]
ENGINES = {"serial": ["--scheduler", "serial"], "2 workers": ["--workers", "2"], "default": [], "Dask 2 workers": None}
DASK = ("import sys; from kanat.sweep import sweep; from kanat.sweep.cluster import local_cluster\n"
        "if __name__ == '__main__':\n"
        "    with local_cluster(2) as client:\n"
        "        sweep(sys.argv[1], dict(v.split('=', 1) for v in sys.argv[3:]), sys.argv[2], scheduler=client)")
REPEATS = 3


def base_case(folder: Path) -> Path:
    text = (EXAMPLES / "speed_step_2d.yaml").read_text()
    text = text.replace("dt: 1.0\n", "dt: 0.1\n").replace("speed_kn: 6, duration: 60", "speed_kn: 6, duration: 20")
    path = folder / "base.yaml"
    path.write_text(text)
    return path


def whole_study(base: Path, out: Path, options: list[str] | None) -> dict:
    """One study process: wall and CPU time (its children included), cases' own time, workers."""
    if options is None:
        command = [sys.executable, "-c", DASK, str(base), str(out), *VARY]
    else:
        command = kanat_command() + ["sweep", str(base), *sum((["--vary", v] for v in VARY), []), "-o", str(out),
                                     *options]
    timed = timed_process(command)
    records = [json.loads(p.read_text()) for p in (out / "records").glob("*.json")]
    assert len(records) == 8 and all(r["status"] == "ok" for r in records), [r.get("message") for r in records]
    cpu, cases = timed["cpu"], sum(r["cpu_time_s"] for r in records)
    per_worker = {}
    for r in records:
        per_worker[r["worker"]] = per_worker.get(r["worker"], 0.0) + r["cpu_time_s"]
    return {"wall": timed["wall"], "cpu": cpu, "busy": sum(r["wall_time_s"] for r in records), "load": timed["load"],
            "processes": len(per_worker), "cases_cpu": cases, "projected": cpu - cases + max(per_worker.values())}


def bench_study(folder: Path) -> None:
    base = base_case(folder)
    whole_study(base, folder / "warm-up", ENGINES["serial"])     # compiled kernels in the cache, files in memory
    runs = {name: [] for name in ENGINES}
    for k in range(REPEATS):                          # interleaved: serial, 2 workers, default, serial, ...
        for name, options in ENGINES.items():
            runs[name].append(whole_study(base, folder / f"{name.replace(' ', '-')}-{k}", options))
    serial = statistics.median(r["wall"] for r in runs["serial"])
    serial_projected = statistics.median(r["projected"] for r in runs["serial"])
    print("| 8-case study, whole process | wall (median) | all walls | vs serial | CPU: all / cases | processes "
          "| projected wall | vs serial | target (measured, projected) |\n|---|---|---|---|---|---|---|---|---|")
    for name, rows in runs.items():
        wall = statistics.median(r["wall"] for r in rows)
        walls = ", ".join(f"{r['wall']:.2f}" for r in rows)
        projected = statistics.median(r["projected"] for r in rows)
        verdict = ", ".join(("meets" if x >= 1.7 else "MISSES") for x in (serial / wall, serial_projected / projected))
        what = f"`kanat sweep ... {' '.join(ENGINES[name])}`" if ENGINES[name] is not None else "Python, Dask"
        print(f"| {what} ({name}) | {wall:.2f} s | {walls} | {serial / wall:.2f}x | "
              f"{statistics.median(r['cpu'] for r in rows):.1f} / {statistics.median(r['cases_cpu'] for r in rows):.1f} s"
              f" | {rows[0]['processes']} | {projected:.2f} s | {serial_projected / projected:.2f}x | "
              f"{verdict + ' >= 1.7x' if name == '2 workers' else ''} |")
    loads = [r["load"] for rows in runs.values() for r in rows]
    print(f"\nload average before the runs: {min(loads):.2f} to {max(loads):.2f}; best walls: "
          + ", ".join(f"{name} {min(r['wall'] for r in rows):.2f} s" for name, rows in runs.items()))


def synthetic_result(nodes: int = 1000, steps: int = 1000) -> xr.Dataset:
    """A towed-cable-like result: a 1000 m catenary swinging in the x-z plane, the vessel at 2 m/s."""
    t = np.arange(steps) * 0.5
    s = np.linspace(0.0, 1000.0, nodes)
    sway = 20.0 * np.sin(2 * np.pi * t / 30.0)[:, None] * (s / 1000.0)[None, :]
    position = np.zeros((steps, nodes, 3))
    position[:, :, 0] = 2.0 * t[:, None] - 0.9 * s[None, :]
    position[:, :, 1] = sway
    position[:, :, 2] = -0.3 * s[None, :] - 0.00005 * s[None, :] ** 2
    tension = 12e3 - 6.0 * s[None, :] + 800.0 * np.sin(2 * np.pi * t / 5.6)[:, None] * np.exp(-s / 400.0)[None, :]
    ds = xr.Dataset({"s": ("node", s), "cable": ("node", np.array(["tow"] * nodes, dtype=object)),
                     "position": (("time", "node", "xyz"), position),
                     "velocity": (("time", "node", "xyz"), np.gradient(position, t, axis=0)),
                     "tension": (("time", "node"), tension),
                     "body_position": (("time", "body", "xyz"), position[:, -1:, :]),
                     "vessel_position": (("time", "xyz"), position[:, 0, :]),
                     "vessel_heading": ("time", np.zeros(steps))},
                    coords={"time": t, "body": np.array(["sled"], dtype=object)},
                    attrs={"case_name": "synthetic-1000x1000", "model": "continuum", "scheme": "none",
                           "status": "ok", "wall_time_s": 0.0})
    return ds


def bench_report(folder: Path) -> None:
    source = write_result(synthetic_result(), folder / "big.nc")
    start = time.perf_counter()
    page = write_report(source, folder / "big.html")
    seconds = time.perf_counter() - start
    size = page.stat().st_size / 1e6
    verdict = ("meets" if seconds < 10 else "MISSES") + " < 10 s, " + ("meets" if size < 20 else "MISSES") + " < 20 MB"
    print(f"| report of a 1000-node, 1000-step result | {seconds:.2f} s | {size:.1f} MB | {verdict} |")


def main() -> None:
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"load average before: {os.getloadavg()[0]:.2f}\n")
    with tempfile.TemporaryDirectory() as tmp:
        bench_study(Path(tmp))
        print("\n| case | time | size | target |\n|---|---|---|---|")
        bench_report(Path(tmp))
    print(f"\nload average after: {os.getloadavg()[0]:.2f} (other processes on the machine skew the speed-up)")


if __name__ == "__main__":
    main()
