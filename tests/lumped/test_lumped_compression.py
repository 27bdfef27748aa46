"""Lines with bending stiffness that carry compression (``compression_stiffness``; kernels eq. 2a).

* Euler buckling of a pinned column: a straight line of ``N`` elements between two anchors, shortened
  until the tangent stiffness (elements' axial and geometric blocks, :func:`kernels.tangent_blocks`,
  with the bending's, :func:`kanat.lumped.bending.bending_blocks`) turns singular. Oracles: the
  discrete column's own critical load ``P = 4 k / l sin^2(pi / 2N)`` (rotational springs
  ``k = EI / L0`` at the nodes, links of length ``l``: Timoshenko & Gere, Theory of Elastic
  Stability, §2.1, for a chain of rigid bars), to 1e-9; and Euler's ``pi^2 EI / L^2``, which it
  approaches at second order in ``1 / N``.
* The force kernel against its NumPy twin with compressed bars, and the tangent against finite
  differences of the forces in compression.
* A whole run: a column shortened between two anchors sagging under its own weight (``q``) starts
  from its equilibrium with the midspan deflection of a beam-column (Timoshenko & Gere §1.11:
  ``delta = q / (P k^2) (sec(k L / 2) - 1) - q L^2 / (8 P)``, ``k^2 = P / EI``), with ``P`` the
  run's own compression, to 1e-3 (40 elements), where a plain beam's ``5 q L^4 / (384 EI)`` is
  30-110 % off.
* A rope (``compression_stiffness: 0``) still carries nothing when compressed, and the key without
  bending stiffness is refused at its key.
"""
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from kanat import api
from kanat.lumped import kernels, oracle_numpy
from kanat.lumped.bending import bending_blocks
from kanat.lumped.network import build_network
from kanat.model import Case

EI, EA, LENGTH = 1.0e4, 1.0e6, 10.0          # Euler load pi^2 EI / L^2 = 987 N: strain ~1e-3


def column(segments: int, compression: float = EA):
    line = dict(diameter=0.05, mass=2.0, axial_stiffness=EA, bending_stiffness=EI, compression_stiffness=compression)
    case = Case.model_validate(dict(
        model="lumped", line_types={"bar": line}, environment={"depth": 200},
        cables=[dict(name="column", line_type="bar", length=LENGTH, segments=segments,
                     **{"from": "anchor:[0, 0, -50]"}, to=f"anchor:[{LENGTH}, 0, -50]")],
        simulation=dict(duration=1, dt=0.01)))
    return build_network(case)


def straight(net, strain: float) -> np.ndarray:
    """The column's nodes evenly along x at ``strain`` (the anchors' span shortened to match)."""
    x = np.array(net.x_guess, dtype=float)
    order = net.node_index                                     # the cable's nodes, first to last
    x[order] = [[s, 0.0, -50.0] for s in np.linspace(0.0, LENGTH * (1.0 + strain), len(order))]
    return x


def stiffness(net, x) -> np.ndarray:
    """The tangent stiffness ``-dF/dx`` over the free nodes (3 n_free square)."""
    n, m = net.n_nodes, net.n_elements
    K, C, D = np.empty((m, 3, 3)), np.empty((m, 3, 3)), np.empty((m, 3, 3))
    zero = np.zeros((n, 3))
    kernels.tangent_blocks(x, zero, np.zeros((m, 3)), net.elements(), K, C, D)
    full = np.zeros((n, 3, n, 3))
    for k, (i, j) in enumerate(zip(net.el_i, net.el_j)):
        for a, b, sign in ((i, i, 1.0), (i, j, -1.0), (j, i, -1.0), (j, j, 1.0)):
            full[a, :, b, :] += sign * K[k]
    before, node, after, k_bend = net.bend[:4]
    Kb = np.empty((len(node), 3, 3, 3, 3))
    bending_blocks(x, before, node, after, k_bend, np.empty((3, 3, 3)), Kb)
    for p, triple in enumerate(zip(before, node, after)):
        for a in range(3):
            for b in range(3):
                full[triple[a], :, triple[b], :] += Kb[p, a, b]
    free = np.flatnonzero(net.free)
    return full[free][:, :, free].reshape(3 * len(free), 3 * len(free))


def critical_strain(net) -> float:
    """The strain at which the straight column's stiffness turns singular (its lowest eigenvalue 0)."""
    lowest = lambda strain: np.linalg.eigvalsh(stiffness(net, straight(net, strain)))[0]   # noqa: E731
    euler = math.pi**2 * EI / LENGTH**2 / EA
    assert lowest(0.0) > 0.0 and lowest(-2.0 * euler) < 0.0
    return brentq(lowest, -2.0 * euler, 0.0, xtol=1e-16, rtol=1e-14)


@pytest.mark.parametrize("segments", [10, 20, 40])
def test_a_compressed_column_buckles_at_the_discrete_columns_load(segments):
    net = column(segments)
    strain = critical_strain(net)
    load = -EA * strain
    l0 = LENGTH / segments
    discrete = 4.0 * (EI / l0) / (l0 * (1.0 + strain)) * math.sin(math.pi / (2 * segments)) ** 2
    assert load == pytest.approx(discrete, rel=1e-9)


