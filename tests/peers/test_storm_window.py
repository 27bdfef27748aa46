"""The storm benchmark's window (benchmarks/bench_storm_moordyn.py ``--window``): the statistics of
the first part of a kept long run, beside a shorter run of another code.

Oracles: the windowed statistics are numpy's mean, standard deviation and maximum of the samples
picked by hand from the window (and the Rayleigh MPM of those same samples); the kept run chosen
for a window is the one of the asked duration if kept, else the shortest kept run covering it.
"""
import sys

import numpy as np
import pytest

from helpers import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
import bench_storm_moordyn as bench  # noqa: E402

from kanat.analysis.extremes import mpm  # noqa: E402

CONFIG = ("kanat", "default", None)


def _series(duration: float, dt: float = 0.5) -> np.ndarray:
    """Time and three random tensions [N], rows every ``dt`` from 0 to ``duration`` s."""
    rng = np.random.default_rng(3)
    t = np.arange(0.0, duration + 0.5 * dt, dt)
    return np.column_stack([t] + [1e6 * (k + 1) + 1e4 * rng.standard_normal(t.size) for k in range(3)])


def test_windowed_statistics_are_those_of_the_window_samples():
    series = _series(3000.0)
    found = bench.statistics(series, 200.0, 600.0)
    picked = series[(series[:, 0] >= 200.0) & (series[:, 0] <= 600.0)]
    assert picked.shape[0] == 801                        # 200 s to 600 s every 0.5 s, both ends
    for leg in range(3):
        values = picked[:, leg + 1]
        expected = [values.mean(), values.std(), values.max(),
                    float(mpm(values, picked[:, 0], bench.STORM, "rayleigh"))]
        np.testing.assert_allclose(found[leg], expected, rtol=1e-12)
    assert not np.allclose(found, bench.statistics(series, 200.0))     # the rest of the run left out


def test_a_window_uses_the_shortest_kept_run_covering_it(tmp_path):
    for duration in (600.0, 1800.0, 10800.0):
        bench.save_runs(tmp_path, CONFIG, duration, [(1.0, duration / 10, 0.5, _series(duration), {"dt": 0.1})])
    runs, covered = bench.stored_runs(tmp_path, CONFIG, 600.0, 600.0)
    assert covered == 600.0 and runs[0][3][-1, 0] == pytest.approx(600.0)
    runs, covered = bench.stored_runs(tmp_path, CONFIG, 900.0, 700.0)
    assert covered == 1800.0 and runs[0][1] == pytest.approx(180.0)
    assert bench.stored_runs(tmp_path, CONFIG, 900.0) == ([], 900.0)          # no window: the duration's own
    assert bench.stored_runs(tmp_path, CONFIG, 20000.0, 20000.0) == ([], 20000.0)
