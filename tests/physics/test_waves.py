"""Wave kinematics against the equations they must satisfy (Laplace, surface conditions,
dispersion) and the JONSWAP spectrum against its moments; a JONSWAP sea's records against the
spectrum within their sampling error, and against repeating within a storm."""
import math

import numpy as np
import pytest
from scipy.integrate import quad

from kanat.errors import KanatError
from kanat.physics.waves import JONSWAP_BAND, jonswap_sea, jonswap_spectrum, regular_wave, wavenumber

from helpers import scatter_of_mean_square

G = 9.81


@pytest.mark.parametrize("depth", [2.0, 20.0, 200.0, None])
def test_dispersion_relation_holds(depth):
    omega = np.array([0.3, 0.8, 1.4, 3.0])
    k = wavenumber(omega, G, depth)
    tanh = 1.0 if depth is None else np.tanh(k * depth)
    np.testing.assert_allclose(G * k * tanh, omega**2, rtol=1e-12)


def test_dispersion_limits_shallow_and_deep():
    omega = 0.05
    assert wavenumber([omega], G, 1.0)[0] == pytest.approx(omega / math.sqrt(G * 1.0), rel=1e-3)
    assert wavenumber([2.0], G, 500.0)[0] == pytest.approx(4.0 / G, rel=1e-12)


@pytest.mark.parametrize("depth", [15.0, None])
def test_velocity_is_divergence_and_curl_free_and_satisfies_the_surface_condition(depth):
    sea = regular_wave(2.0, 6.0, 30.0, depth=depth)
    p = np.array([[3.0, -2.0, -4.0]])
    h = 1e-4
    grad = np.empty((3, 3))
    for i in range(3):
        d = np.zeros(3)
        d[i] = h
        grad[:, i] = (sea.velocity(p + d, 1.3)[0] - sea.velocity(p - d, 1.3)[0]) / (2 * h)
    assert abs(np.trace(grad)) < 1e-7                           # continuity
    np.testing.assert_allclose(grad, grad.T, atol=1e-7)          # irrotational
    # kinematic free-surface condition of linear theory: w(z=0) = d eta / dt
    deta = (sea.elevation(3.0, -2.0, 1.3 + h) - sea.elevation(3.0, -2.0, 1.3 - h)) / (2 * h)
    assert sea.velocity([[3.0, -2.0, 0.0]], 1.3)[0, 2] == pytest.approx(deta, rel=1e-6)
    # dynamic condition via Bernoulli (linear): g eta = -d phi/dt at z=0 <=> u_t = -g d eta/dx
    deta_dx = (sea.elevation(3.0 + h, -2.0, 1.3) - sea.elevation(3.0 - h, -2.0, 1.3)) / (2 * h)
    assert sea.acceleration([[3.0, -2.0, 0.0]], 1.3)[0, 0] == pytest.approx(-G * deta_dx, rel=1e-6)


def test_acceleration_is_the_time_derivative_of_velocity():
    sea = jonswap_sea(3.0, 8.0, heading_deg=180.0, seed=3, depth=60.0)
    p = np.array([[0.0, 0.0, -5.0], [40.0, 3.0, -30.0]])
    h = 1e-4
    fd = (sea.velocity(p, 5.0 + h) - sea.velocity(p, 5.0 - h)) / (2 * h)
    np.testing.assert_allclose(sea.acceleration(p, 5.0), fd, rtol=1e-6, atol=1e-9)


def test_regular_wave_height_period_and_heading():
    sea = regular_wave(2.0, 5.6, 180.0)
    t = np.linspace(0, 5.6, 400, endpoint=False)
    eta = np.array([sea.elevation(0.0, 0.0, ti) for ti in t])
    assert eta.max() - eta.min() == pytest.approx(2.0, rel=1e-4)
    # travelling to -x: the crest at x=0 at t=0 is at x = -c dt a moment later
    c = 2 * math.pi / 5.6 / sea.k[0]
    assert sea.elevation(-c * 0.7, 0.0, 0.7) == pytest.approx(1.0, rel=1e-9)


def test_jonswap_has_the_requested_hs_peak_and_is_reproducible():
    sea = jonswap_sea(3.0, 8.0, 3.3, seed=7)
    assert 4.0 * math.sqrt(0.5 * np.sum(sea.amplitude**2)) == pytest.approx(3.0, rel=1e-12)
    assert 2 * math.pi / sea.omega[np.argmax(sea.amplitude)] == pytest.approx(8.0, rel=0.03)
    again = jonswap_sea(3.0, 8.0, 3.3, seed=7)
    np.testing.assert_array_equal(sea.phase, again.phase)
    np.testing.assert_array_equal(sea.omega, again.omega)
    assert not np.array_equal(sea.phase, jonswap_sea(3.0, 8.0, 3.3, seed=8).phase)
    # DNV's normalization A = 1 - 0.287 ln(gamma) gives m0 = Hs^2/16 to within a few percent
    m0, _ = quad(lambda w: jonswap_spectrum(w, 3.0, 8.0, 3.3), 0.05, 20.0, limit=200)
    assert m0 == pytest.approx(3.0**2 / 16, rel=0.03)
    # a long record has the spectrum's significant height
    t = np.arange(0.0, 3600.0, 0.5)
    eta = np.cos(np.multiply.outer(t, -sea.omega) + sea.phase) @ sea.amplitude
    assert 4.0 * eta.std() == pytest.approx(3.0, rel=0.05)


