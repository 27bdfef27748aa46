"""Statics of a case: one registry of methods, one entry point (theory/statics.md)."""
from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import SolverError
from kanat.statics.budget import budget
from kanat.model.support import has_drag, needs_network, require_supported, single_cable
from kanat.statics.collocation import solve_collocation
from kanat.statics.guess import solve_catenary
from kanat.statics.network_setup import NeedsBending, NeedsDrag
from kanat.statics.problem import CableBVP, FixedEnd
from kanat.statics.setup import cable_problems, vessel_velocity
from kanat.statics.shooting import solve_shooting
from kanat.statics.solution import CableSolution
from kanat.statics.sphere import SphereGroups, SphereSolution, groups_from_dimensional
from kanat.statics.sphere_solvers import solve_sphere
from kanat.statics.steady_checks import check_result

METHODS = {
    "shooting": solve_shooting,
    "collocation": solve_collocation,
    "catenary": solve_catenary,
}
"""Steady-cable solvers by name; each is ``f(problem, s_out) -> CableSolution``."""

log = logging.getLogger(__name__)


def solve_cable(problem: CableBVP, method: str = "auto", s_out=None) -> CableSolution:
    """Solve one steady cable with a named method.

    ``"auto"`` picks the fastest method that applies (benchmarks/RESULTS.md): the
    closed-form catenary for two fixed ends, no flow and a line heavier than water;
    shooting for a cable ending at a body (a single integration in a uniform flow);
    collocation between fixed points in a flow. If that method fails, it tries the other
    numerical one.
    """
    if method != "auto":
        try:
            solver = METHODS[method]
        except KeyError:
            raise SolverError(f"unknown statics method '{method}'; valid: auto, {', '.join(METHODS)}") from None
        return solver(problem, s_out)
    fixed = all(isinstance(e, FixedEnd) for e in (problem.start, problem.end))
    if fixed and not np.any(problem.flow.velocity) and problem.line.weight > 0:
        log.debug("statics method auto: catenary (two fixed ends, still water, a line heavier than water)")
        return solve_catenary(problem, s_out)
    first, second = ("collocation", "shooting") if fixed else ("shooting", "collocation")
    log.debug(f"statics method auto: {first} ({'two fixed ends in a flow' if fixed else 'a cable ending at a body'})")
    try:
        return METHODS[first](problem, s_out)
    except SolverError as error:
        log.info(f"statics: {first} did not solve the cable ({error}); trying {second}")
        return METHODS[second](problem, s_out)


@dataclass(frozen=True)
class StaticsResult:
    """The steady state of a case.

    Attributes
    ----------
    case : kanat.model.Case
    method : str
        Method requested (``auto``, a name of :data:`METHODS`).
    cables : dict of str to CableSolution
        One solution per cable, at the cable's nodes.
    bodies : dict of str to ndarray, shape (3,)
        Body positions [m].
    vessel_velocity : ndarray, shape (3,)
        Velocity of the steadily moving frame (the vessel) [m/s]; every node moves with it.
    sphere : SphereSolution or None
        The Naumov & Agievich problem's solution, for a ``sphere_two_cables`` case.
    """

    case: object
    method: str
    cables: dict[str, CableSolution] = field(default_factory=dict)
    bodies: dict[str, np.ndarray] = field(default_factory=dict)
    vessel_velocity: np.ndarray = field(default_factory=lambda: np.zeros(3))
    sphere: SphereSolution | None = None

    @property
    def anchor_forces(self) -> dict[str, np.ndarray]:
        """Force of each cable on its anchors, named by cable end (``mooring.from``) [N], shape (3,)."""
        return {f"{cable.name}.{label}": force for cable, label, force in self._end_forces()
                if (cable.from_ if label == "from" else cable.to).kind == "anchor"}

    @property
    def body_forces(self) -> dict[str, np.ndarray]:
        """Resultant force of the cables on each body [N], shape (3,)."""
        out: dict[str, np.ndarray] = {}
        for cable, label, force in self._end_forces():
            end = cable.from_ if label == "from" else cable.to
            if end.kind == "body":
                out[end.name] = out.get(end.name, np.zeros(3)) + force
        return out

    def _end_forces(self):
        """``(cable, "from" | "to", force of the cable on that end)``; ``F = T t`` pulls the
        ``from`` end along ``+t`` and the ``to`` end along ``-t``."""
        for cable in self.case.cables if self.sphere is None else ():
            sol = self.cables[cable.name]
            for label, row, sign in (("from", 0, 1.0), ("to", -1, -1.0)):
                yield cable, label, sign * sol.force3[row]

    @property
    def verdict(self):
        """The checks of a steady state on this result (:func:`kanat.statics.steady_checks.check_result`):
        its ``status`` is ``ok`` or ``failed: <check>: ...``."""
        return check_result(self)

    def summary(self) -> str:
        """A few lines an engineer reads first: depths, layback, end tensions."""
        lines = []
        if self.sphere is not None:
            sol = self.sphere
            lines.append(f"sphere on two cables ({sol.convention} convention, {sol.method}): "
                         f"alpha(0) = {np.degrees(sol.alpha0):.4f} deg, tau(0) = {sol.tau0:.6f}, "
                         f"eps1 = {sol.eps1_percent:.2e} %, eps2 = {sol.eps2_percent:.2e} %, "
                         f"sphere at x = {sol.x_A:.4f}, y = {sol.y_A:.4f} (units of L)")
            lines += [f"warning: {w}" for w in sol.physical_warnings]
        for name, sol in self.cables.items():
            tension = sol.tension
            lines.append(f"cable {name} ({sol.method}): tension {tension[0] / 1e3:.3f} kN at s = 0, "
                         f"{tension[-1] / 1e3:.3f} kN at s = {sol.s[-1]:g} m; leaves s = 0 at "
                         f"{np.degrees(np.arctan2(-sol.force3[0, 2], np.hypot(*sol.force3[0, :2]))):.2f} deg "
                         "below the horizontal"
                         + (f"; {sol.grounded_length:.2f} m on the seabed" if sol.grounded_length > 0 else ""))
        for name, position in self.bodies.items():
            y = f"y = {position[1]:.3f} m, " if position[1] else ""
            lines.append(f"body {name}: x = {position[0]:.3f} m, {y}z = {position[2]:.3f} m (depth "
                         f"{-position[2]:.3f} m)")
        return "\n".join(lines)


