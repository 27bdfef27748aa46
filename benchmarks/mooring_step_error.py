"""Where the implicit scheme's step error goes on the three-leg chain mooring of
``bench_mooring_moordyn.py``: kanat's own runs at several steps against its run at 3.125 ms.

Same file, motion and scheme as ``bench_mooring_moordyn.py``, 300 s simulated, outputs every
0.05 s (the benchmark's 0.5 s outputs sample the peaks more coarsely). For each step: the largest
relative error of the fairlead-segment tension's mean and range over 150-300 s. For the
reference: the frequency of the largest spectral peak above 0.5 Hz of its tension less a 1 s
moving average, and the fraction of the time that high-passed tension exceeds 2 kN (the bursts).

Run: ``python benchmarks/mooring_step_error.py`` (about a minute); prints the figures kept in
benchmarks/RESULTS.md.
"""
from __future__ import annotations

import warnings

import numpy as np

import kanat
from kanat.io import load_case

from bench_mooring_moordyn import FILE, MOTION

DURATION, OUTPUT, WINDOW = 300.0, 0.05, 150.0
REFERENCE, STEPS = 0.003125, (0.0125, 0.025, 0.05)


def fairlead_tensions(dt: float) -> np.ndarray:
    """Time and the three fairlead-segment tensions (k, 4) of a run at step ``dt``."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                       # the file's MoorDyn-only options
        case = load_case(FILE)
    case = case.replace({"vessel.motion": MOTION, "simulation.duration": DURATION,
                         "simulation.output_dt": OUTPUT, "simulation.scheme": "generalized-alpha-lumped",
                         "simulation.dt": dt})
    ds = kanat.run(case).dataset
    cables = ds.segment_cable.values
    ends = [int(np.flatnonzero(cables == name)[-1]) for name in ("line1", "line2", "line3")]
    return np.column_stack([ds.time.values] + [ds.segment_tension.values[:, k] for k in ends])


def mean_and_range(series: np.ndarray) -> np.ndarray:
    values = series[series[:, 0] >= WINDOW - 1e-9, 1:]
    return np.stack([values.mean(axis=0), values.max(axis=0) - values.min(axis=0)], -1)


def main() -> None:
    reference = fairlead_tensions(REFERENCE)
    expected = mean_and_range(reference)
    inside = reference[:, 0] >= WINDOW - 1e-9
    tension = reference[inside, 1]
    width = int(round(1.0 / OUTPUT))
    bursts = np.abs(tension - np.convolve(tension, np.ones(width) / width, mode="same"))
    bursts[:width] = bursts[-width:] = 0.0                 # the average's ends
    burst = bursts > 2000.0
    print("| step [s] | fairlead mean, max rel. diff. | range, max rel. diff. | line1's squared error in the bursts |")
    print("|---|---|---|---|")
    for dt in STEPS:
        series = fairlead_tensions(dt)
        diff = np.abs(mean_and_range(series) - expected) / expected
        error = (series[inside, 1] - tension) ** 2
        print(f"| {dt} | {100 * diff[:, 0].max():.3f} % | {100 * diff[:, 1].max():.2f} % | "
              f"{100 * error[burst].sum() / error.sum():.0f} % |")
    frequency = np.fft.rfftfreq(len(tension) - 2 * width, OUTPUT)
    power = np.abs(np.fft.rfft((tension - np.convolve(tension, np.ones(width) / width, mode="same"))[width:-width]))
    peak = frequency[frequency > 0.5][np.argmax(power[frequency > 0.5])]
    print(f"\nreference ({REFERENCE} s): line1's tension less its 1 s moving average peaks at {peak:.2f} Hz "
          f"({2 * np.pi * peak:.1f} rad/s); it exceeds 2 kN (the bursts) {100 * burst.mean():.0f} % of the time")


if __name__ == "__main__":
    main()
