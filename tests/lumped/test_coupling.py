"""kanat.Coupling: the lines driven from a host's loop against a prescribed-motion run of the same
case, against MoorDyn's own coupling API side by side, and its saved states continuing exactly.

Cases: MoorDyn's WD0050 chain (``tests/data/moordyn/wd0050_chain.dat``, one coupled point) and a
three-chain mooring of the OC4 class written for these tests (``three_chain_coupled.dat``, three
coupled points named out of file order by its lines; ``three_chain_body.dat``, the same on a Coupled
body).
"""
import math
import shutil
import warnings

import numpy as np
import pytest

import kanat
from kanat.errors import KanatError
from kanat import api
from kanat.io import load_case
from kanat.lumped import stepping
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem

from helpers import DATA, quiet
from helpers_moordyn import run_moordyn, secant

MOORDYN_DATA = DATA / "moordyn"
WD0050 = MOORDYN_DATA / "wd0050_chain.dat"
THREE = MOORDYN_DATA / "three_chain_coupled.dat"
BODY = MOORDYN_DATA / "three_chain_body.dat"
FAIRLEADS = np.array([[-40.868, 0.0, -14.0], [20.434, 35.3927, -14.0], [20.434, -35.3927, -14.0]])


def wd0050(**keys):
    with warnings.catch_warnings():          # the file's MoorDyn solver settings, not imported
        warnings.simplefilter("ignore")
        return load_case(WD0050).replace(keys) if keys else load_case(WD0050)


def driven_run(motion, duration, dt, scheme="generalized-alpha-lumped"):
    """WD0050 under a prescribed ``motion``, an output every ``dt``: implicit at ``dt``, or an explicit
    ``scheme`` at its safe step."""
    explicit = scheme != "generalized-alpha-lumped"
    case = wd0050(**{"model": "lumped", "vessel.motion": motion, "simulation.duration": duration,
                     "simulation.output_dt": dt, "simulation.dt": None if explicit else dt,
                     "simulation.scheme": scheme})
    with quiet():
        return case, kanat.simulate(case)


def node_forces(case, ds, k):
    """The force on the fairlead node of the run's output ``k`` (eq. (1)'s loads of
    :class:`kanat.lumped.system.LumpedSystem` at the stored positions and velocities)."""
    net = build_network(case)
    system = LumpedSystem(net, case)
    x, v = np.zeros((net.n_nodes, 3)), np.zeros((net.n_nodes, 3))
    x[net.node_index], v[net.node_index] = ds.position.values[k], ds.velocity.values[k]
    t = float(ds.time.values[k])
    F = system.loads(t, x, v, 0.0)[0]
    return F[net.vessel_nodes[0]]


def coupled(case, path, dt, steps, velocity=None):
    """The coupling of ``case`` driven along ``path(t)`` (1, 3) for ``steps`` steps of ``dt``, the host
    giving each step's start and the velocity ``velocity(t)``, the lines starting with its response
    to ``velocity(0)`` (default: the step's secant, and a start at rest): the forces and the nodes at
    every step, the start included."""
    coupling = kanat.Coupling(case)
    start = None if velocity is None else velocity(0.0)
    velocity = velocity or (lambda t: (path(t + dt) - path(t)) / dt)
    forces = [coupling.initialize(path(0.0), start)]
    nodes = [coupling.nodes()[0]]
    for k in range(steps):
        t = k * dt
        forces.append(coupling.step(t, dt, path(t), velocity(t)))
        nodes.append(coupling.nodes()[0])
    return np.array(forces)[:, 0], np.array(nodes)


def test_points_are_a_moordyn_files_coupled_points_in_file_order():
    coupling = kanat.Coupling(THREE)
    assert coupling.points == ["point4", "point5", "point6"]
    forces = coupling.initialize(FAIRLEADS)
    outward = FAIRLEADS[:, :2] / np.linalg.norm(FAIRLEADS[:, :2], axis=1)[:, None]
    pull = np.einsum("pk,pk->p", forces[:, :2], outward)
    assert np.all(pull > 0.0) and np.all(forces[:, 2] < 0.0)           # out to the anchors, and down
    assert pull[1] == pytest.approx(pull[2], rel=1e-9)
    assert pull[0] == pytest.approx(pull[1], rel=1e-4)                 # the file's coordinates to 6 digits


