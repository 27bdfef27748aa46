"""The first phase of the lumped equilibrium (:mod:`kanat.lumped.equilibrium`): Newton's method on
the *taut* residual, where slack elements resist compression.

A tension-only element has no stiffness when slack, so wherever a stiff line sits near zero strain
(a chain at 4 kN strains 5e-5) an iterate leaves some elements a little short and the tangent
loses both their axial and their transverse stiffness: Newton's step there is kilometres, and
the residual, which is blind to how slack an element is, cannot guide a line search. Newton's
method is therefore run first on the residual of the same network with every element's law
extended into compression by its slope at zero strain::

    (1)  F_taut(q) = F(q) + sum_slack k0 (l - L0) (t at i, -t at j),   k0 = f'(0+) / L0

whose tangent (the same coloured finite differences) is regular, and which equals ``F`` wherever
no element is slack. The step is capped at MAX_STEP_FRACTION of an element per node, and a node
that the step would push into the seabed deeper than both its present penetration and
SEABED_MARGIN times its static one (weight / (k_b A)) is put back to that depth along the normal:
the linear model does not see the seabed under a node above it. Steps are taken without a line
search (the kinks of contact and slack make the residual jump on the way). The phase succeeds
when the *true* residual ``F`` meets the tolerance: an element still compressed at the taut
solution leaves ``F`` unbalanced, and the caller goes on with its pseudo-transient continuation.
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import entries
from kanat.physics.seabed import seabed_of
from kanat.statics import budget

TAUT_ITERATIONS = 40         # Newton iterations of the taut phase before the caller takes over
SLACK_STRAIN = 1e-6          # strain at which a law's slope f'(0+) is taken
SECANT_STRAIN = 1e-2         # a law with no slope at zero strain (f = c e^3) takes its secant here
SEABED_MARGIN = 2.0          # a step may sink a node to this many times its static penetration


def onset_stiffness(net) -> np.ndarray:
    """Each element's axial stiffness at the onset of tension, ``k0 = f'(0+) / L0`` [N/m] (m,)."""
    slope = np.empty(net.n_elements)
    for k in range(net.n_elements):
        row = net.el_law[k]
        df = entries.elastic_row(net.law_kind, net.law_n, net.law_x, net.law_y, row, SLACK_STRAIN)[1]
        secant = entries.elastic_row(net.law_kind, net.law_n, net.law_x, net.law_y, row, SECANT_STRAIN)[0]
        slope[k] = df if df > 0.0 else secant / SECANT_STRAIN
    return slope / net.el_length


def compression_forces(net, x, stiffness) -> np.ndarray:
    """The second term of eq. (1) at every node (n, 3) [N]: slack elements pushing their ends apart."""
    d = x[net.el_j] - x[net.el_i]
    length = np.linalg.norm(d, axis=1)
    push = np.minimum(stiffness * (length - net.el_length), 0.0) / np.maximum(length, 1e-300)
    f = push[:, None] * d
    out = np.zeros_like(x)
    np.add.at(out, net.el_i, f)
    np.add.at(out, net.el_j, -f)
    return out


class SeabedGuard:
    """Puts trial nodes that a step pushed too deep back along the seabed normal (module docstring)."""

    def __init__(self, net, case, free_index):
        block, seabed = case.environment.seabed, seabed_of(case.environment)
        area = net.node_contact_area[free_index]
        self.nodes = np.flatnonzero(area > 0.0) if block is not None and seabed is not None else np.zeros(0, int)
        if len(self.nodes):
            self.seabed = seabed
            static = net.node_weight[free_index][self.nodes] / (block.stiffness * area[self.nodes])
            self.allowed = SEABED_MARGIN * static

    def __call__(self, old: np.ndarray, new: np.ndarray) -> np.ndarray:
        """``new`` (n_free, 3) with no node deeper than it may go from ``old``."""
        if not len(self.nodes):
            return new
        k = self.nodes
        depth = self.seabed.penetration(new[k])
        limit = np.maximum(self.seabed.penetration(old[k]), self.allowed)
        deep = depth > limit
        if not np.any(deep):
            return new
        new = new.copy()
        rows = k[deep]
        new[rows] += (depth[deep] - limit[deep])[:, None] * self.seabed.normal(new[rows, 0], new[rows, 1])
        return new


def taut_newton(forces, newton_step, xf, tolerance, max_step, guard, taut_forces):
    """Newton's method on eq. (1) from ``xf`` (n_free, 3).

    Parameters
    ----------
    forces : callable ``xf -> F`` (n_free, 3)
        The true static forces.
    newton_step : callable ``(xf, F_taut) -> step`` (n_free, 3), or None where the tangent is singular
        The solution of ``-dF_taut/dq step = F_taut`` at ``xf``.
    tolerance : float
        On ``max |F|`` [N].
    max_step : float
        Largest move of a node per iteration [m].
    guard : SeabedGuard
    taut_forces : callable ``xf -> F_taut`` (n_free, 3)

    Returns
    -------
    (xf, iterations) if the true residual met ``tolerance``, else None.
    """
    for iteration in range(1, TAUT_ITERATIONS + 1):
        budget.check_time()
        F = taut_forces(xf)
        if not np.all(np.isfinite(F)):
            return None
        step = newton_step(xf, F)
        if step is None:                                         # singular even when taut: leave it
            return None
        size = np.linalg.norm(step, axis=1)
        step *= np.minimum(1.0, max_step / np.maximum(size, 1e-300))[:, None]
        xf = guard(xf, xf + step)
        if np.max(np.abs(forces(xf))) <= tolerance:
            return xf, iteration
    return None
