"""One time step of the planar continuum model: Newton's method on the banded system (SPEC §2.4).

Newton starts from the previous state advanced with its rate, tests convergence on
increments scaled by the problem's own sizes (tension, speed, 1 rad), and stops after
``MAX_ITERATIONS``. A step whose Newton iteration fails is cut in halves, up to
``MAX_CUTS`` levels, before the run is stopped with a message saying what to try.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_banded

from kanat.continuum import kernels2d as k
from kanat.continuum.model2d import PlanarCable, positions
from kanat.errors import SolverError

MAX_ITERATIONS = 20
TOLERANCE = 1e-10        # on increments scaled by (tension scale, speed scale, speed scale, 1 rad)
MAX_CUTS = 4             # a failed step is retried as 2, 4, 8, 16 substeps


@dataclass(frozen=True)
class State:
    """The planar cable at one instant.

    Attributes
    ----------
    t : float
        Time [s].
    y : ndarray, shape (N+1, 4)
        ``(T, u, v, phi)`` at the nodes.
    rate : ndarray, shape (N+1, 4)
        Time derivative of ``y`` (the generalized-α scheme carries it).
    xz : ndarray, shape (N+1, 2)
        Node positions [m].
    """

    t: float
    y: np.ndarray
    rate: np.ndarray
    xz: np.ndarray


class NewtonFailure(SolverError):
    """Newton did not converge; ``node`` is where the largest residual sits."""

    def __init__(self, message: str, node: int):
        super().__init__(message)
        self.node = node


def scales(cable: PlanarCable, y: np.ndarray) -> np.ndarray:
    """Increment scales (4,): tension, speed, speed, angle."""
    p = cable.params
    tension = max(np.max(np.abs(y[:, 0])), abs(p[k.W0]) * cable.length, 1.0)
    speed = max(np.max(np.abs(y[:, 1:3])), 1.0)
    return np.array([tension, speed, speed, 1.0])


def solve(cable: PlanarCable, x0, y, rate, current, p, b0, b1):
    """Newton's method for the new state; returns ``(x, iterations)`` or raises NewtonFailure."""
    x = x0.copy()
    n = x.size
    res = np.empty(n)
    band = np.empty((k.LOWER + k.UPPER + 1, n))
    scale = np.tile(scales(cable, y), len(x))
    for iteration in range(1, MAX_ITERATIONS + 1):
        k.assemble(x, y, rate, current, p, b0, b1, res, band)
        if not np.all(np.isfinite(res)):
            raise NewtonFailure("the residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // 4))
        try:
            dx = solve_banded((k.LOWER, k.UPPER), band, -res, check_finite=False)
        except (np.linalg.LinAlgError, ValueError):
            raise NewtonFailure("the Newton matrix is singular", int(np.argmax(np.abs(res)) // 4)) from None
        x += dx.reshape(x.shape)
        if np.max(np.abs(dx) / scale) < TOLERANCE:
            return x, iteration
    worst = int(np.argmax(np.abs(dx) / scale) // 4)
    raise NewtonFailure(f"Newton did not converge in {MAX_ITERATIONS} iterations", worst)


def step(cable: PlanarCable, state: State, dt: float, coefficients, drive) -> tuple[State, int]:
    """Advance ``state`` by ``dt`` with scheme ``coefficients = (am, ak, gamma)``.

    Parameters
    ----------
    drive : Drive
        Prescribed motion: ``drive.velocities(t)`` gives the end velocities ``(Vx, Vz)``
        at ``s = 0`` and ``s = L``, ``drive.origin(t)`` the position of the first end.

    Returns
    -------
    State, int
        The new state and the Newton iterations spent.
    """
    am, ak, gamma = coefficients
    p = cable.params.copy()
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = am, ak, gamma, dt
    v0, v1 = drive.velocities(state.t + dt)
    rho = p[k.RHO]
    b0, b1 = cable.start.array(v0, rho), cable.end.array(v1, rho)
    current = cable.current_at(state.xz[:, 1])
    x, iterations = solve(cable, state.y + dt * state.rate, state.y, state.rate, current, p, b0, b1)
    rate = (x - state.y) / (gamma * dt) - (1.0 - gamma) / gamma * state.rate
    return State(state.t + dt, x, rate, positions(cable, x, drive.origin(state.t + dt))), iterations


def steady(cable: PlanarCable, guess: np.ndarray, velocities, xz) -> np.ndarray:
    """The discrete steady state of the box equations (no inertia), from ``guess`` (N+1, 4)."""
    p = cable.params.copy()
    p[[k.AM, k.AK, k.GAMMA, k.DT, k.INERTIA]] = 0.0, 0.0, 1.0, 1.0, 0.0
    v0, v1 = velocities
    rho = p[k.RHO]
    x, _ = solve(cable, guess, guess, np.zeros_like(guess), cable.current_at(xz[:, 1]), p,
                 cable.start.array(v0, rho), cable.end.array(v1, rho))
    return x
