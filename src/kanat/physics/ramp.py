"""The start-up ramp of waves, current and prescribed motion (``ramp`` keys of a case).

A ramp of ``T`` seconds multiplies what it ramps by::

    (1)  r(t) = (1 - cos(pi t / T)) / 2   for 0 <= t < T,   r(t) = 1 for t >= T,  0 before t = 0
    (2)  dr/dt = pi / (2 T) sin(pi t / T)  for 0 < t < T, else 0

a half cosine: ``r`` and ``dr/dt`` are continuous, from rest at ``t = 0`` to full strength with
zero slope at ``T``. ``T = 0`` means no ramp (``r = 1`` throughout).
"""
from __future__ import annotations

import math

import numpy as np


def ramp_factor(t: float, duration: float) -> float:
    """``r(t)`` of eq. (1) for a ramp of ``duration`` [s]."""
    if duration <= 0.0 or t >= duration:
        return 1.0
    if t <= 0.0:
        return 0.0
    return 0.5 * (1.0 - math.cos(math.pi * t / duration))


def ramp_rate(t: float, duration: float) -> float:
    """``dr/dt`` [1/s] of eq. (2)."""
    if duration <= 0.0 or t <= 0.0 or t >= duration:
        return 0.0
    return 0.5 * math.pi / duration * math.sin(math.pi * t / duration)


def ramp_series(times, duration: float) -> tuple[np.ndarray, np.ndarray]:
    """``r`` and ``dr/dt`` (k,) at ``times`` (k,): eqs. (1)-(2) vectorized."""
    t = np.asarray(times, dtype=float)
    if duration <= 0.0:
        return np.ones_like(t), np.zeros_like(t)
    inside = (t > 0.0) & (t < duration)
    phase = np.pi * np.clip(t, 0.0, duration) / duration
    r = np.where(t >= duration, 1.0, np.where(inside, 0.5 * (1.0 - np.cos(phase)), 0.0))
    return r, np.where(inside, 0.5 * np.pi / duration * np.sin(phase), 0.0)
