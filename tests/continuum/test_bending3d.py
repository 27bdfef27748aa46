"""Bending stiffness in the spatial continuum model (:mod:`kanat.continuum.bending3d`): the rows against
their symbolic derivation and their Jacobian against complex step; a cantilever bending under its own
weight and a beam-string vibrating out of the x-z plane against Euler-Bernoulli; the in-plane case
against the planar rod; the flexible limit; re-charting and rotation about the vertical."""
import warnings

import numpy as np
import pytest

import kanat
from kanat.continuum import bending3d as b3
from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum import oracle_complex_step3d
from kanat.continuum.chart import angles, choose_chart, frames, rechart
from kanat.continuum.grid import Grid, parameters
from kanat.continuum.models import SpatialModel, model_for
from kanat.continuum.schemes import Box, GeneralizedAlpha
from kanat.continuum.spatial import SpatialCable, SpatialEnd, SpatialState, positions3, steady3, step3

from helpers import EXAMPLES, step_rotated, zero_crossing_period

STEP = (EXAMPLES / "speed_step_2d.yaml").read_text().replace("duration: 600\n", "duration: 120\n")
TURN = (EXAMPLES / "turn_360_3d.yaml").read_text()
CROSS_CURRENT = "  depth: 2000\n  current:\n    profile:\n      - [0, 0.0, 0.8, 0]\n      - [-600, 0.0, 0.2, 0]\n"
CONSTANTS = dict(mass=1.12, added_mass=0.24, axial_stiffness=1.2717e7, weight_in_water=8.89,
                 water_density=1025.0, diameter=0.0173, drag_normal=1.5, drag_tangential=0.01)


def with_bending(text, ei, segments=100):
    return text.replace("segments: 100", f"segments: {segments}").replace(
        "    drag_tangential: 0.01\n", f"    drag_tangential: 0.01\n    bending_stiffness: {ei}\n", 1)


def random_chart(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))                       # columns e1, e2, p; right-handed


def chart_of(pole, e1):
    pole, e1 = np.asarray(pole, dtype=float), np.asarray(e1, dtype=float)
    return np.column_stack([e1, np.cross(pole, e1), pole])


# --- the rows -----------------------------------------------------------------------------------

@pytest.mark.parametrize("seed", range(3))
def test_bending_rows_equal_the_symbolic_derivation(seed):
    """K(Y) Y_s - F(Y) of the ten rows, from sympy's projections of the vector equations (momentum with
    T t + S, compatibility, EI t x t_s = M, dM/ds + (1 + e) t x F = 0), against the kernels' flexible
    matrices plus :func:`bending3d.bending_terms` at random states, gradients and charts."""
    from kanat.continuum.oracle_sympy3d import CableConstants, numeric_bending_system

    rng = np.random.default_rng(seed)
    chart = random_chart(rng)
    system = numeric_bending_system(chart[:, 2], chart[:, 0])
    ei = 350.0
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0, bending=ei)
    for _ in range(5):
        y = np.array([rng.uniform(1e3, 2e4), *rng.normal(0, 2, 3), rng.uniform(-1.4, 1.4), rng.uniform(-3, 3),
                      *rng.normal(0, 100, 4)])
        g = rng.normal(0, 1, 10) * [100, .1, .1, .1, .01, .01, 10, 10, 10, 10]
        current = rng.normal(0, 0.5, 3)
        M, K, F = system(y, CableConstants(**CONSTANTS), ei, current)
        stiffness, mass = np.empty((6, 6)), np.empty((6, 6))
        k3.stiffness_matrix(y, stiffness)
        k3.mass_matrix(y, p, mass)
        load = k3.node_load3(*y[:6], current @ chart, chart.T @ np.array([0.0, 0.0, 1.0]), p)
        rows, dk, dg = np.empty(10), np.empty((10, 10)), np.empty((10, 10))
        b3.bending_terms(y, g, p, rows, dk, dg)
        rows[:6] += stiffness @ g[:6]
        rows[:3] -= load
        np.testing.assert_allclose(rows, K @ g - F, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(M[:6, :6], mass, rtol=1e-12, atol=1e-12)
        assert np.all(M[:, 6:] == 0) and np.all(M[6:] == 0)            # no inertia of S, M (no rotary inertia)


@pytest.mark.parametrize("end", ["body", "free", "anchor"])
@pytest.mark.parametrize("clamped", [False, True])
def test_bending_jacobian_matches_complex_step(end, clamped):
    """Every entry of the ten-unknown Jacobian, with an inline body, against the complex-step oracle."""
    rng = np.random.default_rng(7)
    n = 9
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0, bending=300.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = 1 / 6, 1 / 3, 2 / 3, 0.7
    P = np.tile(p, (n - 1, 1))
    P[4, k.KIND], P[4, k.DS] = k.JUNCTION, 0.0
    P[4, [k.JB_MASS, k.JB_BUOY, k.JB_DRAG, k.JB_F0, k.JB_F1, k.JB_F2, k.JB_WAVE]] = 300, 500, 100, 1, 2, 3, 50
    base = np.column_stack([np.linspace(12e3, 7e3, n), rng.normal(2, .5, n), rng.normal(-.5, .5, n),
                            rng.normal(.3, .5, n), rng.normal(-.4, .3, n), rng.normal(.2, .3, n),
                            rng.normal(0, 50, (n, 2)), rng.normal(0, 100, (n, 2))])
    x = base + rng.normal(0, 1, base.shape) * [50, .05, .05, .05, .01, .01, 5, 5, 5, 5]
    d = rng.normal(0, 1, base.shape) * [20, .1, .1, .1, .01, .01, 1, 1, 1, 1]
    env, up = np.zeros((n, k3.NENV3)), np.array([0.2, -0.3, 0.93]) / np.linalg.norm([0.2, -0.3, 0.93])
    env[:, :3] = rng.normal(0, .3, (n, 3))                            # the current
    pad = np.zeros(5)
    b0 = np.array([k.VELOCITY, 3.0, 0.2, -0.1, 0, 0, 0, 0, 0, 0.0, *pad, float(clamped), 0.1, 0.3])
    b1 = {"body": np.array([k.BODY, 0, 0, 0, 1135.0, -6686.0, 0.5 * 1025 * 0.3276, 0, 0, -500.0, *pad, 0, 0, 0]),
          "free": np.array([k.FREE, *np.zeros(17)]), "anchor": np.zeros(b3.NBPAR3_BENDING)}[end]
    res, band = np.empty(x.size), np.empty((2 * b3.WIDTH + 1, x.size))
    res2, band2 = np.empty(x.size), np.empty((2 * b3.WIDTH + 1, x.size))
    b3.assemble3_bending(x, k3.SpatialStep(base, d, env, up, P, b0, b1, np.zeros(1)), res, band)
    oracle_complex_step3d.jacobian_complex_step3_bending(x, base, d, env, up, P, b0, b1, res2, band2)
    np.testing.assert_allclose(res, res2, rtol=1e-12, atol=1e-9)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))


