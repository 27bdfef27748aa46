"""The symbolic 3-D cable equations (theory/continuum.md §2): frame, planar reduction to §2.1, invariance
under rotations and pole changes, characteristic speeds and the singular set of ``M``."""
import numpy as np
import pytest
import sympy as sp

from kanat.continuum import oracle_sympy3d as d3
from kanat.physics.drag import cable_drag

CONSTANTS = d3.CableConstants(mass=1.12, added_mass=0.24, axial_stiffness=2.0e5, weight_in_water=8.89,
                              water_density=1025.0, diameter=0.0173, drag_normal=1.5, drag_tangential=0.01)
NO_DRAG = d3.CableConstants(**{**CONSTANTS.__dict__, "drag_normal": 0.0, "drag_tangential": 0.0})
VERTICAL = ((0.0, 0.0, 1.0), (1.0, 0.0, 0.0))           # (pole, e1): e2 = y, planar motion is theta = w = 0
HORIZONTAL = ((0.0, -1.0, 0.0), (1.0, 0.0, 0.0))        # e2 = z, planar motion is phi = v = 0


def random_triad(rng):
    """(pole, e1) of a random right-handed orthonormal triad."""
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 1] *= -1.0
    return q[:, 2], q[:, 0]


def random_states(rng, n, phi_limit=1.2):
    """Taut states (n, 6) with |phi| < phi_limit (away from the pole)."""
    return np.column_stack([rng.uniform(1e3, 2e4, n), rng.normal(2.0, 1.0, n), rng.normal(0.0, 0.5, n),
                            rng.normal(0.0, 0.5, n), rng.uniform(-phi_limit, phi_limit, n),
                            rng.uniform(-np.pi, np.pi, n)])


def spec_planar(Y2, c, current_xz):
    """theory/continuum.md §1's printed ``M, K, F`` for planar states (n, 4) = (T, u, v, phi)."""
    T, u, v, phi = Y2.T
    m, mn, EA = c.mass, c.mass + c.added_mass, c.axial_stiffness
    z, one = np.zeros_like(T), np.ones_like(T)
    M = np.array([[z, m * one, z, -m * v], [z, z, mn * one, mn * u], [one / EA, z, z, z], [z, z, z, 1 + T / EA]])
    K = np.array([[-one, z, z, z], [z, z, z, -T], [z, -one, z, v], [z, z, -one, -u]])
    Ux, Uz = current_xz.T
    ur = u - (Ux * np.cos(phi) + Uz * np.sin(phi))
    vr = v - (-Ux * np.sin(phi) + Uz * np.cos(phi))
    root = np.sqrt(1 + T / EA)
    ft = -c.weight_in_water * np.sin(phi) - 0.5 * c.water_density * np.pi * c.diameter * c.drag_tangential \
        * np.abs(ur) * ur * root
    fn = -c.weight_in_water * np.cos(phi) - 0.5 * c.water_density * c.diameter * c.drag_normal * np.abs(vr) * vr * root
    return np.moveaxis(M, -1, 0), np.moveaxis(K, -1, 0), np.column_stack([ft, fn, z, z])


# --- frame -------------------------------------------------------------------------------------

@pytest.mark.parametrize("seed", range(4))
def test_frame_is_orthonormal_and_right_handed(seed):
    rng = np.random.default_rng(seed)
    pole, e1 = random_triad(rng) if seed else VERTICAL
    phi, theta = rng.uniform(-1.5, 1.5, 50), rng.uniform(-np.pi, np.pi, 50)
    t, n, b = d3.frame(phi, theta, pole, e1)
    gram = np.einsum("kij,klj->kil", np.stack([t, n, b], axis=1), np.stack([t, n, b], axis=1))
    np.testing.assert_allclose(gram, np.broadcast_to(np.eye(3), gram.shape), atol=1e-14)
    np.testing.assert_allclose(np.cross(t, n), b, atol=1e-14)                      # t x n = +b
    np.testing.assert_allclose(np.einsum("ki,i->k", t, pole), np.sin(phi), atol=1e-14)


