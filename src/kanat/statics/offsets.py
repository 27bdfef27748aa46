"""The offset curve of a moored vessel: restoring force and line tensions against offset.

The vessel (every cable end ``{vessel: [x, y, z]}``, held in statics) is moved rigidly by
``d_k = k (to / steps) (cos theta, sin theta, 0)``, ``k = 0 .. steps``, ``theta`` the
direction from the x axis towards y; at each offset the network statics
(:mod:`kanat.statics.network`) is solved again, from the previous offset's equilibrium, with
every free point and body re-balanced. At offset ``d`` the vessel's ends are at ``d + R a``
(:func:`displaced`, ``R = Rz(yaw) Ry(pitch) Rx(roll)``; no rotation along the curve). The
slope of the force against offset is the coupled stiffness of :mod:`kanat.statics.coupled`
(tests/statics/test_offsets.py checks one against the other).

A case with several coupled bodies (a MoorDyn file's ``Coupled`` bodies, each its own body as in
:mod:`kanat.statics.coupled`) has, besides that system curve, each body's own curve
(:func:`body_offset_curves`): body ``b`` alone moved by ``d_k``, its points at ``X_b + d_k + R_b
o`` (no rotation), the other bodies held, every free point and body re-balanced; its force is the
lines' force on body ``b`` and its moment is about ``b``'s moved reference point ``X_b + d_k``, as
MoorPy's ``Body.getForces`` after ``setPosition`` and ``solveEquilibrium``. The slope of body
``b``'s curve at zero is the diagonal block of the coupled stiffness along the offset direction
(tests/peers/test_shared_body_offsets.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from kanat.errors import CaseError, Problem, SolverError
from kanat.statics.coupled import SAME_POINT
from kanat.statics.network import NetworkSolution, cross, solve_network
from kanat.statics.network_result import _cable, _check_seabed, _check_loaded, first_guess
from kanat.statics.network_setup import LineEnd, NetworkProblem, fairlead_rotation, network_problem

__all__ = ["OffsetCurve", "body_ends", "body_offset_curves", "displaced", "offset_curve", "vessel_load"]


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
    body : str or None
        The coupled body moved alone (its force and moment only, the moment about its moved
        reference point), or None: every vessel end moved together.
    """

    offset: np.ndarray
    direction_deg: float
    force: np.ndarray
    moment: np.ndarray
    cables: list
    tension: np.ndarray
    body: str | None = None


def _moved(end: LineEnd, k: int, i: int, ends) -> bool:
    """True for a vessel end that moves: every one when ``ends`` is None, else those in ``ends``."""
    return end.node < 0 and end.kind == "vessel" and (ends is None or (k, i) in ends)


def displaced(problem: NetworkProblem, translation, rotation=(0.0, 0.0, 0.0), ends=None) -> NetworkProblem:
    """``problem`` with the vessel's ends moved rigidly to ``translation + R(rotation) a``.

    Parameters
    ----------
    translation : array_like, shape (3,)
        [m].
    rotation : array_like, shape (3,)
        Roll, pitch, yaw of the vessel about its origin [rad].
    ends : set of (int, int), optional
        ``(line, end)`` indices of the vessel ends that move (:func:`body_ends`); the others
        stay. None: every vessel end.
    """
    R = fairlead_rotation(np.asarray(rotation, dtype=float))[0]
    t = np.asarray(translation, dtype=float)
    lines = []
    for k, line in enumerate(problem.lines):
        moved = tuple(LineEnd(end.node, t + R @ end.point, end.kind, end.on_seabed, end.load)
                      if _moved(end, k, i, ends) else end for i, end in enumerate(line.ends))
        lines.append(replace(line, ends=moved))
    return NetworkProblem(list(problem.nodes), lines, problem.seabed, problem.friction, problem.gravity)


