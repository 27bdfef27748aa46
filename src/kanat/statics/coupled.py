"""Mooring stiffness at the coupled ends: what a host program that drives the vessel sees.

In statics the vessel's fairleads (cable ends ``{vessel: [x, y, z]}``, MoorDyn's
``Vessel``/``Coupled`` points and the points of its coupled bodies) are held at their
places, the vessel at the origin with heading 0. Its stiffness is the change of the
lines' force on those ends when they move, every free point and body re-balanced::

    (1)  K = K_cc - K_cf K_ff^-1 K_fc,        K = -dQ/dc

(static condensation, MoorPy's ``getCoupledStiffnessA``; its ``getCoupledStiffness``
takes finite differences of the same), with ``c`` the coupled coordinates, ``f`` the free
unknowns of :mod:`kanat.statics.network`, ``Q`` the lines' force on the coupled ends and
``K_ff`` the free nodes' full tangent (lines and their own loads). The blocks are the
lines' analytic end stiffnesses (eq. 3 of :mod:`kanat.statics.network`): the coupled ends
are made nodes of an augmented network, assembled once at the equilibrium.

Two views of the same ends:

* the **vessel** as a rigid body (named ``vessel``): 6x6 about the vessel origin, per metre
  of translation and per radian of small rotation about the global axes; a fairlead at
  ``a`` moves by ``dr + omega x a``, its force ``f`` adds the moment ``a x f`` and, as the
  lever turns, the geometric term ``-S(f) S(a)`` (MoorPy's ``Body.getStiffnessA``);
* each **coupled point** (the vessel's ends grouped by position, named by its first cable
  end, ``line1.to``): 3x3 of that point moving alone, the other coupled points held.

Several coupled bodies (a MoorDyn file's ``Coupled`` bodies, :mod:`kanat.io.moordyn_coupled`) are
each their own rigid body (:func:`coupled_body_stiffness`): body ``b`` a 6-DOF node at its
reference point ``X_b``, its fairleads at ``o = r - X_b`` in global axes, and eq. (1) of all
of them together is the ``6 N x 6 N`` matrix of MoorPy's ``getCoupledStiffness`` (body by body
in file order, each ``(surge, sway, heave, roll, pitch, yaw)`` about its own reference point;
the off-diagonal blocks are what a line shared by two bodies couples). Each body's own 6x6
is its diagonal block, the other bodies held.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from kanat.statics.network import NetworkSolution, assemble, warm_starts
from kanat.statics.network_setup import LineEnd, NetworkNode, NetworkProblem

__all__ = ["VESSEL", "CoupledBodies", "CoupledStiffness", "coupled_body_stiffness", "coupled_groups",
           "coupled_stiffness"]

VESSEL = "vessel"
SAME_POINT = 1e-9            # m: vessel ends closer than this are one coupled point


@dataclass(frozen=True, eq=False)
class CoupledStiffness:
    """The coupled ends at equilibrium.

    Attributes
    ----------
    points : dict of str to ndarray, shape (3,)
        Position of each coupled point [m].
    point_forces : dict of str to ndarray, shape (3,)
        Force of the lines on each coupled point [N].
    point_stiffness : dict of str to ndarray, shape (3, 3)
        Eq. (1) at each point, the other coupled points held [N/m].
    matrix : ndarray, shape (3 n, 3 n)
        Eq. (1) of all coupled points together, in the order of ``points``.
    body_force, body_moment : ndarray, shape (3,)
        Resultant force of the lines on the vessel [N] and its moment about the origin [N m].
    body_stiffness : ndarray, shape (6, 6)
        Eq. (1) of the vessel as a rigid body about the origin.
    """

    points: dict
    point_forces: dict
    point_stiffness: dict
    matrix: np.ndarray
    body_force: np.ndarray
    body_moment: np.ndarray
    body_stiffness: np.ndarray


def coupled_groups(problem: NetworkProblem) -> list[tuple[str, np.ndarray, list[tuple[int, int]]]]:
    """The vessel's ends grouped by position: ``(name, position, [(line, end), ...])``."""
    groups: list[tuple[str, np.ndarray, list]] = []
    for k, line in enumerate(problem.lines):
        for i, end in enumerate(line.ends):
            if end.node >= 0 or end.kind != "vessel":
                continue
            for _, where, members in groups:
                if np.max(np.abs(where - end.point)) <= SAME_POINT:
                    members.append((k, i))
                    break
            else:
                groups.append((f"{line.name}.{('from', 'to')[i]}", end.point.copy(), [(k, i)]))
    return groups


def _augmented(problem: NetworkProblem, nodes: list, where) -> NetworkProblem:
    """``problem`` with ``nodes`` added and each vessel end ``(line, end)`` re-attached to
    ``where[(line, end)] = (node index, offset)``."""
    lines = []
    for k, line in enumerate(problem.lines):
        ends = tuple(LineEnd(where[(k, i)][0], where[(k, i)][1], end.kind, False, end.load) if (k, i) in where
                     else end for i, end in enumerate(line.ends))
        lines.append(replace(line, ends=ends))
    return NetworkProblem(list(problem.nodes) + nodes, lines, problem.seabed, problem.friction, problem.gravity)


