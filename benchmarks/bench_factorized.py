"""Kaliukh & Vusatiuk's schemes against the generalized-α box scheme: cost per step and time to accuracy.

1. Per-step cost (median of repeats, ms) of every scheme on the planar 1000 m towed-body
   speed step (examples/speed_step_2d.yaml) at 10, 100 and 1000 segments, dt = 0.01 s, and of
   the spatial splits on the 360 deg turn (examples/turn_360_3d.yaml) at 10 and 100.
2. Time to the same accuracy: for each scheme, the cheapest (segments, dt) among a grid of
   choices whose answer is within the target of a converged reference (generalized-α, 160
   segments, small step):
   - planar 80 m tow (examples/factorization_planar80.yaml): top tension at t = 24 s within 1 %;
   - accelerating vehicle (examples/factorization_accel.yaml): body position at t = 3 s within 5 mm
     (0.4 % of the cable length).

Run: ``python benchmarks/bench_factorized.py`` (after ``pip install -e .``); prints markdown.
"""
from __future__ import annotations

import platform
import statistics
import time
from pathlib import Path

import numpy as np

from kanat.continuum.models import model_for
from kanat.continuum.schemes import (
    Factorized,
    Factorized4,
    GeneralizedAlpha,
    WaveFactorized,
    WaveFactorized2,
    WaveFactorized3,
)
from kanat.studies.factorization import body_relative
from kanat.continuum.stepper import NewtonFailure
from kanat.io import parse_case

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
PLANAR = {"generalized-alpha": GeneralizedAlpha(), "factorized": Factorized(), "factorized (delta)": Factorized(delta=True),
          "factorized-4": Factorized4(), "wave-factorized (gamma 0.6)": WaveFactorized(gamma=0.6)}
SPATIAL = {"generalized-alpha": GeneralizedAlpha(), "wave-factorized-2 (gamma 0.6)": WaveFactorized2(gamma=0.6),
           "wave-factorized-3 (gamma 0.6)": WaveFactorized3(gamma=0.6)}
SEGMENTS = (5, 10, 20, 40, 80, 160)
COST_DT = 0.01


def per_step_ms(model, scheme, dt, steps=20, repeats=5):
    """Median wall time of one step [ms] (nan when the scheme cannot take these steps)."""
    state = model.initial()
    try:
        state, _ = scheme.step(model, state, dt)                 # compile and warm up
        runs = []
        for _ in range(repeats):
            s, start = state, time.perf_counter()
            for _ in range(steps):
                s, _ = scheme.step(model, s, dt)
            runs.append((time.perf_counter() - start) / steps * 1e3)
    except NewtonFailure:
        return np.nan
    return statistics.median(runs)


def cost_table():
    print(f"### Cost per step [ms] (median of 5 x 20 steps, dt = {COST_DT} s)\n")
    print("| case | segments | " + " | ".join(PLANAR) + " |\n|---|---|" + "---|" * len(PLANAR))
    text = (EXAMPLES / "speed_step_2d.yaml").read_text()
    for n in (10, 100, 1000):
        model = model_for(parse_case(text.replace("segments: 100", f"segments: {n}")))
        row = [per_step_ms(model, s, COST_DT) for s in PLANAR.values()]
        print(f"| 1000 m tow, speed step (2-D) | {n} | " + " | ".join(f"{v:.2f}" for v in row) + " |")
    print("\n| case | segments | " + " | ".join(SPATIAL) + " |\n|---|---|" + "---|" * len(SPATIAL))
    text = (EXAMPLES / "turn_360_3d.yaml").read_text()
    for n in (10, 100):
        model = model_for(parse_case(text.replace("segments: 100", f"segments: {n}")))
        row = [per_step_ms(model, s, COST_DT) for s in SPATIAL.values()]
        print(f"| 1000 m tow, 360 deg turn (3-D) | {n} | " + " | ".join(f"{v:.2f}" for v in row) + " |")


def run_case(text, segments, scheme, dt, until, measure):
    case = parse_case(text.replace("segments: 10,", f"segments: {segments},").replace("segments: 24,",
                                                                                      f"segments: {segments},"))
    model = model_for(case)
    state = model.initial()
    start = time.perf_counter()
    try:
        for _ in range(round(until / dt)):
            state, _ = scheme.step(model, state, dt)
    except Exception:                                            # noqa: BLE001 - a failed choice is no answer
        return np.nan, time.perf_counter() - start
    return measure(state, model), time.perf_counter() - start


def time_to_accuracy(label, text, until, measure, error, target, dts, reference_dt):
    reference, _ = run_case(text, 160, GeneralizedAlpha(), reference_dt, until, measure)
    print(f"\n### Time to accuracy: {label} (target {target})\n")
    print("| scheme | cheapest (segments, dt) | its error | wall time [s] |\n|---|---|---|---|")
    for name, scheme in PLANAR.items():
        best = None
        for n in SEGMENTS:
            for dt in dts:
                value, wall = run_case(text, n, scheme, dt, until, measure)
                err = error(value, reference)
                if np.isfinite(err) and err <= target and (best is None or wall < best[3]):
                    best = (n, dt, err, wall)
        if best is None:
            print(f"| {name} | none up to {SEGMENTS[-1]} segments | | |")
        else:
            print(f"| {name} | ({best[0]}, {best[1]:g} s) | {best[2]:.3g} | {best[3]:.3f} |")


def main():
    print(f"machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}\n")
    cost_table()
    planar = (EXAMPLES / "factorization_planar80.yaml").read_text()
    time_to_accuracy("planar 80 m tow, top tension at t = 24 s", planar, 24.0, lambda s, m: s.y[0, 0],
                     lambda v, r: abs(v / r - 1), 0.01, (0.01, 0.1, 1.0, 4.0), 0.01)
    accel = (EXAMPLES / "factorization_accel.yaml").read_text()
    time_to_accuracy("accelerating vehicle, body position at t = 3 s", accel, 3.0, body_relative,
                     lambda v, r: float(np.max(np.abs(np.asarray(v) - r))), 0.005, (0.0005, 0.002, 0.01, 0.05),
                     0.0005)


if __name__ == "__main__":
    main()
