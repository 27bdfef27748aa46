"""The wet share of continuum intervals crossing the water surface (SPEC §4).

An interval between nodes whose centrelines stand ``h_i, h_i+1`` above the surface (the mean
surface, or the wave elevation over each node: :func:`kanat.continuum.surface.heights`) is wet
over the fraction ``phi`` of eq. (3) of :mod:`kanat.physics.immersion`, the lumped model's. Only
its wet part carries buoyancy, the water's drag and added mass, and the waves' Froude–Krylov
force, so its parameter row for the step becomes::

    (1)  w   = w0 + (1 - phi) rho g A,      rho g A = m g - w0      weight: in air where dry
    (2)  m_a = phi m_a0,   C_n = phi C_n0,   C_t = phi C_t0          added mass and drag

and the kernels' displaced mass ``m - w / g`` (the Froude–Krylov term,
:mod:`kanat.continuum.kernels2d`) is ``phi rho A`` with it. An interval wholly under the surface
(``phi = 1``) keeps its row untouched, bit for bit. A partly dry interval is given a section
number of its own (negative, unlike a cable's sections): the kernels evaluate a node's load once
for the two intervals beside it when they share a section, and the partly dry interval's nodes
must take theirs with its own row.

``phi`` is taken at the node positions at the start of the step and the wave elevation at the
step's ``[ak]`` time, explicit in space as the water's kinematics are
(:mod:`kanat.continuum.water`): it is a constant of the step's Newton iteration, whose Jacobian
needs no new term, and the error it makes is of the order of the surface crossing's motion in one
step. The steady state takes it at the previous steady pass's nodes
(:data:`kanat.continuum.start.STEADY_PASSES`), a fixed point that the passes converge to.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.surface import heights
from kanat.physics.immersion import element_fractions


def elevation_bound(sea) -> float:
    """The highest the wave surface can rise above the mean surface [m]: the sum of the sea's
    amplitudes (0 without waves)."""
    return 0.0 if sea is None else float(np.sum(sea.amplitude))


def wet_fractions(rows: np.ndarray, position: np.ndarray, sea, t: float) -> np.ndarray:
    """The wetted fraction of every interval (eq. (3) of :mod:`kanat.physics.immersion`); 1 for a
    junction and for an interval that cannot reach the surface.

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
    top = np.maximum(z[:-1], z[1:]) + 0.5 * rows[:, k.DIAM]
    near = np.flatnonzero((rows[:, k.KIND] == k.CABLE) & (top > -elevation_bound(sea)))
    if not len(near):
        return phi
    nodes = np.union1d(near, near + 1)
    xyz = position if position.shape[1] == 3 else np.column_stack([position[:, 0], np.zeros(len(z)), z])
    height = np.zeros(len(z))
    height[nodes] = heights(xyz[nodes], sea, t)
    phi[near] = element_fractions(height[near], height[near + 1], rows[near, k.DIAM])
    return phi


def wet_rows(P: np.ndarray, phi: np.ndarray) -> None:
    """Eqs. (1)-(2) into the step's interval rows ``P`` (N, n_par), in place, for the intervals
    with ``phi < 1``."""
    dry = np.flatnonzero(phi < 1.0)
    if not len(dry):
        return
    share = phi[dry]
    displaced = P[dry, k.M] * P[dry, k.GRAV] - P[dry, k.W0]          # rho g A
    P[dry, k.W0] = P[dry, k.W0] + (1.0 - share) * displaced
    for column in (k.MA, k.CN, k.CT):
        P[dry, column] = share * P[dry, column]
    # a node's load is shared by its two intervals within one section (rows2d._node_loads): a partly
    # dry interval is a section of its own, so both its nodes take their loads with its own row
    P[dry, k.SECTION] = -1.0 - dry


def wet_step_rows(P: np.ndarray, position: np.ndarray, sea, t: float) -> None:
    """:func:`wet_fractions` at ``position`` and ``t`` into the step's rows ``P`` (:func:`wet_rows`)."""
    wet_rows(P, wet_fractions(P, position, sea, t))
