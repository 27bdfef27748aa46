"""The lumped model against independent oracles (theory/lumped.md, theory/validation-cases.md §10; issue 5):

* energy conservation of a pendulum chain without drag or damping (0.5 % over 100 periods);
* a hanging line against the closed-form elastic catenary (0.5 % on tension);
* a taut line's axial and transverse natural frequencies (2 %);
* a mass dropped on an elastic tether: snap peak tension from energy balance;
* generalized-α's amplification at infinity (every scheme's order: test_scheme_order.py).
"""
import math

import numpy as np
import pytest

from kanat import api
from kanat.io.results import read_result
from kanat.lumped import kernels
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.integrators import SCHEMES, ImplicitState, state_positions
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.stepping import step_info
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.schemes import get_scheme
from kanat.statics.catenary import elastic_catenary

G = 9.81


def vacuum_line(mass=1.0, stiffness=2e3, **extra):
    """A line with no buoyancy, drag or added mass: weight in water = weight in air."""
    return dict(diameter=0.01, mass=mass, weight_in_water=mass * G, axial_stiffness=stiffness,
                drag_normal=0.0, drag_tangential=0.0, **extra)


def make_case(cables, line, bodies=None, **sim):
    return Case.model_validate(dict(model="lumped", line_types={"c": line}, bodies=bodies or {},
                                    cables=cables, simulation=dict(duration=1, dt=0.01, **sim)))


def integrate(system, scheme, x, v, h, steps, every=1, observe=None):
    free = system.free_index
    state = scheme.start(system, 0.0, x[free], v[free], h)
    for n in range(steps):
        state = scheme.step(system, state, h)
        if observe is not None and (n + 1) % every == 0:
            observe(state)
    return state


def chain(segments=3, stiffness=2e3):
    case = make_case([dict(name="chain", line_type="c", length=float(segments), segments=segments,
                           **{"from": "anchor:[0,0,0]"}, to="free")], vacuum_line(stiffness=stiffness))
    net = build_network(case)
    x = np.zeros((net.n_nodes, 3))
    x[net.node_index, 0] = net.node_s                        # horizontal, unstretched, at rest
    return case, net, x


def energy(system, state):
    """Kinetic + gravity + elastic energy of a vacuum network (lumped masses, linear law)."""
    net = system.net
    x, v, _, _ = system.full(state.t, *state_positions(state))
    mass = net.node_mass.copy()
    np.add.at(mass, net.el_i, 0.5 * net.el_mass * net.el_length)
    np.add.at(mass, net.el_j, 0.5 * net.el_mass * net.el_length)
    strain = np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1) / net.el_length - 1.0
    elastic = np.sum(0.5 * net.law_y[0, 0] * np.maximum(strain, 0.0) ** 2 * net.el_length)
    return 0.5 * np.sum(mass * np.sum(v * v, axis=1)) + G * np.sum(mass * x[:, 2]) + elastic


def bob_pendulum(angle_deg=30.0, bob=10.0, length=2.0, ea=3e3, line_mass=5.0):
    """Two links and a bob, released at rest at ``angle_deg`` from the vertical, the links
    pre-stretched by the bob's static pull so that they stay taut and smooth."""
    case = make_case([dict(name="chain", line_type="c", length=length, segments=2,
                           **{"from": "anchor:[0,0,0]"}, to="b")], vacuum_line(line_mass, ea),
                     bodies={"b": dict(mass=bob, net_buoyancy=-bob * G)})
    net = build_network(case)
    a = math.radians(angle_deg)
    stretch = 1.0 + (bob + 0.5 * line_mass * length) * G * math.cos(a) / ea
    x = np.zeros((net.n_nodes, 3))
    x[net.node_index] = np.outer(net.node_s * stretch, [math.sin(a), 0.0, -math.cos(a)])
    swing_energy = (bob * length + line_mass * length * length / 2) * G * (1.0 - math.cos(a))   # bob + links
    return case, net, x, swing_energy


@pytest.mark.slow
@pytest.mark.parametrize("name", ["rk4", "abm4"])
def test_pendulum_chain_conserves_energy_over_100_periods(name):
    case, net, x, swing_energy = bob_pendulum()
    system = LumpedSystem(net, case)
    scheme = get_scheme(name, SCHEMES)
    h = 0.3 * step_info(net, x).safe_step(scheme)
    period = 2 * math.pi * math.sqrt(2.0 / G)
    bob = net.body_node[0]
    energies, sway = [], []

    def observe(state):
        energies.append(energy(system, state))
        sway.append(system.full(state.t, *state_positions(state))[0][bob, 0])

    e0 = energy(system, scheme.start(system, 0.0, x[system.free_index], 0 * x[system.free_index], h))
    integrate(system, scheme, x, 0 * x, h, int(110 * period / h), every=10, observe=observe)
    sway = np.array(sway)
    assert np.count_nonzero(np.sign(sway[1:]) != np.sign(sway[:-1])) >= 200    # 100 periods or more
    drift = np.max(np.abs(np.array(energies) - e0)) / swing_energy
    assert drift < 5e-3, f"energy drift {100 * drift:.3f} % of the swing energy"


