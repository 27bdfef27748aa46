"""Naumov & Agievich: sphere on two cables in a uniform flow (theory/statics.md §3, validation case 1).

Oracles: the paper's published numbers (Naumov & Agievich, eq. 21 and the text after
fig. 3: tau(0) = 0.6066, alpha(0) = 46.9 deg, eps1 = -0.00798 %, eps2 = 0.00403 %), its
qualitative second case, hand-computed dimensional groups, and force balances.
"""
import numpy as np
import pytest

from kanat.errors import CaseError, SolverError
from kanat.report.sphere_plot import plot_sphere
from kanat.statics import sphere_solvers as sp
from kanat.statics.sphere import PAPER_CASE_1, PAPER_CASE_2, PAPER_CRITERION_PERCENT, SphereGroups, cable_drag, groups_from_dimensional
from kanat.statics.sphere_solvers import shoot_sphere, solve_sphere, sweep_flow_speed

METHODS = ["shooting", "collocation"]
CONVENTIONS = ["published", "physical"]
CASES = {"case1": PAPER_CASE_1, "case2": PAPER_CASE_2}

# A dimensional system whose groups at V = 1 m/s are the paper's case 1:
# k1 = 0.5 * 1.2 * 0.02 * 1025 * 1^2 = 12.3 N/m, k1 L = 615 N.
DIMS = {"sphere_diameter": np.sqrt(0.4 * 0.02 * 50 / 0.288), "net_buoyancy": 0.45 * 615.0,
        "cable_diameter": 0.02, "cable_length": 50.0, "cable_weight": 0.02 * 12.3,
        "line_length": 100.0, "anchor_x": -86.6}


def _solve(case, convention, method, n_nodes=101):
    return solve_sphere(CASES[case], convention=convention, method=method, n_nodes=n_nodes)


def _bulge(sol):
    """Largest distance of the cable from the chord AB (B at the origin)."""
    return np.max(np.abs(sol.x * sol.y_A - sol.y * sol.x_A)) / np.hypot(sol.x_A, sol.y_A)


@pytest.mark.parametrize("method", METHODS)
def test_published_case_reproduces_paper(method):
    sol = _solve("case1", "published", method)
    assert np.degrees(sol.alpha0) == pytest.approx(46.9, abs=0.1)
    assert sol.tau0 == pytest.approx(0.6066, abs=5e-4)
    assert abs(sol.eps1_percent) < PAPER_CRITERION_PERCENT
    assert abs(sol.eps2_percent) < PAPER_CRITERION_PERCENT
    assert max(abs(sol.eps1_percent), abs(sol.eps2_percent)) < sp.RESIDUAL_TOL_PERCENT
    assert (sol.convention, sol.method) == ("published", method)
    assert sol.x[-1] == pytest.approx(0.0, abs=1e-9) and sol.y[-1] == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("convention", CONVENTIONS)
@pytest.mark.parametrize("case", CASES)
def test_shooting_and_collocation_agree(case, convention):
    a = _solve(case, convention, "shooting")
    b = _solve(case, convention, "collocation")
    assert abs(a.alpha0 - b.alpha0) < 1e-6
    assert abs(a.tau0 - b.tau0) < 1e-6
    for name in ("alpha", "tau", "x", "y"):
        assert np.max(np.abs(getattr(a, name) - getattr(b, name))) < 1e-6, name


def test_paper_values_give_paper_residuals():
    sol = shoot_sphere(PAPER_CASE_1, np.radians(46.9), 0.6066)
    assert sol.method == "single shot"
    assert sol.eps1_percent == pytest.approx(-0.00798, abs=0.002)
    assert sol.eps2_percent == pytest.approx(0.00403, abs=0.002)


def test_eps2_grows_with_alpha0_and_tau0_as_in_paper_fig2():
    base = shoot_sphere(PAPER_CASE_1, np.radians(46.9), 0.63)
    more_alpha = shoot_sphere(PAPER_CASE_1, np.radians(51.9), 0.63)
    more_tau = shoot_sphere(PAPER_CASE_1, np.radians(46.9), 0.64)
    assert more_alpha.eps1_percent < base.eps1_percent
    assert more_alpha.eps2_percent > base.eps2_percent
    assert more_tau.eps2_percent > base.eps2_percent


