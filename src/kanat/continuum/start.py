"""The first guess of a continuum run: the statics of the case's cable at t = 0.

The initial state is the discrete steady state of the box equations, found by Newton from the
statics of the case's cable (:mod:`kanat.continuum.models`): the planar solvers for a plain cable
in the x–z plane at t = 0 (marched from a body end, :mod:`kanat.statics.march`), the 3-D
single-cable statics (:mod:`kanat.statics.shooting3d`) for a cable of several sections, with inline
bodies, a surface buoy, a current with a y component or anything else off the plane at the start.
"""
from __future__ import annotations

from kanat.continuum.tail import free_tail_guess
from kanat.model.plane import out_of_plane
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
    its guess is :func:`kanat.continuum.tail.free_tail_guess` (each interval trailing at the
    critical angle of the flow, below it for a heavy line and above it for a buoyant one), which
    the discrete steady solve then corrects. The statics solve has the budget of any
    (:mod:`kanat.statics.budget`).
    """
    if case.cables[0].to.kind == "free":
        return free_tail_guess(case, s)
    with budget(f"the statics of cable '{name}' (the initial state of the run)"):
        if needs_spatial_statics(case):
            from kanat.statics.setup3d import cable_problem3
            from kanat.statics.solve3d import solve_cable3

            return solve_cable3(cable_problem3(case), "auto", s)
        return steady_guess(cable_problems(case)[name], s)
