"""A 3-hour storm on the three-leg chain mooring with RAO-driven fairleads: kanat's default scheme
beside MoorDyn-C (PyPI ``moordyn``, the ``peers`` extra) driven by the same motion, whole processes.

The mooring is ``examples/moordyn/three_leg_chain_50.dat`` (three 640 m studless chain legs of 50
segments from anchors in 120 m of water to three fairleads 20 m from the vessel's centre, 8 m
deep; MoorDyn's coupled points). The sea is a JONSWAP storm (``HS`` 6 m, ``TP`` 11 s, gamma 3.3,
``SEED``) travelling along ``HEADING_DEG`` (180 deg: in line with leg 1, whose anchor is on +x, so
that leg 1 takes the surge head-on and legs 2 and 3 at 60 deg). The vessel is a floating vertical cylinder of radius 20 m and draft 12 m;
its RAOs (``benchmarks/data/cylinder_raos.csv``, written by :func:`cylinder_raos`,
``python benchmarks/bench_storm_moordyn.py --write-raos``) are closed-form, deep water:

* heave: ``Z3 = rho g A_w e^{-k T} / (rho g A_w - omega^2 (m + A33) - i omega B33)`` with the
  Froude-Krylov force on the bottom, ``A_w = pi a^2``, ``m = rho A_w T`` (freely floating),
  ``A33 = 4/3 rho a^3`` (half a disc's added mass, DNV-RP-H103 table A-2) and the radiation
  damping from the Haskind relation of an axisymmetric body in deep water,
  ``B33 = omega^3 |X3|^2 / (2 rho g^3)`` (Newman, *Marine Hydrodynamics*, 1977, § 6.18);
* surge (sway at 90 deg): the long-wave inertia force (Morison, ``C_M = 2``) on the submerged
  length, ``X1 = -omega^2 C_M rho A_w i A (1 - e^{-k T}) / k``, on the mass ``m + A11 = 2 rho
  A_w T``: ``Z1 = i (1 - e^{-k T}) / (k T)`` (the water particles' mean displacement over the
  draft; ``|Z1| -> 1`` in long waves), no radiation damping. At the storm's peak ``k a = 0.66``,
  beyond the long-wave range (``k a < 0.5``), where MacCamy-Fuchs diffraction would lower the
  force: a plausible floater, not a particular one.

Phases are those of a RAO table (``phase_deg``: motion ``|Z| a cos(omega t - phase)`` for a crest
at the origin at t = 0, i.e. ``Z`` with time factor ``e^{-i omega t}``); the mooring's stiffness
is left out of the RAOs, as in any decoupled RAO-driven analysis.

Both codes see the same sea and the same motion:

* kanat runs ``kanat run case.yaml -o out.nc``: the MoorDyn file imported, ``vessel.motion:
  {rao: cylinder_raos.csv}``, ``environment.waves: {type: jonswap, ..., stretching: wheeler}``,
  its default scheme and step (the file's ``dtM`` dropped).
* MoorDyn reads the same components as ``WaveKin 7`` (``wave_frequencies.txt``, summed at the
  nodes with Wheeler stretching; kanat's component ``a cos(k l - omega t + phi)`` is MoorDyn's
  ``A = a e^{i (pi/2 - phi)}``, :mod:`kanat.io.moordyn_waves`), and its coupled points get, every
  0.05 s coupling step, the fairlead positions kanat's compiled motion gives at that instant
  (:func:`fairlead_motion`: :func:`kanat.physics.motion.compile_motion`,
  :func:`~kanat.physics.motion.motion_at`, :func:`~kanat.physics.motion.rigid_point_motion`) and
  the mean velocity over the step, so that MoorDyn's points (moved linearly within a step) pass
  through kanat's at every coupling instant. tests/peers/test_storm_motion.py checks the positions
  against kanat's own vessel nodes in a run to 1e-9 m.

Each configuration runs as its own process, interleaved, ``--repeats`` times; the table gives
medians of the whole process's wall time and CPU (the child's user + system time,
``resource.getrusage(RUSAGE_CHILDREN)``), the CPU per simulated hour and the stepping alone
(kanat: ``solver_time_s``; MoorDyn: its ``Step`` calls). Accuracy: each fairlead's tension (the
fairlead segment's in both codes) after ``--transient`` s: mean, standard deviation, maximum and
the most probable maximum over a 3-hour storm (:func:`kanat.analysis.extremes.mpm`, Rayleigh),
the largest relative difference over the three legs against MoorDyn at its file's own setting
(RK2, 1 ms). MoorDyn's faster settings count as "best MoorDyn" only within 1 % of that reference
in mean and 3 % in standard deviation and maximum.

Run: ``python benchmarks/bench_storm_moordyn.py [--duration 10800] [--repeats 1] [--store DIR]
[--only LABELS]``; prints the Markdown table kept in benchmarks/RESULTS.md. ``--store`` keeps each
configuration's runs in DIR and reuses them in later tables (the 1 ms reference costs about five
CPU-hours per simulated hour); ``--only MoorDyn-RK2-0.001,kanat`` runs the configurations whose
label ``code-scheme-step`` starts with one of those, so that several processes can share them out.
``--window END`` takes the statistics from ``--transient`` to ``END`` s only and, for a configuration
with no kept run of ``--duration``, uses its shortest kept run that covers the window (the first
600 s of a kept 3-hour kanat run beside a 600 s MoorDyn run); each configuration's CPU per simulated
hour is that of its own run. MoorDyn's record so far is saved every 60 s of simulated time beside its final one
(``moordyn_SCHEME_DT_part.npy`` in the run's folder), as kanat's result is written as it goes
(``OUT.nc.part``), so that a run stopped early leaves its record. ``--reference LABEL`` takes the differences against another
configuration than MoorDyn RK2 1 ms (e.g. ``MoorDyn-RK2-0.004`` when the 1 ms run is out of reach).
"""
from __future__ import annotations