def test_the_buckling_load_converges_to_eulers_at_second_order():
    euler = math.pi**2 * EI / LENGTH**2
    errors = [abs(-EA * critical_strain(column(n)) / euler - 1.0) for n in (10, 20, 40)]
    orders = [math.log2(a / b) for a, b in zip(errors, errors[1:])]
    assert errors[-1] < 2e-3                                  # the strain's own 1e-3 (links' length) included
    assert orders[0] > 1.7, (errors, orders)


def test_a_rope_carries_no_compression_and_a_bar_its_stiffness_times_the_strain():
    strain = -1e-4
    for compression, expected in ((0.0, 0.0), (EA, EA * strain)):
        net = column(10, compression)
        x = straight(net, strain)
        T = np.zeros(net.n_elements)
        kernels.tensions(x, np.zeros_like(x), net.elements(), T)
        np.testing.assert_allclose(T, expected, rtol=1e-9, atol=1e-12)


def test_compressed_bars_match_the_numpy_twin_and_the_tangent_its_finite_differences():
    net = column(8)
    rng = np.random.default_rng(4)
    x = straight(net, -2e-4) + rng.normal(0.0, 2e-3, (net.n_nodes, 3))
    v = rng.normal(0.0, 0.1, (net.n_nodes, 3))
    uw, aw = rng.normal(0.0, 0.5, (net.n_elements, 3)), np.zeros((net.n_elements, 3))
    el, mass = net.elements(), net.node_mass + net.node_added_mass

    def forces(x, v, uw=uw):
        F, M = np.zeros((net.n_nodes, 3)), np.zeros((net.n_nodes, 3, 3))
        T, e = np.zeros(net.n_elements), np.zeros(net.n_elements)
        kernels.forces(x, v, uw, aw, net.node_force, mass, el, F, M, T, e)
        return F, M, T, e

    got, want = forces(x, v), oracle_numpy.forces_numpy(el, x, v, uw, aw, net.node_force, mass)
    assert np.any(got[2] < 0.0)                                  # bars in compression
    for a, b in zip(got, want):
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-9)
    m = net.n_elements
    K, C, D = np.empty((m, 3, 3)), np.empty((m, 3, 3)), np.empty((m, 3, 3))
    v0 = np.zeros_like(v)
    kernels.tangent_blocks(x, v0, np.zeros((m, 3)), el, K, C, D)
    k = int(np.argmin(got[2]))
    i, j, h = net.el_i[k], net.el_j[k], 1e-7
    for q in range(3):
        dx = np.zeros_like(x)
        dx[j, q] = h
        Fp = forces(x + dx, v0, aw)[0]                          # still water, at rest: no drag
        Fm = forces(x - dx, v0, aw)[0]
        np.testing.assert_allclose((Fp[i] - Fm[i]) / (2 * h), K[k][:, q], rtol=1e-5, atol=1e-3)


def test_compression_without_bending_stiffness_is_refused_at_its_key():
    from pydantic import ValidationError

    with pytest.raises(ValidationError, match="compression_stiffness\n.*only with bending stiffness"):
        Case.model_validate(dict(model="lumped", line_types={"rope": dict(
            diameter=0.05, mass=2.0, axial_stiffness=EA, compression_stiffness=EA)},
            cables=[dict(name="c", line_type="rope", length=10, **{"from": "anchor:[0, 0, -50]"},
                         to="anchor:[10, 0, -50]")]))


@pytest.mark.slow
@pytest.mark.parametrize("strain", [-3e-4, -6e-4])
def test_a_sagging_compressed_column_deflects_as_a_beam_column(strain):
    weight = 2.0                                                       # N/m
    line = dict(diameter=0.05, mass=2.0, weight_in_water=weight, axial_stiffness=EA, bending_stiffness=EI,
                compression_stiffness=EA)
    case = api.load_case({
        "model": "lumped", "environment": {"depth": 200}, "line_types": {"bar": line},
        "cables": [dict(name="column", line_type="bar", length=LENGTH, segments=40,
                        **{"from": "anchor:[0, 0, -50]"}, to=f"anchor:[{LENGTH * (1 + strain)}, 0, -50]")],
        "simulation": dict(duration=0.01, output_dt=0.01, scheme="generalized-alpha-lumped")})
    outcome = api.run(case)
    assert outcome.summary.status == "ok"
    start = outcome.dataset.isel(time=0)                               # the equilibrium
    load = -float(start["segment_tension"].mean())
    assert 0.2 < load / (math.pi**2 * EI / LENGTH**2) < 0.6            # compressed, below Euler's load
    assert float(start["tension"].max()) < 0.0                         # node tensions too: no floor on bars
    k = math.sqrt(load / EI)
    beam_column = weight / (load * k * k) * (1.0 / math.cos(k * LENGTH / 2) - 1.0) - weight * LENGTH**2 / (8 * load)
    deflection = -50.0 - float(start["position"][..., 2].min())
    assert deflection == pytest.approx(beam_column, rel=1e-3)
    assert deflection > 1.3 * 5 * weight * LENGTH**4 / (384 * EI)     # the compression's amplification
