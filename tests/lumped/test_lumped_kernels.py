"""Compiled kernels of the lumped model against their NumPy twins and finite differences."""
import numpy as np
import pytest

from kanat.lumped import kernels, oracle_numpy
from kanat.lumped.network import build_network
from kanat.model import Case


def network_case(law=None, dimensional=False):
    line = dict(diameter=0.02, mass=3.0, axial_stiffness=1e6, axial_damping=300.0, added_mass=0.4,
                drag_normal=1.4, drag_tangential=0.03)
    if law is not None:
        line["elastic_law"] = law
    if dimensional:
        line.update(drag_normal_coefficient=15.6, drag_tangential_coefficient=0.78)
    return Case.model_validate(dict(
        model="lumped", line_types={"c": line},
        bodies={"b": dict(mass=100, net_buoyancy=-500, drag_area=0.5, added_mass=20)},
        points={"p": dict(position=[-30, 0, -30], mass=5.0)},
        cables=[dict(name="a", line_type="c", length=50, segments=5, **{"from": "vessel"}, to="p"),
                dict(name="b", line_type="c", length=30, segments=4, **{"from": "p"}, to="b"),
                dict(name="c", line_type="c", length=20, segments=3, **{"from": "p"}, to="free")],
        simulation=dict(duration=1, dt=0.01)))


LAWS = [None, {"polynomial": [1e6, 5e6, -1e6]}, {"table": [[0.01, 8e3], [0.03, 4e4], [0.1, 2e5]]}]


def random_state(net, seed=0):
    rng = np.random.default_rng(seed)
    x = net.x_guess * 1.02 + rng.normal(0.0, 0.3, (net.n_nodes, 3))
    v = rng.normal(0.0, 1.0, (net.n_nodes, 3))
    uw = rng.normal(0.0, 1.0, (net.n_elements, 3))
    aw = rng.normal(0.0, 1.0, (net.n_elements, 3))
    return x, v, uw, aw


def run_forces(net, x, v, uw, aw, mass):
    F, M = np.zeros((net.n_nodes, 3)), np.zeros((net.n_nodes, 3, 3))
    T, e = np.zeros(net.n_elements), np.zeros(net.n_elements)
    kernels.forces(x, v, uw, aw, net.node_force, mass, net.elements(), F, M, T, e)
    return F, M, T, e


@pytest.mark.parametrize("law", LAWS, ids=["kelvin-voigt", "polynomial", "table"])
@pytest.mark.parametrize("dimensional", [False, True], ids=["cd-form", "dimensional"])
def test_force_kernel_matches_its_numpy_twin(law, dimensional):
    net = build_network(network_case(law, dimensional))
    x, v, uw, aw = random_state(net)
    mass = net.node_mass + net.node_added_mass
    got = run_forces(net, x, v, uw, aw, mass)
    want = oracle_numpy.forces_numpy(net.elements(), x, v, uw, aw, net.node_force, mass)
    for a, b in zip(got, want):
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-9)
    assert np.all(got[2] >= 0.0)                                  # never compressive
    assert np.any(got[3] < 0) and np.all(got[2][got[3] <= 0] == 0)  # slack elements carry nothing


def test_tension_only_kernel_matches_the_force_kernel():
    net = build_network(network_case(LAWS[2]))
    x, v, uw, aw = random_state(net, 3)
    T = np.zeros(net.n_elements)
    kernels.tensions(x, v, net.elements(), T)
    np.testing.assert_allclose(T, run_forces(net, x, v, uw, aw, net.node_mass)[2], rtol=1e-14)


