"""The same mooring in MoorPy (Hall et al. 2024, Energies 17, 3155; MoorPy 1.3 from PyPI), for
side-by-side comparisons with kanat's network statics.

:func:`moorpy_system` builds a MoorPy ``System`` from a kanat case, object by object:
anchors and vessel fairleads are fixed points, network points and point bodies are free
points (mass and volume giving the same net buoyancy), a rigid body is a MoorPy body
(weight at its centre of gravity, buoyancy at its centre of buoyancy as MoorPy's ``rM``, or at
its metacentre above it for a body on its waterplane with equal metacentric heights),
its fairleads points on it; a cable of several sections or with attachments becomes one
MoorPy line per stretch, joined by free points that carry the attachments' mass and
volume; a sloped seabed is MoorPy's uniform slope (``xSlope``). MoorPy 1.3's ``System`` applies no seabed friction (``Line.staticSolve``
resets ``cb``), so comparisons of systems are frictionless; friction is compared on single
lines with ``moorpy.Catenary.catenary``.

Used by tests/peers/test_network_statics_moorpy.py, tests/data/moorpy/make_reference.py and
benchmarks/bench_network_statics.py.
"""
from __future__ import annotations

import contextlib
import io

import numpy as np


def moorpy_system(case, vessel: str = "fixed"):
    """A MoorPy ``System`` of the kanat ``case`` (module docstring), initialized.

    ``vessel``: how the vessel's fairleads enter MoorPy: ``fixed`` points, ``points`` (coupled
    points, one per fairlead position) or ``body`` (points on a coupled body at the origin, of
    no mass or volume).

    Returns
    -------
    ms : moorpy.System
    names : dict
        ``{"lines": {cable: [MoorPy line numbers from 'from' to 'to']}, "points": {name:
        MoorPy point number}, "bodies": {name: MoorPy body number}, "anchors": {"cable.from":
        point number}}``.
    """
    import moorpy as mp

    env = case.environment
    rho, g = env.water_density, env.gravity
    slope = env.seabed.slope_deg if env.seabed is not None else 0.0
    with contextlib.redirect_stdout(io.StringIO()):            # MoorPy's uniform slope: depth - xSlope x
        ms = mp.System(depth=env.depth or 0.0, rho=rho, g=g,
                       **({"xSlope": float(np.tan(np.radians(slope)))} if slope else {}))
    for name, lt in case.line_types.items():
        ms.lineTypes[name] = dict(name=name, d_vol=lt.diameter, m=lt.mass, EA=lt.axial_stiffness,
                                  w=lt.weight_in_water_value(rho, g), MBL=1e12, Cd=lt.drag_normal, Ca=1.0,
                                  CdAx=lt.drag_tangential, CaAx=0.0)
    names = {"lines": {}, "points": {}, "bodies": {}, "anchors": {}, "vessel": vessel, "coupled": {}}
    if vessel == "body":
        ms.addBody(-1, np.zeros(6), m=0.0, v=0.0)
        names["bodies"]["vessel"] = len(ms.bodyList)
    for name, body in case.bodies.items():
        if body.dof == 6:
            r6 = [*(body.position or (0.0, 0.0, 0.0)), *np.radians(body.orientation_deg)]
            C = body.hydrostatic_stiffness_matrix(rho, g)
            ms.addBody(0, r6, m=body.mass, v=body.buoyancy(g) / (rho * g), rCG=np.array(body.center_of_gravity),
                       rM=_buoyancy_lever(body, C, r6, g), AWP=C[2, 2] / (rho * g),
                       f6Ext=np.array([*body.force, 0.0, 0.0, 0.0]))
            names["bodies"][name] = len(ms.bodyList)
    for cable in case.cables:
        ends = [_end(ms, case, cable, end, label, names) for end, label in ((cable.from_, "from"), (cable.to, "to"))]
        stretches = _stretches(case, cable)
        numbers = []
        start_point = ends[0]
        for k, (length, line_type, joint) in enumerate(stretches):
            if k == len(stretches) - 1:
                end_point = ends[1]
            else:
                m, v = joint
                ms.addPoint(0, _along(case, cable, ends, sum(s[0] for s in stretches[:k + 1])), m=m, v=v)
                end_point = len(ms.pointList)
            ms.addLine(length, line_type, nSegs=40, pointA=start_point, pointB=end_point)
            numbers.append(len(ms.lineList))
            start_point = end_point
        names["lines"][cable.name] = numbers
    with contextlib.redirect_stdout(io.StringIO()):
        ms.initialize()
    return ms, names


def _buoyancy_lever(body, C, r6, g) -> np.ndarray:
    """MoorPy's ``rM``, where the buoyancy acts: the centre of buoyancy for a body with a heave
    spring only (weight and buoyancy turn it at their centres in both codes); for a body on its
    waterplane with equal roll and pitch restoring (``C44 = C55 = B GM``, level reference), the
    metacentre ``r_M = (b_x, b_y, (C44 + m g z_G) / B)`` above the centre of buoyancy ``b``, so that
    MoorPy's turning weight and buoyancy give ``C44 (z_b x e_z)``, the righting moment of the tilt
    kanat applies, and the centres' horizontal offsets turn the body as in kanat
    (kanat.physics.hydrostatics eq. 3)."""
    heave_only = np.zeros((6, 6))
    heave_only[2, 2] = C[2, 2]
    if C[2, 2] and r6[2]:
        raise ValueError("MoorPy's body has a heave spring about z = 0 only: give the body position z = 0")
    if np.allclose(C, heave_only) and not body.tilt_in_stiffness:
        return np.array(body.buoyancy_point)
    righting = np.diag([0.0, 0.0, C[2, 2], C[3, 3], C[3, 3], 0.0])
    if not np.allclose(C, righting) or np.any(r6[3:5]):
        raise ValueError("MoorPy's body restores roll and pitch by its turning weight and buoyancy only: give "
                         "the body hydrostatic_stiffness [0, 0, C33, 0, 0, 0], or a waterplane with equal "
                         "metacentric heights and a level orientation")
    buoyancy = body.buoyancy(g)
    b = body.buoyancy_point
    return np.array([b[0], b[1], (C[3, 3] + body.mass * g * body.center_of_gravity[2]) / buoyancy])


