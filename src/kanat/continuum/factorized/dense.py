"""The "running count" sweep of the factorized schemes (Kaliukh & Vusatiuk 2018, eqs. 9–11, 15): compiled and NumPy.

One sweep solves a block-bidiagonal system node after node: going forward,

    A_i X_i = r_i + C_i X_{i-1},      i = 1 .. N-1,  X_0 given (the inflow end),

or backward with ``X_{i+1}`` and ``X_N`` given. ``A_i = I + sigma B+_i`` (forward) or
``I - sigma B-_i`` (backward), ``C_i = +-sigma B+-_i``: each node costs one small dense solve.
The matrices are built for all nodes at once (vectorized); only the recursion is sequential,
so it is compiled (:func:`sweep`), and :func:`sweep_numpy` is its plain twin for the tests.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel


@kernel
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
    X = X0.copy()
    sweep_into(A, C, r, X, forward)
    return X


@inner
def sweep_into(A, C, r, X, forward):
    """:func:`sweep` in place: ``X`` holds the inflow value on entry and the solution on exit."""
    n, d = r.shape
    rhs = np.empty(d)
    if forward:
        start, stop, step = 1, n - 1, 1
    else:
        start, stop, step = n - 2, 0, -1
    work = np.empty((d, d))
    piv = np.empty(d, dtype=np.int64)
    for i in range(start, stop, step):
        for a in range(d):
            acc = r[i, a]
            for b in range(d):
                acc += C[i, a, b] * X[i - step, b]
            rhs[a] = acc
        lu_factor(A[i], work, piv)
        lu_solve(work, piv, rhs, X[i])


@inner
def lu_factor(A, LU, piv):
    """In-place LU with partial pivoting of a small ``A`` (d, d) into ``LU``, row order ``piv``.

    Hand-written for d <= 6: cheaper than a LAPACK call per node inside a compiled sweep. A zero
    pivot is left in place (the matrix is singular; callers test ``LU[i, i] == 0``).
    """
    d = A.shape[0]
    for i in range(d):
        piv[i] = i
        for j in range(d):
            LU[i, j] = A[i, j]
    for col in range(d):
        pivot = col
        for i in range(col + 1, d):
            if abs(LU[i, col]) > abs(LU[pivot, col]):
                pivot = i
        if pivot != col:
            for j in range(d):
                LU[col, j], LU[pivot, j] = LU[pivot, j], LU[col, j]
            piv[col], piv[pivot] = piv[pivot], piv[col]
        if LU[col, col] == 0.0:                # singular: the caller tests the diagonal
            continue
        inv = 1.0 / LU[col, col]
        for i in range(col + 1, d):
            LU[i, col] *= inv
            f = LU[i, col]
            if f != 0.0:
                for j in range(col + 1, d):
                    LU[i, j] -= f * LU[col, j]


@inner
def lu_solve(LU, piv, b, out):
    """``out = A^-1 b`` from :func:`lu_factor`."""
    d = b.shape[0]
    for i in range(d):
        acc = b[piv[i]]
        for j in range(i):
            acc -= LU[i, j] * out[j]
        out[i] = acc
    for i in range(d - 1, -1, -1):
        acc = out[i]
        for j in range(i + 1, d):
            acc -= LU[i, j] * out[j]
        out[i] = acc / LU[i, i]


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
