"""Assembly of a case into the lumped network: nodes, elements, bodies (SPEC §5).

Each cable of ``segments`` elements has ``segments + 1`` nodes. Cable ends attached to
the same body or point share one node; the vessel's tow point is one prescribed node;
each anchor end is its own prescribed node; a free end is a free node. Generalized
coordinates are the positions of the free nodes.

Element properties are stored per element as arrays, ready for the kernels
(:mod:`kanat.lumped.kernels`):

* drag as per-length coefficients ``c_n, c_t`` [kg/m^2] of the force per unstretched
  length ``c |v| v``: the seed's dimensional ``C_n, C_t`` as given (seed 004 eq. 4,
  ``stretch_drag = 0``), or from the ``Cd`` form ``c_n = rho d C_n / 2``,
  ``c_t = rho pi d C_t / 2`` with the factor ``sqrt(1 + e)`` (SPEC §2.1, ``stretch_drag = 1``);
* weight in water per unstretched length ``w0`` [N/m];
* displaced mass per length ``rho A`` [kg/m] for the Froude–Krylov inertia in waves;
* the elastic law ``f(e)`` as a polynomial or a table (:func:`law_arrays`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import CaseError, Problem

POLYNOMIAL, TABLE = 0, 1
GUESS_STRETCH = 1.0 + 1e-4   # the first guess stretches every cable by this factor
VESSEL_GUESS_DIRECTION = np.array([-1.0, 0.0, -1.0]) / math.sqrt(2.0)  # astern and down


@dataclass(frozen=True, eq=False)
class Network:
    """The lumped model of a case as typed arrays (SI units).

    Attributes
    ----------
    free : ndarray of bool, shape (n,)
        Nodes moved by the dynamics; the others follow prescribed motions.
    vessel_nodes, anchor_nodes : ndarray of int
        Prescribed nodes: tow point(s) and anchors.
    anchor_position : ndarray, shape (n_anchor, 3)
    x_guess : ndarray, shape (n, 3)
        Initial positions (straight cables between guessed ends).
    node_mass, node_added_mass : ndarray, shape (n,)
        Body and point masses and body added mass [kg] at nodes.
    node_force : ndarray, shape (n, 3)
        Constant nodal loads [N]: body net buoyancy and force, point weight.
    el_i, el_j : ndarray of int, shape (m,)
        Element end nodes.
    el_length, el_mass, el_added_mass, el_weight, el_displaced : ndarray, shape (m,)
        ``L0`` [m], ``m``, ``m_a`` [kg/m], ``w0`` [N/m], ``rho A`` [kg/m].
    el_cn, el_ct, el_stretch_drag : ndarray, shape (m,)
        Drag coefficients [kg/m^2] and the ``sqrt(1+e)`` flag (module docstring).
    el_damping : ndarray, shape (m,)
        Kelvin–Voigt ``C_E2`` [N s].
    el_law : ndarray of int, shape (m,)
        Row of the law arrays.
    law_kind, law_n : ndarray of int, shape (n_law,)
    law_x, law_y : ndarray, shape (n_law, k)
        Polynomial coefficients in ``law_y``, or table strains/tensions (through 0, 0).
    body_names, body_node, body_drag_area, body_spreading : per body
    buoy_body, buoy_area, buoy_height : per surface buoy (index into the bodies)
    node_cable, node_s, node_index : per output node (cables' nodes concatenated)
    segment_cable, cable_names, cable_first_element : per output segment / cable
    """

    free: np.ndarray
    vessel_nodes: np.ndarray
    anchor_nodes: np.ndarray
    anchor_position: np.ndarray
    x_guess: np.ndarray
    node_mass: np.ndarray
    node_added_mass: np.ndarray
    node_force: np.ndarray
    el_i: np.ndarray
    el_j: np.ndarray
    el_length: np.ndarray
    el_mass: np.ndarray
    el_added_mass: np.ndarray
    el_weight: np.ndarray
    el_displaced: np.ndarray
    el_cn: np.ndarray
    el_ct: np.ndarray
    el_stretch_drag: np.ndarray
    el_damping: np.ndarray
    el_law: np.ndarray
    law_kind: np.ndarray
    law_n: np.ndarray
    law_x: np.ndarray
    law_y: np.ndarray
    body_names: list
    body_node: np.ndarray
    body_drag_area: np.ndarray
    body_spreading: np.ndarray
    buoy_body: np.ndarray
    buoy_area: np.ndarray
    buoy_height: np.ndarray
    node_cable: np.ndarray
    node_s: np.ndarray
    node_index: np.ndarray
    segment_cable: np.ndarray
    cable_names: list
    cable_first_element: np.ndarray
    names: dict = field(default_factory=dict)

    @property
    def n_nodes(self) -> int:
        return len(self.free)

    @property
    def n_elements(self) -> int:
        return len(self.el_i)

    def where(self, node: int) -> str:
        """``cable 'x' node k`` for an internal node, for messages."""
        hits = np.flatnonzero(self.node_index == node)
        if len(hits) == 0:
            return f"node {node}"
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


class _Builder:
    """Collects nodes while walking the cables."""

    def __init__(self, case):
        self.case = case
        self.named: dict[str, int] = {}
        self.positions: list = []       # guessed position or None
        self.kinds: list[str] = []

    def node(self, kind: str, position=None) -> int:
        self.kinds.append(kind)
        self.positions.append(None if position is None else np.asarray(position, float))
        return len(self.kinds) - 1

    def end_node(self, end) -> int:
        if end.kind == "vessel":
            if "@vessel" not in self.named:
                self.named["@vessel"] = self.node("vessel", self.case.vessel.tow_point)
            return self.named["@vessel"]
        if end.kind == "anchor":
            return self.node("anchor", end.position)
        if end.kind == "free":
            return self.node("free")
        if end.name not in self.named:
            item = (self.case.bodies if end.kind == "body" else self.case.points)[end.name]
            self.named[end.name] = self.node(end.kind, getattr(item, "position", None))
        return self.named[end.name]


def _guess_positions(builder: _Builder, ends: list[tuple[int, int, float]]) -> None:
    """Place unknown end nodes a cable length from a known one, astern and down."""
    pos = builder.positions
    for _ in range(len(ends) + 1):
        changed = False
        for a, b, length in ends:
            for known, unknown in ((a, b), (b, a)):
                if pos[known] is not None and pos[unknown] is None:
                    pos[unknown] = pos[known] + 0.9 * length * VESSEL_GUESS_DIRECTION
                    changed = True
        if not changed:
            break
    missing = [i for a, b, _ in ends for i in (a, b) if pos[i] is None]
    if missing:
        raise CaseError([Problem("cables", "part of the network is joined to neither the vessel nor "
                                           "an anchor: give its bodies or points a 'position'")])


def sagged_line(p0, p1, length: float, segments: int) -> np.ndarray:
    """Nodes of a cable between ``p0`` and ``p1``: straight when the chord is longer than
    ``GUESS_STRETCH`` times ``length``, else a parabola sagging downward whose polyline is
    that long (elements taut, so the equilibrium's tangent is regular from the start)."""
    xi = np.linspace(0.0, 1.0, segments + 1)[:, None]
    chord = p1 - p0
    straight = p0 + chord * xi
    target = GUESS_STRETCH * length
    if np.linalg.norm(chord) >= target:
        return straight
    down = np.array([0.0, 0.0, -1.0]) - chord * (-chord[2]) / max(chord @ chord, 1e-300)
    if np.linalg.norm(down) < 1e-9:                  # vertical chord: bow sideways
        down = np.array([1.0, 0.0, 0.0])
    down /= np.linalg.norm(down)
    shape = 4.0 * xi * (1.0 - xi) * down
    polyline = lambda sag: np.sum(np.linalg.norm(np.diff(straight + sag * shape, axis=0), axis=1))  # noqa: E731
    low, high = 0.0, target
    for _ in range(100):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if polyline(mid) < target else (low, mid)
    return straight + 0.5 * (low + high) * shape


def build_network(case) -> Network:
    """Assemble the lumped network of ``case`` (module docstring).

    Raises
    ------
    CaseError
        When a part of the network has no prescribed node to hang from and no position.
    """
    env = case.environment
    rho, g = env.water_density, env.gravity
    b = _Builder(case)
    laws = law_arrays(case.line_types)
    el_rows, ends, cable_nodes = [], [], []
    for cable in case.cables:
        first, last = b.end_node(cable.from_), b.end_node(cable.to)
        inner = [b.node("cable") for _ in range(cable.segments - 1)]
        nodes = [first, *inner, last]
        cable_nodes.append(nodes)
        ends.append((first, last, cable.length))
        lt = case.line_types[cable.line_type]
        el_rows.append((nodes, cable, lt))
    _guess_positions(b, ends)
    x = np.zeros((len(b.kinds), 3))
    for nodes, cable, _ in el_rows:
        x[nodes] = sagged_line(b.positions[nodes[0]], b.positions[nodes[-1]], cable.length, cable.segments)
    return _finish(case, b, laws, el_rows, cable_nodes, x, rho, g)


def _element_arrays(el_rows, laws, rho, g):
    cols = {k: [] for k in ("i", "j", "L", "m", "ma", "w", "disp", "cn", "ct", "stretch", "c", "law")}
    for nodes, cable, lt in el_rows:
        n = cable.segments
        weight = lt.weight_in_water_value(rho, g)
        dimensional = lt.drag_normal_coefficient is not None or lt.drag_tangential_coefficient is not None
        if dimensional:
            cn, ct = lt.drag_normal_coefficient or 0.0, lt.drag_tangential_coefficient or 0.0
        else:
            cn = 0.5 * rho * lt.diameter * lt.drag_normal
            ct = 0.5 * rho * math.pi * lt.diameter * lt.drag_tangential
        values = {"i": nodes[:-1], "j": nodes[1:], "L": [cable.length / n] * n, "m": [lt.mass] * n,
                  "ma": [lt.added_mass] * n, "w": [weight] * n,
                  "disp": [(lt.mass * g - weight) / g] * n, "cn": [cn] * n, "ct": [ct] * n,
                  "stretch": [0.0 if dimensional else 1.0] * n, "c": [lt.axial_damping] * n,
                  "law": [laws[0][cable.line_type]] * n}
        for k, v in values.items():
            cols[k].extend(v)
    return cols


def _finish(case, b, laws, el_rows, cable_nodes, x, rho, g) -> Network:
    n = len(b.kinds)
    kinds = np.array(b.kinds)
    node_mass, node_added, node_force = np.zeros(n), np.zeros(n), np.zeros((n, 3))
    body_names = [name for name in case.bodies if name in b.named]
    body_node = np.array([b.named[k] for k in body_names], dtype=np.int64)
    for name, node in zip(body_names, body_node):
        body = case.bodies[name]
        node_mass[node] += body.mass
        node_added[node] += body.added_mass
        node_force[node] += np.asarray(body.force) + np.array([0.0, 0.0, body.net_buoyancy])
    for name, point in case.points.items():
        if name in b.named:
            node_mass[b.named[name]] += point.mass
            node_force[b.named[name], 2] -= point.mass * g
    buoys = [k for k, name in enumerate(body_names) if case.bodies[name].surface_buoy is not None]
    cols = _element_arrays(el_rows, laws, rho, g)
    names, s, index, seg_cable, first_el = [], [], [], [], []
    for (nodes, cable, _), cn in zip(el_rows, cable_nodes):
        first_el.append(len(seg_cable))
        names += [cable.name] * len(nodes)
        s.extend(np.linspace(0.0, cable.length, len(nodes)))
        index.extend(cn)
        seg_cable += [cable.name] * cable.segments
    arr = lambda k, dt=float: np.asarray(cols[k], dtype=dt)  # noqa: E731
    return Network(
        free=~np.isin(kinds, ["vessel", "anchor"]),
        vessel_nodes=np.flatnonzero(kinds == "vessel"), anchor_nodes=np.flatnonzero(kinds == "anchor"),
        anchor_position=x[kinds == "anchor"].copy(), x_guess=x,
        node_mass=node_mass, node_added_mass=node_added, node_force=node_force,
        el_i=arr("i", np.int64), el_j=arr("j", np.int64), el_length=arr("L"), el_mass=arr("m"),
        el_added_mass=arr("ma"), el_weight=arr("w"), el_displaced=arr("disp"), el_cn=arr("cn"),
        el_ct=arr("ct"), el_stretch_drag=arr("stretch"), el_damping=arr("c"), el_law=arr("law", np.int64),
        law_kind=laws[1], law_n=laws[2], law_x=laws[3], law_y=laws[4],
        body_names=body_names, body_node=body_node,
        body_drag_area=np.array([case.bodies[k].drag_area for k in body_names]),
        body_spreading=np.array([case.bodies[k].spreading_force for k in body_names]),
        buoy_body=np.array(buoys, dtype=np.int64),
        buoy_area=np.array([case.bodies[body_names[k]].surface_buoy.waterplane_area for k in buoys]),
        buoy_height=np.array([case.bodies[body_names[k]].surface_buoy.height for k in buoys]),
        node_cable=np.array(names, dtype=object), node_s=np.array(s), node_index=np.array(index, np.int64),
        segment_cable=np.array(seg_cable, dtype=object), cable_names=[c.name for c in case.cables],
        cable_first_element=np.array(first_el, dtype=np.int64), names=dict(b.named))
