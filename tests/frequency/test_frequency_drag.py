"""The equivalent linearisation of drag (kanat.frequency.drag) against its closed forms: the
describing function ``8/(3 pi) c a`` of ``c |v| v`` under ``v = a cos(theta)``, the stochastic
``c sqrt(8/pi) sigma`` of a Gaussian ``v``, and with a mean flow ``U`` the Gaussian expectation
``2 c (sigma sqrt(2/pi) exp(-U^2 / 2 sigma^2) + U erf(U / (sigma sqrt 2)))`` (Borgman 1967); the
describing function of each of two harmonics (eq. 3) against the fundamental of ``c |v| v`` measured
on a long record of the two at incommensurate frequencies."""
import math

import numpy as np
import pytest

from kanat.frequency import drag


def one_pair(tangent=(1.0, 0.0, 0.0), mean=(0.0, 0.0, 0.0), normal=1.0, tangential=0.0):
    t = np.array([tangent], float)
    one = np.ones(1)
    return drag.DragPairs(node=np.zeros(1, int), element=np.zeros(1, int), dof=np.zeros(1, int), tangent=t,
                          normal=normal * one, tangential=tangential * one, inertia_normal=one,
                          inertia_tangential=one, mean=np.array([mean], float), middle=np.zeros((1, 3)))


@pytest.mark.parametrize("a", [0.1, 1.0, 3.0])
def test_describing_function_of_normal_drag_is_8_over_3_pi(a):
    D = drag.describing(one_pair(), np.array([[0.0, 0.0, a * np.exp(0.7j)]]))[0]
    assert D[2, 2] == pytest.approx(8.0 / (3.0 * math.pi) * a, rel=1e-4)
    assert abs(D[0, 0]) < 1e-12                          # nothing along the element (no tangential drag)


@pytest.mark.parametrize("sigma", [0.05, 0.5, 2.0])
def test_stochastic_linearisation_of_tangential_drag_is_sqrt_8_over_pi_sigma(sigma):
    pair = one_pair(normal=0.0, tangential=1.0)
    covariance = np.diag([sigma**2, 0.0, 0.0])[None]
    D = drag.stochastic(pair, covariance)[0]
    assert D[0, 0] == pytest.approx(math.sqrt(8.0 / math.pi) * sigma, rel=5e-3)


@pytest.mark.parametrize("ratio", [0.0, 0.5, 1.0, 3.0])
def test_stochastic_linearisation_about_a_mean_flow_is_the_gaussian_expectation(ratio):
    sigma, U = 0.4, 0.4 * ratio
    D = drag.stochastic(one_pair(normal=0.0, tangential=1.0, mean=(U, 0.0, 0.0)), np.diag([sigma**2, 0, 0])[None])[0]
    exact = 2.0 * (sigma * math.sqrt(2.0 / math.pi) * math.exp(-U**2 / (2 * sigma**2)) + U * math.erf(U / (sigma * math.sqrt(2))))
    assert D[0, 0] == pytest.approx(exact, rel=5e-3)


def test_without_motion_the_linearisation_is_the_tangent_about_the_mean_flow():
    """Zero fluctuation: ``D = J(U)``, the slope the linearisation's C holds, ``c |U| (I + n n)`` across."""
    pair = one_pair(mean=(0.0, 0.0, 1.5))
    D = drag.stochastic(pair, np.zeros((1, 3, 3)))[0]
    np.testing.assert_allclose(D, drag.tangent_at_mean(pair)[0], atol=1e-12)
    np.testing.assert_allclose(np.diag(D), [0.0, 1.5, 3.0], atol=1e-12)


@pytest.mark.parametrize("sigma", [0.1, 1.0])
def test_stochastic_linearisation_of_normal_drag_in_one_and_two_directions(sigma):
    """One direction across the element: ``sqrt(8/pi) sigma``; an isotropic Gaussian in the normal
    plane: ``E[|v| (I + e e)] = 3/2 sigma sqrt(pi/2) I`` (``E|v|`` of a Rayleigh variable)."""
    pair = one_pair()
    one = drag.stochastic(pair, np.diag([0.0, 0.0, sigma**2])[None])[0]
    assert one[2, 2] == pytest.approx(math.sqrt(8.0 / math.pi) * sigma, rel=2e-3)
    both = drag.stochastic(pair, np.diag([0.0, sigma**2, sigma**2])[None])[0]
    np.testing.assert_allclose(np.diag(both)[1:], 1.5 * sigma * math.sqrt(math.pi / 2.0), rtol=2e-3)
    assert abs(both[0, 0]) < 1e-12


@pytest.mark.parametrize("ratio, mean", [(0.0, 0.0), (0.15, 0.0), (0.5, 0.0), (2.0, 0.0), (0.5, 0.4)])
def test_each_of_two_harmonics_gets_the_fundamental_of_the_drag(ratio, mean):
    """``v = U + a_1 cos(w_1 t + p_1) + a_2 cos(w_2 t + p_2)`` with ``w_2 / w_1`` the golden ratio:
    ``D_f a_f e^{i p_f}`` equals the force's Fourier coefficient at ``w_f`` over 3000 periods
    (measured within 5e-4; without the second harmonic ``8/(3 pi) c a_1``, 6e-9)."""
    a, phase, omega = np.array([1.0, ratio]), np.array([0.3, -1.1]), np.array([1.0, (1 + 5 ** 0.5) / 2])
    W = np.zeros((2, 1, 3), complex)
    W[:, 0, 2] = a * np.exp(1j * phase)
    D = drag.multiple_describing(one_pair(mean=(0.0, 0.0, mean)), W)[:, 0, 2, 2]
    t = np.linspace(0.0, 3000 * 2 * math.pi, 3_000_000, endpoint=False)
    v = mean + sum(a[f] * np.cos(omega[f] * t + phase[f]) for f in range(2))
    force = np.abs(v) * v
    for f in range(2 if ratio > 0 else 1):
        fundamental = 2.0 * np.mean(force * np.exp(-1j * omega[f] * t))
        assert D[f] * a[f] * np.exp(1j * phase[f]) == pytest.approx(fundamental, rel=3e-3)
    if ratio == 0.0:
        assert D[0] == pytest.approx(8.0 / (3.0 * math.pi), rel=2e-3)


def test_the_gaussian_rule_overdamps_a_single_harmonic_by_a_third():
    """Why a few harmonics get their own describing functions: under the stochastic rule a
    sinusoid of amplitude ``a`` (``sigma = a / sqrt 2``) gets ``c sqrt(8/pi) a / sqrt 2``, 33 % more
    than its fundamental ``8/(3 pi) c a``."""
    gaussian = drag.stochastic(one_pair(), np.diag([0.0, 0.0, 0.5])[None])[0, 2, 2]
    sinusoid = drag.describing(one_pair(), np.array([[0.0, 0.0, 1.0]]))[0, 2, 2]
    assert gaussian / sinusoid == pytest.approx(3 * math.pi / 8 * math.sqrt(4 / math.pi), rel=2e-3)
    assert gaussian / sinusoid == pytest.approx(1.33, abs=0.005)