@pytest.mark.parametrize("segments", [20, 40])
def test_hanging_line_matches_the_elastic_catenary(segments):
    span, rise, length, weight, ea = 80.0, 60.0, 120.0, 150.0, 5e6
    down = 200.0                       # wholly under water (an element above it loses its buoyancy)
    case = make_case([dict(name="line", line_type="c", length=length, segments=segments,
                           **{"from": f"anchor:[0,0,{-down}]"}, to=f"anchor:[{span},0,{rise - down}]")],
                     dict(diameter=0.05, mass=20.0, weight_in_water=weight, axial_stiffness=ea))
    net = build_network(case)
    x, info = equilibrium(net, case)
    assert info["residual"] < 1e-6
    exact = elastic_catenary(span, rise, length, weight, ea, n_points=2 * segments + 1)
    T = ea * (np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1) / net.el_length - 1.0)
    error = np.max(np.abs(T - exact.tension[1::2])) / exact.tension_upper   # elements vs midpoints
    assert error < 5e-3
    assert np.max(np.abs(x[net.node_index, 2] + down - exact.z[::2])) < 0.002 * length
    assert T[-1] == pytest.approx(exact.tension[-2], rel=5e-3)


def zero_crossing_period(t, signal):
    s = signal - signal.mean()
    idx = np.flatnonzero((s[1:] > 0) & (s[:-1] <= 0))
    crossings = t[idx] - s[idx] * (t[idx + 1] - t[idx]) / (s[idx + 1] - s[idx])
    return np.mean(np.diff(crossings))


