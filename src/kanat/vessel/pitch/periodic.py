"""Direct time integration of the pitch oscillator to its periodic steady state.

The state ``x = (phi, phi')`` obeys ``I_y phi'' = M_m sin(omega t + pi) + f - c phi' - k phi``
(theory/vessel.md §2). The periodic orbit is found by shooting on the initial state over one
period: ``F(x0) = x(T; x0) - x0 = 0`` by Newton's method with a finite-difference
Jacobian. For the open-loop laws ``F`` is affine, so one Newton step solves it up to the
integration error, damped or not (the undamped case needs ``omega_0 != n omega``, which
:meth:`PitchSystem.check_resonance` guards). For the feedback law ``F`` is piecewise
affine and Newton takes a few steps. :func:`transient` instead integrates from rest for
many periods, the physical way for damped systems, and serves as a cross-check.

Each smooth piece of the stabilizer law is integrated on its own (DOP853, ``rtol``
1e-11), so the jumps of the rectangular and shaped laws are met exactly.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from kanat.errors import SolverError

from .laws import Piece
from .system import PitchSystem

RTOL = 1e-11                # relative tolerance of DOP853
ATOL_FRACTION = 1e-13       # absolute tolerance, as a fraction of the angle scale M_m / k
NEWTON_TOL = 1e-10          # residual |x(T) - x0|, as a fraction of the state scale
NEWTON_MAX_ITERATIONS = 30
FD_STEP = 1e-4              # finite-difference step, as a fraction of the state scale


@dataclass(frozen=True)
class PeriodSolution:
    """One period of the time-integrated pitch.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Times within the period [s].
    pitch, rate : ndarray, shape (n,)
        ``phi`` [rad] and ``phi'`` [rad/s].
    moment : ndarray, shape (n,)
        Stabilizer moment [N m].
    initial_state : ndarray, shape (2,)
        ``(phi, phi')`` at ``t = 0``.
    final_state : ndarray, shape (2,)
        ``(phi, phi')`` at ``t = T``.
    iterations : int
        Newton iterations of the shooting (0 for a transient run).
    """

    time: np.ndarray
    pitch: np.ndarray
    rate: np.ndarray
    moment: np.ndarray
    initial_state: np.ndarray
    final_state: np.ndarray
    iterations: int = 0


def _state_scale(system: PitchSystem) -> np.ndarray:
    angle = system.angle_scale
    return np.array([angle, angle * max(system.natural_frequency, system.wave_frequency)])


def _rhs(system: PitchSystem, piece: Piece):
    inertia, damping, restoring = system.inertia, system.damping, system.restoring
    amplitude, omega = system.wave_moment_amplitude, system.wave_frequency

    def rhs(t, y):
        phi, rate = y
        wave = -amplitude * math.sin(omega * t)
        f = float(piece.moment(t, phi, rate))
        return [rate, (wave + f - damping * rate - restoring * phi) / inertia]
    return rhs


def integrate_period(system: PitchSystem, pieces: list[Piece], state0, times=None) -> PeriodSolution:
    """Integrate one period from ``state0`` at ``t = 0``, piece by piece.

    Parameters
    ----------
    system : PitchSystem
    pieces : list of Piece
        The stabilizer law's smooth pieces covering ``[0, T]`` in order.
    state0 : array_like, shape (2,)
        ``(phi, phi')`` at ``t = 0`` [rad, rad/s].
    times : ndarray, shape (n,), optional
        Output times in ``[0, T]`` [s]; none by default.
    """
    times = np.empty(0) if times is None else np.asarray(times, dtype=float)
    atol = ATOL_FRACTION * _state_scale(system)
    y = np.asarray(state0, dtype=float)
    pitch, rate, moment = (np.full(times.shape, np.nan) for _ in range(3))
    for i, piece in enumerate(pieces):
        last = i == len(pieces) - 1
        inside = (times >= piece.start) & ((times <= piece.end) if last else (times < piece.end))
        t_out = times[inside]
        t_eval = np.append(t_out, piece.end) if not t_out.size or t_out[-1] < piece.end else t_out
        sol = solve_ivp(_rhs(system, piece), (piece.start, piece.end), y, method="DOP853",
                        rtol=RTOL, atol=atol, t_eval=t_eval)
        if sol.status != 0:
            raise SolverError(f"time integration of the pitch failed on [{piece.start:.4g}, "
                              f"{piece.end:.4g}] s: {sol.message}; check the case's magnitudes")
        if t_out.size:
            phi, phidot = sol.y[:, :t_out.size]
            pitch[inside], rate[inside] = phi, phidot
            moment[inside] = piece.moment(t_out, phi, phidot)
        y = sol.y[:, -1].copy()
    return PeriodSolution(times, pitch, rate, moment, np.asarray(state0, dtype=float), y)


def periodic_orbit(system: PitchSystem, pieces: list[Piece], times=None, guess=None) -> PeriodSolution:
    """The T-periodic steady state by shooting on the initial state (Newton, FD Jacobian).

    Parameters
    ----------
    system : PitchSystem
    pieces : list of Piece
        The stabilizer law over one period.
    times : ndarray, shape (n,), optional
        Output times in ``[0, T]`` [s].
    guess : array_like, shape (2,), optional
        Initial ``(phi, phi')``; zero by default.

    Raises
    ------
    SolverError
        When Newton does not converge, with what to try.
    """
    scale = _state_scale(system)
    x = np.zeros(2) if guess is None else np.asarray(guess, dtype=float)

    def residual(x0):
        return integrate_period(system, pieces, x0).final_state - x0
    r = residual(x)
    for iteration in range(1, NEWTON_MAX_ITERATIONS + 1):
        jacobian = np.empty((2, 2))
        for j in range(2):
            step = np.zeros(2)
            step[j] = FD_STEP * scale[j]
            jacobian[:, j] = (residual(x + step) - r) / step[j]
        x = x - np.linalg.solve(jacobian, r)
        r = residual(x)
        if np.max(np.abs(r) / scale) < NEWTON_TOL:
            return _with_iterations(integrate_period(system, pieces, x, times), iteration)
    raise SolverError(
        f"periodic shooting for the pitch did not converge in {NEWTON_MAX_ITERATIONS} Newton "
        f"iterations (residual {np.max(np.abs(r) / scale):.3g} of the state scale); give "
        "damping_ratio > 0, lower the feedback gain, or use kanat.vessel.pitch.periodic.transient")


def _with_iterations(sol: PeriodSolution, iterations: int) -> PeriodSolution:
    return PeriodSolution(sol.time, sol.pitch, sol.rate, sol.moment, sol.initial_state,
                          sol.final_state, iterations)


def transient(system: PitchSystem, pieces: list[Piece], periods: int, times=None,
              state0=(0.0, 0.0)) -> PeriodSolution:
    """Integrate ``periods`` periods from ``state0`` and return the last one.

    With damping ``zeta`` the start-up transient decays like ``exp(-zeta omega_0 t)``;
    it is gone to ``1e-6`` after ``14 / (zeta omega_0)`` seconds. Undamped open-loop
    systems never forget it: use :func:`periodic_orbit`.
    """
    state = np.asarray(state0, dtype=float)
    for _ in range(periods - 1):
        state = integrate_period(system, pieces, state).final_state
    return integrate_period(system, pieces, state, times)
