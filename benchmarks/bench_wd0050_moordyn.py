"""MoorDyn's WD0050 chain with its fairlead driven: kanat's default scheme beside MoorDyn-C (PyPI
``moordyn``, the ``peers`` extra), whole processes, on the same MoorDyn input file.

The file is ``tests/data/moordyn/wd0050_chain.dat`` (MoorDyn's ``tests/Mooring/WD0050_Chain.txt``:
410 m of chain, 82 segments, from an anchor 400 m away in 50 m of water to a fairlead at the
surface; seabed ``kBot = 1e5``, ``cBot = 1e4``, friction 0.5). The fairlead moves surge
``-4 cos(2 pi t / 12)`` m and heave ``-cos(2 pi t / 9)`` m (kanat's ``vessel.motion`` with
``phase_deg: -90``; MoorDyn's coupled point driven with the same positions and the mean velocity
of every 0.05 s coupling step).

Each configuration runs as its own process (``kanat run case.yaml -o out.nc``; a Python process
running MoorDyn on the file), interleaved, ``--repeats`` times; the table gives medians of the
whole process's wall time, of its CPU time (user + system, the child's own: on a machine shared with
other work the wall time grows with the load, the CPU time much less) and of the stepping alone
(kanat: ``solver_time_s``; MoorDyn: its ``Step`` calls); "vs best MoorDyn" compares both.
``--kanat-schemes default`` leaves out kanat's ``rk4`` (30 s a run). Accuracy: the fairlead tension's mean, range and maximum over the second half of
the run (the last segment's tension in both codes) against MoorDyn at its file's own setting (RK2,
1 ms). MoorDyn's faster settings count as "best MoorDyn" only within 1 % of that reference in mean
and 3 % in range and maximum (the issue's tolerances for kanat).

``--friction MU`` runs both codes with the file's ``FrictionCoefficient`` replaced by ``MU`` (0.5 in
the file). The two codes' friction differs: kanat's is Coulomb's, ``mu N`` regularized below 1 mm/s
(``kanat.physics.contact``); MoorDyn-C's is ``mu FricDamp |v|`` (``FricDamp`` 200 s/m by default)
capped at ``mu N``, a damper of 100 N s/m per node at ``mu = 0.5`` that reaches the cap only at
tens of m/s on this chain, so ``--friction 0`` changes MoorDyn's fairlead tension by about 1e-5 and
kanat's range by about 1 % (benchmarks/RESULTS.md).

Run: ``python benchmarks/bench_wd0050_moordyn.py [--repeats 3] [--duration 200] [--kanat-schemes default rk4]
[--friction MU]``; prints the Markdown table kept in benchmarks/RESULTS.md.
"""
from __future__ import annotations

import argparse
import json
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from pairs import paired

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "tests" / "data" / "moordyn" / "wd0050_chain.dat"
MOTION = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
COUPLING = 0.05
TOLERANCE = np.array([0.01, 0.03, 0.03])    # mean, range, maximum

MOORDYN_SCRIPT = """
import json, math, sys, time
import numpy as np, moordyn
path, scheme, dt, duration, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
def disp(t):
    return np.array([-4.0 * math.cos(2 * math.pi * t / 12.0), 0.0, -math.cos(2 * math.pi * t / 9.0)])
system = moordyn.Create(path)
moordyn.SetTimeScheme(system, scheme)
moordyn.SetDt(system, dt)
moordyn.Init(system, list(disp(0.0)), [0.0] * 3)
line = moordyn.GetLine(system, 1)
dc = {coupling}
record, start = [], time.perf_counter()
for k in range(int(round(duration / dc))):
    t = k * dc
    moordyn.Step(system, list(disp(t)), list((disp(t + dc) - disp(t)) / dc), t, dc)
    if (k + 1) % 2 == 0:
        record.append([(k + 1) * dc, moordyn.GetLineFairTen(line)])
stepping = time.perf_counter() - start
np.save(out, np.array(record))
print(json.dumps({{"stepping": stepping}}))
"""

CONFIGS = [("MoorDyn", "RK2", 0.001), ("MoorDyn", "RK2", 0.002), ("MoorDyn", "RK2", 0.003),
           ("kanat", "default", None), ("kanat", "rk4", None)]


def timed(command: list) -> tuple[subprocess.CompletedProcess, float, float]:
    """Run ``command``: its result, wall time and CPU time (user + system of the child) [s]."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return done, wall, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def input_file(folder: Path, friction: float | None) -> Path:
    """MoorDyn's file in ``folder`` (MoorDyn writes its outputs beside its input), with its friction
    coefficient replaced by ``friction`` unless None."""
    text = FILE.read_text()
    if friction is not None:
        text = re.sub(r"^\S+(\s+FrictionCoefficient)", rf"{friction}\1", text, flags=re.M)
    path = folder / FILE.name
    path.write_text(text)
    return path


def kanat_case(folder: Path, scheme: str, duration: float, friction: float | None = None) -> Path:
    """The MoorDyn file imported, with the fairlead's motion; the default scheme names none."""
    import warnings

    import yaml
    from kanat.io import load_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                       # the file's MoorDyn-only settings
        case = load_case(input_file(folder, friction))
    keys = {"model": "lumped", "vessel.motion": MOTION, "simulation.duration": duration,
            "simulation.output_dt": 0.1}
    if scheme != "default":
        keys["simulation.scheme"] = scheme
    case = case.replace(keys)
    path = folder / f"kanat_{scheme}.yaml"
    path.write_text(yaml.safe_dump(case.model_dump(mode="json", by_alias=True, exclude_none=True), sort_keys=False))
    return path


