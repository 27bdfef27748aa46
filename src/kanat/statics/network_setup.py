"""From a validated case to the typed network of catenary lines (the case-aware part of
network statics, :mod:`kanat.statics.network`).

The unknowns are the free nodes: network points and point bodies (3 degrees of freedom,
their position) and rigid bodies (``dof: 6``: position of the reference point and the
angles roll, pitch, yaw of ``R = Rz(yaw) Ry(pitch) Rx(roll)``). Anchors, the tow point and
the vessel's fairleads are fixed (the vessel at the origin with heading 0, its mean
position). Each cable is one line of :class:`~kanat.statics.piecewise.Pieces` from its
``from`` end to its ``to`` end: one piece per section, split at every attachment, whose
net weight in water becomes a point load at that joint.

What the catenary cannot carry is refused here with the key that uses it: a current or a
tow speed (:class:`NeedsDrag`, so that the front door can hand the case to the lumped
model's equilibrium), an attached body with a horizontal force.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import CaseError, Problem, SolverError
from kanat.physics.seabed import PlaneSeabed, seabed_of
from kanat.statics.piecewise import Pieces

__all__ = ["NeedsDrag", "NetworkLine", "NetworkNode", "NetworkProblem", "LineEnd", "network_problem"]

ON_SEABED = 1e-6          # an anchor within this many metres (per metre of depth) of the seabed rests on it
END_FRACTION = 1e-9       # an attachment within this fraction of the length of an end loads that end


class NeedsLumped(SolverError):
    """The case needs what the statics solvers do not model; the front door (:mod:`kanat.api`)
    solves it by the lumped model's equilibrium instead."""


class NeedsDrag(NeedsLumped):
    """The case has a current or a tow speed, which the catenary lines cannot carry."""


class NeedsBending(NeedsLumped):
    """A line has bending stiffness, which the statics solvers leave out (perfectly flexible lines)."""


@dataclass(frozen=True, eq=False)
class NetworkNode:
    """A free node: a network point, a point body or a rigid body.

    Attributes
    ----------
    name : str
    kind : {"point", "body"}
    dof : {3, 6}
    position : ndarray, shape (3,) or None
        Given position (a guess, or a 6-DOF body's hydrostatic reference) [m].
    orientation : ndarray, shape (3,)
        Roll, pitch, yaw [rad] (6-DOF bodies: the guess and the hydrostatic reference).
    force : ndarray, shape (3,)
        Constant force at the reference point [N]: net buoyancy and ``force`` (3-DOF), or the
        external ``force`` only (6-DOF).
    weight, buoyancy : float
        6-DOF: ``m g`` at the centre of gravity and ``net_buoyancy + m g`` at the centre of
        buoyancy [N].
    cog, cob : ndarray, shape (3,)
        6-DOF: centres of gravity and buoyancy in body axes [m].
    hydrostatic : ndarray, shape (6, 6)
        6-DOF: hydrostatic stiffness about the reference point (zeros when none).
    tilt_in_stiffness : bool
        6-DOF: True when the hydrostatics restore roll or pitch (:attr:`Body.tilt_in_stiffness`: the
        metacentric height holds the levers of weight and buoyancy along the body's vertical, and
        their offsets across it turn the body); False: the whole levers turn it
        (:mod:`kanat.physics.hydrostatics` eq. 3).
    """

    name: str
    kind: str
    dof: int
    position: np.ndarray | None
    orientation: np.ndarray = field(default_factory=lambda: np.zeros(3))
    force: np.ndarray = field(default_factory=lambda: np.zeros(3))
    weight: float = 0.0
    buoyancy: float = 0.0
    cog: np.ndarray = field(default_factory=lambda: np.zeros(3))
    cob: np.ndarray = field(default_factory=lambda: np.zeros(3))
    hydrostatic: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    tilt_in_stiffness: bool = False


@dataclass(frozen=True, eq=False)
class LineEnd:
    """A cable end: a fixed point, or a free node with an offset.

    Attributes
    ----------
    node : int
        Index of the free node, or -1 for a fixed end.
    point : ndarray, shape (3,)
        The fixed end's global position, or the fairlead offset in the node's axes [m].
    kind : str
        ``anchor``, ``vessel``, ``point`` or ``body``.
    on_seabed : bool
        A fixed end resting on the seabed (the line may lie on the seabed from it).
    load : float
        Downward load of attachments clamped at this end [N].
    """

    node: int
    point: np.ndarray
    kind: str
    on_seabed: bool = False
    load: float = 0.0


