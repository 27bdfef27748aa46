"""Seed 001: a sphere held by two cables in a uniform flow (SPEC §3.2).

Naumov & Agievich, "Numerical solution of the boundary-value problem of the
equilibrium of a spherical body on cables in a uniform stream" (seed 001).

The problem
-----------
Sphere A (diameter ``D``, net buoyancy ``Q``) is held by a weightless straight line
AC (length ``L0``, anchor C at ``(X_C, 0)``) and a heavy cable AOB (length ``L``,
weight ``q`` per metre in water, diameter ``delta``) anchored at B, the origin.
``y`` is the height above the bottom. The arclength ``sigma = S/L`` runs from A
(0) to B (1), ``alpha`` is the local cable angle, with unit tangent and normal

    t = (cos alpha, -sin alpha),     n = (sin alpha, cos alpha).

Dimensionless equations (paper eqs. 10, 11, 14, 15 as corrected in SPEC §3.2)::

    tau dalpha/dsigma + Psi cos(alpha) - r_n = 0
    dtau/dsigma + Psi sin(alpha) + r_t = 0
    dx/dsigma = cos(alpha),     dy/dsigma = -sin(alpha),     x(1) = y(1) = 0
    r_n = (chi + (1 - chi) sin a + cos^2 a sin a) sin a
    r_t = (chi + (1 - chi) sin a - sin^3 a) cos a

They are ``d(tau t)/dsigma + f = 0`` with ``f = (0, -Psi) + r_n n + r_t t``: the cable's
drag ``r_n n`` has the x-component ``r_n sin(alpha) > 0``, so **the flow acts on the
cable in +x**. The formulas hold for ``0 <= alpha <= pi`` (cable descending from A).

Force balance at A and the two conventions
------------------------------------------
Forces on the sphere, in units of ``k1 L``:

    cable        tau0 t(0) = tau0 (cos a0, -sin a0)   (the cable pulls A towards B)
    buoyancy     (0, QkL)
    sphere drag  (s_R RkL, 0)
    line AC      tau_AC u,   u = (x_C - x_A, -y_A) / |AC|

and their sum is zero. Projected on ``p = (y_A, x_C - x_A)`` (AC turned by +90
degrees, ``|p| = |AC|``) the line drops out and, with ``F`` the sum of the first three,
(``F . p = (C - A) x F``, the moment of ``F`` about C with its sign reversed)

    eps2 = 100 (F . p) / sqrt(QkL^2 + RkL^2)
         = 100 [y_A (tau0 cos a0 + s_R RkL) + (x_C - x_A)(QkL - tau0 sin a0)] / sqrt(QkL^2 + RkL^2).

``convention="published"`` takes ``s_R = -1``: the sphere's drag acts in -x, against
the flow that acts on the cable. This is what reproduces the paper (its eq. 19 as
corrected in SPEC §3.2) but is not physically consistent. ``convention="physical"``
takes ``s_R = +1``: cable and sphere feel the same flow. The projection along ``u``
gives the line tension ``tau_AC = -F . u`` (:func:`forces_on_sphere`).

Residuals (paper eqs. 18, 19), both in percent; the paper accepts ``|eps| < 0.01 %``::

    eps1 = 100 (1 - sqrt(y_A^2 + (x_C - x_A)^2) / LoL)

``eps2`` as above. Note: SPEC §3.2 prints the numerator of ``eps2`` with the opposite
overall sign; the root is the same, and the sign used here is the one that gives the
paper's reported residuals (``eps2 = +0.00403 %`` at ``alpha0 = 46.9 deg``,
``tau0 = 0.6066``) and its statement that ``eps2`` grows with ``alpha(0)`` and ``tau(0)``.
Because ``|p| = |AC|``, ``eps2`` is ``|AC|`` (about ``LoL``) times the percentage of
the perpendicular force to the sphere's load, as in the paper.

Solvers
-------
``shooting`` integrates from A with unknown ``(alpha0, tau0)`` (``x, y`` measured from
A, then shifted so that B is at the origin) and finds the root of ``(eps1, eps2)``;
``collocation`` solves the four ODEs with ``x(1) = y(1) = 0, eps1 = eps2 = 0`` by
``scipy.integrate.solve_bvp``. Both fall back to continuation from the paper's first
case when the direct attempts fail.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np
from scipy.integrate import solve_bvp, solve_ivp
from scipy.optimize import root

from kanat.errors import CaseError, Problem, SolverError

#: Sign of the sphere's drag along x, by convention (see the module docstring).
SPHERE_DRAG_SIGN = {"published": -1.0, "physical": +1.0}
#: The paper's acceptance criterion for both residuals [%].
PAPER_CRITERION_PERCENT = 0.01
#: Converged when both residuals are below this [%]; set by the integration tolerance.
RESIDUAL_TOL_PERCENT = 1e-7
#: Smallest tension allowed while integrating: the alpha equation divides by tau.
TAU_MIN = 1e-6
#: Relative / absolute tolerance of the shooting integration (DOP853).
SHOOT_RTOL, SHOOT_ATOL = 1e-11, 1e-13
#: Collocation tolerance of solve_bvp; 1e-9 keeps it within ~1e-10 of shooting.
BVP_TOL, BVP_MAX_NODES = 1e-9, 20_000
#: Continuation in lambda from the paper's case 1: first step, smallest step.
CONTINUATION_STEP, CONTINUATION_MIN_STEP = 0.25, 1.0 / 512


@dataclass(frozen=True)
class SphereGroups:
    """Dimensionless groups of the problem (paper eq. 16).

    Attributes
    ----------
    Psi : float
        ``q / k1``: cable weight in water per metre over its normal drag per metre,
        ``k1 = 0.5 C_90 delta rho V^2`` (eq. 6).
    LoL : float
        ``L0 / L``: length of the line AC over the length of the cable AOB.
    x_C : float
        ``X_C / L``: abscissa of anchor C (anchor B is the origin).
    QkL : float
        ``Q / (k1 L)``: net buoyancy of the sphere.
    RkL : float
        ``R0 / (k1 L) = 0.288 D^2 / (delta L)``: drag of the sphere,
        ``R0 = 0.5 C_u (pi D^2 / 4) rho V^2`` (eq. 5).
    chi : float
        ``C_0 / C_90``: tangential over normal drag coefficient of the cable (eq. 14).
    """

    Psi: float
    LoL: float
    x_C: float
    QkL: float
    RkL: float
    chi: float = 0.0333

    def __post_init__(self) -> None:
        problems = _group_problems(self)
        if problems:
            raise CaseError(problems)


def _group_problems(g: SphereGroups) -> list[Problem]:
    """Every reason why ``g`` cannot have an equilibrium, as :class:`Problem` records."""
    out = []
    if not all(np.isfinite(getattr(g, f.name)) for f in fields(g)):
        out.append(Problem("", f"all groups must be finite, got {g!r}"))
        return out
    if g.LoL <= 0:
        out.append(Problem("LoL", f"line length ratio must be > 0, got {g.LoL}"))
    if g.RkL < 0:
        out.append(Problem("RkL", f"sphere drag group must be >= 0, got {g.RkL}"))
    if not 0 <= g.chi < 1:
        out.append(Problem("chi", f"C_0/C_90 must be in [0, 1), got {g.chi}"))
    if np.hypot(g.QkL, g.RkL) == 0:
        out.append(Problem("QkL", "QkL and RkL are both zero: eps2 has no scale"))
    if g.LoL > 0 and not g.LoL - 1 < abs(g.x_C) < g.LoL + 1:
        out.append(Problem("x_C", f"|x_C| = {abs(g.x_C)} must lie in (LoL - 1, LoL + 1) = "
                           f"({g.LoL - 1}, {g.LoL + 1}) for A to reach both anchors"))
    return out


#: The paper's first case (eq. 21) and its second case (V^2 doubled).
PAPER_CASE_1 = SphereGroups(Psi=0.02, LoL=2.0, x_C=-1.732, QkL=0.45, RkL=0.4)
PAPER_CASE_2 = SphereGroups(Psi=0.01, LoL=2.0, x_C=-1.732, QkL=0.225, RkL=0.4)
#: (alpha0 [rad], tau0) solving PAPER_CASE_1 in each convention: the continuation start.
_REFERENCE_ANSWER = {"published": (0.818367, 0.606623), "physical": (0.496522, 0.372559)}


@dataclass(frozen=True)
class SphereScales:
    """Scales that turn the dimensionless solution into SI (paper eq. 9).

    Attributes
    ----------
    k1 : float
        Normal drag per metre of cable at the flow speed, ``0.5 C_90 delta rho V^2`` [N/m].
    L : float
        Length of the cable AOB [m].
    """

    k1: float
    L: float

    @property
    def force(self) -> float:
        """Force scale ``k1 L`` [N]: ``T = tau k1 L``."""
        return self.k1 * self.L


def groups_from_dimensional(flow_speed, sphere_diameter, net_buoyancy, cable_diameter,
                            cable_length, cable_weight, line_length, anchor_x,
                            water_density=1025.0, c_90=1.2, c_0=0.04, c_u=0.44):
    """Dimensionless groups (eq. 16) and scales (eq. 9) from SI inputs.

    Parameters
    ----------
    flow_speed : float
        Uniform flow speed ``V`` [m/s], > 0.
    sphere_diameter, net_buoyancy : float
        ``D`` [m] and ``Q`` = buoyancy minus weight of the sphere [N].
    cable_diameter, cable_length, cable_weight : float
        ``delta`` [m], ``L`` [m] and weight in water per metre ``q`` [N/m] of AOB.
    line_length, anchor_x : float
        ``L0`` [m] of the line AC and abscissa ``X_C`` [m] of anchor C (B at 0).
    water_density : float
        ``rho`` [kg/m^3].
    c_90, c_0, c_u : float
        Normal and tangential drag coefficients of the cable and the sphere's drag
        coefficient (eqs. 5, 6).

    Returns
    -------
    groups : SphereGroups
    scales : SphereScales
    """
    positive = {"flow_speed": flow_speed, "sphere_diameter": sphere_diameter,
                "cable_diameter": cable_diameter, "cable_length": cable_length,
                "line_length": line_length, "water_density": water_density, "c_90": c_90}
    bad = [Problem(k, f"must be > 0, got {v}") for k, v in positive.items() if not v > 0]
    if bad:
        raise CaseError(bad)
    dynamic_pressure = 0.5 * water_density * flow_speed**2
    k1 = c_90 * cable_diameter * dynamic_pressure                           # eq. 6
    sphere_drag = c_u * (np.pi * sphere_diameter**2 / 4) * dynamic_pressure  # eq. 5
    force = k1 * cable_length
    groups = SphereGroups(Psi=float(cable_weight / k1), LoL=float(line_length / cable_length),
                          x_C=float(anchor_x / cable_length), QkL=float(net_buoyancy / force),
                          RkL=float(sphere_drag / force), chi=float(c_0 / c_90))
    return groups, SphereScales(k1=float(k1), L=float(cable_length))


def cable_drag(alpha, chi):
    """Normal and tangential drag of the cable per unit ``k1`` (eqs. 14, 15 corrected).

    Parameters
    ----------
    alpha : float or ndarray
        Cable angle [rad], ``0 <= alpha <= pi``.
    chi : float
        ``C_0 / C_90``.

    Returns
    -------
    r_n, r_t : float or ndarray, shape of ``alpha``
        Components along ``n = (sin a, cos a)`` and ``t = (cos a, -sin a)``.
    """
    sa, ca = np.sin(alpha), np.cos(alpha)
    r_n = (chi + (1 - chi) * sa + ca**2 * sa) * sa
    r_t = (chi + (1 - chi) * sa - sa**3) * ca
    return r_n, r_t


def cable_rhs(sigma, state, groups):
    """Right-hand side of eqs. (10)-(11) for ``state = (alpha, tau, x, y)``.

    Vectorized: ``state`` may have shape (4,) or (4, m). ``tau`` is floored at
    ``TAU_MIN`` in the division; the callers reject solutions that reach it.
    """
    alpha, tau = state[0], state[1]
    r_n, r_t = cable_drag(alpha, groups.chi)
    sa, ca = np.sin(alpha), np.cos(alpha)
    dalpha = (r_n - groups.Psi * ca) / np.maximum(tau, TAU_MIN)
    dtau = -groups.Psi * sa - r_t
    return np.array([dalpha, dtau, ca, -sa])


def _convention_sign(convention: str) -> float:
    try:
        return SPHERE_DRAG_SIGN[convention]
    except KeyError:
        raise ValueError(f"unknown convention {convention!r}; valid: "
                         f"{sorted(SPHERE_DRAG_SIGN)}") from None


@dataclass(frozen=True, eq=False)
class SphereForces:
    """Forces on the sphere in units of ``k1 L``, each an ndarray of shape (2,) (x, y).

    ``line_tension`` is the tension of AC, ``tau_AC`` (> 0 when the line is taut).
    """

    cable: np.ndarray
    buoyancy: np.ndarray
    drag: np.ndarray
    line: np.ndarray
    line_tension: float

    @property
    def total(self) -> np.ndarray:
        """Sum of the four forces, shape (2,); zero at equilibrium."""
        return self.cable + self.buoyancy + self.drag + self.line


def forces_on_sphere(groups, convention, alpha0, tau0, x_A, y_A) -> SphereForces:
    """Force balance of the sphere at A (module docstring), line tension from its AC part.

    Parameters
    ----------
    groups : SphereGroups
    convention : {"published", "physical"}
    alpha0, tau0 : float
        Cable angle [rad] and tension at A.
    x_A, y_A : float
        Position of A.
    """
    cable = tau0 * np.array([np.cos(alpha0), -np.sin(alpha0)])
    buoyancy = np.array([0.0, groups.QkL])
    drag = np.array([_convention_sign(convention) * groups.RkL, 0.0])
    to_c = np.array([groups.x_C - x_A, -y_A])
    u = to_c / np.hypot(*to_c)
    line_tension = -float(np.dot(cable + buoyancy + drag, u))
    return SphereForces(cable, buoyancy, drag, line_tension * u, line_tension)


def sphere_residuals(groups, convention, alpha0, tau0, x_A, y_A):
    """Residuals ``(eps1, eps2)`` in percent (eqs. 18, 19; module docstring for the sign)."""
    s_r = _convention_sign(convention)
    dx = groups.x_C - x_A
    eps1 = 100.0 * (1.0 - np.hypot(y_A, dx) / groups.LoL)
    # (C - A) x F with F = cable + buoyancy + drag: minus F's moment about C
    cross = y_A * (tau0 * np.cos(alpha0) + s_r * groups.RkL) + dx * (groups.QkL - tau0 * np.sin(alpha0))
    eps2 = 100.0 * cross / np.hypot(groups.QkL, groups.RkL)
    return float(eps1), float(eps2)


@dataclass(frozen=True, eq=False)
class SphereSolution:
    """Equilibrium of the sphere and its cable; the result of :func:`solve_sphere`.

    Attributes
    ----------
    groups : SphereGroups
        The problem solved.
    convention : {"published", "physical"}
        Direction of the sphere's drag (module docstring).
    method : str
        ``"shooting"``, ``"collocation"`` or ``"single shot"`` (:func:`shoot_sphere`).
    alpha0 : float
        Cable angle at A [rad].
    tau0 : float
        Cable tension at A in units of ``k1 L``.
    eps1_percent, eps2_percent : float
        Residuals of eqs. (18), (19) [%].
    sigma, alpha, tau, x, y : ndarray, shape (n,)
        Arclength from A, angle [rad], tension and position along the cable.
    scales : SphereScales or None
        Present when the problem came from :func:`groups_from_dimensional`.
    info : str
        How the solution was reached (which guess, continuation steps).
    """

    groups: SphereGroups
    convention: str
    method: str
    alpha0: float
    tau0: float
    eps1_percent: float
    eps2_percent: float
    sigma: np.ndarray
    alpha: np.ndarray
    tau: np.ndarray
    x: np.ndarray
    y: np.ndarray
    scales: SphereScales | None = None
    info: str = ""

    @property
    def x_A(self) -> float:
        """Abscissa of the sphere A."""
        return float(self.x[0])

    @property
    def y_A(self) -> float:
        """Height of the sphere A above the bottom."""
        return float(self.y[0])

    @property
    def forces(self) -> SphereForces:
        """Forces on the sphere in units of ``k1 L`` (:func:`forces_on_sphere`)."""
        return forces_on_sphere(self.groups, self.convention, self.alpha0, self.tau0,
                                self.x_A, self.y_A)

    @property
    def tau_line(self) -> float:
        """Tension of the line AC in units of ``k1 L``, from the force balance at A."""
        return self.forces.line_tension

    @property
    def physical_warnings(self) -> tuple[str, ...]:
        """Where the equilibrium leaves the model's assumptions, with numbers."""
        out = []
        if self.tau_line <= 0:
            out.append(f"line AC is in compression (tau_AC = {self.tau_line:.4g}): a rope "
                       "cannot hold this equilibrium")
        if self.alpha.min() < 0 or self.alpha.max() > np.pi:
            out.append(f"alpha leaves [0, 180] deg ({np.degrees(self.alpha.min()):.1f} to "
                       f"{np.degrees(self.alpha.max()):.1f}): outside the drag law (eq. 14)")
        if self.y.min() < -1e-9:
            out.append(f"the cable goes below the bottom (min y = {self.y.min():.4g})")
        return tuple(out)

    def _scales(self) -> SphereScales:
        if self.scales is None:
            raise ValueError("no dimensional scales: build the groups with "
                             "groups_from_dimensional() to get s, X, Y, T in SI")
        return self.scales

    @property
    def s(self) -> np.ndarray:
        """Arclength from A [m], shape (n,)."""
        return self.sigma * self._scales().L

    @property
    def X(self) -> np.ndarray:
        """Abscissa along the cable [m], shape (n,)."""
        return self.x * self._scales().L

    @property
    def Y(self) -> np.ndarray:
        """Height above the bottom along the cable [m], shape (n,)."""
        return self.y * self._scales().L

    @property
    def T(self) -> np.ndarray:
        """Cable tension [N], shape (n,)."""
        return self.tau * self._scales().force

    @property
    def T_line(self) -> float:
        """Tension of the line AC [N]."""
        return self.tau_line * self._scales().force


