"""Solving one line's end conditions: the end tensions ``(H, V_B)`` that put end B at
``(span, rise)`` from end A (:mod:`kanat.statics.piecewise`, eqs. 1-3), and the line's
stiffness there.

Newton's method on ``x(H, V_B) = span``, ``z(H, V_B) = rise`` with the exact Jacobian, in
the unknowns ``(log H, V_B)`` (``H`` stays positive), steps halved until the end-position
error falls, from the caller's warm start or from Peyrot & Goulois' guess (1979; as in
MoorPy and :mod:`kanat.statics.catenary`). Where Newton fails, the same equations are
solved as two nested monotone 1-D problems (``z`` grows with ``V_B`` at fixed ``H``, and
``x`` with ``H`` along that curve), slower but bracketed. Two limits are closed: a vertical
line (``span = 0``, ``H = 0``) and, on a seabed, a line so slack that it hangs vertically
to the seabed and lies there without tension (``H = 0``; MoorPy's profile type 4).

The stiffness of end B, ``K = d(H, V_B)/d(span, rise)``, is the inverse of the Jacobian
``d(x, z)/d(H, V_B)`` at the solution (MoorPy's ``stiffnessB``); a slack line has no
horizontal stiffness.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import SolverError
from kanat.statics.piecewise import Ground, LineEvaluation, LiftedLoop, Pieces, end_position

__all__ = ["LineSolution", "solve_line"]

MAX_ITERATIONS = 50
MAX_LOG_STEP = 4.0            # largest change of log H per Newton step (a factor e^4)
MAX_HALVINGS = 30
STEP_TOLERANCE = 1e-13        # relative Newton step at which the iteration has converged
POSITION_TOLERANCE = 1e-9     # accepted end-position error, in line lengths
VERTICAL_SPAN = 1e-12         # spans below this many line lengths are vertical lines
TAUT_GUESS_LAMBDA = 0.2       # Peyrot & Goulois' catenary parameter for a taut line
SLACK_STIFFNESS = 0.01        # horizontal stiffness of a slack line, per N/m of its mean weight (MoorPy's)


@dataclass(frozen=True)
class LineSolution:
    """The end tensions of a line between two given ends.

    Attributes
    ----------
    horizontal_tension : float
        ``H`` [N].
    vertical_tension : float
        ``V_B`` [N] (the line pulls end B down by ``V_B``).
    evaluation : LineEvaluation
        Positions, Jacobian, the force on end A and the grounded length at the solution.
    slack : bool
        True when the line lies slack on the seabed (``H = 0``).
    iterations : int
    slack_stiffness : float
        Horizontal stiffness given to a line without any (slack on the seabed, or hanging
        vertically through a fold) [N/m]: MoorPy's ``0.01 w``, so that a node held by slack
        lines only still moves under a horizontal load.
    """

    horizontal_tension: float
    vertical_tension: float
    evaluation: LineEvaluation
    slack: bool = False
    iterations: int = 0
    slack_stiffness: float = 0.0

    @property
    def stiffness(self) -> np.ndarray:
        """``d(H, V_B)/d(span, rise)`` [N/m], shape (2, 2)."""
        J = self.evaluation.jacobian
        if self.slack or not np.all(np.isfinite(J)):
            return np.array([[self.slack_stiffness, 0.0], [0.0, 1.0 / J[1, 1] if J[1, 1] > 0 else 0.0]])
        return np.linalg.inv(J)

    @property
    def anchor_stiffness(self) -> np.ndarray:
        """``d(H_A, V_A)/d(span, rise)`` [N/m]: how the force on end A follows end B."""
        return self.evaluation.anchor_jacobian @ self.stiffness


def _equivalent(pieces: Pieces):
    """Weight per length, stiffness and sign of a uniform line of the same totals."""
    L = pieces.total_length
    total = pieces.total_weight
    w = abs(total) / L if total != 0.0 else max(float(np.mean(np.abs(pieces.weight))), 1e-9)
    EA = L / float(np.sum(pieces.length / pieces.stiffness))
    return L, w, EA, (1.0 if total >= 0.0 else -1.0)


def initial_guess(span: float, rise: float, pieces: Pieces):
    """``(H, V_B)`` of the uniform line of the same length, weight and stretch.

    Peyrot & Goulois (1979): ``lambda = sqrt(3 ((L^2 - rise^2)/span^2 - 1))`` (0.2 if taut),
    ``H = w span/(2 lambda)``, ``V_upper = w (rise/tanh(lambda) + L)/2``; a buoyant line is a
    heavy one mirrored in ``z``, and ``V_B`` follows from whichever end is the upper one.
    """
    L, w, EA, sign = _equivalent(pieces)
    span = max(span, VERTICAL_SPAN * L)
    up = sign * rise                                   # rise of B in the mirrored, heavy line
    chord = math.hypot(span, rise)
    lam = TAUT_GUESS_LAMBDA if chord >= L else math.sqrt(3.0 * ((L * L - rise * rise) / (span * span) - 1.0))
    H = max(0.5 * w * span / lam, 1e-6 * w * L)
    v_upper = 0.5 * w * (abs(up) / math.tanh(lam) + L)
    if chord > L:                                      # stretched: the tension that stretches the chord
        tension = (chord / L - 1.0) * EA
        H = max(H, tension * span / chord)
        v_upper = max(v_upper, tension * abs(up) / chord + 0.5 * w * L)
    VB = v_upper if up >= 0.0 else w * L - v_upper     # B upper, or A upper: V_A = -v_upper
    return H, sign * VB


def _error(ev: LineEvaluation, span, rise):
    return ev.x - span, ev.z - rise


def _newton(span, rise, pieces, ground, H, VB):
    """Newton's method in ``(log H, V_B)``; returns ``(H, V_B, evaluation, iterations)`` or None."""
    L = pieces.total_length
    try:
        ev = end_position(H, VB, pieces, ground)
    except LiftedLoop:
        raise
    except SolverError:
        return None
    ex, ez = _error(ev, span, rise)
    merit = ex * ex + ez * ez
    for iteration in range(1, MAX_ITERATIONS + 1):
        if math.sqrt(merit) <= 1e-3 * POSITION_TOLERANCE * L:
            return H, VB, ev, iteration
        J = ev.jacobian
        a, b, c, d = J[0, 0] * H, J[0, 1], J[1, 0] * H, J[1, 1]
        det = a * d - b * c
        if det == 0.0 or not math.isfinite(det):
            break
        du, dv = (-d * ex + b * ez) / det, (c * ex - a * ez) / det
        if abs(du) <= STEP_TOLERANCE and abs(dv) <= STEP_TOLERANCE * max(abs(VB), H):
            break
        scale = min(1.0, MAX_LOG_STEP / abs(du)) if du != 0.0 else 1.0
        for _ in range(MAX_HALVINGS):
            H_try, VB_try = H * math.exp(scale * du), VB + scale * dv
            try:
                if ground is not None and VB_try <= H_try * ground.slope:
                    raise SolverError("end B on the seabed")
                ev_try = end_position(H_try, VB_try, pieces, ground)
                ex_t, ez_t = _error(ev_try, span, rise)
                merit_try = ex_t * ex_t + ez_t * ez_t
                if merit_try <= merit:
                    break
            except LiftedLoop:
                raise
            except SolverError:
                pass
            scale *= 0.5
        else:
            break
        H, VB, ev, ex, ez, merit = H_try, VB_try, ev_try, ex_t, ez_t, merit_try
    if math.sqrt(merit) <= POSITION_TOLERANCE * L:
        return H, VB, ev, MAX_ITERATIONS
    return None


