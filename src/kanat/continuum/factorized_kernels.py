"""The "running count" sweep of the factorized schemes (seed 000 eqs. 9–11, 15): compiled and NumPy.

One sweep solves a block-bidiagonal system node after node: going forward,

    A_i X_i = r_i + C_i X_{i-1},      i = 1 .. N-1,  X_0 given (the inflow end),

or backward with ``X_{i+1}`` and ``X_N`` given. ``A_i = I + sigma B+_i`` (forward) or
``I - sigma B-_i`` (backward), ``C_i = +-sigma B+-_i``: each node costs one small dense solve.
The matrices are built for all nodes at once (vectorized); only the recursion is sequential,
so it is compiled (:func:`sweep`), and :func:`sweep_numpy` is its plain twin for the tests.
"""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def sweep(A, C, r, X0, forward):
    """Solve one sweep (module docstring) over the interior nodes.

    Parameters
    ----------
    A, C : ndarray, shape (n, d, d)
        Node matrices (those of the end nodes are not used).
    r : ndarray, shape (n, d)
    X0 : ndarray, shape (n, d)
        Holds the inflow value at the inflow end (node 0 forward, node n-1 backward); its
        other end is copied through.
    forward : bool

    Returns
    -------
    ndarray, shape (n, d)
    """
    n, d = r.shape
    X = X0.copy()
    rhs = np.empty(d)
    if forward:
        start, stop, step = 1, n - 1, 1
    else:
        start, stop, step = n - 2, 0, -1
    work = np.empty((d, d))
    for i in range(start, stop, step):
        prev = X[i - step]
        for a in range(d):
            acc = r[i, a]
            for b in range(d):
                acc += C[i, a, b] * prev[b]
            rhs[a] = acc
        solve_small(A[i], rhs, work, X[i])
    return X


@njit(cache=True)
def solve_small(A, b, work, out):
    """``out = A^-1 b`` for a small dense ``A`` (d, d): Gaussian elimination with partial pivoting.

    ``work`` (d, d) is scratch; ``b`` is left untouched. Cheaper than a LAPACK call at d <= 6.
    """
    d = b.shape[0]
    for i in range(d):
        out[i] = b[i]
        for j in range(d):
            work[i, j] = A[i, j]
    for col in range(d):
        pivot = col
        for i in range(col + 1, d):
            if abs(work[i, col]) > abs(work[pivot, col]):
                pivot = i
        if pivot != col:
            for j in range(d):
                work[col, j], work[pivot, j] = work[pivot, j], work[col, j]
            out[col], out[pivot] = out[pivot], out[col]
        inv = 1.0 / work[col, col]
        for i in range(col + 1, d):
            f = work[i, col] * inv
            if f != 0.0:
                for j in range(col, d):
                    work[i, j] -= f * work[col, j]
                out[i] -= f * out[col]
    for i in range(d - 1, -1, -1):
        acc = out[i]
        for j in range(i + 1, d):
            acc -= work[i, j] * out[j]
        out[i] = acc / work[i, i]


def sweep_numpy(A, C, r, X0, forward):
    """Plain twin of :func:`sweep`: ``X_i = A_i^-1 (r_i + C_i X_prev)`` with vectorized inverses."""
    n, _d = r.shape
    H = np.linalg.solve(A, C)
    g = np.linalg.solve(A, r[..., None])[..., 0]
    X = X0.copy()
    order = range(1, n - 1) if forward else range(n - 2, 0, -1)
    for i in order:
        X[i] = H[i] @ X[i - 1 if forward else i + 1] + g[i]
    return X