def vessel_load(solution: NetworkSolution, origin=(0.0, 0.0, 0.0), ends=None) -> tuple[np.ndarray, np.ndarray]:
    """Force of the lines on the vessel's ends [N] and its moment about ``origin`` [N m]
    (only the ends in ``ends``, as :func:`displaced` takes them, when given)."""
    force, moment = np.zeros(3), np.zeros(3)
    for k, (line, state) in enumerate(zip(solution.problem.lines, solution.lines)):
        for i, end in enumerate(line.ends):
            if _moved(end, k, i, ends):
                f = state.forces[i] - np.array([0.0, 0.0, end.load])
                force += f
                moment += cross(end.point - np.asarray(origin, dtype=float), f)
    return force, moment


def offset_curve(case, direction_deg: float, to: float, steps: int = 20) -> OffsetCurve:
    """The offset curve of ``case`` (module docstring): every vessel end moved together.

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
    problem = _offset_problem(case, steps)
    return _curve(problem, direction_deg, to, steps, None, np.zeros(3), None)


def body_offset_curves(case, direction_deg: float, to: float, steps: int = 20) -> dict[str, OffsetCurve]:
    """Each coupled body's own offset curve (module docstring), by body name in file order; empty
    when the case has fewer than two coupled bodies (one body's curve is :func:`offset_curve`).

    Parameters and errors as :func:`offset_curve`; a body's failure names the body.
    """
    from kanat.io.moordyn_coupled import coupled_bodies

    bodies = coupled_bodies(case)
    if len(bodies) < 2:
        return {}
    problem = _offset_problem(case, steps)
    return {body.name: _curve(problem, direction_deg, to, steps, body_ends(problem, body),
                              np.asarray(body.position, dtype=float), body.name) for body in bodies}


def body_ends(problem: NetworkProblem, body) -> set[tuple[int, int]]:
    """``(line, end)`` indices of the vessel ends on the coupled ``body``
    (:class:`kanat.io.moordyn_coupled.CoupledBody`): those at one of its points, within
    :data:`~kanat.statics.coupled.SAME_POINT` per metre of distance from the origin."""
    points = np.asarray(body.points, dtype=float).reshape(-1, 3)
    out = set()
    for k, line in enumerate(problem.lines):
        for i, end in enumerate(line.ends):
            if _moved(end, k, i, None) and len(points) and np.min(np.max(np.abs(points - end.point), axis=1)) <= (
                    SAME_POINT * max(1.0, float(np.max(np.abs(end.point))))):
                out.add((k, i))
    return out


def _offset_problem(case, steps: int) -> NetworkProblem:
    """The network of ``case``, refused when there is nothing to offset."""
    if steps < 1:
        raise ValueError(f"steps must be at least 1, not {steps}")
    _check_loaded(case)
    problem = network_problem(case)
    if not any(end.node < 0 and end.kind == "vessel" for line in problem.lines for end in line.ends):
        raise CaseError([Problem("cables", "no cable ends at the vessel, so there is nothing to offset; "
                                 "give the fairleads as cable ends {vessel: [x, y, z]}")])
    return problem


def _curve(problem: NetworkProblem, direction_deg: float, to: float, steps: int, ends, origin: np.ndarray,
           body: str | None) -> OffsetCurve:
    """The statics re-solved at each offset of the vessel ends ``ends`` (None: all), the load on
    them about ``origin`` moved with them."""
    theta = math.radians(direction_deg)
    unit = np.array([math.cos(theta), math.sin(theta), 0.0])
    offsets = np.linspace(0.0, to, steps + 1)
    q = first_guess(problem)
    forces, moments, tensions = [], [], []
    for d in offsets:
        moved = displaced(problem, d * unit, ends=ends)
        try:
            solution = solve_network(moved, q)
            _check_seabed(moved, {line.name: _cable(moved, line, state)
                                  for line, state in zip(moved.lines, solution.lines)})
        except SolverError as error:
            which = f" of {body} alone" if body else ""
            raise SolverError(f"at an offset{which} of {d:.4g} m along {direction_deg:g} deg: {error}") from error
        q = solution.q
        force, moment = vessel_load(solution, origin + d * unit, ends)
        forces.append(force)
        moments.append(moment)
        tensions.append([[float(np.linalg.norm(f)) for f in state.forces] for state in solution.lines])
    return OffsetCurve(offsets, float(direction_deg), np.array(forces), np.array(moments),
                       [line.name for line in problem.lines], np.array(tensions), body)
