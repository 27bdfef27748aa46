"""The planar continuum cable as typed data: parameters, end conditions, state (SPEC §2.1, §2.3).

Kernels take flat arrays; this module builds them from a case, once. A continuum case
here is one cable whose first end is the vessel's tow point or an anchor and whose
second end is a body, an anchor or free.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.errors import CaseError, Problem
from kanat.model.plane import out_of_plane


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
    """

    kind: int
    mass: float = 0.0
    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple = (0.0, 0.0)
    moving: bool = False
    position: tuple = (0.0, 0.0)

    def array(self, velocity=(0.0, 0.0), density: float = 1025.0) -> np.ndarray:
        """The kernel's end-parameter vector (kernels2d.NBPAR) for a prescribed ``velocity``."""
        return np.array([self.kind, velocity[0], velocity[1], self.mass, self.net_buoyancy,
                         0.5 * density * self.drag_area, self.force[0], self.force[1]])


class CableGrid:
    """What the planar and the spatial cable share: the grid of nodes and the current profile.

    Subclasses have ``length``, ``segments``, ``current_z`` (ascending heights, m) and
    ``current_rows`` (the current at those heights, one column per component, m/s).
    """

    @property
    def ds(self) -> float:
        """Unstretched segment length [m]."""
        return self.length / self.segments

    @property
    def s(self) -> np.ndarray:
        """Unstretched arclength of the nodes [m], shape (N+1,)."""
        return np.linspace(0.0, self.length, self.segments + 1)

    def current_at(self, z) -> np.ndarray:
        """Current at heights ``z`` (n,): linear between rows, constant beyond -> (n, components)."""
        return np.column_stack([np.interp(z, self.current_z, column) for column in self.current_rows.T])


@dataclass(frozen=True)
class PlanarCable(CableGrid):
    """A planar cable ready for the kernels.

    Attributes
    ----------
    name : str
    length : float
        Unstretched length [m].
    segments : int
    params : ndarray, shape (kernels2d.NPAR,)
        Physical parameters; scheme entries are filled per step.
    start, end : EndCondition
    current_z, current_rows : ndarray
        Current profile: heights (ascending) [m] and (u_x, u_z) rows [m/s].
    """

    name: str
    length: float
    segments: int
    params: np.ndarray
    start: EndCondition
    end: EndCondition
    current_z: np.ndarray = field(default_factory=lambda: np.zeros(1))
    current_rows: np.ndarray = field(default_factory=lambda: np.zeros((1, 2)))


def parameters(mass, added_mass, weight, stiffness, diameter, drag_normal, drag_tangential, density, ds,
               law=None):
    """The kernel parameter vector: the scalars (scheme entries zero), then the elastic law.

    ``law`` is ``(tensions, strains)`` knots (tensions ascending, through (0, 0)); default the
    linear law ``e = T / EA`` (knots (0, 0) and (EA, 1)).
    """
    tensions, strains = law if law is not None else ((0.0, stiffness), (0.0, 1.0))
    p = np.zeros(k.NPAR + 1 + 2 * len(tensions))
    p[[k.M, k.MA, k.W0, k.EA, k.DIAM, k.CN, k.CT, k.RHO, k.DS]] = (
        mass, added_mass, weight, stiffness, diameter, drag_normal, drag_tangential, density, ds)
    p[k.INERTIA] = 1.0
    p[k.LAW] = len(tensions)
    p[k.LAW + 1:] = np.concatenate([tensions, strains])
    return p


def elastic_law_knots(law, max_strain: float = 0.5, samples: int = 400):
    """Knots ``(tensions, strains)`` of a case's ``elastic_law`` for :func:`parameters`.

    A table is used as given, through (0, 0). A polynomial ``f(e) = c1 e + c2 e^2 + ...`` is
    sampled on ``0 <= e <= max_strain`` and must increase there (so that ``e(T)`` exists);
    beyond the last knot the law continues with its last slope.
    """
    if law.table is not None:
        rows = np.array([(0.0, 0.0), *law.table], dtype=float)
        strains, tensions = rows[:, 0], rows[:, 1]
    else:
        strains = np.linspace(0.0, max_strain, samples + 1)
        tensions = sum(c * strains ** (i + 1) for i, c in enumerate(law.polynomial))
    if np.any(np.diff(tensions) <= 0):
        raise CaseError([Problem("line_types.elastic_law", "the tension of the elastic law must increase with "
                                 f"strain up to {max_strain:g} for the continuum model (it inverts the law)")])
    return tensions, strains


def strain_of(tension, params) -> np.ndarray:
    """NumPy strain ``e(T)`` of the law in ``params`` (as :func:`kernels2d.strain`), for positions."""
    n = int(params[k.LAW])
    knots_t, knots_e = params[k.LAW + 1:k.LAW + 1 + n], params[k.LAW + 1 + n:k.LAW + 1 + 2 * n]
    i = np.clip(np.searchsorted(knots_t, tension) - 1, 0, n - 2)
    slope = (knots_e[i + 1] - knots_e[i]) / (knots_t[i + 1] - knots_t[i])
    return knots_e[i] + slope * (np.asarray(tension) - knots_t[i])


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
    lt = case.line_types[cable.line_type]
    law = elastic_law_knots(lt.elastic_law) if getattr(lt, "elastic_law", None) is not None else None
    p = parameters(lt.mass, lt.added_mass, lt.weight_in_water_value(env.water_density, env.gravity),
                   lt.axial_stiffness, lt.diameter, lt.drag_normal, lt.drag_tangential, env.water_density,
                   cable.length / cable.segments, law)
    start = _end(case, cable.from_, "cables[0].from", first=True)
    end = _end(case, cable.to, "cables[0].to", first=False)
    z, rows = case.environment.current.table()
    if check_plane and out_of_plane(case):
        raise CaseError(out_of_plane(case))
    return PlanarCable(cable.name, cable.length, cable.segments, p, start, end, z, rows[:, [0, 2]])


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
        body = case.bodies[end.name]
        return EndCondition(k.BODY, body.mass + body.added_mass, body.net_buoyancy, body.drag_area,
                            (body.force[0], body.force[2]))
    raise CaseError([Problem(key, f"point '{end.name}' joins a network; networks run with model: lumped")])


def positions(cable: PlanarCable, y: np.ndarray, origin) -> np.ndarray:
    """Node positions (N+1, 2) from the first end, trapezoidal in ``(1 + e) t`` (2nd order)."""
    stretch = 1.0 + strain_of(y[:, 0], cable.params)
    step = np.column_stack([stretch * np.cos(y[:, 3]), stretch * np.sin(y[:, 3])])
    increments = 0.5 * cable.ds * (step[1:] + step[:-1])
    return np.vstack([np.zeros((1, 2)), np.cumsum(increments, axis=0)]) + np.asarray(origin, dtype=float)
