"""What a picture of a dynamic result shows, chosen by the kind of system.

One choice, used by ``kanat run --plot`` (:mod:`kanat.report.run_plot`), the gallery
(``scripts/gallery.py``, which calls it) and the HTML report
(:mod:`kanat.report.html_result`):

========  ======================================  ==================================  =====================
kind      tensions drawn                          body histories                      geometry
========  ======================================  ==================================  =====================
towed     top tension: every end at the vessel    depth of every body                 one cable: coloured by time
moored    fairlead tensions: every end that is    surge, heave (from the first        each cable its own colour,
          not an anchor (anchor ends left out)    output) and pitch of every body     named in the legend
network   top tension, as towed                   depth of every body                 each cable its own colour,
                                                                                      named in the legend
========  ======================================  ==================================  =====================

The kind comes from the case embedded in the result (``case_yaml``): a system with an anchor
is moored, else one of several cables is a network, else towed. A result that carries no case
is a network when it has several cables, else towed, and its tensions are those at ``s = 0``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.report.geometry import cable_nodes, embedded_case

KINDS = ("towed", "moored", "network")
"""The kinds of system a picture knows."""
FAIRLEAD_OWNERS = ("body", "vessel")
"""End kinds that are a fairlead when the other end of the line is anchored."""


@dataclass(frozen=True)
class Choice:
    """What to draw of one result.

    Attributes
    ----------
    kind : {"towed", "moored", "network"}
    tension_title : str
        The tension panel's title.
    ends : dict of str to int
        Tension histories to draw: legend label -> node index.
    by_cable : bool
        Geometry coloured and named by cable (else by time, for a single cable).
    """

    kind: str
    tension_title: str
    ends: dict[str, int]
    by_cable: bool


def system_kind(ds, case=None) -> str:
    """The kind of system of a result (module docstring); ``case`` is the embedded case."""
    case = embedded_case(ds) if case is None else case
    if case is not None and any(end.kind == "anchor" for cable in case.cables for end in cable.ends):
        return "moored"
    return "network" if len(cable_nodes(ds)) > 1 else "towed"


def _end_label(end) -> str:
    return end.kind if end.name is None else f"{end.kind} {end.name}"


def _ends(ds, case, chosen) -> dict[str, int]:
    """``label -> node`` of the ends of the case's cables for which ``chosen(end, other)`` holds."""
    nodes, found = cable_nodes(ds), {}
    for cable in case.cables:
        if cable.name not in nodes:
            continue
        index = nodes[cable.name]
        for end, other, node in ((cable.from_, cable.to, index[0]), (cable.to, cable.from_, index[-1])):
            if chosen(end, other):
                found[f"{cable.name} at {_end_label(end)}"] = int(node)
    return found


def _first_ends(ds) -> dict[str, int]:
    return {f"{name} at s = 0": int(index[0]) for name, index in cable_nodes(ds).items()}


def choose(ds) -> Choice:
    """What to draw of a dynamic result (module docstring)."""
    case = embedded_case(ds)
    kind = system_kind(ds, case)
    by_cable = len(cable_nodes(ds)) > 1
    if case is None:
        return Choice(kind, "tension at the first end of each cable", _first_ends(ds), by_cable)
    if kind == "moored":
        fairleads = _ends(ds, case, lambda end, other: end.kind in FAIRLEAD_OWNERS)
        if not fairleads:                      # lines between anchors and points or free ends
            fairleads = _ends(ds, case, lambda end, other: end.kind != "anchor")
        return Choice(kind, "fairlead tensions", fairleads, by_cable)
    top = _ends(ds, case, lambda end, other: end.kind == "vessel")
    if not top:
        return Choice(kind, "tension at the first end of each cable", _first_ends(ds), by_cable)
    return Choice(kind, "top tension (at the vessel)", top, by_cable)


def body_histories(ds, kind: str) -> dict[str, tuple[str, np.ndarray]]:
    """The body histories of a kind of system: ``quantity -> (unit, values of shape (k, b))``.

    Towed systems and networks: ``depth`` [m] = -z (the result's z is up, 0 at the mean
    surface). Moored systems: ``surge`` and ``heave`` [m], the x and z displacement from the
    first output, and ``pitch`` [deg], the second attitude angle (``body_attitude``,
    R = Rz(yaw) Ry(pitch) Rx(roll)) when the result holds it. Empty without bodies.
    """
    if "body" not in ds.dims or ds.sizes["body"] == 0:
        return {}
    position = ds["body_position"].values
    if kind != "moored":
        return {"depth": ("m", -position[..., 2])}
    found = {"surge": ("m", position[..., 0] - position[0, :, 0]),
             "heave": ("m", position[..., 2] - position[0, :, 2])}
    if "body_attitude" in ds:
        found["pitch"] = ("deg", np.degrees(ds["body_attitude"].values[..., 1]))
    return found
