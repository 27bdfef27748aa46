"""Prescribed 6-DOF motion of the vessel about its track, and of points fixed to it.

The vessel's motion (``vessel.motion``, :class:`kanat.model.operations.VesselMotion`) is
compiled once into arrays (:func:`compile_motion`); :func:`motion_at` then gives the
displacement and velocity of the six degrees of freedom at any time, and
:func:`rigid_point_motion` the displacement and velocity of points fixed to the vessel
(fairleads, the tow point), to be added to the track's motion of the vessel frame.

Conventions (vessel axes: x forward, y port, z up; angles right-handed about them):

* displacement ``q = (surge, sway, heave, roll, pitch, yaw)`` [m, m, m, rad, rad, rad];
* a harmonic is ``A sin(omega t + phase)``, its velocity ``A omega cos(omega t + phase)``;
* a table is interpolated linearly in time; its velocity is the slope of the interval
  holding ``t`` (the later one at a row); outside the table the end values hold, at rest;
* a ramp of ``T`` seconds (:mod:`kanat.physics.ramp`) turns ``q, v`` into ``r q`` and
  ``r v + (dr/dt) q``;
* a point at offset ``r`` from the vessel origin moves to ``(surge, sway, heave) + R r``
  with ``R = Rz(yaw) Ry(pitch) Rx(roll)``; its velocity is ``v + w x (R r)`` with the
  angular velocity ``w`` of those Euler angles (:func:`angular_velocity`).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from kanat.errors import KanatError
from kanat.physics.ramp import ramp_factor, ramp_rate
from kanat.physics.rao import rao_harmonics
from kanat.physics.waves import sea_from_model

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
"""Order of the degrees of freedom in every array of this module."""
ROTATIONS = (3, 4, 5)
"""Indices of roll, pitch, yaw (degrees in the case file, radians here)."""


@dataclass(frozen=True)
class Harmonics:
    """Harmonics ``amplitude sin(omega t + phase)`` of single degrees of freedom.

    Attributes
    ----------
    dof : ndarray of int, shape (n,)
        Index into :data:`DOFS`.
    amplitude : ndarray, shape (n,)
        [m] or [rad].
    omega : ndarray, shape (n,)
        Angular frequency ``2 pi / period`` [rad/s].
    phase : ndarray, shape (n,)
        [rad].
    ramp : float
        Start-up ramp [s] (0: none).
    """

    dof: np.ndarray
    amplitude: np.ndarray
    omega: np.ndarray
    phase: np.ndarray
    ramp: float = 0.0


@dataclass(frozen=True)
class MotionTable:
    """A tabulated motion.

    Attributes
    ----------
    time : ndarray, shape (k,)
        Strictly increasing [s].
    values : ndarray, shape (k, 6)
        Displacements [m, m, m, rad, rad, rad].
    ramp : float
        Start-up ramp [s] (0: none).
    """

    time: np.ndarray
    values: np.ndarray
    ramp: float = 0.0


def compile_motion(motion, environment=None) -> Harmonics | MotionTable | None:
    """Arrays of a ``vessel.motion`` block (SI units, radians); None when it is empty.

    Parameters
    ----------
    motion : kanat.model.operations.VesselMotion
        Reads ``harmonics`` (``dof``, ``amplitude`` [m or deg], ``period``, ``phase_deg``),
        ``rows`` (time, surge, sway, heave [m], roll, pitch, yaw [deg]) or ``rao_rows``.
    environment : kanat.model.Environment, optional
        The sea RAOs apply to (:mod:`kanat.physics.rao`); their motion ramps with the sea's
        ramp unless the motion has its own.
    """
    if motion.rao_rows is not None:
        return _rao_motion(motion, environment)
    if motion.rows is not None:
        rows = np.array(motion.rows, dtype=float)
        values = rows[:, 1:].copy()
        values[:, ROTATIONS] = np.radians(values[:, ROTATIONS])
        return MotionTable(rows[:, 0].copy(), values, motion.ramp)
    if not motion.harmonics:
        return None
    dof = np.array([DOFS.index(h.dof) for h in motion.harmonics], dtype=np.int64)
    amplitude = np.array([h.amplitude for h in motion.harmonics], dtype=float)
    amplitude = np.where(dof >= 3, np.radians(amplitude), amplitude)
    omega = np.array([2.0 * math.pi / h.period for h in motion.harmonics])
    phase = np.radians([h.phase_deg for h in motion.harmonics])
    return Harmonics(dof, amplitude, omega, np.asarray(phase, dtype=float), motion.ramp)


def _rao_motion(motion, environment) -> Harmonics:
    """:func:`kanat.physics.rao.rao_harmonics` in the sea of ``environment``, as Harmonics."""
    sea = sea_from_model(environment) if environment is not None else None
    if sea is None:
        raise KanatError("vessel.motion.rao moves the vessel with the sea: give environment.waves")
    *arrays, outside = rao_harmonics(motion.rao_rows, sea)
    if outside > 1e-3:
        warnings.warn(f"{100 * outside:.2g} % of the sea's variance lies at frequencies outside the RAO "
                      f"table ({motion.rao}); those components do not move the vessel", stacklevel=3)
    return Harmonics(*arrays, motion.ramp or sea.ramp)


def harmonic_motion(t: float, harmonics: Harmonics) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and velocity (6,) of a sum of harmonics at time ``t`` [s]."""
    arg = harmonics.omega * t + harmonics.phase
    q, v = np.zeros(6), np.zeros(6)
    np.add.at(q, harmonics.dof, harmonics.amplitude * np.sin(arg))
    np.add.at(v, harmonics.dof, harmonics.amplitude * harmonics.omega * np.cos(arg))
    return q, v


