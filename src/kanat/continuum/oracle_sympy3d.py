"""Symbolic derivation of the spatial (3-D) continuum cable equations (theory/continuum.md §2).

The source of truth for the 3-D model and a test oracle for its numeric kernels. It
needs ``sympy`` (a test dependency, ``pip install kanat[test]``); nothing in the runtime
package imports this module.

What is derived
---------------
Unknowns ``Y = (T, u, v, w, phi, theta)`` of unstretched arclength ``s`` and time ``t``;
velocity ``V = u t + v n + w b``; frame from azimuth-elevation angles about a pole ``p``
with a right-handed reference triad ``(e1, e2, p)``, ``e2 = p x e1``:

    t =  cos(phi) cos(theta) e1 + cos(phi) sin(theta) e2 + sin(phi) p
    n = -sin(phi) cos(theta) e1 - sin(phi) sin(theta) e2 + cos(phi) p
    b =  sin(theta) e1 - cos(theta) e2

The frame is orthonormal and right-handed with ``t x n = b`` (also ``n x b = t``,
``b x t = n``). sympy differentiates it (in the constant orthonormal basis
``(e1, e2, p)``) and finds:

    dt/dphi = n          dt/dtheta = -cos(phi) b
    dn/dphi = -t         dn/dtheta =  sin(phi) b
    db/dphi = 0          db/dtheta =  cos(phi) t - sin(phi) n

so for ``x`` = ``s`` or ``t`` the frame turns with ``d(.)/dx = omega_x x (.)``,
``omega_x = theta_x p + phi_x b = sin(phi) theta_x t + cos(phi) theta_x n + phi_x b``.
The vector equations (theory/continuum.md §2), with ``e = T/EA``,

    m dV/dt + m_a (dV/dt - (dV/dt . t) t) - d(T t)/ds - f = 0      (momentum)
    d/dt[(1 + e) t] - dV/ds                                  = 0      (compatibility)

projected on ``(t, n, b)`` give the six rows of ``M(Y) Y_t + K(Y) Y_s = F(Y)``:

    0 momentum.t       m (u_t - v phi_t + w cos(phi) theta_t)                 - T_s                = f_t
    1 momentum.n       (m + m_a)(v_t + u phi_t - w sin(phi) theta_t)          - T phi_s            = f_n
    2 momentum.b       (m + m_a)(w_t - (u cos(phi) - v sin(phi)) theta_t)     + T cos(phi) theta_s = f_b
    3 compatibility.t  T_t / EA - u_s + v phi_s - w cos(phi) theta_s                              = 0
    4 compatibility.n  (1 + e) phi_t - v_s - u phi_s + w sin(phi) theta_s                        = 0
    5 compatibility.b  -(1 + e) cos(phi) theta_t - w_s + (u cos(phi) - v sin(phi)) theta_s        = 0

Rows 0-2 are momentum along ``t, n, b``, rows 3-5 compatibility along ``t, n, b``; the
sign of every row is "projection of the left-hand sides above". For planar motion
(pole ``p = z``, ``e1 = x``, so ``e2 = y``; ``theta = w = 0``) rows 0, 1, 3, 4 are theory/continuum.md §1's
four rows in its order (momentum t, momentum n, stretch, rotation) and rows 2, 5 vanish
identically when the current has no ``y`` component. With a horizontal pole ``p = -y``,
``e1 = x`` (``e2 = z``) planar motion is instead ``phi = v = 0`` with ``theta`` the §2.1 angle
and ``w = -v_2D``; then rows 0, 2, 3, 5 are §2.1's rows times ``(+1, -1, +1, -1)``.

Loads. Write ``z_hat = z1 e1 + z2 e2 + z3 p`` (``z1 = e1.z_hat`` ...) and likewise the current
``U_c = U1 e1 + U2 e2 + U3 p`` from its global components; then ``U_t = U_c.t`` etc.:

    z_t =  cos(phi)(cos(theta) z1 + sin(theta) z2) + sin(phi) z3
    z_n = -sin(phi)(cos(theta) z1 + sin(theta) z2) + cos(phi) z3
    z_b =  sin(theta) z1 - cos(theta) z2
    u_r = u - U_t,   v_r = v - U_n,   w_r = w - U_b
    f_t = -w0 z_t - 0.5 rho pi d C_t |u_r| u_r sqrt(1 + e)
    f_n = -w0 z_n - 0.5 rho d C_n sqrt(v_r^2 + w_r^2) v_r sqrt(1 + e)
    f_b = -w0 z_b - 0.5 rho d C_n sqrt(v_r^2 + w_r^2) w_r sqrt(1 + e)

Bending stiffness
-----------------
``derive(bending=True)`` adds the rod of :mod:`kanat.continuum.bending3d`: unknowns ``S_n, S_b,
M_n, M_b`` (the shear ``S = S_n n + S_b b`` and moment ``M = M_n n + M_b b``), the force
``T t + S`` in the momentum rows and four rows, ``EI t x t_s - M`` and ``dM/ds + (1 + e) t x F``
projected on ``n`` and ``b`` (torsion left out); the tests compare the kernel's rows with them.

Characteristic speeds and singularities
---------------------------------------
``det(K - lam M) = cos(phi) / EA * (m lam^2 - EA) (T - (m + m_a)(1 + e) lam^2)^2``,
so the eigenvalues of ``M^-1 K`` are exactly (not only to leading order in ``e``)

    longitudinal  +-sqrt(EA / m)
    transverse    +-sqrt(T / ((m + m_a)(1 + e))),  each double (normal and binormal waves),

independent of ``u, v, w, phi, theta`` and of the pole; the transverse eigenvalues have
two independent eigenvectors each (the system is hyperbolic for ``T > 0``, degenerate
at ``T = 0``). ``det M = m (m + m_a)^2 (1 + e)^2 cos(phi) / EA``: ``M`` is singular exactly
where ``cos(phi) = 0``, i.e. ``t = +-p``. There ``theta`` (the azimuth about the pole) is
undefined, row 5 loses its time derivative and the ``theta`` column of ``M`` falls into
the span of the ``v`` and ``w`` columns. (``1 + e = 0``, ``T = -EA``, is unphysical.)
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import sympy as sp

STATE_NAMES = ("T", "u", "v", "w", "phi", "theta")
ROW_NAMES = ("momentum_t", "momentum_n", "momentum_b",
             "compatibility_t", "compatibility_n", "compatibility_b")
BENDING_STATE_NAMES = STATE_NAMES + ("S_n", "S_b", "M_n", "M_b")
BENDING_ROW_NAMES = ROW_NAMES + ("curvature_n", "curvature_b", "moment_n", "moment_b")
TRIAD_TOLERANCE = 1e-9      # |p| = |e1| = 1 and p.e1 = 0 must hold to this (unit vectors given in floats)


@dataclass(frozen=True)
class CableConstants:
    """Physical constants of the cable and the water, in the order of :attr:`Derivation.constants`.

    Attributes
    ----------
    mass : float
        ``m``, mass per unstretched length in air [kg/m].
    added_mass : float
        ``m_a``, normal added mass per length [kg/m].
    axial_stiffness : float
        ``EA`` [N].
    weight_in_water : float
        ``w0`` [N/m].
    water_density : float
        ``rho`` [kg/m^3].
    diameter : float
        ``d`` [m].
    drag_normal, drag_tangential : float
        ``C_n`` (on ``d``) and ``C_t`` (on ``pi d``) [-].
    """

    mass: float
    added_mass: float
    axial_stiffness: float
    weight_in_water: float
    water_density: float
    diameter: float
    drag_normal: float
    drag_tangential: float

    def values(self) -> tuple[float, ...]:
        return (self.mass, self.added_mass, self.axial_stiffness, self.weight_in_water,
                self.water_density, self.diameter, self.drag_normal, self.drag_tangential)


@dataclass(frozen=True)
class Derivation:
    """The derived system ``M(Y) Y_t + K(Y) Y_s = F(Y)`` and the symbols it is written in.

    Attributes
    ----------
    state, rates, slopes : tuple of sympy.Symbol, length 6
        ``Y``, ``Y_t``, ``Y_s`` in the order of :data:`STATE_NAMES`.
    constants : tuple of sympy.Symbol, length 8
        ``(m, m_a, EA, w0, rho, d, C_n, C_t)``, the order of :class:`CableConstants`.
    current, pole, e1 : tuple of sympy.Symbol, length 3
        Global ``(x, y, z)`` components of ``U_c``, ``p`` and ``e1`` (``e2 = p x e1``).
        ``F`` is meaningful only for orthonormal ``p, e1`` (unconstrained symbols here;
        :func:`numeric_system` checks its numbers).
    residual : sympy.Matrix, shape (6, 1)
        ``M Y_t + K Y_s - F``, rows in the order of :data:`ROW_NAMES`.
    M, K : sympy.Matrix, shape (6, 6)
    F : sympy.Matrix, shape (6, 1)
    """

    state: tuple
    rates: tuple
    slopes: tuple
    constants: tuple
    current: tuple
    pole: tuple
    e1: tuple
    residual: sp.Matrix
    M: sp.Matrix
    K: sp.Matrix
    F: sp.Matrix

    @property
    def arguments(self) -> tuple:
        """The symbols ``M, K, F`` depend on: state, constants, current, pole, e1 (26)."""
        return self.state + self.constants + self.current + self.pole + self.e1


def symbolic_frame(phi, theta) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """``(t, n, b)`` as sympy columns of components on the basis ``(e1, e2, p)``."""
    cp, sp_, ct, st = sp.cos(phi), sp.sin(phi), sp.cos(theta), sp.sin(theta)
    return (sp.Matrix([cp * ct, cp * st, sp_]),
            sp.Matrix([-sp_ * ct, -sp_ * st, cp]),
            sp.Matrix([st, -ct, 0]))


def _reduce(expr):
    """Expand and replace ``sin^2`` by ``1 - cos^2`` (exact, much faster than trigsimp here)."""
    expr = sp.expand(expr)
    for angle in expr.atoms(sp.sin):
        expr = sp.expand(expr.subs(angle ** 2, 1 - sp.cos(angle.args[0]) ** 2))
    return expr


def _loads(tv, nv, bv, T, u, v, w, constants, current, pole, e1):
    """``(f_t, f_n, f_b)``: weight in water and drag of the relative flow (module docstring)."""
    EA, w0, rho, d, C_n, C_t = constants[2:]
    pv, e1v = sp.Matrix(pole), sp.Matrix(e1)
    basis = (e1v, pv.cross(e1v), pv)
    zb = sp.Matrix([vec[2] for vec in basis])                      # z_hat on (e1, e2, p)
    ub = sp.Matrix([sp.Matrix(current).dot(vec) for vec in basis])  # U_c on (e1, e2, p)
    root = sp.sqrt(1 + T / EA)
    u_r, v_r, w_r = u - ub.dot(tv), v - ub.dot(nv), w - ub.dot(bv)
    normal_speed = sp.sqrt(v_r ** 2 + w_r ** 2)
    f_t = -w0 * zb.dot(tv) - sp.Rational(1, 2) * rho * sp.pi * d * C_t * sp.Abs(u_r) * u_r * root
    f_n = -w0 * zb.dot(nv) - sp.Rational(1, 2) * rho * d * C_n * normal_speed * v_r * root
    f_b = -w0 * zb.dot(bv) - sp.Rational(1, 2) * rho * d * C_n * normal_speed * w_r * root
    return f_t, f_n, f_b


@lru_cache(maxsize=2)
def derive(bending: bool = False) -> Derivation:
    """Derive the six projected equations and their matrix form (module docstring).

    sympy differentiates the frame through ``phi(s, t)``, ``theta(s, t)``; the loads ``f``
    are built as ``f_t t + f_n n + f_b b`` and projected with the frame's Gram matrix.
    Cached: the first call takes about a second.

    ``bending=True``: the rod of :mod:`kanat.continuum.bending3d`, ten unknowns
    (:data:`BENDING_STATE_NAMES`, constants with ``EI`` last) and ten rows
    (:data:`BENDING_ROW_NAMES`) from the vector equations with the force ``F = T t + S_n n + S_b b``
    and the moment ``M = M_n n + M_b b``:

        m dV/dt + m_a (dV/dt - (dV/dt . t) t) - dF/ds - f = 0       (momentum; t, n, b)
        d/dt[(1 + e) t] - dV/ds                           = 0       (compatibility; t, n, b)
        EI t x t_s - M                                    = 0       (curvature; n, b)
        dM/ds + (1 + e) t x F                             = 0       (moment balance; n, b)
    """
    s, time = sp.symbols("s t", real=True)
    names = BENDING_STATE_NAMES if bending else STATE_NAMES
    fields = [sp.Function(name, real=True)(s, time) for name in names]
    T, u, v, w, phi, theta = fields[:6]
    state = sp.symbols(" ".join(names), real=True)
    rates = sp.symbols(" ".join(f"{name}_t" for name in names), real=True)
    slopes = sp.symbols(" ".join(f"{name}_s" for name in names), real=True)
    constants = sp.symbols("m m_a EA w_0 rho d C_n C_t" + (" EI" if bending else ""), positive=True)
    current = sp.symbols("U_x U_y U_z", real=True)
    pole = sp.symbols("p_x p_y p_z", real=True)
    e1 = sp.symbols("e1_x e1_y e1_z", real=True)
    m, m_a, EA = constants[:3]

    frame = symbolic_frame(phi, theta)
    tv, nv, bv = frame
    V = u * tv + v * nv + w * bv
    acc = V.diff(time)
    force = T * tv
    if bending:
        force = force + fields[6] * nv + fields[7] * bv
    momentum = m * acc + m_a * (acc - acc.dot(tv) * tv) - force.diff(s)
    compatibility = ((1 + T / EA) * tv).diff(time) - V.diff(s)
    kinematic = [_reduce(vec.dot(axis)) for vec in (momentum, compatibility) for axis in frame]
    if bending:
        moment = fields[8] * nv + fields[9] * bv
        curvature = constants[8] * tv.cross(tv.diff(s)) - moment
        balance = moment.diff(s) + (1 + T / EA) * tv.cross(force)
        kinematic += [_reduce(vec.dot(axis)) for vec in (curvature, balance) for axis in (nv, bv)]

    # f = f_t t + f_n n + f_b b projected on (t, n, b) through the frame's Gram matrix,
    # which sympy reduces to the identity (orthonormality is derived, not assumed).
    loads = _loads(tv, nv, bv, T, u, v, w, constants[:8], current, pole, e1)
    gram = [[_reduce(a.dot(b)) for b in frame] for a in frame]
    f = [sum(gram[i][j] * loads[j] for j in range(3)) for i in range(3)]
    rows = [kinematic[i] - f[i] for i in range(3)] + kinematic[3:]
    to_symbols = {}
    for fun, yt, ys in zip(fields, rates, slopes):
        to_symbols[sp.Derivative(fun, time)] = yt
        to_symbols[sp.Derivative(fun, s)] = ys
    residual = sp.Matrix([sp.sympify(r).xreplace(to_symbols) for r in rows])
    residual = residual.xreplace(dict(zip(fields, state)))
    M = residual.jacobian(rates).applyfunc(sp.simplify)
    K = residual.jacobian(slopes).applyfunc(sp.simplify)
    F = -residual.xreplace({x: 0 for x in rates + slopes})
    return Derivation(state, rates, slopes, constants, current, pole, e1, residual, M, K, F)


def characteristic_polynomial(speed: sp.Symbol | None = None) -> sp.Expr:
    """``det(K - lam M)`` factored; its roots ``lam`` are the characteristic speeds."""
    lam = speed if speed is not None else sp.Symbol("lambda")
    d = derive()
    return sp.factor(sp.expand((d.K - lam * d.M).det(method="berkowitz")))


def characteristic_speeds(tension, constants: CableConstants) -> tuple[np.ndarray, np.ndarray]:
    """Exact positive speeds ``(sqrt(EA/m), sqrt(T/((m+m_a)(1+e))))`` [m/s] (each taken +-).

    The longitudinal pair is simple, the transverse pair double (module docstring).
    """
    T = np.asarray(tension, dtype=float)
    c = constants
    longitudinal = np.full_like(T, np.sqrt(c.axial_stiffness / c.mass))
    transverse = np.sqrt(T / ((c.mass + c.added_mass) * (1.0 + T / c.axial_stiffness)))
    return longitudinal, transverse


def triad(pole, e1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The right-handed reference triad ``(e1, e2 = p x e1, p)`` from numeric unit vectors.

    Raises
    ------
    ValueError
        If ``pole`` or ``e1`` is not a unit 3-vector or they are not orthogonal.
    """
    p, a = np.asarray(pole, dtype=float), np.asarray(e1, dtype=float)
    if p.shape != (3,) or a.shape != (3,):
        raise ValueError(f"pole and e1 must be 3-vectors; got shapes {p.shape} and {a.shape}")
    checks = {"|pole| - 1": p @ p - 1.0, "|e1| - 1": a @ a - 1.0, "pole . e1": p @ a}
    bad = {k: v for k, v in checks.items() if abs(v) > TRIAD_TOLERANCE}
    if bad:
        raise ValueError(f"pole and e1 must be orthonormal (to {TRIAD_TOLERANCE:g}); "
                         f"{', '.join(f'{k} = {v:.3g}' for k, v in bad.items())}. Normalize them "
                         "and take e1 perpendicular to the pole.")
    return a, np.cross(p, a), p


