"""Natural modes of the linearised lumped system (kanat.modes, kanat.linearize; issue 26) against:

* a taut string between two anchors: the lumped chain's exact discrete frequencies, transverse
  ``2 sqrt(T / (mu_t l0 l)) sin(n pi / 2N)`` and axial ``2 sqrt(EA / (mu l0^2)) sin(n pi / 2N)``
  (``l0`` the unstretched and ``l`` the stretched element, ``mu_t`` with the added mass), which
  tend to ``n pi / L sqrt(T / mu_t)`` and ``n pi / L sqrt(EA / mu)``;
* a heavy chain hanging from a fixed point: ``omega_n = j_0,n / 2 sqrt(g / L)`` (``j_0,n`` the
  zeros of Bessel's J0; Rayleigh, Theory of Sound §331), converging as ``N^-2``;
* a taut two-leg mooring of a buoy: the lowest mode's frequency against the period of the
  nonlinear time domain's free decay (rk4) from a 1 m offset.
"""
import math

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg  # noqa: F401 - sp.linalg.norm
import scipy.special

import kanat
from kanat.frequency.modes import eigenmodes
from kanat.lumped.integrators import SCHEMES, state_positions
from kanat.lumped.stepping import step_info
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.schemes import get_scheme
from tests.helpers import zero_crossing_period

from helpers import EXAMPLES

G = 9.81
pytestmark = pytest.mark.filterwarnings("ignore:.*must stretch:kanat.errors.CaseWarning")


def line_type(mass, weight, stiffness, added_mass=0.0, diameter=0.01):
    return dict(diameter=diameter, mass=mass, weight_in_water=weight, axial_stiffness=stiffness,
                added_mass=added_mass, drag_normal=0.0, drag_tangential=0.0)


def make_case(cables, line, bodies=None, mass_matrix="lumped"):
    return Case.model_validate(dict(model="lumped", line_types={"c": line}, bodies=bodies or {}, cables=cables,
                                    simulation=dict(duration=1, dt=0.01, mass_matrix=mass_matrix)))


def taut_string(segments, length=100.0, ea=1e5, tension=1000.0, mass=1.0, added=0.5):
    span = length * (1 + tension / ea)
    return make_case([dict(name="string", line_type="c", length=length, segments=segments,
                           **{"from": "anchor:[0,0,-10]"}, to=f"anchor:[{span},0,-10]")],
                     line_type(mass, 0.0, ea, added)), span


def test_taut_string_frequencies_are_the_lumped_chains_exact_ones():
    segments, length, ea, tension, mass, added = 20, 100.0, 1e5, 1000.0, 1.0, 0.5
    case, span = taut_string(segments, length, ea, tension, mass, added)
    lin = kanat.linearize(case)
    values, vectors = eigenmodes(lin, n=3 * (segments - 1))
    omega = np.sqrt(values)
    n = np.arange(1, segments)
    l0, l = length / segments, span / segments
    transverse = 2 * np.sqrt(tension / ((mass + added) * l0 * l)) * np.sin(n * np.pi / (2 * segments))
    axial = 2 * np.sqrt(ea / (mass * l0 * l0)) * np.sin(n * np.pi / (2 * segments))
    exact = np.sort(np.r_[transverse, transverse, axial])
    assert omega == pytest.approx(exact, rel=1e-6)
    assert lin.asymmetry < 1e-6
    assert abs(lin.damping).max() == 0.0                # no damping, and drag has no slope at rest


def test_taut_string_tends_to_the_continuous_string():
    case, span = taut_string(40)
    ds = kanat.modes(case, n=4)
    assert list(ds.direction.values) in (["y", "z", "y", "z"], ["z", "y", "z", "y"])
    continuous = np.array([1, 1, 2, 2]) * math.pi * math.sqrt(1000.0 / (1.5 * 100.0 * span))   # mu_t per L0
    assert ds.natural_frequency.values == pytest.approx(continuous, rel=1.1e-3)   # dispersion (n pi / 2N)^2 / 6
    shape = ds.mode_shape.sel(mode=1).values
    transverse = shape[:, 1] if ds.direction.values[0] == "y" else shape[:, 2]
    xi = ds.s.values / 100.0
    assert transverse == pytest.approx(np.sin(np.pi * xi), abs=1e-6)    # the discrete sine, exactly


def hanging_chain(segments, length=10.0, mass_matrix="lumped"):
    """A chain of 1 kg/m in vacuum fixed at the top with a 1 g weight at its foot (the weight's
    ``position`` starts the equilibrium below the top)."""
    bodies = {"foot": dict(mass=1e-3, net_buoyancy=-1e-3 * G, position=[0.0, 0.0, -1.0 - length])}
    return make_case([dict(name="chain", line_type="c", length=length, segments=segments,
                           **{"from": "anchor:[0,0,-1]"}, to="foot")], line_type(1.0, G, 1e6), bodies,
                     mass_matrix)


