"""Tests of the closed-form elastic catenary (kanat.statics.catenary).

Every check compares with something computed another way: quadrature of the
constitutive ODE, the textbook inextensible catenary, the parabola, the vertical
hang, finite differences of the profile, scipy's solve_bvp on the cable ODE, and
values published in MoorPy's test suite.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_bvp

from kanat.errors import SolverError
from kanat.statics.catenary import CatenarySolution, catenary_profile, elastic_catenary

# (span, rise, length, weight, axial_stiffness, seabed): one configuration per regime
CONFIGURATIONS = {
    "mooring_on_seabed": (900.0, 300.0, 1000.0, 1000.0, 5e8, True),
    "taut_stretched": (800.0, 600.0, 990.0, 1000.0, 5e8, False),        # chord 1000 m > length
    "taut_with_seabed_allowed": (980.0, 300.0, 1000.0, 1000.0, 5e8, True),
    "near_vertical_folded": (1e-3, 500.0, 600.0, 1000.0, 5e8, False),   # H -> 0, V_L < 0
    "near_vertical_taut": (1e-3, 500.0, 499.0, 1000.0, 5e8, False),
    "nearly_horizontal": (999.9, 1.0, 1000.0, 1000.0, 5e9, False),      # huge H
    "lowest_point_between_ends": (300.0, 50.0, 600.0, 1000.0, 5e8, False),
    "inextensible": (400.0, 100.0, 600.0, 10.0, np.inf, False),
    "inextensible_on_seabed": (600.0, 300.0, 800.0, 10.0, np.inf, True),
    "light_line": (400.0, 100.0, 600.0, 1e-9, 5e8, False),
}


def _relative_end_error(solution, span, rise, length):
    """End-position error of the sampled profile, relative to the target (floor 1e-6 L)."""
    return max(abs(solution.x[-1] - span) / max(span, 1e-6 * length),
               abs(solution.z[-1] - rise) / max(rise, 1e-6 * length))


def _end_by_quadrature(solution, length, weight, axial_stiffness):
    """Upper-end position by adaptive quadrature of dx/ds = (1 + T/EA) H/T, dz/ds = (1 + T/EA) V/T."""
    H, V_L, L_B = solution.horizontal_tension, solution.vertical_tension_lower, solution.grounded_length
    suspended = length - L_B

    def T(s):
        return math.hypot(H, V_L + weight * s)

    turning = -V_L / weight
    points = [turning] if 0.0 < turning < suspended else None
    options = dict(points=points, epsabs=1e-13 * length, epsrel=1e-13, limit=500)
    x = quad(lambda s: (1.0 + T(s) / axial_stiffness) * H / T(s), 0.0, suspended, **options)[0]
    z = quad(lambda s: (1.0 + T(s) / axial_stiffness) * (V_L + weight * s) / T(s), 0.0, suspended, **options)[0]
    return x + L_B * (1.0 + H / axial_stiffness), z


@pytest.mark.parametrize("name", CONFIGURATIONS)
def test_profile_reaches_the_upper_end(name):
    span, rise, length, weight, stiffness, seabed = CONFIGURATIONS[name]
    solution = elastic_catenary(span, rise, length, weight, stiffness, seabed=seabed)
    assert _relative_end_error(solution, span, rise, length) < 1e-10
    assert solution.x[0] == 0.0 and solution.z[0] == 0.0
    assert solution.s[0] == 0.0 and solution.s[-1] == length


@pytest.mark.parametrize("name", [n for n in CONFIGURATIONS if not n.startswith("near_vertical")])
def test_end_position_by_quadrature_of_the_ode(name):
    # Near-vertical lines are left out: their integrands are spikes of width H/w ~ 1e-5 m.
    span, rise, length, weight, stiffness, seabed = CONFIGURATIONS[name]
    solution = elastic_catenary(span, rise, length, weight, stiffness, seabed=seabed)
    x, z = _end_by_quadrature(solution, length, weight, stiffness)
    assert abs(x - span) <= 1e-10 * span
    assert abs(z - rise) <= 1e-10 * rise


@pytest.mark.parametrize("name", CONFIGURATIONS)
def test_force_balance(name):
    span, rise, length, weight, stiffness, seabed = CONFIGURATIONS[name]
    sol = elastic_catenary(span, rise, length, weight, stiffness, seabed=seabed)
    suspended = length - sol.grounded_length
    assert sol.suspended_length == pytest.approx(suspended, rel=1e-14)
    assert sol.vertical_tension_upper - sol.vertical_tension_lower == pytest.approx(weight * suspended, rel=1e-12)
    assert sol.tension_upper == pytest.approx(math.hypot(sol.horizontal_tension, sol.vertical_tension_upper), rel=1e-15)
    assert sol.tension_lower == pytest.approx(math.hypot(sol.horizontal_tension, sol.vertical_tension_lower), rel=1e-15)
    assert sol.tension[-1] == pytest.approx(sol.tension_upper, rel=1e-12)
    assert sol.tension[0] == pytest.approx(sol.tension_lower, rel=1e-12)
    if sol.grounded_length > 0.0:
        assert sol.vertical_tension_lower == 0.0
        assert np.allclose(sol.tension[sol.s < sol.grounded_length], sol.horizontal_tension, rtol=1e-15)


def test_regimes_are_the_expected_ones():
    solve = {name: elastic_catenary(*c[:5], seabed=c[5]) for name, c in CONFIGURATIONS.items()}
    assert solve["mooring_on_seabed"].grounded_length > 0.0
    assert solve["taut_stretched"].vertical_tension_lower > 0.0
    assert solve["taut_with_seabed_allowed"].grounded_length == 0.0
    assert solve["taut_with_seabed_allowed"].vertical_tension_lower > 0.0
    assert solve["near_vertical_folded"].vertical_tension_lower < 0.0
    assert solve["near_vertical_folded"].horizontal_tension < 1.0
    assert solve["near_vertical_taut"].vertical_tension_lower > 0.0
    assert solve["nearly_horizontal"].horizontal_tension > 5.0 * 1000.0 * 1000.0        # > 5 x line weight
    assert solve["lowest_point_between_ends"].vertical_tension_lower < 0.0
    assert solve["inextensible_on_seabed"].grounded_length > 0.0


# ------------------------------------------------------------------ analytic limits

def test_inextensible_symmetric_hang_matches_textbook_catenary():
    # y = a cosh(x/a) between x = -b and b: L = 2 a sinh(b/a), sag = a (cosh(b/a) - 1), T_end = w a cosh(b/a)
    a, b, w = 200.0, 150.0, 35.0
    length = 2.0 * a * math.sinh(b / a)
    sol = elastic_catenary(2.0 * b, 0.0, length, w, np.inf, n_points=201)
    assert sol.horizontal_tension == pytest.approx(w * a, rel=1e-9)
    assert -sol.z[100] == pytest.approx(a * (math.cosh(b / a) - 1.0), rel=1e-9)   # s = L/2, the low point
    assert sol.x[100] == pytest.approx(b, rel=1e-12)
    assert sol.tension_upper == pytest.approx(w * a * math.cosh(b / a), rel=1e-9)
    assert sol.vertical_tension_lower == pytest.approx(-sol.vertical_tension_upper, rel=1e-12)


def test_stiff_line_departs_from_inextensible_like_one_over_stiffness():
    a, b, w = 200.0, 150.0, 35.0
    length = 2.0 * a * math.sinh(b / a)
    rigid = elastic_catenary(2.0 * b, 0.0, length, w, np.inf, n_points=201)
    stiff = [elastic_catenary(2.0 * b, 0.0, length, w, ea, n_points=201) for ea in (1e8, 2e8)]
    dH = [rigid.horizontal_tension - s.horizontal_tension for s in stiff]
    dsag = [s.z[100] - rigid.z[100] for s in stiff]                    # the stretched line sags more
    assert dH[0] > 0.0 and dsag[0] < 0.0
    assert dH[0] / dH[1] == pytest.approx(2.0, rel=1e-3)
    assert dsag[0] / dsag[1] == pytest.approx(2.0, rel=1e-3)


@pytest.mark.parametrize("stiffness", [np.inf, 2e10])
def test_parabolic_limit_of_a_taut_shallow_line(stiffness):
    # sag = w S^2 / (8 H (1 + H/EA)) (curvature w/(H (1 + H/EA)) of the shallow elastic line);
    # the catenary exceeds it by (w S / H)^2 / 48 relative, to leading order.
    span, w = 1000.0, 100.0
    length = 1000.2
    sol = elastic_catenary(span, 0.0, length, w, stiffness, n_points=201)
    H = sol.horizontal_tension
    parabola = w * span**2 / (8.0 * H * (1.0 + H / stiffness))
    epsilon = w * span / H
    assert epsilon < 0.1
    relative = -sol.z[100] / parabola - 1.0
    assert relative == pytest.approx(epsilon**2 / 48.0, rel=1e-2)   # next term is O(epsilon^2) smaller


def test_vertical_hang():
    length, w, ea = 500.0, 800.0, 1e8
    stretch = w * length**2 / (2.0 * ea)
    sol = elastic_catenary(0.0, length + stretch, length, w, ea)
    assert sol.horizontal_tension == 0.0
    assert sol.vertical_tension_upper == pytest.approx(w * length, rel=1e-12)
    assert sol.vertical_tension_lower == pytest.approx(0.0, abs=1e-9 * w * length)
    assert np.all(sol.x == 0.0)
    assert sol.z[-1] - length == pytest.approx(stretch, rel=1e-9)
    s = sol.s                                    # z(s) = s + w s^2 / (2 EA) from the free foot
    assert np.allclose(sol.z, s + w * s**2 / (2.0 * ea), rtol=1e-12)


def test_vertical_fold_and_taut_vertical_line():
    length, w, ea = 500.0, 800.0, 1e8
    # folded: two vertical arms hanging from the ends; their lengths differ by rise / (1 + w L / (2 EA))
    rise = 200.0
    fold = elastic_catenary(0.0, rise, length, w, ea)
    arm_difference = rise / (1.0 + w * length / (2.0 * ea))
    assert fold.vertical_tension_upper == pytest.approx(w * 0.5 * (length + arm_difference), rel=1e-12)
    assert fold.vertical_tension_lower == pytest.approx(-w * 0.5 * (length - arm_difference), rel=1e-12)
    assert fold.z.min() < 0.0 and fold.z[-1] == pytest.approx(rise, rel=1e-12)
    # taut: rise = L + (V_U L - w L^2 / 2) / EA
    rise = 510.0
    taut = elastic_catenary(0.0, rise, length, w, ea)
    assert taut.vertical_tension_upper == pytest.approx((rise - length) * ea / length + w * length / 2, rel=1e-12)
    assert taut.z[-1] == pytest.approx(rise, rel=1e-12)


# ------------------------------------------------------------------ seabed

def _hanging_length(rise, w, ea):
    """Unstretched length hanging vertically over ``rise``: l + w l^2 / (2 EA) = rise."""
    return rise if math.isinf(ea) else (math.sqrt((ea / w) ** 2 + 2.0 * rise * ea / w) - ea / w)


@pytest.mark.parametrize("stiffness", [np.inf, 5e8])
def test_slack_limit_returns_the_vertical_hang_exactly(stiffness):
    length, rise, w = 1000.0, 300.0, 1000.0
    hanging = _hanging_length(rise, w, stiffness)
    sol = elastic_catenary(length - hanging, rise, length, w, stiffness, seabed=True)
    assert sol.horizontal_tension == 0.0
    assert sol.vertical_tension_upper == pytest.approx(w * hanging, rel=1e-12)
    assert sol.grounded_length == pytest.approx(length - hanging, rel=1e-12)
    assert _relative_end_error(sol, length - hanging, rise, length) < 1e-10
    # just past the limit, Newton finds a tiny H and the same tensions
    near = elastic_catenary((length - hanging) * (1.0 + 1e-9), rise, length, w, stiffness, seabed=True)
    assert 0.0 < near.horizontal_tension < 1.0
    assert near.vertical_tension_upper == pytest.approx(w * hanging, rel=1e-6)


def test_slacker_than_the_limit_bunches_on_the_seabed():
    length, rise, w = 1000.0, 300.0, 1000.0
    sol = elastic_catenary(500.0, rise, length, w, np.inf, seabed=True, n_points=5)
    assert sol.horizontal_tension == 0.0 and sol.vertical_tension_upper == pytest.approx(w * rise)
    assert sol.grounded_length == pytest.approx(length - rise)
    assert np.all(sol.x <= 500.0) and sol.x[-1] == 500.0
    assert np.all(sol.tension[sol.s <= sol.grounded_length] == 0.0)


def test_line_lying_stretched_on_the_seabed():
    sol = elastic_catenary(1001.0, 0.0, 1000.0, 100.0, 1e7, seabed=True)
    assert sol.horizontal_tension == pytest.approx(1e7 * 1e-3, rel=1e-9)
    assert sol.vertical_tension_upper == 0.0 and sol.grounded_length == 1000.0
    assert sol.x[-1] == pytest.approx(1001.0, rel=1e-14) and np.all(sol.z == 0.0)


def test_horizontal_tension_grows_smoothly_through_touchdown():
    # H rises monotonically with span and the grounded length vanishes continuously
    length, rise, w, ea = 1000.0, 300.0, 1000.0, 5e8
    spans = np.linspace(720.0, 1040.0, 161)
    sols = [elastic_catenary(x, rise, length, w, ea, seabed=True, n_points=2) for x in spans]
    H = np.array([s.horizontal_tension for s in sols])
    grounded = np.array([s.grounded_length for s in sols])
    assert np.all(np.diff(H) > 0.0)
    assert grounded[0] > 0.0 and grounded[-1] == 0.0
    assert np.all(np.diff(grounded) <= 0.0)
    lifted = np.flatnonzero(grounded == 0.0)[0]
    free = [elastic_catenary(x, rise, length, w, ea, seabed=False) for x in spans[lifted - 2:lifted + 2]]
    assert free[0].vertical_tension_lower < 0.0 <= free[-1].vertical_tension_lower   # would dip, then would not
    assert free[-1].horizontal_tension == pytest.approx(sols[lifted + 1].horizontal_tension, rel=1e-13)


# ------------------------------------------------------------------ profile

PROFILE_CASES = ["mooring_on_seabed", "taut_stretched", "lowest_point_between_ends", "inextensible",
                 "inextensible_on_seabed", "nearly_horizontal"]


@pytest.mark.parametrize("name", PROFILE_CASES)
def test_profile_obeys_the_cable_ode(name):
    span, rise, length, weight, stiffness, seabed = CONFIGURATIONS[name]
    sol = elastic_catenary(span, rise, length, weight, stiffness, seabed=seabed)
    H, V_L, L_B = sol.horizontal_tension, sol.vertical_tension_lower, sol.grounded_length
    s = np.linspace(0.01, 0.99, 57) * length
    s = s[np.abs(s - L_B) > 1e-3 * length]                 # central differences off the kink
    step = 1e-5 * length
    xp, zp, _ = catenary_profile(s + step, H, V_L, weight, stiffness, L_B)
    xm, zm, _ = catenary_profile(s - step, H, V_L, weight, stiffness, L_B)
    _, _, T = catenary_profile(s, H, V_L, weight, stiffness, L_B)
    V = np.where(s < L_B, 0.0, V_L + weight * (s - L_B))
    stretch = 1.0 + T / stiffness
    assert np.allclose((xp - xm) / (2 * step), stretch * H / T, rtol=1e-6, atol=0)
    assert np.allclose((zp - zm) / (2 * step), stretch * V / T, rtol=1e-6, atol=1e-6)
    assert np.allclose(T, np.hypot(H, V), rtol=1e-14)
    on_seabed = s < L_B
    assert np.all(zp[on_seabed] == 0.0)


@pytest.mark.parametrize("name", ["mooring_on_seabed", "inextensible_on_seabed"])
def test_profile_is_continuous_at_touchdown(name):
    span, rise, length, weight, stiffness, seabed = CONFIGURATIONS[name]
    sol = elastic_catenary(span, rise, length, weight, stiffness, seabed=seabed)
    H, L_B = sol.horizontal_tension, sol.grounded_length
    gap = 1e-9 * length
    x, z, T = catenary_profile([L_B - gap, L_B, L_B + gap], H, 0.0, weight, stiffness, L_B)
    assert x[0] == pytest.approx(L_B * (1.0 + H / stiffness) - gap * (1.0 + H / stiffness), rel=1e-14)
    assert abs(x[2] - x[0]) < 3 * gap and abs(z[2] - z[0]) < 1e-12 * length and z[0] == 0.0
    assert T[0] == H and T[2] == pytest.approx(H, rel=1e-12)


def test_profile_with_zero_horizontal_tension_hangs_vertically():
    x, z, T = catenary_profile([0.0, 2.5, 5.0, 7.5, 10.0], 0.0, -5.0, 1.0, np.inf)
    assert np.all(x == 0.0)
    assert np.allclose(z, [0.0, -2.5, -5.0, -2.5, 0.0], atol=1e-15)
    assert np.allclose(T, [5.0, 2.5, 0.0, 2.5, 5.0])


def test_profile_rejects_vertical_tension_at_a_grounded_end():
    with pytest.raises(ValueError, match="must be 0"):
        catenary_profile([0.0, 1.0], 1.0, 2.0, 1.0, np.inf, grounded_length=0.5)


# ------------------------------------------------------------------ independent solvers

def _bvp_suspended(span, rise, length, w, ea):
    """Fully suspended line by collocation: y = (x, z, V), parameter H."""
    def ode(s, y, p):
        T = np.hypot(p[0], y[2])
        return np.vstack([(1 + T / ea) * p[0] / T, (1 + T / ea) * y[2] / T, np.full_like(s, w)])

    def bc(ya, yb, p):
        return np.array([ya[0], ya[1], yb[0] - span, yb[1] - rise])

    s = np.linspace(0.0, length, 200)
    guess = np.vstack([span * s / length, rise * s / length, w * (s - length / 2)])
    res = solve_bvp(ode, bc, s, guess, p=[w * length], tol=1e-9, max_nodes=100000)
    assert res.success, res.message
    return res.p[0], res.sol(0.0)[2], res.sol(length)[2]


def _bvp_on_seabed(span, rise, length, w, ea):
    """Line partly on a frictionless seabed: sigma in [0, 1] over the suspended part, parameters (H, L_B)."""
    def ode(sigma, y, p):
        H, L_B = p
        T = np.hypot(H, y[2])
        k = length - L_B
        return np.vstack([k * (1 + T / ea) * H / T, k * (1 + T / ea) * y[2] / T, np.full_like(sigma, k * w)])

    def bc(ya, yb, p):
        H, L_B = p
        return np.array([ya[0] - L_B * (1 + H / ea), ya[1], ya[2], yb[0] - span, yb[1] - rise])

    sigma = np.linspace(0.0, 1.0, 200)
    L_B = 0.3 * length
    guess = np.vstack([L_B + (span - L_B) * sigma, rise * sigma**2, w * (length - L_B) * sigma])
    res = solve_bvp(ode, bc, sigma, guess, p=[0.2 * w * length, L_B], tol=1e-9, max_nodes=100000)
    assert res.success, res.message
    return res.p[0], res.p[1], res.sol(1.0)[2]


@pytest.mark.parametrize("name", ["lowest_point_between_ends", "taut_stretched", "inextensible"])
def test_matches_solve_bvp_on_the_cable_ode(name):
    span, rise, length, weight, stiffness, _ = CONFIGURATIONS[name]
    H, V_L, V_U = _bvp_suspended(span, rise, length, weight, stiffness)
    sol = elastic_catenary(span, rise, length, weight, stiffness)
    assert sol.horizontal_tension == pytest.approx(H, rel=1e-8)
    assert sol.vertical_tension_lower == pytest.approx(V_L, rel=1e-8)
    assert sol.vertical_tension_upper == pytest.approx(V_U, rel=1e-8)


def test_matches_solve_bvp_with_seabed_contact():
    span, rise, length, weight, stiffness, _ = CONFIGURATIONS["mooring_on_seabed"]
    H, L_B, V_U = _bvp_on_seabed(span, rise, length, weight, stiffness)
    sol = elastic_catenary(span, rise, length, weight, stiffness, seabed=True)
    assert sol.horizontal_tension == pytest.approx(H, rel=1e-8)
    assert sol.grounded_length == pytest.approx(L_B, rel=1e-8)
    assert sol.vertical_tension_upper == pytest.approx(V_U, rel=1e-8)


# MoorPy's tests/statics/test_catenary.py (NREL/MoorPy, cases 2, 4 and 5; catenary(XF, ZF, L, EA, W, CB)),
# solved there to an absolute end tolerance of 1e-6 m, hence the 1e-6 relative comparison.
# columns: span, rise, length, weight, axial_stiffness, seabed, H, V_lower, V_upper, grounded_length
MOORPY_CASES = [
    (400.0, 200.0, 500.0, 800.0, 7.51e12, True, 96643.42815934008, 0.0, 237751.75535996316, 202.81030580004602),
    (400.0, 200.0, 500.0, 200.0, 7.51e12, False, 43694.580989249596, -22365.599350216216, 77634.40064978378, 0.0),
    (89.9, 59.2, 130.0, 881.05, 7.51e8, False, 31373.229006023103, -26650.341270116318, 87886.15872988368, 0.0),
]


@pytest.mark.parametrize("case", MOORPY_CASES, ids=["seabed", "suspended", "suspended_elastic"])
def test_matches_moorpy_published_values(case):
    *inputs, seabed, H, V_L, V_U, L_B = case
    sol = elastic_catenary(*inputs, seabed=seabed)
    assert sol.horizontal_tension == pytest.approx(H, rel=1e-6)
    assert sol.vertical_tension_upper == pytest.approx(V_U, rel=1e-6)
    assert sol.vertical_tension_lower == pytest.approx(V_L, rel=1e-6, abs=1e-9)
    assert sol.grounded_length == pytest.approx(L_B, rel=1e-6)


# ------------------------------------------------------------------ robustness and errors

GRID = [0.0, 1e-7, 0.01, 0.3, 0.7, 0.95, 0.999, 1.0, 1.05]


@pytest.mark.parametrize("seabed", [False, True])
@pytest.mark.parametrize("stretch", [0.0, 1e-8, 1e-3, 0.3])
def test_solves_a_grid_of_configurations(stretch, seabed):
    # dimensionless span X and rise Z (in line lengths) and stretch w L / EA; every
    # configuration that has an equilibrium is solved, the others raise SolverError
    length, w = 250.0, 40.0
    stiffness = np.inf if stretch == 0.0 else w * length / stretch
    for X in GRID:
        for Z in GRID:
            if stretch == 0.0 and math.hypot(X, Z) >= 1.0 and not (seabed and X + Z <= 1.0):
                if not (X == 0.0 and Z == 1.0):
                    with pytest.raises(SolverError):
                        elastic_catenary(X * length, Z * length, length, w, stiffness, seabed=seabed)
                    continue
            sol = elastic_catenary(X * length, Z * length, length, w, stiffness, seabed=seabed, n_points=11)
            assert _relative_end_error(sol, X * length, Z * length, length) < 1e-9, (X, Z)
            assert sol.horizontal_tension >= 0.0 and sol.grounded_length >= 0.0
            assert sol.vertical_tension_upper - sol.vertical_tension_lower == pytest.approx(
                w * (length - sol.grounded_length), rel=1e-12)


def test_inextensible_line_shorter_than_chord_has_no_solution():
    with pytest.raises(SolverError, match=r"longer than the chord.*chord=500 m, length=499 m"):
        elastic_catenary(400.0, 300.0, 499.0, 10.0, np.inf)


def test_inextensible_line_on_seabed_longer_span_has_no_solution():
    with pytest.raises(SolverError, match="cannot span more than its length"):
        elastic_catenary(101.0, 0.0, 100.0, 10.0, np.inf, seabed=True)


@pytest.mark.parametrize("bad", [dict(span=-1.0), dict(rise=-1.0), dict(length=0.0), dict(weight=0.0),
                                 dict(axial_stiffness=0.0), dict(span=np.nan), dict(n_points=1)])
def test_rejects_invalid_input(bad):
    args = dict(span=100.0, rise=10.0, length=150.0, weight=10.0, axial_stiffness=1e8, n_points=11) | bad
    with pytest.raises(ValueError):
        elastic_catenary(**args)


def test_solution_is_frozen_and_shaped():
    sol = elastic_catenary(900.0, 300.0, 1000.0, 1000.0, 5e8, seabed=True, n_points=33)
    assert isinstance(sol, CatenarySolution)
    assert sol.s.shape == sol.x.shape == sol.z.shape == sol.tension.shape == (33,)
    with pytest.raises(AttributeError):
        sol.horizontal_tension = 1.0


@pytest.mark.parametrize("h, v, seabed", [(0.3, 0.7, True), (0.3, 0.7, False), (2.0, 1.4, False),
                                          (1e-3, 0.2, False), (50.0, 0.5, False), (0.05, 0.9, True)])
def test_newton_jacobian_matches_finite_differences(h, v, seabed):
    from kanat.statics.catenary import _end_position

    stretch, step = 0.01, 1e-5
    _, _, jac = _end_position(h, v, stretch, seabed)
    dh = [(a - b) / (2 * step * h) for a, b in zip(_end_position(h * (1 + step), v, stretch, seabed)[:2],
                                                   _end_position(h * (1 - step), v, stretch, seabed)[:2])]
    dv = [(a - b) / (2 * step) for a, b in zip(_end_position(h, v + step, stretch, seabed)[:2],
                                               _end_position(h, v - step, stretch, seabed)[:2])]
    assert np.allclose(jac, [dh[0], dv[0], dh[1], dv[1]], rtol=1e-6, atol=1e-8)
