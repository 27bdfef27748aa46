"""A first guess of a steady 2-D cable ending at a body: its equations marched by fixed-step RK4.

The continuum model starts from its own discrete steady state, which Newton finds from the
statics of the cable (:mod:`kanat.continuum.models`). That guess need not be the converged
statics: the box equations differ from the continuous ones by ``O(ds^2)`` anyway, and Newton
corrects both the same way. For a cable ending at a body, the statics is a march from the
body (where the tension is the body's load) to the fixed end, and classical RK4 with steps of at
most :data:`MAX_STEP` of the length, in Python floats, follows the shooting solver to about
``1e-6`` of the tension and ``1e-7`` of the length on the examples, in 1.5-5.5 ms against its
60 ms, without SciPy's ODE solver and root finders (whose imports cost a run 0.2 s of CPU). With a current varying with depth, the body's depth
is found by the secant method, as :mod:`kanat.statics.shooting` does.

Whatever the march cannot give (both ends fixed, a slack cable, a body depth not found) is
left to :func:`kanat.statics.solve_cable`: :func:`steady_guess` returns its solution then.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.statics import budget
from kanat.statics.problem import BodyEnd, CableBVP
from kanat.statics.solution import CableSolution

MAX_STEP = 1.0 / 200.0
"""Longest RK4 step, as a fraction of the cable's length (each output interval is split evenly)."""
MIN_TENSION = 1e-9
"""Relative to the cable's weight: below it the cable is slack and the march gives up."""
DEPTH_TOLERANCE = 1e-9
"""The secant on the body's depth stops when the fixed end is met within this fraction of the length."""
MAX_SECANT = 50
"""Most evaluations of the secant on the body's depth (the shooting solver's own limit)."""


def steady_guess(problem: CableBVP, s_out) -> CableSolution:
    """The marched steady cable at stations ``s_out`` when one end is a body, else the statics.

    Parameters
    ----------
    problem : CableBVP
    s_out : array_like
        Increasing unstretched arclengths from 0 to the cable's length [m].

    Returns
    -------
    CableSolution
        ``method`` says which: ``march`` (this module) or the statics method that solved it.

    Raises
    ------
    SolverError
        From the statics, when neither gives a steady shape.
    """
    s_out = np.asarray(s_out, dtype=float)
    marched = march_from_body(problem, s_out)
    if marched is not None:
        return marched
    from kanat.statics.driver import solve_cable

    return solve_cable(problem, "auto", s_out)


def march_from_body(problem: CableBVP, s_out: np.ndarray) -> CableSolution | None:
    """The steady cable marched from its body end to its fixed end; None when the march does not
    apply (no body end, or two) or fails (slack, not finite, body depth not found)."""
    ends = (problem.start, problem.end)
    bodies = [isinstance(e, BodyEnd) for e in ends]
    if sum(bodies) != 1 or len(s_out) < 2 or s_out[0] != 0.0 or s_out[-1] != problem.length:
        return None
    at_body = bodies.index(True)
    body, fixed = ends[at_body], np.asarray(ends[1 - at_body].position, dtype=float)
    sign = 1.0 if at_body == 1 else -1.0                 # F = T t: the body pulls s = L along +t
    stations = s_out[::-1] if at_body == 1 else s_out     # from the body to the fixed end
    rho = problem.line.water_density

    def march(z_body):
        force = sign * body.load(problem.flow, z_body, rho)
        return _rk4(problem, stations, np.array([0.0, z_body, *force]))

    z_body = 0.0
    y = march(z_body)
    if y is None:
        return None
    z_body = fixed[1] - y[-1, 1]
    if not problem.flow.is_uniform:
        def miss(z):
            marched = march(z)
            return None if marched is None else marched[-1, 1] - fixed[1]
        z_body = _secant(miss, z_body, z_body + 1e-3 * problem.length, DEPTH_TOLERANCE * problem.length)
        if z_body is None:
            return None
    y = march(z_body)
    if y is None:
        return None
    y[:, 0] += fixed[0] - y[-1, 0]
    if at_body == 1:
        y = y[::-1]
    return CableSolution(s_out, y[:, 0], y[:, 1], y[:, 2:4].copy(), "march")


