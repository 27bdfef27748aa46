"""First guesses of the 3-D steady cable's unknowns (:mod:`kanat.statics.shooting3d`).

Still water, equivalent uniform line (its total weight over its length, the harmonic mean of
the pieces' stiffness): the drag-free elastic catenary (:mod:`kanat.statics.catenary`) between
two fixed ends, or on the seabed from an anchor; a straight vertical line under the bodies'
buoyancy when one end is a body. The flow is then brought up by continuation.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.errors import SolverError
from kanat.statics.catenary import elastic_catenary
from kanat.statics.spatial import UP, Body3, CableBVP3, Fixed3


def equivalent_line(problem: CableBVP3) -> tuple[float, float]:
    """``(w, EA)`` of the uniform line with the same weight and stretch as the pieces."""
    length = problem.length
    weight = sum(p.line.weight * p.length for p in problem.pieces) / length
    compliance = sum(p.length / p.line.axial_stiffness for p in problem.pieces) / length
    return weight, 1.0 / compliance if compliance > 0 else math.inf


def lift(problem: CableBVP3) -> np.ndarray:
    """Total constant upward pull of every body (net buoyancy and constant force) [N] (3,)."""
    total = np.zeros(3)
    for _, load in problem.joints:
        total += load.net_buoyancy * UP + np.asarray(load.force, dtype=float)
    for end in (problem.start, problem.end):
        if isinstance(end, Body3):
            load = end.load
            total += (load.net_buoyancy + 0.5 * load.waterplane * load.height) * UP + np.asarray(load.force, dtype=float)
    return total


def still_water_force(problem: CableBVP3, at: int) -> np.ndarray:
    """``F`` at the fixed end ``at`` (0 or 1) of the still-water line.

    A fixed end and a body: the whole line's balance gives ``F(0) = lift - W z`` (fixed first end)
    or ``F(L) = W z - lift`` (fixed second end), ``W`` the line's weight in water. Two fixed ends:
    the catenary's end force.
    """
    if all(isinstance(e, Fixed3) for e in (problem.start, problem.end)):
        return catenary_force(problem, at)
    weight = sum(p.line.weight * p.length for p in problem.pieces)
    net = lift(problem) - weight * UP
    force = net if at == 0 else -net
    floor = 1e-3 * problem.reference_force()
    if np.linalg.norm(force) < floor:
        force = force + floor * (UP if at == 0 else -UP)
    return force


def catenary_force(problem: CableBVP3, at: int) -> np.ndarray:
    """``F`` at end ``at`` of the drag-free catenary between the two fixed ends (equivalent line)."""
    a, b = (np.asarray(e.position, dtype=float) for e in (problem.start, problem.end))
    weight, stiffness = equivalent_line(problem)
    sense = 1.0 if weight >= 0 else -1.0
    low, high = (a, b) if sense * (b[2] - a[2]) >= 0 else (b, a)
    horizontal = high[:2] - low[:2]
    span = float(np.linalg.norm(horizontal))
    direction = np.append(horizontal / span, 0.0) if span > 0 else np.array([1.0, 0.0, 0.0])
    try:
        cat = elastic_catenary(span, sense * (high[2] - low[2]), problem.length, max(abs(weight), 1e-9), stiffness,
                               n_points=2)
        H, V_low, V_high = cat.horizontal_tension, cat.vertical_tension_lower, cat.vertical_tension_upper
    except (SolverError, ValueError):
        chord = b - a
        return problem.reference_force() * chord / max(np.linalg.norm(chord), 1e-9) * (1 if at == 0 else -1)
    lower_is_start = low is a
    # F = T dr/ds: at the lower end it points up the line when s starts there
    lower = H * direction + sense * V_low * UP
    upper = H * direction + sense * V_high * UP
    start_force, end_force = (lower, upper) if lower_is_start else (-upper, -lower)
    return start_force if at == 0 else end_force


def grounding_guess(problem: CableBVP3, anchor: int) -> np.ndarray:
    """``(T_td, L_B, psi)`` of the still-water line resting on the seabed from end ``anchor``."""
    root = np.asarray((problem.start, problem.end)[anchor].position, dtype=float)
    other = (problem.start, problem.end)[1 - anchor]
    weight, stiffness = equivalent_line(problem)
    length = problem.length
    if isinstance(other, Fixed3):
        far = np.asarray(other.position, dtype=float)
        horizontal = far[:2] - root[:2]
        psi = math.atan2(horizontal[1], horizontal[0])
        cat = elastic_catenary(float(np.linalg.norm(horizontal)), float(far[2] - root[2]), length, max(weight, 1e-9),
                               stiffness, seabed=True, n_points=2)
        return np.array([max(cat.horizontal_tension, 1e-3 * problem.reference_force()),
                         min(cat.grounded_length, 0.95 * length), psi])
    up = float(lift(problem)[2])
    hanging = min(max(up / max(weight, 1e-9), 0.05 * length), 0.95 * length)
    flow = problem.flow.at(root[2] + 0.5 * hanging)
    psi = math.atan2(flow[1], flow[0]) if math.hypot(flow[0], flow[1]) > 0 else 0.0
    drag = sum(0.5 * p.line.water_density * p.line.diameter * p.line.drag_normal for p in problem.pieces[-1:]) \
        * float(np.sum(flow[:2] ** 2)) * hanging
    return np.array([max(drag, 0.05 * up, 1e-3 * problem.reference_force()), length - hanging, psi])
