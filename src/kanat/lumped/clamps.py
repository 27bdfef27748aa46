"""Clamped cable ends in the lumped model: a guide node one element behind the end.

With bending stiffness a cable end is pinned (moment-free: :mod:`kanat.lumped.bending`) unless the
case says ``cables[].end_a`` (the ``from`` end) or ``end_b`` (the ``to`` end) ``{clamped: true}``.
A clamped end holds the line's direction ``c`` (unit, from the end into the line). The end's
bending triple is closed by a *guide* node ``g = x_end - l0 c``, one end-element length ``l0``
behind the end, prescribed as the end is, so that it turns with what holds the end:

* at an anchor, fixed (among ``Network.anchor_nodes``, after the anchors);
* at a vessel end, a vessel point with the lever arm ``r - l0 c`` (``c`` in vessel axes);
* at a 6-DOF body end, a fairlead of the body at ``offset - l0 c`` (``c`` in body axes), so the
  clamp's moment reaches the body as the force pair on its two fairleads.

The guide carries no element, mass or load; only the triple ``(g, end, next)`` (or
``(previous, end, g)`` at the ``to`` end), whose energy is eq. (1) of :mod:`kanat.lumped.bending`
with the turning angle ``theta`` between ``c`` and the end element's tangent ``t_0``::

    (1)  E_c = k_c (1 - c . t_0),     k_c = 2 EI / l0

``t_0`` is the line's direction at the middle of the end element, ``l0 / 2`` from the clamp, so the
curvature there is ``2 theta / l0``: the half cell's spring, as MoorDyn v2 takes a line end clamped
to a rod (``Line.cpp``, curvature ``4 sin(theta / 2) / l0`` at a cantilevered end). With ``EI / l0``
instead the cantilever's tip deflection converges at first order (tests/lumped/test_lumped_clamped.py).

The direction ``c`` is the case's ``direction`` (global at an anchor, vessel or body axes), or by
default the end element's direction in the network's first guess (the line straight or sagging
between its end positions, on the seabed where it would dip below it), turned into the vessel's
axes by the track's heading at ``t = 0`` or into the body's axes by its initial orientation.
Clamping needs something that holds a direction: an anchor, the vessel or a 6-DOF body; a free
end, a point or a 3-DOF body is refused.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.model.paths import key_path
from kanat.physics.motion import rotation_matrix

CLAMP_STIFFNESS_FACTOR = 2.0   # k_c = 2 EI / l0: the half cell between the clamp and the end element's middle


@dataclass(frozen=True)
class Clamp:
    """One clamped end: its cable's ``index``, ``end`` (0: from, 1: to), the end node and its
    neighbour along the cable, the end element's ``length`` [m] and ``stiffness`` EI [N m^2]."""

    index: int
    end: int
    node: int
    neighbour: int
    length: float
    stiffness: float


def clamped_ends(case, rows) -> list[tuple[Clamp, object, object]]:
    """The clamped ends of the cables with bending stiffness there, as ``(clamp, cable end, fixity)``;
    ``rows`` are :func:`kanat.lumped.network.build_network`'s ``(nodes, cable, grid)``.

    Raises
    ------
    CaseError
        A clamped end that is free, a point or a 3-DOF body (nothing holds a direction there).
    """
    out = []
    for index, (nodes, cable, grid) in enumerate(rows):
        for end, (where, fixity) in enumerate(((cable.from_, cable.end_a), (cable.to, cable.end_b))):
            if not fixity.clamped:
                continue
            key = ("cables", index, "end_a" if end == 0 else "end_b", "clamped")
            holder = where.kind in ("anchor", "vessel") or (
                where.kind == "body" and case.bodies[where.name].dof == 6)
            if not holder:
                raise CaseError([Problem(key_path(key), f"a clamped end needs something that holds a direction: "
                                         f"an anchor, the vessel or a dof 6 body, not {_described(where)}; "
                                         "drop clamped (a pinned end) or end the cable there")])
            element = 0 if end == 0 else len(grid.s) - 2
            section = cable.sections[grid.section[element]]
            stiffness = case.line_types[section.line_type].bending_stiffness
            if stiffness <= 0.0:
                continue                       # nothing to hold: a line without EI bends freely anyway
            node, neighbour = (nodes[0], nodes[1]) if end == 0 else (nodes[-1], nodes[-2])
            clamp = Clamp(index, end, node, neighbour, float(grid.s[element + 1] - grid.s[element]), stiffness)
            out.append((clamp, where, fixity))
    return out


