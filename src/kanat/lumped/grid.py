"""Nodes along one cable: section joints, even spacing within each section, and a node at
every inline attachment (theory/moorings.md §4 "Sections and attachments").

A cable of sections ``(L_1, n_1), (L_2, n_2), ...`` gets ``n_k`` equal elements per section,
so every section joint is a node and each element lies in one section. An attachment at
arclength ``s_a`` sits on a node: the node already there (within :data:`SNAP_RTOL` of the
cable length), else the nearest interior node of its section is moved to ``s_a`` (the element
count stays, and no element becomes shorter than half its neighbours), else — when that node
is a joint or already holds an attachment — the element holding ``s_a`` is split in two.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

SNAP_RTOL = 1e-6      # an attachment this close (relative to the cable length) to a node sits on it


@dataclass(frozen=True)
class CableGrid:
    """Node arclengths of one cable and what lies where.

    Attributes
    ----------
    s : ndarray, shape (k + 1,)
        Unstretched arclength of each node from the ``from`` end [m], increasing.
    section : ndarray of int, shape (k,)
        Section index of each element (the one holding its midpoint).
    attachment_node : list of int
        Node index (0..k) of each attachment, in the cable's order.
    """

    s: np.ndarray
    section: np.ndarray
    attachment_node: list


def cable_grid(cable) -> CableGrid:
    """The nodes of ``cable`` (a :class:`kanat.model.cable.Cable`), module docstring."""
    bounds = cable.section_bounds()
    pieces = [np.linspace(a, b, sec.segments + 1) for (a, b), sec in zip(bounds, cable.sections)]
    s = list(np.concatenate([pieces[0]] + [p[1:] for p in pieces[1:]]))
    fixed = {0, len(s) - 1}
    k = 0
    for sec in cable.sections[:-1]:                   # joints are fixed
        k += sec.segments
        fixed.add(k)
    tolerance = SNAP_RTOL * cable.length
    placed: list[int] = []
    for item in cable.attachments:
        target = min(max(item.s, 0.0), cable.length)
        near = int(np.argmin(np.abs(np.asarray(s) - target)))
        if abs(s[near] - target) <= tolerance:
            placed.append(near)
        elif near not in fixed and near not in placed:
            s[near] = target
            placed.append(near)
        else:                                          # split the element holding the target
            at = int(np.searchsorted(s, target))
            s.insert(at, target)
            placed = [p + 1 if p >= at else p for p in placed]
            fixed = {f + 1 if f >= at else f for f in fixed}
            placed.append(at)
        fixed.add(placed[-1])
    s_arr = np.asarray(s, dtype=float)
    mid = 0.5 * (s_arr[1:] + s_arr[:-1])
    starts = np.array([a for a, _ in bounds])
    section = np.clip(np.searchsorted(starts, mid, side="right") - 1, 0, len(bounds) - 1).astype(np.int64)
    return CableGrid(s_arr, section, placed)