def _root(f, lo, hi, grow):
    """A root of the increasing ``f`` in ``[lo, hi]``, the bracket widened by ``grow``."""
    from scipy.optimize import brentq           # rarely needed: its import is 0.15 s of a run's CPU

    for _ in range(200):
        if f(lo) <= 0.0:
            break
        lo = grow(lo, -1)
    for _ in range(200):
        if f(hi) >= 0.0:
            break
        hi = grow(hi, +1)
    return brentq(f, lo, hi, xtol=1e-15 * max(abs(lo), abs(hi), 1.0), rtol=1e-15, maxiter=500)


def _vb_at(H, rise, pieces, ground):
    """``V_B`` that puts B at height ``rise`` for a given ``H`` (``z`` increases with ``V_B``)."""
    wL = abs(pieces.total_weight) + float(np.dot(np.abs(pieces.weight), pieces.length)) + 1.0
    low = H * ground.slope * (1.0 + 1e-12) + 1e-12 * wL if ground is not None else -wL

    def f(VB):
        return end_position(H, VB, pieces, ground).z - rise

    def grow(v, direction):
        if direction < 0 and ground is not None:
            return low
        return v + direction * 2.0 * max(abs(v), wL)
    return _root(f, low, max(low, 0.0) + wL, grow)


def _nested(span, rise, pieces, ground, H0):
    """Bracketed fallback: ``x(H, V_B(H)) = span`` along ``z = rise``; None on failure."""
    try:
        def f(u):
            H = math.exp(u)
            return end_position(H, _vb_at(H, rise, pieces, ground), pieces, ground).x - span
        u = _root(f, math.log(H0) - 1.0, math.log(H0) + 1.0, lambda v, d: v + d * MAX_LOG_STEP)
        H = math.exp(u)
        VB = _vb_at(H, rise, pieces, ground)
        ev = end_position(H, VB, pieces, ground)
    except LiftedLoop:
        raise
    except (SolverError, ValueError, OverflowError, ZeroDivisionError):
        return None
    ex, ez = _error(ev, span, rise)
    return (H, VB, ev) if math.hypot(ex, ez) <= POSITION_TOLERANCE * pieces.total_length else None


