"""Prescribed motion of a planar cable's ends: the tow point on the vessel track, or anchors."""
from __future__ import annotations

import math

import numpy as np

from kanat.continuum.model2d import PlanarCable
from kanat.errors import CaseError, Problem
from kanat.vessel.track import VesselTrack


class Drive:
    """End velocities and the first end's position over time, in the x–z plane.

    Parameters
    ----------
    cable : PlanarCable
    track : VesselTrack
    """

    def __init__(self, cable: PlanarCable, track: VesselTrack):
        self.cable = cable
        self.track = track

    @classmethod
    def planar(cls, cable: PlanarCable, vessel) -> Drive:
        """A drive for a planar run; refuses a track that leaves the x–z plane."""
        track = VesselTrack.from_model(vessel)
        for phase in track.phases:
            if phase.yaw_rate or math.sin(phase.heading):
                raise CaseError([Problem("vessel.track", "this track turns or runs off the x axis, which "
                                         "leaves the x–z plane; set simulation.dimensions: 3")])
        return cls(cable, track)

    def velocities(self, t: float):
        """``((Vx, Vz) at s = 0, (Vx, Vz) at s = L)`` [m/s]."""
        v0 = (0.0, 0.0)
        if self.cable.start.moving:
            v = self.track.state(t).velocity
            v0 = (v[0], v[2])
        return v0, (0.0, 0.0)

    def origin(self, t: float) -> np.ndarray:
        """Position ``(x, z)`` of the first end [m]."""
        if self.cable.start.moving:
            p = self.track.state(t).position
            return np.array([p[0], p[2]])
        return np.asarray(self.cable.start.position, dtype=float)
