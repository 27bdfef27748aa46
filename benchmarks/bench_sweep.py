"""Parameter-study and report timings (issue 7).

1. The same 8-case study (speed_step_2d.yaml at 4 step speeds x 2 normal drag coefficients,
   100 segments, dt = 0.1 s, 600 s: 6000 steps a case) serially and on a
   2-worker Dask ``LocalCluster``; target: at least 1.7x faster on 2 workers. Reported
   twice: on a cluster already running (workers started and kanat imported, as on a real
   cluster) and including the cluster's start (``kanat sweep`` as a user runs it). Each
   timing is the best of ``REPEATS`` (the machine may be shared: the load average is printed).
2. The HTML report of a synthetic 1000-node, 1000-step result (read + analyse + write);
   target: under 10 s and under 20 MB.

Run: ``python benchmarks/bench_sweep.py`` (after ``pip install -e .``); prints markdown rows.
"""
from __future__ import annotations

import json
import platform
import tempfile
import time
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.io.results import write_result
from kanat.report.html_report import write_report
from kanat.sweep import sweep

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
VARY = {"vessel.track[1].to_speed_kn": [8, 9, 10, 11], "line_types.towcable.drag_normal": [1.2, 1.5]}
REPEATS = 2


def base_case(folder: Path) -> Path:
    text = (EXAMPLES / "speed_step_2d.yaml").read_text()
    text = text.replace("dt: 1.0\n", "dt: 0.1\n").replace("speed_kn: 6, duration: 60", "speed_kn: 6, duration: 20")
    path = folder / "base.yaml"
    path.write_text(text)
    return path


def timed_study(base: Path, out: Path, scheduler=None, workers=None) -> tuple[float, float]:
    """Best wall time of REPEATS fresh runs of the study [s], and that run's concurrency.

    Concurrency is the sum of the cases' own wall times over the study's wall time: how many
    cases the engine kept running at once (2 at best on 2 workers), whatever else loads the
    machine.
    """
    best, concurrency = float("inf"), 0.0
    for k in range(REPEATS):
        start = time.perf_counter()
        result = sweep(base, VARY, out / str(k), scheduler=scheduler, workers=workers)
        seconds = time.perf_counter() - start
        assert result.failed == 0 and result.ran == 8, result.summary["message"].values
        if seconds < best:
            busy = sum(json.loads(p.read_text())["wall_time_s"] for p in (out / str(k) / "records").glob("*.json"))
            best, concurrency = seconds, busy / seconds
    return best, concurrency


def warm_client(workers: int):
    from dask.distributed import Client

    from kanat.sweep.engine import local_cluster

    cluster = local_cluster(workers)
    client = Client(cluster)
    client.run(lambda: __import__("kanat.sweep.engine") and __import__("kanat.api") and None)
    return cluster, client


def bench_study(folder: Path) -> None:
    base = base_case(folder)
    serial, _ = timed_study(base, folder / "serial", scheduler="serial")
    cluster, client = warm_client(2)
    try:
        warm = timed_study(base, folder / "warm", scheduler=client)
    finally:
        client.close()
        cluster.close()
    cold = timed_study(base, folder / "cold", workers=2)
    for label, (seconds, concurrency) in (("2 workers, cluster running", warm),
                                          ("2 workers, cluster started by the study", cold)):
        speedup = serial / seconds
        verdict = ("meets" if speedup >= 1.7 else "MISSES") + " >= 1.7x"
        print(f"| 8-case study, {label} | {seconds:.2f} s | serial {serial:.2f} s | {speedup:.2f}x "
              f"(concurrency {concurrency:.2f}) | {verdict} |")


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
    import os

    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"load average before: {os.getloadavg()[0]:.2f}\n")
    print("| case | time | reference | ratio / size | target |\n|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        bench_study(Path(tmp))
        bench_report(Path(tmp))
    print(f"\nload average after: {os.getloadavg()[0]:.2f} (other processes on the machine skew the speed-up)")


if __name__ == "__main__":
    main()