import argparse
import json
import math
import re
import resource
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "examples" / "moordyn" / "three_leg_chain_50.dat"
RAOS = ROOT / "benchmarks" / "data" / "cylinder_raos.csv"
HS, TP, GAMMA, SEED, HEADING_DEG = 6.0, 11.0, 3.3, 7, 180.0
RADIUS, DRAFT = 20.0, 12.0              # m: the floating cylinder of the RAOs
RHO, G = 1025.0, 9.81                   # kg/m^3, m/s^2: the MoorDyn file's
COUPLING = 0.05                         # s: MoorDyn's coupling step
OUTPUT_DT = 0.5                         # s: both codes' tension record
KEPT_EVERY = 60.0                       # s: MoorDyn's record so far saved this often (a stopped run keeps it)
STORM = 10800.0                         # s: the MPM's exposure
TOLERANCE = np.array([0.01, 0.03, 0.03, 0.03])    # mean, std, maximum, MPM
STATS = ("mean", "std", "max", "MPM")

CONFIGS = [("MoorDyn", "RK2", 0.001), ("MoorDyn", "RK2", 0.006), ("MoorDyn", "RK2", 0.003), ("MoorDyn", "RK2", 0.004),
           ("MoorDyn", "RK4", 0.008),
           ("kanat", "default", None), ("kanat", "generalized-alpha-lumped", 0.05),
           ("kanat", "generalized-alpha-lumped", 0.025)]

MOORDYN_SCRIPT = """
import json, sys, time
import numpy as np, moordyn
path, scheme, dt, motion, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5]
dc, every = {coupling}, {every}
data = np.load(motion)
positions, velocities = data["positions"], data["velocities"]
system = moordyn.Create(path)
moordyn.SetTimeScheme(system, scheme)
moordyn.SetDt(system, dt)
moordyn.Init(system, list(positions[0]), [0.0] * positions.shape[1])
lines = [moordyn.GetLine(system, i) for i in (1, 2, 3)]
record, start = [], time.perf_counter()
for k in range(len(velocities)):
    moordyn.Step(system, list(positions[k]), list(velocities[k]), k * dc, dc)
    if (k + 1) % every == 0:
        record.append([(k + 1) * dc] + [moordyn.GetLineFairTen(line) for line in lines])
        if len(record) % {kept} == 0:
            np.save(out[:-4] + "_part.npy", np.array(record))
stepping = time.perf_counter() - start
np.save(out, np.array(record))
print(json.dumps({{"stepping": stepping}}))
"""


