"""Dynamic relaxation (kanat.lumped.relaxation), the lumped equilibrium's fallback, against closed forms.

Oracle: a chain of tension-only springs hanging from a fixed point under point weights, started
stretched, bent and sideways; at rest each spring carries the weight below it, so node j (of n, counted
from the top) hangs at z_j = -sum_{i <= j} (L + (n - i + 1) W / k), x_j = 0.
"""
import numpy as np
import pytest
import scipy.sparse as sp

from kanat.lumped.relaxation import fictitious_masses, relax

N, L, W, K = 12, 2.0, 50.0, 1e5           # nodes, rest length [m], weight [N], stiffness [N/m]


def chain_force(q):
    """Forces (N, 3) on the free nodes of the hanging chain at positions ``q`` (N, 3)."""
    x = np.vstack([np.zeros(3), q])
    d = x[1:] - x[:-1]
    length = np.linalg.norm(d, axis=1)
    tension = K * np.maximum(length - L, 0.0)                 # tension only: slack springs push nothing
    pull = (tension / length)[:, None] * d                   # on the lower end, towards the upper
    F = -pull
    F[:-1] += pull[1:]
    F[:, 2] -= W
    return F


def chain_tangent(q):
    """``dF/dq`` (3N square) by central differences, as ``(rows, cols, values)``: the solver needs
    only its size."""
    n, h = q.size, 1e-6
    J = np.zeros((n, n))
    for c in range(n):
        dq = np.zeros(n)
        dq[c] = h
        J[:, c] = (chain_force(q + dq.reshape(q.shape)) - chain_force(q - dq.reshape(q.shape))).ravel() / (2 * h)
    J = sp.coo_matrix(J)
    return J.row, J.col, J.data


def test_relaxation_hangs_a_bent_chain_at_its_closed_form():
    """From a zigzag swung 30 degrees aside, every spring stretched 1 %: it passes through slack
    (the swing) on its way down."""
    k = np.arange(1, N + 1)
    step = 1.01 * L * np.column_stack([np.sin(np.radians(30 + 20 * (-1) ** k)), np.zeros(N),
                                       -np.cos(np.radians(30 + 20 * (-1) ** k))])
    start = np.cumsum(step, axis=0)
    relaxed = relax(chain_force, chain_tangent, start, target=1e-6)
    tension = (N - np.arange(N)) * W
    z = -np.cumsum(L + tension / K)
    assert relaxed.residual <= 1e-6
    assert np.max(np.abs(relaxed.position[:, 2] - z)) < 1e-8 * N * L
    # sideways, 1e-6 N over the lowest spring's transverse stiffness W / L (25 N/m), summed over N nodes
    assert np.max(np.abs(relaxed.position[:, :2])) < N * 1e-6 / (W / L) * 2
    assert relaxed.peaks > 0                                 # kinetic damping did the settling


def test_fictitious_masses_bound_the_unit_step():
    """Eq. (2): with these masses the explicit unit step is stable, h^2 lambda_max(M^-1 K) <= 4 / MASS_SAFETY."""
    q = np.column_stack([np.zeros(N), np.zeros(N), -np.cumsum(np.full(N, L * 1.01))])
    J = chain_tangent(q)
    m = np.repeat(fictitious_masses(J, 1e-9, N), 3)
    dense = sp.coo_matrix((J[2], (J[0], J[1])), shape=(3 * N, 3 * N)).toarray()
    largest = np.max(np.abs(np.linalg.eigvals(dense / m[:, None])))
    assert largest <= 2.0 + 1e-9
    assert largest == pytest.approx(2.0, rel=0.6)             # and not far heavier than needed


def grounded_chain():
    """examples/mooring_current.yaml in still water at 35 segments, lumped, with the default seabed it
    gets from ``environment.depth`` (stiffness 3e6 Pa/m): 529 m of its 700 m chain on the seabed."""
    from helpers import EXAMPLES
    from kanat import load_case

    return load_case(EXAMPLES / "mooring_current.yaml").replace({
        "model": "lumped", "cables[0].segments": 35, "environment.current": {"profile": [[0, 0, 0, 0]]},
        "simulation": {"duration": 1.0, "dt": 0.05}}).with_seabed_contact()


@pytest.mark.slow
def test_relaxation_lays_a_chain_on_the_seabed_as_newtons_method_and_the_catenary_do():
    """The fallback (equilibrium._relaxed_equilibrium) softens the seabed contact with the line, so a node
    on the seabed is not 1e4 times stiffer than its neighbours in the fictitious masses: 632 relaxation
    steps here, where the contact left at its true stiffness took 92,070 (53 s; WHOI's deep_s stalled).
    Oracles: the same discrete equilibrium by Newton's method from the catenary guess (the equilibrium's
    direct path) to 1e-6 m; the anchor tension against the elastic catenary on a frictionless seabed
    (network statics), within 2 % (20 m elements: the touchdown moves by whole elements; 0.5 % at
    70 segments); no node deeper than the run's seabed check allows."""
    from kanat import solve_statics
    from kanat.lumped.equilibrium import _relaxed_equilibrium, equilibrium
    from kanat.lumped.mooring_outputs import allowed_penetration
    from kanat.lumped.network import build_network
    from kanat.physics.seabed import seabed_of

    case = grounded_chain()
    net = build_network(case)
    relaxed, info = _relaxed_equilibrium(net, case, None, True, 0.0)
    direct, _ = equilibrium(net, case)
    assert info["fallback"] == "dynamic relaxation" and info["relaxation_steps"] < 5_000
    assert np.max(np.abs(relaxed - direct)) < 1e-6
    stretched = np.linalg.norm(relaxed[net.el_j[0]] - relaxed[net.el_i[0]]) / net.el_length[0] - 1
    anchor_tension = net.law_y[0, 0] * stretched                  # the chain's linear law: EA strain
    catenary = solve_statics(case.replace({"model": "statics"}))
    assert anchor_tension == pytest.approx(float(catenary["tension"].values[0]), rel=0.02)
    assert np.all(seabed_of(case.environment).penetration(relaxed) <= allowed_penetration(net, case.environment))
