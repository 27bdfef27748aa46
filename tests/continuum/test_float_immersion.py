"""Buoyancy of spherical floats that follows their immersion (``bodies.<name>.diameter``):
the immersed share against the sphere's cap volume, the kernels' Jacobians against their
complex-step oracles, and a float on a vertical tether against its closed-form waterline."""
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import kanat
from kanat.errors import CaseError
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum import oracle_complex_step2d, oracle_complex_step3d
from kanat.continuum.model2d import EndCondition, parameters
from kanat.physics.immersion import float_buoyancy, sphere_fraction

from helpers_float import AREA_WEIGHT, D, DEPTH, EA, FE, FULL, G, ME, MF, SF, TOP, W, tethered_float

N = 12
JUNCTION = 6                                 # the interval holding the float


def test_share_is_the_cap_volume_and_its_derivative():
    """Eq. (1) against the cap volume ``pi h^2 (3a - h) / 3`` by quadrature of the sphere's slices, and
    eq. (2) against a central difference; continuous at both ends."""
    diameter, a = 0.8, 0.4
    for z in np.linspace(-0.5, 0.5, 41):
        h = min(max(-z + a, 0.0), diameter)
        slices = np.linspace(-a, -a + h, 20001)
        volume = np.trapezoid(np.pi * (a * a - slices**2), slices)
        share, slope = sphere_fraction(z, 0.0, diameter)
        assert share == pytest.approx(volume / (4 / 3 * np.pi * a**3), abs=1e-8)
        fd = (sphere_fraction(z + 1e-7, 0.0, diameter)[0] - sphere_fraction(z - 1e-7, 0.0, diameter)[0]) / 2e-7
        assert slope == pytest.approx(fd, abs=1e-6)
    assert sphere_fraction(0.4, 0.0, diameter) == (0.0, 0.0)
    assert sphere_fraction(-0.4, 0.0, diameter) == (1.0, 0.0)
    assert float_buoyancy(200.0, 203.1, 0.0) == pytest.approx(-3.1)


def float_row(p, diameter, eta):
    row = p.copy()
    row[k.KIND], row[k.DS] = k.JUNCTION, 0.0
    row[[k.JB_MASS, k.JB_BUOY, k.JB_DRAG, k.JB_F0, k.JB_F1, k.JB_F2, k.JB_WAVE]] = (
        0.5, 200.0, 0.5 * 1025 * 0.1, 0.0, 0.0, 0.0, 20.0)
    row[[k.JB_DIAMETER, k.JB_FULL, k.JB_ETA]] = diameter, 203.1, eta
    return row


@pytest.mark.parametrize("height", [-0.3, 0.0, 0.15, 0.5])
def test_planar_jacobian_of_a_float_matches_complex_step(height):
    """The float's node at ``height`` against the surface (0.36 m sphere): immersed, half, a cap, out."""
    rng = np.random.default_rng(4)
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT, k.PRED]] = 1 / 6, 1 / 3, 2 / 3, 0.7, 2 / 3 * 0.7
    P = np.tile(p, (N, 1))
    P[JUNCTION] = float_row(p, 0.36, 0.1)
    base = np.column_stack([np.linspace(12e3, 7e3, N + 1), rng.normal(0.02, 0.05, N + 1),
                            rng.normal(-0.05, 0.05, N + 1), rng.normal(1.2, 0.3, N + 1)])
    x = base + rng.normal(0, 1, base.shape) * [50.0, 0.05, 0.05, 0.01]
    d = rng.normal(0, 1, base.shape) * [20.0, 0.1, 0.1, 0.01]
    env = np.zeros((N + 1, k.NENV))
    env[:, [k.UX, k.UZ]] = rng.normal(0, 0.3, (N + 1, 2))
    env[:, [k.AX, k.AZ]] = rng.normal(0, 0.5, (N + 1, 2))          # the waves' acceleration
    z = 0.1 + height - P[JUNCTION, k.PRED] * (np.sin(x[JUNCTION, 3]) * (2 / 3 * x[JUNCTION, 1] + base[JUNCTION, 1] / 3)
                                              + np.cos(x[JUNCTION, 3]) * (2 / 3 * x[JUNCTION, 2] + base[JUNCTION, 2] / 3))
    env[:, k.RZ] = z                                   # about ``height`` over the float's surface
    b0 = EndCondition(k.VELOCITY).array((0.0, 0.0))
    b1 = EndCondition(k.BODY, 1135.0, -6686.0, 0.3276, (0.0, -500.0)).array((0.0, 0.0))
    res, band = np.empty(x.size), np.empty((11, x.size))
    res2, band2 = np.empty(x.size), np.empty((11, x.size))
    k.assemble(x, k.PlanarStep(base, d, env, P, b0, b1, np.zeros(1)), res, band)
    oracle_complex_step2d.jacobian_complex_step(x, base, d, env, P, b0, b1, res2, band2)
    np.testing.assert_allclose(res, res2, rtol=1e-13, atol=1e-10)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))


