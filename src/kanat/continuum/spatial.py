"""The spatial continuum cable: its data, its state and one Newton step (theory/continuum.md §2–3, theory/time-schemes.md §1).

Same structure as the planar model (:mod:`model2d`, :mod:`stepper`) with six unknowns per
node (ten with bending stiffness: :mod:`bending3d`) and the angles in a chart (:mod:`chart`)
that the step re-charts when a tangent nears its pole. Vectors are global (x, y, z) outside
the kernels and chart coordinates inside.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum.chart import choose_chart, frames, needs_rechart, rechart
from kanat.continuum.grid import Grid, SeabedContact
from kanat.continuum.model2d import CableGrid, interval_stretch, strain_of
from kanat.continuum.stepper import MAX_ITERATIONS, NewtonFailure, converged, near_seabed, solve_band, step_rows
from kanat.continuum.water import elevation, float_elevations, has_floats, kinematics_time, predictor_weight
from kanat.continuum.wetted import wet_step_rows

UP = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class SpatialEnd:
    """An end in 3-D: kind (kernels2d constants), body data (global force), tow point or anchor,
    and (as :class:`kanat.continuum.model2d.EndCondition`) wave mass and a surface buoy."""

    kind: int
    mass: float = 0.0
    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple = (0.0, 0.0, 0.0)
    moving: bool = False
    position: tuple = (0.0, 0.0, 0.0)
    wave_mass: float = 0.0
    waterplane: float = 0.0
    height: float = 0.0
    clamped: bool = False
    tangent: tuple = (1.0, 0.0, 0.0)

    def array(self, velocity, chart: np.ndarray, density: float, eta: float = 0.0, payout: float = 0.0) -> np.ndarray:
        """Kernel end vector (bending3d.NBPAR3_BENDING: kernels3d.NBPAR3 and the clamp), vectors rotated
        into ``chart``. ``clamped`` (with bending stiffness) holds the cable's global unit ``tangent``
        there instead of leaving the end moment-free: its angles in ``chart`` (no case key clamps one)."""
        v = np.asarray(velocity, dtype=float) @ chart
        f = np.asarray(self.force, dtype=float) @ chart
        local = (np.asarray([self.tangent], dtype=float) @ chart)[0]   # chart.angles() of one tangent: nothing
        phi = np.arcsin(min(max(local[2], -1.0), 1.0))                  # to unwrap
        theta = np.arctan2(local[1], local[0])
        return np.array([self.kind, *v, self.mass, self.net_buoyancy, 0.5 * density * self.drag_area, *f,
                         self.wave_mass, self.waterplane, self.height, eta, payout, float(self.clamped), phi,
                         theta])


@dataclass(frozen=True)
class SpatialCable(CableGrid):
    """A spatial cable ready for the kernels (see :class:`kanat.continuum.model2d.PlanarCable`)."""

    name: str
    length: float
    segments: int
    params: np.ndarray
    start: SpatialEnd
    end: SpatialEnd
    current_z: np.ndarray = field(default_factory=lambda: np.zeros(1))
    current_rows: np.ndarray = field(default_factory=lambda: np.zeros((1, 3)))
    grid: Grid | None = None
    sea: object = None
    seabed: SeabedContact | None = None
    winch: object = None
    current_ramp: float = 0.0
    water_surface: bool = False

    @property
    def nv(self) -> int:
        """Unknowns per node: 6 (10 with bending stiffness, :mod:`kanat.continuum.bending3d`)."""
        return 10 if self.grid is not None and self.grid.bending else 6


@dataclass(frozen=True)
class SpatialState:
    """The spatial cable at one instant: ``y`` (N+1, nv) and ``rate`` in ``chart``, ``xyz`` global;
    ``rows`` the interval rows and ``s`` the nodes' material arclength when they change in time (a winch)."""

    t: float
    y: np.ndarray
    rate: np.ndarray
    xyz: np.ndarray
    chart: np.ndarray
    rows: np.ndarray | None = None
    s: np.ndarray | None = None
    frames: tuple | None = field(default=None, compare=False, repr=False)
    """``frames(y, chart)`` when the step that made the state worked them out (the next step reads them)."""


