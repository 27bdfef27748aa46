"""The split of ``B = M^-1 K`` by wave and direction (Kaliukh & Vusatiuk 2018, eqs. 3–7, 12–13; theory/time-schemes.md §2).

Property tests over random planar and spatial states: ``B+ + B- = B``, ``B+`` has only
non-negative eigenvalues and ``B-`` only non-positive ones, the four wave parts add up to
``B`` and carry one eigenvalue each, the closed form equals the numerical
eigen-decomposition, and the eigenvalues are ``+-sqrt(EA/m)``, ``+-sqrt(T/((m+m_a)(1+e)))``.
Also: the vectorized matrices equal the full model's kernels, and the compiled sweep and
step equal their NumPy twins.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kanat.continuum import kernels3d as k3
from kanat.continuum.factorized.characteristics import direction_split, group_split, outgoing_rows, split_numerical
from kanat.continuum.factorized.dense import sweep, sweep_numpy
from kanat.continuum.factorized.system import CableSystem
from kanat.continuum.model2d import parameters
from kanat.continuum.models import model_for
from kanat.continuum.oracle_numpy2d import loads, mass_matrix, stiffness_matrix
from kanat.continuum.schemes import Factorized, Factorized4
from kanat.io import parse_case

from helpers import EXAMPLES


cable_data = st.tuples(st.floats(0.1, 10.0), st.floats(0.0, 5.0), st.floats(1e4, 1e9))


def random_states(seed, dim, count=6):
    rng = np.random.default_rng(seed)
    Y = np.empty((count, 2 * dim))
    Y[:, 0] = rng.uniform(1.0, 5e4, count)
    Y[:, 1:1 + dim] = rng.normal(scale=4.0, size=(count, dim))
    Y[:, 1 + dim] = rng.uniform(-1.4, 1.4, count)
    if dim == 3:
        Y[:, 5] = rng.uniform(-np.pi, np.pi, count)
    return Y


def speeds_of(system, Y):
    c_l, c_t2 = system.speeds(Y)
    return c_l, c_t2


@settings(max_examples=40, deadline=None)
@given(data=cable_data, seed=st.integers(0, 2 ** 31), dim=st.sampled_from([2, 3]))
def test_direction_split_adds_up_and_has_signed_eigenvalues(data, seed, dim):
    mass, added, stiffness = data
    system = CableSystem(parameters(mass, added, 5.0, stiffness, 0.02, 1.2, 0.01, 1025.0, 1.0), dim)
    Y = random_states(seed, dim)
    B, _, _ = system.characteristic_form(Y, np.zeros((len(Y), dim)), np.eye(dim)[-1])
    c_l, c_t2 = speeds_of(system, Y)
    plus, minus = direction_split(B, c_l, c_t2)
    scale = np.abs(B).max(axis=(1, 2))[:, None, None]
    assert np.max(np.abs(plus + minus - B) / scale) < 1e-12
    eig_plus, eig_minus = np.linalg.eigvals(plus), np.linalg.eigvals(minus)
    assert np.all(eig_plus.real > -1e-8 * c_l) and np.all(eig_minus.real < 1e-8 * c_l)
    parts = group_split(B, c_l, c_t2)
    assert np.max(np.abs(sum(parts.values()) - B) / scale) < 1e-12
    expected = {"l+": c_l, "l-": -c_l, "t+": np.sqrt(c_t2), "t-": -np.sqrt(c_t2)}
    for key, part in parts.items():                      # each part carries one eigenvalue, the rest zero
        values = np.linalg.eigvals(part)
        largest = np.take_along_axis(values, np.argmax(np.abs(values), axis=1)[:, None], axis=1)[:, 0]
        np.testing.assert_allclose(largest.real, np.broadcast_to(expected[key], largest.shape), rtol=1e-6)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2 ** 31), dim=st.sampled_from([2, 3]))
def test_closed_form_equals_numerical_eigen_decomposition(seed, dim):
    system = CableSystem(parameters(1.12, 0.24, 8.89, 1.27e7, 0.0173, 1.5, 0.01, 1025.0, 10.0), dim)
    Y = random_states(seed, dim)
    B, _, _ = system.characteristic_form(Y, np.zeros((len(Y), dim)), np.eye(dim)[-1])
    c_l, c_t2 = speeds_of(system, Y)
    plus, minus = direction_split(B, c_l, c_t2)
    plus_n, minus_n = split_numerical(B)
    scale = np.abs(B).max(axis=(1, 2))[:, None, None]
    assert np.max(np.abs(plus - plus_n) / scale) < 1e-7
    assert np.max(np.abs(minus - minus_n) / scale) < 1e-7
    values = np.sort(np.linalg.eigvals(B).real, axis=1)
    c_t = np.sqrt(c_t2)
    expected = [-c_l + 0 * c_t, -c_t, c_t, c_l + 0 * c_t] if dim == 2 else \
        [-c_l + 0 * c_t, -c_t, -c_t, c_t, c_t, c_l + 0 * c_t]
    np.testing.assert_allclose(values, np.column_stack(expected), rtol=1e-6)


def test_outgoing_rows_are_left_eigenvectors():
    system = CableSystem(parameters(1.12, 0.24, 8.89, 1.27e7, 0.0173, 1.5, 0.01, 1025.0, 10.0), 3)
    Y = random_states(3, 3, 1)
    B = system.characteristic_form(Y, np.zeros((1, 3)), np.array([0.0, 0.0, 1.0]))[0][0]
    c_l, c_t2 = system.speeds(Y)
    for side, sign in ((-1.0, -1.0), (1.0, 1.0)):
        rows = outgoing_rows(B, c_l, c_t2[0], side)
        assert rows.shape == (3, 6)
        # l B = lambda l with the outgoing speeds: the rows span an invariant subspace of B^T
        coefficients = np.linalg.lstsq(rows.T, (rows @ B).T, rcond=None)[0]
        values = np.sort(np.linalg.eigvals(coefficients).real)
        np.testing.assert_allclose(values, np.sort(sign * np.array([np.sqrt(c_t2[0])] * 2 + [c_l])), rtol=1e-7)


def test_planar_matrices_equal_the_reference_model():
    p = parameters(1.12, 0.24, 8.89, 1.27e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    system = CableSystem(p, 2)
    Y = random_states(7, 2, 9)
    current = np.random.default_rng(1).normal(size=(9, 2))
    np.testing.assert_allclose(system.mass(Y), mass_matrix(Y, p), rtol=1e-15)
    np.testing.assert_allclose(system.stiffness(Y), stiffness_matrix(Y), rtol=1e-15)
    np.testing.assert_allclose(system.loads(Y, current, np.array([0.0, 1.0])), loads(Y, current, p), rtol=1e-12)


def test_spatial_matrices_equal_the_kernels():
    p = parameters(1.12, 0.24, 8.89, 1.27e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    system = CableSystem(p, 3)
    Y = random_states(8, 3, 5)
    current = np.random.default_rng(2).normal(size=(5, 3))
    up = np.array([0.3, -0.2, 0.9])
    up /= np.linalg.norm(up)
    M, K = np.empty((6, 6)), np.empty((6, 6))
    for i, y in enumerate(Y):
        k3.mass_matrix(y, p, M)
        k3.stiffness_matrix(y, K)
        np.testing.assert_allclose(system.mass(Y)[i], M, rtol=1e-14, atol=1e-14)
        np.testing.assert_allclose(system.stiffness(Y)[i], K, rtol=1e-14, atol=1e-14)
        f = k3.node_load3(*y, current[i], up, p)
        np.testing.assert_allclose(system.loads(Y, current, up)[i, :3], f, rtol=1e-12)


@pytest.mark.parametrize("forward", [True, False])
def test_compiled_sweep_equals_its_numpy_twin(forward):
    rng = np.random.default_rng(5)
    n, d = 12, 4
    C = 0.3 * rng.normal(size=(n, d, d))
    A = np.eye(d) + 0.2 * rng.normal(size=(n, d, d))
    r, X0 = rng.normal(size=(n, d)), rng.normal(size=(n, d))
    np.testing.assert_allclose(sweep(A, C, r, X0, forward), sweep_numpy(A, C, r, X0, forward), rtol=1e-12)


@pytest.mark.parametrize("example, dims", [("speed_step_2d.yaml", 2), ("turn_360_3d.yaml", 3)])
@pytest.mark.parametrize("cls", [Factorized, Factorized4], ids=lambda c: c.name)
def test_compiled_step_equals_the_numpy_step(example, dims, cls):
    text = (EXAMPLES / example).read_text().replace("segments: 100", "segments: 12")
    model = model_for(parse_case(text.replace("duration: 60}", "duration: 0.5}")))
    a = b = model.initial()
    for _ in range(20):                                    # through the start of the manoeuvre
        a, _ = cls(compiled=True).step(model, a, 0.05)
        b, _ = cls(compiled=False).step(model, b, 0.05)
    assert np.max(np.abs(a.y[:, 0] - b.y[:, 0])) < 1e-9 * np.max(a.y[:, 0])
    np.testing.assert_allclose(a.y[:, 1:], b.y[:, 1:], atol=1e-11)
