"""Gaisha pitch model (theory/vessel.md §2, theory/validation-cases.md §9): the Fourier steady state against its closed
forms and against time integration, the stabilizer laws, the resonance guard.

Oracles: each harmonic answered by ``A / (I_y (omega_0^2 - (n omega)^2))`` exactly; the
rectangular mode's mean offset ``M0 / (2 I_y omega_0^2)``; paper eqs. 7, 10, 11, 12 written
out here independently; Fourier and shooting within 1 % of the amplitude at N = 20 and
within 0.1 % at the default N = 50; the truncation error falling like N^-2 (rectangular).
"""
import math
import warnings

import numpy as np
import pytest

from kanat.errors import KanatError
from kanat.model import PitchModel
from kanat.model.problems import RESONANCE_RTOL
from kanat.vessel.pitch import (
    Feedback,
    Off,
    PitchSystem,
    Rectangular,
    ResonanceError,
    Shaped,
    Sinusoidal,
    solve_mode,
    solve_pitch,
)
from kanat.vessel.pitch.fourier import fourier_pitch, harmonic_response, steady_state
from kanat.vessel.pitch.laws import FourierSeries
from kanat.vessel.pitch.optimal import optimal_shape
from kanat.studies.pitch import truncation_errors
from kanat.vessel.pitch.periodic import periodic_orbit, transient

I_Y, OMEGA, M_M, M0 = 2e7, 2 * math.pi / 10, 7e5, 1e6     # paper data (eqs. 2, 4, 5)
OMEGA0 = 0.876                                             # examples/pitch_stabilizer.yaml
PAPER = PitchSystem(I_Y, OMEGA0, M_M, OMEGA)
DAMPED = PitchSystem(I_Y, OMEGA0, M_M, OMEGA, damping_ratio=0.1)
TIMES = np.linspace(0.0, 10.0, 401)


def _optimal(system=PAPER, max_moment=M0, objective="amplitude"):
    return optimal_shape(system, max_moment, 50, objective=objective).law


LAWS = {"off": Off(), "sinusoidal": Sinusoidal(), "rectangular": Rectangular(),
        "optimal-max_abs": _optimal(objective="max_abs")}


@pytest.mark.parametrize("n", [1, 2, 3, 7, 50])
def test_each_harmonic_is_answered_exactly(n):
    amplitude = 3.3e5
    expected = amplitude / (I_Y * (OMEGA0**2 - (n * OMEGA) ** 2))
    cos, sin = harmonic_response(PAPER, n, amplitude, 0.0)
    assert cos == expected and sin == 0.0
    cos, sin = harmonic_response(PAPER, n, 0.0, amplitude)
    assert sin == expected and cos == 0.0
    coefficients = np.zeros(n)
    coefficients[-1] = amplitude
    pitch = steady_state(PAPER, FourierSeries(0.0, np.zeros(n), coefficients, OMEGA))
    np.testing.assert_allclose(pitch(TIMES), expected * np.sin(n * OMEGA * TIMES), rtol=0, atol=1e-15)


def test_damped_harmonic_uses_the_complex_transfer_function():
    n, a, b = 2, 1e5, -4e4
    cos, sin = harmonic_response(DAMPED, n, a, b)
    # I phi'' + c phi' + k phi = a cos + b sin, checked on the sampled residual
    phi = lambda t: cos * np.cos(n * OMEGA * t) + sin * np.sin(n * OMEGA * t)
    w = n * OMEGA
    dphi = -w * cos * np.sin(w * TIMES) + w * sin * np.cos(w * TIMES)
    residual = (-I_Y * w**2 * phi(TIMES) + DAMPED.damping * dphi + DAMPED.restoring * phi(TIMES)
                - a * np.cos(w * TIMES) - b * np.sin(w * TIMES))
    assert np.max(np.abs(residual)) < 1e-9 * abs(a)


@pytest.mark.parametrize("system", [PAPER, DAMPED], ids=["undamped", "damped"])
def test_mean_offsets(system):
    rect, _ = fourier_pitch(system, Rectangular(), M0, 50)
    sin, _ = fourier_pitch(system, Sinusoidal(), M0, 50)
    assert rect.mean == M0 / (2 * I_Y * OMEGA0**2)                    # eqs. 9a, 12
    assert sin.mean == pytest.approx(M0 / (math.pi * I_Y * OMEGA0**2), rel=1e-15)   # eq. 10
    shot = solve_mode(system, Rectangular(), M0, TIMES, method="shooting")
    assert np.mean(shot.pitch[:-1]) == pytest.approx(M0 / (2 * I_Y * OMEGA0**2), rel=1e-6)


