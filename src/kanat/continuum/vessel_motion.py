"""The vessel's tow point for the continuum model: the track plus ``vessel.motion``.

The prescribed motion about the track (:mod:`kanat.physics.motion`: harmonics or a table, in
vessel axes) moves the tow point ``r`` (the lever arm ``vessel.tow_point``) by
``d = (surge, sway, heave) + R r - r`` at velocity ``v + w x (R r)``; the heading ``psi`` of the
track turns both into the global frame, and the track's yaw rate ``r_psi`` adds
``r_psi e_z x Rz(psi) d`` to the velocity (the lumped model's :meth:`LumpedSystem.vessel_points`,
the same equations). The continuum model's first end then moves with the sum: its velocity is
the boundary condition at ``s = 0`` and its position the origin the node positions are built
from.

The motion's acceleration is left out of :attr:`VesselState.acceleration` (the track's own):
nothing in the continuum model reads it.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.physics.motion import compile_motion, motion_at, rigid_point_motion
from kanat.vessel.track import VesselState, VesselTrack


class MovedTrack:
    """A :class:`VesselTrack` whose tow point also follows the vessel's prescribed motion.

    Parameters
    ----------
    track : VesselTrack
    motion : Harmonics or MotionTable
        The compiled ``vessel.motion`` (:func:`kanat.physics.motion.compile_motion`).

    Attributes
    ----------
    pitch : callable or None
        The track's own pitch (``vessel.pitch``), unchanged.
    """

    def __init__(self, track: VesselTrack, motion):
        self.track, self.motion = track, motion
        self.pitch = track.pitch
        self._tow: tuple[float, VesselState] | None = None

    def tow_state(self, t: float) -> VesselState:
        """The tow point's kinematics at ``t``: the track's plus the prescribed motion's (read-only
        arrays, the last one kept, as :meth:`VesselTrack.tow_state`)."""
        if self._tow is None or self._tow[0] != t:
            state = self._moved(t)
            for array in (state.position, state.velocity, state.acceleration):
                array.flags.writeable = False
            self._tow = (t, state)
        return self._tow[1]

    def _moved(self, t: float) -> VesselState:
        base = self.track.state(t)
        q, qd = motion_at(self.motion, t)
        disp, dvel = rigid_point_motion(self.track.tow_point, q, qd)
        c, s = math.cos(base.heading), math.sin(base.heading)
        turned = np.array([c * disp[0] - s * disp[1], s * disp[0] + c * disp[1], disp[2]])
        velocity = np.array([c * dvel[0] - s * dvel[1] - base.yaw_rate * turned[1],
                             s * dvel[0] + c * dvel[1] + base.yaw_rate * turned[0], dvel[2]])
        return VesselState(base.position + turned, base.velocity + velocity, base.acceleration.copy(),
                           base.heading, base.yaw_rate, base.speed)


def vessel_track(vessel, environment=None) -> VesselTrack | MovedTrack:
    """The tow point's track of a case's ``vessel`` block: :meth:`VesselTrack.from_model`, moved by
    ``vessel.motion`` when the block has one (RAOs in the sea of ``environment``)."""
    track = VesselTrack.from_model(vessel)
    motion = compile_motion(vessel.motion, environment)
    return track if motion is None else MovedTrack(track, motion)