def cylinder_raos(omegas, headings_deg, radius: float = RADIUS, draft: float = DRAFT) -> list[tuple]:
    """Rows ``(omega, heading_deg, dof, amplitude, phase_deg)`` of the floating cylinder's surge,
    sway and heave RAOs (module docstring: heave with Froude-Krylov force, half-disc added mass
    and Haskind damping; surge and sway from the long-wave inertia force), deep water.

    Parameters
    ----------
    omegas : array_like, shape (k,)
        Angular frequencies [rad/s], > 0.
    headings_deg : array_like, shape (h,)
        Directions the waves travel [deg], from the vessel's +x towards +y.
    radius, draft : float
        The cylinder's [m].
    """
    area = math.pi * radius**2
    mass = RHO * area * draft
    added = 4.0 / 3.0 * RHO * radius**3
    rows = []
    for omega in np.asarray(omegas, dtype=float):
        k = omega**2 / G
        force = RHO * G * area * math.exp(-k * draft)               # heave excitation per metre [N/m]
        damping = omega**3 * force**2 / (2.0 * RHO * G**3)
        heave = force / (RHO * G * area - omega**2 * (mass + added) - 1j * omega * damping)
        surge = 1j * (1.0 - math.exp(-k * draft)) / (k * draft)
        for beta in np.asarray(headings_deg, dtype=float):
            b = math.radians(beta)
            for dof, z in (("surge", surge * math.cos(b)), ("sway", surge * math.sin(b)), ("heave", heave)):
                z = complex(round(z.real, 12), round(z.imag, 12))   # no -0.0 or 1e-17 phases
                rows.append((float(omega), float(beta), dof, abs(z), math.degrees(np.angle(z)) if abs(z) else 0.0))
    return rows


def write_raos(path: Path = RAOS) -> None:
    """The table of :func:`cylinder_raos` at 0.05-3.0 rad/s every 0.05, headings every 30 deg."""
    rows = cylinder_raos(np.arange(1, 61) * 0.05, np.arange(0, 360, 30))
    head = [f"# Displacement RAOs of a freely floating vertical cylinder, radius {RADIUS:g} m, draft {DRAFT:g} m,",
            "# deep water: closed-form surge/sway (long-wave inertia force) and heave (Froude-Krylov force,",
            "# half-disc added mass, Haskind damping); see benchmarks/bench_storm_moordyn.py (cylinder_raos).",
            "# Written by: python benchmarks/bench_storm_moordyn.py --write-raos",
            ",".join(("omega", "heading_deg", "dof", "amplitude", "phase_deg"))]
    body = [f"{w:.2f},{b:g},{d},{a:.6f},{p:.4f}" for w, b, d, a, p in rows]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(head + body) + "\n")


def case_dict(duration: float, scheme: str = "default", dt: float | None = None) -> dict:
    """The kanat case: the MoorDyn file imported, with the storm and the RAO-driven vessel."""
    from kanat.io import load_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                       # the file's MoorDyn-only settings
        case = load_case(FILE)
    data = case.model_dump(mode="json", by_alias=True, exclude_none=True)
    data["environment"]["waves"] = {"type": "jonswap", "hs": HS, "tp": TP, "gamma": GAMMA, "seed": SEED,
                                    "heading_deg": HEADING_DEG, "stretching": "wheeler"}
    data["vessel"]["motion"] = {"rao": str(RAOS)}
    simulation = {"duration": duration, "output_dt": OUTPUT_DT}
    if scheme != "default":
        simulation["scheme"] = scheme
    if dt is not None:
        simulation["dt"] = dt
    data["simulation"] = simulation
    return data


def write_case(folder: Path, duration: float, scheme: str = "default", dt: float | None = None) -> Path:
    import yaml

    path = folder / f"kanat_{scheme}_{dt}.yaml"
    path.write_text(yaml.safe_dump(case_dict(duration, scheme, dt), sort_keys=False))
    return path


def fairlead_motion(case, times) -> tuple[np.ndarray, np.ndarray]:
    """Positions and velocities (k, p, 3) of the case's vessel fairleads at ``times`` (k,), from
    its compiled motion (no track: the vessel frame is fixed; module docstring).

    The fairleads are the cables' ends on the vessel (``{vessel: [x, y, z]}``), in cable order:
    here MoorDyn's coupled points 4, 5, 6, the ends of lines 1, 2, 3.
    """
    from kanat.physics.motion import compile_motion, motion_at, rigid_point_motion

    if case.vessel.track:
        raise ValueError("fairlead_motion takes a vessel without a track")
    offsets = np.array([end.offset for cable in case.cables for end in (cable.from_, cable.to)
                        if end.kind == "vessel"], dtype=float)
    motion = compile_motion(case.vessel.motion, case.environment)
    positions, velocities = [], []
    for t in np.asarray(times, dtype=float):
        q, v = motion_at(motion, float(t))
        moved, speed = rigid_point_motion(offsets, q, v)
        positions.append(offsets + moved)
        velocities.append(speed)
    return np.array(positions), np.array(velocities)