@dataclass(frozen=True, eq=False)
class NetworkLine:
    """One cable as a catenary line from its ``from`` end to its ``to`` end.

    Attributes
    ----------
    name : str
    pieces : Pieces
        From ``from`` to ``to``.
    ends : tuple of LineEnd
        ``(from, to)``.
    stations : ndarray, shape (segments + 1,)
        Output nodes' unstretched arclength from ``from`` (even spacing per section) [m].
    """

    name: str
    pieces: Pieces
    ends: tuple[LineEnd, LineEnd]
    stations: np.ndarray

    @property
    def grounded_end(self) -> int | None:
        """0 or 1: the end whose fixed point rests on the seabed (``from`` first), else None."""
        for index, end in enumerate(self.ends):
            if end.node < 0 and end.on_seabed:
                return index
        return None


@dataclass(frozen=True, eq=False)
class NetworkProblem:
    """The network of a case, ready for :func:`kanat.statics.network.solve_network`.

    Attributes
    ----------
    nodes : list of NetworkNode
    lines : list of NetworkLine
    seabed : PlaneSeabed or None
    friction : float
        Coulomb coefficient along the lines on the seabed (MoorPy's ``CB``).
    gravity : float
    """

    nodes: list
    lines: list
    seabed: PlaneSeabed | None
    friction: float
    gravity: float
    offsets: np.ndarray = field(init=False, repr=False)
    """First unknown of each node in the vector of unknowns, and their total, shape (n + 1,)."""

    def __post_init__(self):
        object.__setattr__(self, "offsets", np.concatenate([[0], np.cumsum([node.dof for node in self.nodes])])
                           .astype(int))


def network_problem(case) -> NetworkProblem:
    """The catenary network of ``case``.

    Raises
    ------
    NeedsDrag
        When the case has a current or its vessel starts moving (drag on the lines).
    CaseError
        For what the catenary statics cannot take, at its key.
    """
    env = case.environment
    _check_still_water(case)
    issues: list[Problem] = []
    names = [n for n in (*case.points, *case.bodies) if _is_node(case, n)]
    index = {name: i for i, name in enumerate(names)}
    nodes = [_node(case, name) for name in names]
    seabed = seabed_of(env)
    lines = []
    for i, cable in enumerate(case.cables):
        try:
            lines.append(_line(case, i, index, seabed))
        except CaseError as error:
            issues.extend(error.problems)
    if issues:
        raise CaseError(issues)
    friction = env.seabed.friction if env.seabed is not None else 0.0
    return NetworkProblem(nodes, lines, seabed, friction, env.gravity)


def _check_still_water(case) -> None:
    current = case.environment.current
    rows = current.profile or ((0.0, *(current.velocity or (0.0, 0.0, 0.0))),)
    speed = case.vessel.initial_speed
    if any(any(r[1:]) for r in rows) or speed:
        value, unit = case.vessel.speed_as_given(speed)
        what = (f"the vessel's initial speed of {value:.4g} {unit}" if speed else "the current")
        raise NeedsDrag(f"{what} drags on the lines, which the catenary (weight only) cannot carry")


def _is_node(case, name: str) -> bool:
    """True for points and bodies that end a cable (attached-only bodies are point loads)."""
    return any(end.kind in ("point", "body") and end.name == name for c in case.cables for end in c.ends)


def _node(case, name: str) -> NetworkNode:
    env = case.environment
    rho, g = env.water_density, env.gravity
    if name in case.points:
        point = case.points[name]
        force = np.asarray(point.force, dtype=float) + np.array([0.0, 0.0, point.net_buoyancy(rho, g)])
        return NetworkNode(name, "point", 3, _vector(point.position), force=force)
    body = case.bodies[name]
    force = np.asarray(body.force, dtype=float)
    if body.dof == 3:
        return NetworkNode(name, "body", 3, _vector(body.position),
                           force=force + np.array([0.0, 0.0, body.net_buoyancy]))
    stiffness = body.hydrostatic_stiffness_matrix(rho, g)
    return NetworkNode(name, "body", 6, _vector(body.position), np.radians(body.orientation_deg), force,
                       weight=body.mass * g, buoyancy=body.buoyancy(g),
                       cog=np.asarray(body.center_of_gravity, dtype=float),
                       cob=np.asarray(body.buoyancy_point, dtype=float), hydrostatic=stiffness,
                       tilt_in_stiffness=body.tilt_in_stiffness)


def _vector(value) -> np.ndarray | None:
    return None if value is None else np.asarray(value, dtype=float)


def _end(case, end, index, seabed, key: str) -> LineEnd:
    if end.kind == "anchor":
        position = np.asarray(end.position, dtype=float)
        return LineEnd(-1, position, "anchor", _rests_on(seabed, position))
    if end.kind == "vessel":
        position = np.asarray(case.vessel.tow_point if end.offset is None else end.offset, dtype=float)
        return LineEnd(-1, position, "vessel", _rests_on(seabed, position))
    if end.kind in ("point", "body"):
        offset = np.zeros(3) if end.offset is None else np.asarray(end.offset, dtype=float)
        return LineEnd(index[end.name], offset, end.kind)
    raise CaseError([Problem(key, "a free end carries no tension, so its steady direction is undefined; "
                             "end the cable at a small body to solve its statics")])


