"""The grid of a continuum cable: nodes, and one parameter row per interval (sections, inline bodies).

A cable of several sections (``cables[i].sections``) gets each section's own properties on
each of its intervals, with a node at every joint, so nothing is averaged across a change of
line type. An attachment (``cables[i].attachments``, an inline float, clump weight or
instrument) sits at a node: the grid puts a *junction* there -- two nodes at the same
arclength joined by a zero-length interval whose rows are the body's equations
(:mod:`kanat.continuum.rows2d`) -- so the tension and the angle may jump across it. When an
attachment does not fall on a node of its section's uniform grid, the section is split there
and its segments shared between the two pieces in proportion to their lengths (at least one
each); :attr:`Grid.notes` says so.

The rows hold everything the kernels read (:mod:`kanat.continuum.kernels2d` has the layout):
the line type's constants and elastic law, the interval's length, gravity, bending stiffness,
the seabed (the same contact model as ``environment.seabed``) and, on junction rows, the body.
The scheme's entries are filled per step.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.errors import CaseError, Problem

ON_NODE_RTOL = 1e-9
"""An attachment within this fraction of a segment from a node sits on that node."""


@dataclass(frozen=True)
class SeabedContact:
    """The contact model the kernels apply (``environment.seabed``; defaults with only ``depth``).

    Attributes
    ----------
    depth : float
        Seabed depth at x = 0 [m].
    slope_deg : float
        Rising towards +x [deg].
    stiffness, damping : float
        ``k_b`` [Pa/m], ``c_b`` [Pa s/m] (MoorDyn's kbot, cbot), on the area diameter x length.
    friction, lateral_friction : float
        Coulomb coefficients along and across the line.
    """

    depth: float
    slope_deg: float = 0.0
    stiffness: float = 3.0e6
    damping: float = 3.0e5
    friction: float = 0.0
    lateral_friction: float = 0.0

    @property
    def normal(self) -> np.ndarray:
        """Upward unit normal (3,) in global (x, y, z)."""
        a = math.radians(self.slope_deg)
        return np.array([-math.sin(a), 0.0, math.cos(a)])

    @property
    def level(self) -> float:
        """``c0`` of the plane ``n . r = c0`` [m]."""
        return -self.depth * math.cos(math.radians(self.slope_deg))

    def penetration(self, points) -> np.ndarray:
        """Depth of ``points`` (..., 3) below the plane along its normal [m]; <= 0 above."""
        return self.level - np.asarray(points, dtype=float) @ self.normal

    def height(self, x) -> np.ndarray:
        """Seabed height at ``x`` [m]."""
        return -self.depth + np.tan(math.radians(self.slope_deg)) * np.asarray(x, dtype=float)


def seabed_contact(environment) -> SeabedContact | None:
    """The contact model of a case's environment: its ``seabed`` block, or the defaults of one when
    only ``depth`` is given (the continuum model always has the seabed it is told of); None without
    ``depth``."""
    if environment.depth is None:
        return None
    sb = environment.seabed
    if sb is None:
        return SeabedContact(environment.depth)
    return SeabedContact(environment.depth, sb.slope_deg, sb.stiffness, sb.damping, sb.friction, sb.lateral_friction)


def parameters(mass, added_mass, weight, stiffness, diameter, drag_normal, drag_tangential, density, ds,
               law=None, gravity=9.81, bending=0.0):
    """The kernel parameter row of an interval: the scalars (scheme entries zero), then the elastic law.

    ``law`` is ``(tensions, strains)`` knots (tensions ascending, through (0, 0)); default the
    linear law ``e = T / EA`` (knots (0, 0) and (EA, 1)).
    """
    tensions, strains = law if law is not None else ((0.0, stiffness), (0.0, 1.0))
    p = np.zeros(k.NPAR + 1 + 2 * len(tensions))
    p[[k.M, k.MA, k.W0, k.EA, k.DIAM, k.CN, k.CT, k.RHO, k.DS, k.GRAV, k.EI]] = (
        mass, added_mass, weight, stiffness, diameter, drag_normal, drag_tangential, density, ds, gravity, bending)
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


def with_seabed(p: np.ndarray, seabed: SeabedContact | None) -> np.ndarray:
    """``p`` with the seabed's entries set (planar normal: components x and z in slots 0 and 1)."""
    p = p.copy()
    if seabed is None:
        return p
    n = seabed.normal
    p[[k.SB_ON, k.SB_K, k.SB_C, k.SB_MUA, k.SB_MUL, k.SB_C0, k.SB_N0, k.SB_N1, k.SB_N2]] = (
        1.0, seabed.stiffness, seabed.damping, seabed.friction, seabed.lateral_friction, seabed.level,
        n[0], n[2], 0.0)
    return p


@dataclass(frozen=True)
class Grid:
    """Nodes and interval rows of one cable.

    Attributes
    ----------
    s : ndarray, shape (n_nodes,)
        Unstretched arclength of every node [m] (a junction's two nodes share theirs).
    rows : ndarray, shape (n_nodes - 1, n_par)
        Parameter row of every interval.
    junctions : tuple of (int, str)
        ``(index of the junction interval, body name)`` of every attachment.
    sections : tuple of str
        Line type of each section, by the index in ``rows[:, SECTION]``.
    notes : tuple of str
        Decisions taken for the user (a section split at an attachment).
    """

    s: np.ndarray
    rows: np.ndarray
    junctions: tuple = ()
    sections: tuple = ()
    notes: tuple = ()

    @property
    def ds(self) -> np.ndarray:
        """Unstretched interval lengths [m] (0 on junctions)."""
        return self.rows[:, k.DS]

    @property
    def bending(self) -> bool:
        """True when some section has bending stiffness (the six-unknown kernels)."""
        return bool(np.any(self.rows[:, k.EI] > 0))

    @property
    def uniform(self) -> bool:
        """One section, no attachment: every row equal."""
        return len(self.sections) == 1 and not self.junctions


def _line_row(case, line_type: str, index: int, seabed) -> np.ndarray:
    env = case.environment
    lt = case.line_types[line_type]
    law = elastic_law_knots(lt.elastic_law) if getattr(lt, "elastic_law", None) is not None else None
    p = parameters(lt.mass, lt.added_mass, lt.weight_in_water_value(env.water_density, env.gravity),
                   lt.axial_stiffness, lt.diameter, lt.drag_normal, lt.drag_tangential, env.water_density, 0.0,
                   law, env.gravity, lt.bending_stiffness)
    p[k.SECTION] = index
    return with_seabed(p, seabed)


def _junction_row(base: np.ndarray, body, env) -> np.ndarray:
    p = base.copy()
    p[k.KIND], p[k.DS], p[k.EI] = k.JUNCTION, 0.0, base[k.EI]
    p[[k.JB_MASS, k.JB_BUOY, k.JB_DRAG, k.JB_F0, k.JB_F1, k.JB_F2, k.JB_WAVE]] = (
        body.mass + body.added_mass, body.net_buoyancy, 0.5 * env.water_density * body.drag_area,
        *body.force, body.added_mass + (body.net_buoyancy + body.mass * env.gravity) / env.gravity)
    if body.diameter is not None:                   # a spherical float: its buoyancy follows its immersion
        p[[k.JB_DIAMETER, k.JB_FULL]] = body.diameter, body.buoyancy(env.gravity)
    return p


def _pieces(cable, key: str):
    """``(section index, start, end, segments)`` of every piece, and the attachments at the ends of
    pieces ``(piece index after which it sits, body name)``, with the notes on splits."""
    bounds = cable.section_bounds()
    cuts: dict[int, list] = {}
    for i, item in enumerate(cable.attachments):
        if item.s <= 0.0 or item.s >= cable.length * (1 - 1e-12):
            raise CaseError([Problem(f"{key}.attachments[{i}].s", f"an attachment at a cable end (s = {item.s:g} m) "
                                     "is that end's body: write it as the end ('from' or 'to') instead")])
        section = next(j for j, (a, b) in enumerate(bounds) if item.s <= b * (1 + 1e-12))
        cuts.setdefault(section, []).append((item.s, item.body))
    pieces, joints, notes = [], [], []
    for j, (section, (a, b)) in enumerate(zip(cable.sections, bounds)):
        n, points = section.segments, [a]
        names = []
        for s_a, body in cuts.get(j, []):
            if abs(s_a - b) <= ON_NODE_RTOL * (b - a) / n:
                names.append((None, body))                 # at the section's far joint
                continue
            points.append(s_a)
            names.append((len(points) - 2, body))
        points.append(b)
        lengths = np.diff(points)
        exact = lengths / ((b - a) / n)
        if np.all(np.abs(exact - np.round(exact)) <= ON_NODE_RTOL * n) and np.all(np.round(exact) >= 1):
            counts = np.round(exact).astype(int)
        else:
            counts = np.maximum(1, np.round(n * lengths / (b - a)).astype(int))
            notes.append(f"cable '{cable.name}' section {j} ({section.line_type}): split at its attachments into "
                         f"{', '.join(f'{c} x {length / c:.4g} m' for c, length in zip(counts, lengths))} "
                         "segments so that each attachment sits on a node")
        first = len(pieces)
        for piece, (start, end, count) in enumerate(zip(points[:-1], points[1:], counts)):
            pieces.append((j, start, end, int(count)))
        for local, body in names:
            joints.append((first + (len(points) - 2 if local is None else local), body))
    return pieces, joints, notes


def cable_grid(case, index: int = 0, seabed: SeabedContact | None = None) -> Grid:
    """The grid of ``case.cables[index]`` (module docstring)."""
    cable = case.cables[index]
    key = f"cables[{index}]"
    pieces, joints, notes = _pieces(cable, key)
    bases = [_line_row(case, section.line_type, j, seabed) for j, section in enumerate(cable.sections)]
    width = max(len(b) for b in bases)
    bases = [np.concatenate([b, np.zeros(width - len(b))]) for b in bases]
    after = {piece: body for piece, body in joints}
    rows, s, junctions = [], [0.0], []
    for piece, (section, start, end, count) in enumerate(pieces):
        row = bases[section].copy()
        row[k.DS] = (end - start) / count
        rows.extend([row] * count)
        s.extend(start + (end - start) * np.arange(1, count + 1) / count)
        if piece in after:
            body = case.bodies[after[piece]]
            junctions.append((len(rows), after[piece]))
            rows.append(_junction_row(row, body, case.environment))
            s.append(end)
    return Grid(np.array(s), np.array(rows), tuple(junctions), tuple(cable.line_types), tuple(notes))
