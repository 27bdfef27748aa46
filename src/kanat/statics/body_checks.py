"""Physical checks of the bodies of a steady state (the ``bodies`` check of
:mod:`kanat.statics.steady_checks`, docs/statics.md "Checks of a steady state").

A body's loads hold only where the case puts it: a point body's ``net_buoyancy`` is its
buoyancy under water, a surface buoy's waterplane lifts only while it is immersed, a rigid
body's fairleads sit at fixed offsets from its reference point. A steady solver that ignores
the surface can lift a float tens of metres into the air and still converge (WHOI's MPL
mooring in the continuum model: fourteen floats that keep their lift out of the water carry
the umbilical 47 m above the surface). :func:`check_bodies` looks at every body's position
(a rigid body's reference point, its attitude when known) and, in order:

1. ``finite``: the position is finite.
2. ``attached``: the body is where its cables hold it. A cable end or an attachment at a body is
   a node of the cable: for a point body that node is the body's position; for a rigid body it
   is the fairlead ``r + R(roll, pitch, yaw) offset`` (``R = Rz Ry Rx``,
   :func:`kanat.physics.motion.rotation_matrix`), or, the attitude unknown, a point
   ``|offset|`` from the reference point (a rotation keeps lengths). Beyond
   :data:`PLACEMENT_TOLERANCE` (plus :data:`RELATIVE_TOLERANCE` of the cable's length) the
   solver lost the body.
3. ``surface``: no body whose loads are those of a submerged body sits above the water
   surface, the mean surface ``z = 0`` raised by the highest crest of the case's waves
   (:func:`crest_height`); the highest such body is named. A surface buoy (``surface_buoy``) is out of the water when its keel
   is above it: its waterplane holds nothing up (a failure). A buoyant body
   (``net_buoyancy > 0``, no waterplane) keeps its lift in the air in the model (a failure); a
   sinking one weighs ``m g`` in the air, not ``-net_buoyancy`` (a warning: the state is off
   by its buoyancy). A spherical float (``diameter``) keeps only its immersed share of its buoyancy,
   so it may sit at or above the surface. A rigid body with a waterplane (``waterplane_area`` or a heave stiffness)
   is out of the water when it rose above its given ``position`` (none given: the origin, where
   network statics balances its hydrostatics, :func:`hydrostatic_reference`) by more than its
   wall-sided draft ``B / (rho g A_w)``, ``B = net_buoyancy + m g`` its buoyancy (a failure).
4. ``seabed``: no rigid body's reference point lies under the seabed by more than its reach
   (the largest fairlead offset) plus :data:`PENETRATION_FLOOR`: the whole body would be in
   the ground. A point body is a node of its cables, whose own ``seabed`` check covers it.
"""
from __future__ import annotations

from typing import Mapping

import numpy as np

from kanat.physics.motion import rotation_matrix
from kanat.physics.seabed import PENETRATION_FLOOR, seabed_of

PLACEMENT_TOLERANCE = 1e-3
"""A body may sit this far from the node its cable holds it at [m] (plus
:data:`RELATIVE_TOLERANCE` of the cable's length)."""
RELATIVE_TOLERANCE = 1e-6
"""Round-off allowed on distances, as a fraction of the cable's length."""
SURFACE_TOLERANCE = 1e-3
"""A body may sit this far above the water surface [m] (round-off of a state at the surface)."""


def crest_height(environment) -> float:
    """Highest elevation of the case's waves above the mean surface [m]: 0 in still water, ``H / 2``
    of regular waves, the sum of the amplitudes of a sea given by components, ``Hs`` of a JONSWAP sea
    (its most probable largest crest in a few hundred waves is about ``0.9 Hs``)."""
    waves = environment.waves
    if waves is None:
        return 0.0
    if waves.type == "regular":
        return 0.5 * waves.height
    if waves.type == "jonswap":
        return waves.hs
    return float(sum(row[1] for row in waves.components))


