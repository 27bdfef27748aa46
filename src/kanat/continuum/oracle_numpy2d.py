"""Plain-NumPy twin of :mod:`kanat.continuum.kernels2d`'s residual, written independently.

Readable and vectorized over intervals, not fast: the tests check the compiled kernels
against it (theory/continuum.md §1 in matrix form ``M Y_t + K Y_s = F``, box method and the
generalized-α weights of theory/time-schemes.md §1).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k


def law(T, p):
    """Strain and compliance ``(e(T), de/dT)`` of the piecewise-linear law in ``p``."""
    n = int(p[k.LAW])
    knots_t, knots_e = p[k.LAW + 1:k.LAW + 1 + n], p[k.LAW + 1 + n:k.LAW + 1 + 2 * n]
    slopes = np.diff(knots_e) / np.diff(knots_t)
    i = np.clip(np.searchsorted(knots_t, T) - 1, 0, n - 2)
    return knots_e[i] + slopes[i] * (T - knots_t[i]), slopes[i]


def mass_matrix(Y, p):
    """``M(Y)`` for states ``Y`` (n, 4) -> (n, 4, 4) (theory/continuum.md §1; ``1/EA -> de/dT`` for a nonlinear law)."""
    T, u, v = Y[:, 0], Y[:, 1], Y[:, 2]
    e, flex = law(T, p)
    n = len(Y)
    M = np.zeros((n, 4, 4))
    M[:, 0, 1], M[:, 0, 3] = p[k.M], -p[k.M] * v
    M[:, 1, 2], M[:, 1, 3] = p[k.M] + p[k.MA], (p[k.M] + p[k.MA]) * u
    M[:, 2, 0] = flex
    M[:, 3, 3] = 1.0 + e
    return M


def stiffness_matrix(Y):
    """``K(Y)`` for states ``Y`` (n, 4) -> (n, 4, 4) (theory/continuum.md §1)."""
    T, u, v = Y[:, 0], Y[:, 1], Y[:, 2]
    K = np.zeros((len(Y), 4, 4))
    K[:, 0, 0] = -1.0
    K[:, 1, 3] = -T
    K[:, 2, 1], K[:, 2, 3] = -1.0, v
    K[:, 3, 2], K[:, 3, 3] = -1.0, -u
    return K


def loads(Y, current, p):
    """``F(Y)`` (n, 4): weight in water and drag of the relative flow (theory/continuum.md §1)."""
    T, u, v, phi = Y.T
    t = np.column_stack([np.cos(phi), np.sin(phi)])
    n = np.column_stack([-np.sin(phi), np.cos(phi)])
    ur = u - np.sum(current * t, axis=1)
    vr = v - np.sum(current * n, axis=1)
    root = np.sqrt(1.0 + law(T, p)[0])
    F = np.zeros_like(Y)
    F[:, 0] = -p[k.W0] * np.sin(phi) - 0.5 * p[k.RHO] * np.pi * p[k.DIAM] * p[k.CT] * np.abs(ur) * ur * root
    F[:, 1] = -p[k.W0] * np.cos(phi) - 0.5 * p[k.RHO] * p[k.DIAM] * p[k.CN] * np.abs(vr) * vr * root
    return F


def interval_residuals(x, y, d, current, p):
    """The 4N box-method rows at new state ``x`` (N+1, 4), old ``y`` and old rate ``d``."""
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    xdot = (x - y) / (gamma * dt) - (1.0 - gamma) / gamma * d
    Ym, Yk, Yd = (1 - am) * x + am * y, (1 - ak) * x + ak * y, (1 - am) * xdot + am * d
    mid = lambda a: 0.5 * (a[1:] + a[:-1])                                    # noqa: E731
    M = mass_matrix(mid(Ym), p)
    K = stiffness_matrix(mid(Yk))
    F = mid(loads(Yk, current, p))
    grad = np.diff(Yk, axis=0) / p[k.DS]
    R = p[k.INERTIA] * np.einsum("nij,nj->ni", M, mid(Yd)) + np.einsum("nij,nj->ni", K, grad) - F
    return R.ravel()
