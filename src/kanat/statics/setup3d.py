"""From a validated case to the 3-D steady problem of its single cable (:mod:`kanat.statics.spatial`).

The steady tow runs along ``+x`` with the vessel at the origin and heading 0 (its tow point at
``vessel.tow_point``): the water seen by the cable is the current (x, y and z components, a
depth profile) minus the vessel's velocity. Sections become pieces with their own line type; an
attachment splits its piece and adds its body as a jump; end bodies are 3-DOF bodies (a surface
buoy's waterplane included). The seabed is ``environment.depth`` with ``seabed.slope_deg`` and
``seabed.friction`` (rigid in statics).
"""
from __future__ import annotations

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.statics.problem import LineProperties
from kanat.statics.setup import vessel_velocity
from kanat.statics.spatial import Body3, CableBVP3, Fixed3, Flow3, Load, Piece, RigidSeabed


def flow_profile3(case) -> Flow3:
    """Water velocity relative to the steadily towed frame (3 components), heights ascending."""
    z, rows = case.environment.current.table()
    return Flow3(np.asarray(z, dtype=float), np.asarray(rows, dtype=float) - vessel_velocity(case))


def body_load(case, name: str) -> Load:
    """The statics load of body ``name``."""
    body, env = case.bodies[name], case.environment
    buoy = body.surface_buoy
    waterplane = 0.0 if buoy is None else env.water_density * env.gravity * buoy.waterplane_area
    return Load(body.net_buoyancy, body.drag_area, tuple(float(f) for f in body.force), waterplane,
                0.0 if buoy is None else buoy.height, body.diameter or 0.0,
                body.buoyancy(env.gravity) if body.diameter else 0.0)


def line_properties(case, line_type: str) -> LineProperties:
    env = case.environment
    lt = case.line_types[line_type]
    return LineProperties(weight=lt.weight_in_water_value(env.water_density, env.gravity),
                          axial_stiffness=lt.axial_stiffness, diameter=lt.diameter, drag_normal=lt.drag_normal,
                          drag_tangential=lt.drag_tangential, water_density=env.water_density)


def _end(case, end, key: str):
    if end.kind == "vessel" and end.offset is None:
        return Fixed3(tuple(float(c) for c in case.vessel.tow_point))
    if end.kind == "anchor":
        return Fixed3(tuple(float(c) for c in end.position))
    if end.kind == "body" and end.offset is None and case.bodies[end.name].dof == 3:
        return Body3(body_load(case, end.name))
    reason = {"free": "a free end carries no tension, so its steady direction is undefined; end the cable at a "
                      "small body (a drogue) to solve its statics",
              "point": f"point '{end.name}' joins a network of cables (network statics solves it)"}.get(
        end.kind, "a fairlead or a 6-DOF body is network statics' (kanat statics CASE solves it)")
    raise CaseError([Problem(key, reason)])


def cable_problem3(case, index: int = 0) -> CableBVP3:
    """The 3-D steady problem of ``case.cables[index]`` (module docstring)."""
    cable = case.cables[index]
    key = f"cables[{index}]"
    cuts = sorted({a.s for a in cable.attachments})
    pieces = []
    for section, (a, b) in zip(cable.sections, cable.section_bounds()):
        line = line_properties(case, section.line_type)
        points = [a, *[s for s in cuts if a < s < b], b]
        pieces += [Piece(line, lo, hi) for lo, hi in zip(points[:-1], points[1:])]
    for i, item in enumerate(cable.attachments):
        if item.s <= 0.0 or item.s >= cable.length:
            raise CaseError([Problem(f"{key}.attachments[{i}].s", "an attachment at a cable end is that end's "
                                     "body: write it as the end ('from' or 'to') instead")])
    joints = tuple((a.s, body_load(case, a.body)) for a in cable.attachments)
    env = case.environment
    seabed = None
    if env.depth is not None:
        sb = env.seabed
        seabed = RigidSeabed(env.depth, sb.slope_deg if sb else 0.0, sb.friction if sb else 0.0)
    return CableBVP3(tuple(pieces), joints, _end(case, cable.from_, f"{key}.from"), _end(case, cable.to, f"{key}.to"),
                     flow_profile3(case), seabed)
