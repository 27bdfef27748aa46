"""Immersion of a spherical float: the share of its volume under the water surface.

A sphere of diameter ``D`` centred at height ``z`` under a surface at ``eta`` is immersed to the
depth ``h = clip(eta - z + D/2, 0, D)`` (from its bottom). Its submerged cap holds the fraction

    f = u^2 (3 - 2 u),    u = h / D,                                              (1)

of its volume (the cap volume ``pi h^2 (3a - h) / 3`` over ``4 pi a^3 / 3``, ``a = D/2``), with

    df/dz = -6 u (1 - u) / D                                                      (2)

inside and zero outside: ``f`` and ``df/dz`` are continuous, so a Newton iteration on a float
that crosses the surface sees no jump in its Jacobian. A float's buoyancy is ``f`` times the
weight of the water it displaces fully submerged (``net_buoyancy + mass g`` of the body).

A straight cable element of diameter ``d`` between centreline heights ``h_i, h_j`` above the
surface spans ``[low, high] = [min(h) - d/2, max(h) + d/2]``; it is wet over the share of that
extent below the surface (the lumped model's :func:`kanat.lumped.kernels.wetted_fraction`, MoorDyn's
VOF)::

    phi = clip(-low / (high - low), 0, 1)                                          (3)

continuous in the heights (a horizontal element at the surface is half wet), 1 once its top is
under the surface, and the share of its chord under it for a slender element (``d`` small against
``|h_j - h_i|``).
"""
from __future__ import annotations

import numpy as np


def sphere_fraction(z, eta, diameter: float):
    """Submerged volume fraction of a sphere and its derivative by the centre's height, eqs. (1)-(2).

    Parameters
    ----------
    z : float or complex
        Height of the centre [m] (complex for a complex-step derivative).
    eta : float
        Water surface elevation above the centre [m].
    diameter : float
        [m], > 0.

    Returns
    -------
    fraction, dfraction_dz : float (or complex), float
        In ``[0, 1]``; [1/m].
    """
    u = (eta - z) / diameter + 0.5
    if u.real <= 0.0:
        return 0.0 * z, 0.0
    if u.real >= 1.0:
        return 1.0 + 0.0 * z, 0.0
    return u * u * (3.0 - 2.0 * u), float((-6.0 * u * (1.0 - u) / diameter).real)


def float_buoyancy(net_buoyancy: float, buoyancy: float, fraction) -> float:
    """Net buoyancy of a float immersed to ``fraction`` [N]: ``net_buoyancy - (1 - f) buoyancy``, with
    ``buoyancy = net_buoyancy + m g`` its buoyancy fully submerged (so ``-m g`` out of the water)."""
    return net_buoyancy - (1.0 - fraction) * buoyancy


def sphere_fractions(z: np.ndarray, eta, diameter: np.ndarray) -> np.ndarray:
    """Eq. (1) for many spheres at once (real heights): the submerged volume fractions.

    Parameters
    ----------
    z : ndarray, shape (n,)
        Heights of the centres [m].
    eta : float or ndarray, shape (n,)
        Water surface elevation over each centre [m].
    diameter : ndarray, shape (n,)
        [m], > 0.

    Returns
    -------
    ndarray, shape (n,)
        In ``[0, 1]``.
    """
    u = np.clip((eta - np.asarray(z, dtype=float)) / diameter + 0.5, 0.0, 1.0)
    return u * u * (3.0 - 2.0 * u)


def element_fractions(h_i, h_j, diameter) -> np.ndarray:
    """Eq. (3) for many cable elements at once: their wetted fractions.

    Parameters
    ----------
    h_i, h_j : ndarray, shape (m,)
        Heights of the elements' end centrelines above the water surface [m] (negative under it).
    diameter : ndarray, shape (m,)
        [m], >= 0.

    Returns
    -------
    ndarray, shape (m,)
        In ``[0, 1]``; exactly 1 for an element wholly under the surface.
    """
    h_i, h_j = np.asarray(h_i, dtype=float), np.asarray(h_j, dtype=float)
    low = np.minimum(h_i, h_j) - 0.5 * np.asarray(diameter)
    high = np.maximum(h_i, h_j) + 0.5 * np.asarray(diameter)
    span = np.maximum(high - low, 1e-300)
    return np.where(high <= 0.0, 1.0, np.clip(-low / span, 0.0, 1.0))
