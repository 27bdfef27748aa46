"""Snap loads: every slack -> taut event of every element (theory/lumped.md §7, Bezverkhyi 2006 "ривки").

An element is slack while its tension is zero (the tension-only law, kernels eq. 2).
An event starts at the first step at which a slack element carries tension, and ends
when it goes slack again (or at the end of the run). For each event the tracker keeps
its start time, the element, the peak tension and the largest rate of rise ``dT/dt``
(finite differences over the steps). Updates are vectorized over elements.
"""
from __future__ import annotations

import numpy as np

from kanat.lumped.entries import Snap

EVENT_FIELDS = ("time", "element", "peak_tension", "rise_rate")
WEIGHT_FRACTION = 0.1
"""A snap's least peak, as a fraction of its element's weight in water ``|w0| L0`` (:func:`significant`)."""


class SnapTracker:
    """Slack -> taut events, updated every step.

    Parameters
    ----------
    t0 : float
        Start time [s].
    tension : ndarray, shape (m,)
        Element tensions at ``t0`` [N]; elements taut there start no event.
    state : dict, optional
        A saved :meth:`state` to continue from (resume).
    """

    def __init__(self, t0: float, tension: np.ndarray, state: dict | None = None):
        self._pending, self._pending_rows = [], 0
        self._kernel: Snap | None = None       # the record of kernel_arrays, while its arrays stay the same
        if state is not None:
            self._arrays = {k: np.array(v) for k, v in state.items()}
            self._arrays["prev_time"] = self._arrays["prev_time"].reshape(1)
            return
        m = len(tension)
        self._arrays = {
            "taut": tension > 0.0, "active": np.zeros(m, bool), "start": np.zeros(m),
            "peak": np.zeros(m), "rate": np.zeros(m), "prev_tension": np.array(tension, float),
            "prev_time": np.array([float(t0)]),
            **{f"done_{k}": np.zeros(0) for k in EVENT_FIELDS}}

    def update(self, t: float, tension: np.ndarray) -> None:
        """Account for the tensions ``tension`` (m,) at time ``t``."""
        a = self._arrays
        rate = (tension - a["prev_tension"]) / max(t - float(a["prev_time"][0]), 1e-300)
        taut = tension > 0.0
        ended = a["active"] & ~taut
        if np.any(ended):
            self._close(np.flatnonzero(ended))
        began = taut & ~a["taut"]
        a["start"][began], a["peak"][began], a["rate"][began] = t, 0.0, 0.0
        a["active"] |= began
        act = a["active"]
        a["peak"][act] = np.maximum(a["peak"][act], tension[act])
        a["rate"][act] = np.maximum(a["rate"][act], rate[act])
        a["taut"], a["prev_tension"], a["prev_time"] = taut, np.array(tension, float), np.array([float(t)])

    def _close(self, elements: np.ndarray) -> None:
        a = self._arrays
        self._append(a["start"][elements], elements.astype(float), a["peak"][elements], a["rate"][elements])
        a["active"][elements] = False

    def _append(self, *columns) -> None:
        """Queue closed events (merged into the ``done_*`` arrays lazily: appends stay O(1))."""
        self._pending.append(np.column_stack([np.asarray(c, float) for c in columns]))
        self._pending_rows += len(self._pending[-1])

    def _merge(self) -> None:
        if self._pending:
            rows = np.concatenate(self._pending)
            a = self._arrays
            for k, column in zip(EVENT_FIELDS, rows.T):
                a[f"done_{k}"] = np.concatenate([a[f"done_{k}"], column])
            self._pending, self._pending_rows = [], 0

    def kernel_arrays(self) -> Snap:
        """The live per-element arrays as the record :func:`kanat.lumped.fast.snap_update` updates
        in place (:class:`kanat.lumped.entries.Snap`)."""
        a = self._arrays
        arrays = (a["taut"], a["active"], a["start"], a["peak"], a["rate"], a["prev_tension"], a["prev_time"])
        kept = self._kernel                    # the same record while the same arrays: the compiled call's
        if kept is None or any(old is not new for old, new in zip(kept, arrays)):    # check passes it at once
            kept = self._kernel = Snap(taut=arrays[0], active=arrays[1], start=arrays[2], peak=arrays[3],
                                       rate=arrays[4], previous_tension=arrays[5], previous_time=arrays[6])
        return kept

    def absorb(self, events: np.ndarray) -> None:
        """Record events closed by the compiled update: rows (time, element, peak, rate)."""
        if len(events):
            self._append(*events.T)

    def events(self) -> dict[str, np.ndarray]:
        """All events so far, the open ones included, sorted by time."""
        self._merge()
        a = self._arrays
        open_ = np.flatnonzero(a["active"])
        out = {"time": np.concatenate([a["done_time"], a["start"][open_]]),
               "element": np.concatenate([a["done_element"], open_.astype(float)]).astype(np.int64),
               "peak_tension": np.concatenate([a["done_peak_tension"], a["peak"][open_]]),
               "rise_rate": np.concatenate([a["done_rise_rate"], a["rate"][open_]])}
        order = np.argsort(out["time"], kind="stable")
        return {k: v[order] for k, v in out.items()}

    @property
    def count(self) -> int:
        """Number of events so far."""
        return (len(self._arrays["done_time"]) + self._pending_rows
                + int(np.count_nonzero(self._arrays["active"])))

    def state(self) -> dict[str, np.ndarray]:
        """Arrays to save in a checkpoint."""
        self._merge()
        return {k: np.array(v) for k, v in self._arrays.items()}


def significant(events: dict, element_weight) -> dict:
    """The events of ``events`` (:meth:`SnapTracker.events`) that are snap loads worth a finding: those
    whose peak tension passes the element's floor::

        (1)  T_peak > WEIGHT_FRACTION |w0| L0

    (``element_weight`` (m,): ``|w0| L0`` [N], the element's weight in water). An element resting on the
    seabed carries its neighbours' pull through the contact's give, a tension that flickers about zero
    with the contact's damping: a 150 m chain laid still in 100 m of water (5 m elements of 6.4 kN in
    water) rang 117 such events in 4 s at the implicit scheme's 0.1 s, the largest 61 N, 1 % of an
    element's weight. A snap load proper rises to tensions of the line's own scale (a released 20 m wire's
    2.16 kN, 50 times its elements' weight; :mod:`kanat.lumped.adapter`'s notes), far above eq. (1).
    The events themselves are all kept in the result; eq. (1) only decides which the notes speak of.
    """
    floor = WEIGHT_FRACTION * np.abs(np.asarray(element_weight, float))
    keep = events["peak_tension"] > floor[events["element"]]
    return {k: v[keep] for k, v in events.items()}
