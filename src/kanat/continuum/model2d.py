"""The planar continuum cable as typed data: parameters, end conditions, state (theory/continuum.md §1, §3).

Kernels take flat arrays; this module builds them from a case, once. A continuum case here is
one cable (of one or several sections, with inline bodies) whose first end is the vessel's tow
point or an anchor and whose second end is a body (a surface buoy too), an anchor or free.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.grid import (Grid, SeabedContact, cable_grid, elastic_law_knots,  # noqa: F401
                                  parameters, seabed_contact)
from kanat.continuum.winch import Winch
from kanat.errors import CaseError, Problem
from kanat.model.plane import out_of_plane
from kanat.physics.ramp import ramp_factor
from kanat.physics.waves import sea_from_model


@dataclass(frozen=True)
class EndCondition:
    """One end: ``kind`` in {velocity, body, free} (kernels2d constants) and its data.

    Attributes
    ----------
    kind : int
    mass : float
        Body mass plus added mass [kg] (kind body).
    net_buoyancy : float
        [N] (kind body).
    drag_area : float
        ``C_D S`` [m^2] (kind body).
    force : tuple of float
        Constant external force ``(F_x, F_z)`` [N] (kind body).
    moving : bool
        True for the vessel's tow point (velocity from the track); False for an anchor.
    position : tuple of float
        ``(x, z)`` of an anchor [m].
    wave_mass : float
        Added mass plus displaced mass ``M_a + rho Vol`` [kg]: the body's coefficient of the
        water's acceleration (Morison, Froude–Krylov) in waves.
    waterplane : float
        ``rho g A_w`` [N/m] of a surface buoy (0: none).
    height : float
        Keel to deck of a surface buoy [m].
    clamped : bool
        With bending stiffness: the end holds the cable's angle (``angle``) instead of leaving
        it moment-free.
    angle : float
        The clamped angle [rad].
    """

    kind: int
    mass: float = 0.0
    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple = (0.0, 0.0)
    moving: bool = False
    position: tuple = (0.0, 0.0)
    wave_mass: float = 0.0
    waterplane: float = 0.0
    height: float = 0.0
    clamped: bool = False
    angle: float = 0.0

    def array(self, velocity=(0.0, 0.0), density: float = 1025.0, eta: float = 0.0, payout: float = 0.0) -> np.ndarray:
        """The kernel's end-parameter vector (kernels2d.NBPAR) for a prescribed ``velocity``, the
        wave elevation ``eta`` over a surface buoy and a winch's pay-out speed ``payout``."""
        return np.array([self.kind, velocity[0], velocity[1], self.mass, self.net_buoyancy,
                         0.5 * density * self.drag_area, self.force[0], self.force[1], self.wave_mass,
                         self.waterplane, self.height, eta, payout, float(self.clamped), self.angle])


class CableGrid:
    """What the planar and the spatial cable share: the grid of nodes and the current profile.

    Subclasses have ``length``, ``segments``, ``params``, ``grid`` (a :class:`Grid` or None for a
    uniform cable), ``current_z`` (ascending heights, m) and ``current_rows`` (the current at
    those heights, one column per component, m/s), and ``current_ramp`` (its ramp, s).
    """

    @property
    def ds(self) -> float:
        """Unstretched length of the first segment [m] (of every segment of a uniform cable)."""
        return float(self.rows()[0, k.DS])

    @property
    def s(self) -> np.ndarray:
        """Unstretched arclength of the nodes [m], shape (n_nodes,) (a junction's two nodes share theirs)."""
        if self.grid is not None:
            return self.grid.s
        return np.linspace(0.0, self.length, self.segments + 1)

    @property
    def nv(self) -> int:
        """Unknowns per node: 4 in the plane (6 with bending stiffness)."""
        return 6 if self.grid is not None and self.grid.bending else 4

    def rows(self) -> np.ndarray:
        """Parameter row of every interval (n_nodes - 1, n_par)."""
        if self.grid is not None:
            return self.grid.rows
        p = self.params.copy()
        p[k.DS] = self.length / self.segments
        return np.tile(p, (self.segments, 1))

    def extras(self):
        """The kernels' ``extras`` argument: None for a plain cable (no seabed, waves, inline bodies,
        bending stiffness or surface buoy: the kernels' short version), else a marker array
        (:mod:`kanat.continuum.rows2d` docstring)."""
        grid = self.grid
        plain = (self.seabed is None and self.sea is None and getattr(self.end, "waterplane", 0.0) == 0.0
                 and (grid is None or (not grid.junctions and not grid.bending)))
        return None if plain else np.zeros(1)

    def current_at(self, z, t: float | None = None) -> np.ndarray:
        """Current at heights ``z`` (n,): linear between rows, constant beyond -> (n, components);
        at time ``t`` [s] ramped (:func:`kanat.physics.ramp.ramp_factor`), at full strength when
        ``t`` is None."""
        scale = 1.0 if t is None else ramp_factor(t, self.current_ramp)
        return scale * np.column_stack([np.interp(z, self.current_z, column) for column in self.current_rows.T])


