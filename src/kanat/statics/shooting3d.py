"""Shooting solver for the 3-D steady cable (:mod:`kanat.statics.spatial`; theory/statics.md §1, Naumov & Agievich's method).

The state ``(x, y, z, F_x, F_y, F_z)`` is integrated along ``s`` with ``solve_ivp`` (DOP853), piece by
piece, jumping across inline bodies; the unknown initial values are found by root finding
(``scipy.optimize.root``) on the far end's three conditions:

* from a fixed first end: the force there ``F(0)`` (3 unknowns);
* from a fixed end at ``s = L`` when the first end is a body: ``F(L)``, integrating backwards;
* from an anchor resting on the seabed: the touchdown tension, the grounded length and the
  grounded line's azimuth, integrating the suspended part from the touchdown point.

The start is the still-water solution (a line hanging or standing straight under its bodies,
or the drag-free elastic catenary between two fixed points); the flow is then brought up in
steps (continuation), halving the step on each failure.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import root_scalar

from kanat.errors import SolverError
from kanat.statics.guess3d import grounding_guess, still_water_force
from kanat.statics.spatial import Body3, CableBVP3, Fixed3, check_solvable, end_residual, grounded_states, jump, rhs_point
from kanat.statics.shooting import _solve_continued
from kanat.statics.solution import CableSolution

RTOL = 1e-12          # ODE tolerance: far below the 1e-6 the solvers must agree to, and rotations leave
                      # tensions to 1e-9 (the integrator takes other steps in turned coordinates)
RESIDUAL_TOL = 1e-10  # end residual, relative to the cable length / reference force
MIN_TENSION = 1e-9    # relative; below this the cable is slack and the equations break down


class Path:
    """The integrated cable: piece solutions in order of ``s`` (dense output), and the grounded part."""

    def __init__(self):
        self.parts: list = []          # (s_low, s_high, sol)
        self.ground = None             # (anchor, tension, length, psi)
        self.shift = np.zeros(3)       # added to the integrated positions

    def sample(self, problem: CableBVP3, s_out) -> np.ndarray:
        """States (6, n) at stations ``s_out``; at an inline body, a repeated station gives the state
        before the jump first and after it second."""
        s_out = np.asarray(s_out, dtype=float)
        out = np.empty((6, len(s_out)))
        for i, s in enumerate(s_out):
            second = i > 0 and s_out[i - 1] == s
            out[:, i] = self._at(problem, s, second)
        out[0:3] += self.shift[:, None]
        return out

    def _at(self, problem, s, second):
        if self.ground is not None:
            anchor, tension, length, psi = self.ground
            from_anchor = s if anchor == 0 else problem.length - s
            if from_anchor <= length:
                return grounded_states(problem, anchor, tension, length, psi, [from_anchor])[0][:, 0]
        parts = sorted(self.parts, key=lambda p: p[0])
        for index, (low, high, sol) in enumerate(parts):
            last = index == len(parts) - 1
            if s < high or (s == high and (last or not second)) or (s <= high and last):
                return sol.sol(min(max(s, low), high))
        return parts[-1][2].sol(parts[-1][1])


def _integrate(problem: CableBVP3, s_from: float, y_from, s_to: float, path: Path | None = None):
    """Integrate from ``s_from`` to ``s_to`` across pieces and inline bodies; the state at ``s_to``."""
    scale = np.array([problem.length] * 3 + [problem.reference_force()] * 3)
    floor = MIN_TENSION * scale[3]
    forward = s_to > s_from
    y = np.asarray(y_from, dtype=float)
    bounds = sorted({p.start for p in problem.pieces} | {p.end for p in problem.pieces})
    inner = [b for b in bounds if min(s_from, s_to) < b < max(s_from, s_to)]
    stops = inner if forward else inner[::-1]
    here = s_from
    for stop in stops + [s_to]:
        piece = problem.piece_at(0.5 * (here + stop))

        def slack(s, state):
            return np.sqrt(state[3] ** 2 + state[4] ** 2 + state[5] ** 2) - floor
        slack.terminal = True
        sol = solve_ivp(lambda s, state, piece=piece: rhs_point(piece, problem.flow, state), (here, stop), y,
                        method="DOP853", rtol=RTOL, atol=RTOL * scale, dense_output=True, events=slack)
        if sol.status == 1:
            raise SolverError(f"the tension vanishes at s = {sol.t_events[0][0]:.6g} m: the cable is slack there "
                              "and its steady shape is not defined (e.g. a buoy too small to lift its line); change "
                              "the ends or the loads")
        if not sol.success:
            raise SolverError(f"integration of the steady cable equations failed: {sol.message}")
        if path is not None:
            path.parts.append((min(here, stop), max(here, stop), sol))
        y = sol.y[:, -1]
        if stop != s_to:
            y = jump(problem, stop, y, forward)
        here = stop
    return y


def solve_shooting3(problem: CableBVP3, s_out=None) -> CableSolution:
    """Solve the 3-D steady cable by shooting (module docstring).

    Parameters
    ----------
    problem : CableBVP3
    s_out : array_like, optional
        Stations [m] (repeat an inline body's arclength to get both sides of its jump); default
        101 equally spaced.

    Returns
    -------
    CableSolution
    """
    check_solvable(problem)
    s_out = np.linspace(0.0, problem.length, 101) if s_out is None else np.asarray(s_out, dtype=float)
    return anchored_or_suspended(problem, s_out, _shoot_grounded, _shoot_suspended)


def anchored_or_suspended(problem: CableBVP3, s_out, grounded, suspended) -> CableSolution:
    """A line that may rest on the seabed from its anchor: the order in which the 3-D shooting and
    collocation solvers try their two problems.

    1. Where the line can rest on the seabed from an anchor (``problem.grounding_anchor()``) and does
       not stand up from it (:func:`stands_up`): ``grounded(problem, s_out, anchor)``, kept if it solves;
    2. else ``suspended(problem, s_out) -> (solution, profile)``, kept unless, with an anchor, it fails
       or the line's profile ``profile() -> (x, z)`` [m] dips below the seabed;
    3. then ``grounded``.
    """
    anchor = problem.grounding_anchor()
    if anchor is not None and not stands_up(problem):
        try:
            return grounded(problem, s_out, anchor)
        except SolverError:
            pass                                   # the line may not touch the seabed after all
    try:
        solution, profile = suspended(problem, s_out)
    except SolverError:
        if anchor is None:
            raise
        return grounded(problem, s_out, anchor)
    if anchor is not None:
        x, z = profile()
        if np.any(z < problem.seabed.height(x) - 1e-9 * problem.length):
            return grounded(problem, s_out, anchor)
    return solution


def stands_up(problem: CableBVP3) -> bool:
    """True when a body end lifts more than the whole line weighs in water (a subsurface mooring): the
    line stands up from its anchor, and only a current could lay it down (tried second)."""
    from kanat.statics.guess3d import lift

    bodies = [e.load for e in (problem.start, problem.end) if isinstance(e, Body3)]
    if not bodies or any(load.follows_height for load in bodies):      # a surface buoy's lift is its draft's
        return False
    return float(lift(problem)[2]) > sum(p.line.weight * p.length for p in problem.pieces)


def _shoot_suspended(problem: CableBVP3, s_out):
    """The line off the seabed, shot from its body end or between its fixed ends; its profile."""
    if any(isinstance(e, Body3) for e in (problem.start, problem.end)):
        solution, path = _shoot_from_body(problem, s_out)
    else:
        solution, path = _shoot_free(problem, s_out)

    def profile():
        fine = path.sample(problem, np.linspace(0.0, problem.length, 2001))
        return fine[0], fine[2]
    return solution, profile


def _shoot_from_body(problem: CableBVP3, s_out):
    """Integrate from the body, where the force is its load at its height; the flow and the loads
    depend on height only, so the one unknown is the body's height (none in a uniform flow with no
    surface buoy and no float whose buoyancy follows its immersion), and the cable is shifted horizontally onto the fixed end."""
    body = 0 if isinstance(problem.start, Body3) else 1
    s_body, s_fixed = (0.0, problem.length) if body == 0 else (problem.length, 0.0)
    target = np.asarray((problem.start, problem.end)[1 - body].position, dtype=float)
    load = (problem.start, problem.end)[body].load
    sign = -1.0 if body == 0 else 1.0

    def shoot(z_body, path=None):
        force = sign * load.at(problem.flow, z_body, problem.density)
        return _integrate(problem, s_body, np.concatenate([[0.0, 0.0, z_body], force]), s_fixed, path)

    y = shoot(target[2])
    z_body, evaluations = target[2] + (target[2] - y[2]), 1
    if not problem.flow.is_uniform or load.follows_height or any(j.follows_height for _, j in problem.joints):
        result = root_scalar(lambda zb: shoot(zb)[2] - target[2], x0=z_body, x1=z_body + 1e-3 * problem.length,
                             method="secant", xtol=RESIDUAL_TOL * problem.length, maxiter=50)
        if not result.converged:
            raise SolverError(f"3-D shooting did not find the body's depth: {result.flag}; try the collocation solver")
        z_body, evaluations = result.root, 1 + result.function_calls
    path = Path()
    end = shoot(z_body, path)
    path.shift = target - end[0:3]
    path.shift[2] = 0.0
    y = path.sample(problem, s_out)
    return _solution(s_out, y, "shooting", 0.0, evaluations), path


def _shoot_free(problem: CableBVP3, s_out):
    fixed = 0 if isinstance(problem.start, Fixed3) else 1
    s_fixed, s_other = (0.0, problem.length) if fixed == 0 else (problem.length, 0.0)
    origin = np.asarray((problem.start, problem.end)[fixed].position, dtype=float)
    reference = problem.reference_force()

    def residual(force, factor):
        flowed = problem.with_flow(factor)
        y = _integrate(flowed, s_fixed, np.concatenate([origin, force]), s_other)
        scale = np.array([problem.length] * 3 if isinstance((problem.start, problem.end)[1 - fixed], Fixed3)
                         else [reference] * 3)
        return end_residual(flowed, 1 - fixed, y) / scale

    force, evaluations = _solve_continued(residual, still_water_force(problem, fixed), np.full(3, reference), "suspended line",
                                         "3-D shooting")
    path = Path()
    _integrate(problem, s_fixed, np.concatenate([origin, force]), s_other, path)
    y = path.sample(problem, s_out)
    return _solution(s_out, y, "shooting", 0.0, evaluations), path


def _shoot_grounded(problem: CableBVP3, s_out, anchor: int) -> CableSolution:
    """Unknown touchdown tension, grounded length and azimuth; integrate the suspended part."""
    length, reference = problem.length, problem.reference_force()
    s_other = length if anchor == 0 else 0.0
    other = (problem.start, problem.end)[1 - anchor]

    def shoot(unknowns, flowed, path=None):
        tension, grounded, psi = unknowns
        if not 0.0 <= grounded < length or tension <= 0.0:
            raise SolverError("grounded length out of range")
        _, touchdown = grounded_states(flowed, anchor, tension, grounded, psi, [0.0])
        s_td = grounded if anchor == 0 else length - grounded
        return _integrate(flowed, s_td, touchdown, s_other, path)

    def residual(unknowns, factor):
        flowed = problem.with_flow(factor)
        scale = length if isinstance(other, Fixed3) else reference
        return end_residual(flowed, 1 - anchor, shoot(unknowns, flowed)) / scale

    guess = grounding_guess(problem, anchor)
    unknowns, evaluations = _solve_continued(residual, guess, np.array([reference, length, 1.0]), "line on the seabed",
                                               "3-D shooting")
    tension, grounded, psi = unknowns
    path = Path()
    path.ground = (anchor, tension, grounded, psi)
    shoot(unknowns, problem, path)
    y = path.sample(problem, s_out)
    return _solution(s_out, y, "shooting", float(grounded), evaluations)


def _solution(s, y, method, grounded, iterations) -> CableSolution:
    return CableSolution(s, y[0], y[2], y[[3, 5]].T.copy(), method, grounded, iterations, y[1].copy(), y[4].copy())


def azimuth(vector) -> float:
    """Azimuth of a vector's horizontal part [rad] (0 when vertical)."""
    return math.atan2(vector[1], vector[0]) if math.hypot(vector[0], vector[1]) > 0 else 0.0
