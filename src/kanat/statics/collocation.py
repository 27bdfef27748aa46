"""Collocation solver for the steady 2-D cable (theory/statics.md §1): ``scipy.integrate.solve_bvp``.

Independent of shooting: the whole profile is the unknown, the equations are
collocated on an adaptive mesh (4th-order Lobatto IIIA) and both ends' conditions
are imposed at once. Variables are scaled (``sigma = s / L``, positions by ``L``,
forces by ``max(|w| L, 1 N)``) so that the tolerance means the same on any cable.
A line resting on the seabed is solved over its suspended part, the grounded length
being an unknown parameter of the BVP with three touchdown conditions (on the bed,
tangent horizontal, straight frictionless grounded part back to the anchor).
When the full problem fails from the guess, the flow is brought up from zero in steps.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_bvp

from kanat.errors import SolverError
from kanat.statics.guess import between_fixed_points, catenary_states, straight_guess
from kanat.statics.problem import CableBVP, FixedEnd, Grounding, check_solvable, end_residual, steady_rhs
from kanat.statics.solution import CableSolution

TOL = 1e-8             # solve_bvp relative residual on the scaled equations (error ~1e-12 vs closed form)
MAX_NODES = 5_000        # finer means no smooth solution (a slack line): fail in seconds, not minutes
CONTINUATION_STEPS = 4
MAX_HALVINGS = 6


def solve_collocation(problem: CableBVP, s_out=None) -> CableSolution:
    """Solve the steady cable by collocation (see module docstring).

    Parameters
    ----------
    problem : CableBVP
    s_out : array_like, optional
        Stations of the output [m]; default 101 equally spaced.

    Returns
    -------
    CableSolution
    """
    s_out = np.linspace(0.0, problem.length, 101) if s_out is None else np.asarray(s_out, dtype=float)
    check_solvable(problem)
    return between_fixed_points(problem, s_out, _collocate_grounded, _collocate_suspended)


def _scales(problem: CableBVP) -> np.ndarray:
    force = max(abs(problem.line.weight) * problem.length, 1.0)
    return np.array([problem.length, problem.length, force, force])


def _continued(solve_at, guess, label: str, name: str = "collocation"):
    """Run ``solve_at(factor, guess)`` at full flow, or continue up from no flow in steps.

    ``guess`` is ``(mesh, y, p)`` as ``solve_bvp`` takes them (``p`` None without parameters); each
    step starts from the last converged result. ``name`` and ``label`` name the solver and the part
    of the line in the error raised when no step is left.
    """
    result = solve_at(1.0, guess)
    if result.success:
        return result
    factor, step, halvings = 0.0, 1.0 / CONTINUATION_STEPS, 0
    result = solve_at(0.0, guess)
    if not result.success:
        raise SolverError(f"{name} ({label}) failed even without current: {result.message}; "
                          "check the end positions against the cable length")
    while factor < 1.0:
        trial = min(1.0, factor + step)
        attempt = solve_at(trial, (result.x, result.y, result.p))
        if attempt.success:
            result, factor = attempt, trial
            continue
        step, halvings = step / 2, halvings + 1
        if halvings > MAX_HALVINGS:
            raise SolverError(f"{name} ({label}) lost the solution at {100 * trial:.1f} % of the flow "
                              f"speed ({attempt.message}); the steady state may not exist")
    return result


def _collocate_suspended(problem: CableBVP, s_out):
    scale = _scales(problem)
    length = problem.length
    end_scale = [scale[0] if isinstance(e, FixedEnd) else scale[2] for e in (problem.start, problem.end)]

    def solve_at(factor, guess):
        flow_problem = problem.with_flow(factor)
        mesh, y0 = guess[0], guess[1]

        def fun(sigma, y):
            return steady_rhs(flow_problem, y * scale[:, None]) * length / scale[:, None]

        def bc(ya, yb):
            return np.concatenate([end_residual(flow_problem, 0, ya * scale) / end_scale[0],
                                   end_residual(flow_problem, 1, yb * scale) / end_scale[1]])
        return solve_bvp(fun, bc, mesh, y0, tol=TOL, max_nodes=MAX_NODES)

    guess = None
    if all(isinstance(e, FixedEnd) for e in (problem.start, problem.end)):
        guess = catenary_states(problem, seabed=False)
    s_guess, y_guess = guess[:2] if guess is not None else straight_guess(problem)
    result = _continued(solve_at, (s_guess / length, y_guess / scale[:, None], None), "suspended line")
    y = result.sol(s_out / length) * scale[:, None]
    fine_z = result.sol(np.linspace(0.0, 1.0, 2001))[1] * length
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "collocation", 0.0, int(result.niter)), fine_z


def _collocate_grounded(problem: CableBVP, s_out, grounding: Grounding, guess) -> CableSolution:
    scale = _scales(problem)
    length, stiffness = problem.length, problem.line.axial_stiffness
    target = np.asarray((problem.start, problem.end)[1 - grounding.anchor].position, dtype=float)
    touchdown_at_start = grounding.anchor == 0          # sigma = 0 at touchdown, else at sigma = 1

    def s_of(sigma, grounded):
        return grounded + sigma * (length - grounded) if touchdown_at_start else sigma * (length - grounded)

    def solve_at(factor, guess):
        flow_problem = problem.with_flow(factor)
        ground = flow_problem.grounding()                # its drag along the seabed scaled with the flow
        mesh, y0, p0 = guess

        def fun(sigma, y, p):
            return steady_rhs(flow_problem, y * scale[:, None]) * (length * (1.0 - p[0])) / scale[:, None]

        def bc(ya, yb, p):
            y_td, y_far = (ya, yb) if touchdown_at_start else (yb, ya)
            td = y_td * scale
            expected = ground.touchdown_state(ground.tangent_x * td[2], p[0] * length, stiffness)
            return np.concatenate([(td[[0, 1, 3]] - expected[[0, 1, 3]]) / scale[[0, 1, 3]],
                                   (y_far[0:2] * scale[0:2] - target) / length])
        return solve_bvp(fun, bc, mesh, y0, p=p0, tol=TOL, max_nodes=MAX_NODES)

    if guess is None:                                   # no grounded catenary: as shooting starts
        guess = (*straight_guess(problem), 0.01 * length)
    s_guess, y_guess, grounded_guess = guess
    sigma = np.linspace(0.0, 1.0, 101)
    s_suspended = s_of(sigma, grounded_guess)
    y0 = np.vstack([np.interp(s_suspended, s_guess, row) for row in y_guess]) / scale[:, None]
    result = _continued(solve_at, (sigma, y0, np.array([grounded_guess / length])), "line on the seabed")
    grounded = float(result.p[0] * length)
    sigma_out = np.clip((s_out - (grounded if touchdown_at_start else 0.0)) / (length - grounded), 0.0, 1.0)
    y = result.sol(sigma_out) * scale[:, None]
    tension = abs(result.sol(0.0 if touchdown_at_start else 1.0)[2] * scale[2])
    grounding.fill(s_out, y, tension, grounded, length, stiffness)
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "collocation", grounded, int(result.niter))
