"""A first guess for the lumped equilibrium from network statics: every cable along its
catenary (:mod:`kanat.statics.network`), solved for the case in still water.

The catenary carries weight, buoyancy, sections, point loads and the seabed, not drag, so the
case's current is dropped for the guess (the lumped equilibrium then adds it). A surface buoy
(a 3-DOF body whose node is its keel, buoyed by ``rho g A_w clip(-z, 0, h)`` in still water,
:class:`kanat.model.body.SurfaceBuoy`) becomes a network body with the linear waterplane
restoring of its immersion::

    (1)  F_z = net_buoyancy - rho g A_w z          (the keel at z <= 0)

written as a ``dof: 6`` node with that heave stiffness about ``z = 0`` (its rotations are held by
a unit stiffness: nothing turns it, its lines meeting at its keel). Each lumped node is then put
at its unstretched arclength on the solved catenary (:func:`kanat.statics.piecewise.sample`). A
line lying slack on the seabed (``H = 0``) is sampled in its limit ``H -> 0+``: straight along
the seabed to the touchdown point, then vertical. That leaves its far end where it is only if
the grounded part is stretched out; a 3-DOF body or point held by that one line alone (its
horizontal place is not unique) is moved to the sampled end, otherwise the grounded part is
compressed horizontally onto the solved span (its elements slack, as they are).

In a current the catenaries are then solved once more with the drag ``D_k`` that the lumped
model's loads put on each node ``k`` of that shape (its loads with the current less those
without) carried to the network's nodes by the lever rule along each cable::

    (2)  F_from += (1 - s_k / L) D_k,    F_to += (s_k / L) D_k

(a fixed end's share goes to its anchor; a network node's own drag is its own), so that the
lines' horizontal tension is of the right size: the guess then overshoots the buoy of
``examples/surface_mooring_waves.yaml`` downstream by 7.8 m (the drag at the top instead of along
the riser), 23 taut Newton iterations from the equilibrium instead of 85 without eq. (2).

None when the case moves the vessel at t = 0 (the catenary would hang a towed cable
vertically), or when network statics cannot represent or solve it: the caller falls back.
"""
from __future__ import annotations

import dataclasses
import logging

import numpy as np

from kanat.errors import CaseError, SolverError

log = logging.getLogger(__name__)

END_MISMATCH = 1e-6      # of the line's length: a sampled end this far from its node is not on it
ROTATION_STIFFNESS = 1.0  # N m/rad holding a surface buoy's unused angles in the statics network


def catenary_guess(net, case) -> np.ndarray | None:
    """Node positions (n, 3) of ``net`` along the still-water catenaries of ``case``, or None
    (module docstring).

    Parameters
    ----------
    net : kanat.lumped.network.Network
    case : kanat.model.Case
    """
    if case.vessel.initial_speed:
        return None
    from kanat.statics.network import solve_network
    from kanat.statics.network_result import first_guess

    try:
        still, problem = _problem(case)
        solution = solve_network(problem, first_guess(problem))
        x = _place(net, case, problem, solution)
        if still is not case:                    # the current's drag on the still-water shape, eq. (2)
            problem = _with_drag(net, case, still, problem, x)
            solution = solve_network(problem, solution.q)
            x = _place(net, case, problem, solution)
    except (CaseError, SolverError, ArithmeticError, ValueError, np.linalg.LinAlgError) as error:
        log.debug(f"lumped equilibrium: no catenary first guess ({error})")
        return None
    return x if np.all(np.isfinite(x)) else None


def _problem(case):
    """The still-water network problem of ``case``, surface buoys as eq. (1)."""
    from kanat.model.environment import Current
    from kanat.statics.network_setup import NetworkNode, network_problem

    env = case.environment
    current = env.current
    moving = any(any(row[1:]) for row in (current.profile or ((0.0, *(current.velocity or (0.0, 0.0, 0.0))),)))
    still = case.model_copy(update={"environment": env.model_copy(update={"current": Current()})}) if moving else case
    problem = network_problem(still)
    nodes = []
    for node in problem.nodes:
        body = case.bodies.get(node.name) if node.kind == "body" else None
        if body is not None and body.surface_buoy is not None:
            stiffness = np.diag([0.0, 0.0, env.water_density * env.gravity * body.surface_buoy.waterplane_area,
                                 ROTATION_STIFFNESS, ROTATION_STIFFNESS, ROTATION_STIFFNESS])
            node = NetworkNode(node.name, "body", 6, None, np.zeros(3), node.force, hydrostatic=stiffness)
        nodes.append(node)
    return still, dataclasses.replace(problem, nodes=nodes)


