"""A three-leg chain mooring with seabed contact, kanat's lumped model beside MoorDyn-C (PyPI
``moordyn``, the ``peers`` extra), whole processes, on the same MoorDyn input file.

The file is ``examples/moordyn/three_leg_chain_50.dat``: three 640 m studless chain legs
(50 segments each, ``BA = -0.8``) from anchors in 120 m of water to three fairleads on a
vessel (MoorDyn's coupled points), seabed ``kBot = 3e6``, ``cBot = 3e5``. The vessel moves as
in waves: surge ``-2 cos(2 pi t / 11)`` m and heave ``-cos(2 pi t / 9)`` m (kanat's
``vessel.motion`` with ``phase_deg: -90``; MoorDyn's coupled points driven with the same
positions and the mean velocity of every 0.05 s coupling step), 600 s simulated.

Each configuration runs as its own process (``kanat run case.yaml -o out.nc``; a Python process
running MoorDyn on the file), interleaved, ``REPEATS`` times; the table gives medians of the
whole process's wall time and of the stepping alone (kanat: the run's ``solver_time_s``, its
set-up and initial equilibrium apart; MoorDyn: its ``Step`` calls, its initial condition
apart). Accuracy: the mean and range (max - min) of each fairlead tension over 300-600 s — the tension of the segment at the fairlead in both codes (MoorDyn's ``FairTen``; kanat's
node ``tension`` extrapolates to the end point, 1.8 % higher here) — relative to MoorDyn at its
input file's own setting (RK2, ``dtM = 1 ms``).

MoorDyn's best stable setting comes from ``--scan``: each of MoorDyn 2.7.2's time schemes (explicit
``RK2``, ``RK4``, ``Heun``, ``AB3``, ``AB4``; implicit ``MidpointK``, ``BEulerK``, ``ACAK``,
``WilsonK`` with K iterations) at steps from 1 to 16 ms for 100 s of the same motion, in its own
process; a step is stable when every fairlead tension stays finite and below 1e8 N, and the scan
gives the largest stable step's accuracy (mean and range over 50-100 s against RK2 at 1 ms). The
fastest stable settings (RK2 at 6 ms; Midpoint2 at 8 ms, stable but its range far off) are in
``CONFIGS``; "best MoorDyn" in the table is the fastest setting within :data:`ACCURATE` of the
reference in both mean and range.

Run: ``python benchmarks/bench_mooring_moordyn.py [--repeats 3] [--duration 600] [--only CONFIG ...]``
(``kanat-default-None`` is kanat with its default scheme, which names neither scheme nor step; CPU is
user + system time of each process); prints the
Markdown table kept in benchmarks/RESULTS.md (about 12 minutes); ``--scan`` prints the scan
(about 15 minutes).
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bench_wd0050_moordyn import timed
from pairs import paired

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "examples" / "moordyn" / "three_leg_chain_50.dat"
MOTION = [{"dof": "surge", "amplitude": 2.0, "period": 11.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
BASE = [[20.0, 0.0, -8.0], [-10.0, 17.321, -8.0], [-10.0, -17.321, -8.0]]
COUPLING = 0.05
WINDOW = [300.0, 600.0]     # s: the second half of the run (set from --duration)
ACCURATE = 0.01             # a MoorDyn setting competes as "best" when its mean and range are within 1 %

MOORDYN_SCRIPT = """
import json, math, sys, time
import numpy as np, moordyn
path, scheme, dt, duration, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
base = np.array({base})
def disp(t):
    return np.array([-2.0 * math.cos(2 * math.pi * t / 11.0), 0.0, -1.0 * math.cos(2 * math.pi * t / 9.0)])
system = moordyn.Create(path)
moordyn.SetTimeScheme(system, scheme)
moordyn.SetDt(system, dt)
moordyn.Init(system, list((base + disp(0.0)).ravel()), [0.0] * 9)
lines = [moordyn.GetLine(system, i) for i in (1, 2, 3)]
dc = {coupling}
record, start = [], time.perf_counter()
for k in range(int(round(duration / dc))):
    t = k * dc
    velocity = np.tile((disp(t + dc) - disp(t)) / dc, 3)
    moordyn.Step(system, list((base + disp(t)).ravel()), list(velocity), t, dc)
    if (k + 1) % 10 == 0:
        record.append([(k + 1) * dc] + [moordyn.GetLineFairTen(line) for line in lines])