class _NotConverged(Exception):
    """One attempt failed; the message says why. Caught by the fallback driver."""


def _shoot(groups, alpha0, tau0, sigma_eval=None, rtol=SHOOT_RTOL):
    """Integrate eqs. (10)-(11) from A with ``x = y = 0`` at A.

    Returns the ``solve_ivp`` result; raises :class:`_NotConverged` if the tension
    falls to ``TAU_MIN`` (the cable would go slack) or the integration fails.
    """
    if not tau0 > TAU_MIN:
        raise _NotConverged(f"tau0 = {tau0:.4g} is not positive")

    def slack(sigma, z, g):
        return z[1] - TAU_MIN

    slack.terminal, slack.direction = True, -1
    sol = solve_ivp(cable_rhs, (0.0, 1.0), [alpha0, tau0, 0.0, 0.0], method="DOP853",
                    t_eval=sigma_eval, rtol=rtol, atol=SHOOT_ATOL * rtol / SHOOT_RTOL,
                    events=slack, args=(groups,))
    if sol.status == 1:
        raise _NotConverged(f"cable goes slack (tau -> 0) at sigma = {sol.t_events[0][0]:.3f}")
    if sol.status != 0:
        raise _NotConverged(f"integration failed: {sol.message}")
    return sol


def _profile_from_shot(groups, convention, alpha0, tau0, n_nodes, method, info=""):
    """A :class:`SphereSolution` from one shot, shifted so that B is the origin."""
    sigma = np.linspace(0.0, 1.0, n_nodes)
    sol = _shoot(groups, alpha0, tau0, sigma)
    alpha, tau, x, y = sol.y
    x, y = x - x[-1], y - y[-1]
    eps1, eps2 = sphere_residuals(groups, convention, alpha0, tau0, x[0], y[0])
    return SphereSolution(groups, convention, method, float(alpha0), float(tau0), eps1, eps2,
                          sigma, alpha, tau, x, y, info=info)


