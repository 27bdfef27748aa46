"""The waves' kinematics as complex amplitudes per unit wave amplitude (:mod:`kanat.physics.waves`
eqs. 3-5): at a point ``(x, y, z)`` and frequency ``omega`` of heading ``beta``, the velocity is
horizontal ``omega C(z) e^{-i psi} (cos beta, sin beta)`` and vertical ``i omega S(z) e^{-i psi}``,
the acceleration ``a_w = i omega u_w`` and the elevation ``e^{-i psi}``, with
``psi = k (x cos beta + y sin beta)``."""
from __future__ import annotations

import numpy as np


def water_velocity(sea, points: np.ndarray) -> np.ndarray:
    """The water's velocity (nf, k, 3) complex at ``points`` (k, 3) per unit amplitude of each
    component of ``sea`` (:class:`kanat.physics.waves.LinearSea`, nf components)."""
    points = np.asarray(points, float).reshape(-1, 3)
    c, s = sea._profiles(points[:, 2])                                          # (k, nf)
    cb, sb = np.cos(sea.direction), np.sin(sea.direction)
    psi = np.multiply.outer(points[:, 0], sea.k * cb) + np.multiply.outer(points[:, 1], sea.k * sb)
    phase = np.exp(-1j * psi) * sea.omega
    u = np.empty((len(sea.omega), len(points), 3), complex)
    u[..., 0] = (c * phase * cb).T
    u[..., 1] = (c * phase * sb).T
    u[..., 2] = (1j * s * phase).T
    return u
