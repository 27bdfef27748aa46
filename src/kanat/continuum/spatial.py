"""The spatial continuum cable: its data, its state and one Newton step (SPEC §2.2–2.4).

Same structure as the planar model (:mod:`model2d`, :mod:`stepper`) with six unknowns per
node and the angles in a chart (:mod:`chart`) that the step re-charts when a tangent nears
its pole. Vectors are global (x, y, z) outside the kernels and chart coordinates inside.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import solve_banded

from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum.chart import choose_chart, frames, needs_rechart, rechart
from kanat.continuum.model2d import CableGrid, strain_of
from kanat.continuum.stepper import MAX_ITERATIONS, TOLERANCE, NewtonFailure

UP = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class SpatialEnd:
    """An end in 3-D: kind (kernels2d constants), body data (global force), tow point or anchor."""

    kind: int
    mass: float = 0.0
    net_buoyancy: float = 0.0
    drag_area: float = 0.0
    force: tuple = (0.0, 0.0, 0.0)
    moving: bool = False
    position: tuple = (0.0, 0.0, 0.0)

    def array(self, velocity, chart: np.ndarray, density: float) -> np.ndarray:
        """Kernel end vector (kernels3d.NBPAR3), vectors rotated into ``chart``."""
        v = np.asarray(velocity, dtype=float) @ chart
        f = np.asarray(self.force, dtype=float) @ chart
        return np.array([self.kind, *v, self.mass, self.net_buoyancy, 0.5 * density * self.drag_area, *f])


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


@dataclass(frozen=True)
class SpatialState:
    """The spatial cable at one instant: ``y`` (N+1, 6) and ``rate`` in ``chart``, ``xyz`` global."""

    t: float
    y: np.ndarray
    rate: np.ndarray
    xyz: np.ndarray
    chart: np.ndarray


def positions3(cable: SpatialCable, y: np.ndarray, chart: np.ndarray, origin) -> np.ndarray:
    """Global node positions (N+1, 3), trapezoidal in ``(1 + e) t`` from the first end."""
    t, _, _ = frames(y, chart)
    step = (1.0 + strain_of(y[:, 0], cable.params))[:, None] * t
    increments = 0.5 * cable.ds * (step[1:] + step[:-1])
    return np.vstack([np.zeros((1, 3)), np.cumsum(increments, axis=0)]) + np.asarray(origin, dtype=float)


def _solve(cable, x0, y, rate, current, up, p, b0, b1):
    x = x0.copy()
    n = x.size
    res, band = np.empty(n), np.empty((k3.LOWER + k3.UPPER + 1, n))
    tension = max(np.max(np.abs(y[:, 0])), abs(p[k.W0]) * cable.length, 1.0)
    speed = max(np.max(np.abs(y[:, 1:4])), 1.0)
    scale = np.tile([tension, speed, speed, speed, 1.0, 1.0], len(x))
    for iteration in range(1, MAX_ITERATIONS + 1):
        k3.assemble3(x, y, rate, current, up, p, b0, b1, res, band)
        if not np.all(np.isfinite(res)):
            raise NewtonFailure("the residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // 6))
        try:
            dx = solve_banded((k3.LOWER, k3.UPPER), band, -res, check_finite=False)
        except (np.linalg.LinAlgError, ValueError):
            raise NewtonFailure("the Newton matrix is singular", int(np.argmax(np.abs(res)) // 6)) from None
        x += dx.reshape(x.shape)
        if np.max(np.abs(dx) / scale) < TOLERANCE:
            return x, iteration
    raise NewtonFailure(f"Newton did not converge in {MAX_ITERATIONS} iterations",
                        int(np.argmax(np.abs(dx) / scale) // 6))


def _kernel_inputs(cable, state_xyz, chart, velocities):
    p_rho = cable.params[k.RHO]
    current = cable.current_at(state_xyz[:, 2]) @ chart
    v0, v1 = velocities
    return current, chart.T @ UP, cable.start.array(v0, chart, p_rho), cable.end.array(v1, chart, p_rho)


def step3(cable: SpatialCable, state: SpatialState, dt: float, coefficients, drive):
    """Advance ``state`` by ``dt`` (re-charting first when a tangent nears the pole)."""
    y, rate, chart = state.y, state.rate, state.chart
    if needs_rechart(y):
        new = choose_chart(frames(y, chart)[0])
        y, rate = rechart(y, rate, chart, new)
        chart = new
    am, ak, gamma = coefficients
    p = cable.params.copy()
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = am, ak, gamma, dt
    current, up, b0, b1 = _kernel_inputs(cable, state.xyz, chart, drive.velocities(state.t + dt))
    x, iterations = _solve(cable, y + dt * rate, y, rate, current, up, p, b0, b1)
    new_rate = (x - y) / (gamma * dt) - (1.0 - gamma) / gamma * rate
    xyz = positions3(cable, x, chart, drive.origin(state.t + dt))
    return SpatialState(state.t + dt, x, new_rate, xyz, chart), iterations


def steady3(cable: SpatialCable, guess: np.ndarray, chart: np.ndarray, velocities, xyz) -> np.ndarray:
    """The discrete steady state (no inertia) in ``chart``, from ``guess`` (N+1, 6)."""
    p = cable.params.copy()
    p[[k.AM, k.AK, k.GAMMA, k.DT, k.INERTIA]] = 0.0, 0.0, 1.0, 1.0, 0.0
    current, up, b0, b1 = _kernel_inputs(cable, xyz, chart, velocities)
    x, _ = _solve(cable, guess, guess, np.zeros_like(guess), current, up, p, b0, b1)
    return x