def shoot_sphere(groups, alpha0, tau0, convention="published", n_nodes=101):
    """One shot from A with given ``(alpha0 [rad], tau0)``: shape and residuals.

    This is the paper's own procedure (its figs. 2, 3) without the root finding;
    the returned solution has ``method="single shot"`` and whatever residuals result.
    """
    try:
        return _profile_from_shot(groups, convention, alpha0, tau0, n_nodes, "single shot")
    except _NotConverged as exc:
        raise SolverError(f"shot from alpha0 = {np.degrees(alpha0):.3f} deg, tau0 = {tau0}: "
                          f"{exc}; increase tau0") from None


def _shooting_residual(p, groups, convention):
    """``(eps1, eps2) / 100`` after a shot from ``p = (alpha0, tau0)``."""
    sol = _shoot(groups, p[0], p[1])
    x_A, y_A = -sol.y[2, -1], -sol.y[3, -1]
    return np.array(sphere_residuals(groups, convention, p[0], p[1], x_A, y_A)) / 100.0


def _solve_shooting(groups, convention, guess, n_nodes):
    """Shooting: root of the residuals in ``(alpha0, tau0)`` by MINPACK's hybrd."""
    _shooting_residual(np.asarray(guess, float), groups, convention)  # guess must shoot

    def fun(p):
        try:
            return _shooting_residual(p, groups, convention)
        except _NotConverged:
            return np.full(2, 1e3)  # a failed shot reads as a bad step: hybrd shrinks it

    sol = root(fun, np.asarray(guess, float), method="hybr", options={"xtol": 1e-13})
    profile = _profile_from_shot(groups, convention, *sol.x, n_nodes, "shooting")
    worst = max(abs(profile.eps1_percent), abs(profile.eps2_percent))
    if not worst < RESIDUAL_TOL_PERCENT:
        message = " ".join(sol.message.split())
        raise _NotConverged(f"root finding stopped with |eps| = {worst:.2e} % ({message})")
    return replace(profile, info=f"{sol.nfev} shots")


