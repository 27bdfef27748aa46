"""Steady cable solvers against independent oracles (theory/statics.md §1, theory/validation-cases.md cases 4 and 5).

Oracles: the closed-form elastic catenary (Irvine), the long-cable critical angle,
global force balance, and agreement of two independent solvers.
"""
import numpy as np
import pytest

from kanat.errors import SolverError
from kanat.physics.drag import cable_drag
from kanat.statics import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties, solve_cable
from kanat.statics.collocation import solve_collocation
from kanat.statics.guess import solve_catenary
from kanat.statics.shooting import solve_shooting

SOLVERS = [solve_shooting, solve_collocation]


def line(weight, stiffness, **kw):
    return LineProperties(weight=weight, axial_stiffness=stiffness, diameter=kw.pop("diameter", 0.1), **kw)


CATENARY_CASES = {
    # slack with seabed contact, both orientations of s
    "slack-seabed": CableBVP(line(1000.0, 5e8), 1000.0, FixedEnd((0.0, -300.0)), FixedEnd((900.0, 0.0)),
                             seabed_z=-300.0),
    "slack-seabed-reversed": CableBVP(line(1000.0, 5e8), 1000.0, FixedEnd((900.0, 0.0)),
                                      FixedEnd((0.0, -300.0)), seabed_z=-300.0),
    # taut: line nearly as short as the chord, stretched, anchor lifted off
    "taut": CableBVP(line(100.0, 1e7), 500.0, FixedEnd((0.0, -400.0)), FixedEnd((300.0, 0.0))),
    "near-vertical": CableBVP(line(500.0, 1e8), 200.0, FixedEnd((0.0, -199.9)), FixedEnd((1.0, 0.0))),
    "nearly-horizontal": CableBVP(line(10.0, 1e7), 100.0, FixedEnd((0.0, 0.0)), FixedEnd((99.99, 0.2))),
    "sag-between-ends": CableBVP(line(50.0, 1e7), 120.0, FixedEnd((0.0, 0.0)), FixedEnd((100.0, 10.0))),
    "buoyant-line": CableBVP(line(-20.0, 1e7), 120.0, FixedEnd((0.0, -100.0)), FixedEnd((80.0, -30.0))),
}


@pytest.mark.parametrize("solver", SOLVERS, ids=lambda f: f.__name__)
@pytest.mark.parametrize("name", CATENARY_CASES)
def test_numerical_solvers_match_closed_form_catenary(name, solver):
    problem = CATENARY_CASES[name]
    s = np.linspace(0.0, problem.length, 41)
    exact = solve_catenary(problem, s)
    numerical = solver(problem, s)
    scale = exact.tension.max()
    assert np.max(np.abs(numerical.tension - exact.tension)) / scale < 1e-6
    assert np.max(np.abs(numerical.force - exact.force)) / scale < 1e-6
    assert np.max(np.hypot(numerical.x - exact.x, numerical.z - exact.z)) / problem.length < 1e-6
    assert numerical.grounded_length == pytest.approx(exact.grounded_length, abs=1e-6 * problem.length)


def test_seabed_cases_really_touch_the_seabed():
    assert solve_catenary(CATENARY_CASES["slack-seabed"]).grounded_length > 300.0
    assert solve_catenary(CATENARY_CASES["taut"]).force[0, 1] > 0.0        # anchor pulled upward


def critical_angle(weight, density, diameter, drag_normal, speed):
    r = 0.5 * density * diameter * drag_normal * speed**2
    return np.degrees(np.arccos((-weight + np.sqrt(weight**2 + 4 * r**2)) / (2 * r)))


@pytest.mark.parametrize("solver", SOLVERS, ids=lambda f: f.__name__)
@pytest.mark.parametrize("speed, drag_tangential", [(1.5, 0.0), (3.0, 0.01), (5.0, 0.02)])
def test_long_towed_cable_reaches_critical_angle(solver, speed, drag_tangential):
    lt = LineProperties(weight=8.89, axial_stiffness=1.2717e8, diameter=0.0173, drag_normal=1.5,
                        drag_tangential=drag_tangential, water_density=1025.0)
    problem = CableBVP(lt, 3000.0, FixedEnd((0.0, 0.0)), BodyEnd(net_buoyancy=-2000.0, drag_area=0.2),
                       FlowProfile.uniform(-speed, 0.0))
    sol = solver(problem, np.linspace(0.0, 3000.0, 61))
    below_horizontal = np.degrees(np.arctan2(-sol.force[0, 1], -sol.force[0, 0]))  # trails astern, downward
    assert below_horizontal == pytest.approx(critical_angle(8.89, 1025.0, 0.0173, 1.5, speed), abs=0.1)


def towed_problem(flow):
    lt = LineProperties(weight=8.89, axial_stiffness=1.2717e7, diameter=0.0173, drag_normal=1.5,
                        drag_tangential=0.01, water_density=1025.0)
    return CableBVP(lt, 1000.0, FixedEnd((0.0, 0.0)), BodyEnd(-6686.0, 0.3276, (0.0, 0.0)), flow)