def moordyn_drive(case, duration: float) -> tuple[np.ndarray, np.ndarray]:
    """What MoorDyn's coupled points get every coupling step: positions (n + 1, 3 p) at ``j dc``
    and the mean velocities (n, 3 p) over each step."""
    steps = int(round(duration / COUPLING))
    positions, _ = fairlead_motion(case, np.arange(steps + 1) * COUPLING)
    flat = positions.reshape(steps + 1, -1)
    return flat, np.diff(flat, axis=0) / COUPLING


def wave_frequencies(case) -> str:
    """``wave_frequencies.txt`` (MoorDyn ``WaveKin 7``) of the case's sea: rows ``omega re im beta``,
    the first at 0 rad/s; ``A = a e^{i (pi/2 - phi)}`` (:mod:`kanat.io.moordyn_waves`)."""
    from kanat.physics.waves import sea_from_model

    sea = sea_from_model(case.environment)
    lines = ["0.0 0.0 0.0 0.0"]
    for a, w, phi, beta in zip(sea.amplitude, sea.omega, sea.phase, sea.direction):
        z = a * np.exp(1j * (0.5 * math.pi - phi))
        lines.append(f"{w:.15g} {z.real:.15g} {z.imag:.15g} {math.remainder(beta, 2 * math.pi):.15g}")
    return "\n".join(lines) + "\n"


def moordyn_file(folder: Path, case) -> Path:
    """The MoorDyn input with ``WaveKin 7`` and its ``wave_frequencies.txt`` beside it."""
    text = FILE.read_text()
    text = text.replace("120.0      WtrDpth", "7          WaveKin      waves summed from wave_frequencies.txt\n"
                        "120.0      WtrDpth")
    path = folder / FILE.name
    path.write_text(text)
    (folder / "wave_frequencies.txt").write_text(wave_frequencies(case))
    return path


def _child_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_kanat(case_path: Path, folder: Path):
    import xarray as xr

    out = folder / (case_path.stem + ".nc")
    cpu, start = _child_cpu(), time.perf_counter()
    subprocess.run([str(Path(sys.executable).with_name("kanat")), "run", str(case_path), "-o", str(out)],
                   capture_output=True)
    whole, cpu = time.perf_counter() - start, _child_cpu() - cpu
    with xr.open_dataset(out) as ds:
        if ds.attrs["status"] != "ok":
            return whole, cpu, float("nan"), f"kanat: {ds.attrs['status']}", {}
        cables = ds.segment_cable.values                     # the fairlead segment's tension, as MoorDyn's
        ends = [int(np.flatnonzero(cables == name)[-1]) for name in ("line1", "line2", "line3")]
        series = np.column_stack([ds.time.values] + [ds.segment_tension.values[:, k] for k in ends])
        extra = {"dt": float(ds.attrs["dt"]), "scheme": str(ds.attrs.get("scheme", ""))}
        return whole, cpu, float(ds.attrs["solver_time_s"]), series, extra


def run_moordyn(scheme: str, dt: float, input_path: Path, motion_path: Path, folder: Path):
    script = folder / "moordyn_run.py"
    script.write_text(MOORDYN_SCRIPT.format(coupling=COUPLING, every=int(round(OUTPUT_DT / COUPLING)),
                                            kept=int(round(KEPT_EVERY / OUTPUT_DT))))
    out = folder / f"moordyn_{scheme}_{dt}.npy"
    cpu, start = _child_cpu(), time.perf_counter()
    done = subprocess.run([sys.executable, str(script), str(input_path), scheme, str(dt), str(motion_path),
                           str(out)], capture_output=True, text=True)
    whole, cpu = time.perf_counter() - start, _child_cpu() - cpu
    if done.returncode != 0:                       # MoorDyn-C raises when a step diverges
        lines = done.stderr.strip().splitlines() or ["no message"]
        return whole, cpu, float("nan"), f"MoorDyn failed: {lines[-1]}", {}
    report = re.findall(r'\{"stepping": [^}]*\}', done.stdout)   # MoorDyn-C prints its own output
    return whole, cpu, json.loads(report[-1])["stepping"], np.load(out), {}


