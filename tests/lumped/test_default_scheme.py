"""The default lumped scheme's choice in driven and wave-loaded runs (:mod:`kanat.lumped.stepping`).

* eq. (8), the period error and algorithmic damping of the lumped generalized-alpha scheme, against
  the trapezoidal rule's closed form ``omega_h h = 2 arctan(omega h / 2)`` (``rho_inf = 1``) and
  against a free vibration integrated step by step with the scheme's own coefficients;
* eq. (7), the shortest period of a spectrum without its tail under 1 % of the variance, against
  harmonics placed on either side of the threshold and against the continuous JONSWAP spectrum's
  tail integral (the sea's discretization is within two of its bins);
* the three-leg storm of benchmarks/bench_storm_moordyn.py (slow): the default scheme is now the
  implicit one, at 80 steps per 3.93 s, and its fairlead tensions agree with rk4 at its safe step.
"""
import math
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy import integrate, optimize

from kanat.lumped import stepping
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.physics.waves import jonswap_sea

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("steps", [10.0, 40.0, 80.0, 400.0])
def test_the_trapezoidal_member_has_the_closed_form_period(steps):
    big = 2.0 * math.pi / steps
    elongation, damping = stepping.period_error(steps, rho_inf=1.0)
    assert elongation == pytest.approx(big / (2.0 * math.atan(0.5 * big)) - 1.0, rel=1e-9, abs=1e-11)
    assert abs(damping) < 1e-12


def free_vibration(steps, rho_inf, periods=40):
    """``x'' = -x`` from ``x = 1`` by generalized-alpha (Chung & Hulbert 1993, eqs. 2-4, ``alpha_f = 0``)
    at ``steps`` a period: the period (least-squares slope of the upward zero crossings, interpolated)
    and the amplitude's decay a period (slope of the log of the velocity at those crossings)."""
    am, af, gamma, beta = GeneralizedAlphaLumped(lambda_inf=-rho_inf).coefficients
    h = 2.0 * math.pi / steps
    x, v, a = 1.0, 0.0, -1.0
    xs, vs = [x], [v]
    for _ in range(int(periods * steps)):
        # (1 - am) a1 + am a + x1 = 0 with x1 = x + h v + h^2 ((1/2 - beta) a + beta a1)
        predictor = x + h * v + h * h * (0.5 - beta) * a
        a1 = -(am * a + predictor) / (1.0 - am + beta * h * h)
        x, v, a = predictor + beta * h * h * a1, v + h * ((1.0 - gamma) * a + gamma * a1), a1
        xs.append(x)
        vs.append(v)
    xs, vs = np.array(xs), np.array(vs)
    t = h * np.arange(len(xs))
    up = np.flatnonzero((xs[:-1] < 0.0) & (xs[1:] >= 0.0))
    crossings = t[up] - xs[up] * h / (xs[up + 1] - xs[up])
    period = float(np.polyfit(np.arange(len(crossings)), crossings, 1)[0])
    share = -xs[up] / (xs[up + 1] - xs[up])
    speed = vs[up] + share * (vs[up + 1] - vs[up])           # amplitude x frequency at each crossing
    decay = 1.0 - math.exp(np.polyfit(np.arange(len(speed)), np.log(speed), 1)[0])
    return period / (2.0 * math.pi) - 1.0, decay


@pytest.mark.parametrize("steps", [20.0, 40.0, 80.0])
def test_the_period_error_is_that_of_a_free_vibration(steps):
    """Eq. (8) at the lumped default ``rho_inf = 0.5``: the elongation within 2 % of the one measured,
    the decay a (discrete) period ``1 - exp(-2 pi xi / sqrt(1 - xi^2))`` within 2 %."""
    elongation, damping = stepping.period_error(steps, rho_inf=0.5)
    measured, decay = free_vibration(steps, 0.5)
    assert elongation == pytest.approx(measured, rel=0.02)
    expected = 1.0 - math.exp(-2.0 * math.pi * damping / math.sqrt(1.0 - damping**2))
    assert decay == pytest.approx(expected, rel=0.02)


