"""Naumov & Agievich: a sphere held by two cables in a uniform flow (theory/statics.md §3).

Naumov & Agievich, "Numerical solution of the boundary-value problem of the
equilibrium of a spherical body on cables in a uniform stream" (Naumov & Agievich).

The problem
-----------
Sphere A (diameter ``D``, net buoyancy ``Q``) is held by a weightless straight line
AC (length ``L0``, anchor C at ``(X_C, 0)``) and a heavy cable AOB (length ``L``,
weight ``q`` per metre in water, diameter ``delta``) anchored at B, the origin.
``y`` is the height above the bottom. The arclength ``sigma = S/L`` runs from A
(0) to B (1), ``alpha`` is the local cable angle, with unit tangent and normal

    t = (cos alpha, -sin alpha),     n = (sin alpha, cos alpha).

Dimensionless equations (paper eqs. 10, 11, 14, 15 as corrected in theory/statics.md §3)::

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
corrected in theory/statics.md §3) but is not physically consistent. ``convention="physical"``
takes ``s_R = +1``: cable and sphere feel the same flow. The projection along ``u``
gives the line tension ``tau_AC = -F . u`` (:func:`forces_on_sphere`).

Residuals (paper eqs. 18, 19), both in percent; the paper accepts ``|eps| < 0.01 %``::

    eps1 = 100 (1 - sqrt(y_A^2 + (x_C - x_A)^2) / LoL)

``eps2`` as above. Note: theory/statics.md §3 prints the numerator of ``eps2`` with the opposite
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

from dataclasses import dataclass, fields

import numpy as np

from kanat.errors import CaseError, Problem

#: Sign of the sphere's drag along x, by convention (see the module docstring).
SPHERE_DRAG_SIGN = {"published": -1.0, "physical": +1.0}
#: The paper's acceptance criterion for both residuals [%].
PAPER_CRITERION_PERCENT = 0.01
#: Smallest tension allowed while integrating: the alpha equation divides by tau.
TAU_MIN = 1e-6


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


def convention_sign(convention: str) -> float:
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
    drag = np.array([convention_sign(convention) * groups.RkL, 0.0])
    to_c = np.array([groups.x_C - x_A, -y_A])
    u = to_c / np.hypot(*to_c)
    line_tension = -float(np.dot(cable + buoyancy + drag, u))
    return SphereForces(cable, buoyancy, drag, line_tension * u, line_tension)


def sphere_residuals(groups, convention, alpha0, tau0, x_A, y_A):
    """Residuals ``(eps1, eps2)`` in percent (eqs. 18, 19; module docstring for the sign)."""
    s_r = convention_sign(convention)
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
