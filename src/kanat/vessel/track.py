"""Vessel manoeuvres (theory/vessel.md §1): the track as phases of constant acceleration and turn rate.

A track is compiled once into :class:`Phase` records, each with a start time, its initial
state (position, heading, speed), a constant longitudinal acceleration ``a`` and a
constant yaw rate ``r``; within a phase the motion has a closed form:

* straight (``r = 0``): ``p = p0 + (v0 tau + a tau^2 / 2) (cos psi0, sin psi0)``;
* turn at constant speed (``a = 0``): a circular arc of radius ``v0 / |r|``,
  ``p = p0 + (v0 / r) (sin(psi0 + r tau) - sin psi0, cos psi0 - cos(psi0 + r tau))``.

The vessel starts at the origin with heading 0 (along ``+x``); heading is positive to
port (counter-clockwise seen from above). A speed step is a phase of zero duration.
After the last segment the vessel runs on straight at its final speed. The tow point
is a fixed point of the vessel (lever arm in vessel axes: x forward, y port, z up).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.model.vessel import start_speeds


@dataclass(frozen=True)
class Phase:
    """A piece of track with constant acceleration ``a`` [m/s^2] and yaw rate ``r`` [rad/s]."""

    start: float
    duration: float
    x: float
    y: float
    heading: float
    speed: float
    acceleration: float = 0.0
    yaw_rate: float = 0.0

    def at(self, tau: float) -> tuple[float, float, float, float]:
        """Position x, y [m], heading [rad] and speed [m/s] at ``tau`` seconds into the phase."""
        v0, a, r, psi0 = self.speed, self.acceleration, self.yaw_rate, self.heading
        if r == 0.0:
            run = v0 * tau + 0.5 * a * tau * tau
            return self.x + run * math.cos(psi0), self.y + run * math.sin(psi0), psi0, v0 + a * tau
        psi = psi0 + r * tau
        return (self.x + v0 / r * (math.sin(psi) - math.sin(psi0)),
                self.y + v0 / r * (math.cos(psi0) - math.cos(psi)), psi, v0)


@dataclass(frozen=True)
class VesselState:
    """Kinematics of a point of the vessel at one instant (global frame, SI).

    Attributes
    ----------
    position, velocity, acceleration : ndarray, shape (3,)
    heading : float
        [rad], 0 along ``+x``, positive to port.
    yaw_rate : float
        [rad/s].
    speed : float
        Vessel speed over ground [m/s].
    """

    position: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    heading: float
    yaw_rate: float
    speed: float


class VesselTrack:
    """The vessel's motion in time, compiled from a case's ``vessel`` block.

    Parameters
    ----------
    phases : list of Phase
        In time order, contiguous.
    tow_point : array_like, shape (3,)
        Lever arm of the tow point in vessel axes [m], from the pitch centre.
    pitch : callable, optional
        ``t -> (angle, rate, acceleration)`` of the pitch [rad, rad/s, rad/s^2], bow up
        positive (theory/vessel.md §2). The lever arm turns with it about the vessel's y axis, so a
        stern tow point rises and falls with the pitch.
    """

    def __init__(self, phases: list[Phase], tow_point=(0.0, 0.0, 0.0), pitch=None):
        self.phases = list(phases)
        self.tow_point = np.asarray(tow_point, dtype=float)
        self.pitch = pitch
        self._starts = np.array([p.start for p in self.phases])
        self._tow: tuple[float, VesselState] | None = None

    @classmethod
    def from_model(cls, vessel, pitch=None) -> VesselTrack:
        """Compile a :class:`kanat.model.Vessel` (raises CaseError for impossible segments).

        ``pitch`` (a callable ``t -> (angle, rate, acceleration)``) overrides the vessel's
        own; without it, a ``vessel.pitch`` block becomes the steady pitch of its stabilizer
        mode (:func:`kanat.vessel.pitch.motion.pitch_motion`; may raise ResonanceError).
        """
        if pitch is None and getattr(vessel, "pitch", None) is not None:
            # imported here: this method is the hook, and the solver is only needed with a pitch block
            from kanat.vessel.pitch.motion import pitch_motion

            pitch = pitch_motion(vessel.pitch)
        return cls(compile_phases(vessel.track), vessel.tow_point, pitch)

    def pitched_arm(self, t: float, arm):
        """Lever arm in level vessel axes after the pitch at ``t``, with its rate and acceleration.

        Bow up by ``a`` maps ``(x, y, z)`` to ``(x cos a - z sin a, y, x sin a + z cos a)``.
        """
        arm = np.asarray(arm, dtype=float)
        if self.pitch is None:
            return arm, np.zeros(3), np.zeros(3)
        a, rate, accel = self.pitch(t)
        c, s = math.cos(a), math.sin(a)
        x, y, z = arm
        turned = np.array([x * c - z * s, y, x * s + z * c])
        d_turned = np.array([-x * s - z * c, 0.0, x * c - z * s])          # d(turned)/da
        dd_turned = np.array([-x * c + z * s, 0.0, -x * s - z * c])
        return turned, rate * d_turned, accel * d_turned + rate * rate * dd_turned

    @property
    def duration(self) -> float:
        """Time at which the last segment ends [s]."""
        last = self.phases[-1]
        return last.start + last.duration

    def _phase(self, t: float) -> Phase:
        """The phase running at ``t``: the last to start at or before it (a step wins at its instant)."""
        index = max(0, int(np.searchsorted(self._starts, t, side="right")) - 1)
        return self.phases[index]

    def tow_state(self, t: float) -> VesselState:
        """:meth:`state` of the tow point at ``t``, the last one kept: a continuum step asks for it
        three times at the same instant (end velocity, first end's position, outputs). Its arrays
        are read-only (it is shared)."""
        if self._tow is None or self._tow[0] != t:
            state = self.state(t)
            for array in (state.position, state.velocity, state.acceleration):
                array.flags.writeable = False
            self._tow = (t, state)
        return self._tow[1]

    def state(self, t: float, lever_arm=None) -> VesselState:
        """Kinematics at time ``t`` [s] of the point ``lever_arm`` (default: the tow point)."""
        arm, arm_rate, arm_accel = self.pitched_arm(t, self.tow_point if lever_arm is None else lever_arm)
        phase = self._phase(t)
        tau = t - phase.start
        if tau > phase.duration:                      # past the end of the track: straight on
            x, y, psi, v = phase.at(phase.duration)
            run = v * (tau - phase.duration)
            x, y, a, r = x + run * math.cos(psi), y + run * math.sin(psi), 0.0, 0.0
        else:
            x, y, psi, v = phase.at(tau)
            a, r = phase.acceleration, phase.yaw_rate
        c, s = math.cos(psi), math.sin(psi)
        yaw = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        rx, ry, _ = yaw @ arm                                  # lever arm in the global frame
        lx, ly, lz = yaw @ arm_rate                            # its rate of turning with the pitch
        ax, ay, az = yaw @ arm_accel
        position = np.array([x + rx, y + ry, arm[2]])
        velocity = np.array([v * c - r * ry + lx, v * s + r * rx + ly, lz])
        accel = np.array([a * c - v * r * s - r * r * rx - 2 * r * ly + ax,
                          a * s + v * r * c - r * r * ry + 2 * r * lx + ay, az])
        return VesselState(position, velocity, accel, psi, r, v)


def compile_phases(segments) -> list[Phase]:
    """Turn track segments (kanat.model.vessel) into contiguous phases.

    Each segment starts at the speed :func:`kanat.model.vessel.start_speeds` gives it (the case
    checks read the same speeds): its own, else where the one before ended (0 at first: from rest).
    """
    phases = [Phase(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)]
    for index, (seg, v) in enumerate(zip(segments, start_speeds(segments))):
        last = phases[-1]
        t = last.start + last.duration
        x, y, psi, _ = last.at(last.duration)
        if seg.kind == "straight":
            new = [Phase(t, seg.duration, x, y, psi, v)]
        elif seg.kind == "speed_step":
            new = [Phase(t, 0.0, x, y, psi, seg.to_speed_ms)]
        elif seg.kind == "accelerate":
            new = _accelerate(seg, t, x, y, psi, v)
        else:
            new = [_turn(seg, index, t, x, y, psi, v)]
        phases.extend(new)
    return phases


def _accelerate(seg, t, x, y, psi, v) -> list[Phase]:
    """A ramp at constant rate to the target speed, then (with ``duration``) a hold."""
    change = seg.to_speed_ms - v
    ramp = abs(change) / seg.acceleration if seg.duration is None else min(abs(change) / seg.acceleration,
                                                                            seg.duration)
    phases = [Phase(t, ramp, x, y, psi, v, math.copysign(seg.acceleration, change) if change else 0.0)]
    if seg.duration is not None and seg.duration > ramp:
        x, y, psi, v = phases[0].at(ramp)
        phases.append(Phase(t + ramp, seg.duration - ramp, x, y, psi, v))
    return phases


def _turn(seg, index, t, x, y, psi, v) -> Phase:
    key = f"vessel.track[{index}]"
    if seg.kind == "heading":
        change = (math.radians(seg.change_deg) if seg.change_deg is not None
                  else (math.radians(seg.to_deg) - psi + math.pi) % (2 * math.pi) - math.pi)
        rate = math.copysign(math.radians(seg.rate_deg_s), change)
        return Phase(t, abs(change / rate), x, y, psi, v, 0.0, rate)
    if seg.radius is not None:
        if v / seg.radius <= 0.0:         # also a speed so small that the turn rate underflows to 0
            raise CaseError([Problem(key, "a turn of given radius needs a speed > 0; give the turn a speed "
                                          "or a rate_deg_s")])
        rate = math.copysign(v / seg.radius, seg.angle_deg)
    else:
        rate = math.radians(seg.rate_deg_s)
    duration = seg.duration if seg.duration is not None else abs(math.radians(seg.angle_deg) / rate)
    return Phase(t, duration, x, y, psi, v, 0.0, rate)
