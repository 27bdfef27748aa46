"""The starting equilibrium's linear systems (kanat.lumped.node_systems): the dense form (small
networks) and the sparse one (SciPy's SuperLU, the oracle) give the same solution to round-off, and
say "singular" alike; the dense form's band elimination is LAPACK's dense solve where rows must be
swapped; a lumped run of a small network imports no SciPy."""
import subprocess
import sys
import warnings

import numpy as np
import pytest
import scipy.sparse as sp
import yaml

from kanat.io import load_case
from kanat.lumped import node_systems

from helpers import DATA


def node_band(nodes, seed):
    """Entries of a non-symmetric block tridiagonal system of ``nodes`` 3 x 3 blocks, with repeated
    entries (as a Jacobian's coloured columns give them): rows, cols, values."""
    rng = np.random.default_rng(seed)
    rows, cols, values = [], [], []
    for k in range(nodes):
        for other in (k - 1, k, k + 1):
            if 0 <= other < nodes:
                r, c = np.meshgrid(3 * k + np.arange(3), 3 * other + np.arange(3), indexing="ij")
                block = rng.normal(size=(3, 3)) + (8.0 * np.eye(3) if other == k else 0.0)
                for part in (0.25, 0.75):                       # each entry given twice: summed
                    rows.extend(r.ravel())
                    cols.extend(c.ravel())
                    values.extend(part * block.ravel())
    return np.array(rows), np.array(cols), np.array(values)


@pytest.mark.parametrize("nodes", [5, 101])          # dense (15 unknowns) and sparse (303)
def test_dense_and_sparse_forms_solve_alike(nodes):
    rows, cols, values = node_band(nodes, seed=nodes)
    size = 3 * nodes
    matrix = node_systems.node_matrix(rows, cols, values, size)
    assert isinstance(matrix, np.ndarray) == (size <= node_systems.DENSE_UNKNOWNS)
    reference = sp.csc_matrix((values, (rows, cols)), shape=(size, size))
    np.testing.assert_allclose(np.asarray(matrix.todense() if sp.issparse(matrix) else matrix),
                               reference.toarray(), rtol=0, atol=1e-14)
    mass = np.random.default_rng(1).normal(size=(nodes, 3, 3))
    b = np.random.default_rng(2).normal(size=size)
    want = sp.linalg.spsolve((sp.block_diag(list(mass), format="csc") - reference).tocsc(), b)
    got = node_systems.solve(node_systems.with_mass(-matrix, mass), b)
    np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-12 * np.max(np.abs(want)))


@pytest.mark.parametrize("lower, upper", [(5, 5), (2, 7), (0, 3), (11, 11)])
def test_band_elimination_is_partial_pivoting(lower, upper):
    """A band matrix whose diagonal is small against the entries below it (every column swaps rows),
    against NumPy's dense LAPACK solve."""
    rng = np.random.default_rng(lower + 10 * upper)
    n = 60
    matrix = np.zeros((n, n))
    for i in range(n):
        for j in range(max(0, i - lower), min(n, i + upper + 1)):
            matrix[i, j] = rng.normal() * (1e-3 if i == j else 1.0)
    rhs = rng.normal(size=n)
    got = node_systems.band_solve(matrix, rhs, lower, upper)
    want = np.linalg.solve(matrix, rhs)
    np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-9 * np.max(np.abs(want)))
    np.testing.assert_allclose(matrix @ got, rhs, rtol=0, atol=1e-11 * np.max(np.abs(matrix)) * np.max(np.abs(got)))


def test_the_sparse_form_past_the_limit(monkeypatch):
    monkeypatch.setattr(node_systems, "DENSE_UNKNOWNS", 10)
    rows, cols, values = node_band(20, seed=3)
    matrix = node_systems.node_matrix(rows, cols, values, 60)
    assert sp.issparse(matrix)
    b = np.arange(60.0)
    want = np.linalg.solve(sp.csc_matrix((values, (rows, cols)), shape=(60, 60)).toarray(), b)
    np.testing.assert_allclose(node_systems.solve(matrix, b), want, rtol=1e-10, atol=1e-12 * np.max(np.abs(want)))


@pytest.mark.parametrize("limit", [300, 0])
def test_a_singular_system_says_so_in_either_form(limit, monkeypatch):
    monkeypatch.setattr(node_systems, "DENSE_UNKNOWNS", limit)
    rows, cols, values = node_band(4, seed=5)
    keep = (rows != 4) & (cols != 4)                        # an unknown no equation holds: a zero column
    matrix = node_systems.node_matrix(rows[keep], cols[keep], values[keep], 12)
    with pytest.raises(RuntimeError, match="singular"):
        node_systems.solve(matrix, np.ones(12))


def test_a_small_lumped_run_imports_no_scipy(tmp_path):
    """``kanat run`` of MoorDyn's WD0050 chain (82 segments, friction on the seabed) from its
    equilibrium, 0.2 s of the default implicit scheme: no SciPy sparse or linear-algebra module (their
    import would be a tenth of the whole process; numba, where the kernels compiled at install are
    stale, imports SciPy itself, and so does an in-memory result's xarray through dask)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                       # the file's MoorDyn-only settings
        case = load_case(DATA / "moordyn" / "wd0050_chain.dat")
    case = case.replace({"model": "lumped", "simulation.duration": 0.2, "simulation.output_dt": 0.1})
    path = tmp_path / "wd0050.yaml"
    path.write_text(yaml.safe_dump(case.model_dump(mode="json", by_alias=True, exclude_none=True), sort_keys=False))
    script = (
        "import sys\n"
        f"sys.argv = ['kanat', 'run', {str(path)!r}, '-o', {str(tmp_path / 'out.nc')!r}]\n"
        "from kanat.cli import app\n"
        "try:\n"
        "    app()\n"
        "except SystemExit as done:\n"
        "    assert not done.code, done.code\n"
        "print('numba' in sys.modules)\n"
        "print(sorted(m for m in sys.modules if m.startswith(('scipy.sparse', 'scipy.linalg'))))\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "status: ok" in done.stdout + done.stderr
    numba, scipy = done.stdout.strip().splitlines()[-2:]
    if numba == "True":
        pytest.skip("the kernels compiled at install are stale or missing here: numba ran them, and numba "
                    "imports scipy.linalg itself")
    assert scipy == "[]"