def run_kanat(case_path: Path, folder: Path):
    import xarray as xr

    out = folder / (case_path.stem + ".nc")
    _, whole, cpu = timed([str(Path(sys.executable).with_name("kanat")), "run", str(case_path), "-o", str(out)])
    with xr.open_dataset(out) as ds:
        if ds.attrs["status"] != "ok":
            return (whole, cpu), float("nan"), ds.attrs["status"], {}
        last = int(np.flatnonzero(ds.segment_cable.values == "line1")[-1])
        series = np.column_stack([ds.time.values, ds.segment_tension.values[:, last]])
        extra = {"dt": float(ds.attrs["dt"]), "explicit": int(ds.attrs.get("explicit_steps", 0)),
                 "cuts": int(ds.attrs.get("step_cuts", 0))}
        return (whole, cpu), float(ds.attrs["solver_time_s"]), series, extra


def run_moordyn(scheme: str, dt: float, duration: float, folder: Path, friction: float | None = None):
    script = folder / "moordyn_run.py"
    script.write_text(MOORDYN_SCRIPT.format(coupling=COUPLING))
    out = folder / f"moordyn_{scheme}_{dt}.npy"
    copy = input_file(folder, friction)
    done, whole, cpu = timed([sys.executable, str(script), str(copy), scheme, str(dt), str(duration), str(out)])
    if done.returncode != 0:                       # MoorDyn-C raises when a step diverges
        lines = done.stderr.strip().splitlines() or ["no message"]
        return (whole, cpu), float("nan"), f"MoorDyn failed: {lines[-1]}", {}
    report = re.findall(r'\{"stepping": [^}]*\}', done.stdout)   # MoorDyn-C's own output
    stepping = json.loads(report[-1])["stepping"]                  # ends without a newline
    return (whole, cpu), stepping, np.load(out), {}


def statistics(series: np.ndarray, duration: float) -> np.ndarray:
    """Mean, range and maximum of the fairlead tension over the second half of the run."""
    values = series[series[:, 0] >= duration / 2 - 1e-9, 1]
    return np.array([values.mean(), np.ptp(values), values.max()])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--duration", type=float, default=200.0)
    parser.add_argument("--kanat-schemes", nargs="+", default=["default", "rk4"], choices=["default", "rk4"])
    parser.add_argument("--friction", type=float, default=None, help="the seabed friction coefficient of both runs")
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp())
    configs = [c for c in CONFIGS if c[0] == "MoorDyn" or c[1] in args.kanat_schemes]
    times = {c: [] for c in configs}
    results, extras = {}, {}
    for _ in range(args.repeats):                                   # interleaved
        for config in configs:
            code, scheme, dt = config
            if code == "kanat":
                whole, stepping, series, extra = run_kanat(kanat_case(folder, scheme, args.duration, args.friction), folder)
            else:
                whole, stepping, series, extra = run_moordyn(scheme, dt, args.duration, folder, args.friction)
            times[config].append({"wall": whole[0], "cpu": whole[1], "stepping": stepping})
            results[config] = statistics(series, args.duration) if not isinstance(series, str) else series
            extras[config] = extra
    reference = results[CONFIGS[0]]

    def accurate(config) -> bool:
        return not isinstance(results[config], str) and np.all(
            np.abs(results[config] / reference - 1.0) <= TOLERANCE)

    def median(config, part):
        return float(np.median([t[part] for t in times[config]]))

    candidates = [c for c in configs if c[0] == "MoorDyn" and accurate(c)]
    best_wall, best_cpu = (min(median(c, "wall") for c in candidates), min(median(c, "cpu") for c in candidates))
    print("| code | scheme | step [s] | whole process [s] | CPU [s] | stepping [s] | vs best MoorDyn (whole; CPU) | "
          "mean | range | maximum |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for config in configs:
        code, scheme, dt = config
        whole, cpu, stepping = median(config, "wall"), median(config, "cpu"), median(config, "stepping")
        if isinstance(results[config], str):
            print(f"| {code} | {scheme} | {dt} | {whole:.2f} | {cpu:.2f} | – | – | {results[config][:90]} | | |")
            continue
        diff = 100 * (results[config] / reference - 1.0)
        extra = extras[config]
        step = f"{extra['dt']:.4g} ({extra['explicit']} rk4 steps, {extra['cuts']} cuts)" if extra else dt
        off = "" if code == "kanat" or accurate(config) else " (outside the tolerances: not a candidate)"
        print(f"| {code} | {scheme} | {step} | {whole:.2f} | {cpu:.2f} | {stepping:.2f} | {best_wall / whole:.2f}x; "
              f"{best_cpu / cpu:.2f}x{off} | {diff[0]:+.2f} % | {diff[1]:+.2f} % | {diff[2]:+.2f} % |")
    best = min(candidates, key=lambda c: median(c, "wall"))
    for config in configs:
        if config[0] == "kanat" and not isinstance(results[config], str):
            print(f"\n{config[0]} {config[1]} against {best[0]} {best[1]} {best[2]} repeat by repeat (the runs "
                  "interleaved, so the ratio is taken at one machine speed): "
                  + ", ".join(f"{name} {paired(*([t[part] for t in times[c]] for c in (best, config)))}"
                              for name, part in (("whole", "wall"), ("CPU", "cpu"))))
    print(f"\nreference (MoorDyn RK2 1 ms): fairlead tension mean {reference[0]:.0f} N, range {reference[1]:.0f} N, "
          f"maximum {reference[2]:.0f} N over {args.duration / 2:g}-{args.duration:g} s")


if __name__ == "__main__":
    main()