def frame(phi, theta, pole, e1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Numeric ``(t, n, b)`` in global coordinates, right-handed with ``t x n = b``.

    Parameters
    ----------
    phi, theta : float or ndarray, shape (...)
        Elevation above the plane normal to the pole and azimuth from ``e1`` [rad].
    pole, e1 : array_like, shape (3,)
        Orthonormal unit vectors (global x, y, z); ``e2 = pole x e1``.

    Returns
    -------
    t, n, b : ndarray, shape (..., 3)
    """
    a1, a2, p = triad(pole, e1)
    phi, theta = np.broadcast_arrays(np.asarray(phi, dtype=float), np.asarray(theta, dtype=float))
    cp, sp_, ct, st = (f(x)[..., None] for f, x in
                       ((np.cos, phi), (np.sin, phi), (np.cos, theta), (np.sin, theta)))
    t = cp * ct * a1 + cp * st * a2 + sp_ * p
    n = -sp_ * ct * a1 - sp_ * st * a2 + cp * p
    b = st * a1 - ct * a2
    return t, n, b


@lru_cache(maxsize=2)
def _lambdified(bending: bool = False):
    """One numpy function of all arguments returning the entries of ``M, K, F`` (78; 210 with bending)."""
    d = derive(bending)
    entries = list(d.M) + list(d.K) + list(d.F)
    return sp.lambdify(d.arguments, entries, modules="numpy", cse=True)


def numeric_bending_system(pole, e1):
    """As :func:`numeric_system` for the rod (``derive(bending=True)``): ``system(Y, constants,
    bending_stiffness, current) -> (M, K, F)`` with ``Y`` (..., 10) in the order of
    :data:`BENDING_STATE_NAMES`, ``M, K`` (..., 10, 10) and ``F`` (..., 10)."""
    a1, _, p = triad(pole, e1)
    fun = _lambdified(True)

    def system(state, constants: CableConstants, bending_stiffness: float, current=(0.0, 0.0, 0.0)):
        Y = np.asarray(state, dtype=float)
        U = np.asarray(current, dtype=float)
        shape = np.broadcast_shapes(Y.shape[:-1], U.shape[:-1])
        args = [*np.moveaxis(Y, -1, 0), *constants.values(), bending_stiffness, *np.moveaxis(U, -1, 0), *p, *a1]
        out = np.stack([np.broadcast_to(np.asarray(x, dtype=float), shape) for x in fun(*args)], axis=-1)
        return (out[..., :100].reshape(shape + (10, 10)), out[..., 100:200].reshape(shape + (10, 10)),
                out[..., 200:])

    return system


def numeric_system(pole, e1):
    """``system(Y, constants, current) -> (M, K, F)`` as numpy arrays for one pole triad.

    Parameters
    ----------
    pole, e1 : array_like, shape (3,)
        Orthonormal unit vectors in global coordinates (``e2 = pole x e1``); any
        right-handed triad, e.g. ``pole = (0, 0, 1), e1 = (1, 0, 0)`` (vertical) or
        ``pole = (0, -1, 0), e1 = (1, 0, 0)`` (horizontal, for towed cables).

    Returns
    -------
    callable
        ``system(Y, constants, current)`` with ``Y`` shape (..., 6) in the order of
        :data:`STATE_NAMES` (T [N], u, v, w [m/s], phi, theta [rad]), ``constants`` a
        :class:`CableConstants` and ``current`` the global current [m/s], shape (3,) or
        (..., 3). Returns ``M`` (..., 6, 6), ``K`` (..., 6, 6), ``F`` (..., 6).
    """
    a1, _, p = triad(pole, e1)
    fun = _lambdified()

    def system(state, constants: CableConstants, current=(0.0, 0.0, 0.0)):
        Y = np.asarray(state, dtype=float)
        U = np.asarray(current, dtype=float)
        shape = np.broadcast_shapes(Y.shape[:-1], U.shape[:-1])
        args = [*np.moveaxis(Y, -1, 0), *constants.values(), *np.moveaxis(U, -1, 0), *p, *a1]
        out = np.stack([np.broadcast_to(np.asarray(x, dtype=float), shape) for x in fun(*args)], axis=-1)
        return (out[..., :36].reshape(shape + (6, 6)), out[..., 36:72].reshape(shape + (6, 6)),
                out[..., 72:])

    return system
