"""The 3-D single-cable statics by name: shooting, collocation, or the first that works."""
from __future__ import annotations

from kanat.errors import SolverError
from kanat.statics.collocation3d import solve_collocation3
from kanat.statics.shooting3d import solve_shooting3
from kanat.statics.solution import CableSolution
from kanat.statics.spatial import CableBVP3

METHODS3 = {"shooting": solve_shooting3, "collocation": solve_collocation3}
"""3-D steady-cable solvers by name; each is ``f(problem, s_out) -> CableSolution``."""


def solve_cable3(problem: CableBVP3, method: str = "auto", s_out=None) -> CableSolution:
    """Solve one 3-D steady cable; ``auto`` tries shooting, then collocation."""
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
