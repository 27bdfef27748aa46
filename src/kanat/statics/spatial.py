"""The 3-D steady cable problem: sections, inline bodies, bodies or fixed points at the ends, a
current with x and y components, a rigid seabed (theory/statics.md §1, theory/moorings.md).

One cable, unstretched arclength ``s`` from its first end (0) to its second (``L``), made of
*pieces* (a section, or the part of a section between attachments) each with its own line
properties. The state along the cable is ``y = (x, y, z, F_x, F_y, F_z)`` with ``F = T t``, and

    dr/ds = (1 + e) F / T,        dF/ds = w z_hat - f_drag(t, U(z), e),        e = T / EA

(``U`` the water velocity relative to the cable: current minus the vessel's velocity in a steady
tow). An inline body at ``s_a`` makes the force jump, ``F(s_a+) = F(s_a-) - F_body`` (the body's
net buoyancy, its drag in the flow at its depth, its constant force). An end body balances the
tension, ``F(L) = F_body`` at ``s = L`` and ``F(0) = -F_body`` at ``s = 0``.

Seabed (``environment.depth``, ``seabed.slope_deg``, ``seabed.friction``): statics treats it as
rigid -- the contact stiffness's penetration ``w / (k_b d)`` (millimetres) is neglected. A line
whose anchor lies on the seabed may rest on it from the anchor: the grounded part lies straight
in the seabed plane along a direction ``g`` (azimuth ``psi``), feels no drag (sheltered in the
bottom boundary layer) and carries ``T(s) = max(T_td - (L_B - s)(w g.z + mu w cos(slope)), 0)``:
weight along the slope, and Coulomb friction fully mobilised towards the anchor (MoorPy's
convention for a line pulled taut; ``s`` from the anchor, ``L_B`` the grounded length,
``T_td`` the touchdown tension).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import SolverError
from kanat.statics import budget
from kanat.physics.drag import axial_drag, body_drag, cable_drag
from kanat.physics.immersion import float_buoyancy, sphere_fraction
from kanat.statics.problem import LineProperties, PiecewiseFlow

UP = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class Piece:
    """A stretch of one line type, ``start <= s <= end`` [m]."""

    line: LineProperties
    start: float
    end: float

    @property
    def length(self) -> float:
        return self.end - self.start


@dataclass(frozen=True)
class Load:
    """What a body adds at a point: net buoyancy [N] (up), ``C_D S`` [m^2], a constant force [N] (3,)
    and, for a surface buoy, its waterplane ``rho g A_w`` [N/m] and height [m] (the buoyancy
    ``rho g A_w clip(-z, 0, height)`` of its immersion below the still surface); for a spherical
    float, its ``diameter`` [m] and its ``buoyancy`` fully submerged [N], of which it keeps the
    share under the still surface (:mod:`kanat.physics.immersion`, eq. (1))."""

    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple = (0.0, 0.0, 0.0)
    waterplane: float = 0.0
    height: float = 0.0
    diameter: float = 0.0
    buoyancy: float = 0.0

    def at(self, flow: Flow3, z: float, density: float) -> np.ndarray:
        """The body's external force at height ``z`` [N], shape (3,)."""
        lift = self.net_buoyancy + self.waterplane * min(max(-float(z), 0.0), self.height)
        if self.diameter > 0.0:
            lift = float_buoyancy(self.net_buoyancy, self.buoyancy, sphere_fraction(float(z), 0.0, self.diameter)[0])
        return np.asarray(self.force, dtype=float) + body_drag(flow.at(z), self.drag_area, density) + lift * UP

    @property
    def follows_height(self) -> bool:
        """True when the load changes with the body's height (a waterplane or a float's immersion)."""
        return self.waterplane > 0 or self.diameter > 0

    @property
    def inert(self) -> bool:
        """True when the body exerts no force whatever the flow."""
        return self.net_buoyancy == 0 and not any(self.force) and self.drag_area == 0 and self.waterplane == 0


@dataclass(frozen=True)
class Fixed3:
    """An end held at ``position`` (3,) [m]: anchor or tow point in the steady frame."""

    position: tuple


@dataclass(frozen=True)
class Body3:
    """A body at an end."""

    load: Load


@dataclass(frozen=True)
class Flow3(PiecewiseFlow):
    """Water velocity relative to the cable, piecewise linear in ``z``: heights ascending (k,), rows (k, 3)."""

    z: np.ndarray = field(default_factory=lambda: np.zeros(1))
    velocity: np.ndarray = field(default_factory=lambda: np.zeros((1, 3)))

    def rotated(self, matrix) -> Flow3:
        """The flow turned by a rotation ``matrix`` (3, 3) about the vertical."""
        return Flow3(self.z, self.velocity @ np.asarray(matrix).T)


