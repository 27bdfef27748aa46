"""What a design check reads from a run's result: the lines' tension records.

A line's **fairlead** is the end of the cable whose mean tension over the run is the larger
(the top of a catenary); its MPM is checked against the line's MBL. The records start after
the sea's start-up ramp (``environment.waves.ramp``; the whole record when there is none).
"""
from __future__ import annotations

import numpy as np

from kanat.catalog import chain_reference_breaking_load
from kanat.errors import KanatError
from kanat.model import Case

YEAR = 365.25 * 86400.0
"""Seconds in a year (Julian year) [s]."""


def analysed(ds, case: Case):
    """The part of a run's dataset after the waves' ramp (``time >= ramp``)."""
    waves = case.environment.waves
    ramp = getattr(waves, "ramp", 0.0) if waves is not None else 0.0
    kept = ds.sel(time=ds.time[ds.time >= ramp])
    if kept.sizes["time"] < 3:
        raise KanatError(f"the run of '{case.name}' keeps {kept.sizes['time']} outputs after the "
                         f"waves' ramp ({ramp:g} s): lengthen the sea state's duration")
    return kept


def cable_nodes(ds, cable: str) -> np.ndarray:
    """Indices of ``cable``'s nodes along the ``node`` dimension, from its ``from`` end."""
    nodes = np.flatnonzero(ds["cable"].values.astype(str) == cable)
    if nodes.size == 0:
        raise KanatError(f"the result holds no node of cable '{cable}'")
    return nodes


def fairlead_node(ds, cable: str) -> int:
    """The index of ``cable``'s end node with the larger mean tension."""
    nodes = cable_nodes(ds, cable)
    ends = (int(nodes[0]), int(nodes[-1]))
    means = [float(ds["tension"].isel(node=n).mean()) for n in ends]
    return ends[int(np.argmax(means))]


def fairlead_tension(ds, cable: str) -> np.ndarray:
    """Tension at ``cable``'s fairlead node, shape (n_time,) [N]."""
    return ds["tension"].isel(node=fairlead_node(ds, cable)).values


def line_types_along(case: Case, cable: str, s: np.ndarray) -> list[str]:
    """The line type at each unstretched arclength ``s`` [m] of ``cable`` (its sections in order)."""
    found = next(c for c in case.cables if c.name == cable)
    ends = np.cumsum([section.length for section in found.sections])
    index = np.minimum(np.searchsorted(ends, np.asarray(s) * (1 - 1e-12)), len(ends) - 1)
    return [found.sections[i].line_type for i in index]


def breaking_load(case: Case, cable: str) -> float:
    """The line's MBL [N]: the smallest ``breaking_load`` of its sections (the fairlead's MPM
    is compared with the weakest link)."""
    found = next(c for c in case.cables if c.name == cable)
    loads = [case.line_types[section.line_type].breaking_load for section in found.sections]
    if any(load is None for load in loads):
        missing = next(s.line_type for s, load in zip(found.sections, loads) if load is None)
        raise KanatError(f"line_types.{missing}.breaking_load: missing; the design check of cable "
                         f"'{cable}' needs the MBL (write it, or name a catalogue line)")
    return float(min(loads))


def reference_strength(case: Case, line_type: str, curve: str) -> float:
    """The reference breaking strength of a T-N curve [N] (API RP 2SK §7.3): for a chain curve,
    the MBL of ORQ chain of the line's nominal diameter; for wire rope, the rope's MBL."""
    kind = case.line_types[line_type]
    if curve.startswith("api-chain"):
        if kind.nominal_diameter is None:
            raise KanatError(f"line_types.{line_type}.nominal_diameter: missing; the T-N curve "
                             f"'{curve}' takes ORQ chain's MBL of the nominal diameter as its "
                             "reference strength")
        return chain_reference_breaking_load(kind.nominal_diameter)
    if kind.breaking_load is None:
        raise KanatError(f"line_types.{line_type}.breaking_load: missing; the T-N curve '{curve}' "
                         "takes the line's MBL as its reference strength")
    return float(kind.breaking_load)


def largest_offsets(runs: list, neutral: dict[str, np.ndarray]) -> dict[str, float]:
    """Per body, the largest horizontal distance [m] of its reference point from ``neutral``
    (body -> position, shape (3,): the intact statics) over the seeds' records."""
    if "body" not in runs[0].dims:
        return {}
    found = {}
    for k, body in enumerate(runs[0]["body"].values.astype(str)):
        if body in neutral:
            found[body] = max(float(np.hypot(*(ds["body_position"].values[:, k, :2] - neutral[body][:2]).T).max())
                              for ds in runs)
    return found


def largest_uplift(runs: list) -> dict[str, float]:
    """Per anchor, the largest upward (+z) force of the line on it [N] over the seeds' records
    (negative: the line presses the anchor down throughout)."""
    if "anchor_force" not in runs[0]:
        return {}
    names = runs[0]["anchor"].values.astype(str)
    return {name: max(float(ds["anchor_force"].values[:, k, 2].max()) for ds in runs)
            for k, name in enumerate(names)}
