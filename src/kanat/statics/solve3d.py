"""The 3-D single-cable statics by name: shooting, collocation, or the first that works."""
from __future__ import annotations

import numpy as np

from kanat.errors import SolverError
from kanat.statics.collocation3d import solve_collocation3
from kanat.statics.shooting3d import solve_shooting3, stands_up
from kanat.statics.solution import CableSolution
from kanat.statics.spatial import Body3, CableBVP3

METHODS3 = {"shooting": solve_shooting3, "collocation": solve_collocation3}
"""3-D steady-cable solvers by name; each is ``f(problem, s_out) -> CableSolution``."""


def solve_cable3(problem: CableBVP3, method: str = "auto", s_out=None) -> CableSolution:
    """Solve one 3-D steady cable; ``auto`` tries shooting, then collocation.

    Raises
    ------
    SolverError
        When no solver can succeed (:func:`refuse_slack_in_still_water`), or none did.
    """
    refuse_slack_in_still_water(problem)
    if method in METHODS3:
        return METHODS3[method](problem, s_out)
    if method not in ("auto", "catenary"):
        raise SolverError(f"unknown 3-D statics method '{method}'; valid: auto, {', '.join(METHODS3)}")
    try:
        return solve_shooting3(problem, s_out)
    except SolverError as first:
        try:
            return solve_collocation3(problem, s_out)
        except SolverError as second:
            raise SolverError(f"{first}; collocation: {second}") from None


def refuse_slack_in_still_water(problem: CableBVP3) -> None:
    """Refuse, before any solver tries, a line from an anchor on the seabed to a free body in still water
    whose line is longer than the anchor's depth.

    Nothing pulls such a line sideways: it rises vertically under its body and the rest lies on the
    seabed with zero tension, wherever the body drifts. The single-cable steady equations need a
    tension above zero everywhere, so there is no solution to find, and the solvers search for one
    for minutes (the still-water surface mooring: 3-D shooting, then collocation up to its largest
    mesh, 45 s of CPU, 135-200 s of wall time, to fail).

    Raises
    ------
    SolverError
        Saying why, and what to use instead.
    """
    anchor = problem.grounding_anchor()
    if anchor is None or np.any(problem.flow.velocity):
        return
    body = (problem.start, problem.end)[1 - anchor]
    if not isinstance(body, Body3) or np.any(np.asarray(body.load.force, dtype=float)[:2]) or stands_up(problem):
        return
    depth = -float((problem.start, problem.end)[anchor].position[2])
    if problem.length <= depth:
        return                                   # a line shorter than the depth may stand taut
    raise SolverError(
        f"the line from the anchor to the body is slack in still water: nothing pulls it sideways, so it "
        f"rises vertically under the body and the rest of its {problem.length:.4g} m (the anchor is "
        f"{depth:.4g} m deep) lies on the seabed with zero tension, wherever the body drifts. A slack "
        "grounded line in still water has no unique single-cable steady state, which the single-cable "
        "statics and the continuum model need (a taut line). Use model: lumped, whose equilibrium "
        "(network statics) carries slack line; or give the case a current or a horizontal force on the body")
