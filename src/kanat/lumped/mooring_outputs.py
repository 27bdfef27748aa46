"""Mooring outputs of the lumped model (case-format.md): seabed contact length, line forces on
bodies, body attitudes, and the penetration the seabed check allows.

* ``seabed_contact_length(cable) = sum_k L0_k (c_i + c_j) / 2`` with ``c = 1`` at a node the
  seabed pushes (normal force > 0): half an element per node in contact;
* the lines' force on a body: at each of its nodes (a 3-DOF body's node, a 6-DOF body's
  fairleads), ``sum_k (+/- T_k t_k - w0_k L0_k / 2 z)`` over the elements there — the end
  tension and the weight in water of the half element the node carries (as statics reports it);
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

from kanat.physics.contact import PENETRATION_FLOOR, PENETRATION_MARGIN

NO_CONTACT_RTOL = 1e-9     # below the seabed by more than this fraction of the depth fails without contact
SURFACE_MARGIN = 1.0
"""A buoyant body's center may rise this far [m] (or its diameter) above the wave surface before
:func:`out_of_water` says it is out of the water."""


def contact_length(net, normal_force: np.ndarray, anchors_on_seabed=None) -> np.ndarray:
    """Unstretched length of each cable resting on the seabed (n_cables,) [m]; anchors on the
    seabed (``anchors_on_seabed`` (n_anchor,)) count as touching."""
    touching = (normal_force > 0.0).astype(float)
    if anchors_on_seabed is not None:
        touching[net.anchors[np.asarray(anchors_on_seabed, bool)]] = 1.0
    per_element = net.el_length * 0.5 * (touching[net.el_i] + touching[net.el_j])
    out = np.zeros(len(net.cable_names))
    for c, first in enumerate(net.cable_first_element):
        last = net.cable_first_element[c + 1] if c + 1 < len(out) else net.n_elements
        out[c] = per_element[first:last].sum()
    return out


def _node_pull(net, x, T, node) -> np.ndarray:
    """The lines' force on ``node``: its elements' end tensions and half weights."""
    out = np.zeros(3)
    for ends, sign in ((net.el_i, 1.0), (net.el_j, -1.0)):
        for k in np.flatnonzero(ends == node):
            d = x[net.el_j[k]] - x[net.el_i[k]]
            out += sign * T[k] * d / np.linalg.norm(d)
            out[2] -= 0.5 * net.el_weight[k] * net.el_length[k]
    return out


def line_forces(net, x, T) -> np.ndarray:
    """Resultant force of the lines on each body (n_body, 3) [N]."""
    out = np.zeros((len(net.body_names), 3))
    rigid = net.rigid
    for b, (name, node) in enumerate(zip(net.body_names, net.body_node)):
        if name in rigid.names:
            r = rigid.names.index(name)
            for f in rigid.fairlead_node[rigid.fairlead_body == r]:
                out[b] += _node_pull(net, x, T, f)
        else:
            out[b] = _node_pull(net, x, T, node)
    return out


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
    out = F[net.anchors].reshape(-1, 3).copy()
    for guide in net.anchor_nodes[len(net.anchor_names):]:
        owner = _clamped_node(net, guide)
        out[np.flatnonzero(net.anchors == owner)] += F[guide]
    for a, node in enumerate(net.anchors):
        if not on_seabed[a]:
            continue
        for ends, others in ((net.el_i, net.el_j), (net.el_j, net.el_i)):
            for k in np.flatnonzero(ends == node):
                if normal_force[others[k]] > 0.0:
                    half = 0.5 * net.el_weight[k] * net.el_length[k]
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


def out_of_water(case, net, x, sea, t: float) -> str | None:
    """Why the state ``x`` is wrong for this model, if a body or point is out of the water: the model
    gives it its full buoyancy wherever it is (only a ``surface_buoy`` or a 6-DOF body has a
    waterplane), so its center more than :data:`SURFACE_MARGIN` (or its diameter, from
    ``drag_area`` or ``volume``) above the local wave surface (``sea``, None for still water)
    is refused; None when every one is in the water."""
    held = [(f"body '{name}'", node, np.sqrt(case.bodies[name].drag_area / np.pi))
            for name, node in zip(net.body_names, net.body_node)
            if case.bodies[name].surface_buoy is None and name not in net.rigid.names]
    held += [(f"point '{name}'", net.names[name], np.cbrt(0.75 * point.volume / np.pi))
             for name, point in case.points.items() if point.volume > 0.0 and name in net.names]
    for label, node, radius in held:
        r = x[node]
        eta = float(sea.elevation(np.array([r[0]]), np.array([r[1]]), t)[0]) if sea is not None else 0.0
        if r[2] - eta > max(SURFACE_MARGIN, 2.0 * radius):
            return (f"{label} is {r[2] - eta:.4g} m above the water surface at t = {t:.6g} s, where this model "
                    "would still give it its full buoyancy; give it a surface_buoy (waterplane_area, height) "
                    "to ride the surface, or lines that hold it under water")
    return None