def given_directions(case, rows) -> dict:
    """The clamped ends whose case gives a ``direction``: end node to the direction's global unit vector
    at ``t = 0`` (for the first guess of the cable's other end, :func:`kanat.lumped.network._guess_positions`)."""
    out = {}
    for nodes, cable, _ in rows:
        for node, where, fixity in ((nodes[0], cable.from_, cable.end_a), (nodes[-1], cable.to, cable.end_b)):
            if fixity.clamped and fixity.direction is not None:
                d = _frame(case, where) @ np.asarray(fixity.direction, float)
                out[node] = d / np.linalg.norm(d)
    return out


def _described(where) -> str:
    if where.kind == "body":
        return f"body '{where.name}' (dof 3)"
    return f"point '{where.name}'" if where.kind == "point" else "a free end"


def place_guides(builder, x: np.ndarray, clamps) -> tuple[np.ndarray, list, list]:
    """Add a guide node for each clamp to ``builder`` (:class:`kanat.lumped.network._Builder`): a vessel
    point or a body fairlead registered there, an anchor guide returned with its position. Returns
    ``x`` with the guides' rows, the anchor guides ``(node, position)`` and the bending triples
    ``(before, node, after, k, l)`` of the clamps."""
    anchors, triples = [], []
    rows = [x]
    for clamp, where, fixity in clamps:
        direction = _direction(builder.case, x, clamp, where, fixity)
        guide = x[clamp.node] - clamp.length * direction
        node = builder.node("clamp", guide)
        rows.append(guide[None, :])
        if where.kind == "anchor":
            anchors.append((node, guide))
        elif where.kind == "vessel":
            arm = np.asarray(builder.case.vessel.tow_point if where.offset is None else where.offset, float)
            builder.vessel.append((node, arm - clamp.length * _local(builder.case, direction, where)))
        else:
            offset = np.zeros(3) if where.offset is None else np.asarray(where.offset, float)
            builder.fairleads.append((node, where.name, offset - clamp.length * _local(builder.case, direction,
                                                                                      where)))
        k = CLAMP_STIFFNESS_FACTOR * clamp.stiffness / clamp.length
        before, after = (node, clamp.neighbour) if clamp.end == 0 else (clamp.neighbour, node)
        triples.append((before, clamp.node, after, k, clamp.length))
        builder.named[f"@clamp {builder.case.cables[clamp.index].name}.{'from' if clamp.end == 0 else 'to'}"] = node
    return np.vstack(rows), anchors, triples


def _direction(case, x, clamp, where, fixity) -> np.ndarray:
    """The clamp's unit direction ``c`` in the global frame at ``t = 0`` (module docstring)."""
    if fixity.direction is None:
        d = x[clamp.neighbour] - x[clamp.node]
    else:
        d = _frame(case, where) @ np.asarray(fixity.direction, float)
    return d / np.linalg.norm(d)


def _frame(case, where) -> np.ndarray:
    """The rotation (3, 3) from the end's axes to the global frame at ``t = 0``: the body's initial
    orientation, the vessel's (:func:`vessel_start`), none at an anchor."""
    if where.kind == "body":
        return rotation_matrix(*np.radians(case.bodies[where.name].orientation_deg))
    if where.kind == "vessel":
        heading, q = vessel_start(case)
        return rotation_matrix(0.0, 0.0, heading) @ rotation_matrix(*q[3:])
    return np.eye(3)


def vessel_start(case) -> tuple[float, np.ndarray]:
    """The vessel at ``t = 0``: the track's heading [rad] (0 without a track) and the prescribed motion's
    displacement (6,) (surge, sway, heave [m], roll, pitch, yaw [rad]; zeros without a motion)."""
    from kanat.physics.motion import compile_motion
    from kanat.physics.motion_samples import motion_series

    heading = 0.0
    if case.vessel.track:
        from kanat.vessel.track import VesselTrack
        heading = VesselTrack.from_model(case.vessel).state(0.0).heading
    return heading, motion_series(compile_motion(case.vessel.motion, case.environment), [0.0])[0][0]


def _local(case, direction, where) -> np.ndarray:
    """``direction`` (global) in the axes of the vessel or body that holds the end."""
    return _frame(case, where).T @ direction