@dataclass(frozen=True)
class RigidSeabed:
    """The plane ``z = -depth + x tan(slope)`` with Coulomb friction ``mu`` along the line."""

    depth: float
    slope_deg: float = 0.0
    friction: float = 0.0

    @property
    def normal(self) -> np.ndarray:
        a = math.radians(self.slope_deg)
        return np.array([-math.sin(a), 0.0, math.cos(a)])

    def height(self, x) -> np.ndarray:
        return -self.depth + math.tan(math.radians(self.slope_deg)) * np.asarray(x, dtype=float)

    def direction(self, psi: float) -> np.ndarray:
        """Unit vector in the seabed plane at azimuth ``psi`` (its horizontal projection at ``psi`` from +x)."""
        h = np.array([math.cos(psi), math.sin(psi), 0.0])
        g = h + (h @ -self.normal / self.normal[2]) * UP if self.normal[2] else h
        return g / np.linalg.norm(g)

    def touches(self, point, length: float) -> bool:
        return abs(point[2] - float(self.height(point[0]))) <= 1e-9 * max(1.0, length)


@dataclass(frozen=True)
class CableBVP3:
    """A steady 3-D cable (module docstring).

    Attributes
    ----------
    pieces : tuple of Piece
        From ``s = 0`` to ``s = L``, contiguous.
    joints : tuple of (float, Load)
        Inline bodies at arclength ``s`` (on piece boundaries), in order.
    start, end : Fixed3 or Body3
    flow : Flow3
    seabed : RigidSeabed or None
    """

    pieces: tuple
    joints: tuple
    start: object
    end: object
    flow: Flow3 = field(default_factory=Flow3)
    seabed: RigidSeabed | None = None

    @property
    def length(self) -> float:
        return self.pieces[-1].end

    @property
    def density(self) -> float:
        return self.pieces[0].line.water_density

    def with_flow(self, factor: float) -> CableBVP3:
        return CableBVP3(self.pieces, self.joints, self.start, self.end, self.flow.scaled(factor), self.seabed)

    def reference_force(self) -> float:
        """A force scale: the line's weight, at least 1 N."""
        return max(sum(abs(p.line.weight) * p.length for p in self.pieces), 1.0)

    def joint_at(self, s: float) -> Load | None:
        """The inline body at the piece boundary ``s``, if any."""
        for s_a, load in self.joints:
            if abs(s_a - s) <= 1e-12 * max(1.0, self.length):
                return load
        return None

    def piece_at(self, s: float) -> Piece:
        for piece in self.pieces:
            if s <= piece.end:
                return piece
        return self.pieces[-1]

    def grounding_anchor(self) -> int | None:
        """Which end (0 or 1) is an anchor on the seabed, if any."""
        if self.seabed is None:
            return None
        for which, end in enumerate((self.start, self.end)):
            other = (self.start, self.end)[1 - which]
            if isinstance(end, Fixed3) and self.seabed.touches(end.position, self.length) and not (
                    isinstance(other, Fixed3) and self.seabed.touches(other.position, self.length)):
                return which
        return None


def rhs(piece: Piece, flow: Flow3, y) -> np.ndarray:
    """``dy/ds`` of the steady equations for states ``y`` (6, n) on one piece (vectorized)."""
    budget.charge()
    line = piece.line
    force = y[3:6]
    tension = np.sqrt(np.sum(force * force, axis=0))
    tangent = force / tension
    strain = tension / line.axial_stiffness
    drag = cable_drag(tangent.T, flow.at(y[2]), strain, line.diameter, line.drag_normal,
                      line.drag_tangential, line.water_density).T
    out = np.empty_like(y)
    out[0:3] = (1.0 + strain) * tangent
    out[3:5] = -drag[0:2]
    out[5] = line.weight - drag[2]
    return out