def _bvp_guess(groups, guess, sigma):
    """Initial profile for solve_bvp: a loose shot from the guess, else a straight chord."""
    try:
        z = _shoot(groups, guess[0], guess[1], sigma, rtol=1e-6).y.copy()
        if z.shape[1] != sigma.size:
            raise _NotConverged("short shot")
    except _NotConverged:
        z = np.empty((4, sigma.size))
        z[0], z[1] = guess[0], guess[1]
        z[2], z[3] = np.cos(guess[0]) * sigma, -np.sin(guess[0]) * sigma
    z[2] -= z[2, -1]
    z[3] -= z[3, -1]
    return z


def _solve_collocation(groups, convention, guess, n_nodes):
    """Collocation: solve_bvp on eqs. (10)-(11) with ``x(1) = y(1) = eps1 = eps2 = 0``."""
    def bc(za, zb):
        eps = sphere_residuals(groups, convention, za[0], za[1], za[2], za[3])
        return np.array([zb[2], zb[3], eps[0] / 100.0, eps[1] / 100.0])

    mesh = np.linspace(0.0, 1.0, 41)
    sol = solve_bvp(lambda s, z: cable_rhs(s, z, groups), bc, mesh, _bvp_guess(groups, guess, mesh),
                    tol=BVP_TOL, bc_tol=BVP_TOL, max_nodes=BVP_MAX_NODES)
    if sol.status != 0:
        raise _NotConverged(f"solve_bvp: {sol.message}")
    if sol.y[1].min() <= 10 * TAU_MIN:
        raise _NotConverged(f"slack cable (min tau = {sol.y[1].min():.2e})")
    sigma = np.linspace(0.0, 1.0, n_nodes)
    alpha, tau, x, y = sol.sol(sigma)
    alpha[0], tau[0], x[0], y[0] = sol.y[:, 0]  # the nodal values at A, exactly
    eps1, eps2 = sphere_residuals(groups, convention, alpha[0], tau[0], x[0], y[0])
    return SphereSolution(groups, convention, "collocation", float(alpha[0]), float(tau[0]),
                          eps1, eps2, sigma, alpha, tau, x, y,
                          info=f"{sol.x.size} mesh nodes, {sol.niter} iterations")


