"""The vessel's prescribed motion (:mod:`kanat.physics.motion`) at many times at once.

Same conventions and equations as :func:`kanat.physics.motion.motion_at` and
:func:`kanat.physics.motion.rigid_point_motion` (their scalar twins, which the tests compare),
vectorized over the times, for the lumped model's samples of every step:

* ``q(t)``, ``q_dot(t)`` (k, 6) of harmonics or a table, ramped (``r q``, ``r q_dot + r' q``);
* points ``r`` (p, 3) fixed to the vessel move by ``(surge, sway, heave) + R r - r`` with
  velocity ``v + w x (R r)``, ``R = Rz(yaw) Ry(pitch) Rx(roll)``, ``w`` from the Euler rates.
"""
from __future__ import annotations

import numpy as np

from kanat.physics.motion import Harmonics, MotionTable
from kanat.physics.ramp import ramp_series


def motion_series(motion, times) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and velocity (k, 6) at ``times`` (k,) of :func:`compile_motion`'s result."""
    t = np.asarray(times, dtype=float)
    if motion is None:
        return np.zeros((len(t), 6)), np.zeros((len(t), 6))
    q, v = _unramped(motion, t)
    if motion.ramp <= 0.0:                 # r = 1, r' = 0: r q is q and r q_dot + r' q is q_dot
        return q, v
    r, rate = ramp_series(t, motion.ramp)
    return r[:, None] * q, r[:, None] * v + rate[:, None] * q


def _unramped(motion, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    q, v = np.zeros((len(t), 6)), np.zeros((len(t), 6))
    if isinstance(motion, MotionTable):
        time, values = motion.time, motion.values
        i = np.clip(np.searchsorted(time, t, side="right") - 1, 0, len(time) - 2)
        slope = (values[i + 1] - values[i]) / (time[i + 1] - time[i])[:, None]
        q = values[i] + slope * (t - time[i])[:, None]
        before, after = t <= time[0], t >= time[-1]
        q[before], q[after] = values[0], values[-1]
        v = np.where((before | after)[:, None], 0.0, slope)
        return q, v
    assert isinstance(motion, Harmonics)
    arg = np.outer(t, motion.omega) + motion.phase
    for h, dof in enumerate(motion.dof):
        q[:, dof] += motion.amplitude[h] * np.sin(arg[:, h])
        v[:, dof] += motion.amplitude[h] * motion.omega[h] * np.cos(arg[:, h])
    return q, v


def rotations(angles) -> np.ndarray:
    """``Rz(yaw) Ry(pitch) Rx(roll)`` (k, 3, 3) of angles (k, 3)."""
    cr, sr = np.cos(angles[:, 0]), np.sin(angles[:, 0])
    cp, sp = np.cos(angles[:, 1]), np.sin(angles[:, 1])
    cy, sy = np.cos(angles[:, 2]), np.sin(angles[:, 2])
    return np.stack([np.stack([cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr], -1),
                     np.stack([sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr], -1),
                     np.stack([-sp, cp * sr, cp * cr], -1)], -2)


def point_series(offsets, q, v) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and velocity (k, p, 3) of points ``offsets`` (p, 3) fixed to the vessel, in the
    frame of the track (module docstring), from ``q, v`` (k, 6)."""
    r = np.asarray(offsets, dtype=float).reshape(-1, 3)
    turned = np.einsum("kij,pj->kpi", rotations(q[:, 3:]), r)
    pitch, yaw = q[:, 4], q[:, 5]
    droll, dpitch, dyaw = v[:, 3], v[:, 4], v[:, 5]
    cp, sp, cy, sy = np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    omega = np.stack([droll * cp * cy - dpitch * sy, droll * cp * sy + dpitch * cy, dyaw - droll * sp], -1)
    displacement = q[:, None, :3] + turned - r[None]
    w = omega[:, None, :]
    cross = np.stack([w[..., 1] * turned[..., 2] - w[..., 2] * turned[..., 1],
                      w[..., 2] * turned[..., 0] - w[..., 0] * turned[..., 2],
                      w[..., 0] * turned[..., 1] - w[..., 1] * turned[..., 0]], -1)
    velocity = v[:, None, :3] + cross
    return displacement, velocity
