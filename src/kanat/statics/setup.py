"""From a validated case to the typed steady-cable problems (the only case-aware code of statics).

Statics is planar (theory/statics.md §1): the steady tow runs along ``+x`` with the vessel at
the origin and heading 0 (its tow point at ``vessel.tow_point``), so every load must
lie in the x–z plane. Each cable is solved on its own, so a body may end one cable
only; networks of cables sharing points are the lumped model's equilibrium (theory/moorings.md §1).
"""
from __future__ import annotations

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.statics.problem import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties

PLANAR_TOL = 1e-12


def vessel_velocity(case) -> np.ndarray:
    """Velocity of the vessel at t = 0 in the global frame [m/s], shape (3,)."""
    return np.array([case.vessel.initial_speed, 0.0, 0.0])


def cable_problems(case) -> dict[str, CableBVP]:
    """The steady problem of every cable in ``case``, keyed by cable name.

    Raises
    ------
    CaseError
        Listing every cable that statics cannot take (out-of-plane loads, free ends,
        shared bodies, network points), with its key path.
    """
    problems, issues = {}, []
    owners: dict[str, str] = {}
    for index, cable in enumerate(case.cables):
        key = f"cables[{index}]"
        for end_key, end in (("from", cable.from_), ("to", cable.to)):
            if end.kind == "body":
                if end.name in owners:
                    issues.append(Problem(f"{key}.{end_key}", f"body '{end.name}' also ends cable "
                                          f"'{owners[end.name]}'; statics solves one cable per body "
                                          "(networks arrive with the lumped model's equilibrium)"))
                owners[end.name] = cable.name
        try:
            problems[cable.name] = _cable_problem(case, index)
        except CaseError as error:
            issues.extend(error.problems)
    if issues:
        raise CaseError(issues)
    return problems


def _cable_problem(case, index: int) -> CableBVP:
    cable = case.cables[index]
    env = case.environment
    line_type = case.line_types[cable.line_type]
    line = LineProperties(weight=line_type.weight_in_water_value(env.water_density, env.gravity),
                          axial_stiffness=line_type.axial_stiffness, diameter=line_type.diameter,
                          drag_normal=line_type.drag_normal, drag_tangential=line_type.drag_tangential,
                          water_density=env.water_density)
    start = _end(case, cable.from_, f"cables[{index}].from")
    end = _end(case, cable.to, f"cables[{index}].to")
    seabed = -env.depth if env.depth is not None else None
    return CableBVP(line, cable.length, start, end, flow_profile(case), seabed)


def flow_profile(case) -> FlowProfile:
    """Water velocity relative to the steadily towed frame: current minus vessel velocity."""
    current = case.environment.current
    ship = vessel_velocity(case)
    if current.profile is None:
        rows = np.array([[0.0, *(current.at(0.0) - ship)]])
    else:
        table = np.asarray(current.profile, dtype=float)[::-1]     # ascending z
        rows = np.column_stack([table[:, 0], table[:, 1:4] - ship])
    if np.any(np.abs(rows[:, 2]) > PLANAR_TOL):
        raise CaseError([Problem("environment.current", "statics is planar (x–z plane) but the current has "
                                 f"a y component up to {np.max(np.abs(rows[:, 2])):.3g} m/s; set the y "
                                 "components to 0, or run a 3-D dynamic model")])
    return FlowProfile(rows[:, 0], rows[:, [1, 3]])


def _end(case, end, key: str):
    if end.kind == "vessel":
        return FixedEnd(_planar(case.vessel.tow_point, "vessel.tow_point"))
    if end.kind == "anchor":
        return FixedEnd(_planar(end.position, key))
    if end.kind == "body":
        body = case.bodies[end.name]
        fx, fy, fz = body.force
        if abs(fy) > PLANAR_TOL:
            raise CaseError([Problem(f"bodies.{end.name}.force", f"statics is planar (x–z plane) but the "
                                     f"force has a y component of {fy:g} N; set it to 0 for statics")])
        return BodyEnd(body.net_buoyancy, body.drag_area, (fx, fz))
    reason = {"free": "a free end carries no tension, so its steady direction is undefined; "
                      "end the cable at a body (a small drogue) to solve its statics",
              "point": f"point '{end.name}' joins a network of cables; network statics arrive "
                       "with the lumped model's equilibrium"}[end.kind]
    raise CaseError([Problem(key, reason)])


def _planar(xyz, key: str) -> tuple[float, float]:
    x, y, z = xyz
    if abs(y) > PLANAR_TOL:
        raise CaseError([Problem(key, f"statics is planar (x–z plane) but y = {y:g} m; set y = 0")])
    return float(x), float(z)