def positions3(cable: SpatialCable, y: np.ndarray, chart: np.ndarray, origin, rows=None, tangents=None) -> np.ndarray:
    """Global node positions (n_nodes, 3), trapezoidal in ``(1 + e) t`` from the first end, each
    interval with its own length and law; ``tangents``: ``frames(y, chart)[0]`` when known."""
    rows = cable.rows() if rows is None else rows
    t = frames(y, chart)[0] if tangents is None else tangents
    left, right = node_stretch(y[:, 0], rows)
    increments = 0.5 * rows[:, k.DS, None] * (left[:, None] * t[:-1] + right[:, None] * t[1:])
    xyz = np.empty((len(y), 3))
    xyz[0] = 0.0
    np.cumsum(increments, axis=0, out=xyz[1:])
    xyz += np.asarray(origin, dtype=float)
    return xyz


def node_stretch(tension: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`kanat.continuum.model2d.interval_stretch` (``1 + e`` of both nodes of every interval,
    shapes (N,), (N,)), each node's strain worked out once when all the intervals share one law."""
    sections = rows[:, k.SECTION]
    if not (sections == sections[0]).all():
        return interval_stretch(tension, rows)
    stretch = 1.0 + strain_of(tension, rows[0])
    return stretch[:-1], stretch[1:]


def spatial_scales(cable, y) -> np.ndarray:
    """Increment scales (nv,): tension, three speeds, two angles (and two shears, two moments with
    bending stiffness)."""
    tension = max(np.max(np.abs(y[:, 0])), abs(cable.params[k.W0]) * cable.length, 1.0)
    speed = max(np.max(np.abs(y[:, 1:4])), 1.0)
    if y.shape[1] == k3.NV_BENDING:
        moment = tension * cable.length
        return np.array([tension, speed, speed, speed, 1.0, 1.0, tension, tension, moment, moment])
    return np.array([tension, speed, speed, speed, 1.0, 1.0])


def kernel_of(nv: int):
    """``(assemble, bandwidth)`` of the kernels for ``nv`` unknowns per node: :func:`kernels3d.assemble3`
    (6), or with bending stiffness :func:`bending3d.assemble3_bending` (10), compiled only when used."""
    if nv == k3.NV_BENDING:
        return k3.assemble3_bending, k3.WIDTH_BENDING
    return k3.assemble3, k3.UPPER


def step_data(cable, y, rate, env, up, P, b0, b1) -> k3.SpatialStep:
    """What the kernels know of one step (:class:`kernels3d.SpatialStep`), its one builder.

    Parameters
    ----------
    cable : SpatialCable
        Its ``extras()`` chooses the plain kernel (None) or the full one.
    y, rate : ndarray, shape (n_nodes, nv)
        The states at the start of the step and their time derivative.
    env : ndarray, shape (n_nodes, NENV3)
        Nodal water and position data in chart coordinates (:func:`spatial_water`).
    up : ndarray, shape (3,)
        The chart components of the vertical.
    P : ndarray, shape (n_nodes - 1, n_par)
        The step's interval rows.
    b0, b1 : ndarray
        The end conditions (NBPAR3, or NBPAR3_BENDING with bending stiffness).
    """
    return k3.SpatialStep(previous=y, rate=rate, water=env, vertical=up, intervals=P, start=b0, end=b1,
                          extras=cable.extras())


def _solve(cable, x0, known: k3.SpatialStep):
    """Newton's method for the new state from ``x0``, the step's inputs ``known`` (:func:`step_data`)."""
    x = x0.copy()
    n, nv = x.size, x.shape[1]
    assemble, width = kernel_of(nv)
    res, band = np.empty(n), np.empty((2 * width + 1, n))
    scale = spatial_scales(cable, known.previous)        # (nv,): broadcast over the nodes
    previous = np.inf
    for iteration in range(1, MAX_ITERATIONS + 1):
        assemble(x, known, res, band)
        if not np.isfinite(res).all():
            raise NewtonFailure("the residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // nv))
        dx = solve_band(width, band, -res)
        if dx is None:
            raise NewtonFailure("the Newton matrix is singular", int(np.argmax(np.abs(res)) // nv))
        step = dx.reshape(x.shape)
        x += step
        size = (np.abs(step) / scale).max()
        if converged(size, previous):
            return x, iteration
        previous = size
    raise NewtonFailure(f"Newton did not converge in {MAX_ITERATIONS} iterations",
                        int(np.argmax(np.abs(dx.reshape(x.shape)) / scale) // nv))


def velocities3(y: np.ndarray, chart: np.ndarray) -> np.ndarray:
    """Global velocities (n, 3) of states ``y`` in ``chart``."""
    t, n, b = frames(y, chart)
    return y[:, 1:2] * t + y[:, 2:3] * n + y[:, 3:4] * b


def spatial_water(cable: SpatialCable, xyz, velocity, tangents, t: float, dt: float, coefficients, chart,
                  waves: bool = True) -> np.ndarray:
    """Nodal data (n, NENV3) in ``chart`` coordinates (:mod:`kanat.continuum.water`; global inputs)."""
    n = len(xyz)
    env = np.zeros((n, k3.NENV3))
    tk = kinematics_time(t, dt, coefficients)
    water = cable.current_at(xyz[:, 2], tk)
    if waves and cable.sea is not None:
        water = water + cable.sea.velocity(xyz, tk)
        env[:, k3.AX3:k3.AX3 + 3] = cable.sea.acceleration(xyz, tk) @ chart
    env[:, k3.UX3:k3.UX3 + 3] = water @ chart
    env[:, k3.RX3:k3.RX3 + 3] = (xyz + predictor_weight(coefficients, dt) * velocity) @ chart
    if cable.seabed is not None:
        normal = cable.seabed.normal
        along = tangents - np.outer(tangents @ normal, normal)
        size = np.linalg.norm(along, axis=1)
        flat = size < 1e-9
        along[flat] = np.cross(normal, [0.0, 1.0, 0.0])
        size[flat] = np.linalg.norm(along[flat], axis=1) if np.any(flat) else size[flat]
        env[:, k3.DX3:k3.DX3 + 3] = (along / size[:, None]) @ chart
    return env


def chart_rows(rows: np.ndarray, cable: SpatialCable, chart: np.ndarray) -> np.ndarray:
    """``rows`` with the seabed's normal in ``chart`` coordinates (in place) -> rows."""
    if cable.seabed is not None:
        rows[:, [k.SB_N0, k.SB_N1, k.SB_N2]] = chart.T @ cable.seabed.normal
    return rows


def step3(cable: SpatialCable, state: SpatialState, dt: float, coefficients, drive, own_rows=None):
    """Advance ``state`` by ``dt`` (re-charting first when a tangent nears the pole); ``own_rows`` is
    ``cable.rows()`` when the caller holds it (used when ``state.rows`` is None)."""
    y, rate, chart = state.y, state.rate, state.chart
    tangent, normal, binormal = frames(y, chart) if state.frames is None else state.frames
    if needs_rechart(y):
        new = choose_chart(tangent)
        y, rate = rechart(y, rate, chart, new)
        chart = new
        tangent, normal, binormal = frames(y, chart)
    rows = (cable.rows() if own_rows is None else own_rows) if state.rows is None else state.rows
    winch = cable.winch
    during, after = winch.step_rows(rows, state.t, dt, coefficients[1]) if winch else (rows, rows)
    P = chart_rows(step_rows(during, coefficients, dt), cable, chart)
    rho = P[0, k.RHO]
    v0, v1 = drive.velocities(state.t + dt)
    velocity = y[:, 1:2] * tangent + y[:, 2:3] * normal + y[:, 3:4] * binormal      # velocities3(y, chart)
    env = spatial_water(cable, state.xyz, velocity, tangent, state.t, dt, coefficients, chart)
    payout = winch.rate(state.t + dt) if winch else 0.0
    eta = elevation(cable.sea, state.xyz[-1, :2], kinematics_time(state.t, dt, coefficients))
    float_elevations(cable.sea, P, state.xyz[:, :2], kinematics_time(state.t, dt, coefficients))
    if cable.water_surface:
        wet_step_rows(P, state.xyz, cable.sea, kinematics_time(state.t, dt, coefficients))
    b0 = cable.start.array(v0, chart, rho, payout=payout)
    b1 = cable.end.array(v1, chart, rho, eta=eta)
    x, iterations = _solve(cable, y + dt * rate, step_data(cable, y, rate, env, chart.T @ UP, P, b0, b1))
    gamma = coefficients[2]
    new_rate = (x - y) / (gamma * dt) - (1.0 - gamma) / gamma * rate
    new_frames = frames(x, chart)
    xyz = positions3(cable, x, chart, drive.origin(state.t + dt), after, new_frames[0])
    if winch is None:
        return SpatialState(state.t + dt, x, new_rate, xyz, chart, state.rows, frames=new_frames), iterations
    rows, arrays, s = winch.regrid(after, {"y": x, "rate": new_rate, "xyz": xyz}, state.s)
    return SpatialState(state.t + dt, arrays["y"], arrays["rate"], arrays["xyz"], chart, rows, s), iterations


def steady3(cable: SpatialCable, guess: np.ndarray, chart: np.ndarray, velocities, xyz) -> np.ndarray:
    """The discrete steady state (no inertia) in ``chart``, from ``guess`` (N+1, nv); with a seabed or
    a surface buoy, Newton on the dense system (:mod:`kanat.continuum.steady`)."""
    rows = cable.rows()
    P = chart_rows(step_rows(rows, (0.0, 0.0, 1.0), 1.0, inertia=0.0), cable, chart)
    P[:, k.PRED] = 0.0
    if cable.water_surface:
        wet_step_rows(P, xyz, None, 0.0)                 # the mean surface, at the previous pass's nodes
    rho = P[0, k.RHO]
    v0, v1 = velocities
    b0, b1 = cable.start.array(v0, chart, rho), cable.end.array(v1, chart, rho)
    up = chart.T @ UP
    env = spatial_water(cable, xyz, np.zeros_like(xyz), frames(guess, chart)[0], 0.0, 0.0, (0.0, 0.0, 1.0), chart,
                        waves=False)
    anchored = cable.end.kind == k.VELOCITY and not cable.end.moving
    if not near_seabed(cable, xyz) and cable.end.waterplane == 0.0 and not anchored and not has_floats(rows):
        x, _ = _solve(cable, guess, step_data(cable, guess, np.zeros_like(guess), env, up, P, b0, b1))
        return x
    from kanat.continuum.steady import steady_with_positions

    def layout(x):
        r = positions3(cable, x, chart, xyz[0], rows)
        e = env.copy()
        e[:, k3.RX3:k3.RX3 + 3] = r @ chart
        return e, r @ chart

    assemble, width = kernel_of(guess.shape[1])

    def residual(x, e):
        res, band = np.empty(x.size), np.empty((2 * width + 1, x.size))
        assemble(x, step_data(cable, x, np.zeros_like(x), e, up, P, b0, b1), res, band)
        return res, band

    def derivative(x):
        n, nv = x.shape
        left, right = interval_stretch(x[:, 0], rows)
        from kanat.continuum.stepper import interval_compliance

        flex_l, flex_r = interval_compliance(x[:, 0], rows)
        t, nn, b = frames(x, chart)
        t, nn, b = t @ chart, nn @ chart, b @ chart            # chart coordinates
        cp = np.cos(x[:, 4])
        half = 0.5 * rows[:, k.DS]
        a = np.zeros((n, 3, n * nv))
        i = np.arange(n - 1)
        for node, stretch, flex in ((i, left, flex_l), (i + 1, right, flex_r)):
            for c in range(3):
                a[i + 1, c, nv * node] = half * flex * t[node, c]
                a[i + 1, c, nv * node + 4] = half * stretch * nn[node, c]
                a[i + 1, c, nv * node + 5] = -half * stretch * cp[node] * b[node, c]
        return np.cumsum(a, axis=0)
    target = np.asarray(cable.end.position, dtype=float) @ chart if anchored else None
    return steady_with_positions(guess, layout, tuple(range(k3.RX3, k3.RX3 + 3)), residual, derivative,
                                 spatial_scales(cable, guess), (4, 5), width, target, (0, 4, 5))
