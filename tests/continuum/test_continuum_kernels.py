"""The compiled planar kernels against their plain-NumPy twin, the complex-step oracle and
finite differences."""
import numpy as np
import pytest

from kanat.continuum import kernels2d as k
from kanat.continuum import oracle_complex_step2d
from kanat.continuum.model2d import EndCondition, parameters
from kanat.continuum.oracle_numpy2d import interval_residuals

N = 12


def setup(seed, end_kind):
    rng = np.random.default_rng(seed)
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = 1 / 6, 1 / 3, 2 / 3, 0.7
    base = np.column_stack([np.linspace(12e3, 7e3, N + 1), rng.normal(2.0, 0.5, N + 1),
                            rng.normal(-0.5, 0.5, N + 1), rng.normal(-2.9, 0.3, N + 1)])
    y = base
    x = base + rng.normal(0, 1, base.shape) * [50.0, 0.05, 0.05, 0.01]
    d = rng.normal(0, 1, base.shape) * [20.0, 0.1, 0.1, 0.01]
    env = np.zeros((N + 1, k.NENV))
    env[:, [k.UX, k.UZ]] = rng.normal(0, 0.3, (N + 1, 2))          # the current
    b0 = EndCondition(k.VELOCITY).array((3.0, 0.2))
    b1 = {"body": EndCondition(k.BODY, 1135.0, -6686.0, 0.3276, (0.0, -500.0)),
          "free": EndCondition(k.FREE), "anchor": EndCondition(k.VELOCITY)}[end_kind].array((0.0, 0.0))
    return x, y, d, env, np.tile(p, (N, 1)), b0, b1


def run(kernel, args, extras=None):
    x = args[0]
    res, band = np.empty(x.size), np.empty((11, x.size))
    if kernel is k.assemble:
        kernel(x, k.PlanarStep(*args[1:], extras), res, band)
    else:
        kernel(*args, res, band)
    return res, band


@pytest.mark.parametrize("end", ["body", "free", "anchor"])
def test_residual_matches_numpy_twin(end):
    args = setup(1, end)
    res, _ = run(k.assemble, args)
    x, y, d, env, P = args[:5]
    np.testing.assert_allclose(res[2:-2], interval_residuals(x, y, d, env[:, [k.UX, k.UZ]], P[0]), rtol=1e-12,
                               atol=1e-9)


@pytest.mark.parametrize("end", ["body", "free", "anchor"])
@pytest.mark.parametrize("inertia", [1.0, 0.0])
def test_analytic_jacobian_matches_complex_step(end, inertia):
    args = setup(2, end)
    args[4][:, k.INERTIA] = inertia
    res, band = run(k.assemble, args)
    res2, band2 = run(oracle_complex_step2d.jacobian_complex_step, args)
    np.testing.assert_allclose(res, res2, rtol=1e-13, atol=1e-10)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))
    res3, band3 = run(k.assemble, args, np.zeros(1))          # the full version, on a plain cable
    assert np.array_equal(res, res3) and np.array_equal(band, band3)


def test_jacobian_matches_central_differences():
    args = setup(3, "body")
    x = args[0]
    _, band = run(k.assemble, args)
    scale = np.tile([50.0, 0.05, 0.05, 0.01], N + 1)
    for col in range(0, x.size, 5):
        h = 1e-6 * scale[col]
        plus, minus = x.copy().ravel(), x.copy().ravel()
        plus[col] += h
        minus[col] -= h
        rp, _ = run(k.assemble, (plus.reshape(x.shape), *args[1:]))
        rm, _ = run(k.assemble, (minus.reshape(x.shape), *args[1:]))
        fd = (rp - rm) / (2 * h)
        rows = np.arange(max(0, col - k.UPPER), min(x.size, col + k.LOWER + 1))
        exact = band[k.UPPER + rows - col, col]
        np.testing.assert_allclose(exact, fd[rows], rtol=1e-5, atol=1e-6 * np.max(np.abs(fd)) + 1e-12)
        outside = np.setdiff1d(np.arange(x.size), rows)
        assert np.all(np.abs(fd[outside]) < 1e-6 * np.max(np.abs(fd)) + 1e-9)      # truly banded
