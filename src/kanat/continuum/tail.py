"""The first guess of a cable with a free tail: each interval trailing at the critical angle of the flow.

A free tail carries no tension at its end, so near it the line lies where its normal drag carries
its weight in water; in a uniform flow a whole inextensible tail does (theory/continuum.md
eq. (C15), :func:`kanat.physics.drag.critical_angle`)::

    (1)  R sin^2(phi) = |w| cos(phi),   R = 0.5 rho d C_n |u|^2,   u = U_current(z) - U_tow

at ``phi`` below the horizontal relative flow ``u`` for a heavy line (``w > 0``) and above it for a
buoyant one (``w < 0``): straight down or straight up in still water. The tension grows from 0 at
the tail with the tangential weight and drag of each interval::

    (2)  dT/ds = -(|w| sin(phi) + 0.5 rho pi d C_t (|u| cos(phi))^2)

(both pull along the line towards the tail, whichever way the weight points). The guess marches
from the tow point, interval by interval, each along the flow at its upper node's depth with its
own section's line type: the exact steady shape of an inextensible tail of one line type in a
uniform flow, a close one otherwise (sections, a sheared current, stretch), which the discrete
steady solve corrects. A still tail of one line type is exact as well: vertical, its tension the
weight in water (or the buoyancy) of the part beyond, ``T(s) = |w| (L - s)``.

A heavy tail whose guess reaches the seabed is refused (:func:`refuse_grounded_tail`): its part on the
seabed carries no tension in still water (next to none in a current), which the continuum model's
tension-based unknowns cannot start from (150 m of chain hung from the surface in 100 m of water
started 28 m below the seabed, tensions of -1.3e8 N, and stopped at t = 0 saying it fell through).
The lumped model lays such a tail on the seabed (:mod:`kanat.lumped.tow_guess`).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum.vessel_motion import vessel_track
from kanat.errors import CaseError, Problem
from kanat.physics.drag import trailing_direction
from kanat.physics.seabed import seabed_of
from kanat.statics import CableSolution

TAIL_TENSION = 1e-6
"""Tension left at the tail node, as a fraction of the tension at the tow point (at least 1e-6 N):
the guess's angles are read from its tension vectors, which must not vanish there."""


def free_tail_guess(case, s) -> CableSolution:
    """The straight-per-interval trailing tail of eq. (1)-(2) (module docstring) at stations ``s``.

    Parameters
    ----------
    case : kanat.model.Case
        A case whose cable runs from the vessel's tow point (or an anchor) to a free end.
    s : ndarray, shape (n,)
        Unstretched arclength of the stations [m], from the attached end.

    Returns
    -------
    CableSolution
        In the x–z plane when the flow has no y component, in 3-D otherwise.
    """
    env, cable = case.environment, case.cables[0]
    tow = vessel_track(case.vessel, env).tow_state(0.0)
    anchored = cable.from_.kind == "anchor"
    origin = np.asarray(cable.from_.position, dtype=float) if anchored else tow.position
    frame = np.zeros(3) if anchored else tow.velocity
    s = np.asarray(s, dtype=float)
    ds = np.diff(s)
    weight, normal, tangential = _interval_loads(case, 0.5 * (s[:-1] + s[1:]))
    position = np.empty((len(s), 3))
    position[0] = origin
    direction = np.empty((len(ds), 3))
    pull = np.empty(len(ds))
    for i, length in enumerate(ds):
        flow = np.asarray(env.current.at(float(position[i, 2])), dtype=float)[:2] - np.asarray(frame)[:2]
        direction[i], pull[i] = _trailing(weight[i], normal[i], tangential[i], flow)
        position[i + 1] = position[i] + length * direction[i]
    refuse_grounded_tail(case, s, position)
    carried = np.concatenate([np.cumsum((pull * ds)[::-1])[::-1], [0.0]])     # eq. (2) from the tail
    tension = np.maximum(carried, TAIL_TENSION * max(carried[0], 1.0))
    tangent = np.vstack([direction, direction[-1:]])                        # a node takes the interval after it
    force = tension[:, None] * tangent
    planar = not np.any(position[:, 1] != origin[1])
    return CableSolution(s, position[:, 0], position[:, 2], force[:, [0, 2]], "free-tail guess",
                         y=None if planar else position[:, 1], force_y=None if planar else force[:, 1])


def refuse_grounded_tail(case, s, position) -> None:
    """Refuse a free tail whose guess ``position`` (n, 3) [m] at stations ``s`` reaches the seabed (module
    docstring).

    Raises
    ------
    CaseError
        On ``cables[0].to``, with the arclength at which the tail reaches the seabed and the model to use.
    """
    seabed = seabed_of(case.environment)
    if seabed is None:
        return
    below = np.flatnonzero(seabed.penetration(position) > 0.0)
    if not len(below):
        return
    reach = float(s[below[0]])
    raise CaseError([Problem("cables[0].to", (
        f"the free tail of cable '{case.cables[0].name}' reaches the seabed (it is below it from s = {reach:.4g} m of "
        f"{float(s[-1]):.4g} m, hanging in the flow at t = 0): its part on the seabed carries no tension, which "
        "the continuum model cannot start from; use model: lumped, which lays the tail on the seabed, or a "
        "shorter tail"))])


def _interval_loads(case, middle: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per interval (its mid-station ``middle``): weight in water ``w`` [N/m], ``0.5 rho d C_n``
    and ``0.5 rho pi d C_t`` [N s^2/m^3] of the section it lies in."""
    env, cable = case.environment, case.cables[0]
    rho = env.water_density
    ends = np.cumsum([section.length for section in cable.sections])
    which = np.minimum(np.searchsorted(ends, middle), len(ends) - 1)
    types = [case.line_types[section.line_type] for section in cable.sections]
    weight = np.array([types[j].weight_in_water_value(rho, env.gravity) for j in which])
    normal = np.array([0.5 * rho * types[j].diameter * types[j].drag_normal for j in which])
    tangential = np.array([0.5 * rho * np.pi * types[j].diameter * types[j].drag_tangential for j in which])
    return weight, normal, tangential


def _trailing(weight: float, normal: float, tangential: float, flow: np.ndarray) -> tuple[np.ndarray, float]:
    """Unit direction (3,) from an interval's upper node to its lower one (eq. (1),
    :func:`kanat.physics.drag.trailing_direction`) and the tension it adds per unit length (eq. (2)) in
    the horizontal relative flow ``flow`` (2,) [m/s]: ``|w| sin(phi)`` is the direction's vertical
    component times ``|w|``, ``|u| cos(phi)`` its horizontal component along the flow."""
    direction = trailing_direction(weight, normal, flow)
    along = float(direction[:2] @ np.asarray(flow, dtype=float)[:2])          # |u| cos(phi)
    return direction, abs(weight) * abs(direction[2]) + tangential * along**2
