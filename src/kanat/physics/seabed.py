"""Seabed geometry: the height of the seabed and its unit normal at horizontal positions.

Every seabed answers two vectorised questions, the interface the contact and statics
code uses:

* ``height(x, y) -> z`` [m], the seabed's height (z up, 0 at the mean free surface);
* ``normal(x, y) -> n`` (..., 3), the upward unit normal.

:class:`PlaneSeabed` is the plane of the case file (``environment.depth`` and
``environment.seabed.slope_deg``): ``z = -depth + x tan(slope)``, rising towards +x. A
bathymetry grid (bilinear interpolation of depths on a regular x-y grid, as MoorDyn's
seafloor file) can be dropped in later as another class with the same two methods; the
:class:`Seabed` protocol states the contract, and nothing that uses a seabed needs to
know which one it has.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

SLIP_VELOCITY = 1.0e-3      # m/s: the velocity scale v_s of regularized Coulomb friction (kanat.physics.contact)
PENETRATION_MARGIN = 10.0   # a node may sink this many times its static penetration before a run fails
PENETRATION_FLOOR = 1.0e-3  # m, and at least this much (a light line's static penetration is ~0)


class Seabed(Protocol):
    """What a seabed geometry provides (vectorised over any shape of ``x``, ``y``)."""

    def height(self, x, y) -> np.ndarray:
        """Seabed height ``z`` [m] at ``(x, y)``; same shape as the broadcast inputs."""

    def normal(self, x, y) -> np.ndarray:
        """Upward unit normal at ``(x, y)``, shape ``broadcast(x, y).shape + (3,)``."""


@dataclass(frozen=True)
class PlaneSeabed:
    """The plane ``z = -depth + x tan(slope)`` (flat when ``slope_deg = 0``).

    Parameters
    ----------
    depth : float
        Depth of the seabed at ``x = 0`` [m] (positive).
    slope_deg : float
        Slope [deg], the seabed rising towards +x; within (-90, 90).
    """

    depth: float
    slope_deg: float = 0.0

    def __post_init__(self):
        if not self.depth > 0:
            raise ValueError(f"depth must be positive (got {self.depth!r} m)")
        if not abs(self.slope_deg) < 90.0:
            raise ValueError(f"slope_deg must be within (-90, 90) (got {self.slope_deg!r})")

    @property
    def gradient(self) -> float:
        """``dz/dx = tan(slope)`` [-]."""
        return math.tan(math.radians(self.slope_deg))

    def height(self, x, y) -> np.ndarray:
        """``-depth + x tan(slope)`` [m], broadcast over ``x`` and ``y``."""
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        return -self.depth + self.gradient * x

    def normal(self, x, y) -> np.ndarray:
        """``(-sin(slope), 0, cos(slope))`` at every point, shape ``(..., 3)``."""
        x, _ = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        angle = math.radians(self.slope_deg)
        n = np.array([-math.sin(angle), 0.0, math.cos(angle)])
        return np.broadcast_to(n, x.shape + (3,)).copy()

    def penetration(self, points) -> np.ndarray:
        """Depth of ``points`` (..., 3) below the seabed along its normal [m]; <= 0 above.

        For a plane, ``(height(x, y) - z) cos(slope)``: the normal distance.
        """
        p = np.asarray(points, dtype=float)
        return (self.height(p[..., 0], p[..., 1]) - p[..., 2]) * math.cos(math.radians(self.slope_deg))


def seabed_of(environment) -> PlaneSeabed | None:
    """The seabed geometry of a case's ``environment`` (None without ``depth``).

    Parameters
    ----------
    environment : kanat.model.Environment
        Reads ``depth`` and ``seabed.slope_deg`` (0 without a ``seabed`` block).
    """
    if environment.depth is None:
        return None
    slope = environment.seabed.slope_deg if environment.seabed is not None else 0.0
    return PlaneSeabed(environment.depth, slope)
