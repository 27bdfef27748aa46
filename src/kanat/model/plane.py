"""Whether a case stays in the x–z plane: one place that says what leaves it.

The planar continuum model holds a case exactly only when nothing in it acts or moves out
of the x–z plane; ``simulation.dimensions: auto`` picks it then, and refuses it (naming each
key) when ``dimensions: 2`` is asked of a case that leaves the plane.
"""
from __future__ import annotations

import math

from ..errors import Problem
from .vessel import Heading, SpeedStep, Turn

OUT_OF_PLANE_DOFS = ("sway", "roll", "yaw")
"""Degrees of freedom of a prescribed vessel motion that leave the x–z plane."""


def out_of_plane(case, at_start: bool = False) -> list[Problem]:
    """One problem per key of ``case`` that leaves the x–z plane (empty: the case is planar).

    Parameters
    ----------
    case : kanat.model.Case
    at_start : bool
        Only what leaves the plane at t = 0, where a continuum run starts from the steady state:
        a turn (or change of heading) that comes after a segment taking time does not count.

    Returns
    -------
    list of kanat.errors.Problem
        Key path and what leaves the plane; the messages end with the remedy
        (``simulation.dimensions: 3``).
    """
    found = []
    current = case.environment.current
    rows = current.profile if current.profile is not None else [(0.0, *(current.velocity or (0.0, 0.0, 0.0)))]
    if any(row[2] for row in rows):
        found.append(("environment.current", "the current has a y component"))
    for name, body in case.bodies.items():
        if body.force[1]:
            found.append((f"bodies.{name}.force", "the force has a y component"))
    for index, cable in enumerate(case.cables):
        for key, end in (("from", cable.from_), ("to", cable.to)):
            if end.kind == "anchor" and end.position[1]:
                found.append((f"cables[{index}].{key}", "the anchor is off y = 0"))
    if case.vessel.tow_point[1]:
        found.append(("vessel.tow_point", "the tow point is off y = 0"))
    waves = case.environment.waves
    if waves is not None and abs(math.sin(math.radians(waves.heading_deg))) > 1e-9:
        found.append(("environment.waves.heading_deg", f"the waves travel at {waves.heading_deg:g} deg from +x"))
    for index, segment in enumerate(case.vessel.track):
        later = any(not isinstance(before, SpeedStep) for before in case.vessel.track[:index])
        if isinstance(segment, (Turn, Heading)) and not (at_start and later):
            found.append((f"vessel.track[{index}]", f"the vessel turns ({segment.KEY})"))
    found += _motion_out_of_plane(case.vessel.motion)
    return [Problem(key, f"{what}, which leaves the x–z plane; set simulation.dimensions: 3") for key, what in found]


def _motion_out_of_plane(motion) -> list[tuple[str, str]]:
    """``(key, what)`` for each harmonic of ``vessel.motion`` in sway, roll or yaw, or for a motion
    table with any of those columns non-zero."""
    found = [(f"vessel.motion[{index}]", f"the vessel's {h.dof} moves the tow point out of the plane")
             for index, h in enumerate(motion.harmonics) if h.dof in OUT_OF_PLANE_DOFS and h.amplitude]
    if motion.rows is not None:
        columns = {"sway": 2, "roll": 4, "yaw": 6}
        moved = [dof for dof in OUT_OF_PLANE_DOFS if any(row[columns[dof]] for row in motion.rows)]
        if moved:
            found.append(("vessel.motion", f"the motion table's {' and '.join(moved)} move the tow point out "
                                           "of the plane"))
    if motion.rao_rows is not None:
        moved = sorted({row[2] for row in motion.rao_rows if row[2] in OUT_OF_PLANE_DOFS and row[3]})
        if moved:
            found.append(("vessel.motion.rao", f"the RAOs' {' and '.join(moved)} move the tow point out of the plane"))
    return found