stepping = time.perf_counter() - start
np.save(out, np.array(record))
print(json.dumps({{"stepping": stepping}}))
"""


def kanat_case(folder: Path, scheme: str, dt: float | None, duration: float) -> Path:
    """The MoorDyn file imported, with the vessel's motion, a scheme and a step."""
    from kanat.io import load_case
    import yaml

    case = load_case(FILE)
    sim = {"simulation.duration": duration, "simulation.output_dt": 0.5}
    if scheme != "default":                                   # the default scheme names neither
        sim.update({"simulation.scheme": scheme, "simulation.dt": dt})
    case = case.replace({"vessel.motion": MOTION, **sim})
    path = folder / f"kanat_{scheme}_{dt}.yaml"
    path.write_text(yaml.safe_dump(case.model_dump(mode="json", by_alias=True, exclude_none=True), sort_keys=False))
    return path


def run_kanat(case_path: Path, folder: Path):
    """Whole process (wall, CPU), stepping, fairlead series (or the status) and the step taken."""
    out = folder / (case_path.stem + ".nc")
    _, whole, cpu = timed([str(Path(sys.executable).with_name("kanat")), "run", str(case_path), "-o", str(out)])
    import xarray as xr
    with xr.open_dataset(out) as ds:
        if ds.attrs["status"] != "ok":
            return (whole, cpu), float("nan"), ds.attrs["status"], ""
        cables = ds.segment_cable.values                     # the fairlead segment's tension, as MoorDyn's
        ends = [int(np.flatnonzero(cables == name)[-1]) for name in ("line1", "line2", "line3")]
        series = np.column_stack([ds.time.values] + [ds.segment_tension.values[:, k] for k in ends])
        step = (f"{float(ds.attrs['dt']):.4g} ({ds.attrs.get('scheme', '')}; "
                f"{int(ds.attrs.get('explicit_steps', 0))} rk4 steps, {int(ds.attrs.get('step_cuts', 0))} cuts)")
        return (whole, cpu), float(ds.attrs["solver_time_s"]), series, step


def run_moordyn(scheme: str, dt: float, duration: float, folder: Path):
    script = folder / "moordyn_run.py"
    script.write_text(MOORDYN_SCRIPT.format(base=BASE, coupling=COUPLING))
    out = folder / f"moordyn_{scheme}_{dt}.npy"
    copy = folder / FILE.name                      # MoorDyn writes its outputs beside its input
    copy.write_text(FILE.read_text())
    done, whole, cpu = timed([sys.executable, str(script), str(copy), scheme, str(dt), str(duration), str(out)])
    if done.returncode != 0:
        raise subprocess.CalledProcessError(done.returncode, done.args, done.stdout, done.stderr)
    stepping = json.loads(done.stdout.strip().splitlines()[-1])["stepping"]
    return (whole, cpu), stepping, np.load(out)


SCAN_SCHEMES = ("RK2", "RK4", "Heun", "AB3", "AB4", "Midpoint1", "Midpoint2", "Midpoint3", "BEuler2", "BEuler3",
                "ACA2", "ACA3", "Wilson3")
SCAN_STEPS = (0.001, 0.002, 0.004, 0.006, 0.008, 0.009, 0.01, 0.0125, 0.016)


def scan(folder: Path) -> None:
    """Each MoorDyn scheme's largest stable step over 100 s (with its range error), and its largest
    step within :data:`ACCURATE` of RK2 at 1 ms in mean and range (with its stepping time)."""
    WINDOW[:] = [50.0, 100.0]
    reference = statistics(run_moordyn("RK2", 0.001, 100.0, folder)[2])
    print("| MoorDyn scheme | largest stable step [s] | its range, max rel. diff. | "
          "largest step within 1 % [s] | its stepping, 100 s simulated [s] |")
    print("|---|---|---|---|---|")
    for scheme in SCAN_SCHEMES:
        stable = accurate = None
        for dt in SCAN_STEPS:
            try:
                _, stepping, series = run_moordyn(scheme, dt, 100.0, folder)
            except subprocess.CalledProcessError:           # MoorDyn stopped: "error integrating"
                break
            if not np.all(np.isfinite(series[:, 1:])) or np.abs(series[:, 1:]).max() > 1e8:
                break
            diff = np.abs(statistics(series) - reference) / reference
            stable = (dt, diff[:, 1].max())
            if diff.max() <= ACCURATE:
                accurate = (dt, stepping)
        print(f"| {scheme} | {stable[0] if stable else 'none'} | "
              f"{f'{100 * stable[1]:.2f} %' if stable else '-'} | {accurate[0] if accurate else 'none'} | "
              f"{f'{accurate[1]:.2f}' if accurate else '-'} |")


