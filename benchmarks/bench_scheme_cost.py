"""What an implicit step costs against RK4's force evaluations: the calibration of the default
scheme's cost model (``kanat.lumped.stepping``, eq. 6: ``IMPLICIT_ITERATIONS``, ``IMPLICIT_COST``).

Each case runs in this process with ``simulation.scheme: rk4`` (its safe step) and with the implicit
scheme at its default step, after a 1 s run of each that loads the kernels; the stepping time is the
run's own ``solver_time_s`` (wall time of the steps alone; run it on a quiet machine), its force
evaluations the run's ``force_evaluations``. An RK4 evaluation's cost is ``solver / evaluations``;
an implicit step's cost in those evaluations is ``(solver / steps) / (RK4's cost of an evaluation)``,
of which ``evaluations / steps`` are its own force evaluations and the rest its tangent's work (band
factors, kept over steps and rebuilt every few, and a substitution per iteration).

Cases: the three-leg chain of ``bench_mooring_moordyn.py`` (driven, 100 s), MoorDyn's WD0050 chain
of ``bench_wd0050_moordyn.py`` (driven, seabed friction 0.5, 40 s), ``examples/lazy_wave.yaml``
(30 s) and Bezverkhyi's trawl ``examples/trawl_head_8s_1to2.yaml`` (in waves, 20 s).

Run: ``python benchmarks/bench_scheme_cost.py``; prints the Markdown table kept in
benchmarks/RESULTS.md (about a minute).
"""
from __future__ import annotations

import sys
import tempfile
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_mooring_moordyn  # noqa: E402
import bench_wd0050_moordyn  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def cases(folder: Path) -> dict:
    from kanat.io import load_case

    return {"three-leg chain, driven (100 s)": load_case(bench_mooring_moordyn.kanat_case(folder, "default", None, 100.0)),
            "WD0050 chain, driven, friction 0.5 (40 s)": load_case(bench_wd0050_moordyn.kanat_case(folder, "default", 40.0)),
            "lazy wave (30 s)": load_case(ROOT / "examples" / "lazy_wave.yaml").replace({"simulation.duration": 30.0}),
            "trawl in waves (20 s)": load_case(ROOT / "examples" / "trawl_head_8s_1to2.yaml").replace(
                {"simulation.duration": 20.0})}


def measure(case, scheme: str) -> tuple[float, float, int, float]:
    """Stepping time [s], step [s], force evaluations and simulated time of ``case`` under ``scheme``."""
    import kanat

    case = case.replace({"simulation.scheme": scheme, "simulation.dt": None})
    kanat.simulate(case.replace({"simulation.duration": 1.0}))           # kernels loaded, nothing compiled later
    attrs = kanat.simulate(case).attrs
    return attrs["solver_time_s"], attrs["dt"], int(attrs["force_evaluations"]), case.simulation.duration


def main() -> None:
    warnings.simplefilter("ignore")
    print("| case | RK4: step [s], stepping [s], us per evaluation | implicit: step [s], stepping [s], "
          "evaluations per step | implicit step in RK4 evaluations | of which the tangent's work |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for name, case in cases(Path(folder)).items():
            rk4_time, rk4_dt, rk4_evaluations, _ = measure(case, "rk4")
            time, dt, evaluations, duration = measure(case, "generalized-alpha-lumped")
            evaluation = rk4_time / rk4_evaluations
            steps = duration / dt
            per_step = time / steps / evaluation
            print(f"| {name} | {rk4_dt:.3g}, {rk4_time:.2f}, {1e6 * evaluation:.1f} | {dt:.3g}, {time:.2f}, "
                  f"{evaluations / steps:.2f} | {per_step:.1f} | {per_step - evaluations / steps:.1f} |")


if __name__ == "__main__":
    main()