def test_hanging_chain_against_bessel_zeros_converges_at_second_order():
    length = 10.0
    exact = scipy.special.jn_zeros(0, 3) / 2 * math.sqrt(G / length)
    errors = []
    for segments in (20, 40):
        ds = kanat.modes(hanging_chain(segments, length), n=6)
        swing = ds.natural_frequency.values[ds.direction.values == "x"]
        errors.append(np.abs(swing / exact - 1))
    assert np.all(errors[1] < [0.001, 0.005, 0.015])
    assert errors[0][1:] / errors[1][1:] == pytest.approx(4.0, rel=0.1)    # modes 2, 3: N^-2


def test_consistent_mass_is_the_time_domains():
    """The consistent mass matrix of a straight string: rows sum to each node's share of the line's
    mass, ``mu_t l0`` across it and ``mu l0`` along it (eq. 9 conserves mass)."""
    case, _ = taut_string(10)
    lin = kanat.linearize(case.replace({"simulation.mass_matrix": "consistent"}))
    rows = np.asarray(lin.mass.sum(axis=1)).ravel().reshape(-1, 3)
    assert rows[1:-1] == pytest.approx(np.tile([1.0 * 10, 1.5 * 10, 1.5 * 10], (7, 1)), rel=1e-9)
    assert (lin.mass - lin.mass.T).count_nonzero() == 0


def buoy_mooring():
    """A buoy of 2 kN net buoyancy on two taut legs to anchors 36 m apart, 24 m below it."""
    leg = dict(line_type="c", length=30.0, segments=10)
    return make_case([dict(name="west", **leg, **{"from": "anchor:[-18,0,-44]"}, to="buoy"),
                      dict(name="east", **leg, **{"from": "anchor:[18,0,-44]"}, to="buoy")],
                     line_type(5.0, 10.0, 1e5, added_mass=2.0, diameter=0.05),
                     {"buoy": dict(mass=200.0, added_mass=100.0, net_buoyancy=2000.0, position=[0.0, 0.0, -20.0])})


def test_mooring_lowest_mode_against_the_time_domains_free_decay():
    """The buoy released at rest 1 m sideways (the legs' nodes moved in proportion to their distance
    from the anchor), integrated by the nonlinear time domain (rk4) over 4.5 periods: the period of
    its sway from zero crossings against the lowest mode (a sway, 0.389 rad/s): 0.2 % apart."""
    case = buoy_mooring()
    lin = kanat.linearize(case)
    values, _ = eigenmodes(lin, n=1)
    omega = math.sqrt(values[0])
    net = lin.net
    body = net.body_node[0]
    share = np.zeros(net.n_nodes)
    share[net.node_index] = net.node_s / 30.0
    share[body] = 1.0
    x = lin.position.copy()
    x[:, 1] += 1.0 * share
    system = LumpedSystem(net, case, waves=False)
    scheme = get_scheme("rk4", SCHEMES)
    h = step_info(net, x).safe_step(scheme)
    free = system.free_index
    state = scheme.start(system, 0.0, x[free], 0 * x[free], h)
    times, sway = [], []
    for _ in range(int(4.5 * 2 * math.pi / omega / h)):
        state = scheme.step(system, state, h)
        times.append(state.t)
        sway.append(system.full(state.t, *state_positions(state))[0][body, 1] - lin.position[body, 1])
    measured = 2 * math.pi / zero_crossing_period(np.array(times), np.array(sway))
    assert omega == pytest.approx(measured, rel=0.01)


def test_modes_command_prints_the_table_and_writes_the_modes(tmp_path):
    """``kanat modes`` on a taut string file: the first row is the exact discrete fundamental."""
    import xarray as xr
    from typer.testing import CliRunner

    from kanat.cli import app

    case = tmp_path / "string.yaml"
    case.write_text("model: lumped\nline_types:\n  c: {diameter: 0.01, mass: 1.0, weight_in_water: 0.0, "
                    "axial_stiffness: 1.0e+5, added_mass: 0.5, drag_normal: 0.0, drag_tangential: 0.0}\n"
                    "cables:\n  - {name: s, line_type: c, length: 100.0, segments: 10, "
                    "from: 'anchor:[0,0,-10]', to: 'anchor:[101,0,-10]'}\n"
                    "simulation: {duration: 1, dt: 0.01}\n")
    out = tmp_path / "modes.nc"
    result = CliRunner().invoke(app, ["modes", str(case), "-n", "2", "-o", str(out)])
    assert result.exit_code == 0, result.output
    exact = 2 * math.sqrt(1000.0 / (1.5 * 10.0 * 10.1)) * math.sin(math.pi / 20)
    first = next(line.split() for line in result.output.splitlines() if line.split()[:1] == ["1"])
    assert float(first[1]) == pytest.approx(exact, rel=1e-4)
    assert float(first[2]) == pytest.approx(2 * math.pi / exact, rel=1e-4)
    with xr.open_dataset(out) as ds:
        assert ds.natural_frequency.values == pytest.approx([exact, exact], rel=1e-6)
        assert ds.mode_shape.dims == ("mode", "node", "xyz")