@dataclass(frozen=True)
class PlanarCable(CableGrid):
    """A planar cable ready for the kernels.

    Attributes
    ----------
    name : str
    length : float
        Unstretched length [m].
    segments : int
    params : ndarray, shape (kernels2d.NPAR + law,)
        Physical parameters of the first section; scheme entries are filled per step.
    start, end : EndCondition
    current_z, current_rows : ndarray
        Current profile: heights (ascending) [m] and (u_x, u_z) rows [m/s].
    grid : Grid or None
        Sections, attachments and per-interval rows; None: ``segments`` equal intervals of ``params``.
    sea : kanat.physics.waves.LinearSea or None
        Waves acting on the cable and its bodies.
    seabed : SeabedContact or None
    winch : kanat.continuum.winch.Winch or None
        Pay-out and haul-in at the first end (:mod:`kanat.continuum.winch`).
    current_ramp : float
        The current's start-up ramp [s] (``environment.current.ramp``; 0: none).
    water_surface : bool
        True: the water ends at its surface (``z = 0``, or the waves' elevation), and the part of
        the cable above it is dry (:mod:`kanat.continuum.wetted`), as for every cable of a case;
        False: the water is unbounded (the idealized cables of :mod:`kanat.validation`).
    """

    name: str
    length: float
    segments: int
    params: np.ndarray
    start: EndCondition
    end: EndCondition
    current_z: np.ndarray = field(default_factory=lambda: np.zeros(1))
    current_rows: np.ndarray = field(default_factory=lambda: np.zeros((1, 2)))
    grid: Grid | None = None
    sea: object = None
    seabed: SeabedContact | None = None
    winch: object = None
    current_ramp: float = 0.0
    water_surface: bool = False


def strain_of(tension, params) -> np.ndarray:
    """NumPy strain ``e(T)`` of the law in ``params`` (as :func:`kernels2d.strain`), for positions."""
    n = int(params[k.LAW])
    knots_t, knots_e = params[k.LAW + 1:k.LAW + 1 + n], params[k.LAW + 1 + n:k.LAW + 1 + 2 * n]
    i = np.clip(np.searchsorted(knots_t, tension) - 1, 0, n - 2)
    slope = (knots_e[i + 1] - knots_e[i]) / (knots_t[i + 1] - knots_t[i])
    return knots_e[i] + slope * (np.asarray(tension) - knots_t[i])


def interval_stretch(tension, rows) -> tuple[np.ndarray, np.ndarray]:
    """``(1 + e)`` of both nodes of every interval, each with that interval's law: shapes (N,), (N,)."""
    left, right = np.empty(len(rows)), np.empty(len(rows))
    sections = rows[:, k.SECTION]
    for value in sorted(set(sections.tolist())):                # np.unique would import numpy.ma
        which = np.flatnonzero(sections == value)
        p = rows[which[0]]
        left[which] = 1.0 + strain_of(tension[which], p)
        right[which] = 1.0 + strain_of(tension[which + 1], p)
    return left, right


