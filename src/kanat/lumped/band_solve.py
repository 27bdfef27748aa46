"""Sparse linear solves of the lumped model without SciPy's sparse package: LAPACK's band solver
after a bandwidth-reducing order of the nodes.

The matrices of the lumped equilibrium and of the Python implicit step are made of 3 x 3 node
blocks on the network's node graph: a line is a chain (one block either side of the diagonal
once its nodes are in order), a mooring a few chains joined at a buoy or a body. Ordered by
reverse Cuthill–McKee (:func:`reverse_cuthill_mckee`), such a matrix is a band of half-width
``kl = 3 b + 2`` unknowns for a node half-width ``b``, and LAPACK's ``dgbsv`` (LU with partial
pivoting in band storage, Golub & Van Loan 2013 §4.3.5) solves it in ``O(n kl^2)`` operations::

    (1)  P A P^T (P x) = P b,        A = L U  (band, 2 kl + ku + 1 rows of storage)

``dgbsv`` is loaded from SciPy's LAPACK extension alone (:func:`kanat._private_api.banded_lapack`):
``import scipy.sparse`` costs a process 0.1-0.3 s of CPU (it imports ``scipy._lib.array_api_compat``
and through it NumPy's f2py, ma, testing and polynomial packages), as much as a short lumped run's
stepping. Where the band's storage would exceed the dense matrix's (a network whose nodes no order
keeps near each other) and the matrix is not small (SMALL), the solve is SciPy's sparse LU
(SuperLU), imported there only.
"""
from __future__ import annotations

import numpy as np

from kanat._private_api import banded_lapack

SMALL = 48     # unknowns: a matrix this small goes to the band solver whatever its width (microseconds)


def reverse_cuthill_mckee(neighbours) -> np.ndarray:
    """A bandwidth-reducing order of a graph's nodes: reverse Cuthill–McKee (Cuthill & McKee 1969;
    George & Liu 1981 §4.3).

    Each connected component is searched breadth first from its node of least degree, the
    unvisited neighbours of each node in the queue being appended in order of increasing degree
    (ties by index); the whole order is then reversed. This is
    :func:`scipy.sparse.csgraph.reverse_cuthill_mckee`'s algorithm, seeds taken in the order of
    NumPy's default ``argsort`` of the degrees as 32-bit integers, as SciPy takes them, so that the
    order, and the implicit scheme's results, are SciPy's to the bit (tests: same order and same
    bandwidth on the examples' networks). It is written out here because the
    lumped model's graphs are small (tens to a few thousand nodes, a BFS of well under a
    millisecond per hundred nodes) and SciPy's function cannot be had without importing
    ``scipy.sparse`` (module docstring); the tests compare the bandwidths of the two on the
    examples' networks.

    Parameters
    ----------
    neighbours : sequence of iterables of int, length n
        Each node's neighbours (symmetric; a node listed among its own is ignored).

    Returns
    -------
    ndarray of int64, shape (n,)
        The nodes in the new order (``order[k]`` is the node placed k-th).
    """
    n = len(neighbours)
    adjacent = [sorted({int(j) for j in near if j != i}) for i, near in enumerate(neighbours)]
    degree = np.array([len(near) for near in adjacent], dtype=np.int64)
    visited = np.zeros(n, dtype=bool)
    order = []
    for seed in np.argsort(degree.astype(np.int32)):
        if visited[seed]:
            continue
        visited[seed] = True
        queue = [int(seed)]
        head = 0
        while head < len(queue):
            fresh = [j for j in adjacent[queue[head]] if not visited[j]]
            fresh.sort(key=lambda j: degree[j])                    # stable: ties keep their index order
            visited[fresh] = True
            queue.extend(fresh)
            head += 1
        order.extend(queue)
    return np.array(order[::-1], dtype=np.int64)


class NodeBandSolver:
    """Solves ``A x = b`` for matrices ``A`` of 3 x 3 blocks on a fixed node graph (eq. 1).

    Parameters
    ----------
    neighbours : sequence of iterables of int, length n_nodes
        Each node's neighbours: the node blocks ``A`` may hold off its diagonal. ``A`` has
        ``3 n_nodes`` unknowns, node ``k``'s being ``3 k, 3 k + 1, 3 k + 2``.

    Attributes
    ----------
    width : int
        Sub- and super-diagonals of the reordered ``A`` (``3 b + 2`` for a node half-width ``b``).
    banded : bool
        Whether solves go to LAPACK's band solver: where the band's storage is no larger than the
        dense matrix, or the matrix has at most SMALL unknowns (False: SciPy's sparse LU; module
        docstring).
    """

    def __init__(self, neighbours):
        n = len(neighbours)
        self.size = 3 * n
        order = reverse_cuthill_mckee(neighbours) if n else np.zeros(0, dtype=np.int64)
        rank = np.empty(n, dtype=np.int64)
        rank[order] = np.arange(n)
        half = max((abs(int(rank[i]) - int(rank[j])) for i, near in enumerate(neighbours) for j in near), default=0)
        self.width = 3 * half + 2 if n else 0
        self.banded = self.size <= SMALL or (3 * self.width + 1) <= self.size
        self.position = (3 * rank[:, None] + np.arange(3)).ravel()   # unknown -> its place in the band order

    def solve(self, rows, cols, values, rhs) -> np.ndarray | None:
        """The solution ``x`` (3 n_nodes,) of ``A x = rhs``, or None when ``A`` is singular.

        Parameters
        ----------
        rows, cols : ndarray of int, shape (k,)
            Row and column of each entry of ``A`` (repeated entries are summed, as in a COO matrix).
        values : ndarray, shape (k,)
        rhs : ndarray, shape (3 n_nodes,)

        Raises
        ------
        ValueError
            An entry lies outside the node graph's band.
        """
        if self.size == 0:
            return np.zeros(0)
        if not self.banded:
            return _sparse_solve(rows, cols, values, rhs, self.size)
        n, w = self.size, self.width
        r, c = self.position[rows], self.position[cols]
        if len(r) and np.max(np.abs(r - c)) > w:
            raise ValueError("a matrix entry joins two nodes that are not neighbours in the node graph")
        # LAPACK band storage: A[i, j] at row 2 w + i - j (the top w rows hold the LU's fill-in), column j
        flat = (2 * w + r - c) * n + c
        band = np.bincount(flat, weights=values, minlength=(3 * w + 1) * n).reshape(3 * w + 1, n)
        b = np.empty(n)
        b[self.position] = rhs
        _, _, x, info = banded_lapack().dgbsv(w, w, np.asfortranarray(band), b, overwrite_ab=True, overwrite_b=True)
        if info != 0:
            return None
        return x[self.position]


def _sparse_solve(rows, cols, values, rhs, size) -> np.ndarray | None:
    """SciPy's sparse LU solve of the COO matrix (rows, cols, values), or None when it is singular."""
    import scipy.sparse as sp                      # here only: a network too wide for the band (module docstring)
    import scipy.sparse.linalg as spla

    matrix = sp.csc_matrix((values, (rows, cols)), shape=(size, size))
    try:
        return spla.splu(matrix).solve(rhs)
    except RuntimeError:                                        # exactly singular
        return None
