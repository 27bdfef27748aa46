"""The result of a steady cable solve, independent of the method that found it."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CableSolution:
    """Steady shape and tension of one cable: in the x–z plane, or in 3-D with ``y`` and ``force_y``.

    Attributes
    ----------
    s : ndarray, shape (n,)
        Unstretched arclength of the output stations [m]. At an inline body (an attachment)
        the station may be repeated: the first holds the state before the body's jump, the
        second after it.
    x, z : ndarray, shape (n,)
        Positions [m].
    force : ndarray, shape (n, 2)
        Tension vector ``T t``, x and z components [N].
    method : str
        Name of the solver that produced the solution.
    grounded_length : float
        Unstretched length resting on the seabed [m].
    iterations : int
        Nonlinear iterations (root-finder evaluations or Newton steps).
    y, force_y : ndarray, shape (n,), or None
        The y components of the position [m] and of ``T t`` [N] of a 3-D solution; None
        in the x–z plane.
    """

    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    force: np.ndarray
    method: str
    grounded_length: float = 0.0
    iterations: int = 0
    y: np.ndarray | None = None
    force_y: np.ndarray | None = None

    @property
    def force3(self) -> np.ndarray:
        """Tension vector ``T t`` (x, y, z) [N], shape (n, 3)."""
        fy = np.zeros(len(self.s)) if self.force_y is None else self.force_y
        return np.column_stack([self.force[:, 0], fy, self.force[:, 1]])

    @property
    def tension(self) -> np.ndarray:
        """Tension magnitude ``T`` [N], shape (n,)."""
        if self.force_y is None:
            return np.hypot(self.force[:, 0], self.force[:, 1])
        return np.sqrt(self.force[:, 0] ** 2 + self.force_y ** 2 + self.force[:, 1] ** 2)

    @property
    def angle(self) -> np.ndarray:
        """Angle of the tangent above the horizontal [rad], shape (n,): ``atan2(F_z, F_x)`` in the
        x–z plane (``phi``, through +-pi), the elevation ``atan2(F_z, |F_h|)`` in 3-D."""
        if self.force_y is None or not np.any(self.force_y):
            return np.arctan2(self.force[:, 1], self.force[:, 0])
        return np.arctan2(self.force[:, 1], np.hypot(self.force[:, 0], self.force_y))

    @property
    def position(self) -> np.ndarray:
        """Positions ``(x, y, z)``, shape (n, 3) (``y = 0`` in the x–z plane)."""
        y = np.zeros_like(self.x) if self.y is None else self.y
        return np.column_stack([self.x, y, self.z])
