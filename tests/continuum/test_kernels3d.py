"""The compiled spatial kernels against the symbolic derivation (theory/continuum.md §2) and the complex-step
oracle of their own Jacobian."""
import numpy as np
import pytest

from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum import oracle_complex_step3d
from kanat.continuum.oracle_sympy3d import CableConstants, numeric_system
from kanat.continuum.model2d import parameters

CONSTANTS = dict(mass=1.12, added_mass=0.24, axial_stiffness=1.2717e7, weight_in_water=8.89,
                 water_density=1025.0, diameter=0.0173, drag_normal=1.5, drag_tangential=0.01)


def random_chart(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))                       # columns e1, e2, p; right-handed


@pytest.mark.parametrize("seed", range(5))
def test_kernel_matrices_equal_the_symbolic_derivation(seed):
    rng = np.random.default_rng(seed)
    chart = random_chart(rng)
    system = numeric_system(chart[:, 2], chart[:, 0])
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    for _ in range(10):
        y = np.array([rng.uniform(1e3, 2e4), *rng.normal(0, 2, 3), rng.uniform(-1.4, 1.4), rng.uniform(-3, 3)])
        current = rng.normal(0, 0.5, 3)
        M, K, F = system(y, CableConstants(**CONSTANTS), current)
        mk, kk = np.empty((6, 6)), np.empty((6, 6))
        k3.mass_matrix(y, p, mk)
        k3.stiffness_matrix(y, kk)
        f = k3.node_load3(*y, current @ chart, chart.T @ np.array([0.0, 0.0, 1.0]), p)
        np.testing.assert_allclose(mk, M, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(kk, K, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(f, F[:3], rtol=1e-10, atol=1e-10)
        assert np.all(F[3:] == 0)


@pytest.mark.parametrize("end", ["body", "free", "anchor"])
def test_spatial_jacobian_matches_complex_step(end):
    rng = np.random.default_rng(7)
    n = 13
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = 1 / 6, 1 / 3, 2 / 3, 0.7
    base = np.column_stack([np.linspace(12e3, 7e3, n), rng.normal(2, .5, n), rng.normal(-.5, .5, n),
                            rng.normal(.3, .5, n), rng.normal(-.4, .3, n), rng.normal(.2, .3, n)])
    x = base + rng.normal(0, 1, base.shape) * [50, .05, .05, .05, .01, .01]
    d = rng.normal(0, 1, base.shape) * [20, .1, .1, .1, .01, .01]
    env, up = np.zeros((n, k3.NENV3)), np.array([0.2, -0.3, 0.93]) / np.linalg.norm([0.2, -0.3, 0.93])
    env[:, :3] = rng.normal(0, .3, (n, 3))                            # the current
    pad = np.zeros(5)
    b0 = np.array([k.VELOCITY, 3.0, 0.2, -0.1, 0, 0, 0, 0, 0, 0.0, *pad])
    b1 = {"body": np.array([k.BODY, 0, 0, 0, 1135.0, -6686.0, 0.5 * 1025 * 0.3276, 0, 0, -500.0, *pad]),
          "free": np.array([k.FREE, 0, 0, 0, 0, 0, 0, 0, 0, 0.0, *pad]), "anchor": np.zeros(15)}[end]
    P = np.tile(p, (n - 1, 1))
    res, band = np.empty(x.size), np.empty((17, x.size))
    res2, band2 = np.empty(x.size), np.empty((17, x.size))
    k3.assemble3(x, k3.SpatialStep(base, d, env, up, P, b0, b1, None), res, band)
    oracle_complex_step3d.jacobian_complex_step3(x, base, d, env, up, P, b0, b1, res2, band2)
    np.testing.assert_allclose(res, res2, rtol=1e-12, atol=1e-9)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))
    res3, band3 = np.empty(x.size), np.empty((17, x.size))
    full = k3.SpatialStep(base, d, env, up, P, b0, b1, np.zeros(1))
    k3.assemble3(x, full, res3, band3)                                    # the full version, plain cable
    assert np.array_equal(res, res3) and np.array_equal(band, band3)