# --- Euler-Bernoulli oracles ---------------------------------------------------------------------------

def beam3(n, length, mass, weight, ei, start, end, ea=1e9):
    p = parameters(mass, 0.0, weight, ea, 0.05, 0.0, 0.0, 1025.0, length / n, bending=ei)
    grid = Grid(np.linspace(0.0, length, n + 1), np.tile(p, (n, 1)), (), ("beam",))
    return SpatialCable("beam", length, n, p, start, end, grid=grid)


CHARTS = {"pole x": chart_of((1, 0, 0), (0, 1, 0)),        # the beam's deflection turns theta (M_n, S_b rows)
          "pole z": chart_of((0, 0, 1), (1, 0, 0)),        # ... turns phi (M_b, S_n rows)
          "random": random_chart(np.random.default_rng(3))}


@pytest.mark.parametrize("segments", [10, 40])
@pytest.mark.parametrize("chart", list(CHARTS))
def test_cantilever_along_y_deflects_as_euler_bernoulli(chart, segments):
    """Clamped horizontally along y at the origin, free tip, own weight w: tip deflection w L^4 / (8 EI),
    root shear force -w L z and moment -w L^2 / 2 x, in any chart. Measured: tip 1.25e-4 short (the
    geometric nonlinearity of a 1.25 % deflection, as the planar rod's), shear 1.3e-6 and 7.8e-8, moment
    6.3e-5 at 10 and 40 segments; the random chart moves the tip 2.4e-5 m and 1.5e-6 m sideways."""
    length, w, ei = 10.0, 1.0, 1.0e4
    along, frame = np.array([0.0, 1.0, 0.0]), CHARTS[chart]
    cable = beam3(segments, length, 0.5, w, ei, SpatialEnd(k.VELOCITY, clamped=True, tangent=tuple(along)),
                  SpatialEnd(k.FREE))
    assert cable.nv == 10
    guess = np.zeros((segments + 1, 10))
    guess[:, 4], guess[:, 5] = angles(np.tile(along, (segments + 1, 1)), frame)
    y = steady3(cable, guess, frame, (np.zeros(3), np.zeros(3)), np.outer(cable.s, along))
    tip = positions3(cable, y, frame, np.zeros(3))[-1]
    assert tip[2] == pytest.approx(-w * length**4 / (8 * ei), rel=2e-4)
    assert abs(tip[0]) < 3e-5 * (10 / segments) ** 2                   # second order in ds
    _, n, b = frames(y[:1], frame)
    shear, moment = y[0, 6] * n[0] + y[0, 7] * b[0], y[0, 8] * n[0] + y[0, 9] * b[0]
    np.testing.assert_allclose(shear, [0.0, 0.0, -w * length], atol=2e-5 * w * length)
    np.testing.assert_allclose(moment, [-w * length**2 / 2, 0.0, 0.0], atol=2e-4 * w * length**2 / 2)