def _rests_on(seabed: PlaneSeabed | None, position) -> bool:
    if seabed is None:
        return False
    height = float(seabed.height(position[0], position[1]))
    return bool(position[2] <= height + ON_SEABED * seabed.depth)


def _line(case, i: int, index, seabed) -> NetworkLine:
    cable = case.cables[i]
    env = case.environment
    key = f"cables[{i}]"
    ends = [_end(case, end, index, seabed, f"{key}.{name}")
            for end, name in ((cable.from_, "from"), (cable.to, "to"))]
    for end, name in zip(ends, ("from", "to")):
        if end.node < 0 and seabed is not None:
            height = float(seabed.height(end.point[0], end.point[1]))
            if end.point[2] < height - ON_SEABED * seabed.depth:
                raise CaseError([Problem(f"{key}.{name}", f"the end at z = {end.point[2]:g} m lies below "
                                         f"the seabed (z = {height:g} m there); raise it onto the seabed")])
    cuts, loads, end_loads = _attachments(case, i)
    lengths, weights, stiffnesses, joint_loads = [], [], [], []
    start = 0.0
    for section in cable.sections:
        line_type = case.line_types[section.line_type]
        w = line_type.weight_in_water_value(env.water_density, env.gravity)
        end = start + section.length
        inner = [s for s in cuts if start < s < end]
        for a, b in zip([start, *inner], [*inner, end]):
            if lengths:
                joint_loads.append(loads.get(a, 0.0))
            lengths.append(b - a)
            weights.append(w)
            stiffnesses.append(line_type.axial_stiffness)
        start = end
    ends = [LineEnd(e.node, e.point, e.kind, e.on_seabed, load) for e, load in zip(ends, end_loads)]
    pieces = Pieces(np.array(lengths), np.array(weights), np.array(stiffnesses), np.array(joint_loads))
    grid = np.concatenate([np.linspace(a, b, s.segments + 1) for (a, b), s in zip(cable.section_bounds(),
                                                                                  cable.sections)])
    stations = np.array(sorted(set(grid.tolist())))            # np.unique would import numpy.ma (40-70 ms)
    return NetworkLine(cable.name, pieces, (ends[0], ends[1]), stations)


def _attachments(case, i: int):
    """Arclengths of the joints (attachments and section ends), their loads, and the loads
    of attachments at the two ends."""
    cable = case.cables[i]
    bounds = [b for _, b in cable.section_bounds()][:-1]
    loads: dict[float, float] = {}
    end_loads = [0.0, 0.0]
    for j, item in enumerate(cable.attachments):
        body = case.bodies[item.body]
        key = f"cables[{i}].attachments[{j}]"
        if _is_node(case, item.body):
            raise CaseError([Problem(key, f"body '{item.body}' also ends a cable; an attached body is "
                                     "clamped to one cable only")])
        if body.dof == 6 or abs(body.force[0]) > 0 or abs(body.force[1]) > 0:
            raise CaseError([Problem(key, f"body '{item.body}' pulls sideways or turns (dof: 6 or a "
                                     "horizontal force); the catenary statics takes attachments that "
                                     "add weight or buoyancy only")])
        load = -body.net_buoyancy - body.force[2]
        if item.s <= END_FRACTION * cable.length:
            end_loads[0] += load
        elif item.s >= (1.0 - END_FRACTION) * cable.length:
            end_loads[1] += load
        else:
            loads[item.s] = loads.get(item.s, 0.0) + load
    cuts = sorted(set(bounds) | set(loads))
    return cuts, loads, end_loads


def fairlead_rotation(angles) -> tuple[np.ndarray, list[np.ndarray]]:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` and its derivatives with respect to the three angles.

    Parameters
    ----------
    angles : array_like, shape (3,)
        Roll, pitch, yaw [rad].

    Returns
    -------
    R : ndarray, shape (3, 3)
    dR : list of 3 ndarrays, shape (3, 3)
        ``dR/droll``, ``dR/dpitch``, ``dR/dyaw``.
    """
    r, p, y = angles
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    dRx = np.array([[0, 0, 0], [0, -sr, -cr], [0, cr, -sr]])
    dRy = np.array([[-sp, 0, cp], [0, 0, 0], [-cp, 0, -sp]])
    dRz = np.array([[-sy, -cy, 0], [cy, -sy, 0], [0, 0, 0]])
    return Rz @ Ry @ Rx, [Rz @ Ry @ dRx, Rz @ dRy @ Rx, dRz @ Ry @ Rx]
