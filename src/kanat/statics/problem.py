"""The 2-D steady cable problem as typed data, and its equations (theory/statics.md §1).

A single cable in the x–z plane, unstretched arclength ``s`` from its first end
(``s = 0``) to its second (``s = L``). The state along the cable is

    y(s) = (x, z, F_x, F_z),     F = T t   (tension vector, t the unit tangent)

and the steady equations ``d(T t)/ds + f = 0``, ``dr/ds = (1 + e) t`` read

    dx/ds = (1 + e) F_x / T,      dz/ds = (1 + e) F_z / T
    dF/ds = -f = (0, w) - f_drag(t, U(z), e)

with ``T = |F|``, ``e = T / EA`` and ``U(z)`` the water velocity relative to the
cable (for a steady tow: current minus vessel velocity). Writing the tension as a
vector instead of ``(T, phi)`` keeps the equations free of the angle, so vertical
and horizontal stretches of cable are equally well conditioned.

Ends: each supplies two conditions. A :class:`FixedEnd` fixes the position (anchor,
fixed point, or the tow point in the steady frame); a :class:`BodyEnd` balances the
tension against a body's net buoyancy, its drag in the local flow and a constant
force (buoy, towed body, depressor). Force balance of a body at ``s = L`` is
``T t(L) = F_body``; at ``s = 0`` it is ``T t(0) = -F_body`` (theory/continuum.md §3).

A frictionless horizontal seabed at ``z = seabed_z`` may carry part of a line whose
fixed end lies on it; the grounded part is straight, carries the touchdown tension
and feels no drag (assumed sheltered in the seabed boundary layer).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kanat.errors import SolverError
from kanat.statics import budget
from kanat.physics.drag import axial_drag, body_drag, cable_drag


@dataclass(frozen=True)
class LineProperties:
    """Properties of a line type needed by statics (SI units).

    Attributes
    ----------
    weight : float
        Weight in water per unstretched length ``w`` [N/m] (negative for a line
        lighter than water).
    axial_stiffness : float
        ``EA`` [N]; ``np.inf`` for an inextensible line.
    diameter : float
        Hydrodynamic diameter ``d`` [m].
    drag_normal, drag_tangential : float
        ``C_n``, ``C_t`` (tangential referred to ``pi d``) [-].
    water_density : float
        ``rho`` [kg/m^3].
    """

    weight: float
    axial_stiffness: float
    diameter: float = 0.0
    drag_normal: float = 0.0
    drag_tangential: float = 0.0
    water_density: float = 1025.0


@dataclass(frozen=True)
class PiecewiseFlow:
    """Water velocity relative to the cable, piecewise linear in ``z``, in any number of components.

    Attributes
    ----------
    z : ndarray, shape (k,)
        Increasing heights of the rows [m]; one row means a uniform flow.
    velocity : ndarray, shape (k, c)
        The velocity's ``c`` components at each row [m/s]; constant beyond the first and last row.
    """

    z: np.ndarray
    velocity: np.ndarray

    @property
    def is_uniform(self) -> bool:
        return bool(np.all(self.velocity == self.velocity[0]))

    def at(self, z):
        """Velocity at heights ``z`` (any shape) -> shape ``z.shape + (c,)``."""
        z = np.asarray(z, dtype=float)
        components = self.velocity.shape[1]
        if self.is_uniform:
            return np.broadcast_to(self.velocity[0], z.shape + (components,)).copy()
        return np.stack([np.interp(z, self.z, self.velocity[:, k]) for k in range(components)], axis=-1)

    def scaled(self, factor: float):
        """The same flow with every velocity times ``factor``."""
        return type(self)(self.z, self.velocity * factor)


@dataclass(frozen=True)
class FlowProfile(PiecewiseFlow):
    """Water velocity relative to the cable in the plane, piecewise linear in ``z``.

    Attributes
    ----------
    z : ndarray, shape (k,)
        Increasing depths of the rows [m]; one row means a uniform flow.
    velocity : ndarray, shape (k, 2)
        ``(u_x, u_z)`` at each row [m/s]; constant beyond the first and last row.
    """

    z: np.ndarray = field(default_factory=lambda: np.zeros(1))
    velocity: np.ndarray = field(default_factory=lambda: np.zeros((1, 2)))

    @classmethod
    def uniform(cls, ux: float = 0.0, uz: float = 0.0) -> FlowProfile:
        return cls(np.zeros(1), np.array([[ux, uz]], dtype=float))


@dataclass(frozen=True)
class FixedEnd:
    """An end held at ``position = (x, z)`` [m]: anchor, fixed point or tow point."""

    position: tuple[float, float]


@dataclass(frozen=True)
class BodyEnd:
    """A body at a free end: buoy, towed body or depressor.

    Attributes
    ----------
    net_buoyancy : float
        Buoyancy minus weight [N] (negative sinks).
    drag_area : float
        ``C_D S`` [m^2].
    force : tuple[float, float]
        Constant external force ``(F_x, F_z)`` [N] (depressor, spreading force).
    """

    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple[float, float] = (0.0, 0.0)

    def load(self, flow: FlowProfile, z: float, density: float) -> np.ndarray:
        """Total external force on the body at height ``z`` [N], shape (2,)."""
        drag = body_drag(flow.at(z), self.drag_area, density)
        return np.array(self.force, dtype=float) + drag + np.array([0.0, self.net_buoyancy])


@dataclass(frozen=True)
class CableBVP:
    """A steady 2-D cable between two ends (theory/statics.md §1).

    Attributes
    ----------
    line : LineProperties
    length : float
        Unstretched length ``L`` [m].
    start, end : FixedEnd or BodyEnd
        Conditions at ``s = 0`` and ``s = L``.
    flow : FlowProfile
        Water velocity relative to the cable.
    seabed_z : float or None
        Height of a frictionless seabed [m], or None.
    """

    line: LineProperties
    length: float
    start: FixedEnd | BodyEnd
    end: FixedEnd | BodyEnd
    flow: FlowProfile = field(default_factory=FlowProfile)
    seabed_z: float | None = None

    def with_flow(self, factor: float) -> CableBVP:
        """The same problem with the flow scaled by ``factor`` (for continuation)."""
        return CableBVP(self.line, self.length, self.start, self.end, self.flow.scaled(factor), self.seabed_z)

    def grounding(self) -> Grounding | None:
        """The seabed geometry when a fixed end lies on the seabed, else None."""
        if self.seabed_z is None:
            return None
        ends = (self.start, self.end)
        for anchor, end in enumerate(ends):
            other = ends[1 - anchor]
            if (isinstance(end, FixedEnd) and isinstance(other, FixedEnd)
                    and abs(end.position[1] - self.seabed_z) <= 1e-9 * max(1.0, self.length)):
                direction = 1.0 if other.position[0] >= end.position[0] else -1.0
                line = self.line
                u_along = direction * self.flow.at(np.array([self.seabed_z]))[0, 0]   # towards touchdown
                pull = axial_drag(u_along, line.diameter, line.drag_tangential, line.water_density)
                return Grounding(anchor, end.position[0], end.position[1], direction, float(pull))
        return None


@dataclass(frozen=True)
class Grounding:
    """A line lying straight on a frictionless seabed from a fixed end (the anchor).

    The flow at the seabed drags the grounded part along itself by ``pull`` per unit length
    (:func:`kanat.physics.drag.axial_drag`; its normal part the seabed bears), so that the tension grows linearly from touchdown to the anchor: at a distance ``r``
    from the anchor along a grounded length ``G``,

        (G1)  T(r) = T_td + pull (G - r),
        (G2)  x(r) = x_A + direction (r + (T_A r - pull r^2 / 2) / EA),   T_A = T_td + pull G,

    the balance ``dT/dr = -pull`` of a frictionless element and its stretch ``int (1 + T/EA) dr``.

    Attributes
    ----------
    anchor : int
        Which end lies on the seabed (0: ``s = 0``, 1: ``s = L``).
    x_anchor, z_anchor : float
        The anchor's position [m].
    direction : float
        +1 when the other end lies at larger ``x``, else -1.
    pull : float
        The flow's drag along the grounded part, per unit length, towards touchdown [N/m]
        (negative: towards the anchor).
    """

    anchor: int
    x_anchor: float
    z_anchor: float
    direction: float
    pull: float = 0.0

    @property
    def tangent_x(self) -> float:
        """x component of the unit tangent ``t = dr/ds`` (normalised) on the grounded part."""
        return self.direction if self.anchor == 0 else -self.direction

    def touchdown_s(self, grounded_length: float, length: float) -> float:
        """Unstretched arclength of the touchdown point [m]."""
        return grounded_length if self.anchor == 0 else length - grounded_length

    def tensions(self, from_anchor, tension: float, grounded_length: float) -> np.ndarray:
        """Tension at distances ``from_anchor`` [m] along the grounded part for a touchdown tension
        ``tension`` [N], eq. (G1)."""
        return tension + self.pull * (grounded_length - np.asarray(from_anchor, dtype=float))

    def positions(self, from_anchor, tension: float, grounded_length: float, stiffness: float) -> np.ndarray:
        """x at distances ``from_anchor`` [m] along the grounded part, eq. (G2)."""
        r = np.asarray(from_anchor, dtype=float)
        at_anchor = tension + self.pull * grounded_length
        return self.x_anchor + self.direction * (r + (at_anchor * r - 0.5 * self.pull * r * r) / stiffness)

    def touchdown_state(self, tension: float, grounded_length: float, stiffness: float) -> np.ndarray:
        """State ``(x, z, F_x, F_z)`` at touchdown for a horizontal tension ``tension`` [N]."""
        x = float(self.positions(grounded_length, tension, grounded_length, stiffness))
        return np.array([x, self.z_anchor, self.tangent_x * tension, 0.0])

    def fill(self, s, y, tension: float, grounded_length: float, length: float, stiffness: float) -> None:
        """Overwrite the states ``y`` (4, n) at stations ``s`` that lie on the seabed.

        Raises
        ------
        SolverError
            The flow pushes the grounded part towards the anchor harder than the line pulls it
            (the tension would fall below zero before the anchor): the line would not lie straight.
        """
        from_anchor = s if self.anchor == 0 else length - s
        on_bed = from_anchor <= grounded_length
        at_anchor = tension + self.pull * grounded_length
        if at_anchor < 0.0:
            raise SolverError(f"the current along the seabed pushes the {grounded_length:.4g} m of line lying on "
                              f"it towards its anchor ({-self.pull:.4g} N/m) harder than the line pulls it "
                              f"({tension:.4g} N at touchdown): it would not lie straight, and statics assumes it "
                              "does; run a dynamic model (model: lumped), whose seabed contact carries it")
        y[0, on_bed] = self.positions(from_anchor[on_bed], tension, grounded_length, stiffness)
        y[1, on_bed] = self.z_anchor
        y[2, on_bed] = self.tangent_x * self.tensions(from_anchor[on_bed], tension, grounded_length)
        y[3, on_bed] = 0.0


def steady_rhs(problem: CableBVP, y):
    """Right-hand side ``dy/ds`` of the steady equations, vectorized.

    Parameters
    ----------
    problem : CableBVP
    y : ndarray, shape (4, n)
        States ``(x, z, F_x, F_z)`` at ``n`` stations.

    Returns
    -------
    ndarray, shape (4, n)
    """
    budget.charge()
    line = problem.line
    force = y[2:4]
    tension = np.hypot(force[0], force[1])
    tangent = force / tension
    strain = tension / line.axial_stiffness
    drag = cable_drag(tangent.T, problem.flow.at(y[1]), strain, line.diameter,
                      line.drag_normal, line.drag_tangential, line.water_density).T
    out = np.empty_like(y)
    out[0:2] = (1.0 + strain) * tangent
    out[2] = -drag[0]
    out[3] = line.weight - drag[1]
    return out


def end_residual(problem: CableBVP, which: int, y_end) -> np.ndarray:
    """The two conditions of one end, zero when satisfied (unscaled).

    Parameters
    ----------
    which : int
        0 for ``s = 0``, 1 for ``s = L``.
    y_end : ndarray, shape (4,)
    """
    end = (problem.start, problem.end)[which]
    if isinstance(end, FixedEnd):
        return y_end[0:2] - np.asarray(end.position, dtype=float)
    load = end.load(problem.flow, y_end[1], problem.line.water_density)
    sign = 1.0 if which == 1 else -1.0
    return y_end[2:4] - sign * load


COINCIDENT_ENDS = 1e-9
"""Distance between two fixed ends, relative to the cable length, below which they are one point."""


def check_solvable(problem: CableBVP) -> None:
    """Refuse problems with no steady solution before any solver tries them.

    Raises
    ------
    SolverError
        Both ends are bodies (nothing holds the cable), both are fixed at one point (the
        line doubles back on itself: its end conditions do not fix its tension, and the
        shooting and collocation solvers would search forever), or a body exerts no force
        on the cable whatever its depth (the end is slack and its direction undefined).
    """
    ends = (problem.start, problem.end)
    if all(isinstance(e, BodyEnd) for e in ends):
        raise SolverError("both ends of the cable are bodies, so nothing holds it in place; "
                          "fix one end (anchor, vessel) to solve its statics")
    if all(isinstance(e, FixedEnd) for e in ends) and np.allclose(
            ends[0].position, ends[1].position, rtol=0.0, atol=COINCIDENT_ENDS * problem.length):
        x, z = ends[0].position
        raise SolverError(f"both ends of the cable are at the same point (x = {x:.6g} m, z = {z:.6g} m): "
                          "the line would double back on itself, a shape whose tension its ends do "
                          "not fix and which the shooting and collocation solvers cannot find; give "
                          "the ends distinct positions")
    for end in ends:
        if (isinstance(end, BodyEnd) and end.net_buoyancy == 0 and not any(end.force)
                and (end.drag_area == 0 or not np.any(problem.flow.velocity))):
            raise SolverError("the body exerts no force on the cable (net buoyancy, drag and force are "
                              "all zero), so the cable end is slack and its steady direction undefined; "
                              "give the body weight, buoyancy or drag")
