"""Shooting solver for the steady 2-D cable (theory/statics.md §1; Naumov & Agievich's method).

The state ``(x, z, F_x, F_z)`` is integrated along ``s`` with ``solve_ivp``
(DOP853) from one end, the unknown initial values being found by root finding
on the other end's conditions:

* a cable ending at a body is integrated *from the body*, where the tension is
  known from the body's load; the only unknown is the body's height (the flow
  depends on ``z`` only), so a uniform flow needs a single integration;
* a cable between two fixed points is integrated from ``s = 0`` with the tension
  vector there unknown (2 unknowns, 2 position residuals at ``s = L``);
* a line resting on the seabed is integrated from its touchdown point, the
  unknowns being the touchdown tension and the grounded length.

When the root finder fails from the drag-free catenary guess, the flow is scaled
down and brought back to full strength in steps (continuation from an easier
problem), halving the step on each failure.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import root, root_scalar

from kanat.errors import SolverError
from kanat.statics.guess import between_fixed_points, catenary_states, straight_guess
from kanat.statics.problem import BodyEnd, CableBVP, Grounding, check_solvable, steady_rhs
from kanat.statics.solution import CableSolution

RTOL = 1e-11          # ODE tolerance, far below the 1e-6 the solvers must agree to
RESIDUAL_TOL = 1e-10  # end residual, relative to the cable length / reference force
MIN_TENSION = 1e-9    # relative; below this the cable is slack and the equations break down
CONTINUATION_STEPS = 4
MAX_HALVINGS = 8


def solve_shooting(problem: CableBVP, s_out=None) -> CableSolution:
    """Solve the steady cable by shooting.

    Parameters
    ----------
    problem : CableBVP
    s_out : array_like, optional
        Unstretched arclengths at which to report the solution [m]; default 101
        equally spaced stations.

    Returns
    -------
    CableSolution

    Raises
    ------
    SolverError
        When no solution is found, with the reason and what to try.
    """
    s_out = _stations(problem, s_out)
    check_solvable(problem)
    body_ends = [isinstance(e, BodyEnd) for e in (problem.start, problem.end)]
    if any(body_ends):
        return _shoot_from_body(problem, s_out, body_ends.index(True))
    return _shoot_between_points(problem, s_out)


def _stations(problem, s_out):
    return np.linspace(0.0, problem.length, 101) if s_out is None else np.asarray(s_out, dtype=float)


def _reference_force(problem: CableBVP) -> float:
    return max(abs(problem.line.weight) * problem.length, 1.0)


def _integrate(problem: CableBVP, s_from: float, y_from, s_to: float):
    """Integrate the steady equations from ``s_from`` to ``s_to`` with dense output."""
    scale = np.array([problem.length, problem.length, *(2 * [_reference_force(problem)])])
    floor = MIN_TENSION * scale[2]

    def slack(s, y):
        return np.hypot(y[2], y[3]) - floor
    slack.terminal = True

    sol = solve_ivp(lambda s, y: steady_rhs(problem, y[:, None])[:, 0], (s_from, s_to), np.asarray(y_from, float),
                    method="DOP853", rtol=RTOL, atol=RTOL * scale, dense_output=True, events=slack)
    if sol.status == 1:
        where = sol.t_events[0][0]
        raise SolverError(f"the tension vanishes at s = {where:.6g} m: the cable is slack there and "
                          "its steady shape is not defined (e.g. a buoy too small to lift its line, "
                          "or a body with no load); change the ends or the loads")
    if not sol.success:
        raise SolverError(f"integration of the steady cable equations failed: {sol.message}")
    return sol


def _shoot_from_body(problem: CableBVP, s_out, body_index: int) -> CableSolution:
    """Integrate from the body end; root-find its height when the flow varies with depth."""
    body = (problem.start, problem.end)[body_index]
    fixed = (problem.start, problem.end)[1 - body_index].position
    s_body, s_fixed = (0.0, problem.length) if body_index == 0 else (problem.length, 0.0)
    sign = -1.0 if body_index == 0 else 1.0
    rho = problem.line.water_density

    def shoot(z_body):
        force = sign * body.load(problem.flow, z_body, rho)
        return _integrate(problem, s_body, [0.0, z_body, *force], s_fixed)

    sol = shoot(0.0)
    z_body = fixed[1] - sol.y[1, -1]
    iterations = 1
    if not problem.flow.is_uniform:
        result = root_scalar(lambda zb: shoot(zb).y[1, -1] - fixed[1], x0=z_body, x1=z_body + 1e-3 * problem.length,
                             method="secant", xtol=RESIDUAL_TOL * problem.length, maxiter=50)
        if not result.converged:
            raise SolverError(f"shooting did not find the body depth: {result.flag}; try the collocation solver")
        z_body, iterations = result.root, 1 + result.function_calls
    sol = shoot(z_body)
    y = sol.sol(s_out)
    y[0] += fixed[0] - sol.y[0, -1]
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "shooting", 0.0, iterations)


def _solve_continued(residual, unknowns, scale, label: str, name: str = "shooting"):
    """Root-find ``residual(x, factor) = 0`` at ``factor = 1``, continuing from 0 if needed.

    ``unknowns`` is the solution at ``factor = 0`` (the drag-free guess). Returns the
    root and the number of residual evaluations. ``name`` names the solver in messages
    (the planar and the 3-D shooting solvers share this continuation).
    """
    evaluations = 0

    def attempt(factor, start):
        nonlocal evaluations
        try:
            sol = root(lambda q: residual(q * scale, factor), start / scale, method="hybr", options={"xtol": 1e-13})
        except SolverError:
            return None
        evaluations += sol.nfev
        if np.max(np.abs(sol.fun)) > RESIDUAL_TOL or not np.all(np.isfinite(sol.x)):
            return None
        return sol.x * scale

    direct = attempt(1.0, unknowns)
    if direct is not None:
        return direct, evaluations
    current, factor, step, halvings = attempt(0.0, unknowns), 0.0, 1.0 / CONTINUATION_STEPS, 0
    if current is None:
        raise SolverError(f"{name} ({label}) failed even without current; check the end positions "
                          "against the cable length, or use the collocation solver")
    while factor < 1.0:
        trial = min(1.0, factor + step)
        found = attempt(trial, current)
        if found is None:
            step, halvings = step / 2, halvings + 1
            if halvings > MAX_HALVINGS:
                raise SolverError(f"{name} ({label}) lost the solution at {100 * trial:.1f} % of the flow speed; "
                                  "the steady state may not exist (line blown onto the seabed or slack); "
                                  "try the collocation solver or a longer line")
            continue
        current, factor = found, trial
    return current, evaluations


def _shoot_between_points(problem: CableBVP, s_out) -> CableSolution:
    """A line between two fixed points, resting on the seabed where it must."""
    missing = (None, None, 0.01 * problem.length)
    return between_fixed_points(problem, s_out, _shoot_grounded, _shoot_suspended, missing)


def _shoot_suspended(problem: CableBVP, s_out):
    """Unknown tension vector at ``s = 0``; residual: the position of ``s = L``."""
    start = np.asarray(problem.start.position, dtype=float)
    target = np.asarray(problem.end.position, dtype=float)
    guess = catenary_states(problem, seabed=False)
    f0 = guess[1][2:4, 0] if guess is not None else straight_guess(problem)[1][2:4, 0]

    def residual(force, factor):
        sol = _integrate(problem.with_flow(factor), 0.0, [*start, *force], problem.length)
        return (sol.y[0:2, -1] - target) / problem.length

    force, evaluations = _solve_continued(residual, f0, np.full(2, _reference_force(problem)), "suspended line")
    sol = _integrate(problem, 0.0, [*start, *force], problem.length)
    y = sol.sol(s_out)
    fine_z = sol.sol(np.linspace(0.0, problem.length, 2001))[1]
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "shooting", 0.0, evaluations), fine_z


def _shoot_grounded(problem: CableBVP, s_out, grounding: Grounding, guess) -> CableSolution:
    """Unknown touchdown tension and grounded length; integrate the suspended part."""
    length, stiffness = problem.length, problem.line.axial_stiffness
    target = np.asarray((problem.start, problem.end)[1 - grounding.anchor].position, dtype=float)
    s_other = length if grounding.anchor == 0 else 0.0

    def shoot(unknowns, flow_problem):
        tension, grounded = unknowns
        ground = flow_problem.grounding()                # its drag along the seabed scaled with the flow
        return _integrate(flow_problem, ground.touchdown_s(grounded, length),
                          ground.touchdown_state(tension, grounded, stiffness), s_other)

    def residual(unknowns, factor):
        return (shoot(unknowns, problem.with_flow(factor)).y[0:2, -1] - target) / length

    _, y_guess, grounded_guess = guess
    tension_guess = abs(y_guess[2, 0]) if y_guess is not None else 0.1 * _reference_force(problem)
    scale = np.array([_reference_force(problem), length])
    (tension, grounded), evaluations = _solve_continued(residual, np.array([tension_guess, grounded_guess]),
                                                        scale, "line on the seabed")
    sol = shoot((tension, grounded), problem)
    y = sol.sol(np.clip(s_out, min(sol.t[0], sol.t[-1]), max(sol.t[0], sol.t[-1])))
    grounding.fill(s_out, y, tension, grounded, length, stiffness)
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "shooting", float(grounded), evaluations)