@pytest.mark.parametrize("law", LAWS, ids=["kelvin-voigt", "polynomial", "table"])
def test_elastic_law_kernel_matches_twin(law):
    net = build_network(network_case(law))
    e = np.linspace(0.0, 0.2, 41)
    for row in range(len(net.law_kind)):
        args = (net.law_kind[row], net.law_n[row], net.law_x[row], net.law_y[row])
        got = np.array([kernels.elastic(*args, ei) for ei in e])
        f, df = oracle_numpy.elastic_numpy(*args, e)
        np.testing.assert_allclose(got[:, 0], f, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(got[:, 1], df, rtol=1e-12)


@pytest.mark.slow
def test_mass_solves_match_twins():
    net = build_network(network_case())
    x, v, uw, aw = random_state(net, 1)
    mass = net.node_mass + net.node_added_mass
    F, M, _, _ = run_forces(net, x, v, uw, aw, mass)
    a0 = np.random.default_rng(2).normal(size=(net.n_nodes, 3))
    a = a0.copy()
    kernels.lumped_solve(M, F, net.free, a)
    np.testing.assert_allclose(a, oracle_numpy.lumped_solve_numpy(M, F, net.free, a0), rtol=1e-11)
    B = np.empty((net.n_elements, 3, 3))
    kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
    a = a0.copy()
    iterations = kernels.consistent_solve(B, net.el_i, net.el_j, mass, F, net.free, a)
    assert iterations < 40
    np.testing.assert_allclose(a, oracle_numpy.consistent_solve_numpy(net, x, mass, F, net.free, a0), rtol=1e-9, atol=1e-10)


def test_consistent_matvec_is_the_sparse_matrix():
    net = build_network(network_case())
    x, _, _, _ = random_state(net, 4)
    B = np.empty((net.n_elements, 3, 3))
    kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
    a = np.random.default_rng(5).normal(size=(net.n_nodes, 3))
    y = np.empty_like(a)
    kernels.consistent_matvec(B, net.el_i, net.el_j, net.node_mass, a, y)
    np.testing.assert_allclose(y.ravel(), oracle_numpy.consistent_matrix(net, x, net.node_mass) @ a.ravel(), rtol=1e-12)


@pytest.mark.parametrize("law", LAWS, ids=["kelvin-voigt", "polynomial", "table"])
def test_tangent_blocks_are_the_derivatives_of_the_forces(law):
    from dataclasses import replace
    full = build_network(network_case(law))
    net = replace(full, el_cn=0 * full.el_cn, el_ct=0 * full.el_ct)    # stiffness and damping alone
    x, v, uw, _ = random_state(net, 6)
    v *= 0.01
    x = net.x_guess * 1.03                           # all taut, smooth
    m = net.n_elements
    K, C, D = np.empty((m, 3, 3)), np.empty((m, 3, 3)), np.empty((m, 3, 3))
    kernels.tangent_blocks(x, v, uw, net.elements(), K, C, D)
    zero = np.zeros((m, 3))
    k = 0
    i, j = net.el_i[k], net.el_j[k]
    h = 1e-6
    for q in range(3):
        dx = np.zeros_like(x)
        dx[j, q] = h
        Fp = run_forces(net, x + dx, v, zero, zero, net.node_mass)[0]
        Fm = run_forces(net, x - dx, v, zero, zero, net.node_mass)[0]
        np.testing.assert_allclose((Fp[i] - Fm[i]) / (2 * h), K[k][:, q], rtol=1e-5, atol=1e-3)
        dv = np.zeros_like(v)
        dv[j, q] = h
        Fp = run_forces(net, x, v + dv, zero, zero, net.node_mass)[0]
        Fm = run_forces(net, x, v - dv, zero, zero, net.node_mass)[0]
        np.testing.assert_allclose((Fp[i] - Fm[i]) / (2 * h), C[k][:, q], rtol=1e-5, atol=1e-3)
        # drag: -dF_i/dv_i from element k alone equals D (isolate: other elements' drag off)
    assert T_of(net, x, v)[k] > 0
    only = np.zeros(m)
    only[k] = 1.0
    net = full
    solo = replace(net, el_cn=net.el_cn * only, el_ct=net.el_ct * only, el_damping=net.el_damping * 0)
    x_slack = net.x_guess * 0.5                                          # no tension: drag alone
    v = v.copy()
    v[j] = v[i]                     # D is taken at the element's mean flow: exact when its ends move together
    for q in range(3):
        dv = np.zeros_like(v)
        dv[i, q] = h
        Fp = run_forces(solo, x_slack, v + dv, uw, zero, net.node_mass)[0]
        Fm = run_forces(solo, x_slack, v - dv, uw, zero, net.node_mass)[0]
        Ks, Cs, Ds = np.empty((m, 3, 3)), np.empty((m, 3, 3)), np.empty((m, 3, 3))
        kernels.tangent_blocks(x_slack, v, uw, solo.elements(), Ks, Cs, Ds)
        np.testing.assert_allclose(-(Fp[i] - Fm[i]) / (2 * h), Ds[k][:, q], rtol=1e-5, atol=1e-6)


def T_of(net, x, v):
    zero = np.zeros((net.n_elements, 3))
    return run_forces(net, x, v, zero, zero, net.node_mass)[2]


def test_body_kernel_matches_the_formula():
    net = build_network(network_case())
    x, v, _, _ = random_state(net, 7)
    uw, aw = np.array([[0.3, -0.2, 0.1]]), np.array([[0.05, 0.0, -0.1]])
    F = np.zeros((net.n_nodes, 3))
    kernels.body_loads(x, v, uw, aw, net.body_node, net.body_drag_area, np.array([700.0]), net.node_added_mass,
                       1025.0, 0.3, F)
    node = net.body_node[0]
    ur = uw[0] - v[node]
    want = 0.5 * 1025 * 0.5 * np.linalg.norm(ur) * ur + 20.0 * aw[0] + 700.0 * np.array([-np.sin(0.3), np.cos(0.3), 0])
    np.testing.assert_allclose(F[node], want, rtol=1e-13)
