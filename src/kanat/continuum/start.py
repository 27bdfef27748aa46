"""The first guess of a continuum run: the statics of the case's cable at t = 0.

The initial state is the discrete steady state of the box equations, found by Newton from the
statics of the case's cable (:mod:`kanat.continuum.models`): the planar solvers for a plain cable
in the x–z plane at t = 0 (marched from a body end, :mod:`kanat.statics.march`), the 3-D
single-cable statics (:mod:`kanat.statics.shooting3d`) for a cable of several sections, with inline
bodies, a surface buoy, a current with a y component or anything else off the plane at the start.
"""
from __future__ import annotations

import numpy as np

from kanat.model.plane import out_of_plane
from kanat.physics.drag import critical_angle
from kanat.statics import CableSolution
from kanat.statics.budget import budget
from kanat.statics.march import steady_guess
from kanat.statics.setup import cable_problems

STEADY_PASSES = 4
"""Steady solves at most, each with the current (and the seabed) at the previous solve's node positions."""


def needs_spatial_statics(case) -> bool:
    """True when the planar statics cannot give the cable's shape at t = 0 (module docstring).

    Only the start counts: a turn later in the track leaves the steady state at t = 0 in the
    x–z plane (:func:`kanat.model.plane.out_of_plane` with ``at_start``), where the planar
    statics give the spatial model's first guess as well.
    """
    cable, env = case.cables[0], case.environment
    ends = [case.bodies[e.name] for e in cable.ends if e.kind == "body"]
    slope = env.seabed is not None and (env.seabed.slope_deg != 0 or env.seabed.friction > 0)
    return (len(cable.sections) > 1 or bool(cable.attachments) or bool(out_of_plane(case, at_start=True))
            or slope or any(b.surface_buoy is not None for b in ends) or grounds_under_body(case))


def grounds_under_body(case) -> bool:
    """True for a line from an anchor on the seabed to a body that is longer than the anchor is deep: its
    lower part may rest on the seabed, which the planar statics, marched down from the body, does not
    lay it on (the 3-D statics does)."""
    cable, depth = case.cables[0], case.environment.depth
    if depth is None or cable.from_.kind != "anchor" or cable.to.kind != "body":
        return False
    anchor_z = cable.from_.position[2]
    return anchor_z <= -depth + 1e-6 * cable.length and cable.length > -anchor_z


def static_shape(case, name, s) -> CableSolution:
    """The statics solution of the case's cable at stations ``s`` (the initial guess).

    A cable with a free tail has no statics solution of its own (statics refuses free ends);
    its guess is :func:`free_tail_guess`, which the discrete steady solve then corrects. The
    statics solve has the budget of any (:mod:`kanat.statics.budget`).
    """
    if case.cables[0].to.kind == "free":
        return free_tail_guess(case, s)
    with budget(f"the statics of cable '{name}' (the initial state of the run)"):
        if needs_spatial_statics(case):
            from kanat.statics.setup3d import cable_problem3
            from kanat.statics.solve3d import solve_cable3

            return solve_cable3(cable_problem3(case), "auto", s)
        return steady_guess(cable_problems(case)[name], s)


def free_tail_guess(case, s) -> CableSolution:
    """A straight cable trailing from the tow point at the critical angle of the relative flow.

    ``cos(phi_c) = (-w + sqrt(w^2 + 4R^2)) / (2R)``, ``R = 0.5 rho d C_n U^2`` (theory/continuum.md eq. (C15),
    :func:`kanat.physics.drag.critical_angle`); the
    tension grows from 0 at the tail with the tangential weight and drag. Vertical in still water.
    """
    env, cable = case.environment, case.cables[0]
    lt = case.line_types[cable.line_type]
    w = lt.weight_in_water_value(env.water_density, env.gravity)
    speed = case.vessel.initial_speed - env.current.at(0.0)[0]
    phi = critical_angle(w, 0.5 * env.water_density * lt.diameter * lt.drag_normal, speed)
    along = np.array([-np.sign(speed) * np.cos(phi) if speed else 0.0, -np.sin(phi)])
    per_length = w * np.sin(phi) + 0.5 * env.water_density * np.pi * lt.diameter * lt.drag_tangential * (
        speed * np.cos(phi))**2
    tension = np.maximum(per_length * (cable.length - s), 1e-6 * w * cable.length)
    origin = np.array([case.vessel.tow_point[0], case.vessel.tow_point[2]])
    xz = origin + np.outer(s, along)
    return CableSolution(s, xz[:, 0], xz[:, 1], np.outer(tension, along), "free-tail guess")
