"""Spectral fatigue and extremes (kanat.analysis.spectral) against closed forms, numerical
integration, and the rainflow count and maxima of long synthetic Gaussian records made from the
same spectra.

The records are random-phase superpositions (``x(t) = sum a_k cos(omega_k t + phi_k)``,
``a_k = sqrt(2 S(omega_k) d omega)``, uniform phases, summed by an inverse FFT) of two spectra:
a JONSWAP sea (Tp 10 s, gamma 7) cut at 1.6 rad/s, narrow (bandwidth 0.51), and a bimodal swell +
wind sea, broad (bandwidth 0.85). Four seeds of 3 hours each are counted by
:func:`kanat.analysis.fatigue.rainflow`; the seeds' damage rates scatter by about 1 % (m = 3)
to 3 % (m = 5), and the tolerances below are the measured method errors plus that scatter.
"""
import math

import numpy as np
import pytest
from scipy import integrate, optimize, special, stats

from kanat.analysis import fatigue, spectral
from kanat.catalog import chain_reference_breaking_load
from kanat.errors import KanatError
from kanat.physics.waves import JONSWAP_BAND, jonswap_sea

from helpers import scatter_of_mean_square

OMEGA = np.linspace(0.05, 3.0, 3000)


def jonswap(omega, hs, tp, gamma):
    """JONSWAP spectrum [m^2 s/rad] (DNV-RP-C205 §3.5.5, with its normalising factor)."""
    wp = 2.0 * np.pi / tp
    sigma = np.where(omega <= wp, 0.07, 0.09)
    peak = np.exp(-((omega - wp) ** 2) / (2.0 * sigma**2 * wp**2))
    return (5.0 / 16.0 * hs**2 * wp**4 * omega**-5.0 * np.exp(-1.25 * (wp / omega) ** 4)
            * gamma**peak * (1.0 - 0.287 * np.log(gamma)))


SPECTRA = {
    "narrow": np.where(OMEGA <= 1.6, jonswap(OMEGA, 1.0, 10.0, 7.0), 0.0),
    "bimodal": jonswap(OMEGA, 1.0, 14.0, 3.3) + 0.6 * jonswap(OMEGA, 0.6, 4.0, 2.0),
}


