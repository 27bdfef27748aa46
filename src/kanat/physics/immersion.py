"""Immersion of a spherical float: the share of its volume under the water surface.

A sphere of diameter ``D`` centred at height ``z`` under a surface at ``eta`` is immersed to the
depth ``h = clip(eta - z + D/2, 0, D)`` (from its bottom). Its submerged cap holds the fraction

    f = u^2 (3 - 2 u),    u = h / D,                                              (1)

of its volume (the cap volume ``pi h^2 (3a - h) / 3`` over ``4 pi a^3 / 3``, ``a = D/2``), with

    df/dz = -6 u (1 - u) / D                                                      (2)

inside and zero outside: ``f`` and ``df/dz`` are continuous, so a Newton iteration on a float
that crosses the surface sees no jump in its Jacobian. A float's buoyancy is ``f`` times the
weight of the water it displaces fully submerged (``net_buoyancy + mass g`` of the body).

A line's length above the surface, interval by interval (the part of each interval above it by
linear interpolation of its ends' heights ``h`` above the surface)::

    L_dry = sum_i  ds_i * f_i,   f_i = 1 both ends above, 0 both below,
                                 max(h_i, h_i+1) / |h_i+1 - h_i| crossing                (3)

(:func:`dry_shares`, :func:`dry_length`): the continuum model wets each interval over ``1 - f_i``,
and the statics solvers that take a whole line as submerged say how much of it was not.
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


def heights(position: np.ndarray, sea, t: float) -> np.ndarray:
    """Height [m] of each node's centreline above the water surface (negative under it): the mean
    surface ``z = 0``, or the wave elevation over the node when ``sea`` is given."""
    position = np.asarray(position, dtype=float)
    if sea is None:
        return position[:, 2].copy()
    return position[:, 2] - sea.elevation(position[:, 0], position[:, 1], t)


def dry_shares(height: np.ndarray) -> np.ndarray:
    """Eq. (3)'s ``f``: the share of each interval's chord above the surface (N,), from its nodes'
    heights ``height`` (N + 1,) (:func:`heights`); exactly 0 for an interval with no node above it."""
    h0, h1 = height[:-1], height[1:]
    crossing = (h0 > 0.0) != (h1 > 0.0)
    return np.where(crossing, np.maximum(h0, h1) / np.where(crossing, np.abs(h1 - h0), 1.0),
                    (h0 > 0.0).astype(float))


def dry_length(s: np.ndarray, height: np.ndarray) -> float:
    """Eq. (3): the length [m] of cable above the surface, from the nodes' arclengths ``s`` and
    heights ``height`` (:func:`heights`)."""
    return float(np.sum(np.diff(s) * dry_shares(height)))
