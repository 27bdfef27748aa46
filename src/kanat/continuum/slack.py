"""Slack events of a continuum run: where and when the cable carried compression.

A perfectly flexible cable cannot carry compression, and a line with bending stiffness carries
it only up to about the Euler load of one segment (:func:`kanat.continuum.adapter.euler_loads`).
When a cable goes slack for a moment (a tether in waves whose body rides a crest down, a top
driven towards the anchor), the box equations still have a solution for small compressions: the
run goes on through it, as WHOI Cable does, and each slack event is recorded.

An *event* is a maximal run of consecutive steps during which some node's tension falls below
``-allowed - tolerance`` (``allowed`` the node's Euler load, ``tolerance`` the compression
tolerance of the run's checks). It keeps the first and the last step time, the most
compressed node and its tension.

A line from an anchor to a body in still water that is longer than the anchor is deep lies slack
on the seabed: it rises vertically under its body and the rest lies there with zero tension,
wherever the body drifts (:func:`kanat.statics.solve3d.refuse_slack_in_still_water`), so it has no
steady state of its own to start from. :func:`pulled_start` gives the case the run starts from
instead: the same case with a small horizontal pull on the body, away from the anchor
(:data:`PULL_FRACTION` of the line's weight in water), whose steady state is a catenary lying on the
seabed with that horizontal tension; the pull is released at t = 0.
"""
from __future__ import annotations

import numpy as np

from kanat.errors import SolverError

PULL_FRACTION = 0.01
"""The horizontal pull a slack grounded line starts from, as a fraction of its weight in water."""
EVENT_FIELDS = ("start", "end", "node", "tension")
"""Columns of :attr:`SlackLog.events`: first and last time [s], node, lowest tension [N]."""


class SlackLog:
    """The slack events of one run, updated after every step.

    Parameters
    ----------
    events : ndarray, shape (k, 4), optional
        Events already recorded (a run resumed from a checkpoint): :data:`EVENT_FIELDS`.
    """

    def __init__(self, events=None):
        rows = np.zeros((0, 4)) if events is None else np.asarray(events, dtype=float).reshape(-1, 4)
        self._events = [list(row) for row in rows]
        self._open = False

    def observe(self, t: float, tension: np.ndarray, allowed: np.ndarray, tolerance: float) -> None:
        """Record the step ending at ``t`` with nodal ``tension`` (n,) [N]; a node is slack where
        ``tension + allowed < -tolerance``."""
        margin = tension + allowed
        low = int(np.argmin(margin))
        if margin[low] >= -tolerance:
            self._open = False
            return
        if not self._open:
            self._events.append([t, t, low, tension[low]])
            self._open = True
            return
        event = self._events[-1]
        event[1] = t
        if tension[low] < event[3]:
            event[2], event[3] = low, tension[low]

    @property
    def events(self) -> np.ndarray:
        """The events (k, 4): :data:`EVENT_FIELDS`."""
        return np.array(self._events, dtype=float).reshape(-1, 4)

    def note(self, s: np.ndarray, cable: str) -> str | None:
        """The run's note on its slack events (None without any), naming the worst one.

        Parameters
        ----------
        s : ndarray, shape (n,)
            Arclength of the nodes [m].
        cable : str
        """
        events = self.events
        if not len(events):
            return None
        worst = int(np.argmin(events[:, 3]))
        start, end, node, tension = events[worst]
        slack_time = float(np.sum(events[:, 1] - events[:, 0]))
        return (f"slack: cable '{cable}' went slack {len(events)} time(s) between t = {events[0, 0]:.6g} s and "
                f"t = {events[-1, 1]:.6g} s (about {slack_time:.4g} s in all); the lowest tension was "
                f"{tension:.4g} N at node {int(node)} (s = {s[int(node)]:.4g} m) at t = {start:.6g}–{end:.6g} s. "
                "The run carried the compression and went on (simulation.slack: continue); the events are the "
                "result's slack_start, slack_end, slack_node and slack_tension. The tensions during and just "
                "after an event (a snap as the line comes taut) are not resolved: model: lumped, whose elements "
                "carry no compression, resolves them")


def pulled_start(case):
    """``(case with the pull, pull [N])`` to start a slack grounded line from (module docstring), or None
    when the case's line is not one (or ``simulation.slack: stop``, which keeps the refusal)."""
    cable = case.cables[0]
    if case.simulation.slack == "stop" or cable.from_.kind != "anchor" or cable.to.kind != "body":
        return None
    from kanat.statics.setup3d import cable_problem3            # (SciPy's solvers: only for such a line)
    from kanat.statics.solve3d import refuse_slack_in_still_water

    problem = cable_problem3(case)
    try:
        refuse_slack_in_still_water(problem)
        return None
    except SolverError:
        pass
    pull = PULL_FRACTION * sum(piece.line.weight * piece.length for piece in problem.pieces)
    away = -np.sign(problem.start.position[0]) or 1.0
    body = case.bodies[cable.to.name]
    force = (body.force[0] + away * pull, body.force[1], body.force[2])
    bodies = {**case.bodies, cable.to.name: body.model_copy(update={"force": force})}
    return case.model_copy(update={"bodies": bodies}), pull
