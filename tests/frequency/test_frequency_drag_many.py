"""Equivalent drag of many harmonics at once (kanat.frequency.drag eqs. 3-4) against two oracles:

* the Fourier coefficient of the drag ``c |v| v`` at each harmonic's frequency over a long record
  of ``v = U + sum_f a_f cos(w_f t + p_f)`` at incommensurate frequencies (``sqrt`` of the primes),
  as tests/frequency/test_frequency_drag.py does for two;
* for many harmonics, where the record's combination tones crowd the spectrum, the exact mean of
  eq. (3) over the independent uniform phases by plain Monte Carlo (2^20 samples, standard error
  1e-3), an estimator independent of the Sobol rules under test.

and the Gaussian rule for the whole sum (``c sqrt(8/pi) sigma`` about the mean flow) beside them:
what the many-harmonic rule replaces, 22-26 % off a dominant harmonic however many small ones ride
on it, and the limit the rule reaches when no harmonic dominates.
"""
import math

import numpy as np
import pytest

from kanat.frequency import drag

PRIMES = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37)


def one_pair(mean=0.0):
    one = np.ones(1)
    return drag.DragPairs(node=np.zeros(1, int), element=np.zeros(1, int), dof=np.zeros(1, int),
                          tangent=np.array([[1.0, 0.0, 0.0]]), normal=one, tangential=0.0 * one,
                          inertia_normal=one, inertia_tangential=one, mean=np.array([[0.0, 0.0, mean]]),
                          middle=np.zeros((1, 3)))


def amplitudes(pattern, n):
    """Harmonic amplitudes of total variance 1 (``sum a^2 / 2``), or a dominant one of 1 m/s."""
    if pattern == "dominant":
        return np.r_[1.0, np.full(n - 1, 0.5 / math.sqrt(n - 1))]
    if pattern == "random":
        a = np.random.default_rng(n).uniform(0.1, 1.0, n)
        return a / math.sqrt(np.sum(a**2) / 2)
    return np.full(n, math.sqrt(2.0 / n))


def rules(a, phase, mean):
    """``D_f`` across the element (normal drag, ``c = 1``) by the rule under test and by the Gaussian rule."""
    W = np.zeros((len(a), 1, 3), complex)
    W[:, 0, 2] = a * np.exp(1j * phase)
    D = drag.harmonic_describing(one_pair(mean), W)[:, 0, 2, 2]
    gaussian = drag.stochastic(one_pair(mean), np.diag([0.0, 0.0, np.sum(a**2) / 2])[None])[0, 2, 2]
    return D, gaussian


def torus_mean(a, mean, samples=2**20, chunk=2**16):
    """Eq. (3) for ``c |v| v`` across the element: ``E[2 |v| 2 sin^2(theta_f)]`` by plain Monte Carlo."""
    rng = np.random.default_rng(7)
    total = np.zeros(len(a))
    for _ in range(samples // chunk):
        theta = rng.uniform(0.0, 2 * math.pi, (chunk, len(a)))
        v = mean + np.cos(theta) @ a
        total += ((2.0 * np.abs(v))[:, None] * 2.0 * np.sin(theta) ** 2).sum(axis=0)
    return total / samples


@pytest.mark.parametrize("pattern", ["dominant", "random"])
@pytest.mark.parametrize("n, mean", [(6, 0.0), (8, 0.4), (10, 0.0)])
def test_each_of_several_harmonics_gets_the_fundamental_of_the_drag(pattern, n, mean):
    """Up to 10 harmonics (eq. 3 to 8, eq. 4 beyond): within 2 % of the record's Fourier coefficient
    at every frequency, where the Gaussian rule is off by 15 % and more (a dominant harmonic) or
    by 4-7 % (random amplitudes)."""
    a = amplitudes(pattern, n)
    phase = np.random.default_rng(1).uniform(0.0, 2 * math.pi, n)
    omega = np.sqrt(np.array(PRIMES[:n], float))
    D, gaussian = rules(a, phase, mean)
    t = np.linspace(0.0, 3000 * 2 * math.pi, 3_000_000, endpoint=False)
    v = mean + sum(a[f] * np.cos(omega[f] * t + phase[f]) for f in range(n))
    force = np.abs(v) * v
    exact = np.array([2.0 * np.mean(force * np.exp(-1j * omega[f] * t)) / (a[f] * np.exp(1j * phase[f]))
                      for f in range(n)])
    assert np.max(np.abs(D - exact) / np.abs(exact)) < 0.02
    assert np.max(np.abs(gaussian - exact) / np.abs(exact)) > (0.15 if pattern == "dominant" else 0.03)


@pytest.mark.slow
@pytest.mark.parametrize("pattern, tolerance", [("dominant", 0.008), ("random", 0.02), ("equal", 0.02)])
@pytest.mark.parametrize("n", [16, 64])
def test_many_harmonics_against_the_exact_phase_average(pattern, tolerance, n):
    a = amplitudes(pattern, n)
    D, gaussian = rules(a, np.random.default_rng(2).uniform(0.0, 2 * math.pi, n), 0.3)
    exact = torus_mean(a, 0.3)
    assert np.max(np.abs(D.real - exact) / exact) < tolerance
    assert np.max(np.abs(D.imag)) < 1e-12
    if pattern == "dominant":                                  # a sinusoid stays a sinusoid
        assert abs(gaussian - exact[0]) / exact[0] > 0.2
    if pattern == "equal":                                     # no harmonic dominates: the Gaussian limit
        assert np.max(np.abs(gaussian - exact) / exact) < 0.02


def test_up_to_eight_harmonics_the_rule_is_the_phase_average_of_all():
    W = np.zeros((drag.SINUSOIDS, 1, 3), complex)
    W[:, 0, 2] = amplitudes("random", drag.SINUSOIDS)
    np.testing.assert_array_equal(drag.harmonic_describing(one_pair(0.2), W),
                                  drag.multiple_describing(one_pair(0.2), W))


def test_the_smaller_harmonics_share_the_gaussian_gain_and_the_largest_keep_their_own():
    n = drag.SINUSOIDS + 5
    a = amplitudes("dominant", n)[::-1].copy()                   # the dominant one last
    D, _ = rules(a, np.zeros(n), 0.0)
    order = np.argsort(-a, kind="stable")
    rest = order[drag.SINUSOIDS:]
    assert np.all(D[rest] == D[rest[0]])
    assert D[-1] == pytest.approx(torus_mean(a, 0.0, samples=2**18)[-1], rel=0.01)
