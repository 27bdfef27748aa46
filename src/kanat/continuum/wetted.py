"""The wet share of continuum intervals crossing the water surface (docs/theory/continuum.md).

An interval whose nodes' centrelines stand ``h_i, h_i+1`` above the surface (the mean surface, or
the wave elevation over each node: :func:`kanat.continuum.surface.heights`) is wet over the share of
its chord under the surface, exact for a straight interval::

    (1)  phi = 1 - f(h_i, h_i+1)        (f of eq. (1) of kanat.continuum.surface: 1, 0, or
                                         max(h_i, h_i+1) / |h_i+1 - h_i| for a crossing interval)

Only its wet part carries buoyancy, the water's drag and added mass, and the waves' Froude–Krylov
force, so its parameter row for the step becomes::

    (2)  w   = w0 + (1 - phi) rho g A,      rho g A = m g - w0      weight: in air where dry
    (3)  m_a = phi m_a0,   C_n = phi C_n0,   C_t = phi C_t0          added mass and drag

and the kernels' displaced mass ``m - w / g`` (the Froude–Krylov term,
:mod:`kanat.continuum.kernels2d`) is ``phi rho A`` with it. This is the lumped model's treatment
(:func:`kanat.lumped.kernels.wetted_fraction`), whose fraction also counts the cable's diameter; the
chord's share leaves an interval with no node above the surface wholly wet (a tow point at ``z = 0``
adds no dry part), and such an interval keeps its row untouched, bit for bit. A partly dry interval
is given a section number of its own (negative, unlike a cable's sections): the kernels evaluate a
node's load once for the two intervals beside it when they share a section, and the partly dry
interval's nodes must take theirs with its own row (else the weight of half an interval would be
misplaced at each crossing, a first-order error).

It applies to a cable whose water ends at its surface (``cable.water_surface``: every cable of a
case), not to the idealized cables of :mod:`kanat.validation` in unbounded water.

``phi`` is taken at the node positions at the start of the step and the wave elevation at the
step's ``[ak]`` time, explicit in space as the water's kinematics are
(:mod:`kanat.continuum.water`): it is a constant of the step's Newton iteration, whose Jacobian
needs no new term, and the error it makes is of the order of the surface crossing's motion in one
step. The steady state takes it at the previous steady pass's nodes
(:data:`kanat.continuum.start.STEADY_PASSES`), a fixed point that the passes converge to. A
horizontal interval floating at the surface is wet or dry as a whole (``phi`` jumps there), so a
buoyant line lying on the surface is left to :func:`kanat.continuum.surface.dry_buoyant_node`.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.physics.immersion import dry_shares, heights


ROUND_OFF = 1e-8
"""A node this little [m] above the surface is on it (a tow point at ``z = 0`` whose statics guess
puts it 1e-14 m up keeps its cable wholly wet)."""


def elevation_bound(sea) -> float:
    """The highest the wave surface can rise above the mean surface [m]: the sum of the sea's
    amplitudes (0 without waves)."""
    return 0.0 if sea is None else float(np.sum(sea.amplitude))


def wet_fractions(rows: np.ndarray, position: np.ndarray, sea, t: float) -> np.ndarray:
    """Eq. (1): the wetted fraction of every interval; 1 for a junction and for an interval that
    cannot reach the surface.

    Parameters
    ----------
    rows : ndarray, shape (N, n_par)
        The interval rows.
    position : ndarray, shape (N + 1, 2 or 3)
        Node positions [m]: (x, z) of a planar cable, (x, y, z) of a spatial one.
    sea : kanat.physics.waves.LinearSea or None
    t : float
        When the wave elevation is taken [s].

    Returns
    -------
    ndarray, shape (N,)
    """
    position = np.asarray(position, dtype=float)
    z = position[:, -1]
    phi = np.ones(len(rows))
    top = np.maximum(z[:-1], z[1:])
    near = np.flatnonzero((rows[:, k.KIND] == k.CABLE) & (top > ROUND_OFF - elevation_bound(sea)))
    if not len(near):
        return phi
    nodes = np.union1d(near, near + 1)
    xyz = position if position.shape[1] == 3 else np.column_stack([position[:, 0], np.zeros(len(z)), z])
    height = np.full(len(z), -1.0)
    height[nodes] = heights(xyz[nodes], sea, t)
    height[(height > 0.0) & (height <= ROUND_OFF)] = 0.0
    phi[near] = 1.0 - dry_shares(height)[near]
    return phi


def wet_rows(P: np.ndarray, phi: np.ndarray) -> None:
    """Eqs. (2)-(3) into the step's interval rows ``P`` (N, n_par), in place, for the intervals
    with ``phi < 1`` (each then a section of its own: module docstring)."""
    dry = np.flatnonzero(phi < 1.0)
    if not len(dry):
        return
    share = phi[dry]
    displaced = P[dry, k.M] * P[dry, k.GRAV] - P[dry, k.W0]          # rho g A
    P[dry, k.W0] = P[dry, k.W0] + (1.0 - share) * displaced
    for column in (k.MA, k.CN, k.CT):
        P[dry, column] = share * P[dry, column]
    P[dry, k.SECTION] = -1.0 - dry


def wet_step_rows(P: np.ndarray, position: np.ndarray, sea, t: float) -> None:
    """:func:`wet_fractions` at ``position`` and ``t`` into the step's rows ``P`` (:func:`wet_rows`)."""
    wet_rows(P, wet_fractions(P, position, sea, t))