@pytest.mark.parametrize("method", METHODS)
def test_second_case_trends_as_in_paper(method):
    one, two = _solve("case1", "published", method), _solve("case2", "published", method)
    assert two.y_A < one.y_A                     # the sphere settles deeper
    assert _bulge(two) > _bulge(one)             # the cable bulges more
    assert two.alpha[0] < one.alpha[0]           # the top angle falls
    assert two.alpha[-1] > one.alpha[-1]         # the bottom angle rises


@pytest.mark.parametrize("method", METHODS)
def test_physical_convention(method):
    phys = _solve("case1", "physical", method)
    pub = _solve("case1", "published", method)
    assert phys.convention == "physical"
    assert max(abs(phys.eps1_percent), abs(phys.eps2_percent)) < sp.RESIDUAL_TOL_PERCENT
    assert np.hypot(phys.x_A - pub.x_A, phys.y_A - pub.y_A) > 0.1   # the sphere sits elsewhere
    assert phys.forces.drag[0] > 0 > pub.forces.drag[0]
    assert phys.tau_line > 0


@pytest.mark.parametrize("convention", CONVENTIONS)
@pytest.mark.parametrize("case", CASES)
def test_force_balance_at_sphere(case, convention):
    sol = _solve(case, convention, "shooting")
    f = sol.forces
    assert np.max(np.abs(f.total)) < 1e-8
    assert np.linalg.norm(f.line) == pytest.approx(abs(sol.tau_line), rel=1e-12)
    # the line pulls along A -> C
    to_c = np.array([sol.groups.x_C - sol.x_A, -sol.y_A])
    assert np.dot(f.line, to_c) == pytest.approx(sol.tau_line * np.hypot(*to_c), rel=1e-12)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("convention", CONVENTIONS)
@pytest.mark.parametrize("case", CASES)
def test_global_equilibrium_of_cable(case, convention, method):
    sol = _solve(case, convention, method, n_nodes=20001)
    g, a = sol.groups, sol.alpha
    t = np.stack([np.cos(a), -np.sin(a)])
    n = np.stack([np.sin(a), np.cos(a)])
    r_n, r_t = cable_drag(a, g.chi)
    load = r_n * n + r_t * t + np.array([[0.0], [-g.Psi]])
    total = sol.tau[-1] * t[:, -1] - sol.tau[0] * t[:, 0] + np.trapezoid(load, sol.sigma, axis=1)
    assert np.max(np.abs(total)) < 1e-6


def test_cable_drag_limits():
    chi = 0.0333
    assert cable_drag(np.pi / 2, chi) == pytest.approx((1.0, 0.0), abs=1e-15)
    assert cable_drag(0.0, chi) == pytest.approx((0.0, chi), abs=1e-15)


def test_groups_from_dimensional_hand_computed():
    groups, scales = groups_from_dimensional(
        flow_speed=1.0, sphere_diameter=1.0, net_buoyancy=276.75, cable_diameter=0.02,
        cable_length=50.0, cable_weight=0.246, line_length=100.0, anchor_x=-86.6)
    assert scales.k1 == pytest.approx(12.3, rel=1e-12)          # 0.5 * 1.2 * 0.02 * 1025
    assert scales.L == 50.0 and scales.force == pytest.approx(615.0, rel=1e-12)
    assert groups.Psi == pytest.approx(0.02, rel=1e-12)
    assert groups.QkL == pytest.approx(0.45, rel=1e-12)
    assert groups.LoL == 2.0 and groups.x_C == pytest.approx(-1.732, rel=1e-12)
    r0 = 0.5 * 0.44 * np.pi / 4 * 1025.0                         # 177.107 N
    assert groups.RkL == pytest.approx(r0 / 615.0, rel=1e-12)
    assert groups.chi == pytest.approx(0.04 / 1.2, rel=1e-12)


@pytest.mark.parametrize("diameter, delta, length", [(1.0, 0.02, 50.0), (0.5, 0.01, 200.0),
                                                      (2.0, 0.05, 30.0)])
def test_sphere_drag_group_is_0288_d2_over_delta_l(diameter, delta, length):
    groups, _ = groups_from_dimensional(2.0, diameter, 100.0, delta, length, 1.0,
                                        2 * length, -1.7 * length)
    assert groups.RkL == pytest.approx(0.288 * diameter**2 / (delta * length), rel=1e-4)


