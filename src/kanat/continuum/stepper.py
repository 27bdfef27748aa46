"""One time step of the planar continuum model: Newton's method on the banded system (theory/time-schemes.md §1).

Newton starts from the previous state advanced with its rate, tests convergence on
increments scaled by the problem's own sizes (tension, speed, 1 rad; shear and moment with
bending), and stops after ``MAX_ITERATIONS``. A step whose Newton iteration fails is cut in
halves, up to ``MAX_CUTS`` levels, before the run is stopped with a message saying what to try.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat._private_api import banded_lapack
from kanat.continuum import kernels2d as k
from kanat.continuum.model2d import PlanarCable, positions
from kanat.continuum.newton import MAX_ITERATIONS, TOLERANCE, NewtonFailure
from kanat.continuum.steady import steady_with_positions
from kanat.continuum.water import elevation, float_elevations, has_floats, kinematics_time, planar_water
from kanat.continuum.wetted import wet_step_rows

MAX_CUTS = 4             # a failed step is retried as 2, 4, 8, 16 substeps


@dataclass(frozen=True)
class State:
    """The planar cable at one instant.

    Attributes
    ----------
    t : float
        Time [s].
    y : ndarray, shape (n_nodes, nv)
        ``(T, u, v, phi)`` at the nodes (and ``S, M`` with bending stiffness).
    rate : ndarray, shape (n_nodes, nv)
        Time derivative of ``y`` (the generalized-α scheme carries it).
    xz : ndarray, shape (n_nodes, 2)
        Node positions [m].
    rows : ndarray or None
        The interval rows when they change in time (a winch); None: the cable's own.
    s : ndarray or None
        With a winch: each node's material arclength at t = 0 (node 0 is the winch point).
    """

    t: float
    y: np.ndarray
    rate: np.ndarray
    xz: np.ndarray
    rows: np.ndarray | None = None
    s: np.ndarray | None = None


def converged(size: float, previous: float) -> bool:
    """Newton's test on the scaled increment ``size`` (and the one before, ``previous``): below
    :data:`TOLERANCE`, or the next one predicted below it from the rate of convergence
    (``theta = size / previous``, next ``<= theta / (1 - theta) size``: Hairer & Wanner's test, which
    spares the iteration that would only confirm a quadratically converged step)."""
    if size < TOLERANCE:
        return True
    if not np.isfinite(previous):
        return False
    theta = size / previous
    return theta < 0.5 and theta / (1.0 - theta) * size < TOLERANCE


def scales(cable, y: np.ndarray) -> np.ndarray:
    """Increment scales (nv,): tension, speed, speed, angle (and shear, moment with bending)."""
    p = cable.params
    tension = max(np.max(np.abs(y[:, 0])), abs(p[k.W0]) * cable.length, 1.0)
    speed = max(np.max(np.abs(y[:, 1:3])), 1.0)
    if y.shape[1] == 6:
        return np.array([tension, speed, speed, 1.0, tension, tension * cable.length])
    return np.array([tension, speed, speed, 1.0])


def step_data(cable, y, rate, env, P, b0, b1) -> k.PlanarStep:
    """What the kernels know of one step (:class:`kernels2d.PlanarStep`), its one builder.

    Parameters
    ----------
    cable : PlanarCable
        Its ``extras()`` chooses the plain kernel (None) or the full one.
    y, rate : ndarray, shape (n_nodes, nv)
        The states at the start of the step and their time derivative.
    env : ndarray, shape (n_nodes, NENV)
        Nodal water velocity, acceleration and position (:func:`kanat.continuum.water.planar_water`).
    P : ndarray, shape (n_nodes - 1, n_par)
        The step's interval rows (:func:`step_rows`).
    b0, b1 : ndarray, shape (NBPAR,)
        The end conditions at ``s = 0`` and ``s = L``.
    """
    return k.PlanarStep(previous=y, rate=rate, water=env, intervals=P, start=b0, end=b1, extras=cable.extras())


def solve(cable, x0, known: k.PlanarStep):
    """Newton's method for the new state from ``x0``, the step's inputs ``known`` (:func:`step_data`);
    returns ``(x, iterations)`` or raises NewtonFailure."""
    x = x0.copy()
    n, nv = x.size, x.shape[1]
    width = k.bandwidth(nv)
    res = np.empty(n)
    band = np.empty((2 * width + 1, n))
    scale = np.tile(scales(cable, known.previous), len(x))
    previous = np.inf
    for iteration in range(1, MAX_ITERATIONS + 1):
        k.assemble(x, known, res, band)
        if not np.all(np.isfinite(res)):
            raise NewtonFailure("the residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // nv))
        dx = solve_band(width, band, -res)
        if dx is None:
            raise NewtonFailure("the Newton matrix is singular", int(np.argmax(np.abs(res)) // nv))
        x += dx.reshape(x.shape)
        size = np.max(np.abs(dx) / scale)
        if converged(size, previous):
            return x, iteration
        previous = size
    worst = int(np.argmax(np.abs(dx) / scale) // nv)
    raise NewtonFailure(f"Newton did not converge in {MAX_ITERATIONS} iterations", worst)


def solve_band(width: int, band: np.ndarray, rhs: np.ndarray) -> np.ndarray | None:
    """The solution of the banded system ``A x = rhs`` (LAPACK ``dgbsv``), or None when ``A`` is singular.

    What :func:`scipy.linalg.solve_banded` does for ``(width, width)`` diagonals and float64 arrays,
    without its per-call checks (about 17 us of the 60 us a call costs on a 400-unknown system):
    the same LAPACK call on the same arrays, so the same answer bit for bit.

    Parameters
    ----------
    width : int
        Sub- and super-diagonals, both (:func:`kernels2d.bandwidth`).
    band : ndarray, shape (2 width + 1, n)
        ``A`` in LAPACK's band storage (diagonal in row ``width``); not modified.
    rhs : ndarray, shape (n,)
        Overwritten.
    """
    # the top rows hold the LU's fill-in; in Fortran order, which f2py would otherwise copy it into
    work = np.zeros((3 * width + 1, band.shape[1]), order="F")
    work[width:] = band
    _, _, x, info = banded_lapack().dgbsv(width, width, work, rhs, overwrite_ab=True, overwrite_b=True)
    return x if info == 0 else None


def step_rows(rows: np.ndarray, coefficients, dt: float, inertia: float = 1.0) -> np.ndarray:
    """A copy of the interval rows with the scheme's entries set for a step of ``dt``."""
    am, ak, gamma = coefficients
    P = rows.copy()
    P[:, k.AM], P[:, k.AK], P[:, k.GAMMA], P[:, k.DT], P[:, k.PRED] = am, ak, gamma, dt, gamma * dt
    P[:, k.INERTIA] = inertia
    return P