#: Solvers by name: ``fn(groups, convention, guess, n_nodes) -> SphereSolution``.
METHODS = {"shooting": _solve_shooting, "collocation": _solve_collocation}


def chord_guess(groups, convention="published"):
    """Cheap ``(alpha0 [rad], tau0)``: a straight cable of chord 1 from A to B.

    A is where the circles ``|A - B| = 1`` and ``|A - C| = LoL`` meet above the
    bottom; ``tau0`` balances the sphere with a straight cable and a taut line
    (falls back to the sphere's load ``sqrt(QkL^2 + RkL^2)`` if that gives tau0 <= 0).
    """
    x_a = (1.0 - groups.LoL**2 + groups.x_C**2) / (2.0 * groups.x_C)
    y_a = np.sqrt(max(1.0 - x_a**2, 1e-6))
    alpha0 = float(np.arctan2(y_a, -x_a))
    t = np.array([np.cos(alpha0), -np.sin(alpha0)])
    u = np.array([groups.x_C - x_a, -y_a]) / np.hypot(groups.x_C - x_a, y_a)
    load = np.array([_convention_sign(convention) * groups.RkL, groups.QkL])
    try:
        tau0 = float(np.linalg.solve(np.column_stack([t, u]), -load)[0])
    except np.linalg.LinAlgError:
        tau0 = 0.0
    return alpha0, (tau0 if tau0 > 0 else float(np.hypot(groups.QkL, groups.RkL)))


