"""Planar continuum model against analytic wave oracles (theory/validation-cases.md case 3).

Straight weightless cables without drag: a longitudinal step in end velocity travels at
``sqrt(EA/m)`` with ``dT = sqrt(EA m) dV``; a transverse kink at ``sqrt(T/(m+m_a))``; a taut
string rings at ``c_t / 2L``; an axial cable with an end mass at ``beta c_l / L`` with
``beta tan(beta) = m L / M``.
"""
import numpy as np
import pytest
from scipy.optimize import brentq

from kanat.continuum import kernels2d as k
from kanat.continuum.model2d import EndCondition, PlanarCable, parameters
from kanat.continuum.schemes import Box, GeneralizedAlpha
from kanat.continuum.stepper import step
from kanat.validation.checks_dynamics import straight_cable

from helpers import EXAMPLES, StepDrive, front, march, run, zero_crossing_period


def test_longitudinal_step_speed_and_jump():
    ea, m, t0, dv = 1e6, 1.0, 1000.0, 0.1
    cable, state = straight_cable(1000.0, 200, t0, ea, m)
    state = march(cable, state, StepDrive((-dv, 0.0)), 0.0025, 200, GeneralizedAlpha(-0.3))
    jump = np.sqrt(ea * m) * dv
    tension = state.y[:, 0]
    assert front(cable.s, tension, t0 + 0.5 * jump) / state.t == pytest.approx(np.sqrt(ea / m), rel=0.02)
    plateau = np.median(tension[cable.s < 300.0])
    assert plateau - t0 == pytest.approx(jump, rel=0.02)


def test_transverse_kink_speed():
    t0, m, ma, dv = 1000.0, 1.0, 0.6, 0.05
    cable, state = straight_cable(1000.0, 250, t0, 1e7, m, ma)
    state = march(cable, state, StepDrive((0.0, dv)), 0.05, 200, GeneralizedAlpha(-0.3))
    speed = front(cable.s, state.y[:, 2], 0.5 * dv) / state.t
    assert speed == pytest.approx(np.sqrt(t0 / (m + ma)), rel=0.02)


def test_taut_string_fundamental_frequency():
    length, t0, m = 100.0, 1000.0, 1.0
    cable, state = straight_cable(length, 50, t0, 1e7, m)
    state.y[:, 2] = 0.01 * np.sin(np.pi * cable.s / length)            # first mode, initial velocity
    coefficients, hold = Box().coefficients(), StepDrive((0.0, 0.0))
    times, mid = [], []
    for _ in range(600):
        state, _ = step(cable, state, 0.02, coefficients, hold)
        times.append(state.t)
        mid.append(state.y[25, 2])
    period = zero_crossing_period(np.array(times), np.array(mid))
    c_t = np.sqrt(t0 / (m * (1 + t0 / 1e7)))
    assert 1.0 / period == pytest.approx(c_t / (2 * length), rel=0.01)


def test_axial_frequency_with_end_mass():
    length, ea, m, body, force = 100.0, 1e6, 1.0, 100.0, 1000.0
    beta = brentq(lambda b: b * np.tan(b) - m * length / body, 1e-6, np.pi / 2 - 1e-9)
    end = EndCondition(k.BODY, mass=body, force=(force, 0.0))
    cable, state = straight_cable(length, 50, force, ea, m, end=end)
    state.y[:, 0] = force + 0.01 * ea * beta / length * np.cos(beta * cable.s / length)   # mode shape
    coefficients, hold = Box().coefficients(), StepDrive((0.0, 0.0))
    times, speed = [], []
    for _ in range(500):
        state, _ = step(cable, state, 0.004, coefficients, hold)
        times.append(state.t)
        speed.append(state.y[-1, 1])
    omega = 2 * np.pi / zero_crossing_period(np.array(times), np.array(speed))
    assert omega == pytest.approx(beta * np.sqrt(ea / m) / length, rel=0.01)


def test_nonlinear_law_sets_the_longitudinal_wave_speed():
    """A stiffening law (slope 1e6 N then 3e6 N): pre-tensioned in its stiff part, a step travels
    at sqrt(f'(e0)/m) and carries sqrt(f'(e0) m) dV (not the small-strain EA)."""
    m, t0, dv = 1.0, 2e4, 0.05
    _, state = straight_cable(1000.0, 200, t0, 1e6, m)
    law = ((0.0, 1e4, 4e4), (0.0, 0.01, 0.02))
    cable = PlanarCable("c", 1000.0, 200, parameters(m, 0.0, 0.0, 1e6, 0.01, 0.0, 0.0, 1025.0, 5.0, law),
                        EndCondition(k.VELOCITY), EndCondition(k.VELOCITY))
    state = march(cable, state, StepDrive((-dv, 0.0)), 0.0015, 200, GeneralizedAlpha(-0.3))
    modulus = 3e6
    jump = np.sqrt(modulus * m) * dv
    tension = state.y[:, 0]
    assert front(cable.s, tension, t0 + 0.5 * jump) / state.t == pytest.approx(np.sqrt(modulus / m), rel=0.02)
    assert np.median(tension[cable.s < 200.0]) - t0 == pytest.approx(jump, rel=0.02)


def test_case_elastic_law_reaches_the_kernels(tmp_path):
    """A linear law written as a table gives the linear run; the case plumbing is exercised."""
    from kanat.io import parse_case
    from kanat.io.results import read_result

    text = (EXAMPLES / "speed_step_2d.yaml").read_text()
    text = text.replace("duration: 600\n", "duration: 120\n")
    as_table = text.replace("    drag_tangential: 0.01\n",
                            "    drag_tangential: 0.01\n    elastic_law: {table: [[1.0, 1.2717e7]]}\n", 1)
    run(parse_case(text), tmp_path / "linear.nc")
    run(parse_case(as_table), tmp_path / "table.nc")
    a, b = read_result(tmp_path / "linear.nc"), read_result(tmp_path / "table.nc")
    np.testing.assert_allclose(b.tension.values, a.tension.values, rtol=1e-10)