def node_velocity(y: np.ndarray) -> np.ndarray:
    """Global velocities (x, z) (n, 2) of planar states ``y``."""
    c, s = np.cos(y[:, 3]), np.sin(y[:, 3])
    return np.column_stack([y[:, 1] * c - y[:, 2] * s, y[:, 1] * s + y[:, 2] * c])


def step(cable: PlanarCable, state: State, dt: float, coefficients, drive, own_rows=None) -> tuple[State, int]:
    """Advance ``state`` by ``dt`` with scheme ``coefficients = (am, ak, gamma)``.

    Parameters
    ----------
    drive : Drive
        Prescribed motion: ``drive.velocities(t)`` gives the end velocities ``(Vx, Vz)``
        at ``s = 0`` and ``s = L``, ``drive.origin(t)`` the position of the first end; an
        optional ``drive.payout(t)`` the winch's pay-out speed [m/s].
    own_rows : ndarray, optional
        ``cable.rows()``, when the caller holds it (a uniform cable builds it at every call);
        used when ``state.rows`` is None.

    Returns
    -------
    State, int
        The new state and the Newton iterations spent.
    """
    rows = (cable.rows() if own_rows is None else own_rows) if state.rows is None else state.rows
    winch = getattr(cable, "winch", None)
    during, after = winch.step_rows(rows, state.t, dt, coefficients[1]) if winch else (rows, rows)
    P = step_rows(during, coefficients, dt)
    v0, v1 = drive.velocities(state.t + dt)
    rho = P[0, k.RHO]
    env = planar_water(cable, state.xz, node_velocity(state.y), state.t, dt, coefficients)
    payout = winch.rate(state.t + dt) if winch else 0.0
    eta = elevation(cable.sea, (state.xz[-1, 0], 0.0), kinematics_time(state.t, dt, coefficients))
    if cable.sea is not None:
        float_elevations(cable.sea, P, np.column_stack([state.xz[:, 0], np.zeros(len(state.xz))]),
                         kinematics_time(state.t, dt, coefficients))
    if cable.water_surface:
        wet_step_rows(P, state.xz, cable.sea, kinematics_time(state.t, dt, coefficients))
    b0, b1 = cable.start.array(v0, rho, payout=payout), cable.end.array(v1, rho, eta=eta)
    x, iterations = solve(cable, state.y + dt * state.rate, step_data(cable, state.y, state.rate, env, P, b0, b1))
    gamma = coefficients[2]
    rate = (x - state.y) / (gamma * dt) - (1.0 - gamma) / gamma * state.rate
    xz = positions(cable, x, drive.origin(state.t + dt), after)
    if winch is None:
        return State(state.t + dt, x, rate, xz, state.rows), iterations
    rows, arrays, s = winch.regrid(after, {"y": x, "rate": rate, "xz": xz}, state.s)
    return State(state.t + dt, arrays["y"], arrays["rate"], arrays["xz"], rows, s), iterations


