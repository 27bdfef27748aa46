"""The offset curve of a moored vessel: restoring force and line tensions against offset.

The vessel (every cable end ``{vessel: [x, y, z]}``, held in statics) is moved rigidly by
``d_k = k (to / steps) (cos theta, sin theta, 0)``, ``k = 0 .. steps``, ``theta`` the
direction from the x axis towards y; at each offset the network statics
(:mod:`kanat.statics.network`) is solved again, from the previous offset's equilibrium, with
every free point and body re-balanced. At offset ``d`` the vessel's ends are at ``d + R a``
(:func:`displaced`, ``R = Rz(yaw) Ry(pitch) Rx(roll)``; no rotation along the curve). The
slope of the force against offset is the coupled stiffness of :mod:`kanat.statics.coupled`
(tests/statics/test_offsets.py checks one against the other).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from kanat.errors import CaseError, Problem, SolverError
from kanat.statics.network import NetworkSolution, cross, solve_network
from kanat.statics.network_result import _cable, _check_seabed, _check_loaded, first_guess
from kanat.statics.network_setup import LineEnd, NetworkProblem, fairlead_rotation, network_problem

__all__ = ["OffsetCurve", "displaced", "offset_curve", "vessel_load"]


@dataclass(frozen=True, eq=False)
class OffsetCurve:
    """Restoring force and line tensions of a moored vessel against its offset.

    Attributes
    ----------
    offset : ndarray, shape (n,)
        Horizontal offset of the vessel along ``direction_deg`` [m].
    direction_deg : float
        Direction of the offset, from the x axis towards y [deg].
    force, moment : ndarray, shape (n, 3)
        Force of the lines on the vessel [N] and its moment about the vessel's (moved)
        origin [N m]: the restoring force is the horizontal part.
    cables : list of str
    tension : ndarray, shape (n, len(cables), 2)
        Tension at each cable's ``from`` and ``to`` ends [N] (fairlead and anchor).
    """

    offset: np.ndarray
    direction_deg: float
    force: np.ndarray
    moment: np.ndarray
    cables: list
    tension: np.ndarray


def displaced(problem: NetworkProblem, translation, rotation=(0.0, 0.0, 0.0)) -> NetworkProblem:
    """``problem`` with the vessel's ends moved rigidly to ``translation + R(rotation) a``.

    Parameters
    ----------
    translation : array_like, shape (3,)
        [m].
    rotation : array_like, shape (3,)
        Roll, pitch, yaw of the vessel about its origin [rad].
    """
    R = fairlead_rotation(np.asarray(rotation, dtype=float))[0]
    t = np.asarray(translation, dtype=float)
    lines = []
    for line in problem.lines:
        ends = tuple(LineEnd(end.node, t + R @ end.point, end.kind, end.on_seabed, end.load)
                     if end.node < 0 and end.kind == "vessel" else end for end in line.ends)
        lines.append(replace(line, ends=ends))
    return NetworkProblem(list(problem.nodes), lines, problem.seabed, problem.friction, problem.gravity)


def vessel_load(solution: NetworkSolution, origin=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """Force of the lines on the vessel's ends [N] and its moment about ``origin`` [N m]."""
    force, moment = np.zeros(3), np.zeros(3)
    for line, state in zip(solution.problem.lines, solution.lines):
        for i, end in enumerate(line.ends):
            if end.node < 0 and end.kind == "vessel":
                f = state.forces[i] - np.array([0.0, 0.0, end.load])
                force += f
                moment += cross(end.point - np.asarray(origin, dtype=float), f)
    return force, moment


def offset_curve(case, direction_deg: float, to: float, steps: int = 20) -> OffsetCurve:
    """The offset curve of ``case`` (module docstring).

    Parameters
    ----------
    case : kanat.model.Case
        A network in still water whose cables end at the vessel.
    direction_deg : float
        [deg], from the x axis towards y.
    to : float
        Largest offset [m] (negative: the other way).
    steps : int
        Offsets after the first (0), evenly spaced.

    Raises
    ------
    CaseError
        When no cable ends at the vessel.
    SolverError
        When the statics does not converge at some offset (the message names it).
    """
    if steps < 1:
        raise ValueError(f"steps must be at least 1, not {steps}")
    _check_loaded(case)
    problem = network_problem(case)
    if not any(end.node < 0 and end.kind == "vessel" for line in problem.lines for end in line.ends):
        raise CaseError([Problem("cables", "no cable ends at the vessel, so there is nothing to offset; "
                                 "give the fairleads as cable ends {vessel: [x, y, z]}")])
    theta = math.radians(direction_deg)
    unit = np.array([math.cos(theta), math.sin(theta), 0.0])
    offsets = np.linspace(0.0, to, steps + 1)
    q = first_guess(problem)
    forces, moments, tensions = [], [], []
    for d in offsets:
        moved = displaced(problem, d * unit)
        try:
            solution = solve_network(moved, q)
            _check_seabed(moved, {line.name: _cable(moved, line, state)
                                  for line, state in zip(moved.lines, solution.lines)})
        except SolverError as error:
            raise SolverError(f"at an offset of {d:.4g} m along {direction_deg:g} deg: {error}") from error
        q = solution.q
        force, moment = vessel_load(solution, d * unit)
        forces.append(force)
        moments.append(moment)
        tensions.append([[float(np.linalg.norm(f)) for f in state.forces] for state in solution.lines])
    return OffsetCurve(offsets, float(direction_deg), np.array(forces), np.array(moments),
                       [line.name for line in problem.lines], np.array(tensions))