@pytest.mark.parametrize("share, kept", [(0.005, False), (0.02, True)])
def test_a_harmonic_under_one_percent_of_the_variance_does_not_set_the_period(share, kept):
    """Two harmonics of 10 s and 3 s; the short one holds ``share`` of the variance."""
    small = math.sqrt(share / (1.0 - share))
    period = stepping.shortest_period(2.0 * math.pi / np.array([10.0, 3.0]), [1.0, small])
    assert period == pytest.approx(3.0 if kept else 10.0, rel=1e-12)


def test_a_zero_amplitude_spectrum_has_no_period():
    assert stepping.shortest_period([1.0, 2.0], [0.0, 0.0]) is None


def test_the_jonswap_tail_is_the_continuous_spectrums():
    """The sea of the storm benchmark (Hs 6 m, Tp 11 s, gamma 3.3, 200 components): eq. (7)'s cut
    frequency within two bins of the continuous spectrum's, ``int_wc^top S = 0.01 int_band S``
    (JONSWAP with DNV's normalisation, sigma 0.07 / 0.09, written out here)."""
    hs, tp, gamma = 6.0, 11.0, 3.3
    wp = 2.0 * math.pi / tp

    def spectrum(w):
        sigma = 0.07 if w <= wp else 0.09
        pm = 5.0 / 16.0 * hs**2 * wp**4 / w**5 * math.exp(-1.25 * (wp / w) ** 4)
        return (1.0 - 0.287 * math.log(gamma)) * pm * gamma ** math.exp(-((w - wp) ** 2) / (2.0 * sigma**2 * wp**2))

    sea = jonswap_sea(hs, tp, gamma, seed=7)
    bottom, top = sea.omega.min(), sea.omega.max()
    total = integrate.quad(spectrum, bottom, top, points=[wp], limit=200)[0]
    cut = optimize.brentq(lambda w: integrate.quad(spectrum, w, top, limit=200)[0] - 0.01 * total, wp, top)
    bin_width = (top - bottom) / (len(sea.omega) - 1)
    found = 2.0 * math.pi / stepping.shortest_period(sea.omega, sea.amplitude)
    assert abs(found - cut) < 2.0 * bin_width
    assert 2.0 * math.pi / cut == pytest.approx(3.93, abs=0.1)


@pytest.mark.slow
def test_the_storm_runs_implicit_by_default_and_agrees_with_rk4(tmp_path):
    """The storm benchmark's case, 40 s: the default is generalized-alpha at 0.5 / 51 s (400 steps
    per 3.93 s, fitted to the output interval), and its fairlead tensions over 15-40 s agree with rk4 at its safe step (mean
    within 1 %, standard deviation and maximum within 3 %)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import bench_storm_moordyn as storm
    from kanat import api
    from kanat.io import load_case

    def run(scheme):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = api.run(load_case(storm.write_case(tmp_path, 40.0, scheme)))
        ds = result.dataset
        assert ds.attrs["status"] == "ok"
        tops = [int(np.flatnonzero(ds.segment_cable.values == c)[-1]) for c in np.unique(ds.segment_cable.values)]
        window = ds.time.values >= 15.0
        return ds, ds.segment_tension.values[window][:, tops]

    ours, tension = run("default")
    assert ours.attrs["scheme"] == "generalized-alpha-lumped"
    assert float(ours.attrs["dt"]) == pytest.approx(0.5 / 51.0, rel=1e-9)
    _, reference = run("rk4")
    assert np.abs(tension.mean(0) / reference.mean(0) - 1.0).max() < 0.01
    assert np.abs(tension.std(0) / reference.std(0) - 1.0).max() < 0.03
    assert np.abs(tension.max(0) / reference.max(0) - 1.0).max() < 0.03