def _condensed(J: np.ndarray, n_free: int) -> np.ndarray:
    """Eq. (1) from the full tangent ``J = dR/dq`` whose first ``n_free`` unknowns are free.

    ``K_ff^-1 K_fc`` is the least-squares solution of least norm: a free body whose yaw nothing
    restores leaves ``K_ff`` singular, and that turn then carries no load (as in
    :func:`kanat.statics.network_result.condensed_stiffness`)."""
    K = -J
    c, f = slice(n_free, None), slice(0, n_free)
    if n_free == 0:
        return K[c, c]
    return K[c, c] - K[c, f] @ np.linalg.lstsq(K[f, f], K[f, c], rcond=None)[0]


def coupled_stiffness(solution: NetworkSolution) -> CoupledStiffness | None:
    """Eq. (1) at the vessel and its coupled points, at the equilibrium ``solution``; None
    when no cable ends at the vessel."""
    problem = solution.problem
    groups = coupled_groups(problem)
    if not groups:
        return None
    n_free = problem.offsets[-1]
    starts = warm_starts(solution.lines)
    single = len(problem.nodes)
    rigid = _augmented(problem, [NetworkNode(VESSEL, "body", 6, np.zeros(3))],
                       {member: (single, point) for _, point, members in groups for member in members})
    R, J, _, _ = assemble(rigid, np.concatenate([solution.q, np.zeros(6)]), starts)
    body = _condensed(J, n_free)
    names = [name for name, _, _ in groups]
    points = _augmented(problem, [NetworkNode(name, "point", 3, point) for name, point, _ in groups],
                        {member: (single + g, np.zeros(3)) for g, (_, _, members) in enumerate(groups)
                         for member in members})
    R_points, J_points, _, _ = assemble(points, np.concatenate([solution.q, *[p for _, p, _ in groups]]), starts)
    matrix = _condensed(J_points, n_free)
    return CoupledStiffness(
        {name: point.copy() for name, point, _ in groups},
        {name: R_points[n_free + 3 * g:n_free + 3 * g + 3].copy() for g, name in enumerate(names)},
        {name: matrix[3 * g:3 * g + 3, 3 * g:3 * g + 3].copy() for g, name in enumerate(names)},
        matrix, R[n_free:n_free + 3].copy(), R[n_free + 3:n_free + 6].copy(), body)


@dataclass(frozen=True, eq=False)
class CoupledBodies:
    """Several coupled rigid bodies at equilibrium, each about its own reference point.

    Attributes
    ----------
    positions : dict of str to ndarray, shape (3,)
        Each body's reference point [m], in the order of ``matrix``.
    forces, moments : dict of str to ndarray, shape (3,)
        Resultant force of the lines on each body [N] and its moment about the body's reference
        point [N m].
    stiffness : dict of str to ndarray, shape (6, 6)
        Each body's diagonal block of ``matrix``: eq. (1) of that body moving alone, the other
        coupled bodies and points held.
    matrix : ndarray, shape (6 N, 6 N)
        Eq. (1) of all the bodies together (MoorPy's ``getCoupledStiffness``): rows and columns
        ``6 b .. 6 b + 5`` are body ``b``'s surge, sway, heave [m] and small rotations about the
        global axes [rad] at its reference point.
    """

    positions: dict
    forces: dict
    moments: dict
    stiffness: dict
    matrix: np.ndarray


def coupled_body_stiffness(solution: NetworkSolution, bodies) -> CoupledBodies:
    """Eq. (1) of the coupled ``bodies`` (sequence of :class:`kanat.io.moordyn_coupled.CoupledBody`)
    as rigid bodies, each about its reference point, at the equilibrium ``solution`` (module
    docstring). A vessel end on none of them stays held; a body with no line end has zero rows."""
    problem = solution.problem
    n_free = problem.offsets[-1]
    single = len(problem.nodes)
    nodes, where, q = [], {}, [solution.q]
    for b, body in enumerate(bodies):
        X = np.asarray(body.position, float)
        for _, point, members in coupled_groups(problem):
            if len(body.points) and np.min(np.max(np.abs(body.points - point), axis=1)) <= SAME_POINT * max(
                    1.0, np.max(np.abs(point))):
                where.update({member: (single + b, point - X) for member in members})
        nodes.append(NetworkNode(body.name, "body", 6, X.copy()))
        q.append(np.concatenate([X, np.zeros(3)]))
    augmented = _augmented(problem, nodes, where)
    R, J, _, _ = assemble(augmented, np.concatenate(q), warm_starts(solution.lines))
    matrix = _condensed(J, n_free)
    names = [body.name for body in bodies]
    load = R[n_free:].reshape(-1, 6)
    return CoupledBodies({name: np.asarray(body.position, float).copy() for name, body in zip(names, bodies)},
                         {name: load[b, :3].copy() for b, name in enumerate(names)},
                         {name: load[b, 3:].copy() for b, name in enumerate(names)},
                         {name: matrix[6 * b:6 * b + 6, 6 * b:6 * b + 6].copy() for b, name in enumerate(names)},
                         matrix)
