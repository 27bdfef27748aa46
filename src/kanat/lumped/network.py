"""Assembly of a case into the lumped network: nodes, elements, bodies (theory/moorings.md, theory/lumped.md).

Each cable is cut into elements by :func:`kanat.lumped.grid.cable_grid` (every section joint
and every inline attachment is a node). Cable ends attached to the same 3-DOF body or point
share one node; the vessel's tow point is one prescribed node and each vessel fairlead
(``{vessel: [x, y, z]}``) another, moved by the track and ``vessel.motion``; each anchor end
is its own prescribed node; a free end is a free node. A clamped end (``cables[].end_a/end_b``)
adds a prescribed *guide* node one element behind it (:mod:`kanat.lumped.clamps`). A 6-DOF body is
two *pseudo-nodes* among the generalized coordinates — its reference point ``r`` and its Euler
angles ``(roll, pitch, yaw)`` — and each of its fairleads a node prescribed by them
(:mod:`kanat.lumped.rigid`). Generalized coordinates are the positions of the free nodes.

Element properties are stored per element as arrays, ready for the kernels
(:mod:`kanat.lumped.kernels`):

* drag as per-length coefficients ``c_n, c_t`` [kg/m^2] of the force per unstretched
  length ``c |v| v``: Bezverkhyi's dimensional ``C_n, C_t`` as given (Bezverkhyi 2006, eq. 4,
  ``stretch_drag = 0``), or from the ``Cd`` form ``c_n = rho d C_n / 2``,
  ``c_t = rho pi d C_t / 2`` with the factor ``sqrt(1 + e)`` (theory/continuum.md §1, ``stretch_drag = 1``);
* weight in water per unstretched length ``w0`` [N/m] and the buoyancy ``rho g A`` it
  includes (lost above the surface);
* displaced mass per length ``rho A`` [kg/m] (Froude–Krylov), added mass normal ``m_a`` and
  tangential ``m_at`` [kg/m];
* the elastic law ``f(e)`` as a polynomial or a table (:func:`law_arrays`).

Nodal arrays for the seabed contact (:mod:`kanat.physics.contact`): the contact area
``sum d L0 / 2`` of the elements at each node [m^2] and the node's weight in water [N].
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.lumped.bending import bending_triples
from kanat.lumped.clamps import clamped_ends, given_directions, place_guides, vessel_start
from kanat.lumped.entries import Elements
from kanat.lumped.grid import cable_grid
from kanat.lumped.rigid import RigidBodies, rigid_bodies
from kanat.model.paths import key_path
from kanat.physics.motion import rotation_matrix
from kanat.physics.seabed import seabed_of

POLYNOMIAL, TABLE = 0, 1
GUESS_STRETCH = 1.0 + 1e-4   # the first guess stretches every cable by this factor
VESSEL_GUESS_DIRECTION = np.array([-1.0, 0.0, -1.0]) / math.sqrt(2.0)  # astern and down
PRESCRIBED = ("vessel", "anchor", "fairlead", "clamp")
BUOY_GUESS_DEPTH = 0.02      # a submerged float's first guess is at least this fraction of the depth down


@dataclass(frozen=True, eq=False)
class Network:
    """The lumped model of a case as typed arrays (SI units).

    Attributes
    ----------
    free : ndarray of bool, shape (n,)
        Nodes moved by the dynamics (cable nodes, 3-DOF bodies, points, 6-DOF body pseudo-nodes).
    kinds : ndarray of str, shape (n,)
        ``cable``, ``vessel``, ``anchor``, ``free``, ``body``, ``point``, ``fairlead``,
        ``body_ref``, ``body_rot``.
    vessel_nodes : ndarray of int
        Prescribed vessel nodes (tow point and fairleads); ``vessel_offset`` (k, 3) their lever
        arms in vessel axes.
    anchor_nodes, anchor_position, anchor_names
        Fixed nodes and their positions (k, 3): the anchors, named ``cable.from`` / ``cable.to`` in
        ``anchor_names``, then the guide nodes of clamped anchor ends (:mod:`kanat.lumped.clamps`);
        :attr:`anchors` are the anchors alone.
    x_guess : ndarray, shape (n, 3)
        Initial positions (cables sagging between guessed ends; Euler angles on ``body_rot``).
    node_mass, node_added_mass : ndarray, shape (n,)
        Body, attachment and point masses and added masses [kg] at nodes.
    node_fluid_inertia : ndarray, shape (n,)
        Morison inertia of the point bodies and points at nodes, displaced plus added mass
        ``rho V + m_a`` [kg]: the water's acceleration ``a_w`` pulls them with
        ``(rho V + m_a) a_w`` (Froude–Krylov and added-mass parts, as on elements).
    node_force : ndarray, shape (n, 3)
        Constant nodal loads [N]: net buoyancy and force of bodies, point weight, buoyancy, force.
    node_contact_area, node_weight : ndarray, shape (n,)
        Seabed contact area ``sum d L0 / 2`` [m^2] and weight in water [N] (module docstring).
    el_i, el_j : ndarray of int, shape (m,)
        Element end nodes.
    el_length, el_mass, el_added_mass, el_weight, el_displaced : ndarray, shape (m,)
        ``L0`` [m], ``m``, ``m_a`` [kg/m], ``w0`` [N/m], ``rho A`` [kg/m].
    el_added_tangential, el_buoyancy, el_diameter : ndarray, shape (m,)
        ``m_at`` [kg/m], ``rho g A`` [N/m], ``d`` [m].
    el_type : list of str
        Line type of each element (its section's).
    el_cn, el_ct, el_stretch_drag, el_damping, el_law, law_kind, law_n, law_x, law_y
        Drag, Kelvin–Voigt ``C_E2`` [N s] and elastic laws (module docstring).
    el_compression : ndarray, shape (m,)
        The line type's ``compression_stiffness`` [N]: > 0, the element is a bar that also pushes
        (:func:`kanat.lumped.kernels.axial_force`); 0, a rope.
    body_names, body_node : per body (3-DOF: its node; 6-DOF: its reference pseudo-node)
    body_drag_area, body_spreading : per body (0 for 6-DOF bodies)
    load_node, load_drag_area, load_spreading : nodes with point-body loads (3-DOF bodies and
        points with drag or added mass), for :func:`kanat.lumped.kernels.body_loads`
    buoy_body, buoy_area, buoy_height : per surface buoy (index into the bodies)
    float_body, float_diameter, float_buoyancy : per spherical inline float (``diameter`` given; index
        into the bodies), its diameter [m] and its buoyancy fully submerged ``net_buoyancy + m g`` [N],
        of which ``1 - f`` (:func:`kanat.physics.immersion.sphere_fraction`) is taken off out of the water
    rigid : RigidBodies
        The 6-DOF bodies (:mod:`kanat.lumped.rigid`).
    node_cable, node_s, node_index : per output node (cables' nodes concatenated)
    segment_cable, cable_names, cable_first_element : per output segment / cable
    names : dict
        Node of each named body, point and shared end.
    bend : tuple (before, node, after, k, l)
        The interior nodes with bending stiffness (:func:`kanat.lumped.bending.bending_triples`), then
        the clamped ends' triples with their guide nodes (:mod:`kanat.lumped.clamps`).
    """

    free: np.ndarray
    kinds: np.ndarray
    vessel_nodes: np.ndarray
    vessel_offset: np.ndarray
    anchor_nodes: np.ndarray
    anchor_position: np.ndarray
    anchor_names: list
    x_guess: np.ndarray
    node_mass: np.ndarray
    node_added_mass: np.ndarray
    node_fluid_inertia: np.ndarray
    node_force: np.ndarray
    node_contact_area: np.ndarray
    node_weight: np.ndarray
    el_i: np.ndarray
    el_j: np.ndarray
    el_length: np.ndarray
    el_mass: np.ndarray
    el_added_mass: np.ndarray
    el_weight: np.ndarray
    el_displaced: np.ndarray
    el_added_tangential: np.ndarray
    el_buoyancy: np.ndarray
    el_diameter: np.ndarray
    el_type: list
    el_cn: np.ndarray
    el_ct: np.ndarray
    el_stretch_drag: np.ndarray
    el_damping: np.ndarray
    el_compression: np.ndarray
    el_law: np.ndarray
    law_kind: np.ndarray
    law_n: np.ndarray
    law_x: np.ndarray
    law_y: np.ndarray
    body_names: list
    body_node: np.ndarray
    body_drag_area: np.ndarray
    body_spreading: np.ndarray
    load_node: np.ndarray
    load_drag_area: np.ndarray
    load_spreading: np.ndarray
    buoy_body: np.ndarray
    buoy_area: np.ndarray
    buoy_height: np.ndarray
    float_body: np.ndarray
    float_diameter: np.ndarray
    float_buoyancy: np.ndarray
    rigid: RigidBodies
    node_cable: np.ndarray
    node_s: np.ndarray
    node_index: np.ndarray
    segment_cable: np.ndarray
    cable_names: list
    cable_first_element: np.ndarray
    names: dict = field(default_factory=dict)
    bend: tuple = field(default_factory=lambda: bending_triples(*[np.zeros(0)] * 5))

    @property
    def n_nodes(self) -> int:
        return len(self.free)

    @property
    def n_elements(self) -> int:
        return len(self.el_i)

    @property
    def anchors(self) -> np.ndarray:
        """The anchors' nodes (``anchor_nodes`` without the clamps' guides), in ``anchor_names``' order."""
        return self.anchor_nodes[:len(self.anchor_names)]

    def elements(self) -> Elements:
        """The elements as the kernels read them (:class:`kanat.lumped.entries.Elements`), built here
        only: a new element property is a field there and its fill here."""
        before, node, after, stiffness = self.bend[:4]
        return Elements(
            first_node=self.el_i, second_node=self.el_j, length=self.el_length, mass=self.el_mass,
            added_mass=self.el_added_mass, weight=self.el_weight, displaced=self.el_displaced,
            drag_normal=self.el_cn, drag_tangential=self.el_ct, stretch_drag=self.el_stretch_drag,
            damping=self.el_damping, law=self.el_law, law_kind=self.law_kind, law_size=self.law_n,
            law_strains=self.law_x, law_values=self.law_y, added_mass_tangential=self.el_added_tangential,
            buoyancy=self.el_buoyancy, diameter=self.el_diameter, bend_before=before, bend_node=node,
            bend_after=after, bend_stiffness=stiffness, compression_stiffness=self.el_compression)

    def where(self, node: int) -> str:
        """``cable 'x' node k`` for an internal node, for messages."""
        hits = np.flatnonzero(self.node_index == node)
        if len(hits) == 0:
            named = [k for k, v in self.names.items() if v == node and not k.startswith("@")]
            return f"'{named[0]}'" if named else f"node {node}"
        k = hits[0]
        cable = self.node_cable[k]
        local = k - np.flatnonzero(self.node_cable == cable)[0]
        return f"cable '{cable}' node {local} (s = {self.node_s[k]:.4g} m)"

    def element_where(self, element: int) -> str:
        """``cable 'x' element k`` for an element, for messages."""
        cable = self.segment_cable[element]
        local = element - self.cable_first_element[self.cable_names.index(cable)]
        return f"cable '{cable}' element {local}"


def law_arrays(line_types: dict) -> tuple[dict, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Elastic laws of the line types as padded arrays for the kernels.

    Returns
    -------
    row : dict of str to int
        Law row of each line type.
    kind, n : ndarray of int, shape (n_law,)
    x, y : ndarray, shape (n_law, k)
        ``POLYNOMIAL``: ``y[:n]`` the coefficients ``c1..cn`` of ``f = sum c_k e^k``
        (``axial_stiffness`` alone when no law is given: Kelvin–Voigt);
        ``TABLE``: ``(x, y)[:n]`` the table with ``(0, 0)`` prepended.
    """
    rows, kinds, xs, ys = {}, [], [], []
    for name, lt in line_types.items():
        law = lt.elastic_law
        rows[name] = len(kinds)
        if law is None or law.polynomial is not None:
            coefficients = [lt.axial_stiffness] if law is None else list(law.polynomial)
            kinds.append(POLYNOMIAL), xs.append([0.0] * len(coefficients)), ys.append(coefficients)
        else:
            kinds.append(TABLE)
            xs.append([0.0] + [r[0] for r in law.table])
            ys.append([0.0] + [r[1] for r in law.table])
    width = max(len(r) for r in ys) if ys else 1
    pad = lambda rows_: np.array([r + [0.0] * (width - len(r)) for r in rows_], dtype=float)  # noqa: E731
    return rows, np.array(kinds, dtype=np.int64), np.array([len(r) for r in ys], dtype=np.int64), pad(xs), pad(ys)


def _key(offset) -> str:
    return "[" + ",".join(f"{c:.12g}" for c in offset) + "]"


class _Builder:
    """Collects nodes while walking the cables."""

    def __init__(self, case):
        self.case = case
        self.named: dict[str, int] = {}
        self.positions: list = []       # guessed position or None
        self.kinds: list[str] = []
        self.vessel: list[tuple[int, np.ndarray]] = []      # (node, lever arm)
        self.fairleads: list[tuple[int, str, np.ndarray]] = []   # (node, body, offset)
        self.anchor_names: list[str] = []

    def node(self, kind: str, position=None) -> int:
        self.kinds.append(kind)
        self.positions.append(None if position is None else np.asarray(position, float))
        return len(self.kinds) - 1

    def end_node(self, end, label: str, where: tuple) -> int:
        if end.kind == "vessel":
            arm = np.asarray(self.case.vessel.tow_point if end.offset is None else end.offset, float)
            key = "@vessel" if end.offset is None else "@vessel" + _key(end.offset)
            if key not in self.named:
                self.named[key] = self.node("vessel", _vessel_guess(self.case, arm))
                self.vessel.append((self.named[key], arm))
            return self.named[key]
        if end.kind == "anchor":
            self.anchor_names.append(label)
            return self.node("anchor", end.position)
        if end.kind == "free":
            return self.node("free")
        if end.kind == "body" and self.case.bodies[end.name].dof == 6:
            return self._fairlead(end, where)
        if end.offset is not None:
            raise CaseError([Problem(key_path(where), f"a fairlead offset needs a rigid body: body '{end.name}' "
                                     "is a point (dof 3); add dof: 6 and its inertia, or drop the offset")])
        if end.name not in self.named:
            item = (self.case.bodies if end.kind == "body" else self.case.points)[end.name]
            self.named[end.name] = self.node(end.kind, getattr(item, "position", None))
        return self.named[end.name]

    def _fairlead(self, end, where) -> int:
        body = self.case.bodies[end.name]
        if body.position is None:
            raise CaseError([Problem(key_path(("bodies", end.name, "position")),
                                     "a dof: 6 body needs its position (the reference point) in the lumped "
                                     "model")])
        offset = np.zeros(3) if end.offset is None else np.asarray(end.offset, float)
        key = f"{end.name}@{_key(offset)}"
        if key not in self.named:
            rotation = rotation_matrix(*np.radians(body.orientation_deg))
            self.named[key] = self.node("fairlead", np.asarray(body.position) + rotation @ offset)
            self.fairleads.append((self.named[key], end.name, offset))
        return self.named[key]

    def attach(self, name: str, node: int, where: tuple) -> None:
        body = self.case.bodies[name]
        if name in self.named:
            raise CaseError([Problem(key_path(where), f"body '{name}' is already placed (a cable end or "
                                     "another attachment); each attached body needs its own body entry")])
        if body.dof == 6:
            raise CaseError([Problem(key_path(where), f"body '{name}' has dof: 6; an inline attachment is a "
                                     "point (dof 3)")])
        if self.kinds[node] not in ("cable", "free"):
            raise CaseError([Problem(key_path(where), f"body '{name}' is attached at a cable end that is a "
                                     f"{self.kinds[node]}; attach it inside the cable or end the "
                                     "cable at the body")])
        self.kinds[node] = "body"
        self.named[name] = node


def _vessel_guess(case, arm) -> np.ndarray:
    """A vessel point's place at t = 0: the track's (or the arm itself without a track), moved by the
    prescribed motion's displacement at t = 0 turned by the heading (as :class:`LumpedSystem` places it)."""
    arm = np.asarray(arm, float)
    place = arm
    if case.vessel.track:
        from kanat.vessel.track import VesselTrack
        place = VesselTrack.from_model(case.vessel).state(0.0, arm).position
    heading, q = vessel_start(case)
    moved = q[:3] + rotation_matrix(*q[3:]) @ arm - arm
    return place + rotation_matrix(0.0, 0.0, heading) @ moved


def _buoyant(builder: _Builder, node: int) -> bool:
    """True for a body or point at ``node`` that floats: a surface buoy, or a net upward load."""
    case = builder.case
    env = case.environment
    for name, at in builder.named.items():
        if at != node:
            continue
        if name in case.bodies:
            body = case.bodies[name]
            return body.surface_buoy is not None or body.net_buoyancy + body.force[2] > 0.0
        if name in case.points:
            point = case.points[name]
            return point.net_buoyancy(env.water_density, env.gravity) + point.force[2] > 0.0
    return False


def _float_guess(builder: _Builder, node: int, known: np.ndarray, length: float) -> np.ndarray:
    """A floating end's place ``0.9 length`` of line from ``known``, laid as an L: a rise as high
    as that reaches, up to BUOY_GUESS_DEPTH of the depth (a surface buoy: its keel half its
    height down), and the rest of the length as a run along the surface current, or astern in
    still water (the line between them then sags onto the seabed, as a grounded chain lies)."""
    case = builder.case
    env = case.environment
    name = next(k for k, v in builder.named.items() if v == node)
    buoy = case.bodies[name].surface_buoy if name in case.bodies else None
    depth = env.depth if env.depth is not None else -float(known[2]) + length
    top = -0.5 * buoy.height if buoy is not None else -BUOY_GUESS_DEPTH * depth
    reach = 0.9 * length
    rise = min(max(top - float(known[2]), 0.0), reach)
    flow = np.asarray(env.current.at(0.0), float)[:2]
    direction = flow / np.linalg.norm(flow) if np.linalg.norm(flow) > 0.0 else np.array([-1.0, 0.0])
    run = reach - rise
    return known + np.array([run * direction[0], run * direction[1], rise])


def _guess_positions(builder: _Builder, ends: list[tuple[int, int, float]], clamped: dict) -> None:
    """Place unknown end nodes a cable length from a known one: up towards the surface and along
    the current for a floating body or point (:func:`_float_guess`); along the known end's clamp
    direction where the case gives one (``clamped``: node to global unit direction; the cable then
    lies straight, as a beam would start); else astern and down."""
    pos = builder.positions
    for _ in range(len(ends) + 1):
        changed = False
        for a, b, length in ends:
            for known, unknown in ((a, b), (b, a)):
                if pos[known] is not None and pos[unknown] is None:
                    if _buoyant(builder, unknown):
                        pos[unknown] = _float_guess(builder, unknown, pos[known], length)
                    elif known in clamped:              # straight along the clamp's given direction
                        pos[unknown] = pos[known] + GUESS_STRETCH * length * clamped[known]
                    else:
                        pos[unknown] = pos[known] + 0.9 * length * VESSEL_GUESS_DIRECTION
                    changed = True
        if not changed:
            break
    missing = [i for a, b, _ in ends for i in (a, b) if pos[i] is None]
    if missing:
        raise CaseError([Problem("cables", "part of the network is joined to neither the vessel nor "
                                           "an anchor: give its bodies or points a 'position'")])


def sagged_line(p0, p1, length: float, segments: int, s=None, stretch: float = GUESS_STRETCH) -> np.ndarray:
    """Nodes of a cable between ``p0`` and ``p1``: straight when the chord is as long as the
    cable, else a parabola sagging downward whose length is ``stretch`` times the cable's, the
    nodes spaced evenly along it in arclength. ``s`` (segments + 1,) places the nodes at those
    fractions of the length (default even). The equilibrium's first guess takes
    :data:`GUESS_STRETCH` (elements taut, so its tangent is regular from the start); a start as given
    (``stretch`` 1) lays the cable unstretched, at no tension. A vertical chord bows sideways (in +x),
    but for a start as given whose chord is at least half the cable's length: it lies straight, its
    elements slack (MoorDyn's pendulum test file: 100.5 m over 100 m), where a bow would push it
    metres sideways; a shorter chord would bunch its elements up, and hangs in the bow's U."""
    fraction = np.linspace(0.0, 1.0, segments + 1) if s is None else np.asarray(s) / length
    chord = p1 - p0
    if np.linalg.norm(chord) >= stretch * length or np.linalg.norm(chord) >= length * (1.0 - 1e-12):
        return p0 + chord * fraction[:, None]          # taut, or laid out straight as given
    down = np.array([0.0, 0.0, -1.0]) - chord * (-chord[2]) / max(chord @ chord, 1e-300)
    if np.linalg.norm(down) < 1e-9:                  # vertical chord
        if stretch <= 1.0 and np.linalg.norm(chord) >= 0.5 * length:
            return p0 + chord * fraction[:, None]
        down = np.array([1.0, 0.0, 0.0])
    down /= np.linalg.norm(down)
    xi = np.linspace(0.0, 1.0, 20 * segments + 201)[:, None]
    shape = 4.0 * xi * (1.0 - xi) * down
    curve = lambda sag: p0 + chord * xi + sag * shape  # noqa: E731
    polyline = lambda sag: np.sum(np.linalg.norm(np.diff(curve(sag), axis=0), axis=1))  # noqa: E731
    target = stretch * length
    low, high = 0.0, target
    for _ in range(100):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if polyline(mid) < target else (low, mid)
    points = curve(0.5 * (low + high))
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
    wanted = fraction * arc[-1]
    return np.stack([np.interp(wanted, arc, points[:, r]) for r in range(3)], -1)


def given_positions(net: Network, case) -> np.ndarray:
    """All nodes' positions (n, 3) of a start as given (``simulation.initial_state: as_given``): those of
    ``net.x_guess`` with each cable laid unstretched between its ends (:func:`sagged_line` with ``stretch``
    1, at no tension; the guess's cables are stretched by :data:`GUESS_STRETCH`, which at rest is a
    tension of ``EA 1e-4``) and, as in the guess, on the seabed where its sag would dip below it."""
    x = net.x_guess.copy()
    laid = np.zeros(net.n_nodes, dtype=bool)
    for cable in case.cables:
        on = net.node_cable == cable.name
        nodes, s = net.node_index[on], net.node_s[on]
        x[nodes] = sagged_line(x[nodes[0]], x[nodes[-1]], cable.length, len(nodes) - 1, s, stretch=1.0)
        laid[nodes] = True
    _onto_seabed(x, laid & net.free, case.environment)
    return x


def _onto_seabed(x: np.ndarray, loose: np.ndarray, environment) -> None:
    """Lift the ``loose`` nodes (mask) of ``x`` whose sag would dip below the seabed onto it, in place."""
    seabed = seabed_of(environment)
    if seabed is not None:
        x[loose, 2] = np.maximum(x[loose, 2], seabed.height(x[loose, 0], x[loose, 1]))


def build_network(case) -> Network:
    """Assemble the lumped network of ``case`` (module docstring).

    Raises
    ------
    CaseError
        When a part of the network has no prescribed node to hang from and no position, or an
        attachment or fairlead cannot be placed.
    """
    env = case.environment
    b = _Builder(case)
    laws = law_arrays(case.line_types)
    rows, ends, cable_nodes = [], [], []
    for index, cable in enumerate(case.cables):
        grid = cable_grid(cable)
        first = b.end_node(cable.from_, f"{cable.name}.from", ("cables", index, "from"))
        inner = [b.node("cable") for _ in range(len(grid.s) - 2)]
        last = b.end_node(cable.to, f"{cable.name}.to", ("cables", index, "to"))
        nodes = [first, *inner, last]
        for k, (item, node) in enumerate(zip(cable.attachments, grid.attachment_node)):
            b.attach(item.body, nodes[node], ("cables", index, "attachments", k, "body"))
        cable_nodes.append(nodes)
        ends.append((first, last, cable.length))
        rows.append((nodes, cable, grid))
    _guess_positions(b, ends, given_directions(case, rows))
    x = np.zeros((len(b.kinds), 3))
    for nodes, cable, grid in rows:
        x[nodes] = sagged_line(b.positions[nodes[0]], b.positions[nodes[-1]], cable.length, len(grid.s) - 1,
                               grid.s)
    _onto_seabed(x, ~np.isin(np.array(b.kinds), PRESCRIBED), env)    # a sag that would dip below it lies on it
    x, guides, clamp_triples = place_guides(b, x, clamped_ends(case, rows))
    rigid = rigid_bodies(case, b)
    x = np.vstack([x, rigid.guess]) if rigid.count else x
    net = _finish(case, b, laws, rows, cable_nodes, x, rigid, env.water_density, env.gravity)
    return _with_clamps(net, guides, clamp_triples)


def _with_clamps(net: Network, guides: list, triples: list) -> Network:
    """``net`` with the clamps' guide nodes (:mod:`kanat.lumped.clamps`): anchor guides after the
    anchors in ``anchor_nodes``, the clamps' triples after the interior nodes' in ``bend``."""
    if not triples:
        return net
    columns = list(zip(*triples))
    bend = tuple(np.concatenate([part, np.asarray(extra, dtype=part.dtype)]) for part, extra in zip(net.bend, columns))
    nodes = np.array([node for node, _ in guides], dtype=np.int64)
    positions = np.array([position for _, position in guides], dtype=float).reshape(-1, 3)
    return replace(net, bend=bend, anchor_nodes=np.concatenate([net.anchor_nodes, nodes]),
                   anchor_position=np.vstack([net.anchor_position, positions]))


def _element_arrays(case, rows, laws, rho, g):
    cols = {k: [] for k in ("i", "j", "L", "m", "EI", "ma", "mat", "w", "disp", "buoy", "d", "cn", "ct", "stretch",
                            "c", "law", "type", "compression")}
    for nodes, cable, grid in rows:
        for k in range(len(grid.s) - 1):
            name = cable.sections[grid.section[k]].line_type
            lt = case.line_types[name]
            weight = lt.weight_in_water_value(rho, g)
            dimensional = lt.drag_normal_coefficient is not None or lt.drag_tangential_coefficient is not None
            if dimensional:
                cn, ct = lt.drag_normal_coefficient or 0.0, lt.drag_tangential_coefficient or 0.0
            else:
                cn = 0.5 * rho * lt.diameter * lt.drag_normal
                ct = 0.5 * rho * math.pi * lt.diameter * lt.drag_tangential
            values = {"i": nodes[k], "j": nodes[k + 1], "L": grid.s[k + 1] - grid.s[k], "m": lt.mass,
                      "EI": lt.bending_stiffness,
                      "ma": lt.added_mass, "mat": lt.added_mass_tangential, "w": weight,
                      "disp": (lt.mass * g - weight) / g, "buoy": lt.mass * g - weight, "d": lt.diameter,
                      "cn": cn, "ct": ct, "stretch": 0.0 if dimensional else 1.0, "c": lt.axial_damping,
                      "law": laws[0][name], "type": name, "compression": lt.compression_stiffness}
            for key, value in values.items():
                cols[key].append(value)
    return cols


def _node_loads(case, b, n, g, rho):
    node_mass, node_added, node_force = np.zeros(n), np.zeros(n), np.zeros((n, 3))
    displaced = np.zeros(n)          # rho V [kg] of point bodies and points (Froude–Krylov)
    loads = []                      # (node, drag area, spreading) of point-like loads
    for name, body in case.bodies.items():
        if name in b.named and body.dof == 3:
            node = b.named[name]
            node_mass[node] += body.mass
            node_added[node] += body.added_mass
            displaced[node] += body.buoyancy(g) / g
            node_force[node] += np.asarray(body.force) + np.array([0.0, 0.0, body.net_buoyancy])
            loads.append((node, body.drag_area, body.spreading_force))
    for name, point in case.points.items():
        if name in b.named:
            node = b.named[name]
            node_mass[node] += point.mass
            node_added[node] += point.added_mass
            displaced[node] += rho * point.volume
            node_force[node] += np.asarray(point.force) + np.array([0.0, 0.0, point.net_buoyancy(rho, g)])
            if point.drag_area or point.added_mass or point.volume:
                loads.append((node, point.drag_area, 0.0))
    return node_mass, node_added, node_added + displaced, node_force, loads


def _contact_arrays(n, cols, node_force):
    area, weight = np.zeros(n), np.zeros(n)
    half = 0.5 * np.asarray(cols["L"])
    for key in ("i", "j"):
        np.add.at(area, np.asarray(cols[key], np.int64), half * np.asarray(cols["d"]))
        np.add.at(weight, np.asarray(cols[key], np.int64), half * np.asarray(cols["w"]))
    weight += np.maximum(-node_force[:, 2], 0.0)
    return area, weight


def _finish(case, b, laws, rows, cable_nodes, x, rigid, rho, g) -> Network:
    n = len(x)
    kinds = np.array(b.kinds + ["body_ref", "body_rot"] * rigid.count)
    node_mass, node_added, node_fluid, node_force, loads = _node_loads(case, b, n, g, rho)
    body_names = [name for name in case.bodies if name in b.named or name in rigid.names]
    body_node = np.array([b.named[k] if k in b.named else rigid.ref_node[rigid.names.index(k)]
                          for k in body_names], dtype=np.int64)
    buoys = [k for k, name in enumerate(body_names) if case.bodies[name].surface_buoy is not None]
    floats = [k for k, name in enumerate(body_names) if case.bodies[name].diameter is not None]
    cols = _element_arrays(case, rows, laws, rho, g)
    area, weight = _contact_arrays(n, cols, node_force)
    for name, body in case.bodies.items():         # a point body's own bearing area (seabed_area)
        if name in b.named and body.dof == 3:
            area[b.named[name]] += body.seabed_area
    names, s, index, seg_cable, first_el = [], [], [], [], []
    for (nodes, cable, grid), cn in zip(rows, cable_nodes):
        first_el.append(len(seg_cable))
        names += [cable.name] * len(nodes)
        s.extend(grid.s)
        index.extend(cn)
        seg_cable += [cable.name] * (len(nodes) - 1)
    arr = lambda k, dt=float: np.asarray(cols[k], dtype=dt)  # noqa: E731
    three = [case.bodies[k].dof == 3 for k in body_names]
    vessel_nodes = np.array([node for node, _ in b.vessel], dtype=np.int64)
    return Network(
        free=~np.isin(kinds, PRESCRIBED), kinds=kinds,
        vessel_nodes=vessel_nodes,
        vessel_offset=np.array([arm for _, arm in b.vessel], dtype=float).reshape(-1, 3),
        anchor_nodes=np.flatnonzero(kinds == "anchor"), anchor_position=x[kinds == "anchor"].copy(),
        anchor_names=list(b.anchor_names), x_guess=x,
        node_mass=node_mass, node_added_mass=node_added, node_fluid_inertia=node_fluid, node_force=node_force,
        node_contact_area=area, node_weight=weight,
        el_i=arr("i", np.int64), el_j=arr("j", np.int64), el_length=arr("L"), el_mass=arr("m"),
        el_added_mass=arr("ma"), el_weight=arr("w"), el_displaced=arr("disp"),
        el_added_tangential=arr("mat"), el_buoyancy=arr("buoy"), el_diameter=arr("d"), el_type=list(cols["type"]),
        el_cn=arr("cn"), el_ct=arr("ct"), el_stretch_drag=arr("stretch"), el_damping=arr("c"),
        el_compression=arr("compression"),
        el_law=arr("law", np.int64), law_kind=laws[1], law_n=laws[2], law_x=laws[3], law_y=laws[4],
        body_names=body_names, body_node=body_node,
        body_drag_area=np.array([case.bodies[k].drag_area if t else 0.0 for k, t in zip(body_names, three)]),
        body_spreading=np.array([case.bodies[k].spreading_force if t else 0.0 for k, t in zip(body_names, three)]),
        load_node=np.array([r[0] for r in loads], dtype=np.int64),
        load_drag_area=np.array([r[1] for r in loads], dtype=float),
        load_spreading=np.array([r[2] for r in loads], dtype=float),
        buoy_body=np.array(buoys, dtype=np.int64),
        buoy_area=np.array([case.bodies[body_names[k]].surface_buoy.waterplane_area for k in buoys]),
        buoy_height=np.array([case.bodies[body_names[k]].surface_buoy.height for k in buoys]),
        float_body=np.array(floats, dtype=np.int64),
        float_diameter=np.array([case.bodies[body_names[k]].diameter for k in floats], dtype=float),
        float_buoyancy=np.array([case.bodies[body_names[k]].buoyancy(g) for k in floats], dtype=float),
        rigid=rigid,
        node_cable=np.array(names, dtype=object), node_s=np.array(s), node_index=np.array(index, np.int64),
        segment_cable=np.array(seg_cable, dtype=object), cable_names=[c.name for c in case.cables],
        cable_first_element=np.array(first_el, dtype=np.int64), names=dict(b.named),
        bend=bending_triples(arr("i", np.int64), arr("j", np.int64), np.array(seg_cable, dtype=object), arr("EI"),
                             arr("L")))