@pytest.mark.slow
def test_six_dof_buoy_surge_mode_against_the_time_domains_free_decay():
    """examples/mooring_buoy_decay.yaml (a 6-DOF buoy on three catenary chains resting on the
    seabed) released 2 m off in surge: the period of its decay (drag-damped, zero crossings over
    160 s) against the mode in which the buoy surges most."""
    example = EXAMPLES / "mooring_buoy_decay.yaml"
    case = kanat.load_case(example).replace({"bodies.buoy.position": [2.0, 0.0, -2.0], "simulation.duration": 160.0,
                                             "simulation.output_dt": 0.5})
    lin = kanat.linearize(case)
    ds = kanat.modes(case, n=8)
    surge = int(np.argmax(np.abs(ds.body_mode_shape.sel(body="buoy", dof="x").values)))
    assert ds.direction.values[surge] == "x"
    result = kanat.simulate(case)
    x = result.body_position.sel(body="buoy").values[:, 0]
    offset = x - lin.position[lin.net.body_node[0], 0]
    measured = 2 * math.pi / zero_crossing_period(result.time.values, offset)
    assert float(ds.natural_frequency[surge]) == pytest.approx(measured, rel=0.03)


@pytest.mark.parametrize("bending", [0.0, 2.0e5])
def test_stiffness_is_the_implicit_schemes_analytic_tangent(bending):
    """``K`` by coloured finite differences against the generalized-α scheme's analytic tangent
    (kanat.lumped.implicit.jacobian: axial, geometric, seabed contact, bending) on a chain resting on
    the seabed, with and without bending stiffness: equal to 1e-6 of its norm (measured 3e-9, 2e-8)."""
    from kanat.lumped.implicit import jacobian

    chain = dict(diameter=0.1, mass=150.0, weight_in_water=1300.0, axial_stiffness=8e8, added_mass=8.0,
                 drag_normal=1.2, drag_tangential=0.5, bending_stiffness=bending)
    case = Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0, "seabed": {"friction": 0.0}}, line_types={"chain": chain},
        cables=[dict(name="leg", line_type="chain", length=400.0, segments=40, **{"from": "anchor:[0, 0, -100]"},
                     to="anchor:[375, 0, -10]")], simulation={"duration": 1.0, "dt": 0.01}))
    lin = kanat.linearize(case)
    system = LumpedSystem(lin.net, case, waves=False, friction=False)
    x, v = lin.position, np.zeros_like(lin.position)
    system.loads(0.0, x, v, 0.0)                          # the contact's normal forces at x
    analytic = jacobian(system, 0.0, x, v, 0.0, 0.0, 1.0, np.zeros((lin.net.n_nodes, 3, 3)))
    assert np.count_nonzero(system.normal_force) > 5     # some of the chain lies on the seabed
    difference = sp.linalg.norm(lin.stiffness - analytic) / sp.linalg.norm(analytic)
    assert difference < 1e-6


def test_damping_is_the_axial_damping_and_no_drag_in_still_water():
    """A straight taut string with axial damping ``c`` [N s] and drag: ``C`` is ``c / EA`` times the
    axial (x) part of ``K`` (a linear law: ``T = EA e + c e_dot``), with nothing across the line (a
    transverse velocity of a straight line stretches it at second order, and drag ``|u| u`` has no
    slope at rest: its central difference is of the order of the step)."""
    line = dict(line_type(1.0, 0.0, 1e5, 0.5), axial_damping=300.0, drag_normal=1.2, drag_tangential=0.5)
    case = make_case([dict(name="string", line_type="c", length=100.0, segments=10,
                           **{"from": "anchor:[0,0,-10]"}, to="anchor:[101,0,-10]")], line)
    lin = kanat.linearize(case)
    along = lin.xyz == 0
    C, K = lin.damping.toarray(), lin.stiffness.toarray()
    scale = np.abs(C).max()                              # 2 c / l0 = 60 N s/m
    # drag's central difference at rest is 1/2 rho C_D d l0 x VELOCITY_STEP (6e-5 N s/m), not zero
    assert C[np.ix_(along, along)] == pytest.approx(300.0 / 1e5 * K[np.ix_(along, along)], abs=2e-6 * scale)
    assert np.abs(C[~along]).max() < 2e-6 * scale


def test_sparse_shift_invert_finds_the_dense_modes(monkeypatch):
    """Above DENSE_LIMIT degrees of freedom ARPACK's shift-invert about 0 takes over: the same lowest
    frequencies as the dense solver on the taut string."""
    import sys

    lin = kanat.linearize(taut_string(20)[0])
    dense, _ = eigenmodes(lin, n=6)
    monkeypatch.setattr(sys.modules["kanat.frequency.modes"], "DENSE_LIMIT", 10)
    sparse, shapes = eigenmodes(lin, n=6)
    assert sparse == pytest.approx(dense, rel=1e-9)
    assert np.abs(shapes).max(axis=0) == pytest.approx(np.ones(6))