def planar_cable(case, check_plane: bool = True) -> PlanarCable:
    """The planar model of a case's single cable (raises CaseError when it does not fit).

    ``check_plane=False`` skips the refusal of out-of-plane data, for the spatial model,
    which builds its parameters here too.
    """
    if len(case.cables) != 1:
        raise CaseError([Problem("cables", f"the continuum model takes one cable; this case has "
                                 f"{len(case.cables)} (networks run with model: lumped)")])
    cable = case.cables[0]
    env = case.environment
    seabed = within_reach(seabed_contact(env), case)
    grid = cable_grid(case, 0, seabed)
    start = _end(case, cable.from_, "cables[0].from", first=True)
    end = _end(case, cable.to, "cables[0].to", first=False)
    z, rows = case.environment.current.table()
    if check_plane and out_of_plane(case):
        raise CaseError(out_of_plane(case))
    grid.rows[:, k.TFLOOR] = tension_floor(case, grid.rows)
    first = grid.rows[0].copy()
    winch = Winch.from_case(case, float(grid.rows[0, k.DS]))
    if winch is not None and start.kind != k.VELOCITY:
        raise CaseError([Problem("winch", "the winch pays out at the first cable's 'from' end, which must be the "
                                 "vessel or an anchor")])
    plain = grid.uniform and not grid.bending and seabed is None and winch is None
    return PlanarCable(cable.name, cable.length, cable.segments, first, start, end, z, rows[:, [0, 2]],
                       None if plain else grid, sea_from_model(env), seabed, winch, env.current.ramp,
                       water_surface=True)


SLACK_FLOOR = 0.01
"""The default tension floor of ``simulation.slack: continue``, as a fraction of the cable's weight in
water (at least 1 N): small beside the tensions of a hanging line, enough to keep a slack interval's
normal row a string's (:func:`kanat.continuum.loads2d.transverse_tension`)."""


def tension_floor(case, rows: np.ndarray) -> float:
    """The tension floor [N] of a case's cable with interval ``rows``: ``simulation.tension_floor``, or
    :data:`SLACK_FLOOR` of its weight in water (at least 1 N); 0 (none) with ``simulation.slack: stop``."""
    sim = case.simulation
    if sim.slack == "stop":
        return 0.0
    if sim.tension_floor is not None:
        return float(sim.tension_floor)
    return max(SLACK_FLOOR * float(np.sum(np.abs(rows[:, k.W0] * rows[:, k.DS]))), 1.0)


REACH = 1.1
"""A cable reaches at most this many times its length from its ends (stretch included)."""


def within_reach(seabed: SeabedContact | None, case) -> SeabedContact | None:
    """``seabed``, or None when the cable cannot touch it: a flat seabed deeper than every end's
    height less :data:`REACH` times the cable's length (then the model runs without contact)."""
    if seabed is None or seabed.slope_deg != 0.0:
        return seabed
    cable = case.cables[0]
    heights = [case.vessel.tow_point[2] if e.kind == "vessel" else e.position[2] for e in cable.ends
               if e.kind in ("vessel", "anchor")]
    lowest = min(heights) - REACH * cable.length
    return seabed if lowest < -seabed.depth + 1.0 else None


def _end(case, end, key: str, first: bool) -> EndCondition:
    if end.kind == "vessel":
        return EndCondition(k.VELOCITY, moving=True, position=(case.vessel.tow_point[0], case.vessel.tow_point[2]))
    if end.kind == "anchor":
        return EndCondition(k.VELOCITY, position=(end.position[0], end.position[2]))
    if first:
        raise CaseError([Problem(key, "the continuum model's first end must be the vessel or an anchor "
                                 "(its positions are built from there); swap 'from' and 'to'")])
    if end.kind == "free":
        return EndCondition(k.FREE)
    if end.kind == "body":
        body, env = case.bodies[end.name], case.environment
        buoy = body.surface_buoy
        return EndCondition(k.BODY, body.mass + body.added_mass, body.net_buoyancy, body.drag_area,
                            (body.force[0], body.force[2]),
                            wave_mass=body.added_mass + (body.net_buoyancy + body.mass * env.gravity) / env.gravity,
                            waterplane=0.0 if buoy is None else env.water_density * env.gravity * buoy.waterplane_area,
                            height=0.0 if buoy is None else buoy.height)
    raise CaseError([Problem(key, f"point '{end.name}' joins a network; networks run with model: lumped")])


def positions(cable: PlanarCable, y: np.ndarray, origin, rows=None) -> np.ndarray:
    """Node positions (n_nodes, 2) from the first end, trapezoidal in ``(1 + e) t`` (2nd order),
    each interval with its own length and elastic law (``rows``: the cable's own by default)."""
    rows = cable.rows() if rows is None else rows
    left, right = interval_stretch(y[:, 0], rows)
    c, s = np.cos(y[:, 3]), np.sin(y[:, 3])
    half = 0.5 * rows[:, k.DS]
    increments = np.column_stack([half * (left * c[:-1] + right * c[1:]), half * (left * s[:-1] + right * s[1:])])
    return np.vstack([np.zeros((1, 2)), np.cumsum(increments, axis=0)]) + np.asarray(origin, dtype=float)