def solve_statics(case, method: str = "auto") -> StaticsResult:
    """Steady state of a case: its cables (theory/statics.md §1) or its Naumov & Agievich problem (theory/statics.md §3).

    Parameters
    ----------
    case : kanat.model.Case
    method : str
        ``auto`` or a name of :data:`METHODS` (the Naumov & Agievich problem takes
        ``shooting`` or ``collocation``; ``auto`` means shooting).

    Returns
    -------
    StaticsResult
    """
    if case.sphere_two_cables is not None:
        with budget("the statics of the sphere on two cables"):
            return StaticsResult(case, method, sphere=_solve_sphere_block(case.sphere_two_cables, case, method))
    require_supported(case, "statics")
    bent = [name for name, line in case.line_types.items() if line.bending_stiffness > 0]
    if bent:
        if method != "auto":
            raise SolverError(f"method '{method}' finds perfectly flexible lines, and line type '{bent[0]}' has "
                              "bending_stiffness; use method auto (the lumped model's equilibrium, with the "
                              "bending)")
        raise NeedsBending(f"line type '{bent[0]}' has bending stiffness, which the lumped equilibrium includes")
    if needs_network(case):
        if has_drag(case) and single_cable(case):
            log.debug("statics: one cable in 3-D (sections, attachments or a cross current)")
            with budget(f"the statics of cable '{case.cables[0].name}'"):
                return _solve_single_3d(case, method)
        log.debug("statics: a network (points, shared bodies, fairleads or sections), solved as a whole")
        with budget("the network statics"):
            return _solve_network(case, method)
    problems = cable_problems(case)
    solutions, bodies = {}, {}
    for cable in case.cables:
        problem = problems[cable.name]
        s_out = np.linspace(0.0, cable.length, cable.segments + 1)
        with budget(f"the statics of cable '{cable.name}'"):
            solution = solve_cable(problem, method, s_out)
        solutions[cable.name] = solution
        for end, index in ((cable.from_, 0), (cable.to, -1)):
            if end.kind == "body":
                bodies[end.name] = solution.position[index]
    return StaticsResult(case, method, solutions, bodies, vessel_velocity(case))


def stations(cable) -> np.ndarray:
    """The nodes of a cable: ``segments`` equal steps, and each attachment's arclength twice (the state
    before and after the body's jump)."""
    s = list(np.linspace(0.0, cable.length, cable.segments + 1))
    for item in cable.attachments:
        at = int(np.searchsorted(s, item.s))
        on_node = at < len(s) and abs(s[at] - item.s) <= 1e-9 * cable.length
        s[at:at] = [item.s] if on_node else [item.s, item.s]
    return np.array(s)


def _solve_single_3d(case, method: str) -> StaticsResult:
    """One cable in 3-D with sections, attachments, a current in x and y (:mod:`kanat.statics.solve3d`)."""
    from kanat.statics.setup3d import cable_problem3
    from kanat.statics.solve3d import solve_cable3

    cable = case.cables[0]
    s_out = stations(cable)
    solution = solve_cable3(cable_problem3(case), method, s_out)
    bodies = {end.name: solution.position[index] for end, index in ((cable.from_, 0), (cable.to, -1))
              if end.kind == "body"}
    for item in cable.attachments:
        bodies[item.body] = solution.position[int(np.searchsorted(s_out, item.s))]
    return StaticsResult(case, method, {cable.name: solution}, bodies, vessel_velocity(case))


def _solve_network(case, method: str):
    """Network statics (:mod:`kanat.statics.network`): still water only."""
    from kanat.statics.network_result import solve_network_case

    if has_drag(case):
        raise NeedsDrag("network statics solves catenary lines, which carry no drag: "
                        + ("the vessel's initial speed" if case.vessel.initial_speed else "the current")
                        + " needs the lumped model's equilibrium (kanat.solve_statics and kanat statics "
                        "use it for such a case)")
    if method not in ("auto", "catenary"):
        raise SolverError(f"method '{method}' solves single cables in the x-z plane; this case is a 3-D "
                          "network (points, shared bodies, fairleads, sections, ...): use auto or catenary")
    return solve_network_case(case, "catenary")


def _solve_sphere_block(block, case, method: str) -> SphereSolution:
    method = "shooting" if method == "auto" else method
    if block.dimensionless is not None:
        groups, scales = SphereGroups(**block.dimensionless.model_dump()), None
    else:
        inputs = block.dimensional.model_dump()
        inputs["water_density"] = inputs["water_density"] or case.environment.water_density
        groups, scales = groups_from_dimensional(**inputs)
    return solve_sphere(groups, block.convention, method, block.n_nodes, scales=scales)
