"""The lumped model's outputs and checks do less work, and give the very same numbers (to the bit):

* :meth:`kanat.lumped.system.LumpedSystem.loads` with ``masses=False`` gives the forces (and seabed
  normal forces) of the full call, and those of :func:`kanat.lumped.kernels.forces` on a network with
  nothing but elements;
* the outputs of a network with a point body, a 6-DOF body or none equal the same outputs worked out
  the long way (every load, the mass matrix solved: eq. O1 of :mod:`kanat.lumped.mooring_outputs`);
* the seabed check names the node that the check over every node (non-cable nodes at ``-inf``) names;
* a motion without a ramp samples to ``r q`` and ``r q_dot + r' q`` with the ramp's own ``r = 1, r' = 0``;
* the run loop's screen finds a non-finite scalar as well as a non-finite array entry.
"""
from pathlib import Path

import numpy as np
import pytest

from kanat.dynamics import Point, _non_finite
from kanat.io import load_case
from kanat.io.schema import Layout
from kanat.lumped import kernels
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.integrators import state_positions
from kanat.lumped.mooring_outputs import line_forces
from kanat.physics.motion import MotionTable, compile_motion
from kanat.physics.motion_samples import _unramped, motion_series
from kanat.physics.ramp import ramp_series
from kanat.step_control import Steps

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CASES = {"point body": ("subsurface_mooring.yaml", {"model": "lumped", "simulation.scheme": "rk4"}),
         "6-DOF body": ("mooring_buoy_decay.yaml", {}),
         "no body, seabed, current": ("mooring_current.yaml", {"model": "lumped"})}


def model_of(name):
    file, changes = CASES[name]
    case = load_case(EXAMPLES / file).replace({**changes, "simulation.duration": 0.5, "simulation.output_dt": 0.5})
    return LumpedModel(case)


def moved(model):
    """All nodes' x, v of the model's initial state with the free nodes set moving (a state with drag)."""
    state = model.initial()
    xf, vf = state_positions(state.scheme)
    vf = vf + 0.3 * np.sin(np.arange(vf.size)).reshape(vf.shape)
    x, v, a, heading = model.system.full(0.2, xf, vf)
    return state, x, v, a, heading


@pytest.mark.parametrize("name", CASES)
def test_forces_without_the_mass_blocks_are_the_full_calls_forces(name):
    model = model_of(name)
    system = model.system
    _, x, v, _, heading = moved(model)
    F, M = (part.copy() for part in system.loads(0.2, x, v, heading))
    normal = system.normal_force.copy()
    system._M[:] = -1.0
    F_only = system.loads(0.2, x, v, heading, masses=False)[0]
    assert F_only.tobytes() == F.tobytes()
    assert system.normal_force.tobytes() == normal.tobytes()
    if not system.net.rigid.count:
        assert np.all(system._M == -1.0)                   # left as they were
    np.testing.assert_array_equal(system.loads(0.2, x, v, heading)[1], M)


def test_loads_of_a_bare_network_are_the_force_kernels():
    model = model_of("no body, seabed, current")
    model.system.contact = None                                                  # no seabed: elements alone
    system, net = model.system, model.net
    _, x, v, _, heading = moved(model)
    uw, aw = system.water(0.2, 0.5 * (x[net.el_i] + x[net.el_j]))
    n, m = net.n_nodes, net.n_elements
    F, M, T, strain = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros(m), np.zeros(m)
    kernels.forces(x, v, uw, aw, net.node_force, system.node_mass, system.el_args, F, M, T, strain,
                   system.wetted(0.2, x).copy())
    got_F, got_M = system.loads(0.2, x, v, heading)
    assert got_F.tobytes() == F.tobytes() and got_M.tobytes() == M.tobytes()
    assert system.tension.tobytes() == T.tobytes()


@pytest.mark.parametrize("name", CASES)
def test_outputs_are_those_of_every_load_and_the_solved_mass(name):
    model = model_of(name)
    system = model.system
    state = model.initial()
    values = model.outputs(state)
    t = state.scheme.t
    x, v, a, heading = system.full(t, *state_positions(state.scheme))
    F, M = system.loads(t, x, v, heading)
    a = system.solve_mass(x, F, M, a)
    T = values["segment_tension"]
    np.testing.assert_array_equal(values["anchor_force"],
                                  model._mooring.anchor_forces(F, system.normal_force, model._friction))
    np.testing.assert_array_equal(values["seabed_contact_length"], model._mooring.contact_length(system.normal_force))
    np.testing.assert_array_equal(values["body_force"], line_forces(system, t, x, v, a, heading, T))
    if name == "point body":
        assert np.any(values["body_force"] != 0.0)
    if name.startswith("no body"):
        assert np.any(system.normal_force > 0.0) and np.any(values["anchor_force"] != 0.0)


