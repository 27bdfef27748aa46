"""The lumped model's band solves (kanat.lumped.band_solve) against SciPy: the reverse Cuthill–McKee
order against scipy.sparse.csgraph.reverse_cuthill_mckee on the examples' networks (same bandwidth,
same order), and LAPACK's band LU against SciPy's sparse LU on matrices of those networks' pattern.
A lumped run imports no SciPy for them (checked in a fresh process)."""
import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee as scipy_rcm
from scipy.sparse.linalg import splu

from kanat.io import load_case
from kanat.lumped.band_solve import NodeBandSolver, reverse_cuthill_mckee
from kanat.lumped.network import build_network

from helpers import EXAMPLES

CASES = ["mooring_buoy_decay.yaml", "mooring_3leg.yaml", "subsurface_mooring.yaml", "lazy_wave.yaml",
         "surface_mooring_waves.yaml", "towed_array.yaml"]


def free_graph(name):
    """The free nodes' graph (elements and bending triples) of an example's lumped network."""
    case = load_case(EXAMPLES / name).model_copy(update={"model": "lumped"})
    net = build_network(case)
    free = np.flatnonzero(net.free)
    local = -np.ones(net.n_nodes, dtype=np.int64)
    local[free] = np.arange(len(free))
    a, b = local[np.r_[net.el_i, net.bend[0]]], local[np.r_[net.el_j, net.bend[2]]]
    keep = (a >= 0) & (b >= 0)
    return len(free), a[keep], b[keep]


def bandwidth(order, a, b):
    rank = np.empty(len(order), dtype=np.int64)
    rank[order] = np.arange(len(order))
    return int(np.max(np.abs(rank[a] - rank[b]), initial=0))


@pytest.mark.parametrize("name", CASES)
def test_order_is_scipys(name):
    n, a, b = free_graph(name)
    graph = sp.coo_matrix((np.ones(2 * len(a)), (np.r_[a, b], np.r_[b, a])), shape=(n, n)).tocsr()
    want = scipy_rcm(graph, symmetric_mode=True)
    neighbours = [set() for _ in range(n)]
    for i, j in zip(a, b):
        neighbours[i].add(j)
        neighbours[j].add(i)
    got = reverse_cuthill_mckee(neighbours)
    assert sorted(got) == list(range(n))
    assert bandwidth(got, a, b) == bandwidth(want, a, b) <= 1    # chains joined at buoys: one node either side
    assert np.array_equal(got, want)                              # the fused implicit steps see SciPy's order


def test_order_narrows_a_shuffled_grid():
    """A 6 x 30 grid numbered at random: as narrow as SciPy's order makes it (6 or 7 nodes)."""
    rng = np.random.default_rng(1)
    rows, cols = 6, 30
    label = rng.permutation(rows * cols).reshape(rows, cols)
    edges = [(label[r, c], label[r, c + 1]) for r in range(rows) for c in range(cols - 1)]
    edges += [(label[r, c], label[r + 1, c]) for r in range(rows - 1) for c in range(cols)]
    a, b = np.array(edges).T
    n = rows * cols
    neighbours = [set() for _ in range(n)]
    for i, j in edges:
        neighbours[i].add(j)
        neighbours[j].add(i)
    graph = sp.coo_matrix((np.ones(2 * len(a)), (np.r_[a, b], np.r_[b, a])), shape=(n, n)).tocsr()
    ours, scipys = bandwidth(reverse_cuthill_mckee(neighbours), a, b), bandwidth(scipy_rcm(graph, True), a, b)
    assert ours <= max(scipys, rows + 1)
    assert bandwidth(np.arange(n), a, b) > 10 * ours                  # the random numbering was wide


def block_matrix(neighbours, rng):
    """A non-symmetric matrix of 3 x 3 blocks on the graph ``neighbours``, dominated by its diagonal
    blocks as the implicit tangent is by its mass; repeated entries included (summed)."""
    rows, cols = [], []
    for i, near in enumerate(neighbours):
        for j in near | {i}:
            for r in range(3):
                for q in range(3):
                    rows.append(3 * i + r)
                    cols.append(3 * j + q)
    rows, cols = np.array(rows + rows[:9]), np.array(cols + cols[:9])
    values = rng.normal(size=len(rows))
    values[rows == cols] += 12.0
    return rows, cols, values