def _stored(folder: Path, config, duration: float) -> Path:
    code, scheme, dt = config
    return folder / f"{code}_{scheme}_{dt}_{duration:g}.json"


def save_runs(folder: Path, config, duration: float, runs: list) -> None:
    """Keep a configuration's runs (times, tension series or failure message, step) for later tables."""
    folder.mkdir(parents=True, exist_ok=True)
    rows = [[w, c, s, x if isinstance(x, str) else x.tolist(), e] for w, c, s, x, e in runs]
    _stored(folder, config, duration).write_text(json.dumps(rows))


def load_runs(folder: Path, config, duration: float) -> list:
    """The runs :func:`save_runs` kept for ``config`` at ``duration``, or an empty list."""
    path = _stored(folder, config, duration)
    if not path.exists():
        return []
    return [(w, c, s, x if isinstance(x, str) else np.array(x), e) for w, c, s, x, e in json.loads(path.read_text())]


def stored_runs(folder: Path, config, duration: float, window: float | None = None) -> tuple[list, float]:
    """The kept runs of ``config`` and the simulated time they cover [s]: those of ``duration``;
    failing those, with a ``window`` [s], those of the shortest kept duration that covers it;
    else an empty list."""
    runs = load_runs(folder, config, duration)
    if runs or window is None:
        return runs, duration
    code, scheme, dt = config
    kept = sorted(float(path.stem.rsplit("_", 1)[1]) for path in folder.glob(f"{code}_{scheme}_{dt}_*.json"))
    covering = [d for d in kept if d >= window - 1e-9]
    return (load_runs(folder, config, covering[0]), covering[0]) if covering else ([], duration)


def statistics(series: np.ndarray, transient: float, until: float = math.inf) -> np.ndarray:
    """Mean, standard deviation, maximum and 3-hour Rayleigh MPM of each fairlead tension from
    ``transient`` to ``until`` [s]: shape (3, 4) [N]."""
    from kanat.analysis.extremes import mpm

    kept = series[(series[:, 0] >= transient - 1e-9) & (series[:, 0] <= until + 1e-9)]
    t, values = kept[:, 0], kept[:, 1:]
    return np.array([[v.mean(), v.std(), v.max(), float(mpm(v, t, STORM, "rayleigh"))] for v in values.T])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--duration", type=float, default=STORM, help="simulated time [s]")
    parser.add_argument("--transient", type=float, default=200.0, help="start-up left out of the statistics [s]")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--store", type=Path, help="keep each configuration's runs in this folder and reuse "
                        "those already there (same duration): the reference takes hours")
    parser.add_argument("--only", default="", help="run only the configurations whose label code-scheme-step starts "
                        "with one of these, comma-separated (MoorDyn, kanat, MoorDyn-RK2-0.001, ...)")
    parser.add_argument("--window", type=float, help="statistics from --transient to this time [s] only; kept "
                        "runs longer than --duration that cover it are used (with --store)")
    parser.add_argument("--reference", default="MoorDyn-RK2-0.001", help="the configuration the differences "
                        "are taken against, by label code-scheme-step")
    parser.add_argument("--write-raos", action="store_true", help=f"write {RAOS.relative_to(ROOT)} and stop")
    args = parser.parse_args()
    if args.write_raos:
        write_raos()
        return
    labels = {f"{code}-{scheme}-{dt}": (code, scheme, dt) for code, scheme, dt in CONFIGS}
    if args.reference not in labels:
        parser.error(f"--reference {args.reference}: not a configuration; the labels are {', '.join(labels)}")
    if args.window is not None and not args.transient < args.window <= args.duration:
        parser.error(f"--window {args.window:g} must lie after --transient {args.transient:g} and within "
                     f"--duration {args.duration:g}")
    until = math.inf if args.window is None else args.window
    from kanat.io import load_case

    folder = Path(tempfile.mkdtemp())
    case_path = write_case(folder, args.duration)
    case = load_case(case_path)
    started = time.perf_counter()
    positions, velocities = moordyn_drive(case, args.duration)
    drive_time = time.perf_counter() - started
    motion_path = folder / "fairlead_motion.npz"
    np.savez(motion_path, positions=positions, velocities=velocities)
    input_path = moordyn_file(folder, case)
    runs = {c: [] for c in CONFIGS}
    results, extras = {}, {}
    stored = {c: stored_runs(args.store, c, args.duration, args.window) for c in CONFIGS} if args.store else {}
    durations = {c: stored[c][1] if stored.get(c, ([],))[0] else args.duration for c in CONFIGS}
    stored = {c: runs for c, (runs, _) in stored.items()}
    for _ in range(args.repeats):                                   # interleaved
        for config in CONFIGS:
            code, scheme, dt = config
            if stored.get(config) or not f"{code}-{scheme}-{dt}".startswith(tuple(args.only.split(","))):
                continue
            if code == "kanat":
                path = case_path if scheme == "default" else write_case(folder, args.duration, scheme, dt)
                whole, cpu, stepping, series, extra = run_kanat(path, folder)
            else:
                whole, cpu, stepping, series, extra = run_moordyn(scheme, dt, input_path, motion_path, folder)
            runs[config].append((whole, cpu, stepping, series, extra))
    for config in CONFIGS:
        runs[config] = stored.get(config) or runs[config]
        if args.store and runs[config] and not stored.get(config):
            save_runs(args.store, config, args.duration, runs[config])
    runs = {c: r for c, r in runs.items() if r}
    for config, done in runs.items():
        series, extras[config] = done[-1][3], done[-1][4]
        results[config] = statistics(series, args.transient, until) if not isinstance(series, str) else series
        runs[config] = [r[:3] for r in done]
    if args.window is not None:
        print(f"statistics from {args.transient:g} s to {args.window:g} s of each run; runs: "
              + ", ".join(f"{code}-{scheme}-{dt} {durations[(code, scheme, dt)]:g} s" for code, scheme, dt in runs)
              + "\n")
    print_table(runs, results, extras, durations, labels[args.reference], args.reference)
    print(f"\nfairlead motion for MoorDyn computed with kanat's API in {drive_time:.1f} s (not in MoorDyn's times); "
          f"fairlead surge/heave std {positions[:, 0].std():.2f} m / {positions[:, 2].std():.2f} m")