def _blend(start, end, lam):
    """Groups ``(1 - lam) start + lam end``, field by field."""
    return SphereGroups(**{f.name: (1 - lam) * getattr(start, f.name) + lam * getattr(end, f.name)
                           for f in fields(SphereGroups)})


def _continuation(groups, convention, solve, n_nodes):
    """Step from the paper's case 1 (known answer) to ``groups`` in lambda in [0, 1].

    The step grows by 1.5 after a success and halves after a failure; each step starts
    from the previous converged ``(alpha0, tau0)``.
    """
    current = solve(PAPER_CASE_1, convention, _REFERENCE_ANSWER[convention], n_nodes)
    lam, step, n_steps = 0.0, CONTINUATION_STEP, 0
    while lam < 1.0:
        trial = min(1.0, lam + step)
        try:
            current = solve(_blend(PAPER_CASE_1, groups, trial), convention,
                            (current.alpha0, current.tau0), n_nodes)
        except (_NotConverged, CaseError) as exc:
            step /= 2
            if step < CONTINUATION_MIN_STEP:
                raise _NotConverged(f"continuation from the paper's case 1 stalled at "
                                    f"lambda = {lam:.4f} ({exc})") from None
            continue
        lam, step, n_steps = trial, min(1.5 * step, 0.5), n_steps + 1
    return replace(current, info=f"continuation from the paper's case 1 in {n_steps} steps; "
                                 + current.info)


