"""kanat's lumped model with its default choices against MoorDyn-C (PyPI ``moordyn``) on a towed
cable: 500 m, 100 segments, a towed body at its end, 300 s.

The vessel's tow point (5 m deep) starts at rest with the cable hanging straight down, then
accelerates at 0.05 m/s^2 to 2 m/s (40 s) and tows on to 300 s; the cable streams aft and the
body rises. Same cable in both codes (a steel-armoured 17.3 mm tow cable: mass, EA,
Kelvin–Voigt damping as MoorDyn ``BA`` in N s, Cd-form normal and axial drag, normal added
mass) and the same body (MoorDyn free point: mass, volume, ``CdA``, ``Ca``); calm water, no
seabed (1000 m deep). Each code starts from its own static equilibrium. MoorDyn's initial-condition
solver runs at ``IC_STEP`` whatever the step of the run, for up to 600 s with drag x50: with its
defaults, or at the smallest steps, it stops off the equilibrium and the line rings (4100-8100 N
at the top) for the first minutes. MoorDyn's coupled
point follows the tow point's position at every coupling step (``COUPLING`` s) at the mean
velocity over it.

Accuracy: the body's position relative to the tow point and the top tension, sampled every
``SAMPLE`` s, against the code's own converged run (RK4 at a quarter of kanat's explicit safe
step): the largest position difference as a fraction of that vector's range of motion (its
largest distance from the start), the largest tension difference as a fraction of the largest
tension; a run is accurate when both are within ``TOLERANCE``. kanat runs as a user runs it — ``kanat.api.run`` with no scheme and no
step in the case — and, for comparison, with each scheme at the largest step within
``TOLERANCE``; MoorDyn with each time scheme at the largest stable step within ``TOLERANCE``
("best stable setting": the fastest of those; the largest stable step is shown too when it is
less accurate). Times: the stepping only (kanat
``solver_time_s``, MoorDyn's loop of ``Step`` calls), best of ``REPEATS``; set-up times
(equilibrium, initial conditions) beside them.

Run: ``python benchmarks/bench_lumped_towed.py [--quick]`` (about 10 minutes; the ``peers``
extra); prints the Markdown table recorded in benchmarks/RESULTS.md.
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

from kanat.api import load_case, run
from kanat.lumped.network import build_network
from kanat.lumped.stepping import step_info
from kanat.lumped.integrators import SCHEMES
from kanat.schemes import get_scheme

sys.path.insert(0, str(Path(__file__).resolve().parent))
from console import quiet  # noqa: E402

DURATION = 300.0      # s simulated
SAMPLE = 1.0          # s between compared samples (kanat's output interval)
COUPLING = 0.05       # s, MoorDyn's coupling step
IC_STEP = 0.0005      # s, MoorDyn's step while it finds its initial equilibrium
TOLERANCE = 0.01      # error allowed, fraction of the range of motion
REPEATS = 3
RHO, G = 1025.0, 9.81
TOW_POINT = (0.0, 0.0, -5.0)
SPEED, ACCELERATION = 2.0, 0.05      # m/s, m/s^2 from rest
CABLE = dict(length=500.0, segments=100, diameter=0.0173, mass=1.12, ea=1.27e7, damping=1.0e4, cd=1.5, ct=0.01,
             ca=1.0)
BODY = dict(mass=511.0, volume=0.3, cda=0.5, ca=0.65)    # net weight in water 2000 N, added mass 200 kg


# --- the two models ------------------------------------------------------------------------------
def tow_x(t):
    """Tow point's x at times ``t`` [m]: at rest, then constant acceleration to SPEED."""
    t = np.asarray(t, float)
    ramp = SPEED / ACCELERATION
    return np.where(t < ramp, 0.5 * ACCELERATION * t * t, 0.5 * SPEED * ramp + SPEED * (t - ramp))


def case_dict(scheme=None, dt=None) -> dict:
    c, b = CABLE, BODY
    line = dict(diameter=c["diameter"], mass=c["mass"], axial_stiffness=c["ea"], axial_damping=c["damping"],
                added_mass=RHO * math.pi * c["diameter"] ** 2 / 4 * c["ca"], drag_normal=c["cd"],
                drag_tangential=c["ct"])
    body = dict(mass=b["mass"], net_buoyancy=(RHO * b["volume"] - b["mass"]) * G, drag_area=b["cda"],
                added_mass=b["ca"] * RHO * b["volume"], position=[0.0, 0.0, TOW_POINT[2] - c["length"]])
    simulation = dict(duration=DURATION, output_dt=SAMPLE)
    if scheme is not None:
        simulation["scheme"] = scheme
    if dt is not None:
        simulation["dt"] = SAMPLE / math.ceil(SAMPLE / dt - 1e-9)       # a whole number of steps per sample
    return dict(model="lumped", name="towed-500m", line_types={"cable": line}, bodies={"body": body},
                environment=dict(water_density=RHO),
                vessel=dict(tow_point=list(TOW_POINT),
                            track=[{"straight": {"speed": 0.0, "duration": 1e-6}},
                                   {"accelerate": {"to_speed": SPEED, "acceleration": ACCELERATION}},
                                   {"straight": {"duration": DURATION}}]),
                cables=[dict(name="tow", line_type="cable", length=c["length"], segments=c["segments"],
                             **{"from": "vessel"}, to="body")],
                simulation=simulation)


