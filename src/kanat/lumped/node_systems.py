"""Linear systems of the network's starting equilibrium (:mod:`kanat.lumped.equilibrium`), in
3 x 3 node blocks: held dense for small networks, sparse (SciPy) for the others.

A process that starts a small network never imports SciPy: its sparse modules take about
0.3 s of CPU to import (``scipy.sparse`` and ``scipy.sparse.linalg``), more than all the dense
solves of such an equilibrium together. :data:`DENSE_UNKNOWNS` draws the line. Both forms are
solved by Gaussian elimination with partial pivoting, so either answers to round-off: the dense
one by :func:`band_solve`, which touches only the matrix's band (LAPACK ``gbsv``'s algorithm: a
line's matrix is 3 x 3 blocks wide) in plain NumPy, never LAPACK's dense ``gesv`` — on a machine
shared with other work, OpenBLAS's threads made that 5 times slower than SciPy's sparse LU where
the command line's one BLAS thread (:mod:`kanat.cli`) was not set; the sparse one by SuperLU
(``splu``).
"""
from __future__ import annotations

import numpy as np

DENSE_UNKNOWNS = 300
"""Unknowns (3 per free node) up to which a system is dense: :func:`band_solve` of a line's 243
unknowns takes about 3 ms, and an equilibrium solves some 30-60 of them, 0.1-0.2 s, below SciPy's
import; a wider band costs up to ``n`` times more."""


def node_matrix(rows, cols, values, size: int):
    """The ``size`` square matrix with ``values`` at ``(rows, cols)`` (repeated entries summed):
    an ndarray up to :data:`DENSE_UNKNOWNS`, else a SciPy CSC matrix."""
    if size <= DENSE_UNKNOWNS:
        matrix = np.zeros((size, size))
        np.add.at(matrix, (np.asarray(rows, dtype=np.int64), np.asarray(cols, dtype=np.int64)),
                  np.asarray(values, dtype=float))
        return matrix
    import scipy.sparse as sp

    return sp.csc_matrix((values, (rows, cols)), shape=(size, size))


def with_mass(matrix, mass_blocks: np.ndarray):
    """``blockdiag(mass_blocks) + matrix`` in the form of ``matrix`` (``mass_blocks`` (n, 3, 3))."""
    if isinstance(matrix, np.ndarray):
        result = matrix.copy()
        for k, block in enumerate(mass_blocks):
            result[3 * k:3 * k + 3, 3 * k:3 * k + 3] += block
        return result
    import scipy.sparse as sp

    return sp.block_diag(list(mass_blocks), format="csc") + matrix


def solve(matrix, rhs: np.ndarray) -> np.ndarray:
    """``x`` of ``matrix x = rhs``.

    Raises
    ------
    RuntimeError
        When the matrix is exactly singular (a zero pivot), in either form.
    """
    if isinstance(matrix, np.ndarray):
        rows, cols = np.nonzero(matrix)
        lower = int(np.max(rows - cols, initial=0))
        return band_solve(matrix, rhs, lower, int(np.max(cols - rows, initial=0)))
    import scipy.sparse.linalg as spla

    return spla.splu(matrix.tocsc()).solve(rhs)


def band_solve(matrix: np.ndarray, rhs: np.ndarray, lower: int, upper: int) -> np.ndarray:
    """``x`` of ``matrix x = rhs`` (n square, n) by Gaussian elimination with partial pivoting
    within the band: ``lower`` and ``upper`` diagonals hold every nonzero; a row swap widens the
    upper part to ``lower + upper`` (Golub & Van Loan, Matrix Computations, 4th ed., §4.3.5,
    Algorithm 4.3.5 with pivoting; LAPACK ``gbsv``). Neither argument is modified.

    Raises
    ------
    RuntimeError
        On an exactly zero pivot (a singular matrix).
    """
    a, b = np.array(matrix, dtype=float), np.array(rhs, dtype=float)
    n = len(b)
    for k in range(n):
        last, right = min(n, k + lower + 1), min(n, k + lower + upper + 1)
        p = k + int(np.argmax(np.abs(a[k:last, k])))
        if a[p, k] == 0.0:
            raise RuntimeError(f"singular matrix (zero pivot in column {k})")
        if p != k:
            a[[k, p], k:right] = a[[p, k], k:right]
            b[k], b[p] = b[p], b[k]
        factors = a[k + 1:last, k] / a[k, k]
        a[k + 1:last, k + 1:right] -= np.outer(factors, a[k, k + 1:right])
        b[k + 1:last] -= factors * b[k]
    x = np.empty(n)
    for k in range(n - 1, -1, -1):
        right = min(n, k + lower + upper + 1)
        x[k] = (b[k] - a[k, k + 1:right] @ x[k + 1:right]) / a[k, k]
    return x
