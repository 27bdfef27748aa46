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
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from kanat.statics.network import NetworkSolution, assemble, warm_starts
from kanat.statics.network_setup import LineEnd, NetworkNode, NetworkProblem

__all__ = ["VESSEL", "CoupledStiffness", "coupled_groups", "coupled_stiffness"]

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
