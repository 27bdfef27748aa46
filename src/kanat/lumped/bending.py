"""Bending stiffness in the lumped model: moments from the discrete curvature at interior nodes.

Each interior node ``i`` of a cable joins its elements ``a = (i-1, i)`` and ``b = (i, i+1)``,
with unit tangents ``t_a = d_a / |d_a|``, ``t_b = d_b / |d_b|`` (``d_a = x_i - x_i-1``,
``d_b = x_i+1 - x_i``). A beam's bending energy ``int EI kappa^2 / 2 ds`` over the half
elements about the node, with the turning angle ``theta`` between the tangents and
``kappa = theta / l`` over ``l = (L0_a + L0_b) / 2``, is ``EI theta^2 / (2 l)``; with
``|t_b - t_a|^2 = 2 (1 - cos theta) = theta^2 + O(theta^4)``::

    (1)  E_i = k_i (1 - t_a . t_b),            k_i = EI / l   [N m]
    (2)  g_a = dE/dd_a = -k (I - t_a t_a^T) t_b / |d_a|,   g_b = dE/dd_b = -k (I - t_b t_b^T) t_a / |d_b|
    (3)  F_i-1 += g_a,   F_i += g_b - g_a,   F_i+1 -= g_b         (F = -dE/dx)

The forces are exact derivatives of (1), so they sum to zero and conserve energy; both ends
are pinned (moment-free): nodes with one element carry no bending energy. ``EI`` of a node is
the mean of its two elements' line types (sections). For the implicit tangent the Hessian of
(1) is taken in the Gauss-Newton form, exact on a straight line and positive semidefinite
(Nocedal & Wright, Numerical Optimization, 2nd ed., §10.3): with ``r = t_b - t_a`` and
``E = k |r|^2 / 2``,

    (4)  J_i-1 = P_a / |d_a|,   J_i = -P_a / |d_a| - P_b / |d_b|,   J_i+1 = P_b / |d_b|,
         K_pq = k J_p^T J_q    (P = I - t t^T; p, q in i-1, i, i+1)

This is MoorDyn v2's bending of lines (Hall, 2023, MoorDyn v2 documentation: curvature from the
turning angle at each node, moments ``EI kappa``) in an energy form whose derivative gives the
forces and whose second derivative the tangent. The plain-Python twin :func:`bending_energy`
gives (1) for the tests, which check (3) against its numerical gradient.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import kernel


def bending_triples(el_i, el_j, el_cable, el_stiffness, el_length):
    """The interior nodes of every cable as ``(before, node, after, k, l)``: consecutive elements of a
    cable sharing a node, ``k = EI / l`` of eq. (1) and ``l`` (arrays of length ``n_triples``), for
    the nodes where the mean ``EI`` is positive."""
    before, node, after, k, span = [], [], [], [], []
    for e in range(len(el_i) - 1):
        if el_cable[e] != el_cable[e + 1] or el_j[e] != el_i[e + 1]:
            continue
        stiffness = 0.5 * (el_stiffness[e] + el_stiffness[e + 1])
        if stiffness > 0.0:
            before.append(el_i[e])
            node.append(el_j[e])
            after.append(el_j[e + 1])
            span.append(0.5 * (el_length[e] + el_length[e + 1]))
            k.append(stiffness / span[-1])
    return (np.array(before, dtype=np.int64), np.array(node, dtype=np.int64), np.array(after, dtype=np.int64),
            np.array(k, dtype=float), np.array(span, dtype=float))


@kernel
def bending_forces(x, before, node, after, k, F):
    """Add eq. (3) to ``F`` (n, 3) for every triple."""
    for p in range(node.shape[0]):
        h, i, j = before[p], node[p], after[p]
        a0, a1, a2 = x[i, 0] - x[h, 0], x[i, 1] - x[h, 1], x[i, 2] - x[h, 2]
        b0, b1, b2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        la = np.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
        lb = np.sqrt(b0 * b0 + b1 * b1 + b2 * b2)
        a0, a1, a2 = a0 / la, a1 / la, a2 / la
        b0, b1, b2 = b0 / lb, b1 / lb, b2 / lb
        c = a0 * b0 + a1 * b1 + a2 * b2
        ga0, ga1, ga2 = -k[p] * (b0 - c * a0) / la, -k[p] * (b1 - c * a1) / la, -k[p] * (b2 - c * a2) / la
        gb0, gb1, gb2 = -k[p] * (a0 - c * b0) / lb, -k[p] * (a1 - c * b1) / lb, -k[p] * (a2 - c * b2) / lb
        F[h, 0] += ga0
        F[h, 1] += ga1
        F[h, 2] += ga2
        F[i, 0] += gb0 - ga0
        F[i, 1] += gb1 - ga1
        F[i, 2] += gb2 - ga2
        F[j, 0] -= gb0
        F[j, 1] -= gb1
        F[j, 2] -= gb2


@kernel
def bending_blocks(x, before, node, after, k, J, K):
    """The Gauss-Newton tangent of eq. (4): ``K`` (n_triples, 3, 3, 3, 3) holds ``K_pq`` for ``p, q``
    in (before, node, after); ``J`` (3, 3, 3) is work space."""
    for p in range(node.shape[0]):
        h, i, j = before[p], node[p], after[p]
        la, lb = 0.0, 0.0
        for r in range(3):
            la += (x[i, r] - x[h, r]) ** 2
            lb += (x[j, r] - x[i, r]) ** 2
        la, lb = np.sqrt(la), np.sqrt(lb)
        for r in range(3):
            for q in range(3):
                eye = 1.0 if r == q else 0.0
                pa = (eye - (x[i, r] - x[h, r]) * (x[i, q] - x[h, q]) / (la * la)) / la
                pb = (eye - (x[j, r] - x[i, r]) * (x[j, q] - x[i, q]) / (lb * lb)) / lb
                J[0, r, q] = pa
                J[1, r, q] = -pa - pb
                J[2, r, q] = pb
        for m in range(3):
            for n in range(3):
                for r in range(3):
                    for q in range(3):
                        s = 0.0
                        for w in range(3):
                            s += J[m, w, r] * J[n, w, q]
                        K[p, m, n, r, q] = k[p] * s


def bending_energy(x, before, node, after, k) -> float:
    """Eq. (1) summed over the triples (the tests' twin of :func:`bending_forces`)."""
    a = x[node] - x[before]
    b = x[after] - x[node]
    ta = a / np.linalg.norm(a, axis=1)[:, None]
    tb = b / np.linalg.norm(b, axis=1)[:, None]
    return float(np.sum(k * (1.0 - np.einsum("kr,kr->k", ta, tb))))


def bending_frequency(node, k, length, node_mass) -> float:
    """The bending's highest angular frequency [1/s] for the explicit schemes' safe step
    (:mod:`kanat.lumped.stepping`): eq. (4) on a straight line of elements ``l`` assembles to ``k / l^2``
    times the fourth difference ``[1, -4, 6, -4, 1]``, whose largest eigenvalue is 16, so
    ``omega = 4 sqrt(k / (m l^2))`` for a node of mass ``m`` (``length`` the triples' ``l``)."""
    if not len(node):
        return 0.0
    mass = node_mass[node]
    free = mass > 0
    if not np.any(free):
        return 0.0
    return float(np.max(4.0 * np.sqrt(k[free] / (mass[free] * length[free] ** 2))))