def check_bodies(case, cables: Mapping, bodies: Mapping, attitudes: Mapping | None,
                 when: str, warnings: list) -> str | None:
    """Run the checks of the module docstring on the bodies of ``case`` found in ``bodies``.

    Parameters
    ----------
    case : kanat.model.Case
    cables : mapping of str to CableNodes
        Every cable's nodes by name (``s`` (n,), ``position`` (n, 3)).
    bodies : mapping of str to array_like, shape (3,)
        Body positions (a rigid body's reference point) [m].
    attitudes : mapping of str to array_like, shape (3,), or None
        Roll, pitch, yaw of the bodies [rad], where known.
    when : str
        Names the state in the messages.
    warnings : list of str
        Receives the warnings (a sinking body above the water).

    Returns
    -------
    str or None
        The message of the first failed check, None when all pass.
    """
    attitudes = attitudes or {}
    present = [(name, np.asarray(bodies[name], dtype=float).reshape(3)) for name in case.bodies if name in bodies]
    highest_first = sorted(present, key=lambda item: -item[1][2] if np.isfinite(item[1][2]) else 0.0)
    for check in (_finite, _attached, _surface, _seabed):
        for name, position in (highest_first if check is _surface else present):
            failure = check(case, name, position, attitudes.get(name), cables, when, warnings)
            if failure is not None:
                return failure
    return None


def _finite(case, name, position, attitude, cables, when, warnings) -> str | None:
    if np.all(np.isfinite(position)):
        return None
    return (f"body '{name}' is not at a finite position ({list(position)}) in {when}: the solver diverged; try "
            "another statics method or check the body's loads")


def holds(case, name: str):
    """Where the cables hold body ``name``: ``(cable, s, offset or None)`` for every cable end at the
    body (``s`` 0 or the cable's length) and every attachment of it."""
    for cable in case.cables:
        for end, s in ((cable.from_, 0.0), (cable.to, cable.length)):
            if end.kind == "body" and end.name == name:
                yield cable, s, end.offset
        for attachment in cable.attachments:
            if attachment.body == name:
                yield cable, attachment.s, None


def _attached(case, name, position, attitude, cables, when, warnings) -> str | None:
    body = case.bodies[name]
    for cable, s, offset in holds(case, name):
        nodes = cables.get(cable.name)
        if nodes is None:
            continue
        s_nodes = np.asarray(nodes.s, dtype=float)
        tolerance = PLACEMENT_TOLERANCE + RELATIVE_TOLERANCE * cable.length
        k = int(np.argmin(np.abs(s_nodes - s)))
        if abs(s_nodes[k] - s) > tolerance:
            continue                                   # no node at the attachment (a coarser output)
        node = np.asarray(nodes.position, dtype=float).reshape(-1, 3)[k]
        arm = np.zeros(3) if offset is None else np.asarray(offset, dtype=float)
        if body.dof == 6 and attitude is None:
            off = abs(float(np.linalg.norm(node - position)) - float(np.linalg.norm(arm)))
            what = f"{np.linalg.norm(arm):.4g} m (its fairlead offset) from its reference point"
        else:
            turn = np.zeros(3) if attitude is None else np.asarray(attitude, dtype=float)
            target = position + rotation_matrix(*turn) @ arm
            off = float(np.linalg.norm(node - target))
            what = "at its fairlead" if offset is not None else "at the body"
        if off > tolerance:
            return (f"body '{name}' at {_xyz(position)} is {off:.6g} m from where cable '{cable.name}' holds it "
                    f"(node {k}, s = {s_nodes[k]:.6g} m, at {_xyz(node)}, must be {what}) in {when}: the solver "
                    "lost the body; try another statics method")
    return None


