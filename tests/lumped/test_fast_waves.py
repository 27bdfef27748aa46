"""The compiled wave kinematics of the fused lumped path (kanat.lumped.fast: sincos, water) against
their oracles: ``math.cos``/``math.sin``, and the plain NumPy sea of kanat.physics.waves
(LinearSea.velocity/acceleration, eqs. 3-5 with stretching eq. 7 and ramp eq. 8), finite and deep
water, with and without Wheeler stretching, points above the surface and on the seabed, and
points so far away that the phases leave sincos's reach (the library functions take over)."""

import math
from dataclasses import replace

import numpy as np
import pytest
from numba import njit

from kanat.lumped import fast
from kanat.lumped.advance import sea_arrays
from kanat.physics.waves import jonswap_sea, regular_wave


@njit
def _sincos_all(theta, out):                 # not cached: the tests' own entry to an inner kernel
    for i in range(theta.shape[0]):
        out[i, 0], out[i, 1] = fast.sincos(theta[i])


@njit
def _water(points, t, sea, u, a):
    fast.water(points, t, np.zeros(1), np.zeros((1, 3)), 0.0, sea, u, a)


def test_sincos_matches_the_library_to_an_ulp():
    """Over the reach (|theta| <= 1e6 rad, 3 days of a 4 s wave), quadrant edges and tiny angles."""
    rng = np.random.default_rng(3)
    quarter = np.arange(-40, 41) * 0.5 * math.pi
    theta = np.concatenate([rng.uniform(-10, 10, 20000), rng.uniform(-1e6, 1e6, 20000), quarter,
                            np.nextafter(quarter, np.inf), [0.0, 1e-300, -1e-20, 1e-8]])
    got = np.empty((theta.size, 2))
    _sincos_all(theta, got)
    want = np.column_stack([np.cos(theta), np.sin(theta)])
    assert np.max(np.abs(got - want)) <= 2.3e-16                       # an ulp of values near 1
    small = np.abs(want) < 0.5
    assert np.max(np.abs(got - want)[small] / np.spacing(np.abs(want[small]))) <= 2.0   # ulps, small values


SEAS = {"jonswap-120m": lambda: jonswap_sea(6.0, 11.0, 3.3, 180.0, seed=7, depth=120.0),
        "jonswap-deep": lambda: jonswap_sea(2.5, 7.0, 3.3, 200.0, seed=4),
        "regular-30m": lambda: regular_wave(4.0, 8.0, 30.0, depth=30.0)}


@pytest.mark.parametrize("name", sorted(SEAS))
@pytest.mark.parametrize("stretching", ["none", "wheeler"])
@pytest.mark.parametrize("t, ramp", [(1234.5, 0.0), (3.0, 10.0)])
def test_water_matches_the_numpy_sea(name, stretching, t, ramp):
    sea = replace(SEAS[name](), stretching=stretching, ramp=ramp)
    depth = sea.depth or 150.0
    rng = np.random.default_rng(5)
    n = 60
    points = np.column_stack([rng.uniform(-700, 700, n), rng.uniform(-700, 700, n),
                              np.linspace(-depth, 4.0, n)])
    points[-3:, :2] = [[3e6, 0.0], [-2e6, 5e5], [1e5, -4e6]]            # beyond sincos's reach
    points[0, 2] = -depth - 1.0                                          # below the seabed (or deep)
    u, a = np.empty((n, 3)), np.empty((n, 3))
    _water(points, t, sea_arrays(sea), u, a)
    want_u, want_a = sea.velocity(points, t), sea.acceleration(points, t)
    scale_u = np.sum(sea.amplitude * sea.omega)                          # the largest possible speed
    scale_a = np.sum(sea.amplitude * sea.omega**2)
    # the phases themselves are summed in another order: round-off of |theta|, not of 1
    theta = sea.k.max() * np.abs(points[:, :2]).sum(axis=1) + sea.omega.max() * t + 2.0 * math.pi
    allowed = 8.0 * np.finfo(float).eps * (theta + 10.0)[:, None]
    assert np.all(np.abs(u - want_u) <= allowed * scale_u)
    assert np.all(np.abs(a - want_a) <= allowed * scale_a)
    assert np.max(np.abs(want_a)) > 0.01 * scale_a                       # not a comparison of zeros