def _quiet(solve):
    """``solve`` with floating-point warnings off: failed iterates may overflow, and
    every result is checked by its residuals instead."""
    def wrapped(*args):
        with np.errstate(all="ignore"):
            return solve(*args)
    return wrapped


def _candidate_guesses(groups, convention, initial_guess):
    """Named ``(alpha0, tau0)`` guesses to try in turn before continuation."""
    out = [] if initial_guess is None else [("the given initial guess", tuple(initial_guess))]
    out.append(("the paper's case-1 answer", _REFERENCE_ANSWER[convention]))
    out.append(("the straight-chord guess", chord_guess(groups, convention)))
    return out


def solve_sphere(groups, convention="published", method="shooting", n_nodes=101,
                 initial_guess=None, scales=None) -> SphereSolution:
    """Equilibrium of the sphere on two cables (SPEC §3.2, paper eqs. 10-19).

    Parameters
    ----------
    groups : SphereGroups
        Dimensionless groups (eq. 16).
    convention : {"published", "physical"}
        Direction of the sphere's drag, see the module docstring.
    method : {"shooting", "collocation"}
        Solver, see :data:`METHODS`.
    n_nodes : int
        Number of output stations along ``sigma``, uniform on [0, 1].
    initial_guess : tuple of float, optional
        ``(alpha0 [rad], tau0)``. Tried first; then the paper's case-1 answer, the
        straight-chord guess (:func:`chord_guess`), and continuation from case 1.
    scales : SphereScales, optional
        Attached to the solution for the SI properties ``s, X, Y, T, T_line``.

    Returns
    -------
    SphereSolution
        Residuals below ``RESIDUAL_TOL_PERCENT`` (1e-7 %).

    Raises
    ------
    SolverError
        When every guess and the continuation fail; the message lists each attempt.
    """
    _convention_sign(convention)
    if n_nodes < 2:
        raise ValueError(f"n_nodes must be >= 2, got {n_nodes}")
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; valid: {sorted(METHODS)}")
    solve, tried = _quiet(METHODS[method]), []
    for label, guess in _candidate_guesses(groups, convention, initial_guess):
        try:
            sol = solve(groups, convention, guess, n_nodes)
            return replace(sol, scales=scales, info=f"from {label}; {sol.info}")
        except _NotConverged as exc:
            tried.append(f"{label} (alpha0 = {np.degrees(guess[0]):.2f} deg, "
                         f"tau0 = {guess[1]:.4g}): {exc}")
    try:
        return replace(_continuation(groups, convention, solve, n_nodes), scales=scales)
    except _NotConverged as exc:
        tried.append(str(exc))
    raise SolverError(
        f"{method} found no equilibrium for {groups} ({convention} convention). Tried:\n  "
        + "\n  ".join(tried) + "\nPass initial_guess=(alpha0_rad, tau0) from a converged "
        "neighbour (e.g. sweep_flow_speed from a speed that converges) or try the other "
        f"method. Check that the sphere can hold the cable up: buoyancy QkL = {groups.QkL:.4g} "
        f"against cable weight Psi = {groups.Psi:.4g} (this model has no seabed contact).")