def two_chains(**keys):
    """Two 120 m chains (10 elements each, 100 kg/m, EA 1e8 N) from anchors 110 m either side, 50 m
    down, to vessel points 1 m either side of the origin, 5 m down; a statics case, changed by ``keys``."""
    east = {"name": "east", "line_type": "chain", "length": 120.0, "segments": 10,
            "from": {"vessel": [1.0, 0.0, -5.0]}, "to": {"anchor": [110.0, 0.0, -50.0]}}
    west = {"name": "west", "line_type": "chain", "length": 120.0, "segments": 10,
            "from": {"anchor": [-110.0, 0.0, -50.0]}, "to": {"vessel": [-1.0, 0.0, -5.0]}}
    case = kanat.load_case({"name": "two", "model": "statics", "environment": {"depth": 50.0},
                            "line_types": {"chain": {"diameter": 0.1, "mass": 100.0, "axial_stiffness": 1e8}},
                            "cables": [east, west]})
    return case.replace(keys) if keys else case


def test_points_are_a_yaml_cases_vessel_ends_in_cable_order():
    case = two_chains()
    coupling = kanat.Coupling(case)
    assert coupling.points == ["east.from", "west.to"]
    implicit = kanat.Coupling(case, scheme="generalized-alpha-lumped")
    assert implicit.inner_step(0.05) == 0.05                      # 0.1 s at most, dividing the step:
    assert implicit.inner_step(0.25) == pytest.approx(0.25 / 3)
    given = kanat.Coupling(case, scheme="generalized-alpha-lumped", substep=0.02)
    assert given.inner_step(0.05) == pytest.approx(0.05 / 3)
    forces = coupling.initialize([[1.0, 0.0, -5.0], [-1.0, 0.0, -5.0]])
    assert forces[0, 0] > 0.0 > forces[1, 0]
    assert forces[0, 0] == pytest.approx(-forces[1, 0], rel=1e-6)
    with pytest.raises(KanatError, match=r"shape \(2, 3\)"):
        coupling.step(0.0, 0.1, [[1.0, 0.0, -5.0]], [[0.0, 0.0, 0.0]])
    with pytest.raises(KanatError, match="the coupling is at t = 0"):
        coupling.step(1.0, 0.1, [[1.0, 0.0, -5.0], [-1.0, 0.0, -5.0]], np.zeros((2, 3)))


SEAS = {"regular": ({"type": "regular", "height": 2.0, "period": 8.0}, "generalized-alpha-lumped"),
        "jonswap": ({"type": "jonswap", "hs": 4.0, "tp": 10.0, "seed": 1}, "generalized-alpha-lumped")}