def record(spectrum, duration, dt, seed):
    """A random-phase Gaussian record of ``spectrum`` over OMEGA, periodic over ``duration``."""
    rng = np.random.default_rng(seed)
    n = int(round(duration / dt))
    d_omega = 2.0 * np.pi / (n * dt)
    omega_k = np.arange(n // 2 + 1) * d_omega
    amplitude = np.sqrt(2.0 * np.interp(omega_k, OMEGA, spectrum, left=0.0, right=0.0) * d_omega)
    phase = rng.uniform(0.0, 2.0 * np.pi, omega_k.size)
    return np.fft.irfft(amplitude * np.exp(1j * phase) * n / 2.0, n)


def rainflow_rate(x, exponent, intercept, duration):
    cycles = fatigue.rainflow(x)
    return float(np.sum(cycles[:, 2] * cycles[:, 0] ** exponent) / intercept / duration)


@pytest.fixture(scope="module")
def records():
    return {name: [record(s, 3 * 3600.0, 0.05, seed) for seed in range(4)] for name, s in SPECTRA.items()}


def test_moments_rates_and_bandwidth_of_a_known_spectrum():
    # a rectangular spectrum of height 1 on [1, 2] rad/s: m_n = (2^(n+1) - 1) / (n + 1)
    omega = np.linspace(1.0, 2.0, 20001)
    moments = spectral.spectral_moments(omega, np.ones_like(omega))
    exact = [(2.0 ** (n + 1) - 1.0) / (n + 1) for n in (0, 1, 2, 4)]
    np.testing.assert_allclose([moments.m0, moments.m1, moments.m2, moments.m4], exact, rtol=1e-8)
    assert moments.upcrossing_rate == pytest.approx(math.sqrt(exact[2] / exact[0]) / (2 * math.pi))
    assert moments.peak_rate == pytest.approx(math.sqrt(exact[3] / exact[2]) / (2 * math.pi))
    assert moments.bandwidth == pytest.approx(math.sqrt(1 - exact[2] ** 2 / (exact[0] * exact[3])))


@pytest.mark.parametrize("exponent", [3.0, 3.36, 4.09, 5.05])
def test_narrow_band_damage_is_its_gamma_function_closed_form_integrated(exponent):
    # the closed form against the Rayleigh range density integrated numerically
    moments = spectral.spectral_moments(OMEGA, SPECTRA["narrow"])
    sigma = moments.std
    rayleigh = lambda s: s / (4 * sigma**2) * math.exp(-s * s / (8 * sigma**2))  # noqa: E731
    expected, _ = integrate.quad(lambda s: s**exponent * rayleigh(s), 0, 60 * sigma, limit=200)
    closed = spectral.narrow_band_damage_rate(moments, exponent, 2.0)
    assert closed == pytest.approx(moments.upcrossing_rate * expected / 2.0, rel=1e-9)
    assert closed == pytest.approx(moments.upcrossing_rate / 2.0 * (2 * math.sqrt(2 * moments.m0)) ** exponent
                                   * special.gamma(1 + exponent / 2), rel=1e-12)


@pytest.mark.parametrize("name", list(SPECTRA))
def test_dirlik_density_is_a_density_and_its_closed_form_its_moment(name):
    moments = spectral.spectral_moments(OMEGA, SPECTRA[name])
    top = 40 * moments.std
    total, _ = integrate.quad(lambda s: float(spectral.dirlik_range_density(s, moments)), 0, top, limit=200)
    assert total == pytest.approx(1.0, abs=1e-8)
    for m in (3.0, 4.8):
        moment, _ = integrate.quad(lambda s: s**m * float(spectral.dirlik_range_density(s, moments)), 0, top,
                                   limit=200)
        assert spectral.dirlik_damage_rate(moments, m, 1.0) == pytest.approx(moments.peak_rate * moment, rel=1e-7)


# measured (4 seeds x 3 h): narrow: Dirlik / rainflow 0.990 (m = 3) and 1.009 (m = 5), narrow-band
# 1.022 and 1.043; bimodal: Dirlik 0.949 and 0.918, narrow-band 1.147 and 1.128 (conservative, as
# it should be for a broad band)
@pytest.mark.parametrize("name, exponent, dirlik_tol, narrow_band_range", [
    ("narrow", 3.0, 0.04, (1.0, 1.08)),
    ("narrow", 5.0, 0.06, (1.0, 1.10)),
    ("bimodal", 3.0, 0.08, (1.08, 1.22)),
    ("bimodal", 5.0, 0.12, (1.05, 1.22)),
])
def test_spectral_damage_against_rainflow_of_synthetic_records(records, name, exponent, dirlik_tol,
                                                               narrow_band_range):
    moments = spectral.spectral_moments(OMEGA, SPECTRA[name])
    counted = np.mean([rainflow_rate(x, exponent, 1.0, 3 * 3600.0) for x in records[name]])
    dirlik = spectral.dirlik_damage_rate(moments, exponent, 1.0)
    narrow = spectral.narrow_band_damage_rate(moments, exponent, 1.0)
    assert dirlik / counted == pytest.approx(1.0, abs=dirlik_tol)
    assert narrow_band_range[0] <= narrow / counted <= narrow_band_range[1]


def test_tension_and_stress_curves_are_those_of_the_time_domain_fatigue(records):
    # a tension record about 1.5 MN of the narrow spectrum scaled to a std of 0.1 MN
    mbl = chain_reference_breaking_load(0.076)
    moments = spectral.spectral_moments(OMEGA, SPECTRA["narrow"])
    scale = 1.0e5 / moments.std
    tension = 1.5e6 + scale * np.concatenate(records["narrow"])
    duration = 4 * 3 * 3600.0
    for curve in ("api-chain-studless", "api-wire-six-strand"):
        counted = fatigue.damage(tension, mbl, curve) / duration
        found = spectral.tension_damage_rate(moments.scaled(scale), mbl, curve, mean_tension=1.5e6)
        assert found == pytest.approx(counted, rel=0.04)
    area = math.pi * 0.076**2 / 2
    counted = fatigue.stress_damage(tension / area, "dnv-chain-studless") / duration
    assert spectral.stress_damage_rate(moments.scaled(scale / area), "dnv-chain-studless") == \
        pytest.approx(counted, rel=0.04)


def test_clh_maxima_distribution_limits():
    eta = np.linspace(0.1, 5, 50)
    np.testing.assert_allclose(spectral.maxima_cdf(eta, 1e-9), 1 - np.exp(-eta**2 / 2), atol=1e-12)
    np.testing.assert_allclose(spectral.maxima_cdf(eta, 0.999999), stats.norm.cdf(eta), atol=1e-3)
    for eps in (0.3, 0.7):
        grid = np.linspace(-8, 8, 20001)
        np.testing.assert_allclose(np.gradient(spectral.maxima_cdf(grid, eps), grid),
                                   spectral.maxima_density(grid, eps), atol=1e-6)
    # narrow band: the mode of the largest of N Rayleigh maxima solves
    # 1/eta - eta + (N - 1) eta e^(-eta^2/2) / (1 - e^(-eta^2/2)) = 0, near sqrt(2 ln N)
    n = 1.0e4
    root = optimize.brentq(lambda e: 1 / e - e + (n - 1) * e * math.exp(-e * e / 2) / -math.expm1(-e * e / 2), 2, 6)
    assert spectral.largest_maximum_mode(1e-9, n) == pytest.approx(root, rel=1e-7)
    assert root == pytest.approx(math.sqrt(2 * math.log(n)), rel=0.005)


# measured (400 records of 30 min, dt 0.05 s): the mode of a Gumbel fitted to the records'
# maxima is 2.1 % (narrow) and 1.4 % (bimodal) below the CLH MPM, 1.2 % and 0.6 % below the
# Rayleigh one (both assume independent maxima, so they err on the safe side)
@pytest.mark.parametrize("name", list(SPECTRA))
def test_mpm_against_the_maxima_of_synthetic_records(name):
    moments = spectral.spectral_moments(OMEGA, SPECTRA[name])
    duration = 1800.0
    maxima = [record(SPECTRA[name], duration, 0.05, 1000 + k).max() for k in range(400)]
    mode = stats.gumbel_r.fit(maxima)[0]
    clh = spectral.most_probable_maximum(moments, duration)
    rayleigh = spectral.most_probable_maximum(moments, duration, method="rayleigh")
    assert mode == pytest.approx(clh, rel=0.03)
    assert mode == pytest.approx(rayleigh, rel=0.03)
    assert spectral.most_probable_maximum(moments, duration, mean=5.0) == pytest.approx(5.0 + clh)


def test_bad_spectra_are_refused_with_the_reason():
    with pytest.raises(KanatError, match="increasing"):
        spectral.spectral_moments([1.0, 0.5], [1.0, 1.0])
    with pytest.raises(KanatError, match="negative"):
        spectral.spectral_moments([0.5, 1.0], [1.0, -1.0])
    with pytest.raises(KanatError, match="no energy"):
        spectral.spectral_moments([0.5, 1.0], [0.0, 0.0])
    moments = spectral.spectral_moments(OMEGA, SPECTRA["narrow"])
    with pytest.raises(KanatError, match="dirlik, narrow-band"):
        spectral.damage_rate(moments, 3.0, 1.0, "wirsching")
    with pytest.raises(KanatError, match="not a fatigue curve"):
        spectral.tension_damage_rate(moments, 1.0e6, "api-rope")


def test_a_welch_spectrum_in_hertz_gives_the_records_variance_and_damage(records):
    from scipy.signal import welch

    x = records["narrow"][0]
    frequency, psd = welch(x, fs=1 / 0.05, nperseg=8192)
    moments = spectral.spectral_moments(*spectral.from_hertz(frequency, psd))
    assert moments.m0 == pytest.approx(np.var(x), rel=0.03)   # measured 1.4 % (Welch estimate)
    counted = rainflow_rate(x, 3.0, 1.0, 3 * 3600.0)
    assert spectral.dirlik_damage_rate(moments, 3.0, 1.0) == pytest.approx(counted, rel=0.05)   # measured 0.994


def test_a_line_spectrum_has_the_moments_of_its_components():
    """A JONSWAP sea's 200 components (:func:`kanat.physics.waves.jonswap_sea`: unequally spaced,
    one drawn in each bin of width ``d omega``) as the line spectrum ``S_j = a_j^2 / (2 d omega)``
    with ``width = d omega``: ``m_0`` and ``m_2`` are ``sum a_j^2 / 2`` and ``sum (a_j omega_j)^2 / 2``
    to round-off, and a 3-hour record's mean squares of the elevation and of its rate agree with
    them within 3 standard deviations of their sampling scatter (``scatter_of_mean_square``)."""
    sea = jonswap_sea(3.0, 9.0, 3.3, seed=4)
    d_omega = (JONSWAP_BAND[1] - JONSWAP_BAND[0]) * 2.0 * np.pi / 9.0 / len(sea.omega)
    moments = spectral.spectral_moments(sea.omega, sea.amplitude**2 / (2.0 * d_omega), d_omega)
    assert moments.m0 == pytest.approx(np.sum(sea.amplitude**2) / 2, rel=1e-12)
    assert moments.m2 == pytest.approx(np.sum((sea.amplitude * sea.omega) ** 2) / 2, rel=1e-12)
    t = np.arange(0.0, 10800.0, 1.0)
    phase = np.multiply.outer(t, sea.omega) - sea.phase
    x, rate = np.cos(phase) @ sea.amplitude, -np.sin(phase) @ (sea.amplitude * sea.omega)
    assert abs(np.mean(x**2) - moments.m0) < 3 * scatter_of_mean_square(sea.amplitude, sea.omega, t)
    assert abs(np.mean(rate**2) - moments.m2) < 3 * scatter_of_mean_square(sea.amplitude * sea.omega, sea.omega, t)
    with pytest.raises(KanatError, match="widths must be positive"):
        spectral.spectral_moments(sea.omega, sea.amplitude**2, 0.0)
