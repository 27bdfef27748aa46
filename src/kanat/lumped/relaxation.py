"""Dynamic relaxation: the lumped equilibrium's fallback (:mod:`kanat.lumped.equilibrium`) where
Newton's method and its pseudo-transient continuation stall.

A line held up by many small inline floats under a weakly restrained surface float has an
equilibrium that Newton's method reaches only from close by: far from it the floats' sections
go slack and taut from one iterate to the next, the tangent changes with them, and every
regularized step is rejected. Dynamic relaxation (Day 1965; Underwood 1983, in *Computational
Methods for Transient Analysis*, ch. 5; Barnes 1999, Int. J. Space Struct. 14, 89) needs no
tangent: it integrates the fictitious motion::

    (1)  m_i dv_i/dt = F_i(q),    dq_i/dt = v_i

with the explicit central difference at a unit step ``h = 1`` and *kinetic damping*: when the
total kinetic energy ``sum m_i |v_i|^2`` passes a peak, every velocity is set to zero and the
positions are taken back to the peak (``q - h v``). The system then loses, at each peak, the
energy of its slowest mode's swing, and settles where ``F(q) = 0`` whatever path it takes through
slack and contact. The fictitious masses make the unit step stable (Gershgorin's bound on the
largest eigenvalue of ``M^-1 dF/dq``)::

    (2)  m_i = MASS_SAFETY h^2 / 2 max_r sum_c |dF_r/dq_c|,   r the rows of node i

recomputed from the tangent every REMASS_PEAKS energy peaks (a line's transverse stiffness grows
with its tension); a step that raises the residual to BLOW_UP times the start's doubles every mass
and restarts from the last peak. The relaxation stops when the largest force falls below ``target``; Newton's
method polishes the rest (quadratic convergence from there).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.statics import budget

MASS_SAFETY = 2.0          # eq. (2): the Gershgorin bound times this (slack elements may snap taut)
MASS_FLOOR = 1e-2          # of the heaviest node: the lightest a slack node may be
REMASS_PEAKS = 20          # energy peaks between recomputations of the masses, eq. (2)
BLOW_UP = 10.0             # a residual this many times the start's doubles the masses
MAX_RELAXATION_STEPS = 200_000


@dataclass(frozen=True)
class Relaxed:
    """The end of a relaxation: free nodes' positions (n_free, 3) [m], the largest force there [N],
    the steps and energy peaks it took."""
    position: np.ndarray
    residual: float
    steps: int
    peaks: int


def fictitious_masses(jacobian, floor: float, n_free: int) -> np.ndarray:
    """Eq. (2): each free node's mass (n_free,) from the sparse tangent ``dF/dq`` (3 n_free square)
    given as ``(rows, cols, values)`` with no entry repeated, at least MASS_FLOOR of the heaviest
    (a node whose elements are all slack has no tangent) and ``floor``."""
    rows, _, values = jacobian
    rows = np.bincount(rows, weights=np.abs(values), minlength=3 * n_free).reshape(-1, 3).max(axis=1)
    mass = 0.5 * MASS_SAFETY * rows
    return np.maximum(mass, max(MASS_FLOOR * np.max(mass, initial=0.0), floor))


def relax(force, tangent, xf: np.ndarray, target: float, max_steps: int = MAX_RELAXATION_STEPS) -> Relaxed:
    """Eq. (1) with kinetic damping from ``xf`` until ``max |F| <= target`` or ``max_steps``.

    Parameters
    ----------
    force : callable
        ``force(q) -> F``, the free nodes' static forces (n_free, 3) [N] at positions ``q``.
    tangent : callable
        ``tangent(q) -> dF/dq``, sparse (3 n_free square) [N/m], as ``(rows, cols, values)``.
    xf : ndarray, shape (n_free, 3)
        Start [m].
    target : float
        Largest force at which the relaxation stops [N].
    max_steps : int

    Returns
    -------
    Relaxed
        The state at the lowest residual met (the last peak's, or the target's).
    """
    x = np.array(xf, dtype=float)
    F = force(x)
    floor = 1e-12 * max(float(np.max(np.abs(F))), 1.0)
    mass = fictitious_masses(tangent(x), floor, len(x))
    v = np.zeros_like(x)
    energy, peaks, since_mass = 0.0, 0, 0
    anchor_x, first_norm = x.copy(), float(np.max(np.abs(F)))
    best = (first_norm, x.copy())
    for step in range(1, max_steps + 1):
        if step % 1000 == 0:
            budget.check_time()
        v += F / mass[:, None]
        x += v
        F = force(x)
        norm = float(np.max(np.abs(F)))
        if norm < best[0]:
            best = (norm, x.copy())
        if norm <= target:
            return Relaxed(x, norm, step, peaks)
        if not np.isfinite(norm) or norm > BLOW_UP * max(first_norm, target):
            mass *= 2.0                                     # unstable: heavier, from the last peak
            x, v, energy = anchor_x.copy(), np.zeros_like(x), 0.0
            F = force(x)
            continue
        kinetic = float(np.sum(mass[:, None] * v * v))
        if kinetic < energy:                                # a peak: back to it, at rest
            x -= v
            v[:] = 0.0
            energy, peaks, since_mass = 0.0, peaks + 1, since_mass + 1
            F = force(x)
            anchor_x = x.copy()
            if since_mass >= REMASS_PEAKS:
                mass = np.maximum(mass, fictitious_masses(tangent(x), floor, len(x)))
                since_mass = 0
        else:
            energy = kinetic
    return Relaxed(best[1], best[0], max_steps, peaks)
