"""The implicit scheme's band order (kanat.lumped.band_order) against SciPy's reverse
Cuthill–McKee, the oracle it reproduces without importing SciPy in a run: the same order on the
shipped lumped networks (a three-leg mooring, trawl gear with bodies, a lazy wave, a buoy
mooring, WHOI Cable's branched and multi-leg systems and loops) and on random forests, and the same half-width."""
import warnings

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee

from kanat.io import load_case
from kanat.lumped.band_order import band_order
from kanat.lumped.network import build_network

from helpers import EXAMPLES

CASES = ["design/quasi_static.yaml", "trawl_head_8s_1to2.yaml", "lazy_wave.yaml", "mooring_buoy_waves.yaml",
         "whoi/branch.yaml", "whoi/multi_leg.yaml", "whoi/loops.yaml"]


def scipy_order(net, free_index):
    """The order the implicit scheme took before (SciPy's RCM on the free nodes' graph)."""
    n_free = len(free_index)
    local = -np.ones(net.n_nodes, dtype=np.int64)
    local[free_index] = np.arange(n_free)
    a, b = local[np.r_[net.el_i, net.bend[0]]], local[np.r_[net.el_j, net.bend[2]]]
    keep = (a >= 0) & (b >= 0)
    graph = sp.coo_matrix((np.ones(2 * keep.sum()), (np.r_[a[keep], b[keep]], np.r_[b[keep], a[keep]])),
                          shape=(n_free, n_free)).tocsr()
    order = reverse_cuthill_mckee(graph, symmetric_mode=True)
    rank = np.empty(n_free, dtype=np.int64)
    rank[order] = np.arange(n_free)
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free_index] = rank
    return position, int(np.max(np.abs(rank[a[keep]] - rank[b[keep]]), initial=0))


@pytest.mark.parametrize("name", CASES)
def test_band_order_is_scipys_reverse_cuthill_mckee(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(EXAMPLES / name)
    net = build_network(case)
    free = np.flatnonzero(net.free)
    position, bandwidth = band_order(net, free)
    want, want_bandwidth = scipy_order(net, free)
    np.testing.assert_array_equal(position, want)
    assert bandwidth == want_bandwidth
    assert sorted(position[free]) == list(range(len(free)))


class RandomTree:
    """A graph shaped as :func:`band_order` reads a network: elements ``el_i - el_j``, no bending."""

    def __init__(self, n, seed):
        rng = np.random.default_rng(seed)
        self.n_nodes = n
        parent = np.array([rng.integers(0, k) for k in range(1, n)])
        self.el_i, self.el_j = parent, np.arange(1, n)
        empty = np.zeros(0, dtype=np.int64)
        self.bend = (empty, empty, empty)


@pytest.mark.parametrize("seed", range(4))
def test_band_order_is_scipys_on_random_trees_and_forests(seed):
    """Trees of 300 nodes with ties in degree everywhere, some nodes prescribed (cutting the tree
    into a forest: every part is ordered in turn)."""
    net = RandomTree(300, seed)
    free = np.sort(np.random.default_rng(seed + 10).choice(300, 270, replace=False))
    position, bandwidth = band_order(net, free)
    want, want_bandwidth = scipy_order(net, free)
    np.testing.assert_array_equal(position, want)
    assert bandwidth == want_bandwidth