def test_dimensional_outputs_consistent():
    groups, scales = groups_from_dimensional(1.0, **DIMS)
    sol = solve_sphere(groups, scales=scales)
    assert sol.T[0] == pytest.approx(sol.tau0 * scales.k1 * scales.L, rel=1e-12)
    assert sol.T_line == pytest.approx(sol.tau_line * 615.0, rel=1e-12)
    assert sol.s[-1] == pytest.approx(50.0) and sol.X[0] == pytest.approx(50.0 * sol.x_A)
    assert sol.Y[0] == pytest.approx(50.0 * sol.y_A)
    assert np.degrees(sol.alpha0) == pytest.approx(46.9, abs=0.1)  # the paper's case 1
    with pytest.raises(ValueError, match="groups_from_dimensional"):
        _ = solve_sphere(PAPER_CASE_1).T


@pytest.mark.parametrize("method", METHODS)
def test_sweep_flow_speed(method):
    speeds = [0.5, 1.0, 1.414, 2.0]
    sols = sweep_flow_speed(speeds, **DIMS, method=method)
    assert len(sols) == len(speeds)
    assert all("initial guess" in s.info for s in sols[1:])
    heights = [s.y_A for s in sols]
    assert np.all(np.diff(heights) < 0)                         # faster flow, deeper sphere
    ref = solve_sphere(sols[1].groups, method=method)
    assert sols[1].alpha0 == pytest.approx(ref.alpha0, abs=1e-9)
    assert sols[2].groups.Psi == pytest.approx(0.01, rel=1e-3)   # V^2 doubled: case 2


def test_continuation_reaches_target():
    sol = sp._continuation(PAPER_CASE_2, "published", sp.METHODS["shooting"], 101)
    ref = solve_sphere(PAPER_CASE_2)
    assert "continuation" in sol.info
    assert sol.alpha0 == pytest.approx(ref.alpha0, abs=1e-9)


def test_hard_case_needs_continuation():
    groups = SphereGroups(Psi=0.5, LoL=1.5, x_C=-0.8, QkL=0.1, RkL=0.1)
    sol = solve_sphere(groups, convention="physical")
    assert "continuation" in sol.info
    assert max(abs(sol.eps1_percent), abs(sol.eps2_percent)) < sp.RESIDUAL_TOL_PERCENT


def test_initial_guess_is_used():
    ref = solve_sphere(PAPER_CASE_2)
    sol = solve_sphere(PAPER_CASE_2, initial_guess=(ref.alpha0, ref.tau0))
    assert sol.info.startswith("from the given initial guess")


def test_slack_cable_is_guarded():
    heavy = SphereGroups(Psi=2.0, LoL=2.0, x_C=-1.732, QkL=0.45, RkL=0.4)
    with pytest.raises(SolverError, match="slack"):
        shoot_sphere(heavy, np.radians(60.0), 1e-5)     # tau' = -Psi sin(a) - r_t < 0
    with pytest.raises(SolverError, match="not positive"):
        shoot_sphere(PAPER_CASE_1, np.radians(46.9), -0.1)


@pytest.mark.slow
def test_no_equilibrium_raises_with_advice():
    heavy = SphereGroups(Psi=0.5, LoL=2.0, x_C=-1.7, QkL=0.1, RkL=0.1)   # cable too heavy
    with pytest.raises(SolverError, match="initial_guess") as info:
        solve_sphere(heavy)
    assert "Tried" in str(info.value) and "continuation" in str(info.value)


def test_bad_input_is_rejected():
    with pytest.raises(ValueError, match="physical"):
        solve_sphere(PAPER_CASE_1, convention="paper")
    with pytest.raises(ValueError, match="collocation"):
        solve_sphere(PAPER_CASE_1, method="newton")
    with pytest.raises(CaseError, match="x_C"):
        SphereGroups(Psi=0.02, LoL=2.0, x_C=-3.5, QkL=0.45, RkL=0.4)
    with pytest.raises(CaseError, match="flow_speed"):
        groups_from_dimensional(0.0, **DIMS)


def test_physical_warnings():
    assert solve_sphere(PAPER_CASE_1, convention="physical").physical_warnings == ()
    warnings = solve_sphere(PAPER_CASE_2).physical_warnings   # published case 2: AC pushes
    assert any("compression" in w for w in warnings)


def test_plot_writes_png(tmp_path):
    sols = [_solve("case1", "published", "shooting"), _solve("case2", "published", "shooting")]
    path = tmp_path / "sphere.png"
    fig = plot_sphere(sols, path=path, labels=["case 1", "case 2"])
    assert len(fig.axes) == 2
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000
    with pytest.raises(ValueError, match="labels"):
        plot_sphere(sols, labels=["only one"])
