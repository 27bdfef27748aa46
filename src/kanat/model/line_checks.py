"""Checks of a case's lines, bodies and anchors (part of :data:`kanat.model.checks.CHECKS`): weights,
placements against the seabed, spans between fixed ends, static loads of hanging bodies and
mooring buoys, element lengths, and bodies or points no cable uses."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ._base import fmt
from .cable import Cable, CableEnd
from .findings import Findings, kn

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

MAX_STRETCH = 0.20          # strain beyond which fixed ends are an error, not a warning
MAX_STATIC_STRAIN = 0.10    # static strain of a hanging system considered unphysical


def _end_position(case: Case, end: CableEnd) -> tuple[float, float, float] | None:
    """Initial global position of a fixed end: an anchor, or a vessel point (its own ``offset``, else
    the tow point) at t = 0, moved by the prescribed motion's translation there (rotations left out)."""
    if end.kind == "anchor":
        return tuple(end.position)
    if end.kind == "vessel":  # vessel at the origin, heading 0: vessel axes = global axes
        point = end.offset if end.offset is not None else case.vessel.tow_point
        return tuple(float(p + q) for p, q in zip(point, _motion_at_start(case)))
    return None


def _motion_at_start(case: Case) -> tuple[float, float, float]:
    """Surge, sway and heave of ``vessel.motion`` at t = 0 [m] (zeros without one)."""
    block = case.vessel.motion
    if not block.is_used:                                    # (no arrays, nor NumPy, for a case without one)
        return (0.0, 0.0, 0.0)
    from ..physics.motion import compile_motion, motion_at

    return tuple(float(q) for q in motion_at(compile_motion(block, case.environment), 0.0)[0][:3])


def _line_weight(case: Case, cable: Cable) -> float:
    """Weight in water of the whole cable [N], section by section."""
    env = case.environment
    return sum(case.line_types[s.line_type].weight_in_water_value(env.water_density, env.gravity) * s.length
               for s in cable.sections)


def check_line_types(case: Case, out: Findings) -> None:
    """A line cannot weigh more in water than in air."""
    g = case.environment.gravity
    for name, line in case.line_types.items():
        in_air = line.mass * g
        if line.weight_in_water is not None and line.weight_in_water > in_air:
            out.error(("line_types", name, "weight_in_water"),
                      f"weight in water {fmt(line.weight_in_water)} N/m exceeds the weight in "
                      f"air {in_air:.4g} N/m (mass {fmt(line.mass)} kg/m × g {fmt(g)} m/s^2); "
                      "buoyancy cannot be negative")


def check_bodies(case: Case, out: Findings) -> None:
    """Net buoyancy cannot be below minus the weight in air (negative displacement)."""
    g = case.environment.gravity
    for name, body in case.bodies.items():
        weight = body.mass * g
        if body.net_buoyancy < -weight:
            out.error(("bodies", name, "net_buoyancy"),
                      f"net buoyancy {fmt(body.net_buoyancy)} N is below -(mass × g) = "
                      f"{-weight:.6g} N (mass {fmt(body.mass)} kg): that needs a negative "
                      "buoyancy; net_buoyancy is buoyancy minus weight")


def check_anchors(case: Case, out: Findings) -> None:
    """Anchors lie between the seabed (a sloped one where ``seabed.slope_deg``) and the free surface."""
    if not any(end.kind == "anchor" for cable in case.cables for end in cable.ends):
        return                                  # (the seabed model, NumPy and all, loads for anchors only)
    from ..physics.seabed import seabed_of

    depth = case.environment.depth
    seabed = seabed_of(case.environment)
    for i, cable in enumerate(case.cables):
        for key, end in (("from", cable.from_), ("to", cable.to)):
            if end.kind != "anchor":
                continue
            z = end.position[2]
            floor = None if seabed is None else float(seabed.height(end.position[0], end.position[1]))
            if floor is not None and z < floor - 1e-9 * depth:
                out.error(("cables", i, key),
                          f"anchor at z = {fmt(z)} m is below the seabed at z = {fmt(floor)} m "
                          f"(depth {fmt(depth)} m at x = 0)")
            elif z > 0:
                out.warning(("cables", i, key),
                            f"anchor at z = {fmt(z)} m is above the free surface z = 0")


