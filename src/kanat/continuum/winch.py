"""A winch at the first cable's 'from' end: pay-out and haul-in with an adapting grid (theory/moorings.md §9).

Node 0 is the winch point, fixed to the vessel; every other node is a material point of the
cable. Paying out at ``c`` [m/s of unstretched length] (``winch`` steps, positive out), new cable
leaves the winch: the first interval grows, ``d(ds_0)/dt = c``, and the cable's velocity at the
winch is the tow point's plus ``c`` along the tangent. Since node 0 is not a material point, the
first interval's rows use the material rate at node 0, ``dY/dt|node + c dY/ds``: the box rows get
``+ c g / 2`` in their mean rate (:mod:`kanat.continuum.rows2d`), with ``ds_0`` at the scheme's
``[ak]`` level.

The grid adapts as WHOI Cable's does: when the first interval exceeds :data:`SPLIT` times the
first section's segment length ``ds``, a node is inserted ``ds`` from node 1 (so every interior
node stays on the section's grid of material points ``ds`` apart), its state interpolated
linearly; when hauling in shrinks it below :data:`MERGE` times ``ds``, node 1 (a material point
now on the drum) is removed. The unstretched length in the water is ``L(t) = L + int c dt``, held
exactly by the interval lengths, so the mass of cable in the water is ``m L(t)``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.errors import SolverError

SPLIT = 1.5   # insert a node when the first interval exceeds this many segment lengths
MERGE = 0.5   # remove node 1 when the first interval falls below this many segment lengths


@dataclass(frozen=True)
class Winch:
    """The winch's schedule.

    Attributes
    ----------
    steps : tuple of (start, end, rate)
        Times [s] and pay-out rates [m/s] (negative: haul-in).
    segment : float
        The first section's segment length ``ds`` [m].
    """

    steps: tuple
    segment: float

    @classmethod
    def from_case(cls, case, segment: float) -> Winch | None:
        if not case.winch:
            return None
        return cls(tuple((w.start, w.end, w.rate) for w in case.winch), segment)

    def rate(self, t: float) -> float:
        """Pay-out speed at ``t`` [m/s] (a step holds on ``start < t <= end``)."""
        return sum(rate for start, end, rate in self.steps if start < t <= end + 1e-12)

    def paid(self, t: float) -> float:
        """Length paid out by ``t`` [m]."""
        return sum(rate * (min(max(t, start), end) - start) for start, end, rate in self.steps)

    def step_rows(self, rows: np.ndarray, t: float, dt: float, ak: float) -> tuple[np.ndarray, np.ndarray]:
        """The rows of a step from ``t`` (first interval at the ``[ak]`` level, with the convective
        speed) and the rows at ``t + dt``."""
        rate = self.rate(t + dt)
        during, after = rows.copy(), rows.copy()
        during[:, k.CONV] = 0.0
        during[0, k.CONV] = rate
        during[0, k.DS] = rows[0, k.DS] + (1.0 - ak) * rate * dt
        after[0, k.DS] = rows[0, k.DS] + rate * dt
        return during, after

    def regrid(self, rows: np.ndarray, arrays: dict, s: np.ndarray):
        """Split or merge the first interval (module docstring).

        Parameters
        ----------
        rows : ndarray (n - 1, n_par)
        arrays : dict of str to ndarray
            Nodal arrays (first axis: nodes) to split or merge with the grid (state, rate, positions).
        s : ndarray (n,)
            Material arclength of the nodes at t = 0 (node 0: the winch point, nan).

        Returns
        -------
        rows, arrays, s
        """
        first = rows[0, k.DS]
        if first > SPLIT * self.segment:
            keep = first - self.segment
            fraction = keep / first
            new = {name: np.insert(a, 1, a[0] + fraction * (a[1] - a[0]), axis=0) for name, a in arrays.items()}
            rows = np.insert(rows, 0, rows[0], axis=0)
            rows[0, k.DS], rows[1, k.DS] = keep, self.segment
            rows[1, k.CONV] = 0.0
            return rows, new, np.insert(s, 1, s[1] - self.segment)
        if first < MERGE * self.segment:
            if len(rows) < 2 or rows[1, k.KIND] == k.JUNCTION or rows[1, k.SECTION] != rows[0, k.SECTION]:
                raise SolverError("the winch has hauled in all of the first section up to "
                                  + ("an attachment" if len(rows) > 1 and rows[1, k.KIND] == k.JUNCTION
                                     else "its end") + "; haul in less")
            merged = first + rows[1, k.DS]
            rows = np.delete(rows, 1, axis=0)
            rows[0, k.DS] = merged
            return rows, {name: np.delete(a, 1, axis=0) for name, a in arrays.items()}, np.delete(s, 1)
        return rows, arrays, s


def material_stations(case, grid_s: np.ndarray, winch: Winch, dt: float, duration: float) -> np.ndarray:
    """Material arclengths (at t = 0) of every node that is ever in the water, the winch point first
    (``s = 0``); stations paid out later are negative (on the drum at t = 0)."""
    first = grid_s[1]
    length = first
    lowest = first
    steps = int(round(duration / dt))
    for i in range(steps):
        length += winch.rate((i + 1) * dt) * dt
        while length > SPLIT * winch.segment:
            length -= winch.segment
            lowest -= winch.segment
        if length < MERGE * winch.segment:
            length += winch.segment
    count = int(round((first - lowest) / winch.segment))
    extra = first - winch.segment * np.arange(count, 0, -1)
    return np.concatenate([[0.0], extra, grid_s[1:]])