def moordyn_file(folder: Path) -> Path:
    c, b = CABLE, BODY
    bottom = TOW_POINT[2] - c["length"]
    text = f"""--------------------- MoorDyn Input File ------------------------------------
kanat benchmark: towed cable
---------------------- LINE TYPES ----------------------------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
cable  {c['diameter']}  {c['mass']}  {c['ea']}  {c['damping']}  0.0  {c['cd']}  {c['ca']}  {c['ct']}  0.0
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Coupled {TOW_POINT[0]}  {TOW_POINT[1]}  {TOW_POINT[2]}  0  0  0  0
2     Free    0.0  0.0  {bottom}  {b['mass']}  {b['volume']}  {b['cda']}  {b['ca']}
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     cable      1        2        {c['length']}     {c['segments']}       -
---------------------- OPTIONS -----------------------------------------
0          writeLog
{RHO}      rho
{G}        g
1000.0     WtrDpth
1.0e-4     dtM
1.0e-6     threshIC
600.0      TmaxIC
50.0       CdScaleIC
1.0        dtIC
1          disableOutput
1          disableOutTime
------------------------- need this line -------------------------------------
"""
    path = folder / "towed.txt"
    path.write_text(text)
    return path


# --- runs ------------------------------------------------------------------------------------------
def run_kanat(scheme=None, dt=None):
    """``(record (k, 4), stepping s, set-up s, scheme, dt)``: body position relative to the tow
    point and top tension every SAMPLE; record None if the run failed."""
    out = run(load_case(case_dict(scheme, dt)))
    s, ds = out.summary, out.dataset
    if out.status != "ok":
        return None, s.solver_time_s, s.setup_time_s, s.scheme, s.dt
    relative = ds.body_position.values[:, 0, :] - ds.vessel_position.values
    top = 0.5 * (ds.segment_tension.values[:, 0] + ds.segment_tension.values[:, 1])   # node 1, as MoorDyn
    return np.column_stack([relative, top]), s.solver_time_s, s.setup_time_s, s.scheme, s.dt


def run_moordyn(path, scheme, dt):
    """As :func:`run_kanat` for MoorDyn at time ``scheme`` and step ``dt``: ``(record, stepping s,
    initial conditions s)``."""
    with quiet():
        return _run_moordyn(path, scheme, dt)


def _run_moordyn(path, scheme, dt):
    start = time.perf_counter()
    system = moordyn.Create(str(path))
    moordyn.SetTimeScheme(system, scheme)
    moordyn.SetDt(system, IC_STEP)
    moordyn.Init(system, list(TOW_POINT), [0.0, 0.0, 0.0])
    moordyn.SetDt(system, dt)
    setup = time.perf_counter() - start
    line, body = moordyn.GetLine(system, 1), moordyn.GetPoint(system, 2)

    def sample(k):
        rel = np.array(moordyn.GetPointPos(body)) - np.array([tow_x(k * COUPLING), TOW_POINT[1], TOW_POINT[2]])
        return [*rel, np.linalg.norm(moordyn.GetLineNodeTen(line, 1))]      # node 1: next to the tow point

    per = int(round(SAMPLE / COUPLING))
    steps = int(round(DURATION / COUPLING))
    xs = tow_x(np.arange(steps + 1) * COUPLING)
    record = [sample(0)]
    start = time.perf_counter()
    for k in range(steps):
        velocity = (xs[k + 1] - xs[k]) / COUPLING
        try:
            moordyn.Step(system, [float(xs[k]), TOW_POINT[1], TOW_POINT[2]], [velocity, 0.0, 0.0], k * COUPLING,
                         COUPLING)
        except Exception:                                      # MoorDyn raises on NaN
            return None, time.perf_counter() - start, setup
        if (k + 1) % per == 0:
            record.append(sample(k + 1))
    wall = time.perf_counter() - start
    moordyn.Close(system)
    record = np.array(record, dtype=float)
    return (record if np.all(np.isfinite(record)) else None), wall, setup