def test_frame_derivative_identities():
    phi, theta = sp.symbols("phi theta", real=True)
    t, n, b = d3.symbolic_frame(phi, theta)
    expected = {(0, phi): n, (0, theta): -sp.cos(phi) * b, (1, phi): -t, (1, theta): sp.sin(phi) * b,
                (2, phi): sp.zeros(3, 1), (2, theta): sp.cos(phi) * t - sp.sin(phi) * n}
    for (i, angle), rhs in expected.items():
        assert sp.simplify((t, n, b)[i].diff(angle) - rhs) == sp.zeros(3, 1), (i, angle)


@pytest.mark.parametrize("pole,e1", [((0, 0, 2.0), (1, 0, 0)), ((0, 0, 1), (1, 0, 0.1)), ((0, 0, 1), (1, 0))])
def test_bad_triad_raises_with_advice(pole, e1):
    with pytest.raises(ValueError, match="pole and e1 must be"):
        d3.numeric_system(pole, e1)


# --- the derived system ------------------------------------------------------------------------

def test_residual_is_quasilinear_and_matches_the_written_rows():
    d = d3.derive()
    T, u, v, w, phi, _ = d.state
    Tt, ut, vt, wt, pt, tt = d.rates
    Ts, us, vs, ws, ps, ts = d.slopes
    m, ma, EA = d.constants[:3]
    e, c, s = T / EA, sp.cos(phi), sp.sin(phi)
    written = [m * (ut - v * pt + w * c * tt) - Ts,                                  # module docstring
               (m + ma) * (vt + u * pt - w * s * tt) - T * ps,
               (m + ma) * (wt - (u * c - v * s) * tt) + T * c * ts,
               Tt / EA - us + v * ps - w * c * ts,
               (1 + e) * pt - vs - u * ps + w * s * ts,
               -(1 + e) * c * tt - ws + (u * c - v * s) * ts]
    lhs = d.M * sp.Matrix(d.rates) + d.K * sp.Matrix(d.slopes)
    for i in range(6):
        assert sp.simplify(lhs[i] - written[i]) == 0, d3.ROW_NAMES[i]
        assert sp.simplify(d.residual[i] - (lhs[i] - d.F[i])) == 0, d3.ROW_NAMES[i]
    assert list(d.F[3:]) == [0, 0, 0]
    assert (d.M.free_symbols | d.K.free_symbols) <= {T, u, v, w, phi, m, ma, EA}


def test_planar_reduction_vertical_pole_symbolic():
    """Pole z, e1 x, theta = w = 0, no y current: rows 0,1,3,4 are theory/continuum.md §1; rows 2,5 vanish."""
    d = d3.derive()
    T, u, v, w, phi, theta = d.state
    m, ma, EA, w0, rho, dia, Cn, Ct = d.constants
    Ux, Uy, Uz = d.current
    plane = dict(zip(d.pole + d.e1, (0, 0, 1, 1, 0, 0))) | {theta: 0, w: 0, Uy: 0}
    M, K, F = (X.subs(plane) for X in (d.M, d.K, d.F))
    rows, cols = [0, 1, 3, 4], [0, 1, 2, 4]
    e, c, s = T / EA, sp.cos(phi), sp.sin(phi)
    M2 = sp.Matrix([[0, m, 0, -m * v], [0, 0, m + ma, (m + ma) * u], [1 / EA, 0, 0, 0], [0, 0, 0, 1 + e]])
    K2 = sp.Matrix([[-1, 0, 0, 0], [0, 0, 0, -T], [0, -1, 0, v], [0, 0, -1, -u]])
    ur, vr = u - (Ux * c + Uz * s), v - (-Ux * s + Uz * c)
    F2 = sp.Matrix([-w0 * s - rho * sp.pi * dia * Ct * sp.Abs(ur) * ur * sp.sqrt(1 + e) / 2,
                    -w0 * c - rho * dia * Cn * sp.Abs(vr) * vr * sp.sqrt(1 + e) / 2, 0, 0])
    assert sp.simplify(M.extract(rows, cols) - M2) == sp.zeros(4, 4)
    assert sp.simplify(K.extract(rows, cols) - K2) == sp.zeros(4, 4)
    assert sp.simplify(F.extract(rows, [0]) - F2) == sp.zeros(4, 1)
    assert M.extract([2, 5], cols) == sp.zeros(2, 4) and K.extract([2, 5], cols) == sp.zeros(2, 4)
    assert sp.simplify(F[2]) == 0 and F[5] == 0


