"""What the kernels need of the water at every node for one step: its velocity, its acceleration
and each node's predicted position (theory/continuum.md §1, theory/moorings.md; :mod:`kanat.continuum.kernels2d`).

The water velocity is the current (a depth profile) plus the waves' orbital velocity (Airy or
JONSWAP, :mod:`kanat.physics.waves`), its acceleration the waves' (the current is steady, or ramped
up by ``environment.current.ramp`` without the ramp's own acceleration). Both
are taken at the node positions of the previous step (explicit in space) and at the time of the
scheme's ``[ak]`` level, ``t_n + (1 - a_k) dt`` (implicit in time). The position predictor
``R = r^n + dt ((1 - ak)(1 - gamma) - gamma ak) V^n`` completes ``r^[ak] = R + gamma dt V^[ak]``
inside the kernels (seabed contact, a surface buoy's immersion).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k


def predictor_weight(coefficients, dt: float) -> float:
    """``dt ((1 - ak)(1 - gamma) - gamma ak)``: the old velocity's weight in ``R``."""
    am, ak, gamma = coefficients
    return dt * ((1.0 - ak) * (1.0 - gamma) - gamma * ak)


def kinematics_time(t: float, dt: float, coefficients) -> float:
    """The time of the ``[ak]`` level of a step from ``t`` [s]."""
    return t + (1.0 - coefficients[1]) * dt


def planar_water(cable, xz: np.ndarray, velocity: np.ndarray, t: float, dt: float, coefficients,
                 waves: bool = True) -> np.ndarray:
    """Nodal data (n, NENV) of a planar cable for a step of ``dt`` from ``t``.

    Parameters
    ----------
    cable : PlanarCable
    xz : ndarray, shape (n, 2)
        Node positions at ``t`` [m].
    velocity : ndarray, shape (n, 2)
        Node velocities (x, z) at ``t`` [m/s].
    waves : bool
        False for the steady state (current only).
    """
    n = len(xz)
    env = np.zeros((n, k.NENV))
    tk = kinematics_time(t, dt, coefficients)
    env[:, [k.UX, k.UZ]] = cable.current_at(xz[:, 1], tk)
    if waves and cable.sea is not None:
        points = np.column_stack([xz[:, 0], np.zeros(n), xz[:, 1]])
        env[:, [k.UX, k.UZ]] += cable.sea.velocity(points, tk)[:, [0, 2]]
        env[:, [k.AX, k.AZ]] = cable.sea.acceleration(points, tk)[:, [0, 2]]
    env[:, [k.RX, k.RZ]] = xz + predictor_weight(coefficients, dt) * velocity
    return env


def elevation(sea, point, t: float) -> float:
    """Wave elevation above the point (x, y) at ``t`` [m] (0 without waves)."""
    if sea is None:
        return 0.0
    return float(sea.elevation(np.array([point[0]]), np.array([point[1]]), t)[0])


def float_elevations(sea, P: np.ndarray, points: np.ndarray, t: float) -> None:
    """Write into ``P[j, JB_ETA]`` the wave elevation over every spherical float's junction ``j`` at ``t``
    (0 without waves): its immersion is measured from there (:mod:`kanat.physics.immersion`).

    Parameters
    ----------
    P : ndarray, shape (N, n_par)
        The step's interval rows; modified in place.
    points : ndarray, shape (N + 1, 2)
        Node positions (x, y) at the step's start [m].
    """
    floats = np.flatnonzero((P[:, k.KIND] == k.JUNCTION) & (P[:, k.JB_DIAMETER] > 0.0))
    if sea is None or not len(floats):
        return
    P[floats, k.JB_ETA] = sea.elevation(points[floats, 0], points[floats, 1], t)


def has_floats(rows: np.ndarray) -> bool:
    """True when an interval row is a spherical float's junction (its lift depends on its height)."""
    return bool(np.any((rows[:, k.KIND] == k.JUNCTION) & (rows[:, k.JB_DIAMETER] > 0.0)))
