"""Node tensions of the lumped model's result (``tension(time, node)``).

Node tension is the mean of the two adjacent element tensions at interior nodes, and
extrapolated linearly from the first two elements at cable ends (``1.5 T_0 - 0.5 T_1``,
clipped at 0 on ropes; a bar's, ``compression_stiffness > 0``, may be negative), second-order
accurate like the elements' own midpoint values.
"""
from __future__ import annotations

import numpy as np


class NodeTension:
    """Weights mapping element tensions to the output nodes (module docstring)."""

    def __init__(self, net):
        ia, ib, wa, wb = [], [], [], []
        for c, first in enumerate(net.cable_first_element):
            n = int(np.count_nonzero(net.segment_cable == net.cable_names[c]))
            e = first + np.arange(n)
            if n == 1:
                ia += [e[0], e[0]]
                ib += [e[0], e[0]]
                wa += [1.0, 1.0]
                wb += [0.0, 0.0]
                continue
            ia += [e[0], *e[:-1], e[-1]]
            ib += [e[1], *e[1:], e[-2]]
            wa += [1.5, *([0.5] * (n - 1)), 1.5]
            wb += [-0.5, *([0.5] * (n - 1)), -0.5]
        self.ia, self.ib = np.array(ia, np.int64), np.array(ib, np.int64)
        self.wa, self.wb = np.array(wa), np.array(wb)
        self.floor = np.where(net.el_compression[self.ia] > 0.0, -np.inf, 0.0)   # bars push: no floor

    def __call__(self, T: np.ndarray) -> np.ndarray:
        return np.maximum(self.floor, self.wa * T[self.ia] + self.wb * T[self.ib])
