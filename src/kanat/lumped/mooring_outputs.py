"""Mooring outputs of the lumped model (case-format.md): seabed contact length, line forces on
bodies, body attitudes, and the penetration the seabed check allows.

* ``seabed_contact_length(cable) = sum_k L0_k (c_i + c_j) / 2`` with ``c = 1`` at a node the
  seabed pushes (normal force > 0): half an element per node in contact;
* the lines' force on a 3-DOF body: what the line ends exert on the body itself, not on the
  node that also carries half of each element next to it. The node's equation ``M a = F`` (system
  eq. 1) splits into the body's ``M_b a = F_b + F_line`` and its half elements', so

      F_line = M_b a - F_b,    M_b = (m + m_a) I,                                    (O1)

  with ``F_b`` the body's own loads (net buoyancy, ``force``, drag and fluid inertia, the
  buoyancy a spherical float loses out of the water, a surface buoy's waterplane) and ``a`` the
  node's acceleration; at rest ``F_line = -F_b`` (the continuum model's ``body_force``, which has
  no half elements). A 6-DOF body's fairleads are points of the body, so the half elements there
  are the body's load: ``sum_k (+/- T_k t_k - w0_k L0_k / 2 z)`` over the elements at its fairleads;
* the line's force on an anchor: the total force on its prescribed node (end tension and the
  half element's loads), less the half element's weight where that element rests on the seabed
  (both its ends touching, or the anchor on the seabed and the other end touching): the
  seabed carries it, not the anchor;
* the allowed penetration of node ``n``: ``PENETRATION_MARGIN max(W_n, 0) / (k_b A_n) + PENETRATION_FLOOR``
  (its weight in water over the contact stiffness; a node lighter than water, of a buoyant
  section, presses on nothing: the floor alone), or round-off without seabed contact.
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import kernels
from kanat.physics.contact import PENETRATION_FLOOR, PENETRATION_MARGIN, contact_forces
from kanat.physics.immersion import sphere_fractions

NO_CONTACT_RTOL = 1e-9     # below the seabed by more than this fraction of the depth fails without contact
SURFACE_MARGIN = 1.0
"""A buoyant body's center may rise this far [m] (or its diameter) above the wave surface before
:func:`out_of_water` says it is out of the water."""


def contact_length(net, normal_force: np.ndarray, anchors_on_seabed=None) -> np.ndarray:
    """Unstretched length of each cable resting on the seabed (n_cables,) [m]; anchors on the
    seabed (``anchors_on_seabed`` (n_anchor,)) count as touching."""
    return MooringOutputs(net, anchors_on_seabed).contact_length(normal_force)


def _node_elements(net, node) -> list[tuple[int, float]]:
    """The elements ending at ``node`` with the sign of their pull on it, ``el_i`` ends first."""
    return [(int(k), sign) for ends, sign in ((net.el_i, 1.0), (net.el_j, -1.0)) for k in np.flatnonzero(ends == node)]


def _node_pull(net, x, T, elements) -> np.ndarray:
    """The lines' force on a node: its elements' (:func:`_node_elements`) end tensions and half weights."""
    out = np.zeros(3)
    for k, sign in elements:
        d = x[net.el_j[k]] - x[net.el_i[k]]
        out += sign * T[k] * d / np.linalg.norm(d)
        out[2] -= 0.5 * net.el_weight[k] * net.el_length[k]
    return out


def line_forces(system, t, x, v, a, heading, T) -> np.ndarray:
    """Resultant force of the lines on each body (n_body, 3) [N], eq. (O1) (module docstring).

    ``system``: the run's :class:`kanat.lumped.system.LumpedSystem`; ``x, v, a`` (n, 3) every
    node's position, velocity and acceleration at time ``t``; ``heading`` the vessel's [rad] (the
    spreading force's direction); ``T`` (m,) the element tensions."""
    return MooringOutputs(system.net, case=system.case).line_forces(system, t, x, v, a, heading, T)


def own_loads(system, t, x, v, heading, bodies) -> np.ndarray:
    """The loads on 3-DOF bodies themselves, ``F_b`` of eq. (O1) (len(bodies), 3) [N].

    ``bodies``: indices into ``net.body_names``. Net buoyancy and ``force`` (``net.node_force``
    holds them with any point's at the same node, which is counted as the body's), drag, spreading
    and fluid inertia (:func:`kanat.lumped.kernels.body_loads`), the buoyancy a spherical float keeps
    out of the water (:func:`kanat.physics.immersion.sphere_fractions`), a surface buoy's waterplane
    and, for a body with a ``seabed_area``, its share ``A_b / A_n`` of its node's seabed contact."""
    net = system.net
    nodes = net.body_node[bodies]
    out = np.zeros((net.n_nodes, 3))
    out[nodes] = net.node_force[nodes]
    loads = np.flatnonzero(np.isin(net.load_node, nodes))
    if len(loads):
        u, aw = system.water(t, x[net.load_node[loads]])
        kernels.body_loads(x, v, u, aw, net.load_node[loads], net.load_drag_area[loads], net.load_spreading[loads],
                           net.node_fluid_inertia, system.rho, heading, out)
    for k, b in enumerate(net.float_body):
        node = net.body_node[b]
        share = sphere_fractions(x[node:node + 1, 2], _eta(system, x[node], t), net.float_diameter[k:k + 1])[0]
        out[node, 2] -= (1.0 - share) * net.float_buoyancy[k]
    for k, b in enumerate(net.buoy_body):
        node = net.body_node[b]
        immersion = np.clip(_eta(system, x[node], t) - x[node, 2], 0.0, net.buoy_height[k])
        out[node, 2] += system.rho * system.g * net.buoy_area[k] * immersion
    bearing = np.array([system.case.bodies[net.body_names[b]].seabed_area for b in bodies])
    if system.contact is not None and np.any(bearing > 0.0):
        seabed, contact = system.contact, np.zeros_like(out)
        contact_forces(x, v, net.el_i, net.el_j, seabed.area, seabed.seabed, seabed.law, seabed.laid,
                       np.zeros_like(out), contact, np.zeros(net.n_nodes))
        out[nodes] += (bearing / seabed.area[nodes])[:, None] * contact[nodes]
    return out[nodes]


def _eta(system, point, t) -> float:
    """The wave elevation over ``point`` (3,) [m], 0 in still water."""
    if system.sea is None:
        return 0.0
    return float(system.sea.elevation(point[:1], point[1:2], t)[0])


def attitudes(net, x) -> np.ndarray:
    """Roll, pitch, yaw of each body (n_body, 3) [rad]; zeros for point bodies."""
    out = np.zeros((len(net.body_names), 3))
    for r, name in enumerate(net.rigid.names):
        out[net.body_names.index(name)] = x[net.rigid.rot_node[r]]
    return out


def anchor_forces(net, F, normal_force, on_seabed, friction: float = 0.0) -> np.ndarray:
    """Force of the lines on each anchor (n_anchor, 3) [N] (module docstring); ``on_seabed``
    (n_anchor,) whether each anchor lies on the seabed; ``friction`` the axial coefficient, which
    on a resting half element also relieves the anchor of up to ``mu w L0 / 2`` of horizontal pull. The
    bending force on a clamped anchor's guide node (:mod:`kanat.lumped.clamps`) is the anchor's too."""
    return MooringOutputs(net, on_seabed).anchor_forces(F, normal_force, friction)


class MooringOutputs:
    """The mooring outputs of one network (module docstring), its element lists worked out once for
    the outputs of a whole run; the same numbers as the functions of this module.

    Parameters
    ----------
    net : kanat.lumped.network.Network
    on_seabed : ndarray of bool, shape (n_anchor,), optional
        Whether each anchor lies on the seabed (:func:`anchors_on_seabed`); none when not given.
    case : kanat.model.Case, optional
        The case the network is built from (its bodies' masses): :meth:`line_forces` needs it.
    """

    def __init__(self, net, on_seabed=None, case=None):
        self.net = net
        on_seabed = np.zeros(len(net.anchor_names), bool) if on_seabed is None else np.asarray(on_seabed, bool)
        self.resting_anchors = net.anchors[on_seabed]
        self.cable_bounds = [(first, net.cable_first_element[c + 1] if c + 1 < len(net.cable_names)
                              else net.n_elements) for c, first in enumerate(net.cable_first_element)]
        self.guides = [(np.flatnonzero(net.anchors == _clamped_node(net, guide)), guide)
                       for guide in net.anchor_nodes[len(net.anchor_names):]]
        self.anchor_elements = [(a, [(int(k), int(others[k]), 0.5 * net.el_weight[k] * net.el_length[k])
                                     for ends, others in ((net.el_i, net.el_j), (net.el_j, net.el_i))
                                     for k in np.flatnonzero(ends == node)])
                                for a, node in enumerate(net.anchors) if on_seabed[a]]
        rigid = net.rigid
        self.rigid_bodies = [b for b, name in enumerate(net.body_names) if name in rigid.names]
        self.point_bodies = np.array([b for b, name in enumerate(net.body_names) if name not in rigid.names],
                                     dtype=np.int64)
        self.body_mass = None if case is None else np.array(
            [case.bodies[net.body_names[b]].mass + case.bodies[net.body_names[b]].added_mass
             for b in self.point_bodies], dtype=float)
        self.body_elements = []
        for name, node in zip(net.body_names, net.body_node):
            nodes = (rigid.fairlead_node[rigid.fairlead_body == rigid.names.index(name)] if name in rigid.names
                     else [node])
            self.body_elements.append([_node_elements(net, f) for f in nodes])

    def contact_length(self, normal_force: np.ndarray) -> np.ndarray:
        """Unstretched length of each cable resting on the seabed (n_cables,) [m] (module docstring)."""
        net = self.net
        touching = (normal_force > 0.0).astype(float)
        touching[self.resting_anchors] = 1.0
        per_element = net.el_length * 0.5 * (touching[net.el_i] + touching[net.el_j])
        out = np.zeros(len(self.cable_bounds))
        for c, (first, last) in enumerate(self.cable_bounds):
            out[c] = per_element[first:last].sum()
        return out

    def line_forces(self, system, t, x, v, a, heading, T) -> np.ndarray:
        """Resultant force of the lines on each body (n_body, 3) [N] (:func:`line_forces`)."""
        out = np.zeros((len(self.body_elements), 3))
        for b in self.rigid_bodies:
            for elements in self.body_elements[b]:
                out[b] += _node_pull(self.net, x, T, elements)
        if len(self.point_bodies):
            nodes = self.net.body_node[self.point_bodies]
            out[self.point_bodies] = (self.body_mass[:, None] * a[nodes]
                                      - own_loads(system, t, x, v, heading, self.point_bodies))
        return out

    def anchor_forces(self, F, normal_force, friction: float = 0.0) -> np.ndarray:
        """Force of the lines on each anchor (n_anchor, 3) [N] (:func:`anchor_forces`)."""
        out = F[self.net.anchors].reshape(-1, 3).copy()
        for rows, guide in self.guides:
            out[rows] += F[guide]
        for a, elements in self.anchor_elements:
            for k, other, half in elements:
                if normal_force[other] > 0.0:
                    out[a, 2] += half
                    pull = np.hypot(out[a, 0], out[a, 1])
                    if pull > 0.0:
                        out[a, :2] *= max(pull - friction * half, 0.0) / pull
        return out


def _clamped_node(net, guide: int) -> int:
    """The end node whose clamp ``guide`` is (the middle of the guide's bending triple)."""
    before, node, after = net.bend[:3]
    return int(node[np.flatnonzero((before == guide) | (after == guide))[0]])


def anchors_on_seabed(net, environment) -> np.ndarray:
    """Whether each anchor (n_anchor,) lies on the seabed (within 1e-6 of the depth), none without one."""
    from kanat.physics.seabed import seabed_of

    seabed = seabed_of(environment)
    if seabed is None:
        return np.zeros(len(net.anchor_names), bool)
    return seabed.penetration(net.anchor_position[:len(net.anchor_names)]) > -1e-6 * seabed.depth


def allowed_penetration(net, environment) -> np.ndarray:
    """Penetration below the seabed each node may reach before a run fails (n,) [m]: never less than
    :data:`PENETRATION_FLOOR` (module docstring)."""
    block = environment.seabed
    if block is None:
        return np.full(net.n_nodes, NO_CONTACT_RTOL * (environment.depth or 0.0))
    area = net.node_contact_area
    weight = np.maximum(net.node_weight, 0.0)      # a node lighter than water presses on nothing
    static = np.where(area > 0, weight / (block.stiffness * np.maximum(area, 1e-300)), 0.0)
    return PENETRATION_MARGIN * static + PENETRATION_FLOOR


def held_under_water(case, net) -> list[tuple[str, int, float, str | None]]:
    """The bodies and points :func:`out_of_water` watches: ``(label, node, limit [m], part)``, the
    height above the local wave surface at which each is out of the water; ``part`` names the node
    of a body that floats by immersion (a ``surface_buoy``'s keel, a spherical float's center with
    a ``diameter``), None for one that keeps its buoyancy."""
    held = []
    for name, node in zip(net.body_names, net.body_node):
        body = case.bodies[name]
        if name in net.rigid.names:
            continue
        if body.surface_buoy is not None:
            held.append((f"surface buoy '{name}'", node, max(SURFACE_MARGIN, body.surface_buoy.height), "keel"))
        elif body.diameter is not None:
            held.append((f"float '{name}'", node, max(SURFACE_MARGIN, body.diameter), "center"))
        else:
            held.append((f"body '{name}'", node, max(SURFACE_MARGIN, 2.0 * np.sqrt(body.drag_area / np.pi)), None))
    held += [(f"point '{name}'", net.names[name], max(SURFACE_MARGIN, 2.0 * np.cbrt(0.75 * point.volume / np.pi)), None)
             for name, point in case.points.items() if point.volume > 0.0 and name in net.names]
    return held


def out_of_water(case, net, x, sea, t: float, held=None) -> str | None:
    """Why the state ``x`` is wrong for this model, if a body or point is out of the water: the model
    gives a body or point its full buoyancy wherever it is, so its center more than
    :data:`SURFACE_MARGIN` (or its diameter, from ``drag_area`` or ``volume``) above the local wave
    surface (``sea``, None for still water) is refused. A body that floats by immersion (a
    ``surface_buoy``'s waterplane, a spherical float with a ``diameter``: no radiation or slamming
    damping) is refused when thrown clear of the water by more than its height or diameter:
    measured, a 1-cm-draft buoy started off its forced heave bounced on the surface and gained
    energy until it flew 27 m high, which no floating buoy does. None when every one is in the
    water. ``held``: :func:`held_under_water` of the case, if already worked out."""
    for label, node, limit, part in held_under_water(case, net) if held is None else held:
        r = x[node]
        eta = float(sea.elevation(np.array([r[0]]), np.array([r[1]]), t)[0]) if sea is not None else 0.0
        if r[2] - eta <= limit:
            continue
        if part is not None:
            return (f"{label}'s {part} is {r[2] - eta:.4g} m above the water surface at t = {t:.6g} s, more "
                    "than its size: thrown clear of the water, where its immersion model (no radiation or "
                    "slamming damping) does not hold; a free heave started at its waterplane frequency (start "
                    "the waves with a ramp) or a line that snaps it up are the usual causes")
        return (f"{label} is {r[2] - eta:.4g} m above the water surface at t = {t:.6g} s, where this model "
                "would still give it its full buoyancy; give it a surface_buoy (waterplane_area, height) "
                "to ride the surface at a cable's end, a diameter (a spherical float) inline, or lines that "
                "hold it under water")
    return None
