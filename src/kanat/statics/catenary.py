"""Closed-form elastic catenary, with an optional horizontal frictionless seabed.

A uniform line of weight in water ``w`` per unstretched length and axial
stiffness ``EA`` hangs between a lower end at the origin and an upper end at
``(span, rise)``, with no current. The horizontal tension ``H`` is constant and the
vertical tension grows linearly along the unstretched arclength ``s``, measured
here from the **lower** end: ``V(s) = V_L + w s``, ``T = sqrt(H^2 + V^2)``.
Integrating ``dx/ds = (1 + T/EA) H/T``, ``dz/ds = (1 + T/EA) V/T`` gives the elastic
catenary (Irvine 1981, *Cable Structures*; the quasi-static mooring line of
Jonkman 2007, NREL/TP-500-41958, used by FAST, MoorDyn, MoorPy and MAP++):

fully suspended, ``V_L = V_U - w L``::

    (1)  x_U = H/w [asinh(V_U/H) - asinh(V_L/H)] + H L/EA
    (2)  z_U = H/w [sqrt(1 + (V_U/H)^2) - sqrt(1 + (V_L/H)^2)] + (V_U L - w L^2/2)/EA

partly on a frictionless seabed, grounded length ``L_B = L - V_U/w``, ``V_L = 0``::

    (3)  x_U = L_B + H/w asinh(V_U/H) + H L/EA
    (4)  z_U = H/w [sqrt(1 + (V_U/H)^2) - 1] + V_U^2/(2 EA w)
    (5)  x(s) = s (1 + H/EA),  z(s) = 0,  T(s) = H      on the seabed, s <= L_B

(3)-(4) are (1)-(2) applied to the suspended part, started at ``x = L_B (1 + H/EA)``.
They are evaluated in forms that stay accurate when ``H -> 0`` (near-vertical
lines) and when the line is nearly straight, with ``V_0 = V(0)``, ``T_0 = T(0)``::

    (6)  H/w [sqrt(1 + (V/H)^2) - sqrt(1 + (V_0/H)^2)] = (T - T_0)/w = s (V + V_0)/(T + T_0)
    (7)  asinh(V/H) - asinh(V_0/H) = asinh(w s (V + V_0)/(V T_0 + V_0 T))   (V, V_0 of one sign)

The end tensions ``(H, V_U)`` solve (1)-(2) or (3)-(4) by Newton's method with the
analytic Jacobian, in the dimensionless unknowns ``(log(H/(w L)), V_U/(w L))``. The
seabed regime is chosen by the iterate (grounded while ``V_U < w L``); the two
regimes join with a continuous Jacobian at touchdown, so Newton crosses it freely.
Where Newton struggles (nearly taut, nearly vertical lines), a bracketed solve of
the same equations as two nested monotone 1-D problems takes over. Edge cases with
``H = 0`` (vertical lines, a line slack on the seabed) are solved in closed form,
as in MoorPy (Hall et al. 2024, Energies 17, 3155).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import SolverError

__all__ = ["CatenarySolution", "catenary_profile", "elastic_catenary"]

MAX_NEWTON_ITERATIONS = 30     # 2-D Newton converges in < 15 from the guess below when it works
MAX_LOG_STEP = 4.0             # cap on a step in log(H): at most a factor e^4 ~ 55 per iteration
MAX_HALVINGS = 8               # more halvings than this: too nonlinear, hand over to _nested_solve
MAX_BRACKETED_ITERATIONS = 200 # safeguarded 1-D Newton: halves the bracket at worst, 200 >> 2 x 53 bits
STEP_TOLERANCE = 1e-13         # relative change of (H, V_U) at which Newton has converged
RESIDUAL_TOLERANCE = 1e-9      # end-position error accepted after convergence, relative to
                               # the target coordinate (floored at POSITION_FLOOR L)
POSITION_FLOOR = 1e-6          # so coordinates below 1e-6 L are held to 1e-15 L, the round-off
                               # of z(V_U) when rise << L (and of x(H) when span << L)
MIN_LOG_H = -690.0             # log(H/(w L)) floor: e^-690 ~ 1e-300, keeps asinh(V/H) finite
MAX_LOG_H = 690.0              # and ceiling, keeps exp() finite
TAUT_GUESS_LAMBDA = 0.2        # Peyrot & Goulois (1979) catenary parameter for a taut line
SLACK_LIMIT_TOLERANCE = 1e-12  # a span within this (relative) of the H = 0 seabed limit is at it


@dataclass(frozen=True, eq=False)
class CatenarySolution:
    """Elastic catenary between a lower end at the origin and an upper end.

    Attributes
    ----------
    horizontal_tension : float
        ``H`` [N], constant along the suspended part and the frictionless grounded part.
    vertical_tension_upper : float
        ``V_U`` [N], vertical component of the tension at the upper end (positive
        when the line rises into the end).
    vertical_tension_lower : float
        ``V_L`` [N] at the lower end: 0 when part of the line is grounded, negative
        when the lowest point lies between the ends.
    grounded_length : float
        Unstretched length resting on the seabed [m], 0 if none.
    s : ndarray, shape (n,)
        Unstretched arclength from the lower end (0) to the upper end (``length``) [m].
    x, z : ndarray, shape (n,)
        Position of the points ``s`` [m], lower end at the origin.
    tension : ndarray, shape (n,)
        Effective tension magnitude at ``s`` [N].

    Notes
    -----
    On a seabed, a line with ``span <= L - l`` (``l`` the length that hangs vertically
    over the rise) has ``H = 0``: it hangs vertically and lies slack on the seabed.
    At ``span = L - l`` the grounded part is straight; below, it is drawn bunched
    at the touchdown point ``x = span`` with zero tension.
    """

    horizontal_tension: float
    vertical_tension_upper: float
    vertical_tension_lower: float
    grounded_length: float
    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    tension: np.ndarray

    @property
    def tension_upper(self) -> float:
        """Tension magnitude at the upper end, ``sqrt(H^2 + V_U^2)`` [N]."""
        return math.hypot(self.horizontal_tension, self.vertical_tension_upper)

    @property
    def tension_lower(self) -> float:
        """Tension magnitude at the lower end, ``sqrt(H^2 + V_L^2)`` [N]."""
        return math.hypot(self.horizontal_tension, self.vertical_tension_lower)

    @property
    def suspended_length(self) -> float:
        """Unstretched length off the seabed [m]."""
        return float(self.s[-1]) - self.grounded_length


# --------------------------------------------------------------------------- profile

def _suspended_offsets(length, horizontal_tension, vertical_tension_start, weight, axial_stiffness):
    """Offsets ``(dx, dz)`` and vertical tension along a suspended catenary segment.

    Module eqs. (1)-(2) from a point with vertical tension ``V_0``, in the
    cancellation-free forms (6)-(7), with ``V = V_0 + w l``, ``T = sqrt(H^2 + V^2)``::

        dx = H/w asinh((V^2 - V_0^2) / (V T_0 + V_0 T)) + H l/EA   (V, V_0 of one sign)
        dx = H/w [asinh(V/H) - asinh(V_0/H)]           + H l/EA   (otherwise)
        dz = l (V + V_0)/(T + T_0)                     + l (V + V_0)/(2 EA)

    Parameters
    ----------
    length : ndarray, shape (n,)
        Unstretched length ``l >= 0`` from the segment start [m].
    horizontal_tension, vertical_tension_start, weight, axial_stiffness : float
        ``H >= 0``, ``V_0``, ``w > 0`` [N/m], ``EA`` [N] (``inf`` allowed).

    Returns
    -------
    dx, dz, vertical_tension : ndarray, shape (n,)
    """
    H, V0, w, EA = horizontal_tension, vertical_tension_start, weight, axial_stiffness
    l = length
    V = V0 + w * l
    T, T0 = np.hypot(H, V), math.hypot(H, V0)
    zero = np.zeros_like(l)
    dz = np.divide(l * (V + V0), T + T0, out=zero.copy(), where=(T + T0) > 0) + l * (V + V0) / (2.0 * EA)
    if H == 0.0:
        return zero, dz, V
    one_sign = (V0 >= 0.0) | (V <= 0.0)
    denominator = V * T0 + V0 * T
    ratio = np.divide(w * l * (V + V0), denominator, out=zero.copy(), where=one_sign & (denominator != 0))
    angle = np.where(one_sign, np.arcsinh(ratio), np.arcsinh(V / H) - math.asinh(V0 / H))
    dx = H / w * angle + H * l / EA
    return dx, dz, V


def catenary_profile(s, horizontal_tension, vertical_tension_lower, weight, axial_stiffness,
                     grounded_length=0.0):
    """Position and tension of an elastic catenary at unstretched arclengths ``s``.

    Module eqs. (1)-(2) along the suspended part and (5) along a taut frictionless
    grounded part ``0 <= s <= L_B``.

    Parameters
    ----------
    s : array_like, shape (n,)
        Unstretched arclength from the lower end [m], ``s >= 0``.
    horizontal_tension : float
        ``H >= 0`` [N].
    vertical_tension_lower : float
        ``V_L`` [N] at ``s = 0``; must be 0 when ``grounded_length > 0``.
    weight : float
        Weight in water per unstretched length ``w > 0`` [N/m].
    axial_stiffness : float
        ``EA > 0`` [N]; ``np.inf`` for an inextensible line.
    grounded_length : float, optional
        Unstretched length ``L_B`` resting on the seabed [m].

    Returns
    -------
    x, z, tension : ndarray, shape (n,)
        Horizontal and vertical position [m] (lower end at the origin) and tension [N].
    """
    if grounded_length > 0.0 and vertical_tension_lower != 0.0:
        raise ValueError(f"vertical_tension_lower must be 0 when grounded_length > 0 "
                         f"(got {vertical_tension_lower} N with {grounded_length} m grounded)")
    s = np.asarray(s, dtype=float)
    H, EA = float(horizontal_tension), float(axial_stiffness)
    suspended = np.maximum(s - grounded_length, 0.0)
    dx, dz, V = _suspended_offsets(suspended, H, float(vertical_tension_lower), float(weight), EA)
    on_seabed = s < grounded_length
    x = np.where(on_seabed, s, grounded_length) * (1.0 + H / EA) + np.where(on_seabed, 0.0, dx)
    z = np.where(on_seabed, 0.0, dz)
    return x, z, np.hypot(H, V)


# --------------------------------------------------------------------------- end conditions

def _end_position(h, v, stretch, seabed):
    """Dimensionless upper-end position and its Jacobian.

    All quantities scaled by the line: ``h = H/(w L)``, ``v = V_U/(w L)``,
    ``stretch = w L/EA``, positions divided by ``L``. Module eqs. (1)-(2) with (6)-(7),
    or (3)-(4) when ``seabed`` and ``v < 1``.

    Returns
    -------
    x, z : float
    jacobian : tuple of 4 floats
        ``(dx/dh, dx/dv, dz/dh, dz/dv)``; the matrix is symmetric (``dx/dv = dz/dh``).
    """
    t_upper = math.hypot(h, v)
    if seabed and v < 1.0:
        angle = math.asinh(v / h)
        x = (1.0 - v) + h * angle + h * stretch
        z = v * v / (t_upper + h) + 0.5 * stretch * v * v
        cross = -v * v / (t_upper * (t_upper + h))                     # h/T_U - 1
        return x, z, (angle - v / t_upper + stretch, cross, cross, v / t_upper + stretch * v)
    v_lower = v - 1.0
    t_lower = math.hypot(h, v_lower)
    if v_lower >= 0.0 or v <= 0.0:
        angle = math.asinh((v + v_lower) / (v * t_lower + v_lower * t_upper))
    else:
        angle = math.asinh(v / h) + math.asinh(-v_lower / h)
    x = h * angle + h * stretch
    z = (2.0 * v - 1.0) / (t_upper + t_lower) + stretch * (v - 0.5)
    cross = -h * (2.0 * v - 1.0) / (t_upper * t_lower * (t_upper + t_lower))  # h/T_U - h/T_L
    slope = v / t_upper - v_lower / t_lower
    return x, z, (angle - slope + stretch, cross, cross, slope + stretch)


def _initial_guess(span, rise, stretch):
    """Dimensionless ``(h, v)`` to start Newton (Peyrot & Goulois 1979, as in MoorPy).

    ``lambda = sqrt(3 ((1 - rise^2)/span^2 - 1))`` for a slack line, 0.2 for a taut
    one; ``h = span/(2 lambda)``, ``v = (rise/tanh(lambda) + 1)/2``. A stretched line
    (chord longer than the line) starts instead from the tension that stretches the
    straight chord, which can be many orders of magnitude larger.
    """
    chord = math.hypot(span, rise)
    if chord >= 1.0:
        lam = TAUT_GUESS_LAMBDA
    else:
        lam = math.sqrt(3.0 * ((1.0 - rise * rise) / (span * span) - 1.0))
    h = max(0.5 * span / lam, math.exp(MIN_LOG_H))
    v = 0.5 * (rise / math.tanh(lam) + 1.0)
    if chord > 1.0 and stretch > 0.0:
        tension = (chord - 1.0) / stretch
        h = max(h, tension * span / chord)
        v = max(v, tension * rise / chord + 0.5)
    return h, v


def _relative_error(x, z, span, rise):
    """Largest end-position error relative to its target (floored at POSITION_FLOOR L)."""
    return max(abs(x - span) / max(span, POSITION_FLOOR), abs(z - rise) / max(rise, POSITION_FLOOR))


def _newton(span, rise, stretch, seabed):
    """Solve the end conditions for dimensionless ``(h, v)``; None if Newton fails.

    Unknowns ``(log h, v)`` keep ``H > 0``; steps are capped in ``log h``, kept at
    ``v > 0`` (``V_U > 0`` whenever ``rise >= 0``) and halved until the squared
    end-position error (in line lengths) decreases. Converged when the Newton step
    would change ``H`` and ``V_U`` by less than STEP_TOLERANCE relative.
    """
    h, v = _initial_guess(span, rise, stretch)
    u = math.log(h)
    x, z, jac = _end_position(h, v, stretch, seabed)
    merit = (x - span) ** 2 + (z - rise) ** 2
    for _ in range(MAX_NEWTON_ITERATIONS):
        a, b, c, d = jac[0] * h, jac[1], jac[2] * h, jac[3]             # d/d(log h), d/dv
        det = a * d - b * c
        if det == 0.0 or not math.isfinite(det):
            break
        fx, fz = x - span, z - rise
        du, dv = (-d * fx + b * fz) / det, (c * fx - a * fz) / det
        if abs(du) <= STEP_TOLERANCE and abs(dv) <= STEP_TOLERANCE * max(1.0, abs(v)):
            break                                                       # converged to round-off
        scale = min(1.0, MAX_LOG_STEP / abs(du)) if du != 0.0 else 1.0
        if v + scale * dv <= 0.0:
            scale = 0.9 * v / -dv
        for _ in range(MAX_HALVINGS):
            u_try, v_try = min(max(u + scale * du, MIN_LOG_H), MAX_LOG_H), v + scale * dv
            h_try = math.exp(u_try)
            x_try, z_try, jac_try = _end_position(h_try, v_try, stretch, seabed)
            merit_try = (x_try - span) ** 2 + (z_try - rise) ** 2
            if merit_try <= merit:
                break
            scale *= 0.5
        else:
            break                                                       # stalled, at round-off or lost
        u, v, h, x, z, jac, merit = u_try, v_try, h_try, x_try, z_try, jac_try, merit_try
    return (h, v) if _relative_error(x, z, span, rise) <= RESIDUAL_TOLERANCE else None


def _bracketed_root(function, low, high, start):
    """Root of an increasing function by Newton's method safeguarded by bisection.

    ``function(p)`` returns ``(f, df/dp, extra)``; ``f(low) < 0 < f(high)``. Returns
    ``(p, extra)`` at the root, to round-off.
    """
    p = min(max(start, low), high)
    for _ in range(MAX_BRACKETED_ITERATIONS):
        f, slope, extra = function(p)
        if f == 0.0:
            break
        if f < 0.0:
            low = p
        else:
            high = p
        step = -f / slope if slope > 0.0 else math.inf
        if low < p + step < high:
            p_next = p + step
        else:
            p_next = 0.5 * (low + high)
        if abs(p_next - p) <= STEP_TOLERANCE * max(1.0, abs(p)) or not low < p_next < high:
            break
        p = p_next
    return p, extra


def _expand_bracket(function, start, step, limit):
    """Walk from ``start`` by ``step`` until ``function(p)[0]`` changes sign; None if it never does."""
    sign = function(start)[0] > 0.0
    previous, p = start, start
    while (step > 0.0 and p < limit) or (step < 0.0 and p > limit):
        previous, p = p, min(p + step, limit) if step > 0.0 else max(p + step, limit)
        if (function(p)[0] > 0.0) != sign:
            return (previous, p) if step > 0.0 else (p, previous)
    return None


def _nested_solve(span, rise, stretch, seabed):
    """Fallback: the end conditions as two nested monotone 1-D problems; None on failure.

    For fixed ``h``, ``z_U`` increases with ``v`` (``dz/dv = V_U/T_U - V_L/T_L + w L/EA > 0``)
    and is negative at ``v = 0`` (suspended) or zero (grounded), so ``v(h)`` is bracketed.
    Along ``v(h)``, ``x_U`` increases with ``h`` (``dx/dh = det J / (dz/dv)``, the
    flexibility matrix ``J`` being positive definite), from its ``H -> 0`` limit
    (0, or ``1 - hanging length`` on a seabed) upwards, so ``h`` is bracketed as well.
    Slower than :func:`_newton` but cannot wander off.
    """
    def rise_error(h):
        def z_error(v):
            x, z, jac = _end_position(h, v, stretch, seabed)
            return z - rise, jac[3], (x, z, jac)
        high = 1.0
        while z_error(high)[0] < 0.0:
            high *= 2.0
        return _bracketed_root(z_error, 0.0, high, high)

    def span_error(u):
        h = math.exp(u)
        v, (x, z, jac) = rise_error(h)
        return x - span, h * (jac[0] - jac[1] * jac[2] / jac[3]), (h, v, x, z)

    u0 = math.log(_initial_guess(span, rise, stretch)[0])
    going_up = span_error(u0)[0] < 0.0
    bracket = _expand_bracket(span_error, u0, MAX_LOG_STEP if going_up else -MAX_LOG_STEP,
                              MAX_LOG_H if going_up else MIN_LOG_H)
    if bracket is None:
        return None
    _, (h, v, x, z) = _bracketed_root(span_error, *bracket, u0)
    return (h, v) if _relative_error(x, z, span, rise) <= RESIDUAL_TOLERANCE else None


# --------------------------------------------------------------------------- special cases

def _hanging_length(rise, stretch):
    """Dimensionless unstretched length hanging vertically to reach ``rise``.

    Root of ``l + stretch l^2/2 = rise`` (module eq. (4) with ``H = 0``), written
    without cancellation.
    """
    return 2.0 * rise / (1.0 + math.sqrt(1.0 + 2.0 * stretch * rise))


def _vertical_tension_when_vertical(rise, stretch):
    """Dimensionless ``v`` of a suspended vertical line (``span = 0``, ``H = 0``).

    Taut (``V_L >= 0``): ``rise = 1 + stretch (v - 1/2)``. Folded (lowest point between
    the ends, both parts hanging down, ``V_L < 0``): the two arms differ in length by
    ``rise/(1 + stretch/2)``. An inextensible line exactly as long as the rise is
    taken as hanging from the top (``V_L = 0``), the limit of the folded branch.
    """
    if rise <= 1.0 + 0.5 * stretch:
        return 0.5 * (1.0 + rise / (1.0 + 0.5 * stretch))
    return 0.5 + (rise - 1.0) / stretch                    # stretch > 0: the caller checked


def _solution(H, V_upper, V_lower, grounded, length, weight, axial_stiffness, n_points):
    """Package end tensions with the profile sampled at ``n_points`` even steps of ``s``."""
    s = np.linspace(0.0, length, n_points)
    x, z, tension = catenary_profile(s, H, V_lower, weight, axial_stiffness, grounded)
    return CatenarySolution(H, V_upper, V_lower, grounded, s, x, z, tension)


def _slack_on_seabed(span, length, weight, axial_stiffness, hanging, n_points):
    """``H = 0``: vertical hang of ``hanging`` metres, rest on the seabed, bunched if slack."""
    V_upper = weight * hanging
    solution = _solution(0.0, V_upper, 0.0, length - hanging, length, weight, axial_stiffness, n_points)
    np.minimum(solution.x, span, out=solution.x)      # the grounded part lies slack up to touchdown
    return solution


def _check_inputs(span, rise, length, weight, axial_stiffness, n_points):
    checks = {"span": span >= 0.0, "rise": rise >= 0.0, "length": length > 0.0,
              "weight": weight > 0.0, "axial_stiffness": axial_stiffness > 0.0}
    values = {"span": span, "rise": rise, "length": length, "weight": weight,
              "axial_stiffness": axial_stiffness}
    for name, ok in checks.items():
        if not ok or (name != "axial_stiffness" and not math.isfinite(values[name])):
            raise ValueError(f"{name} = {values[name]!r} is not valid: span and rise must be finite and >= 0 "
                             "(swap the ends if the upper end is lower), length and weight finite and > 0, "
                             "axial_stiffness > 0 (inf for an inextensible line)")
    if n_points < 2:
        raise ValueError(f"n_points = {n_points} must be at least 2")


# --------------------------------------------------------------------------- solver

def elastic_catenary(span, rise, length, weight, axial_stiffness, seabed=False, n_points=101):
    """Elastic catenary through two points, optionally resting on a frictionless seabed.

    Solves the end conditions, module eqs. (1)-(2) or, on the seabed, (3)-(4), for
    ``(H, V_U)`` to round-off (~1e-13 relative), then samples the closed-form
    profile (:func:`catenary_profile`).

    Parameters
    ----------
    span : float
        Horizontal distance from the lower end to the upper end, ``>= 0`` [m].
    rise : float
        Height of the upper end above the lower end, ``>= 0`` [m].
    length : float
        Unstretched line length ``L`` [m].
    weight : float
        Weight in water per unstretched length ``w > 0`` [N/m].
    axial_stiffness : float
        ``EA > 0`` [N]; ``np.inf`` for an inextensible line.
    seabed : bool, optional
        If True, the lower end lies on a horizontal frictionless seabed at its own
        height and the line rests on it wherever a suspended line would dip below it.
    n_points : int, optional
        Number of profile points, evenly spaced in ``s``.

    Returns
    -------
    CatenarySolution

    Raises
    ------
    SolverError
        No equilibrium exists (inextensible line not longer than the chord) or the
        solver failed; the message gives the numbers.
    ValueError
        Inputs out of range.
    """
    span, rise, length = float(span), float(rise), float(length)
    weight, axial_stiffness = float(weight), float(axial_stiffness)
    _check_inputs(span, rise, length, weight, axial_stiffness, n_points)
    X, Z, stretch = span / length, rise / length, weight * length / axial_stiffness
    wL = weight * length
    args = (length, weight, axial_stiffness, n_points)
    if seabed:
        hanging = _hanging_length(Z, stretch)
        if hanging < 1.0 and X <= (1.0 - hanging) * (1.0 + SLACK_LIMIT_TOLERANCE):
            return _slack_on_seabed(span, length, weight, axial_stiffness, hanging * length, n_points)
        if Z == 0.0:                                            # straight, stretched along the seabed
            if stretch == 0.0:
                raise _no_solution(span, rise, length, "an inextensible line on the seabed cannot span more than its length")
            return _solution((X - 1.0) / stretch * wL, 0.0, 0.0, length, *args)
    chord = math.hypot(X, Z)
    if stretch == 0.0 and (chord > 1.0 or (chord == 1.0 and X > 0.0)):
        raise _no_solution(span, rise, length, "an inextensible line must be longer than the chord")
    if X == 0.0:
        v = _vertical_tension_when_vertical(Z, stretch)
        return _solution(0.0, v * wL, (v - 1.0) * wL, 0.0, *args)
    root = _newton(X, Z, stretch, seabed) or _nested_solve(X, Z, stretch, seabed)
    if root is None:
        raise SolverError(
            f"elastic catenary did not converge for span={span:.9g} m, rise={rise:.9g} m, length={length:.9g} m, "
            f"weight={weight:.9g} N/m, axial_stiffness={axial_stiffness:.9g} N, seabed={seabed} "
            f"(2-D Newton and the bracketed nested solve both failed); check that the inputs are what you meant")
    h, v = root
    if seabed and v < 1.0:
        return _solution(h * wL, v * wL, 0.0, (1.0 - v) * length, *args)
    return _solution(h * wL, v * wL, (v - 1.0) * wL, 0.0, *args)


def _no_solution(span, rise, length, reason):
    chord = math.hypot(span, rise)
    return SolverError(f"no catenary exists: {reason} (span={span:.9g} m, rise={rise:.9g} m, "
                       f"chord={chord:.9g} m, length={length:.9g} m); give a finite axial_stiffness "
                       "or a longer line")