def test_the_seabed_check_names_the_node_the_check_over_every_node_names():
    model = model_of("no body, seabed, current")
    state, x, *_ = moved(model)
    seabed, net = model._seabed, model.net
    cables = np.zeros(net.n_nodes, bool)
    cables[net.node_index] = True
    assert model._below_seabed(x, 0.2) is None
    x = x.copy()
    deep = [int(net.node_index[3]), int(net.node_index[5])]
    x[deep, 2] -= [0.4, 0.7]                                 # two nodes pushed into the seabed
    excess = np.where(cables, seabed.penetration(x), -np.inf) - model.penetration
    worst = int(np.argmax(excess))
    assert worst == deep[1]
    message = model._below_seabed(x, 0.2)
    assert f"a node is {seabed.penetration(x)[worst]:.4g} m below the seabed" in message
    assert net.where(worst) in message


HARMONICS = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
             {"dof": "surge", "amplitude": 0.5, "period": 5.0},
             {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
TABLE = MotionTable(time=np.array([0.0, 5.0, 10.0]),
                    values=np.array([[0.0, 0, 0, 0, 0, 0], [2.0, 0, 0.5, 0, 0.01, 0], [-1.0, 0, 0.5, 0, -0.02, 0]]))


@pytest.mark.parametrize("kind", ["harmonics", "table"])
def test_a_motion_without_ramp_samples_as_the_ramps_formula(kind):
    if kind == "table":
        compiled = TABLE
    else:
        case = load_case(EXAMPLES / "mooring_current.yaml").replace(
            {"model": "lumped", "vessel.motion": HARMONICS, "simulation.duration": 1.0})
        compiled = compile_motion(case.vessel.motion, case.environment)
    assert compiled.ramp == 0.0
    times = np.linspace(-1.0, 12.0, 57)
    q, v = _unramped(compiled, times)
    r, rate = ramp_series(times, compiled.ramp)
    got_q, got_v = motion_series(compiled, times)
    np.testing.assert_array_equal(got_q, r[:, None] * q)
    np.testing.assert_array_equal(got_v, r[:, None] * v + rate[:, None] * q)
    assert np.any(got_v != 0.0)


LAYOUT = Layout({}, {}, ("vessel_heading", "tension"), {})


@pytest.mark.parametrize("heading", [np.nan, np.float64(np.inf), float("-inf")])
def test_a_non_finite_scalar_output_is_found(heading):
    point = Point(2, 0.5, {"tension": np.ones(4), "vessel_heading": heading}, None, Steps(), None)
    assert "t = 0.5 s in vessel_heading" in _non_finite(LAYOUT, point)


def test_finite_scalars_and_integer_arrays_pass():
    point = Point(2, 0.5, {"tension": np.arange(4), "vessel_heading": 0.25, "count": 3}, None, Steps(), None)
    assert _non_finite(LAYOUT, point) is None


def jacobian_entries_one_by_one(force, free, xf, colour, step, neighbours_of):
    """The equilibrium's coloured differences entry by entry (the loop :func:`_jacobian_entries` replaces)."""
    position = {node: k for k, node in enumerate(free)}
    rows, cols, vals = [], [], []
    for c in range(colour[free].max() + 1):
        group = np.flatnonzero(colour[free] == c)
        for r in range(3):
            dx = np.zeros_like(xf)
            dx[group, r] = step
            dF = (force(xf + dx) - force(xf - dx)) / (2 * step)
            for k in group:
                for node in neighbours_of[free[k]]:
                    if node in position:
                        m = position[node]
                        rows.extend(3 * m + np.arange(3))
                        cols.extend([3 * k + r] * 3)
                        vals.extend(dF[m])
    return np.array(rows, dtype=np.int64), np.array(cols, dtype=np.int64), np.array(vals, dtype=float)


@pytest.mark.parametrize("name", CASES)
def test_the_equilibriums_jacobian_entries_are_those_worked_out_one_by_one(name):
    from kanat.lumped.equilibrium import _jacobian_entries, distance2_colouring, node_graph

    model = model_of(name)
    system, net = model.system, model.net
    free = system.free_index
    _, x, v, _, heading = moved(model)

    def force(q):
        y = x.copy()
        y[free] = q
        return system.loads(0.0, y, v, heading)[0][free].copy()

    neighbours = node_graph(net)
    colour = distance2_colouring(net)
    got = _jacobian_entries(force, free, x[free], colour, 1e-4, neighbours)
    expected = jacobian_entries_one_by_one(force, free, x[free], colour, 1e-4, neighbours)
    for part, reference in zip(got, expected):
        assert part.dtype == reference.dtype and part.tobytes() == reference.tobytes()
    assert len(got[0]) > 9 * len(free)


@pytest.mark.parametrize("file", ["lazy_wave.yaml", "subsurface_mooring.yaml"])
def test_body_loads_in_a_uniform_current_are_those_of_the_water_at_each_body(file):
    case = load_case(EXAMPLES / file).replace({"model": "lumped", "simulation.scheme": "rk4",
                                               "environment.current": {"velocity": [0.4, -0.1, 0.0]}})
    model = LumpedModel(case)
    system = model.system
    assert system._uniform and len(system.net.load_node)
    _, x, v, _, heading = moved(model)
    F = system.loads(0.2, x, v, heading)[0].copy()
    system._uniform = False                                  # the water sampled at the bodies and midpoints
    assert system.loads(0.2, x, v, heading)[0].tobytes() == F.tobytes()