@pytest.mark.parametrize("waves, expected", SEAS.values(), ids=SEAS.keys())
def test_a_coupling_in_waves_takes_the_scheme_and_step_of_a_run(waves, expected):
    """The two chains in waves, neither scheme nor dt named, outputs every 0.5 s: the coupling takes the
    run's scheme and step, eq. (6) of :mod:`kanat.lumped.stepping` by hand with the waves' cost per force
    evaluation ``E = 1 + 0.052 n`` (``n`` sea components) and the implicit step of 400 steps per shortest
    period of the sea (a regular 8 s wave: 0.02 s); an implicit step costs 3 evaluations and a
    tangent worth 4: the implicit scheme in both (RK4's safe step is 7.7 ms; before the cost model
    counted the kept factors, RK4 in the regular wave). (Before, the coupling weighed no waves and stepped
    the implicit scheme at 0.1 s.)"""
    case = two_chains(**{"model": "lumped", "environment.waves": waves,
                         "simulation": {"duration": 10.0, "output_dt": 0.5}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = api.dynamic_model(case)
        coupling = kanat.Coupling(case)
    sea = run.system.sea
    evaluation = 1.0 + 0.052 * len(sea.omega)
    period = 8.0 if waves["type"] == "regular" else stepping.excitation_period(run.system)
    implicit = period / 400.0
    safe = 0.8 * 2.8 / coupling.info.omega_max                  # RK4 at 0.8 of its limit, eq. (5)
    costs = {"rk4": 4 * evaluation / min(safe, implicit), "generalized-alpha-lumped": (3 * evaluation + 4) / implicit}
    assert min(costs, key=costs.get) == expected
    step = 0.5 / math.ceil(0.5 / (safe if expected == "rk4" else implicit))
    assert run.scheme.name == coupling.scheme.name == expected
    assert run.dt == pytest.approx(step, rel=1e-12)
    assert coupling.inner_step(0.5) == run.dt


@pytest.mark.parametrize("scheme", ["generalized-alpha-lumped", "rk4"])
def test_a_coupled_drift_is_the_prescribed_motion_run_to_round_off(scheme):
    """The fairlead drifts at 0.1 m/s (a motion table, linear from before t = 0 to after the end): the
    host's positions and velocity at each step's start move it exactly as the run's table does, so at
    every coupling step of 0.05 s the nodes and the fairlead force are the run's outputs to round-off
    (the implicit scheme at 0.05 s, 60 steps; rk4 at its safe step, 10 steps)."""
    dt, steps = 0.05, 60 if scheme == "generalized-alpha-lumped" else 10
    rows = [[-10.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0], [100.0, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0]]
    case, ds = driven_run({"rows": rows}, steps * dt, dt, scheme)
    assert ds.attrs["status"] == "ok" and ds.attrs["scheme"] == scheme

    def path(t):
        return np.array([[0.1 * t, 0.0, 0.0]])

    forces, nodes = coupled(case, path, dt, steps, velocity=lambda t: np.array([[0.1, 0.0, 0.0]]))
    scale = np.max(np.abs(ds.position.values))
    assert np.max(np.abs(nodes - ds.position.values)) < 1e-9 * scale
    for k in (0, 1, steps // 2, steps):
        reference = node_forces(case, ds, k)
        np.testing.assert_allclose(forces[k], reference, rtol=0, atol=1e-7 * np.max(np.abs(reference)))


def test_a_rigid_vessel_drifting_and_turning_is_the_prescribed_motion_run_to_round_off():
    """The three-chain platform driven as one rigid body (``rigid_vessel=True``): surge 0.2 m/s, roll
    0.5, pitch -0.3, yaw 1 deg/s from before t = 0 (a motion table), the host giving (x, y, z, roll,
    pitch, yaw) and their rates at each step's start: every node and the resultant force are the
    run's to round-off, and the moment is that of the run's fairlead forces about the moved origin,
    eq. (3) of kanat.coupling, at every one of 10 steps of 0.1 s."""
    dt, steps = 0.1, 10
    rate = np.array([0.2, 0.0, 0.0, *np.radians([0.5, -0.3, 1.0])])
    rows = [[t, *(t * rate[:3]), *np.degrees(t * rate[3:])] for t in (-10.0, 100.0)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(THREE).replace({"model": "lumped", "vessel.motion": {"rows": rows},
                                         "simulation": {"duration": steps * dt, "output_dt": dt, "dt": dt}})
    with quiet():
        ds = kanat.simulate(case)
    assert ds.attrs["status"] == "ok"
    coupling = kanat.Coupling(case, rigid_vessel=True)
    assert coupling.points == ["vessel"]
    forces, nodes = [coupling.initialize([np.zeros(6)], [rate])], [coupling.nodes()[0]]
    for k in range(steps):
        forces.append(coupling.step(k * dt, dt, [k * dt * rate], [rate]))
        nodes.append(coupling.nodes()[0])
    forces, nodes = np.array(forces)[:, 0], np.array(nodes)
    assert np.max(np.abs(nodes - ds.position.values)) < 1e-9 * np.max(np.abs(ds.position.values))
    net = build_network(case)
    system = LumpedSystem(net, case)
    for k in (0, 1, steps):
        x, v = np.zeros((net.n_nodes, 3)), np.zeros((net.n_nodes, 3))
        x[net.node_index], v[net.node_index] = ds.position.values[k], ds.velocity.values[k]
        F = system.loads(float(ds.time.values[k]), x, v, 0.0)[0][net.vessel_nodes]
        origin = k * dt * rate[:3]
        moment = np.cross(x[net.vessel_nodes] - origin, F).sum(axis=0)
        np.testing.assert_allclose(forces[k, :3], F.sum(axis=0), rtol=0, atol=1e-7 * np.max(np.abs(F)))
        np.testing.assert_allclose(forces[k, 3:], moment, rtol=0, atol=1e-7 * 40.0 * np.max(np.abs(F)))


@pytest.mark.slow
def test_a_coupled_oscillation_converges_on_the_prescribed_motion_run():
    """The fairlead moves surge -4 cos(2 pi t / 12) m, heave -cos(2 pi t / 9) m (from rest): the host
    gives each step's start and secant (MoorDyn's linear motion over the step, eq. (1) of
    kanat.coupling) where the run follows the curve, so they differ by the interpolation: the chord's
    sag (up to |r''| dt^2 / 8, 0.3 mm at dt = 0.1 s) and its velocity (up to |r''| dt / 2, 6 cm/s),
    which the chain's axial damping turns into force at once. Of the fairlead force's range, the
    largest difference is below 3 % at dt = 0.1 s and falls at least as dt (first order: the
    velocity), the mean one below 0.5 % and falls at least as dt^1.7 (measured at 0.1, 0.05 and
    0.025 s: largest 2.2, 0.92, 0.41 %; mean 0.37, 0.085, 0.028 %)."""
    def path(t):
        return np.array([[-4.0 * math.cos(2 * math.pi * t / 12.0), 0.0, -math.cos(2 * math.pi * t / 9.0)]])

    motion = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
              {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
    errors = []
    for dt in (0.1, 0.05):
        steps = int(round(6.0 / dt))
        case, ds = driven_run(motion, steps * dt, dt)
        forces = coupled(case, path, dt, steps)[0]
        reference = np.array([node_forces(case, ds, k) for k in range(steps + 1)])
        span = np.ptp(np.linalg.norm(reference, axis=1))
        difference = np.max(np.abs(forces - reference), axis=1) / span
        errors.append((difference.max(), difference.mean()))
    (largest, mean), (largest_half, mean_half) = errors
    assert largest < 0.03 and mean < 0.005
    assert largest_half < 0.5 * 1.1 * largest
    assert mean_half < 0.5 ** 1.7 * mean


def test_a_saved_state_continues_bit_for_bit():
    """state() after 10 steps, 10 more, then restore() in a new coupling and the same 10 again: the
    same forces and nodes, bit for bit."""
    def path(t):
        return FAIRLEADS + np.array([3.0 * math.sin(0.5 * t), 0.0, 0.5 * math.sin(0.7 * t)])

    dt = 0.1
    coupling = kanat.Coupling(THREE)
    coupling.initialize(path(0.0))
    for k in range(10):
        coupling.step(k * dt, dt, path(k * dt), (path((k + 1) * dt) - path(k * dt)) / dt)
    saved = coupling.state()
    first = [coupling.step(k * dt, dt, path(k * dt), (path((k + 1) * dt) - path(k * dt)) / dt)
             for k in range(10, 20)]
    other = kanat.Coupling(THREE)
    other.restore(saved)
    again = [other.step(k * dt, dt, path(k * dt), (path((k + 1) * dt) - path(k * dt)) / dt)
             for k in range(10, 20)]
    assert np.array_equal(np.array(first), np.array(again))
    assert np.array_equal(coupling.nodes()[0], other.nodes()[0])
    assert other.time == coupling.time


def test_the_coupling_agrees_with_moordyns_own_coupling(tmp_path):
    """The three-chain mooring, its fairleads surging 5 m in 20 s and heaving 1 m in 10 s (from rest),
    coupled every 0.05 s for 30 s to kanat (default scheme) and to MoorDyn-C (its Step, RK2 at the
    file's 1 ms), both given each step's start and secant: every force component within 2 % of the
    point's largest, the mean of |F| within 0.5 % and its range within 2 % (measured: 0.8 %, 0.05 %,
    0.7 %)."""
    moordyn = pytest.importorskip("moordyn")
    copy = tmp_path / THREE.name                    # MoorDyn writes its outputs beside its input
    shutil.copy(THREE, copy)
    dt, steps = 0.05, 600

    def path(t):
        return FAIRLEADS + np.array([-5.0 * math.cos(2 * math.pi * t / 20.0), 0.0,
                                     -math.cos(2 * math.pi * t / 10.0)])

    coupling = kanat.Coupling(THREE)
    coupling.initialize(path(0.0))
    rate = secant(path, dt)
    ours = np.array([coupling.step(k * dt, dt, path(k * dt), rate(k * dt)) for k in range(steps)])
    _, theirs = run_moordyn(moordyn, copy, steps * dt, dt, point=lambda t: path(t).ravel(), forces=True)
    theirs = theirs[:, 1:].reshape(-1, 3, 3)
    largest = np.max(np.abs(theirs), axis=(0, 2))
    assert np.all(np.max(np.abs(ours - theirs), axis=(0, 2)) < 0.02 * largest)
    mine, ref = np.linalg.norm(ours, axis=2), np.linalg.norm(theirs, axis=2)
    np.testing.assert_allclose(mine.mean(axis=0), ref.mean(axis=0), rtol=5e-3)
    np.testing.assert_allclose(np.ptp(mine, axis=0), np.ptp(ref, axis=0), rtol=2e-2)


def test_a_coupled_body_agrees_with_moordyns_own_coupling(tmp_path):
    """The three chains on a MoorDyn Coupled body at the origin, driven in surge (5 m in 20 s), heave
    (1 m in 10 s) and pitch (3 deg in 15 s), from rest, every 0.05 s for 30 s: kanat's resultant and
    moment about the body's origin (``rigid_vessel=True``) against MoorDyn-C's six components, each
    within 2 % of the largest force or moment, the ranges within 2 % (measured: Fx 0.7 %, Fz 0.2 %,
    My 1.7 %; ranges 0.3, 0.2, 0.6 %)."""
    moordyn = pytest.importorskip("moordyn")
    copy = tmp_path / BODY.name
    shutil.copy(BODY, copy)
    dt, steps, pitch = 0.05, 600, math.radians(3.0)

    def q(t):
        return np.array([-5.0 * math.cos(2 * math.pi * t / 20.0), 0.0, -math.cos(2 * math.pi * t / 10.0), 0.0,
                         -pitch * math.cos(2 * math.pi * t / 15.0), 0.0])

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        coupling = kanat.Coupling(BODY, rigid_vessel=True)
    assert coupling.points == ["body1"]
    coupling.initialize([q(0.0)])
    rate = secant(q, dt)
    ours = np.array([coupling.step(k * dt, dt, [q(k * dt)], [rate(k * dt)])[0] for k in range(steps)])
    _, theirs = run_moordyn(moordyn, copy, steps * dt, dt, point=q, forces=True)
    theirs = theirs[:, 1:]
    force, moment = np.max(np.abs(theirs[:, :3])), np.max(np.abs(theirs[:, 3:]))
    scale = np.array([force] * 3 + [moment] * 3)
    assert np.all(np.max(np.abs(ours - theirs), axis=0) < 0.02 * scale)
    for j in (0, 2, 4):                                                 # surge, heave, pitch
        assert np.ptp(ours[:, j]) == pytest.approx(np.ptp(theirs[:, j]), rel=0.02)
