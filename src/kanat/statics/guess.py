"""Closed-form and straight-line states for the steady cable: first guesses and the fast path.

The drag-free elastic catenary (closed form, :mod:`kanat.statics.catenary`) is
the easier problem for a line between two fixed points: it is the shooting and
collocation solvers' first guess, the start of their continuation in flow speed,
and, with no flow, the solution itself (:func:`solve_catenary`). A straight line
along the body's load is the guess for a cable ending at a body.
"""
from __future__ import annotations

import numpy as np

from kanat.errors import SolverError
from kanat.statics.catenary import catenary_profile, elastic_catenary
from kanat.statics.problem import BodyEnd, CableBVP, FixedEnd
from kanat.statics.solution import CableSolution


def catenary_states(problem: CableBVP, seabed: bool, s=None):
    """Drag-free elastic catenary through the two fixed ends, along the cable's own ``s``.

    Parameters
    ----------
    problem : CableBVP
        Both ends must be :class:`FixedEnd`; the flow is ignored.
    seabed : bool
        Let the line rest on the seabed at its lower end.
    s : array_like, optional
        Stations [m]; default 201 equally spaced.

    Returns
    -------
    tuple (s, y, grounded_length) or None
        States ``y = (x, z, F_x, F_z)``, shape (4, n); None when the catenary has no
        solution (the caller then falls back to a straight guess).
    """
    s = np.linspace(0.0, problem.length, 201) if s is None else np.asarray(s, dtype=float)
    (x0, z0), (x1, z1) = problem.start.position, problem.end.position
    weight = problem.line.weight
    sense = 1.0 if weight >= 0 else -1.0                      # a buoyant line is a mirrored catenary
    start_is_lower = sense * (z1 - z0) >= 0
    (xl, zl), (xu, zu) = ((x0, z0), (x1, z1)) if start_is_lower else ((x1, z1), (x0, z0))
    direction = 1.0 if xu >= xl else -1.0
    w = max(abs(weight), 1e-12)
    try:
        cat = elastic_catenary(abs(xu - xl), sense * (zu - zl), problem.length, w,
                               problem.line.axial_stiffness, seabed=seabed, n_points=2)
    except SolverError:
        return None
    from_lower = s if start_is_lower else problem.length - s
    x, z, _ = catenary_profile(from_lower, cat.horizontal_tension, cat.vertical_tension_lower, w,
                               problem.line.axial_stiffness, cat.grounded_length)
    vertical = cat.vertical_tension_lower + w * np.clip(from_lower - cat.grounded_length, 0.0, None)
    orientation = 1.0 if start_is_lower else -1.0             # F = T dr/ds points along increasing s
    y = np.vstack([xl + direction * x, zl + sense * z,
                   orientation * direction * np.full_like(x, cat.horizontal_tension),
                   orientation * sense * vertical])
    return s, y, cat.grounded_length


def between_fixed_points(problem: CableBVP, s_out, grounded, suspended, missing=None) -> CableSolution:
    """A line between two fixed points, resting on the seabed where it must: the order in which the
    shooting and the collocation solvers try their two problems.

    1. Where the seabed is within reach (``problem.grounding()``) and the grounded catenary rests a
       length on it: ``grounded(problem, s_out, grounding, guess)`` from that catenary, kept if it
       solves with a grounded length >= 0 (the flow may lift the line off the seabed);
    2. else ``suspended(problem, s_out) -> (solution, fine_z)``, kept unless its profile ``fine_z``
       [m] dips below the seabed;
    3. then ``grounded`` from the grounded catenary, or from ``missing`` where there is none.
    """
    grounding = problem.grounding()
    if grounding is not None:
        guess = catenary_states(problem, seabed=True)
        if guess is not None and guess[2] > 0.0:
            try:
                solution = grounded(problem, s_out, grounding, guess)
                if solution.grounded_length >= 0.0:
                    return solution
            except SolverError:
                pass                              # the flow may lift the line off the seabed
    solution, fine_z = suspended(problem, s_out)
    if grounding is not None and np.min(fine_z) < problem.seabed_z - 1e-9 * problem.length:
        return grounded(problem, s_out, grounding, catenary_states(problem, seabed=True) or missing)
    return solution


def solve_catenary(problem: CableBVP, s_out=None) -> CableSolution:
    """The fast path: closed-form elastic catenary for a line between two fixed points, no flow."""
    if not all(isinstance(e, FixedEnd) for e in (problem.start, problem.end)):
        raise SolverError("the closed-form catenary needs two fixed ends (anchor, vessel, fixed point); "
                          "use the shooting or collocation method for a cable ending at a body")
    if np.any(problem.flow.velocity):
        raise SolverError("the closed-form catenary has no current or tow speed; "
                          "use the shooting or collocation method")
    s_out = np.linspace(0.0, problem.length, 101) if s_out is None else np.asarray(s_out, dtype=float)
    states = catenary_states(problem, seabed=problem.grounding() is not None, s=s_out)
    if states is None:
        raise SolverError("no catenary joins the two ends: they are farther apart than the line can "
                          "stretch to; lengthen the line or move the ends")
    _, y, grounded = states
    return CableSolution(s_out, y[0], y[1], y[2:4].T.copy(), "catenary", grounded, 0)


def straight_guess(problem: CableBVP, n: int = 51):
    """A straight cable from the fixed end along the body's load (or along the chord)."""
    s = np.linspace(0.0, problem.length, n)
    ends = (problem.start, problem.end)
    if all(isinstance(e, FixedEnd) for e in ends):
        r0, r1 = (np.asarray(e.position, dtype=float) for e in ends)
        chord = r1 - r0
        t = chord / max(np.linalg.norm(chord), 1e-12)
        tension = max(abs(problem.line.weight) * problem.length, 1.0)
        pos = r0[:, None] + np.outer(t, s) * np.linalg.norm(chord) / problem.length
        return s, np.vstack([pos, np.outer(t * tension, np.ones(n))])
    body_index = 0 if isinstance(problem.start, BodyEnd) else 1
    body, fixed = ends[body_index], ends[1 - body_index]
    r_fixed = np.asarray(fixed.position, dtype=float)
    load = body.load(problem.flow, r_fixed[1], problem.line.water_density)
    force = load if body_index == 1 else -load
    if not np.any(force):
        force = np.array([0.0, -1.0])
    t = force / np.linalg.norm(force)
    along = s if body_index == 1 else s - problem.length
    pos = r_fixed[:, None] + np.outer(t, along)
    return s, np.vstack([pos, np.outer(force, np.ones(n))])