def _with_drag(net, case, still, problem, x):
    """``problem`` with the current's drag on the lumped nodes at ``x`` (n, 3) added to its nodes'
    constant forces, eq. (2)."""
    from kanat.lumped.system import LumpedSystem

    def loads(which):
        system = LumpedSystem(net, which, waves=False, steady_velocity=np.zeros(3))
        full, v, _, heading = system.full(0.0, x[system.free_index], np.zeros((len(system.free_index), 3)))
        return system.loads(0.0, full, v, heading)[0]
    drag = loads(case) - loads(still)
    index = {node.name: n for n, node in enumerate(problem.nodes)}
    owner = {}                                   # lumped node -> network node it belongs to
    for name, n in index.items():
        if name in net.names:
            owner[net.names[name]] = n
    for key, node in net.names.items():          # a 6-DOF body's fairleads
        if "@" in key and key.split("@")[0] in index:
            owner[node] = index[key.split("@")[0]]
    extra = np.zeros((len(problem.nodes), 3))
    for cable in case.cables:
        mask = net.node_cable == cable.name
        nodes, share = net.node_index[mask], net.node_s[mask] / cable.length
        ends = (nodes[0], nodes[-1])
        for node, f in zip(nodes, share):
            if node in owner:
                continue                         # a network node's own drag, added once below
            for end, weight in zip(ends, (1.0 - f, f)):
                if end in owner:
                    extra[owner[end]] += weight * drag[node]
    for node, n in owner.items():
        extra[n] += drag[node]
    nodes = [dataclasses.replace(node, force=node.force + extra[n]) for n, node in enumerate(problem.nodes)]
    return dataclasses.replace(problem, nodes=nodes)


def _place(net, case, problem, solution) -> np.ndarray:
    """The lumped nodes on the solved lines, the network's nodes at their solved places."""
    from kanat.statics.network import fairlead
    from kanat.statics.piecewise import sample

    x = net.x_guess.copy()
    q = solution.q
    place = {}                                   # network node -> lumped node(s) to move with it
    for n, node in enumerate(problem.nodes):
        at = problem.offsets[n]
        if node.name in net.names and net.names[node.name] in np.flatnonzero(net.free):
            place[n] = net.names[node.name]
            x[place[n]] = q[at:at + 3]
        elif node.name in net.rigid.names:
            b = net.rigid.names.index(node.name)
            x[net.rigid.ref_node[b]], x[net.rigid.rot_node[b]] = q[at:at + 3], q[at + 3:at + 6]
    degree = np.zeros(len(problem.nodes), dtype=int)
    for line in problem.lines:
        for end in line.ends:
            if end.node >= 0:
                degree[end.node] += 1
    for line, state in zip(problem.lines, solution.lines):
        mask = net.node_cable == line.name
        nodes, s = net.node_index[mask], net.node_s[mask]
        sol = state.solution
        pieces = line.pieces.reversed() if state.reversed else line.pieces
        length = line.pieces.total_length
        along, up, _, _ = sample(length - s if state.reversed else s, sol.horizontal_tension,
                                 sol.vertical_tension, pieces, state.ground)
        far = line.ends[0 if state.reversed else 1]                    # end B of the line's plane
        b_row = 0 if state.reversed else -1
        span = float(np.hypot(*(fairlead(problem, q, far)[0] - state.origin)[:2]))
        if sol.slack and abs(along[b_row] - span) > END_MISMATCH * length:
            if far.node in place and degree[far.node] == 1:
                x[place[far.node]] = state.origin + along[b_row] * state.direction + up[b_row] * np.array([0, 0, 1.0])
            elif along[b_row] > 0.0:
                along = along * span / along[b_row]
        x[nodes] = state.origin + np.outer(along, state.direction) + np.outer(up, [0.0, 0.0, 1.0])
    seabed = _seabed(case)
    if seabed is not None:                       # a catenary's round-off below a flat seabed
        loose = net.free
        x[loose, 2] = np.maximum(x[loose, 2], np.where(net.kinds[loose] == "body_rot", -np.inf,
                                                        seabed.height(x[loose, 0], x[loose, 1])))
    return x


def _seabed(case):
    from kanat.physics.seabed import seabed_of
    return seabed_of(case.environment)