class Hold:
    def velocities(self, t):
        return np.zeros(3), np.zeros(3)

    def origin(self, t):
        return np.zeros(3)


@pytest.mark.parametrize("mode", [1, 2, 3])
def test_beam_string_vibrates_out_of_plane_at_its_natural_frequencies(mode):
    """A taut beam-string pinned at (0, 0, 0) and (L, 0, 0) vibrating in y (the binormal of a vertical
    pole: theta, M_n and S_b at work): omega^2 = (T k^2 / (1 + e) + EI k^4 / (1 + e)^2) / m, k = n pi / L.
    Measured: -0.026 %, 0.066 %, 0.25 % for modes 1, 2, 3 (bending raises them 4.8 % to 77 %)."""
    n, length, tension, m, ea, ei = 60, 100.0, 1000.0, 1.0, 1e7, 1e5
    cable = beam3(n, length, m, 0.0, ei, SpatialEnd(k.VELOCITY), SpatialEnd(k.VELOCITY, position=(length, 0, 0)), ea)
    s = cable.s
    y = np.zeros((n + 1, 10))
    y[:, 0] = tension
    y[:, 3] = -1e-3 * np.sin(mode * np.pi * s / length)            # w along b = -y: the mode shape in +y
    state = SpatialState(0.0, y, np.zeros_like(y), np.column_stack([s, 0 * s, 0 * s]), CHARTS["pole z"])
    e, wavenumber = tension / ea, mode * np.pi / length
    omega = np.sqrt((tension * wavenumber**2 / (1 + e) + ei * wavenumber**4 / (1 + e) ** 2) / m)
    dt, probe = 2 * np.pi / omega / 80, n // (2 * mode)
    times, values = [], []
    for _ in range(600):
        state, _ = step3(cable, state, dt, Box().coefficients(), Hold())
        times.append(state.t)
        values.append(state.y[probe, 3])
    measured = 2 * np.pi / zero_crossing_period(np.array(times), np.array(values))
    assert measured == pytest.approx(omega, rel=0.01)
    assert np.max(np.abs(state.y[:, [2, 4, 6, 9]])) == 0.0                # nothing in the x-z plane moves


# --- the model's limits ------------------------------------------------------------------------------

def test_the_spatial_rod_in_the_plane_is_the_planar_rod_to_round_off():
    """The speed step with EI = 300 N m^2, 120 s, dimensions 2 and 3: tensions within 1.1e-15 of the
    largest, positions within 5e-13 m (measured)."""
    runs = {}
    for dims in (2, 3):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            runs[dims] = kanat.simulate(kanat.load_case(with_bending(STEP, 300.0).replace(
                "dimensions: 2", f"dimensions: {dims}")))
    a, b = runs[2], runs[3]
    assert a.attrs["status"] == b.attrs["status"] == "ok" and b.attrs["dimensions"] == 3
    assert np.max(np.abs(a.tension.values - b.tension.values)) < 1e-13 * a.tension.values.max()
    assert np.max(np.abs(a.position.values - b.position.values)) < 1e-9


def test_zero_bending_stiffness_is_todays_spatial_model_bit_for_bit():
    plain = model_for(kanat.load_case(TURN))
    zero = model_for(kanat.load_case(with_bending(TURN, 0.0)))
    assert plain.cable.nv == zero.cable.nv == 6
    a, b = plain.initial(), zero.initial()
    coefficients = GeneralizedAlpha().coefficients()
    for _ in range(30):
        a, _ = plain.step(a, 1.0, coefficients)
        b, _ = zero.step(b, 1.0, coefficients)
    assert np.array_equal(a.y, b.y) and np.array_equal(a.xyz, b.xyz)