def table_motion(t: float, table: MotionTable) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and velocity (6,) of a table at time ``t`` [s] (module docstring)."""
    time, values = table.time, table.values
    if t <= time[0]:
        return values[0].copy(), np.zeros(6)
    if t >= time[-1]:
        return values[-1].copy(), np.zeros(6)
    i = int(np.searchsorted(time, t, side="right")) - 1
    slope = (values[i + 1] - values[i]) / (time[i + 1] - time[i])
    return values[i] + slope * (t - time[i]), slope


def motion_at(motion: Harmonics | MotionTable | None, t: float) -> tuple[np.ndarray, np.ndarray]:
    """The 6-DOF displacement and velocity of the vessel about its track at time ``t``.

    Parameters
    ----------
    motion : Harmonics, MotionTable or None
        From :func:`compile_motion` (None: no motion).
    t : float
        Time [s].

    Returns
    -------
    q, v : ndarray, shape (6,)
        ``(surge, sway, heave, roll, pitch, yaw)`` [m, rad] and their rates [m/s, rad/s].
    """
    if motion is None:
        return np.zeros(6), np.zeros(6)
    q, v = table_motion(t, motion) if isinstance(motion, MotionTable) else harmonic_motion(t, motion)
    r = ramp_factor(t, motion.ramp)
    return r * q, r * v + ramp_rate(t, motion.ramp) * q


def rotation_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` (3, 3): body axes to the frame the angles are in."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def skew(p) -> np.ndarray:
    """``S(p)`` (3, 3) with ``S(p) q = p x q``."""
    return np.array([[0.0, -p[2], p[1]], [p[2], 0.0, -p[0]], [-p[1], p[0], 0.0]])


def point_jacobian(offset) -> np.ndarray:
    """``J = [I, -S(p)]`` (3, 6): a point at ``offset`` ``p`` from a rigid body's reference moves
    ``J (u, theta)`` for a small translation ``u`` and rotation ``theta`` of the body."""
    return np.hstack([np.eye(3), -skew(offset)])


def angular_velocity(angles, rates) -> np.ndarray:
    """Angular velocity (3,) [rad/s], in the outer frame, of ``R = Rz Ry Rx`` whose angles
    ``(roll, pitch, yaw)`` change at ``rates``: ``dR/dt = S(w) R``.

    ``w = (roll' cos(pitch) cos(yaw) - pitch' sin(yaw),
    roll' cos(pitch) sin(yaw) + pitch' cos(yaw), yaw' - roll' sin(pitch))``.
    """
    _, pitch, yaw = angles
    droll, dpitch, dyaw = rates
    cp, sp, cy, sy = math.cos(pitch), math.sin(pitch), math.cos(yaw), math.sin(yaw)
    return np.array([droll * cp * cy - dpitch * sy, droll * cp * sy + dpitch * cy,
                     dyaw - droll * sp])


def rigid_point_motion(offsets, q, v) -> tuple[np.ndarray, np.ndarray]:
    """Displacement and velocity of points fixed to the vessel, from its 6-DOF motion.

    Parameters
    ----------
    offsets : array_like, shape (n, 3) or (3,)
        Points in vessel axes, from the vessel origin [m].
    q, v : ndarray, shape (6,)
        The vessel's displacement and velocity (:func:`motion_at`).

    Returns
    -------
    displacement, velocity : ndarray, shape of ``offsets``
        ``(surge, sway, heave) + R r - r`` [m] and ``v + w x (R r)`` [m/s], in the frame
        of the track (still to be turned by the heading and moved with the track).
    """
    r = np.asarray(offsets, dtype=float)
    rotation = rotation_matrix(*q[3:])
    turned = r @ rotation.T
    omega = angular_velocity(q[3:], v[3:])
    return q[:3] + turned - r, v[:3] + np.cross(omega, turned)