def test_bad_waves_are_refused():
    with pytest.raises(KanatError, match="height > 0"):
        regular_wave(-1.0, 5.0)
    with pytest.raises(KanatError, match="gamma"):
        jonswap_sea(2.0, 8.0, 0.5)


def bin_edges(tp: float, components: int = 200) -> np.ndarray:
    return np.linspace(JONSWAP_BAND[0], JONSWAP_BAND[1], components + 1) * 2 * math.pi / tp


def test_a_jonswap_sea_does_not_repeat_within_a_storm():
    """Equally spaced components (the same 200 bins, at their centres) repeat their envelope
    every 2 pi / d_omega = 200 Tp / 3.5 = 629 s at Tp 11 s (each component turns a whole number
    of times plus one common angle, so the wave groups and their maxima come back to round-off).
    The sea's frequencies are drawn in their bins: a period later its envelope is uncorrelated
    with itself, as a 3-hour storm's must be; the phases are those the seed gave before."""
    sea = jonswap_sea(6.0, 11.0, 3.3, seed=7)
    edges = bin_edges(11.0)
    period = 2 * math.pi / (edges[1] - edges[0])
    assert period == pytest.approx(200 * 11.0 / 3.5, rel=1e-12)
    t = np.arange(0.0, 1800.0, 0.5)

    def envelope(omega, time):                     # |sum a exp(i (omega t - phase))|
        return np.abs(np.exp(1j * (np.multiply.outer(time, omega) - sea.phase)) @ sea.amplitude)

    centres = 0.5 * (edges[1:] + edges[:-1])
    np.testing.assert_allclose(envelope(centres, t + period), envelope(centres, t), atol=1e-9)
    assert np.all((sea.omega > edges[:-1]) & (sea.omega < edges[1:]))
    np.testing.assert_array_equal(sea.phase, np.random.default_rng(7).uniform(0.0, 2 * math.pi, 200))
    now, later = envelope(sea.omega, t), envelope(sea.omega, t + period)
    assert abs(np.corrcoef(now, later)[0, 1]) < 0.2
    assert np.corrcoef(envelope(centres, t), envelope(centres, t + period))[0, 1] > 0.999


@pytest.mark.parametrize("seed", [0, 7, 12])
def test_a_storms_record_has_the_spectrums_zeroth_moment(seed):
    """The mean square of a 3-hour elevation record (1 s samples) is ``m0 = Hs^2 / 16`` within
    3 standard deviations of the record mean of a sum of components at these frequencies
    (``scatter_of_mean_square``: exact for independent uniform phases, whatever the spacing)."""
    sea = jonswap_sea(4.0, 9.0, 3.3, seed=seed)
    t = np.arange(0.0, 10800.0, 1.0)
    eta = np.cos(np.multiply.outer(t, -sea.omega) + sea.phase) @ sea.amplitude
    m0, sigma = np.mean(eta**2), scatter_of_mean_square(sea.amplitude, sea.omega, t)
    assert abs(m0 - 4.0**2 / 16) < 3 * sigma, f"m0 {m0:.4f} m^2 vs {1.0:.4f} m^2 (sigma {sigma:.4f})"
    assert sigma < 0.01                               # the test can tell: 3 sigma is < 3 % of m0


def test_drawn_frequencies_sample_the_spectrum_without_bias():
    """Before the amplitudes' scaling, ``sum S(omega_j) d_omega`` with ``omega_j`` uniform in bin
    ``j`` is an unbiased estimate of the band's ``integral S d_omega`` whose variance is
    ``sum_j (d_omega integral_bin S^2 - (integral_bin S)^2)``; over 40 seeds the estimates agree
    with the integral (quad) within 3 standard deviations of their mean. The scaled sea's own
    zeroth moment is Hs^2 / 16 to round-off."""
    hs, tp, gamma = 3.0, 8.0, 3.3
    edges = bin_edges(tp)
    d_omega = edges[1] - edges[0]
    bins = list(zip(edges[:-1], edges[1:]))
    each = np.array([quad(lambda w: jonswap_spectrum(w, hs, tp, gamma), a, b)[0] for a, b in bins])
    square = np.array([quad(lambda w: jonswap_spectrum(w, hs, tp, gamma) ** 2, a, b)[0] for a, b in bins])
    integral, sigma = each.sum(), math.sqrt(np.sum(d_omega * square - each**2))
    estimates = []
    for seed in range(40):
        sea = jonswap_sea(hs, tp, gamma, seed=seed)
        assert 0.5 * np.sum(sea.amplitude**2) == pytest.approx(hs**2 / 16, rel=1e-12)
        estimates.append(np.sum(jonswap_spectrum(sea.omega, hs, tp, gamma)) * d_omega)
    assert abs(np.mean(estimates) - integral) < 3 * sigma / math.sqrt(40)
    assert np.std(estimates) == pytest.approx(sigma, rel=0.35)      # the spread the bins predict

