"""kanat's lumped model side by side with MoorDyn-C (PyPI ``moordyn``, the ``peers`` extra) on
the same single line.

The line hangs as a catenary from a fixed anchor to a fairlead (kanat's vessel tow point,
MoorDyn's coupled point) that, after 1 s at rest, surges 5 m away from the anchor in a
half-cosine over 8 s; 20 s are simulated. MoorDyn moves a coupled point at constant velocity
over each coupling step (``SAMPLE``), so kanat's track is the same piecewise-constant velocity.
Same segments, mass, EA, Kelvin–Voigt damping (MoorDyn ``BA`` in N s), Cd-form drag (``Cd``,
``CdAx`` on pi d), normal added mass (``Ca``; ``CaAx = 0``), weight and buoyancy, calm water,
no seabed contact; each code starts from its own static equilibrium. Remaining differences of
formulation: MoorDyn applies drag at nodes with the node's velocity and mean tangent, kanat on
elements with their mean velocity and tangent and a ``sqrt(1 + e)`` stretch factor; the
converged runs of the two codes differ by < 0.1 % of the range of motion.

Measured: wall time per simulated second of the stepping (equilibrium, compilation and output
excluded for both), at the largest step (on a grid) whose record of the middle node's position,
every ``SAMPLE``, stays within ``TOLERANCE`` of the code's own converged record (RK4 at a
quarter of kanat's explicit safe step), relative to that node's range of motion; best of
``REPEATS``. kanat runs through :func:`kanat.lumped.advance.advance` (the compiled paths of
``kanat run``), sampled from the compiled path's work arrays.

Run: ``python benchmarks/bench_lumped_moordyn.py [--quick] [--lines wire stiff]``; prints the
Markdown tables recorded in benchmarks/RESULTS.md (about 5 minutes).
"""
from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

import moordyn
import numpy as np

from kanat.errors import SolverError
from kanat.lumped import kernels
from kanat.lumped.advance import advance
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.integrators import state_positions
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.stepping import step_info
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.lumped.integrators import SCHEMES
from kanat.schemes import get_scheme

sys.path.insert(0, str(Path(__file__).resolve().parent))
from console import quiet  # noqa: E402

DURATION = 20.0       # s simulated
SAMPLE = 0.05         # s between compared samples (and MoorDyn coupling steps)
TOLERANCE = 0.01      # error allowed, fraction of the middle node's range of motion
REPEATS = 3
RHO, G = 1025.0, 9.81
ANCHOR = (-85.0, 0.0, -40.0)
FAIRLEAD = (0.0, 0.0, -5.0)
SURGE, SURGE_START, SURGE_TIME = 5.0, 1.0, 8.0     # m, s, s: a smooth surge away from the anchor

LINES = {
    # a steel wire rope hanging as a catenary; "stiff": a 40-segment rod-like line, EA x 20, damped
    "wire": dict(length=100.0, segments=20, diameter=0.04, mass=8.0, ea=1.0e8, damping=1.0e4, cd=1.2, ct=0.01,
                 ca=1.0),
    "stiff": dict(length=100.0, segments=40, diameter=0.04, mass=8.0, ea=2.0e9, damping=2.0e5, cd=1.2, ct=0.01,
                  ca=1.0),
}


# --- the two models of one line --------------------------------------------------------------
def fairlead_x(t):
    """Surge of the fairlead at times ``t``: a half-cosine ramp of SURGE metres."""
    tau = np.clip((np.asarray(t, float) - SURGE_START) / SURGE_TIME, 0.0, 1.0)
    return FAIRLEAD[0] + SURGE * 0.5 * (1.0 - np.cos(np.pi * tau))


def sample_speeds() -> np.ndarray:
    """Constant fairlead speed over each sample interval (what MoorDyn's coupling applies)."""
    times = np.arange(0.0, DURATION + SAMPLE / 2, SAMPLE)
    return np.diff(fairlead_x(times)) / SAMPLE


def kanat_case(p) -> Case:
    added = RHO * math.pi * p["diameter"] ** 2 / 4 * p["ca"]
    line = dict(diameter=p["diameter"], mass=p["mass"], axial_stiffness=p["ea"], axial_damping=p["damping"],
                added_mass=added, drag_normal=p["cd"], drag_tangential=p["ct"])
    track = [{"straight": {"speed": float(v), "duration": SAMPLE}} for v in sample_speeds()]
    return Case.model_validate(dict(
        model="lumped", name="bench", line_types={"wire": line},
        vessel={"tow_point": list(FAIRLEAD), "track": track},
        cables=[dict(name="line", line_type="wire", length=p["length"], segments=p["segments"],
                     **{"from": "anchor:[{},{},{}]".format(*ANCHOR)}, to="vessel")],
        simulation=dict(duration=DURATION, dt=0.01, output_dt=SAMPLE)))


