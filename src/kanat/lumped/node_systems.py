"""Linear systems of the network's starting equilibrium (:mod:`kanat.lumped.equilibrium`), in
3 x 3 node blocks: held dense for small networks, sparse (SciPy) for the others.

A process that starts a small network never imports SciPy: its sparse modules take about
0.3 s of CPU to import (``scipy.sparse`` and ``scipy.sparse.linalg``), more than all the dense
solves of such an equilibrium together. :data:`DENSE_UNKNOWNS` draws the line. Both forms are
solved by LU with partial pivoting (LAPACK ``gesv``; SuperLU's ``splu``), so either answers to
round-off.
"""
from __future__ import annotations

import numpy as np

DENSE_UNKNOWNS = 300
"""Unknowns (3 per free node) up to which a system is dense: a dense LU of 300 unknowns takes
about 2 ms (``2 n^3 / 3`` flops), and an equilibrium solves some 30-60 of them, 0.1 s at most,
below SciPy's import; past it the cubic cost soon exceeds the import."""


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
        try:
            return np.linalg.solve(matrix, rhs)
        except np.linalg.LinAlgError as error:
            raise RuntimeError(f"singular matrix ({error})") from None
    import scipy.sparse.linalg as spla

    return spla.splu(matrix.tocsc()).solve(rhs)