def _rk4(problem: CableBVP, stations: np.ndarray, y0: np.ndarray) -> np.ndarray | None:
    """States ``(x, z, F_x, F_z)`` (n, 4) at ``stations`` by RK4 from ``y0`` at ``stations[0]``; None
    when the tension falls below the slack floor or a state is not finite."""
    floor = MIN_TENSION * max(abs(problem.line.weight) * problem.length, 1.0)
    longest = MAX_STEP * problem.length
    rhs = scalar_rhs(problem)
    out = np.empty((len(stations), 4))
    out[0] = y0
    x, z, fx, fz = (float(v) for v in y0)
    for i in range(1, len(stations)):
        span = float(stations[i] - stations[i - 1])
        substeps = max(1, math.ceil(abs(span) / longest - 1e-9))
        h = span / substeps
        for _ in range(substeps):
            a = rhs(z, fx, fz)
            b = rhs(z + 0.5 * h * a[1], fx + 0.5 * h * a[2], fz + 0.5 * h * a[3])
            c = rhs(z + 0.5 * h * b[1], fx + 0.5 * h * b[2], fz + 0.5 * h * b[3])
            d = rhs(z + h * c[1], fx + h * c[2], fz + h * c[3])
            x, z, fx, fz = (v + h / 6.0 * (p + 2.0 * q + 2.0 * r + w) for v, p, q, r, w in
                            zip((x, z, fx, fz), a, b, c, d))
        if not all(map(math.isfinite, (x, z, fx, fz))) or math.hypot(fx, fz) <= floor:
            return None
        out[i] = x, z, fx, fz
    return out


def scalar_rhs(problem: CableBVP):
    """:func:`kanat.statics.problem.steady_rhs` for one state, in Python floats (a march calls it
    thousands of times, where NumPy's per-call cost on 4 numbers would dominate).

    Returns
    -------
    callable
        ``rhs(z, F_x, F_z) -> (dx/ds, dz/ds, dF_x/ds, dF_z/ds)`` (the equations do not depend on ``x``).
    """
    line, flow = problem.line, problem.flow
    uniform = flow.is_uniform
    table_z, table_u, table_w = (list(map(float, v)) for v in (flow.z, flow.velocity[:, 0], flow.velocity[:, 1]))
    area = 0.5 * line.water_density * line.diameter
    normal, tangential = line.drag_normal, math.pi * line.drag_tangential
    stiffness, weight = line.axial_stiffness, line.weight
    charge = budget.charge

    def rhs(z, fx, fz):
        charge()
        if uniform:
            u, w = table_u[0], table_w[0]
        else:
            u, w = float(np.interp(z, table_z, table_u)), float(np.interp(z, table_z, table_w))
        tension = math.hypot(fx, fz)
        if tension == 0.0:                      # slack: no direction (NumPy's 0/0, without its cost)
            return math.nan, math.nan, math.nan, math.nan
        tx, tz = fx / tension, fz / tension
        strain = tension / stiffness
        along = u * tx + w * tz
        nu, nw = u - along * tx, w - along * tz
        scale = math.sqrt(1.0 + strain) * area
        speed = math.hypot(nu, nw)
        drag_x = scale * (normal * speed * nu + tangential * abs(along) * along * tx)
        drag_z = scale * (normal * speed * nw + tangential * abs(along) * along * tz)
        return (1.0 + strain) * tx, (1.0 + strain) * tz, -drag_x, weight - drag_z
    return rhs


def _secant(f, x0: float, x1: float, tolerance: float) -> float | None:
    """A root of ``f`` by the secant method from ``x0`` and ``x1``, met when ``|f| <= tolerance``; None
    when ``f`` gives None or no root is met within :data:`MAX_SECANT` evaluations."""
    f0, f1 = f(x0), f(x1)
    for _ in range(MAX_SECANT):
        if f0 is None or f1 is None:
            return None
        if abs(f1) <= tolerance:
            return x1
        if f1 == f0:
            return None
        x0, x1, f0 = x1, x1 - f1 * (x1 - x0) / (f1 - f0), f1
        f1 = f(x1)
    return None