def statistics(series: np.ndarray) -> np.ndarray:
    """Mean and range of each fairlead tension over WINDOW: shape (3, 2)."""
    t = series[:, 0]
    inside = (t >= WINDOW[0] - 1e-9) & (t <= WINDOW[1] + 1e-9)
    values = series[inside, 1:]
    return np.stack([values.mean(axis=0), values.max(axis=0) - values.min(axis=0)], -1)


CONFIGS = [("MoorDyn", "RK2", 0.001), ("MoorDyn", "RK2", 0.006), ("MoorDyn", "RK4", 0.008),
           ("MoorDyn", "Midpoint2", 0.008),
           ("kanat", "generalized-alpha-lumped", 0.05), ("kanat", "generalized-alpha-lumped", 0.025),
           ("kanat", "generalized-alpha-lumped", 0.0125), ("kanat", "rk4", None), ("kanat", "default", None)]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--duration", type=float, default=600.0)
    parser.add_argument("--scan", action="store_true", help="find MoorDyn's largest stable step per scheme")
    parser.add_argument("--only", nargs="+", help="configurations to run, as CODE-SCHEME-STEP (e.g. kanat-default-None, "
                                                  "MoorDyn-RK2-0.006); the reference MoorDyn-RK2-0.001 always runs")
    args = parser.parse_args()
    WINDOW[:] = [args.duration / 2, args.duration]
    folder = Path(tempfile.mkdtemp())
    if args.scan:
        scan(folder)
        return
    configs = [c for c in CONFIGS if c == CONFIGS[0] or not args.only or f"{c[0]}-{c[1]}-{c[2]}" in args.only]
    times = {c: [] for c in configs}
    results, steps = {}, {}
    for _ in range(args.repeats):                                   # interleaved
        for config in configs:
            code, scheme, dt = config
            if code == "kanat":
                (whole, cpu), stepping, series, steps[config] = run_kanat(
                    kanat_case(folder, scheme, dt, args.duration), folder)
            else:
                (whole, cpu), stepping, series = run_moordyn(scheme, dt, args.duration, folder)
            times[config].append((whole, cpu, stepping))
            results[config] = statistics(series) if not isinstance(series, str) else series
    reference = results[CONFIGS[0]]

    def accurate(config) -> bool:
        return np.all(np.abs(results[config] - reference) <= ACCURATE * reference)

    def median(config, k: int) -> float:
        return float(np.median([row[k] for row in times[config]]))

    candidates = [c for c in configs if c[0] == "MoorDyn" and not isinstance(results[c], str) and accurate(c)]
    best = min(candidates, key=lambda c: median(c, 0))
    print("| code | scheme | step [s] | whole process [s] | CPU [s] | stepping [s] | vs best MoorDyn (whole; CPU) | "
          "fairlead mean, max rel. diff. | range, max rel. diff. |")
    print("|---|---|---|---|---|---|---|---|---|")
    for config in configs:
        whole, cpu, stepping = (median(config, k) for k in range(3))
        code, scheme, dt = config
        if isinstance(results[config], str):
            print(f"| {code} | {scheme} | {dt} | {whole:.2f} | {cpu:.2f} | – | – | {results[config][:90]} | |")
            continue
        diff = np.abs(results[config] - reference) / reference
        off = "" if code == "kanat" or accurate(config) else " (off by more than 1 %: not a candidate)"
        step = steps.get(config) or (dt if dt else "safe")
        print(f"| {code} | {scheme} | {step} | {whole:.2f} | {cpu:.2f} | {stepping:.2f} | "
              f"{median(best, 0) / whole:.2f}x; {median(best, 1) / cpu:.2f}x{off} | "
              f"{100 * diff[:, 0].max():.2f} % | {100 * diff[:, 1].max():.2f} % |")
    for config in configs:
        if config[0] == "kanat" and not isinstance(results[config], str):
            print(f"\n{' '.join(map(str, config))} against {' '.join(map(str, best))} repeat by repeat (the runs "
                  "interleaved, so the ratio is taken at one machine speed): "
                  + ", ".join(f"{name} {paired(*([t[k] for t in times[c]] for c in (best, config)))}"
                              for name, k in (("whole", 0), ("CPU", 1))))
    print(f"\nreference (MoorDyn RK2 1 ms) fairlead tension mean {reference[:, 0].round(0).tolist()} N, "
          f"range {reference[:, 1].round(0).tolist()} N over {WINDOW[0]:g}-{WINDOW[1]:g} s")


if __name__ == "__main__":
    main()