def _surface(case, name, position, attitude, cables, when, warnings) -> str | None:
    env, body = case.environment, case.bodies[name]
    surface = crest_height(env)
    height = float(position[2]) - surface
    where = (f"body '{name}' at {_xyz(position)} is {height:.6g} m above the water surface (z = {surface:g} m) "
             f"in {when}")
    if body.dof == 6 and (body.waterplane_area is not None or body.hydrostatic_stiffness is not None):
        return _rigid_surface(case, name, position, when)
    if height <= SURFACE_TOLERANCE or body.diameter is not None:      # a float's buoyancy follows its immersion
        return None
    if body.surface_buoy is not None:
        return (f"{where}: its keel is out of the water, where its waterplane holds nothing up, so only its "
                "lines can hold it there (floats that keep their net_buoyancy in the air in the model, or a "
                "fairlead above the water); "
                "use fewer or smaller floats (the lines' weight must hold them under water), a deeper anchor or "
                "a shorter line")
    if body.net_buoyancy > 0:
        return (f"{where}: its net_buoyancy {body.net_buoyancy:.4g} N lifts it only under water, but a point "
                "body keeps it in the air in the model, so the floats carry their lines through the surface and "
                "the state is no possible one; use fewer or smaller floats (the lines' weight must hold them "
                "under water), a deeper anchor or a shorter line; a body meant to float at the surface is a "
                "surface_buoy at a cable's end, or, clamped inline, a float with a diameter (its buoyancy then "
                "follows its immersion)")
    buoyancy = body.buoyancy(env.gravity)
    warnings.append(f"{where}: out of the water it weighs m g = {body.mass * env.gravity:.4g} N, not the "
                    f"{-body.net_buoyancy:.4g} N of its net_buoyancy (its {buoyancy:.4g} N of buoyancy is "
                    "counted in the air)")
    return None


def _rigid_surface(case, name, position, when) -> str | None:
    """A surface-piercing rigid body: out of the water once it rose more than its wall-sided draft
    above where its hydrostatics balance (:func:`hydrostatic_reference`)."""
    env, body = case.environment, case.bodies[name]
    heave_stiffness = float(body.hydrostatic_stiffness_matrix(env.water_density, env.gravity)[2, 2])
    if heave_stiffness <= 0:
        return None
    draft = max(body.buoyancy(env.gravity), 0.0) / heave_stiffness         # B / (rho g A_w)
    reference = hydrostatic_reference(body)
    rise = float(position[2]) - float(reference[2])
    if rise <= draft + SURFACE_TOLERANCE:
        return None
    given = ("its given position" if body.position is not None
             else "its hydrostatic reference z = 0 (no position given)")
    return (f"body '{name}' at {_xyz(position)} rose {rise:.4g} m above {given} in {when}, more than "
            f"its draft B / (rho g A_w) = {draft:.4g} m: it is out of the water, where its linear hydrostatics "
            "no longer hold; check its buoyancy, its hydrostatics and the lines' pull")


def hydrostatic_reference(body) -> np.ndarray:
    """Where a rigid body's hydrostatics balance, the point its ``hydrostatic_stiffness`` (or
    waterplane) restores towards [m], shape (3,): its ``position``, or, none given, the origin on
    the mean surface, as network statics takes it (:func:`kanat.statics.network._own_loads`)."""
    return np.zeros(3) if body.position is None else np.asarray(body.position, dtype=float)


def _seabed(case, name, position, attitude, cables, when, warnings) -> str | None:
    body = case.bodies[name]
    seabed = seabed_of(case.environment)
    if body.dof != 6 or seabed is None:
        return None
    reach = max([float(np.linalg.norm(offset)) for _, _, offset in holds(case, name) if offset is not None] + [0.0])
    depth = float(seabed.penetration(position[None, :])[0])
    if depth <= reach + PENETRATION_FLOOR:
        return None
    return (f"body '{name}' has its reference point at {_xyz(position)}, {depth:.6g} m below the seabed in {when}, "
            f"farther than its fairleads reach ({reach:.4g} m): the whole body is in the ground; lighten it, "
            "shorten its lines or deepen the water")


def _xyz(position) -> str:
    return "(" + ", ".join(f"{c:.4g}" for c in position) + ") m"