@pytest.mark.parametrize("height", [-0.3, 0.05, 0.5])
def test_spatial_jacobian_of_a_float_matches_complex_step(height):
    rng = np.random.default_rng(8)
    n = 13
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT, k.PRED]] = 1 / 6, 1 / 3, 2 / 3, 0.7, 2 / 3 * 0.7
    P = np.tile(p, (n - 1, 1))
    P[JUNCTION] = float_row(p, 0.36, -0.2)
    base = np.column_stack([np.linspace(12e3, 7e3, n), rng.normal(0.02, .05, n), rng.normal(-.05, .05, n),
                            rng.normal(.03, .05, n), rng.normal(-.4, .3, n), rng.normal(.2, .3, n)])
    x = base + rng.normal(0, 1, base.shape) * [50, .01, .01, .01, .01, .01]
    d = rng.normal(0, 1, base.shape) * [20, .1, .1, .1, .01, .01]
    up = np.array([0.2, -0.3, 0.93]) / np.linalg.norm([0.2, -0.3, 0.93])
    env = np.zeros((n, k3.NENV3))
    env[:, :3] = rng.normal(0, .3, (n, 3))
    env[:, k3.AX3:k3.AX3 + 3] = rng.normal(0, .5, (n, 3))           # the waves' acceleration
    env[:, k3.RX3:k3.RX3 + 3] = (-0.2 + height) * up       # the float's centre about ``height`` above its surface
    pad = np.zeros(5)
    b0 = np.array([k.VELOCITY, 0.0, 0.0, 0.0, 0, 0, 0, 0, 0, 0.0, *pad])
    b1 = np.array([k.BODY, 0, 0, 0, 1135.0, -6686.0, 0.5 * 1025 * 0.3276, 0, 0, -500.0, *pad])
    res, band = np.empty(x.size), np.empty((17, x.size))
    res2, band2 = np.empty(x.size), np.empty((17, x.size))
    k3.assemble3(x, k3.SpatialStep(base, d, env, up, P, b0, b1, np.zeros(1)), res, band)
    oracle_complex_step3d.jacobian_complex_step3(x, base, d, env, up, P, b0, b1, res2, band2)
    np.testing.assert_allclose(res, res2, rtol=1e-12, atol=1e-9)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))


def tether_case(duration=0.05, dt=0.05, waves=None):
    """The tethered float (tests/helpers_float.py) in the planar continuum model."""
    return tethered_float("continuum", duration, dt, waves, dimensions=2)


def waterline(eta=0.0, dry_tail=False):
    """The float's height: ``z = -depth + s_f + (T_f s_f - w s_f^2 / 2) / EA`` with the tension under it
    ``T_f = f(z) B_f - m g + T_top`` and ``T_top = F - m_e g - w l_top`` (the tail hangs from the pull);
    with ``dry_tail`` the vertical tail's part above the surface, ``l_top - (eta - z)``, weighs its weight
    in air ``w + rho g A`` (the continuum model, whose intervals are wet over the share of their chord
    under the surface; the statics solvers take the whole cable as wet)."""
    def gap(z):
        dry = max(0.0, TOP - max(eta - z, 0.0)) if dry_tail else 0.0
        top = FE - ME * G - W * TOP - AREA_WEIGHT * dry
        below = FULL * sphere_fraction(z, eta, D)[0] - MF * G + top
        return -DEPTH + SF + (below * SF - W * SF**2 / 2) / EA - z
    return brentq(gap, -2.0, 2.0)


@pytest.mark.parametrize("method", ["auto", "collocation"])
def test_statics_float_floats_at_its_waterline(method):
    z = waterline()
    assert 0.0 < sphere_fraction(z, 0.0, D)[0] < 1.0                 # at the surface, partly immersed
    solution = solve_cable3(cable_problem3(tether_case()), method, np.array([0.0, SF, SF + TOP]))
    assert solution.z[1] == pytest.approx(z, abs=1e-6)


@pytest.mark.slow
@pytest.mark.parametrize("dimensions, bending", [(2, 0.0), (3, 0.0), (2, 5.0), (3, 5.0)])
def test_continuum_steady_state_floats_at_its_waterline(dimensions, bending):
    """The planar and spatial kernels, with and without bending stiffness (which a straight line does
    not load). Without the immersion in the kernels the float would sit 0.28 m higher."""
    case = tether_case()
    tether = {**case.line_types["tether"].model_dump(exclude_none=True), "bending_stiffness": bending}
    case = case.replace({"simulation": {**case.simulation.model_dump(exclude_none=True), "dimensions": dimensions},
                         "line_types": {"tether": tether}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                    # the small pulling body above the water
        ds = kanat.simulate(case)
    assert ds.attrs["status"] == "ok"
    assert float(ds["body_position"].sel(body="float").values[0, 2]) == pytest.approx(waterline(dry_tail=True),
                                                                                      abs=1e-6)


@pytest.mark.slow
def test_continuum_float_follows_a_long_wave():
    """A 0.1 m, 40 s wave: the float (heave period ~0.5 s) rides it quasi-statically, at the waterline
    of the wave's elevation over it, ``eta = 0.05 cos(2 pi t / 40)`` at x = 0, once the start's
    transient (the run starts from the still-water state) has died out."""
    waves = {"type": "regular", "height": 0.1, "period": 40.0, "heading_deg": 0}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(tether_case(20.0, 0.05, waves))
    assert ds.attrs["status"] == "ok"
    z = ds["body_position"].sel(body="float").values[:, 2]
    late = ds.time.values >= 15.0
    expected = np.array([waterline(0.05 * math.cos(2 * math.pi * t / 40.0), dry_tail=True) for t in ds.time.values[late]])
    assert np.max(np.abs(z[late] - expected)) < 2e-3
    assert np.min(np.abs(expected - waterline())) > 0.02     # the still-water height is 10x that away


def test_network_statics_which_keeps_full_buoyancy_refuses_a_diameter():
    """(The lumped model honours it: tests/lumped/test_lumped_float_immersion.py.)"""
    case = tether_case()
    with pytest.raises(CaseError, match=r"bodies\.float\.diameter"):
        kanat.solve_statics(case.replace({"model": "statics"}))
