"""Prescribed motion of a planar cable's ends: the tow point on the vessel track, or anchors."""
from __future__ import annotations

import numpy as np

from kanat.continuum.model2d import PlanarCable
from kanat.vessel.track import VesselTrack


class Drive:
    """End velocities and the first end's position over time, in the x–z plane (the case was
    checked to stay in it: :func:`kanat.model.plane.out_of_plane`).

    Parameters
    ----------
    cable : PlanarCable
    track : VesselTrack or kanat.continuum.vessel_motion.MovedTrack
        The tow point's track (with the prescribed motion, when the case has one).
    """

    def __init__(self, cable: PlanarCable, track: VesselTrack):
        self.cable = cable
        self.track = track

    def velocities(self, t: float):
        """``((Vx, Vz) at s = 0, (Vx, Vz) at s = L)`` [m/s]."""
        v0 = (0.0, 0.0)
        if self.cable.start.moving:
            v = self.track.tow_state(t).velocity
            v0 = (v[0], v[2])
        return v0, (0.0, 0.0)

    def origin(self, t: float) -> np.ndarray:
        """Position ``(x, z)`` of the first end [m]."""
        if self.cable.start.moving:
            p = self.track.tow_state(t).position
            return np.array([p[0], p[2]])
        return np.asarray(self.cable.start.position, dtype=float)