def test_paper_series_eq7_and_eq11():
    n = np.arange(1, 41)
    f1 = Sinusoidal().fourier(M0, OMEGA, 40)
    a_n = M0 / math.pi * np.array([(1 - (-1.0) ** (1 - k)) / (1 - k**2) if k != 1 else 0.0 for k in n])
    np.testing.assert_allclose(f1.cos, a_n, rtol=1e-14, atol=1e-9)
    assert f1.mean == M0 / math.pi and f1.sin[0] == M0 / 2 and not f1.sin[1:].any()
    f2 = Rectangular().fourier(M0, OMEGA, 40)
    np.testing.assert_allclose(f2.sin, M0 * (1 - (-1.0) ** n) / (math.pi * n), rtol=1e-14)
    assert f2.mean == M0 / 2 and not f2.cos.any()
    # the shaped law with every node at M0 is the rectangle, by its own exact integrals
    g = Shaped((1.0,) * 9).fourier(M0, OMEGA, 40)
    np.testing.assert_allclose([g.mean, *g.cos, *g.sin], [f2.mean, *f2.cos, *f2.sin], atol=1e-8 * M0)
    # and a fine piecewise-linear sine approaches f_1 like h^2
    fine = Shaped(tuple(np.sin(np.linspace(0, math.pi, 401)))).fourier(M0, OMEGA, 40)
    assert np.max(np.abs(fine.cos - f1.cos)) < 1e-4 * M0


def test_fourier_pitch_is_paper_eq10_and_eq12():
    N, t, w, w0 = 30, TIMES, OMEGA, OMEGA0
    n = np.arange(1, N + 1)[:, None]
    wave = -M_M / I_Y * np.sin(w * t) / (w0**2 - w**2)
    coef = np.where(n == 1, 0.0, (1 - (-1.0) ** (1 - n)) / (math.pi * (1 - np.where(n == 1, 2, n) ** 2)))
    eq10 = wave + M0 / I_Y * (1 / (math.pi * w0**2) + np.sum(coef * np.cos(n * w * t) / (w0**2 - (n * w) ** 2), 0)
                              + np.sin(w * t) / (2 * (w0**2 - w**2)))
    eq12 = wave + M0 / I_Y * (1 / (2 * w0**2) + np.sum((1 - (-1.0) ** n) / (math.pi * n) * np.sin(n * w * t)
                                                       / (w0**2 - (n * w) ** 2), 0))
    np.testing.assert_allclose(fourier_pitch(PAPER, Sinusoidal(), M0, N)[0](t), eq10, rtol=0, atol=1e-14)
    np.testing.assert_allclose(fourier_pitch(PAPER, Rectangular(), M0, N)[0](t), eq12, rtol=0, atol=1e-14)


@pytest.mark.parametrize("system", [PAPER, DAMPED], ids=["undamped", "damped"])
@pytest.mark.parametrize("name", list(LAWS))
def test_fourier_and_time_integration_agree(name, system):
    law = LAWS[name]
    shot = solve_mode(system, law, M0, TIMES, method="shooting")
    for harmonics, tolerance in ((20, 1e-2), (50, 1e-3)):
        fourier = solve_mode(system, law, M0, TIMES, harmonics)
        assert fourier.method == "fourier"
        assert np.max(np.abs(fourier.pitch - shot.pitch)) < tolerance * shot.amplitude


def test_truncation_error_falls_with_n():
    harmonics = [5, 10, 20, 40, 80]
    rect = truncation_errors(PAPER, Rectangular(), M0, harmonics, TIMES)
    sin = truncation_errors(PAPER, Sinusoidal(), M0, harmonics, TIMES)
    assert np.all(np.diff(rect) < 0) and np.all(np.diff(sin) < 0)
    slope = np.polyfit(np.log(harmonics[1:]), np.log(rect[1:]), 1)[0]
    assert -2.3 < slope < -1.7                   # jump in f_2: coefficients 1/n, response 1/n^3
    assert rect[1] > 1e-2 > rect[2]              # N = 20 is the first to reach 1 %
    assert sin[0] < 1e-2 and sin[-1] < 1e-6      # f_1 is continuous: faster


