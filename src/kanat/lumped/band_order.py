"""The order of the free nodes in the implicit scheme's band tangent
(:mod:`kanat.lumped.fast_implicit`): reverse Cuthill–McKee.

Cuthill & McKee (1969, Proc. 24th ACM National Conference, 157-172) number a graph's nodes by
breadth-first search from a node of least degree, each new level's nodes in increasing degree;
reversed (George 1971), the order has the same bandwidth and less fill in an LU. This is
SciPy's ``scipy.sparse.csgraph.reverse_cuthill_mckee`` step for step — the same seeds (NumPy's
``argsort`` of the degrees), neighbours in increasing index, each level sorted by degree
stably — so the order is the same (tests), without importing SciPy's sparse modules in every run
(:mod:`kanat.lumped.node_systems` says why).
"""
from __future__ import annotations

import numpy as np


def band_order(net, free_index) -> tuple[np.ndarray, int]:
    """Position of each free node in the band order (n_nodes,; -1 for prescribed nodes) and the
    band's half-width in nodes (3 x 3 blocks).

    Parameters
    ----------
    net : kanat.lumped.network.Network
        Its elements join nodes ``el_i, el_j``; its bending triples join ``bend[0]`` and ``bend[2]``.
    free_index : ndarray of int, shape (n_free,)
    """
    n_free = len(free_index)
    local = -np.ones(net.n_nodes, dtype=np.int64)
    local[free_index] = np.arange(n_free)
    a, b = local[np.r_[net.el_i, net.bend[0]]], local[np.r_[net.el_j, net.bend[2]]]   # bending joins i-1, i+1
    keep = (a >= 0) & (b >= 0)
    rank = np.empty(n_free, dtype=np.int64)
    rank[reverse_cuthill_mckee(_neighbours(a[keep], b[keep], n_free))] = np.arange(n_free)
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free_index] = rank
    return position, int(np.max(np.abs(rank[a[keep]] - rank[b[keep]]), initial=0))


def _neighbours(a: np.ndarray, b: np.ndarray, n: int) -> list[list[int]]:
    """Each node's neighbours (edges ``a - b`` both ways, repeated ones once), in increasing index."""
    joined = [set() for _ in range(n)]
    for i, j in zip(a.tolist(), b.tolist()):
        if i != j:
            joined[i].add(j)
            joined[j].add(i)
    return [sorted(near) for near in joined]


def reverse_cuthill_mckee(neighbours: list[list[int]]) -> np.ndarray:
    """The reverse Cuthill–McKee order (n,) of a graph given by each node's ``neighbours``
    (in increasing index; no node its own neighbour), every connected part in turn."""
    n = len(neighbours)
    degree = np.array([len(near) for near in neighbours], dtype=np.int32)
    seeds = np.argsort(degree)                     # SciPy's: least degree first, ties as NumPy's sort leaves them
    visited = np.zeros(n, dtype=bool)
    order: list[int] = []
    for seed in seeds.tolist():
        if visited[seed]:
            continue
        visited[seed] = True
        order.append(seed)
        start = len(order) - 1
        while start < len(order):
            node = order[start]
            start += 1
            level = [j for j in neighbours[node] if not visited[j]]
            visited[level] = True
            order.extend(sorted(level, key=degree.__getitem__))   # stable, as SciPy's insertion sort
    return np.array(order[::-1], dtype=np.int64)
