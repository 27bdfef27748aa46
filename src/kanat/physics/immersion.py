"""Immersion of a spherical float: the share of its volume under the water surface.

A sphere of diameter ``D`` centred at height ``z`` under a surface at ``eta`` is immersed to the
depth ``h = clip(eta - z + D/2, 0, D)`` (from its bottom). Its submerged cap holds the fraction

    f = u^2 (3 - 2 u),    u = h / D,                                              (1)

of its volume (the cap volume ``pi h^2 (3a - h) / 3`` over ``4 pi a^3 / 3``, ``a = D/2``), with

    df/dz = -6 u (1 - u) / D                                                      (2)

inside and zero outside: ``f`` and ``df/dz`` are continuous, so a Newton iteration on a float
that crosses the surface sees no jump in its Jacobian. A float's buoyancy is ``f`` times the
weight of the water it displaces fully submerged (``net_buoyancy + mass g`` of the body).
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