def steady(cable: PlanarCable, guess: np.ndarray, velocities, xz) -> np.ndarray:
    """The discrete steady state of the box equations (no inertia), from ``guess`` (n_nodes, nv).

    With a seabed, the contact forces depend on the node positions, which depend on every
    state up the cable: Newton then runs on the dense system (:mod:`kanat.continuum.steady`).
    """
    rows = cable.rows()
    P = step_rows(rows, (0.0, 0.0, 1.0), 1.0, inertia=0.0)
    P[:, k.PRED] = 0.0
    if cable.water_surface:
        wet_step_rows(P, xz, None, 0.0)                  # the mean surface, at the previous pass's nodes
    v0, v1 = velocities
    rho = P[0, k.RHO]
    b0, b1 = cable.start.array(v0, rho), cable.end.array(v1, rho)
    env = planar_water(cable, xz, np.zeros_like(xz), 0.0, 0.0, (0.0, 0.0, 1.0), waves=False)
    anchored = cable.end.kind == k.VELOCITY and not cable.end.moving
    if not near_seabed(cable, np.column_stack([xz[:, 0], np.zeros(len(xz)), xz[:, 1]])) and \
            cable.end.waterplane == 0.0 and not anchored and not has_floats(rows):
        x, _ = solve(cable, guess, step_data(cable, guess, np.zeros_like(guess), env, P, b0, b1))
        return x

    def layout(x):
        r = positions(cable, x, xz[0], rows)
        e = env.copy()
        e[:, [k.RX, k.RZ]] = r
        return e, r

    width = k.bandwidth(guess.shape[1])

    def residual(x, e):
        res, band = np.empty(x.size), np.empty((2 * width + 1, x.size))
        k.assemble(x, step_data(cable, x, np.zeros_like(x), e, P, b0, b1), res, band)
        return res, band
    target = np.asarray(cable.end.position, dtype=float) if anchored else None
    return steady_with_positions(guess, layout, (k.RX, k.RZ), residual, planar_position_jacobian(rows),
                                 scales(cable, guess), (3,), width, target, (0, 3))


SEABED_MARGIN = 0.01
"""A steady guess whose nodes all stay this fraction of the cable's length (at least 1 m) above the
seabed cannot touch it: its steady state needs no dense Newton."""


def near_seabed(cable, xyz) -> bool:
    """True when a node of ``xyz`` (n, 3) is within :data:`SEABED_MARGIN` of the seabed."""
    if cable.seabed is None:
        return False
    return bool(np.max(cable.seabed.penetration(xyz)) > -max(1.0, SEABED_MARGIN * cable.length))


def planar_position_jacobian(rows):
    """``D(x)`` (n, 2, n nv): the derivatives of the node positions (:func:`positions`) by the states."""
    def derivative(x):
        from kanat.continuum.model2d import interval_stretch

        n, nv = x.shape
        left, right = interval_stretch(x[:, 0], rows)
        flex_l, flex_r = interval_compliance(x[:, 0], rows)
        c, s = np.cos(x[:, 3]), np.sin(x[:, 3])
        half = 0.5 * rows[:, k.DS]
        a = np.zeros((n, 2, n * nv))
        i = np.arange(n - 1)
        for node, stretch, flex in ((i, left, flex_l), (i + 1, right, flex_r)):
            a[i + 1, 0, nv * node] = half * flex * c[node]
            a[i + 1, 1, nv * node] = half * flex * s[node]
            a[i + 1, 0, nv * node + 3] = -half * stretch * s[node]
            a[i + 1, 1, nv * node + 3] = half * stretch * c[node]
        return np.cumsum(a, axis=0)
    return derivative


def interval_compliance(tension, rows):
    """``de/dT`` of both nodes of every interval with that interval's law: (N,), (N,)."""
    left, right = np.empty(len(rows)), np.empty(len(rows))
    for value in sorted(set(rows[:, k.SECTION].tolist())):     # np.unique would import numpy.ma
        which = np.flatnonzero(rows[:, k.SECTION] == value)
        p = rows[which[0]]
        n = int(p[k.LAW])
        knots_t, knots_e = p[k.LAW + 1:k.LAW + 1 + n], p[k.LAW + 1 + n:k.LAW + 1 + 2 * n]
        slopes = np.diff(knots_e) / np.diff(knots_t)
        for out, nodes in ((left, which), (right, which + 1)):
            out[which] = slopes[np.clip(np.searchsorted(knots_t, tension[nodes]) - 1, 0, n - 2)]
    return left, right
