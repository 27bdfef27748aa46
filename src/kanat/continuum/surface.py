"""The check that a buoyant part of a continuum cable stays in the water, and the note on a part
above it.

An interval crossing the water surface carries its buoyancy, drag and added mass on the share of
its chord under it only (:mod:`kanat.continuum.wetted`, eq. (1) below for the share above), as the
lumped model's elements do (:mod:`kanat.lumped.kernels`). A buoyant line out of the water then has
no buoyancy left to lift it, but the model cannot float it either: a line lying along the surface
has intervals that are wholly wet or wholly dry as a whole, with no equilibrium in between, and a
still buoyant free tail too long for its tow depth stands straight up out of the sea as a column in
compression (268.9 m above it for ``examples/towed_array.yaml`` with the array's weight in water
reversed, the tow point 30 m deep and the vessel still). A node of a buoyant interval whose
centreline is more than half a diameter above the water surface (the mean surface, or the wave
elevation over the node) is wholly dry, and fails the run; a deeper tow point or a shorter buoyant
part keeps it in the water.

A heavy part above the water (a tow point on deck, a stern heaving out of the sea) is not
refused: it hangs with its weight in air and without the water's drag and added mass.
:class:`DryLength` keeps the largest length of cable whose centreline is above the surface over a
run, for the run's note (interval by interval, the part of each interval above the surface by
linear interpolation of its ends' heights)::

    (1)  L_dry = sum_i  ds_i * f(h_i, h_i+1),   f = 1 both ends above, 0 both below,
                                                 max(h_i, h_i+1) / |h_i+1 - h_i| crossing

with ``h`` a node's height above the surface (the mean surface, or the wave elevation over it).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.physics.immersion import dry_length                   # eq. (1): kanat.physics.immersion eq. (3)

DRY_MARGIN = 1e-3
"""How far [m] beyond half a diameter above the surface a node counts as out of the water (round-off
on a line floating at the surface)."""


def buoyant_nodes(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The nodes of buoyant intervals and the largest diameter of their buoyant intervals.

    Parameters
    ----------
    rows : ndarray, shape (n - 1, P)
        The grid's parameter rows (:mod:`kanat.continuum.grid`).

    Returns
    -------
    nodes : ndarray of int
        Nodes that end a cable interval with ``w < 0`` (the first end, prescribed, excluded).
    diameter : ndarray, shape (len(nodes),)
        [m].
    """
    n = len(rows) + 1
    buoyant = (rows[:, k.KIND] == k.CABLE) & (rows[:, k.W0] < 0.0)
    diameter = np.zeros(n)
    for side in (0, 1):
        which = np.flatnonzero(buoyant) + side
        diameter[which] = np.maximum(diameter[which], rows[buoyant, k.DIAM])
    nodes = np.flatnonzero(diameter > 0.0)
    nodes = nodes[nodes > 0]
    return nodes, diameter[nodes]


def dry_buoyant_node(rows: np.ndarray, height: np.ndarray) -> tuple[int, float] | None:
    """The buoyant node highest out of the water, ``(node, height of its centreline above the
    surface)`` [m], or None when every buoyant node is in it (module docstring).

    Parameters
    ----------
    rows : ndarray, shape (n - 1, P)
    height : ndarray, shape (n,)
        Every node's height above the water surface [m] (:func:`kanat.physics.immersion.heights`).
    """
    nodes, diameter = buoyant_nodes(rows)
    if not len(nodes):
        return None
    height = height[nodes]
    worst = int(np.argmax(height - 0.5 * diameter))
    if height[worst] - 0.5 * diameter[worst] <= DRY_MARGIN:
        return None
    return int(nodes[worst]), float(height[worst])


class DryLength:
    """The largest eq. (1) over a run's outputs, its time, and the note that says so."""

    def __init__(self):
        self.length, self.time = 0.0, 0.0

    def observe(self, s: np.ndarray, height: np.ndarray, t: float) -> float:
        """One output: the nodes' arclengths ``s`` and heights above the surface at ``t``
        (:func:`kanat.physics.immersion.heights`); returns its eq. (1)."""
        length = dry_length(s, height)
        if length > self.length:
            self.length, self.time = length, t
        return length

    def note(self, cable: str) -> str | None:
        """The run's note, or None when no part of the cable was ever above the surface."""
        if self.length <= 0.0:
            return None
        return (f"up to {self.length:.4g} m of cable '{cable}' was above the water surface (at t = "
                f"{self.time:.6g} s); it weighed its weight in air there, without the water's drag and added mass")