@pytest.mark.parametrize("name", CASES[:3])
def test_band_lu_solves_as_scipys_sparse_lu(name):
    n, a, b = free_graph(name)
    neighbours = [set() for _ in range(n)]
    for i, j in zip(a, b):
        neighbours[i].add(j)
        neighbours[j].add(i)
    rng = np.random.default_rng(7)
    rows, cols, values = block_matrix(neighbours, rng)
    rhs = rng.normal(size=3 * n)
    solver = NodeBandSolver(neighbours)
    assert solver.banded and solver.width == 5                          # 3 x 1 + 2 unknowns either side
    got = solver.solve(rows, cols, values, rhs)
    matrix = sp.csc_matrix((values, (rows, cols)), shape=(3 * n, 3 * n))
    want = splu(matrix).solve(rhs)
    assert np.max(np.abs(got - want)) < 1e-12 * np.max(np.abs(want))
    assert np.max(np.abs(matrix @ got - rhs)) < 1e-12 * np.max(np.abs(rhs))


def test_singular_and_wide_matrices():
    """A singular matrix gives None (as SuperLU's failure did); a graph whose band would be wider than
    the dense matrix (a star of 31 nodes) goes to SciPy's sparse LU and solves the same; a small one
    (a star of 8 nodes, 24 unknowns) stays on the band solver."""
    chain = [{1}, {0, 2}, {1}]
    rows, cols, values = block_matrix(chain, np.random.default_rng(2))
    values[rows // 3 == 1] = 0.0                                       # node 1's rows: zero
    assert NodeBandSolver(chain).solve(rows, cols, values, np.ones(9)) is None
    star = [set(range(1, 31))] + [{0} for _ in range(30)]
    solver = NodeBandSolver(star)
    assert not solver.banded
    rows, cols, values = block_matrix(star, np.random.default_rng(3))
    rhs = np.arange(93.0)
    matrix = sp.csc_matrix((values, (rows, cols)), shape=(93, 93))
    assert np.allclose(matrix @ solver.solve(rows, cols, values, rhs), rhs, rtol=0, atol=1e-11)
    small = [set(range(1, 8))] + [{0} for _ in range(7)]
    rows, cols, values = block_matrix(small, np.random.default_rng(4))
    matrix = sp.csc_matrix((values, (rows, cols)), shape=(24, 24))
    assert NodeBandSolver(small).banded
    assert np.allclose(matrix @ NodeBandSolver(small).solve(rows, cols, values, rhs[:24]), rhs[:24], atol=1e-11)
    with pytest.raises(ValueError, match="not neighbours"):
        NodeBandSolver([{1}, {0, 2}, {1, 3}, {2, 4}, {3, 5}, {4}]).solve(
            np.array([0, 15]), np.array([0, 0]), np.array([1.0, 1.0]), np.ones(18))


def test_a_lumped_equilibrium_imports_no_scipy():
    """The equilibrium of a mooring in a fresh process with the plain kernels (numba's own import
    loads scipy.linalg for its BLAS): SciPy's LAPACK extension module alone, not the package."""
    code = (
        "import sys, numpy as np\n"
        "from kanat.io import load_case\n"
        "from kanat.lumped.network import build_network\n"
        "from kanat.lumped.equilibrium import equilibrium\n"
        f"case = load_case({str(EXAMPLES / 'mooring_buoy_decay.yaml')!r})\n"
        "net = build_network(case)\n"
        "x, info = equilibrium(net, case)\n"
        "print(info['residual'], sorted(m for m in sys.modules if m.split('.')[0] == 'scipy'))\n")
    env = {"KANAT_KERNELS": "python", "PATH": "/usr/bin:/bin"}
    env.update({k: v for k, v in os.environ.items() if k in ("PYTHONPATH", "NUMBA_CACHE_DIR", "HOME")})
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    residual, modules = out.stdout.split(" ", 1)
    assert float(residual) < 1e-3
    assert modules.strip() == "['scipy.linalg._flapack']"