def print_table(runs, results, extras, durations: dict, reference_config, reference_label: str) -> None:
    """The Markdown table: times per configuration, each over its own simulated ``durations`` [s],
    and the statistics' largest relative differences over the legs against ``reference_config``."""
    reference = results.get(reference_config, "not run (no stored run either)")
    if isinstance(reference, str):
        print(f"the reference failed: {reference}")
        return

    def accurate(config) -> bool:
        return not isinstance(results[config], str) and bool(np.all(
            np.abs(results[config] / reference - 1.0) <= TOLERANCE))

    medians = {c: np.median(np.array(runs[c]), axis=0) for c in runs}
    best = min((medians[c][1] / durations[c] for c in runs if c[0] == "MoorDyn" and accurate(c)), default=None)
    print("| code | scheme | step [s] | whole process [s] | CPU [s] | CPU per simulated hour [s] | stepping [s] | "
          "vs best MoorDyn (CPU) | " + " | ".join(f"{s}, max rel. diff." for s in STATS) + " |")
    print("|---|---|---|---|---|---|---|---|" + "---|" * len(STATS))
    for config in runs:
        code, scheme, dt = config
        whole, cpu, stepping = medians[config]
        if isinstance(results[config], str):
            print(f"| {code} | {scheme} | {dt} | {whole:.1f} | {cpu:.1f} | – | – | – | {results[config][:90]} |"
                  + " |" * (len(STATS) - 1))
            continue
        diff = np.abs(results[config] / reference - 1.0).max(axis=0)
        step = f"{extras[config]['dt']:.4g}" if extras[config] else f"{dt:g}"
        if code == "kanat" and scheme == "default":
            scheme = f"default ({extras[config]['scheme']})"
        off = "" if code == "kanat" or accurate(config) else " (outside the tolerances: not a candidate)"
        per_hour = cpu / (durations[config] / 3600.0)
        versus = "–" if best is None else f"{best * 3600.0 / per_hour:.2f}x"
        print(f"| {code} | {scheme} | {step} | {whole:.1f} | {cpu:.1f} | {per_hour:.1f} | {stepping:.1f} | "
              f"{versus}{off} | " + " | ".join(f"{100 * d:.2f} %" for d in diff) + " |")
    print(f"\nreference: {reference_label}; fairlead tensions [kN], legs 1-3:")
    for config, found in results.items():
        if not isinstance(found, str):
            print(f"- {'-'.join(str(x) for x in config)}: " + "; ".join(
                f"{name} {', '.join(f'{v / 1e3:.0f}' for v in found[:, j])}" for j, name in enumerate(STATS)))


if __name__ == "__main__":
    main()