def test_transient_reaches_the_periodic_orbit_when_damped():
    pieces = Rectangular().pieces(M0, OMEGA)
    orbit = periodic_orbit(DAMPED, pieces, TIMES)
    late = transient(DAMPED, pieces, 30, TIMES)
    assert orbit.iterations == 1                 # affine shooting map: one Newton step
    assert np.max(np.abs(late.pitch - orbit.pitch)) < 1e-8 * np.ptp(orbit.pitch)


def test_feedback_is_solved_by_shooting_only():
    law = Feedback()
    with pytest.raises(KanatError, match="no open-loop Fourier form"):
        solve_mode(PAPER, law, M0, TIMES, method="fourier")
    orbit = solve_mode(PAPER, law, M0, TIMES)
    assert orbit.method == "shooting"
    pieces = law.pieces(M0, OMEGA, law.gain_for(PAPER))
    late = transient(PAPER, pieces, 10, TIMES)   # the one-sided damper forgets the start
    assert np.max(np.abs(late.pitch - orbit.pitch)) < 1e-6 * orbit.amplitude
    sol = periodic_orbit(PAPER, pieces, TIMES)
    np.testing.assert_allclose(sol.moment, np.clip(-2 * I_Y * OMEGA0 * sol.rate, 0.0, M0))


@pytest.mark.parametrize("law", [Sinusoidal(), Rectangular(), LAWS["optimal-max_abs"], Feedback()],
                         ids=lambda law: law.name)
def test_every_law_stays_within_zero_and_m0(law):
    if law.closed_loop:
        moment = solve_mode(PAPER, law, M0, TIMES).moment
    else:
        moment = law.moment(np.linspace(0, 30, 3001), M0, OMEGA)
    assert moment.min() >= 0.0 and moment.max() <= M0 * (1 + 1e-12)
    assert moment.max() == pytest.approx(M0)


def test_optimal_shape_is_never_worse_than_the_paper_laws():
    for max_moment in (1e6, 2e6):
        best = solve_mode(PAPER, _optimal(max_moment=max_moment), max_moment, TIMES)
        rect = solve_mode(PAPER, Rectangular(), max_moment, TIMES)
        sin = solve_mode(PAPER, Sinusoidal(), max_moment, TIMES)
        assert best.amplitude <= min(rect.amplitude, sin.amplitude) * (1 + 1e-3)
    assert best.amplitude < 0.1 * rect.amplitude      # M0 = 2e6: the rectangle overshoots


@pytest.mark.parametrize("n", [1, 2, 3])
def test_resonance_guard(n):
    at = PAPER.with_natural_frequency(n * OMEGA)
    near = PAPER.with_natural_frequency(n * OMEGA * (1 + 0.5 * RESONANCE_RTOL))
    clear = PAPER.with_natural_frequency(n * OMEGA * (1 + 2 * RESONANCE_RTOL))
    with warnings.catch_warnings():
        warnings.simplefilter("error")           # no division-by-zero warning on the way
        for system in (at, near):
            for method in ("fourier", "shooting"):
                with pytest.raises(ResonanceError, match=rf"harmonic n = {n} .*damping_ratio > 0"):
                    solve_mode(system, Rectangular(), M0, TIMES, method=method)
        response = solve_mode(clear, Rectangular(), M0, TIMES)
    assert np.isfinite(response.pitch).all()
    damped = solve_mode(PitchSystem(I_Y, n * OMEGA, M_M, OMEGA, 0.05), Rectangular(), M0, TIMES)
    assert np.isfinite(damped.pitch).all()


def test_resonance_guard_from_the_model():
    model = PitchModel(inertia=I_Y, natural_frequency=2 * OMEGA, wave_moment_amplitude=M_M,
                       wave_period=10.0, stabilizer={"mode": "rectangular", "max_moment": M0})
    with pytest.raises(ResonanceError, match="within 0 % of the natural frequency"):
        solve_pitch(model)


def test_unknown_mode_and_method_are_explained():
    from kanat.vessel.pitch import stabilizer_law

    with pytest.raises(KanatError, match="known: off, sinusoidal, rectangular, feedback, optimal"):
        stabilizer_law("square", PAPER)
    with pytest.raises(KanatError, match="use one of: auto, fourier, shooting"):
        solve_mode(PAPER, Off(), M0, TIMES, method="euler")