def moordyn_file(p, folder: Path) -> Path:
    text = f"""--------------------- MoorDyn Input File ------------------------------------
kanat benchmark line
---------------------- LINE TYPES ----------------------------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
wire  {p['diameter']}  {p['mass']}  {p['ea']}  {p['damping']}  0.0  {p['cd']}  {p['ca']}  {p['ct']}  0.0
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed   {ANCHOR[0]}  {ANCHOR[1]}  {ANCHOR[2]}  0  0  0  0
2     Coupled {FAIRLEAD[0]}  {FAIRLEAD[1]}  {FAIRLEAD[2]}  0  0  0  0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     wire       1        2        {p['length']}     {p['segments']}       -
---------------------- OPTIONS -----------------------------------------
0          writeLog
{RHO}      rho
{G}        g
1000.0     WtrDpth
1.0e-4     dtM
1.0e-6     threshIC
1          disableOutput
1          disableOutTime
------------------------- need this line -------------------------------------
"""
    path = folder / f"{p['segments']}_{p['ea']:g}.txt"
    path.write_text(text)
    return path


# --- runs --------------------------------------------------------------------------------------
def run_kanat(p, scheme_name, h):
    """Record (k, 4) of the middle node's position and the tension at the node next to the
    fairlead at every SAMPLE, and the stepping wall time (None for the record if it blew up)."""
    case = kanat_case(p)
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = equilibrium(net, case)[0]
    scheme = get_scheme(scheme_name, SCHEMES, lambda_inf=-0.5)
    h = SAMPLE / math.ceil(SAMPLE / h - 1e-9)       # a whole number of steps per sample
    free = system.free_index
    state = scheme.start(system, 0.0, x[free], np.zeros((len(free), 3)), h)
    tracker = SnapTracker(0.0, np.zeros(net.n_elements))
    T = np.zeros(net.n_elements)
    middle = net.node_index[p["segments"] // 2]

    def tensions(st):
        xs, vs, _, _ = system.full(st.t, *state_positions(st))
        kernels.tensions(xs, vs, net.elements(), T)
        return T

    def sample():                                   # the compiled path leaves the last state in its work arrays
        work = system._fused.work
        return [*work[0][middle], _node_tension(work[4])]

    per = int(round(SAMPLE / h))
    record = [[*x[middle], _node_tension(tensions(state))]]
    start = time.perf_counter()
    try:
        for _ in range(int(round(DURATION / SAMPLE))):
            state, _ = advance(scheme, system, state, h, per, tracker, tensions)
            record.append(sample())
    except SolverError:
        return None, time.perf_counter() - start
    wall = time.perf_counter() - start
    record = np.array(record)
    return (record if np.all(np.isfinite(record)) else None), wall


def _node_tension(T):
    return 0.5 * (T[-1] + T[-2])                   # node N-1: mean of its two segments (as MoorDyn)


def run_moordyn(path, scheme, dt):
    with quiet():
        return _run_moordyn(path, scheme, dt)


def _run_moordyn(path, scheme, dt):
    system = moordyn.Create(str(path))
    moordyn.SetTimeScheme(system, scheme)
    moordyn.SetDt(system, dt)
    moordyn.Init(system, list(FAIRLEAD), [0.0, 0.0, 0.0])
    line = moordyn.GetLine(system, 1)
    n = moordyn.GetLineN(line)

    def sample():
        return [*moordyn.GetLineNodePos(line, n // 2), np.linalg.norm(moordyn.GetLineNodeTen(line, n - 1))]

    record = [sample()]
    speeds = sample_speeds()
    start = time.perf_counter()
    for k, speed in enumerate(speeds):
        where = [float(fairlead_x(k * SAMPLE)), FAIRLEAD[1], FAIRLEAD[2]]
        try:
            moordyn.Step(system, where, [float(speed), 0.0, 0.0], k * SAMPLE, SAMPLE)
        except Exception:                                      # MoorDyn raises on NaN
            break
        record.append(sample())
    wall = time.perf_counter() - start
    moordyn.Close(system)
    record = np.array(record, dtype=float)
    if len(record) < len(speeds) + 1 or not np.all(np.isfinite(record)):
        return None, wall
    return record, wall


# --- search and report ---------------------------------------------------------------------------
KANAT_SCHEMES = ("rk4", "abm4", "generalized-alpha-lumped")
MOORDYN_SCHEMES = ("RK2", "RK4", "Midpoint5")
IMPLICIT_SUBDIVISIONS = (1, 2, 4, 8, 16)          # generalized-α steps per SAMPLE


def error(record, reference) -> float:
    """Largest distance of the middle node from the reference, over the reference's range of motion."""
    scale = np.max(np.linalg.norm(reference[:, :3] - reference[0, :3], axis=1))
    return float(np.max(np.linalg.norm(record[1:, :3] - reference[1:, :3], axis=1)) / scale)


def candidates(code, scheme, safe) -> list[float]:
    """Steps to try, largest first: the implicit scheme by divisions of SAMPLE, the others on a
    geometric grid around kanat's explicit safe step."""
    if scheme == "generalized-alpha-lumped":
        return [SAMPLE / k for k in IMPLICIT_SUBDIVISIONS]
    grid = [safe * 2.0 ** (k / 4.0) for k in range(6, -13, -1)]
    return grid


def best_run(code, scheme, p, path, safe, reference, repeats):
    """The largest step within TOLERANCE (and stable), with its error and best wall time."""
    run = (lambda h: run_kanat(p, scheme, h)) if code == "kanat" else (lambda h: run_moordyn(path, scheme, h))
    for h in candidates(code, scheme, safe):
        record, wall = run(h)
        if record is None or error(record, reference) > TOLERANCE:
            continue
        walls = [wall] + [run(h)[1] for _ in range(repeats - 1)]
        return h, error(record, reference), min(walls)
    return None, None, None


def benchmark(name, repeats) -> list[dict]:
    p = LINES[name]
    folder = Path(tempfile.mkdtemp())
    path = moordyn_file(p, folder)
    net = build_network(kanat_case(p))
    info = step_info(net, net.x_guess)
    safe = info.safe_step(get_scheme("rk4", SCHEMES))
    references = {"kanat": run_kanat(p, "rk4", safe / 4)[0], "MoorDyn": run_moordyn(path, "RK4", safe / 4)[0]}
    run_kanat(p, "generalized-alpha-lumped", SAMPLE)               # compile before timing
    rows = []
    for code, schemes in (("MoorDyn", MOORDYN_SCHEMES), ("kanat", KANAT_SCHEMES)):
        for scheme in schemes:
            h, err, wall = best_run(code, scheme, p, path, safe, references[code], repeats)
            rows.append(dict(line=name, code=code, scheme=scheme, step=h, error=err,
                             per_second=None if wall is None else wall / DURATION))
    agree = error(references["kanat"], references["MoorDyn"])
    return rows, agree, info


def table(rows) -> str:
    best_md = min(r["per_second"] for r in rows if r["code"] == "MoorDyn" and r["per_second"] is not None)
    out = ["| line | code | scheme | step [s] | error | wall per simulated s [ms] | vs best MoorDyn |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["per_second"] is None:
            out.append(f"| {r['line']} | {r['code']} | {r['scheme']} | unstable or > {TOLERANCE:.0%} at every "
                       "step tried | | | |")
            continue
        out.append(f"| {r['line']} | {r['code']} | {r['scheme']} | {r['step']:.3g} | {r['error']:.1e} | "
                   f"{1e3 * r['per_second']:.2f} | {best_md / r['per_second']:.2f}x |")
    return "\n".join(out)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="one timing per case instead of REPEATS")
    parser.add_argument("--lines", nargs="+", default=list(LINES), choices=list(LINES))
    args = parser.parse_args(argv)
    for name in args.lines:
        rows, agree, info = benchmark(name, 1 if args.quick else REPEATS)
        p = LINES[name]
        print(f"\n### {name}: {p['length']:g} m, {p['segments']} segments, EA {p['ea']:.3g} N, "
              f"damping {p['damping']:.3g} N s; shortest axial nodal period {info.axial_period:.3g} s; "
              f"kanat and MoorDyn references differ by {agree:.2%} of the range of motion\n")
        print(table(rows))


if __name__ == "__main__":
    main()