def check_positions_above_seabed(case: Case, out: Findings) -> None:
    """A body's or a point's given position lies above the seabed (the solvers would start it
    inside the ground and fail later as an element "stretched by 1510 %")."""
    placed = [(("bodies", name, "position"), f"body '{name}'", body.position)
              for name, body in case.bodies.items() if body.position is not None]
    placed += [(("points", name, "position"), f"point '{name}'", getattr(point, "position", None))
               for name, point in case.points.items() if getattr(point, "position", None) is not None]
    if not placed or case.environment.depth is None:
        return
    from ..physics.seabed import seabed_of

    depth = case.environment.depth
    seabed = seabed_of(case.environment)
    for path, what, position in placed:
        floor = float(seabed.height(position[0], position[1]))
        if position[2] < floor - 1e-9 * depth:
            out.error(path, f"{what} at z = {fmt(position[2])} m is {fmt(floor - position[2])} m below the "
                      f"seabed at z = {fmt(floor)} m (depth {fmt(depth)} m): place it in the water, "
                      f"above z = {fmt(floor)} m, or deepen environment.depth")


def check_fixed_span(case: Case, out: Findings) -> None:
    """A cable between two fixed ends must be long enough to reach both."""
    for i, cable in enumerate(case.cables):
        a, b = (_end_position(case, end) for end in cable.ends)
        if a is None or b is None:
            continue
        span = math.dist(a, b)
        if span <= cable.length:
            continue
        line = case.line_types[cable.line_type]
        strain = span / cable.length - 1.0
        tension = line.axial_stiffness * strain
        message = (f"its fixed ends ({cable.from_}, {cable.to}) are {span:.6g} m apart but it is "
                   f"{fmt(cable.length)} m long: it must stretch {100 * strain:.3g} %, a tension "
                   f"of {kn(tension)} (EA {kn(line.axial_stiffness)} × strain {strain:.4g})")
        too_far = strain > MAX_STRETCH
        broken = line.breaking_load is not None and tension > line.breaking_load
        if broken:
            message += f", above the breaking load {kn(line.breaking_load)}"
        if too_far:
            message += f"; more than {MAX_STRETCH:.0%} stretch is not a cable"
        (out.error if too_far or broken else out.warning)(("cables", i, "length"), message)


def _hanging_load(case: Case, cable: Cable, body_name: str) -> tuple[float, float, float]:
    """Body pull, cable weight and largest static tension of a body hanging on a cable [N]."""
    pull = case.bodies[body_name].submerged_weight()
    weight = _line_weight(case, cable)
    return pull, weight, max(abs(pull), abs(pull + weight))


def check_hanging_loads(case: Case, out: Findings) -> None:
    """A body on a cable from the vessel or an anchor must not break or overstretch it."""
    for i, cable in enumerate(case.cables):
        for body_end, other in ((cable.to, cable.from_), (cable.from_, cable.to)):
            if body_end.kind != "body" or not other.is_fixed:
                continue
            line = case.line_types[cable.line_type]
            pull, weight, tension = _hanging_load(case, cable, body_end.name)
            what = "submerged weight" if pull >= 0 else "net buoyancy"
            load = (f"body '{body_end.name}' ({what} {kn(abs(pull))}) and the cable's weight "
                    f"in water {kn(weight)} ({weight / cable.length:.4g} N/m × "
                    f"{fmt(cable.length)} m) give a static tension of up to {kn(tension)}")
            if line.breaking_load is not None and tension > line.breaking_load:
                out.error(("cables", i), f"{load}, above the breaking load "
                          f"{kn(line.breaking_load)} of line type '{cable.line_type}'")
            strain = tension / line.axial_stiffness
            if strain > MAX_STATIC_STRAIN:
                out.error(("cables", i), f"{load}: a static strain of {100 * strain:.3g} % "
                          f"(EA {kn(line.axial_stiffness)}), more than "
                          f"{MAX_STATIC_STRAIN:.0%}; check axial_stiffness (N) and the loads")