@pytest.mark.parametrize("mode", ["axial", "transverse"])
def test_taut_line_natural_frequencies(mode):
    length, segments, ea, pretension, m, ma = 100.0, 40, 1e5, 1000.0, 1.0, 0.5
    stretched = length * (1 + pretension / ea)
    line = dict(diameter=0.01, mass=m, weight_in_water=0.0, axial_stiffness=ea, added_mass=ma,
                drag_normal=0.0, drag_tangential=0.0)
    case = make_case([dict(name="line", line_type="c", length=length, segments=segments,
                           **{"from": "anchor:[0,0,-10]"}, to=f"anchor:[{stretched},0,-10]")], line)
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = np.zeros((net.n_nodes, 3))
    x[net.node_index, 0] = net.node_s * stretched / length
    x[net.node_index, 2] = -10.0
    xi = net.node_s / length
    amplitude = 0.05 if mode == "transverse" else 0.002
    component = 2 if mode == "transverse" else 0
    x[net.node_index, component] += amplitude * np.sin(math.pi * xi) * (1 if mode == "transverse" else length)
    if mode == "axial":
        exact = math.pi / length * math.sqrt(ea / m)
        exact *= 1.0 - (math.pi / segments) ** 2 / 24      # leading dispersion of the lumped chain is O(1e-3)
        exact = math.pi / length * math.sqrt(ea / m)
    else:
        exact = math.pi / length * math.sqrt(pretension / (m + ma))
    scheme = get_scheme("rk4", SCHEMES)
    h = step_info(net, x).safe_step(scheme)
    steps = int(3.2 * 2 * math.pi / exact / h)
    mid = net.node_index[segments // 2]
    times, values = [], []
    integrate(system, scheme, x, 0 * x, h, steps, observe=lambda s: (
        times.append(s.t), values.append(system.full(s.t, *state_positions(s))[0][mid, component])))
    omega = 2 * math.pi / zero_crossing_period(np.array(times), np.array(values))
    assert omega == pytest.approx(exact, rel=0.02)


def test_mass_dropped_on_a_tether_snaps_to_the_energy_balance_peak():
    """A body of mass M on a light one-element tether (stiffness k = EA/L), released at rest
    a height ``drop`` above the point where the tether becomes taut, falls freely, then
    stretches it: M g (drop + delta) = k delta^2 / 2, T_peak = k delta (energy balance)."""
    length, ea, mass, drop = 10.0, 1e6, 100.0, 2.0
    line = vacuum_line(mass=1e-3, stiffness=ea)
    body = {"b": dict(mass=mass, net_buoyancy=-mass * G)}
    case = make_case([dict(name="tether", line_type="c", length=length, segments=1,
                           **{"from": "anchor:[0,0,0]"}, to="b")], line, bodies=body)
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = np.zeros((net.n_nodes, 3))
    x[net.body_node[0], 2] = -(length - drop)
    scheme = get_scheme("rk4", SCHEMES)
    h = 0.1 * step_info(net, x).safe_step(scheme)
    m_eff = mass + 0.5e-3 * length
    k = ea / length
    weight = m_eff * G
    delta = (weight + math.sqrt(weight**2 + 2 * k * weight * drop)) / k
    tracker = SnapTracker(0.0, np.zeros(1))
    T = np.zeros(1)

    def observe(state):
        xs, vs, _, _ = system.full(state.t, *state_positions(state))
        kernels.tensions(xs, vs, net.elements(), T)
        tracker.update(state.t, T)

    fall = math.sqrt(2 * drop / G)
    bounce = 2 * fall + math.pi * math.sqrt(m_eff / k)      # slack flight up and down + half a stretch cycle
    integrate(system, scheme, x, 0 * x, h, int((fall + 1.5 * bounce) / h), observe=observe)
    events = tracker.events()
    assert len(events["time"]) == 2                          # snapped, flew up slack, snapped again
    assert events["time"][0] == pytest.approx(fall, abs=2 * h)
    np.testing.assert_allclose(events["peak_tension"], k * delta, rtol=2e-3)
    v_impact = G * fall
    assert events["rise_rate"][0] == pytest.approx(k * v_impact, rel=0.02)   # dT/dt = k v at contact


@pytest.mark.parametrize("lam", [-1.0, -0.5, 0.0])
def test_generalized_alpha_damps_the_highest_frequency_by_lambda_inf(lam):
    """A stiff taut element under a hanging mass, stepped at omega h = 1e4. The scheme balances
    forces at the step's end (WBZ-α, ``alpha_f = 0``), so a deviation of the position from
    equilibrium is gone after one step (to ``1/(omega h)^2``), and the one-step map of the velocity
    and acceleration deviations ``(v, h a)`` has both eigenvalues at ``lambda_inf`` (spectral
    radius at infinity ``rho_inf``). At infinite stiffness ``x_1 = x_eq`` makes eq. (1) the map
    ``h a_1 = -(v + (1/2 - beta) h a) / beta``, ``v_1 = v + (1 - gamma) h a + gamma h a_1``, whose
    characteristic polynomial with the WBZ coefficients is ``(lambda + rho_inf)^2``."""
    ea, mass, length = 1e9, 10.0, 1.0
    body = {"b": dict(mass=mass, net_buoyancy=-mass * G)}
    case = make_case([dict(name="t", line_type="c", length=length, segments=1, **{"from": "anchor:[0,0,0]"},
                           to="b")], vacuum_line(mass=1e-6, stiffness=ea), bodies=body)
    net = build_network(case)
    system = LumpedSystem(net, case)
    z_eq = -length * (1 + mass * G / ea)
    omega = math.sqrt(ea / length / mass)
    h = 1e4 / omega
    scheme = get_scheme("generalized-alpha-lumped", SCHEMES, lambda_inf=lam)

    def step(z, v, u):
        """One step from the body at height z with vertical velocity v and acceleration u / h."""
        state = ImplicitState(0.0, np.array([[0.0, 0.0, z]]), np.array([[0.0, 0.0, v]]),
                              np.array([[0.0, 0.0, u / h]]))
        after = scheme.step(system, state, h)
        return after.x[0, 2] - z_eq, after.v[0, 2], h * after.a[0, 2]

    assert abs(step(z_eq - 1e-6, 0.0, 0.0)[0]) < 1e-6 / 1e4 ** 2 * 10      # the position balanced at once
    size = 1e-6 * omega
    columns = [step(z_eq, size, 0.0)[1:], step(z_eq, 0.0, size)[1:]]
    growth = np.array(columns).T / size                                     # d(v', u') / d(v, u)
    assert np.linalg.eigvals(growth) == pytest.approx([lam, lam], abs=2e-3)


def test_a_network_with_nothing_free_has_no_axial_period(tmp_path):
    """A single element from an anchor to the vessel: no node moves of itself, so there is no axial
    period (eq. 3 of kanat.lumped.stepping: infinite, not a huge number standing for it), the result
    says so, and the run steps at its output interval."""
    case = Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0}, line_types={"c": vacuum_line()},
        vessel={"motion": [{"dof": "heave", "amplitude": 1.0, "period": 9.0}]},
        cables=[dict(name="leg", line_type="c", length=100.0, segments=1, **{"from": "anchor:[0, 0, -99]"},
                     to={"vessel": [0, 0, 0]})],
        simulation={"duration": 2.0, "output_dt": 0.5}))
    net = build_network(case)
    assert step_info(net, net.x_guess).axial_period == math.inf
    out = api.run(case, output=tmp_path / "fixed.nc")
    assert out.status == "ok" and out.summary.dt == 0.5
    assert read_result(tmp_path / "fixed.nc").attrs["axial_period"] == math.inf