def _hanging(rise, pieces, ground):
    """``H = 0``: the line hangs vertically from B (to the seabed, or folded); None if it
    cannot reach ``rise`` that way."""
    try:
        VB = _vb_at(0.0, rise, pieces, ground)
        return VB, end_position(0.0, VB, pieces, ground)
    except (SolverError, ValueError):
        return None


def _lying(span, rise, pieces: Pieces, ground: Ground) -> LineSolution:
    """Both ends on the seabed: the line lies along it, eq. (3) with the touchdown at B.

    Its unstretched length reaches ``span/cos alpha`` when the tension at B, falling towards
    A by eq. (3), stretches it that far; a shorter distance leaves it slack (``T = 0``,
    bunched). Lifting B needs no force at first: its vertical stiffness is that of the
    lightest piece at B, ``w_B`` per metre (MoorPy's approximation).
    """
    from kanat.statics.piecewise import grounded_piece

    reach = span / ground.cos - pieces.total_length
    c = ground.resistance

    def stretch(T_B):
        total, slope, T, dT = 0.0, 0.0, T_B, 1.0
        for j in range(len(pieces.length) - 1, -1, -1):
            I, T_next, q = grounded_piece(T, pieces.length[j], c * pieces.weight[j], pieces.stiffness[j])
            total, slope = total + I, slope + q[0] * dT
            T, dT = T_next, q[2] * dT
            if j > 0:
                T, dT = (T - c * pieces.load[j - 1], dT) if T > c * pieces.load[j - 1] else (0.0, 0.0)
        return total, slope
    T_B, slope = 0.0, math.inf
    if reach > 0.0:
        from scipy.optimize import brentq

        EA = float(np.max(pieces.stiffness))
        T_B = brentq(lambda T: stretch(T)[0] - reach, 0.0, 2.0 * (reach / pieces.total_length) * EA
                     + c * abs(pieces.total_weight) + 1.0, xtol=1e-12, rtol=1e-15)
        slope = stretch(T_B)[1]
    H, VB = T_B * ground.cos, T_B * ground.sin
    jacobian = np.array([[slope, 0.0], [ground.slope * slope if ground.slope else 0.0,
                                         1.0 / max(pieces.weight[-1], 1e-300)]])
    T_A = _anchor_tension_lying(T_B, pieces, c)
    ev = LineEvaluation(span, rise, jacobian, np.array([T_A * ground.cos, T_A * ground.sin]),
                        np.zeros((2, 2)), pieces.total_length)
    return LineSolution(H, VB, ev, slack=T_B == 0.0)