def test_vanishing_bending_stiffness_converges_to_the_flexible_spatial_model():
    """EI = 1e-3 N m^2 on the tow in a current across it (the line trails 181 m in y): the rod's steady
    state differs from the flexible one by a discretization error that falls about 16 times a halving of
    ds (measured 1.4e-5, 9.4e-7, 6.0e-8 of the top tension at 50, 100, 200 segments), as in the plane."""
    text = TURN.replace("  depth: 2000\n", CROSS_CURRENT)
    differences = []
    for segments in (50, 100, 200):
        flexible = model_for(kanat.load_case(text.replace("segments: 100", f"segments: {segments}"))).initial()
        stiff = model_for(kanat.load_case(with_bending(text, 1e-3, segments))).initial()
        assert stiff.y.shape[1] == 10 and np.ptp(flexible.xyz[:, 1]) > 150.0
        differences.append(np.max(np.abs(stiff.y[:, 0] - flexible.y[:, 0])) / flexible.y[:, 0].max())
    assert differences[2] < 1e-7
    assert differences[0] / differences[1] > 8 and differences[1] / differences[2] > 8


def turning_rod(steps=100, segments=50):
    model = SpatialModel(kanat.load_case(with_bending(TURN, 300.0, segments)))
    state = model.initial()
    coefficients = GeneralizedAlpha().coefficients()
    for _ in range(steps):
        state, _ = model.step(state, 1.0, coefficients)
    return model, state


def test_rechart_of_a_rod_is_exact_both_ways_and_a_step_agrees_to_truncation_error():
    """The shear and the moment are physical vectors normal to t: a re-chart rewrites them (and their
    rates) exactly; a step in another chart agrees to the truncation error, which falls with the grid."""
    model, state = turning_rod()
    assert state.y.shape[1] == 10 and np.max(np.abs(state.y[:, 8:])) > 1.0
    other = choose_chart(np.random.default_rng(4).normal(size=(5, 3)))
    y2, rate2 = rechart(state.y, state.rate, state.chart, other)
    y3, rate3 = rechart(y2, rate2, other, state.chart)
    np.testing.assert_allclose(y3, state.y, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(rate3, state.rate, rtol=1e-10, atol=1e-9)
    def vector(y, chart, first):                                         # S (first = 6) and M (8), global
        _, n, b = frames(y, chart)
        return y[:, first:first + 1] * n + y[:, first + 1:first + 2] * b

    for first in (6, 8):
        np.testing.assert_allclose(vector(y2, other, first), vector(state.y, state.chart, first), atol=1e-9)
    coefficients = GeneralizedAlpha().coefficients()
    differences = []
    for segments in (50, 100):
        m, s = turning_rod(segments=segments)
        y2, rate2 = rechart(s.y, s.rate, s.chart, other)
        a, _ = m.step(s, 1.0, coefficients)
        b, _ = m.step(SpatialState(s.t, y2, rate2, s.xyz, other), 1.0, coefficients)
        differences.append(np.max(np.abs(b.y[:, 0] - a.y[:, 0])) / np.max(a.y[:, 0]))
    assert differences[0] < 1e-3
    assert differences[1] < 0.5 * differences[0]


@pytest.mark.parametrize("angle_deg", [37.0, 180.0])
def test_a_turning_rod_rotated_about_the_vertical_keeps_its_tensions_and_moments(angle_deg):
    model, state = turning_rod()
    plain, turned, rotation = step_rotated(model, state, angle_deg)
    np.testing.assert_allclose(turned.y[:, 0], plain.y[:, 0], rtol=1e-9)
    scale = np.max(np.abs(plain.y[:, 8:]))
    np.testing.assert_allclose(turned.y[:, 8:], plain.y[:, 8:], atol=1e-9 * scale)
    np.testing.assert_allclose(turned.xyz, plain.xyz @ rotation.T, atol=1e-7)


def test_compression_beyond_a_segments_euler_load_stops_a_3d_run_with_the_planar_advice():
    from kanat.continuum.adapter import ContinuumModel

    case = kanat.load_case(with_bending(TURN.replace("  depth: 2000\n", CROSS_CURRENT), 50.0, 20))
    model = ContinuumModel(case.replace({"simulation.slack": "stop"}))         # a run told to stop on slack
    assert model.cable_model.dimensions == 3 and model.cable_model.cable.nv == 10
    state = model.initial()
    values = model.outputs(state)
    assert model.check(state, values) is None
    values["tension"] = values["tension"].copy()
    euler = np.pi**2 * 50.0 / (2 * 50.0) ** 2
    values["tension"][5] = -0.5 * euler                        # within the rod's reach
    assert model.check(state, values) is None
    values["tension"][5] = -2.0 * euler - 1e-3 * np.max(values["tension"])
    message = model.check(state, values)
    assert "Euler load of one segment" in message and "use more segments" in message
    assert "(at most 35.4 m long, now 50 m)" in message