@pytest.mark.parametrize("chart", ["vertical", "horizontal"])
def test_planar_reduction_numeric(chart):
    """Random planar states in both charts against the printed §2.1 matrices.

    Vertical pole: Y = (T, u, v, 0, phi, 0), rows (0, 1, 3, 4). Horizontal pole p = -y:
    Y = (T, u, 0, -v, 0, phi), rows (0, 2, 3, 5) with signs (+, -, +, -).
    """
    rng = np.random.default_rng(7)
    n = 40
    Y2 = random_states(rng, n)[:, [0, 1, 2, 4]]
    Y2[:, 3] = rng.uniform(-np.pi, np.pi, n)
    current = np.column_stack([rng.normal(0, 0.5, n), np.zeros(n), rng.normal(0, 0.3, n)])
    Y3 = np.zeros((n, 6))
    if chart == "vertical":
        Y3[:, [0, 1, 2, 4]] = Y2
        rows, other, cols = [0, 1, 3, 4], [2, 5], [0, 1, 2, 4]
        col_sign = row_sign = np.ones(4)
    else:
        Y3[:, [0, 1, 3, 5]] = Y2 * [1, 1, -1, 1]
        rows, other, cols = [0, 2, 3, 5], [1, 4], [0, 1, 3, 5]
        col_sign, row_sign = np.array([1, 1, -1, 1.0]), np.array([1, -1, 1, -1.0])
    M, K, F = d3.numeric_system(*(VERTICAL if chart == "vertical" else HORIZONTAL))(Y3, CONSTANTS, current)
    M2, K2, F2 = spec_planar(Y2, CONSTANTS, current[:, [0, 2]])

    def restrict(A):
        return row_sign[:, None] * A[:, rows][:, :, cols] * col_sign

    np.testing.assert_allclose(restrict(M), M2, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(restrict(K), K2, rtol=1e-13, atol=1e-12)
    np.testing.assert_allclose(row_sign * F[:, rows], F2, rtol=1e-12, atol=1e-12)
    # the out-of-plane rows are satisfied identically by planar motion
    assert np.abs(M[:, other][:, :, cols]).max() == 0 and np.abs(K[:, other][:, :, cols]).max() == 0
    np.testing.assert_allclose(F[:, other], 0.0, atol=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_rotation_about_vertical_leaves_equations_unchanged(seed):
    rng = np.random.default_rng(seed)
    pole, e1 = random_triad(rng)
    alpha = rng.uniform(0, 2 * np.pi)
    Rz = np.array([[np.cos(alpha), -np.sin(alpha), 0], [np.sin(alpha), np.cos(alpha), 0], [0, 0, 1]])
    Y = random_states(rng, 30)
    current = rng.normal(0, 0.6, (30, 3))
    first = d3.numeric_system(pole, e1)(Y, CONSTANTS, current)
    rotated = d3.numeric_system(Rz @ pole, Rz @ e1)(Y, CONSTANTS, current @ Rz.T)
    for a, b in zip(first, rotated):
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-10)


# --- any pole: the projected rows against the vector equations (finite differences) -----------

def motion(s, tau):
    """A smooth, arbitrary (not a solution) cable motion: tension, unit tangent, velocity."""
    g = np.array([np.cos(0.3 * s + 0.2 * tau) + 0.5, np.sin(0.4 * s - 0.1 * tau),
                  0.7 * np.cos(0.2 * s + 0.5 * tau) - 0.2])
    V = np.array([1 + 0.3 * np.sin(0.5 * s + tau), -0.4 * np.cos(0.3 * s - 0.7 * tau),
                  0.2 * np.sin(0.9 * s + 0.4 * tau)])
    return 5e3 * (1 + 0.2 * np.sin(0.6 * s - 0.3 * tau)), g / np.linalg.norm(g), V


def chart_state(s, tau, pole, e1):
    T, t, V = motion(s, tau)
    a1, a2, p = d3.triad(pole, e1)
    phi, theta = np.arcsin(t @ p), np.arctan2(t @ a2, t @ a1)
    _, n, b = d3.frame(phi, theta, pole, e1)
    return np.array([T, V @ t, V @ n, V @ b, phi, theta])


def central(f, x, h):
    diff = (f(x + h) - f(x - h)) / (2 * h)
    diff[5] = (((f(x + h)[5] - f(x - h)[5]) + np.pi) % (2 * np.pi) - np.pi) / (2 * h)   # theta unwrapped
    return diff


def vector_residuals(s, tau, c, current, h):
    """Momentum and compatibility vectors computed directly, with no chart (theory/continuum.md §2)."""
    def d(f, x):
        return (f(x + h) - f(x - h)) / (2 * h)

    T, t, V = motion(s, tau)
    acc = d(lambda x: motion(s, x)[2], tau)
    tension_flux = d(lambda x: motion(x, tau)[0] * motion(x, tau)[1], s)
    strain = T / c.axial_stiffness
    f = -c.weight_in_water * np.array([0, 0, 1.0]) + cable_drag(
        t, current - V, strain, c.diameter, c.drag_normal, c.drag_tangential, c.water_density)
    momentum = c.mass * acc + c.added_mass * (acc - (acc @ t) * t) - tension_flux - f
    compat = d(lambda x: (1 + motion(s, x)[0] / c.axial_stiffness) * motion(s, x)[1], tau) \
        - d(lambda x: motion(x, tau)[2], s)
    return momentum, compat


@pytest.mark.parametrize("seed", range(4))
def test_rows_are_projections_of_the_vector_equations_for_any_pole(seed):
    rng = np.random.default_rng(100 + seed)
    pole, e1 = (VERTICAL, HORIZONTAL)[seed] if seed < 2 else random_triad(rng)
    current, h = rng.normal(0, 0.5, 3), 1e-5
    checked = 0
    for s, tau in rng.uniform(0, 10, (6, 2)):
        Y = chart_state(s, tau, pole, e1)
        if abs(np.cos(Y[4])) < 0.2:
            continue                                          # too near this chart's singular set
        Ys = central(lambda x, tau=tau: chart_state(x, tau, pole, e1), s, h)
        Yt = central(lambda x, s=s: chart_state(s, x, pole, e1), tau, h)
        M, K, F = d3.numeric_system(pole, e1)(Y, CONSTANTS, current)
        rows = M @ Yt + K @ Ys - F
        momentum, compat = vector_residuals(s, tau, CONSTANTS, current, h)
        t, n, b = d3.frame(Y[4], Y[5], pole, e1)
        expected = np.array([momentum @ t, momentum @ n, momentum @ b, compat @ t, compat @ n, compat @ b])
        np.testing.assert_allclose(rows[:3], expected[:3], atol=1e-5 * np.abs(momentum).max() + 1e-6)
        np.testing.assert_allclose(rows[3:], expected[3:], atol=1e-8)
        checked += 1
    assert checked >= 3


# --- characteristic speeds and singular set --------------------------------------------------

def test_characteristic_polynomial_factors_exactly():
    d = d3.derive()
    T, phi = d.state[0], d.state[4]
    m, ma, EA = d.constants[:3]
    lam = sp.Symbol("lambda")
    expected = sp.cos(phi) / EA * (m * lam**2 - EA) * (T - (m + ma) * (1 + T / EA) * lam**2) ** 2
    assert sp.simplify(d3.characteristic_polynomial(lam) - expected) == 0


@pytest.mark.parametrize("seed", range(3))
def test_characteristic_speeds_numeric(seed):
    rng = np.random.default_rng(seed)
    pole, e1 = random_triad(rng)
    c = NO_DRAG if seed else CONSTANTS                 # drag enters F only
    Y = random_states(rng, 25)
    M, K, _ = d3.numeric_system(pole, e1)(Y, c, rng.normal(0, 0.5, 3))
    longitudinal, transverse = d3.characteristic_speeds(Y[:, 0], c)
    for Mi, Ki, cl, ct in zip(M, K, longitudinal, transverse):
        eig = np.sort(np.linalg.eigvals(np.linalg.solve(Mi, Ki)).real)
        np.testing.assert_allclose(eig, [-cl, -ct, -ct, ct, ct, cl], rtol=1e-7)
        for speed in (ct, -ct):                           # two independent eigenvectors each
            assert np.linalg.matrix_rank(Ki - speed * Mi, tol=1e-8 * np.abs(Ki).max()) == 4
    e = Y[:, 0] / c.axial_stiffness                       # leading order in e
    np.testing.assert_allclose(transverse, np.sqrt(Y[:, 0] / (c.mass + c.added_mass)) * (1 - e / 2),
                               rtol=2 * e.max() ** 2)
    np.testing.assert_allclose(longitudinal, np.sqrt(c.axial_stiffness / c.mass))


def test_mass_matrix_determinant_symbolic():
    d = d3.derive()
    T, phi = d.state[0], d.state[4]
    m, ma, EA = d.constants[:3]
    expected = m * (m + ma) ** 2 * (1 + T / EA) ** 2 * sp.cos(phi) / EA
    assert sp.simplify(d.M.det() - expected) == 0


def test_mass_matrix_singular_exactly_where_cos_phi_vanishes():
    rng = np.random.default_rng(11)
    pole, e1 = random_triad(rng)
    system = d3.numeric_system(pole, e1)
    Y = random_states(rng, 20)
    Y[:10, 4] = rng.choice([-np.pi / 2, np.pi / 2, 3 * np.pi / 2], 10)
    M, _, _ = system(Y, CONSTANTS, np.zeros(3))
    sigma = np.linalg.svd(M, compute_uv=False)
    ratio = sigma[:, -1] / sigma[:, 0]
    assert np.all(ratio[:10] < 1e-15)                       # cos(phi) = 0: singular
    assert np.all(ratio[10:] > 1e-7)                        # elsewhere: regular
    assert np.linalg.matrix_rank(M[0], tol=1e-12 * sigma[0, 0]) == 5
    detM = np.linalg.det(M[10:])
    c = CONSTANTS
    expected = c.mass * (c.mass + c.added_mass) ** 2 * (1 + Y[10:, 0] / c.axial_stiffness) ** 2 \
        * np.cos(Y[10:, 4]) / c.axial_stiffness
    np.testing.assert_allclose(detM, expected, rtol=1e-10)


def test_numeric_system_broadcasts_over_states():
    rng = np.random.default_rng(3)
    system = d3.numeric_system(*HORIZONTAL)
    Y = random_states(rng, 6).reshape(2, 3, 6)
    M, K, F = system(Y, CONSTANTS, (0.3, 0.0, -0.1))
    assert M.shape == (2, 3, 6, 6) and K.shape == (2, 3, 6, 6) and F.shape == (2, 3, 6)
    M1, _, F1 = system(Y[1, 2], CONSTANTS, (0.3, 0.0, -0.1))
    assert M1.shape == (6, 6) and F1.shape == (6,)
    np.testing.assert_array_equal(M[1, 2], M1)
    np.testing.assert_array_equal(F[1, 2], F1)