def rhs_point(piece: Piece, flow: Flow3, y) -> np.ndarray:
    """:func:`rhs` for one state (6,), in scalar arithmetic: what the shooting integrator calls
    (twenty times faster than the vectorized form on one point)."""
    budget.charge()
    line = piece.line
    fx, fy, fz = float(y[3]), float(y[4]), float(y[5])
    tension = math.sqrt(fx * fx + fy * fy + fz * fz)
    tx, ty, tz = fx / tension, fy / tension, fz / tension
    strain = tension / line.axial_stiffness
    if flow.is_uniform:
        ux, uy, uz = (float(v) for v in flow.velocity[0])
    else:
        z = float(y[2])
        ux, uy, uz = (float(np.interp(z, flow.z, flow.velocity[:, c])) for c in range(3))
    along = ux * tx + uy * ty + uz * tz
    nx, ny, nz = ux - along * tx, uy - along * ty, uz - along * tz
    normal = math.sqrt(nx * nx + ny * ny + nz * nz)
    area = math.sqrt(1.0 + strain) * 0.5 * line.water_density * line.diameter
    cn, ct = area * line.drag_normal * normal, area * math.pi * line.drag_tangential * abs(along) * along
    stretch = 1.0 + strain
    return np.array([stretch * tx, stretch * ty, stretch * tz, -(cn * nx + ct * tx), -(cn * ny + ct * ty),
                     line.weight - (cn * nz + ct * tz)])


def end_residual(problem: CableBVP3, which: int, y_end) -> np.ndarray:
    """The three conditions of one end, zero when satisfied (unscaled)."""
    end = (problem.start, problem.end)[which]
    if isinstance(end, Fixed3):
        return y_end[0:3] - np.asarray(end.position, dtype=float)
    load = end.load.at(problem.flow, y_end[2], problem.density)
    return y_end[3:6] - (1.0 if which == 1 else -1.0) * load


def jump(problem: CableBVP3, s: float, y, forward: bool) -> np.ndarray:
    """The state across the inline body at ``s`` (if any), integrating forward or backward."""
    load = problem.joint_at(s)
    if load is None:
        return y
    out = np.array(y, dtype=float)
    force = load.at(problem.flow, out[2], problem.density)
    out[3:6] += -force if forward else force
    return out


def check_solvable(problem: CableBVP3) -> None:
    """Refuse problems with no steady solution before any solver tries them."""
    ends = (problem.start, problem.end)
    if all(isinstance(e, Body3) for e in ends):
        raise SolverError("both ends of the cable are bodies, so nothing holds it in place; fix one end "
                          "(anchor, vessel) to solve its statics")
    for end in ends:
        if isinstance(end, Body3) and end.load.inert:
            raise SolverError("the body exerts no force on the cable (net buoyancy, drag and force are all "
                              "zero), so the cable end is slack and its steady direction undefined; give the "
                              "body weight, buoyancy or drag")


def grounded_states(problem: CableBVP3, anchor: int, tension: float, grounded: float, psi: float, s):
    """States (6, n) on the grounded part at stations ``s`` (distance from the anchor ``<= grounded``),
    and the state at touchdown (module docstring), for touchdown tension ``tension`` and azimuth ``psi``."""
    seabed = problem.seabed
    g = seabed.direction(psi)
    root = np.asarray((problem.start, problem.end)[anchor].position, dtype=float)
    along = np.asarray(s, dtype=float)
    knots = np.linspace(0.0, grounded, 401)
    s_knots = knots if anchor == 0 else problem.length - knots
    lines = [problem.piece_at(min(max(v, 0.0), problem.length)).line for v in s_knots]
    weight, stiffness = np.array([(line.weight, line.axial_stiffness) for line in lines]).T
    cos_slope = seabed.normal[2]
    u_along = problem.flow.at(root[2] + g[2] * knots) @ g           # the flow along the ground, away from the anchor
    pull = axial_drag(u_along, [line.diameter for line in lines], [line.drag_tangential for line in lines],
                      problem.density)
    gradient = weight * (g @ UP + seabed.friction * cos_slope) - pull  # dT/ds along the ground, from the anchor
    rise = np.concatenate([[0.0], np.cumsum(0.5 * (gradient[1:] + gradient[:-1]) * np.diff(knots))])
    tensions = np.maximum(tension - (rise[-1] - rise), 0.0)
    stretch = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(knots) * (
        tensions[1:] / stiffness[1:] + tensions[:-1] / stiffness[:-1]))])
    distance = knots + stretch
    at = np.interp(along, knots, distance)
    t_at = np.interp(along, knots, tensions)
    sign = 1.0 if anchor == 0 else -1.0                           # F = T dr/ds, s increasing away from 0
    states = np.vstack([root[:, None] + np.outer(g, at), sign * np.outer(g, t_at)])
    touchdown = np.concatenate([root + g * distance[-1], sign * g * tension])
    return states, touchdown