# --- comparison ------------------------------------------------------------------------------------
def errors(record, reference) -> tuple[float, float]:
    """Largest differences after the start: body position over its range of motion, top tension
    over its largest value (fractions). Both codes start from their equilibrium; MoorDyn's node
    tensions are first computed by its first step, so the start is left out."""
    span = np.max(np.linalg.norm(reference[:, :3] - reference[0, :3], axis=1))
    position = np.max(np.linalg.norm(record[1:, :3] - reference[1:, :3], axis=1)) / span
    tension = np.max(np.abs(record[1:, 3] - reference[1:, 3])) / np.max(reference[1:, 3])
    return float(position), float(tension)


def best(runs, reference, repeats):
    """The first stable run within TOLERANCE among ``runs`` (label, step, callable returning
    ``(record, stepping, setup, ...)``), largest step first — the fastest of a scheme — timed
    best of ``repeats``, and the largest stable one whatever its error: two rows (or None)."""
    stable = None
    for label, step, go in runs:
        first = go()
        if first[0] is None:
            continue
        err = errors(first[0], reference)
        row = dict(label=label, step=step, error=err, stepping=first[1], setup=first[2])
        stable = stable or row
        if max(err) > TOLERANCE:
            continue
        row["stepping"] = min([first[1]] + [go()[1] for _ in range(repeats - 1)])
        return row, stable
    return None, stable


def benchmark(repeats: int, quick: bool):
    folder = Path(tempfile.mkdtemp())
    path = moordyn_file(folder)
    net = build_network(load_case(case_dict()))
    safe = step_info(net, net.x_guess).safe_step(get_scheme("rk4", SCHEMES))
    references = {"kanat": run_kanat("rk4", safe / 4)[0], "MoorDyn": run_moordyn(path, "RK4", safe / 4)[0]}
    agree = errors(references["kanat"], references["MoorDyn"])
    run_kanat("generalized-alpha-lumped", 0.5)                        # compile before timing
    rows = []
    grid = [safe * 2.0 ** (k / 4.0) for k in range(8, -9, -1 if not quick else -2)]     # largest first
    for scheme in ("RK2", "RK4"):
        row, stable = best([(scheme, h, (lambda h=h, s=scheme: run_moordyn(path, s, h))) for h in grid],
                           references["MoorDyn"], repeats)
        rows.append(("MoorDyn", scheme, row))
        if stable is not row:
            rows.append(("MoorDyn", f"{scheme}, largest stable step (less accurate)", stable))
    default = run_kanat()
    rows.append(("kanat", f"default ({default[3]}, dt {default[4]:.3g} s)",
                 best([("default", default[4], run_kanat)], references["kanat"], repeats)[0]))
    rows.append(("kanat", "rk4", best([("rk4", h, (lambda h=h: run_kanat("rk4", h))) for h in grid if h <= safe],
                                      references["kanat"], repeats)[0]))
    implicit = [1.0, 0.5, 0.25, 0.1, 0.05]
    rows.append(("kanat", "generalized-alpha-lumped",
                 best([("implicit", h, (lambda h=h: run_kanat("generalized-alpha-lumped", h))) for h in implicit],
                      references["kanat"], repeats)[0]))
    return rows, agree, safe


def table(rows) -> str:
    md = [r for c, scheme, r in rows if c == "MoorDyn" and r is not None and "largest" not in scheme]
    best_md = min(r["stepping"] for r in md)
    out = ["| code | scheme | step [s] | body position error | top tension error | stepping [s] | set-up [s] "
           "| vs MoorDyn's best |", "|---|---|---|---|---|---|---|---|"]
    for code, scheme, r in rows:
        if r is None:
            out.append(f"| {code} | {scheme} | unstable or > {TOLERANCE:.0%} at every step tried | | | | | |")
            continue
        out.append(f"| {code} | {scheme} | {r['step']:.3g} | {r['error'][0]:.1e} | {r['error'][1]:.1e} | "
                   f"{r['stepping']:.3f} | {r['setup']:.2f} | {best_md / r['stepping']:.1f}x |")
    return "\n".join(out)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="one timing per run, a coarser step grid")
    args = parser.parse_args(argv)
    rows, agree, safe = benchmark(1 if args.quick else REPEATS, args.quick)
    print(f"\nTowed cable: {CABLE['length']:g} m, {CABLE['segments']} segments, {DURATION:g} s; kanat's explicit "
          f"safe step {safe:.3g} s; the two codes' references differ by {agree[0]:.2%} (body position) and "
          f"{agree[1]:.2%} (top tension) of the ranges of motion\n")
    print(table(rows))


if __name__ == "__main__":
    main()