def sweep_flow_speed(speeds, *, sphere_diameter, net_buoyancy, cable_diameter, cable_length,
                     cable_weight, line_length, anchor_x, water_density=1025.0, c_90=1.2,
                     c_0=0.04, c_u=0.44, convention="published", method="shooting",
                     n_nodes=101) -> list[SphereSolution]:
    """Equilibria over flow speeds, each solved from the previous one's answer.

    Parameters
    ----------
    speeds : array_like, shape (m,)
        Flow speeds ``V`` [m/s] in the order to visit them (sorted is best).
    sphere_diameter, ..., c_u
        As in :func:`groups_from_dimensional`.
    convention, method, n_nodes
        As in :func:`solve_sphere`.

    Returns
    -------
    list of SphereSolution, length m
        With scales, so ``T``, ``X``, ``Y`` are in SI.
    """
    out, guess = [], None
    for speed in np.asarray(speeds, float):
        groups, scales = groups_from_dimensional(
            speed, sphere_diameter, net_buoyancy, cable_diameter, cable_length, cable_weight,
            line_length, anchor_x, water_density=water_density, c_90=c_90, c_0=c_0, c_u=c_u)
        sol = solve_sphere(groups, convention, method, n_nodes, initial_guess=guess,
                           scales=scales)
        out.append(sol)
        guess = (sol.alpha0, sol.tau0)
    return out
