"""The result of a steady cable solve, independent of the method that found it."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CableSolution:
    """Steady shape and tension of one cable in the x–z plane.

    Attributes
    ----------
    s : ndarray, shape (n,)
        Unstretched arclength of the output stations [m].
    x, z : ndarray, shape (n,)
        Positions [m].
    force : ndarray, shape (n, 2)
        Tension vector ``T t`` [N].
    method : str
        Name of the solver that produced the solution.
    grounded_length : float
        Unstretched length resting on the seabed [m].
    iterations : int
        Nonlinear iterations (root-finder evaluations or Newton steps).
    """

    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    force: np.ndarray
    method: str
    grounded_length: float = 0.0
    iterations: int = 0

    @property
    def tension(self) -> np.ndarray:
        """Tension magnitude ``T`` [N], shape (n,)."""
        return np.hypot(self.force[:, 0], self.force[:, 1])

    @property
    def angle(self) -> np.ndarray:
        """Angle of the tangent above the horizontal, ``phi`` [rad], shape (n,)."""
        return np.arctan2(self.force[:, 1], self.force[:, 0])

    @property
    def position(self) -> np.ndarray:
        """Positions as ``(x, y, z)`` with ``y = 0``, shape (n, 3)."""
        return np.column_stack([self.x, np.zeros_like(self.x), self.z])