def _end(ms, case, cable, end, label, names) -> int:
    env = case.environment
    rho, g = env.water_density, env.gravity
    if end.kind == "vessel" and names["vessel"] != "fixed":
        xyz = tuple(end.offset or case.vessel.tow_point)
        if xyz not in names["coupled"]:
            if names["vessel"] == "body":
                ms.addPoint(1, list(xyz), body=names["bodies"]["vessel"])
            else:
                ms.addPoint(-1, list(xyz))
            names["coupled"][xyz] = len(ms.pointList)
        return names["coupled"][xyz]
    if end.kind in ("anchor", "vessel"):
        xyz = end.position if end.kind == "anchor" else (end.offset or case.vessel.tow_point)
        ms.addPoint(1, list(xyz))
        if end.kind == "anchor":
            names["anchors"][f"{cable.name}.{label}"] = len(ms.pointList)
        return len(ms.pointList)
    if end.kind == "body" and case.bodies[end.name].dof == 6:
        ms.addPoint(1, list(end.offset or (0.0, 0.0, 0.0)), body=names["bodies"][end.name])
        return len(ms.pointList)
    if end.name not in names["points"]:
        if end.kind == "point":
            point = case.points[end.name]
            ms.addPoint(0, list(point.position or (0.0, 0.0, -1.0)), m=point.mass, v=point.volume,
                        fExt=np.array(point.force))
        else:
            body = case.bodies[end.name]
            ms.addPoint(0, list(body.position or (0.0, 0.0, -1.0)), m=body.mass,
                        v=body.buoyancy(g) / (rho * g), fExt=np.array(body.force))
        names["points"][end.name] = len(ms.pointList)
    return names["points"][end.name]


def _stretches(case, cable):
    """``(length, line type, (mass, volume) of the joint after it)`` from 'from' to 'to'."""
    env = case.environment
    rho, g = env.water_density, env.gravity
    cuts = {}
    for item in cable.attachments:
        body = case.bodies[item.body]
        cuts[item.s] = (body.mass, body.buoyancy(g) / (rho * g))
    out = []
    for (a, b), section in zip(cable.section_bounds(), cable.sections):
        inner = sorted(s for s in cuts if a < s < b)
        for lo, hi in zip([a, *inner], [*inner, b]):
            out.append((hi - lo, section.line_type, cuts.get(hi, (0.0, 0.0))))
    return out


def _along(case, cable, ends, s):
    """A first guess for a joint: on the chord between the cable's ends, at ``s / length``."""
    frac = s / cable.length
    return list((1.0 - frac) * np.array(_where(case, cable.from_)) + frac * np.array(_where(case, cable.to)))


def _where(case, end):
    if end.kind == "anchor":
        return end.position
    if end.kind == "vessel":
        return end.offset or case.vessel.tow_point
    item = case.bodies.get(end.name) or case.points.get(end.name)
    return item.position or (0.0, 0.0, -1.0)


def solve(ms, tol=1e-7, max_iterations=2000):
    """``ms.solveEquilibrium`` with MoorPy's printing silenced."""
    with contextlib.redirect_stdout(io.StringIO()):
        ms.solveEquilibrium(tol=tol, maxIter=max_iterations)
    return ms


def line_end_tensions(ms, numbers):
    """Tension at the 'from' and 'to' ends of a cable made of the MoorPy lines ``numbers``."""
    return ms.lineList[numbers[0] - 1].TA, ms.lineList[numbers[-1] - 1].TB


def grounded_length(ms, numbers):
    return sum(ms.lineList[n - 1].LBot for n in numbers)


def assert_body_is_moorpys(case, result, body: str = "buoy"):
    """Network statics' ``result`` of ``case`` against MoorPy's equilibrium of the same system (solved
    to 1e-10): the body's position to 1e-8 m, roll, pitch and heading to 1e-9 rad, every cable's
    fairlead tension to 1e-9 relative."""
    import math

    ms, names = moorpy_system(case)
    solve(ms, tol=1e-10, max_iterations=5000)
    r6 = ms.bodyList[names["bodies"][body] - 1].r6
    attitude = result.attitudes[body]
    np.testing.assert_allclose(result.bodies[body], r6[:3], rtol=0, atol=1e-8)
    np.testing.assert_allclose(attitude[:2], r6[3:5], rtol=0, atol=1e-9)
    assert abs((attitude[2] - r6[5] + math.pi) % (2 * math.pi) - math.pi) < 1e-9
    for cable in case.cables:
        fairlead = line_end_tensions(ms, names["lines"][cable.name])[1]
        assert abs(result.cables[cable.name].tension[-1] / fairlead - 1.0) < 1e-9, cable.name