def check_mooring_buoys(case: Case, out: Findings) -> None:
    """A buoy held only by anchored lines must lift their weight in water."""
    by_body: dict[str, list[Cable]] = {}
    for cable in case.cables:
        for name in dict.fromkeys(e.name for e in cable.ends if e.kind == "body"):
            by_body.setdefault(name, []).append(cable)
    for name, body in case.bodies.items():
        attached = by_body.get(name, [])
        if not attached or not all(any(e.kind == "anchor" for e in c.ends) for c in attached):
            continue
        weight = sum(_line_weight(case, c) for c in attached)
        if case.environment.seabed is not None:      # chain may rest on the seabed: only what must hang
            weight = sum(_hanging_at_least(case, c) for c in attached)
        lift = body.net_buoyancy
        buoy = body.surface_buoy
        if buoy is not None:                          # its hull, immersed to the deck, lifts this much more
            env = case.environment
            lift += env.water_density * env.gravity * buoy.waterplane_area * buoy.height
        if weight > 0 and lift < weight:
            names = ", ".join(f"'{c.name}'" for c in attached)
            hull = "" if buoy is None else f" and {lift - body.net_buoyancy:.6g} N more from its hull awash"
            out.warning(("bodies", name, "net_buoyancy"),
                        f"buoy '{name}' has net buoyancy {fmt(body.net_buoyancy)} N{hull}, less than "
                        f"the weight in water {weight:.6g} N of its mooring line(s) {names}: "
                        "it will sink")


def _hanging_at_least(case: Case, cable: Cable) -> float:
    """Weight in water of the least length of ``cable`` that must hang off the seabed [N]: the
    height of its body end above the anchor, in its lightest line type (the rest may rest on
    the seabed)."""
    env = case.environment
    anchors = [e.position[2] for e in cable.ends if e.kind == "anchor"]
    body = next((case.bodies[e.name] for e in cable.ends if e.kind == "body"), None)
    if not anchors or body is None or body.position is None:
        return 0.0
    lightest = min(case.line_types[s.line_type].weight_in_water_value(env.water_density, env.gravity)
                   for s in cable.sections)
    return max(lightest, 0.0) * min(max(body.position[2] - min(anchors), 0.0), cable.length)


def check_element_length(case: Case, out: Findings) -> None:
    """Elements shorter than the cable diameter are pointless and stiff."""
    for i, cable in enumerate(case.cables):
        diameter = case.line_types[cable.line_type].diameter
        element = cable.length / cable.segments
        if element < diameter:
            out.warning(("cables", i, "segments"),
                        f"elements are {element:.3g} m long ({fmt(cable.length)} m / "
                        f"{cable.segments} segments), shorter than the diameter {fmt(diameter)} m "
                        f"of line type '{cable.line_type}'; use at most "
                        f"{max(1, math.floor(cable.length / diameter))} segments")


def check_clamps(case: Case, out: Findings) -> None:
    """A clamped end (``cables[].end_a/end_b``) needs something that holds a direction (an anchor, the
    vessel or a dof 6 body) and bending stiffness at that end, without which it holds nothing."""
    for i, cable in enumerate(case.cables):
        for key, end, section in (("end_a", cable.from_, cable.sections[0]), ("end_b", cable.to, cable.sections[-1])):
            if not getattr(cable, key).clamped:
                continue
            rigid = end.kind == "body" and end.name in case.bodies and case.bodies[end.name].dof == 6
            if end.kind not in ("anchor", "vessel") and not rigid:
                what = "a free end" if end.kind == "free" else f"{end.kind} '{end.name}'"
                out.error(("cables", i, key, "clamped"), f"a clamped end needs something that holds a direction: "
                          f"an anchor, the vessel or a dof 6 body, not {what}; drop clamped (a pinned end)")
            elif section.line_type in case.line_types and case.line_types[section.line_type].bending_stiffness <= 0:
                out.warning(("cables", i, key, "clamped"), f"line type '{section.line_type}' has no "
                            "bending_stiffness, so the clamp holds nothing: the end bends freely")


def check_attachments(case: Case, out: Findings) -> None:
    """Bodies and points that no cable uses are ignored."""
    if not case.cables:
        return
    used = {(e.kind, e.name) for c in case.cables for e in c.ends}
    used |= {("body", a.body) for c in case.cables for a in c.attachments}
    for group, kind, items in (("bodies", "body", case.bodies), ("points", "point", case.points)):
        for name in items:
            if (kind, name) not in used:
                out.warning((group, name), f"{kind} '{name}' is not attached to any cable and "
                            "is ignored")