def _anchor_tension_lying(T, pieces: Pieces, c: float) -> float:
    for j in range(len(pieces.length) - 1, -1, -1):
        T = max(T - c * pieces.weight[j] * pieces.length[j], 0.0)
        if j > 0:
            T = max(T - c * pieces.load[j - 1], 0.0)
    return T


def solve_line(span: float, rise: float, pieces: Pieces, ground: Ground | None = None,
               start: tuple[float, float] | None = None) -> LineSolution:
    """End tensions of a line whose end B is at ``(span, rise)`` from end A (:func:`_solve`),
    with the slack stiffness of module SLACK_STIFFNESS."""
    solution = _solve(span, rise, pieces, ground, start)
    kx = SLACK_STIFFNESS * float(np.dot(np.abs(pieces.weight), pieces.length)) / pieces.total_length
    return LineSolution(solution.horizontal_tension, solution.vertical_tension, solution.evaluation,
                        solution.slack, solution.iterations, kx)


def _solve(span: float, rise: float, pieces: Pieces, ground: Ground | None,
           start: tuple[float, float] | None) -> LineSolution:
    """End tensions of a line whose end B is at ``(span, rise)`` from end A.

    Parameters
    ----------
    span : float
        Horizontal distance from A to B, ``>= 0`` [m].
    rise : float
        Height of B above A [m] (may be negative).
    pieces : Pieces
    ground : Ground or None
        End A resting on the seabed (friction, slope), or None.
    start : (H, V_B), optional
        Warm start (the previous solution of the same line).

    Returns
    -------
    LineSolution

    Raises
    ------
    SolverError
        No equilibrium found (the message gives the numbers); :class:`LiftedLoop` for a
        buoyant stretch on the seabed.
    """
    L = pieces.total_length
    if ground is not None and rise <= span * ground.slope + POSITION_TOLERANCE * L:
        if not pieces.can_lie_slack():
            raise LiftedLoop("a line with buoyant parts lying on the seabed between two grounded ends "
                             "is not modelled by the catenary statics")
        return _lying(span, rise, pieces, ground)
    if span <= VERTICAL_SPAN * L:
        hang = _hanging(rise, pieces, None if ground is None else Ground(0.0, ground.friction))
        if hang is not None:
            return LineSolution(0.0, hang[0], hang[1], slack=ground is not None and hang[1].touchdown > 0)
    guesses = [start] if start is not None and start[0] > 0.0 else []
    guesses.append(initial_guess(span, rise, pieces))
    for H, VB in guesses:
        if ground is not None and VB <= H * ground.slope:
            VB = H * ground.slope + 0.5 * abs(pieces.total_weight)
        found = _newton(span, rise, pieces, ground, H, VB)
        if found is not None:                    # H > 0 excludes the slack state (x grows with H)
            H, VB, ev, iterations = found
            return LineSolution(H, VB, ev, iterations=iterations)
    if ground is not None and pieces.can_lie_slack():
        hang = _hanging(rise, pieces, ground)
        if hang is not None and span <= hang[1].x * (1.0 + 1e-12):
            return LineSolution(0.0, hang[0], hang[1], slack=True)
    found = _nested(span, rise, pieces, ground, guesses[-1][0])
    if found is not None:
        return LineSolution(*found, iterations=-1)
    raise SolverError(f"no catenary found for a line of {L:.6g} m whose end B is {span:.6g} m away "
                      f"horizontally and {rise:.6g} m higher (weight {pieces.total_weight:.6g} N in water"
                      f"{', end A on the seabed' if ground is not None else ''}); Newton's method and the "
                      "bracketed solve both failed")