FLOWS = {
    "uniform-6kn": FlowProfile.uniform(-3.0867, 0.0),
    "sheared": FlowProfile(np.array([-800.0, -100.0, 0.0]),
                           np.array([[-3.0867, 0.0], [-2.7, 0.0], [-2.2, 0.0]])),
    "depressor": FlowProfile.uniform(-5.0, 0.0),
}


@pytest.mark.parametrize("name", FLOWS)
def test_shooting_and_collocation_agree_on_towed_body(name):
    problem = towed_problem(FLOWS[name])
    s = np.linspace(0.0, problem.length, 101)
    a, b = solve_shooting(problem, s), solve_collocation(problem, s)
    assert np.max(np.abs(a.tension - b.tension)) / a.tension.max() < 1e-6
    assert np.max(np.hypot(a.x - b.x, a.z - b.z)) / problem.length < 1e-6


def test_towed_body_global_force_balance():
    """Top tension = body load + integrated weight and drag (independent quadrature)."""
    problem = towed_problem(FLOWS["sheared"])
    s = np.linspace(0.0, problem.length, 4001)
    sol = solve_shooting(problem, s)
    tangent = sol.force / sol.tension[:, None]
    strain = sol.tension / problem.line.axial_stiffness
    drag = cable_drag(tangent, problem.flow.at(sol.z), strain, 0.0173, 1.5, 0.01, 1025.0)
    load = drag + np.array([0.0, -problem.line.weight])
    body = problem.end.load(problem.flow, sol.z[-1], 1025.0)
    top = body + np.trapezoid(load, s, axis=0)                 # F(0) = F(L) + int f ds
    assert np.allclose(sol.force[0], top, rtol=1e-6, atol=1e-6 * sol.tension[0])
    assert np.allclose(sol.force[-1], body, rtol=1e-9)


def test_depressor_force_pulls_body_deeper():
    base = towed_problem(FLOWS["uniform-6kn"])
    pressed = CableBVP(base.line, base.length, base.start, BodyEnd(-6686.0, 0.3276, (0.0, -4000.0)), base.flow)
    assert solve_shooting(pressed).z[-1] < solve_shooting(base).z[-1] - 20.0


def mooring_in_current(speed):
    lt = LineProperties(weight=981.0, axial_stiffness=5.1e8, diameter=0.137, drag_normal=2.4,
                        drag_tangential=0.4, water_density=1025.0)
    flow = FlowProfile(np.array([-150.0, 0.0]), np.array([[0.2 * speed, 0.0], [speed, 0.0]]))
    return CableBVP(lt, 700.0, FixedEnd((-600.0, -150.0)), FixedEnd((0.0, -5.0)), flow, seabed_z=-150.0)


@pytest.mark.parametrize("speed", [0.0, 1.0, -1.5, 3.0])
def test_mooring_with_seabed_in_current_solvers_agree(speed):
    problem = mooring_in_current(speed)
    s = np.linspace(0.0, problem.length, 71)
    a, b = solve_shooting(problem, s), solve_collocation(problem, s)
    assert a.grounded_length > 0.0
    assert a.grounded_length == pytest.approx(b.grounded_length, abs=1e-6 * problem.length)
    assert np.max(np.abs(a.tension - b.tension)) / a.tension.max() < 1e-6
    assert np.max(np.hypot(a.x - b.x, a.z - b.z)) / problem.length < 1e-6
    assert np.min(a.z) >= -150.0 - 1e-9


def test_current_toward_fairlead_shortens_grounded_length():
    still, pushed = (solve_shooting(mooring_in_current(u)) for u in (0.0, 3.0))
    assert pushed.grounded_length != pytest.approx(still.grounded_length, rel=1e-3)


def test_auto_takes_catenary_fast_path_and_falls_back():
    assert solve_cable(CATENARY_CASES["taut"]).method == "catenary"
    assert solve_cable(towed_problem(FLOWS["uniform-6kn"])).method == "shooting"
    with pytest.raises(SolverError, match="valid: auto, shooting, collocation, catenary"):
        solve_cable(CATENARY_CASES["taut"], "newton")


@pytest.mark.parametrize("solver", SOLVERS, ids=lambda f: f.__name__)
def test_cable_between_two_bodies_is_refused(solver):
    problem = CableBVP(line(10.0, 1e7), 100.0, BodyEnd(100.0), BodyEnd(-100.0))
    with pytest.raises(SolverError, match="nothing holds it in place"):
        solver(problem)


def test_too_short_line_is_refused_with_numbers():
    problem = CableBVP(line(10.0, np.inf), 100.0, FixedEnd((0.0, 0.0)), FixedEnd((150.0, 0.0)))
    with pytest.raises(SolverError, match="farther apart"):
        solve_catenary(problem)


def test_slack_body_is_refused():
    problem = CableBVP(line(10.0, 1e7), 100.0, FixedEnd((0.0, 0.0)), BodyEnd(0.0, 0.0))
    with pytest.raises(SolverError, match="slack"):
        solve_shooting(problem)
