"""Physical checks of a steady state: what a dynamic run checks at every output, applied to
every steady solution before its status is ``ok`` (docs/statics.md, "Checks of a steady state").

A steady solver can converge on a state no cable can take (a 100 m leg stretched to an anchor
600 m away, a towed body under the seabed); its residual is small, so the solver alone cannot
tell. :func:`check_steady` looks at the nodes of every cable — positions ``(n, 3)``, tensions
``(n,)`` at unstretched arclengths ``s`` — and applies, in order (the first failure is the one
reported, as ``<check>: ...``):

1. ``finite``: every position and tension is finite.
2. ``strain``: the strain of every node (the line's law inverted at its tension) and of every
   element between two nodes (chord over unstretched length, minus 1) within the line's limit
   (:meth:`kanat.model.LineType.strain_limit`) and within its ``elastic_law`` table, beyond
   which the law is only extrapolated.
3. ``tension``: no tension above :data:`ABSURD_BREAKING_MULTIPLE` times the line's breaking
   load (a failure); above the breaking load itself it is a warning.
4. ``reach``: an anchored end sits on its anchor, and no node is farther from either end of
   its cable than the arclength between them stretched to the line's limit.
5. ``seabed``: no node deeper below the seabed (``environment.depth`` is a seabed, with or
   without a ``seabed`` block) than the contact allows: :data:`PENETRATION_MARGIN` times the
   static penetration ``w / (k d)`` of its line plus :data:`PENETRATION_FLOOR` with a
   ``seabed`` block, :data:`PENETRATION_FLOOR` without one (statics' seabed is rigid).
6. ``grounded``: the length resting on the seabed (a statics result's ``grounded_length``)
   between 0 and the cable's length.
7. ``bodies``: every body (given its positions) where its cables hold it, not above the water
   surface when its loads are those of a submerged body, and not wholly under the seabed
   (:mod:`kanat.statics.body_checks`); not made on a dynamic run's start ``as_given``, which is
   no steady state (:func:`checks_of_state`).

A statics result from a solver that takes every cable as submerged (the single-cable and network
statics, not the lumped model's equilibrium) also gets a warning for each cable with a part above the
water surface (:func:`dry_parts`; :func:`check_result`), and fails where that part is of a buoyant
line type, held up in the air by buoyancy it does not have there (``buoyant_above_water``).

A node that holds a body (a cable end at a body, an attachment) is named with it in the messages
(``body 'sled' at cable 'tow' node 100 (s = 1000 m)``).

The checks read a case and node arrays only, so the statics (single cables and networks) and the
lumped model's equilibrium use this one module; so does the initial state of a dynamic run
(:mod:`kanat.dynamics`), for the checks its model's own ``check()`` of every output does not
make (:data:`LEFT_BY_DYNAMIC_MODELS`: the models check strain and the seabed with their own
contact models).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Protocol

import numpy as np

from kanat.physics.immersion import dry_shares
from kanat.physics.seabed import PENETRATION_FLOOR, PENETRATION_MARGIN, seabed_of
from kanat.statics.body_checks import check_bodies

ABSURD_BREAKING_MULTIPLE = 10.0
"""A tension this many times the line's breaking load fails a steady state: safety factors on
the breaking load are 1.5 to 3, so ten times it is no load a line meets but a wrong model
(lengths, speeds, currents or drag coefficients)."""
PLACEMENT_TOLERANCE = 1e-3
"""An anchored end may sit this far from its anchor [m] (plus :data:`RELATIVE_TOLERANCE` of
the cable's length)."""
RELATIVE_TOLERANCE = 1e-6
"""Round-off allowed on strains and on distances, as a fraction of the quantity."""
LEFT_BY_DYNAMIC_MODELS = ("tension", "reach", "bodies")
"""The checks a dynamic model's own ``check()`` does not make of its outputs (it checks strain and
the seabed with its own contact model, the run loop finiteness): those :mod:`kanat.dynamics` adds
at t = 0."""
POLYNOMIAL_SAMPLES = 2001
"""Strains sampled on [0, 1] to invert a polynomial ``elastic_law``."""


class CableNodes(Protocol):
    """What the checks read of one cable (:class:`kanat.statics.solution.CableSolution`,
    :class:`kanat.statics.network_result.NetworkCable` or :class:`NodeArrays`)."""

    s: np.ndarray
    position: np.ndarray
    tension: np.ndarray


@dataclass(frozen=True)
class NodeArrays:
    """One cable's nodes: unstretched arclength ``s`` (n,) [m] from its ``from`` end, positions
    (n, 3) [m] and tensions (n,) [N]."""

    s: np.ndarray
    position: np.ndarray
    tension: np.ndarray


@dataclass(frozen=True)
class Verdict:
    """The outcome of :func:`check_steady`.

    Attributes
    ----------
    failure : str or None
        ``<check>: <message>`` of the first failed check; None when all pass.
    warnings : tuple of str
        Sentences for the user (a tension above the breaking load).
    """

    failure: str | None = None
    warnings: tuple[str, ...] = ()

    @property
    def status(self) -> str:
        """``ok`` or ``failed: <check>: <message>`` (a result's ``status``)."""
        return "ok" if self.failure is None else f"failed: {self.failure}"


def check_steady(case, cables: Mapping[str, CableNodes], when: str = "the steady state",
                 only: tuple[str, ...] | None = None, bodies: Mapping | None = None,
                 attitudes: Mapping | None = None, start: bool = False) -> Verdict:
    """Run the checks of the module docstring on the nodes of every cable of ``case``.

    Parameters
    ----------
    case : kanat.model.Case
    cables : mapping of str to CableNodes
        Every cable of the case by name; ``s`` ascending from the cable's ``from`` end (nodes
        at ``s < 0``, line still on a winch's drum, are not checked).
    when : str
        Names the state in the messages (``the initial state`` for a dynamic run's).
    only : tuple of str, optional
        The names of the checks to make (e.g. :data:`LEFT_BY_DYNAMIC_MODELS`); None: all.
    bodies : mapping of str to array_like, shape (3,), optional
        Body positions (a rigid body's reference point) [m]; None: no ``bodies`` check.
    attitudes : mapping of str to array_like, shape (3,), optional
        Roll, pitch, yaw of the bodies [rad] where known (rigid bodies' fairleads).
    start : bool
        The state is a dynamic run's initial state. A start ``as_given``
        (``simulation.initial_state``) is then no steady state: a body may start anywhere (a buoy
        dropped from the air), so the ``bodies`` check is not made (:func:`checks_of_state`).

    Returns
    -------
    Verdict
    """
    warnings: list[str] = []
    only = checks_of_state(case, only, start)
    prepared = [(cable, _Nodes(case, cable, cables[cable.name])) for cable in case.cables if cable.name in cables]
    checks = [check for check in CHECKS if only is None or check.__name__[1:] in only]
    with np.errstate(over="ignore", invalid="ignore"):      # a state at 1e200 m fails, it does not warn
        for check in checks:
            for cable, nodes in prepared:
                failure = check(case, cable, nodes, when, warnings) if len(nodes.s) > 1 else None
                if failure is not None:
                    return Verdict(f"{check.__name__[1:]}: {failure}", tuple(warnings))
        if bodies is not None and (only is None or "bodies" in only):
            failure = check_bodies(case, cables, bodies, attitudes, when, warnings)
            if failure is not None:
                return Verdict(f"bodies: {failure}", tuple(warnings))
    return Verdict(None, tuple(warnings))


def checks_of_state(case, only: tuple[str, ...] | None, start: bool) -> tuple[str, ...] | None:
    """The checks a state must pass: ``only`` (None: all), less ``bodies`` for a dynamic run's
    start as given, which places the bodies where the case writes them, in or out of the water,
    and is no steady state."""
    given = start and getattr(case.simulation, "initial_state", "equilibrium") == "as_given"
    if not given:
        return only
    every = [check.__name__[1:] for check in CHECKS] + ["bodies"]
    return tuple(name for name in (every if only is None else only) if name != "bodies")


def nodes_by_cable(cable_of_node, s, position, tension) -> dict[str, NodeArrays]:
    """Split the node arrays of a result (``cable``, ``s``, ``position``, ``tension`` along
    ``node``) into :class:`NodeArrays` by cable."""
    names = np.asarray(cable_of_node).astype(str)
    s, position, tension = (np.asarray(a, dtype=float) for a in (s, position, tension))
    return {name: NodeArrays(s[names == name], position[names == name], tension[names == name])
            for name in dict.fromkeys(names)}


class _Nodes:
    """A cable's node arrays with the line type of every node and element."""

    def __init__(self, case, cable, nodes: CableNodes):
        s = np.asarray(nodes.s, dtype=float)
        self.index = np.flatnonzero(s >= 0.0)             # s < 0: line still on a winch's drum
        self.s = s[self.index]
        self.position = np.asarray(nodes.position, dtype=float).reshape(-1, 3)[self.index]
        self.tension = np.asarray(nodes.tension, dtype=float)[self.index]
        self.grounded_length = float(getattr(nodes, "grounded_length", 0.0))
        ends = np.cumsum([section.length for section in cable.sections])[:-1]
        self.types = [case.line_types[section.line_type] for section in cable.sections]
        self.before = np.searchsorted(ends, self.s, side="left")     # the section ending at the node,
        self.after = np.searchsorted(ends, self.s, side="right")     # the one starting there (the same inside)
        self.element_type = np.searchsorted(ends, 0.5 * (self.s[:-1] + self.s[1:]), side="left")
        held = [(0.0, cable.from_), (cable.length, cable.to)]
        self.bodies = [(s_end, end.name) for s_end, end in held if end.kind == "body"]
        self.bodies += [(attachment.s, attachment.body) for attachment in cable.attachments]

    def lenient(self, score) -> tuple[np.ndarray, np.ndarray]:
        """Per node, the smaller of ``score(line, nodes)`` (an array over the node indices ``nodes``)
        for the line types on either side of the node, and the index of that type: a node on a
        section boundary passes a check when either line passes it."""
        best = np.full(len(self.s), np.inf)
        kind = self.before.copy()
        for side in (self.before, self.after):
            for i, line in enumerate(self.types):
                mine = np.flatnonzero(side == i)
                value = np.asarray(score(line, mine), dtype=float)
                better = value < best[mine]
                best[mine[better]] = value[better]
                kind[mine[better]] = i
        return best, kind

    def where(self, cable, k: int) -> str:
        """The node ``k`` in a message, with the body it holds if any."""
        node = f"cable '{cable.name}' node {self.index[k]} (s = {self.s[k]:.6g} m)"
        tolerance = PLACEMENT_TOLERANCE + RELATIVE_TOLERANCE * cable.length
        held = [name for s, name in self.bodies if abs(s - self.s[k]) <= tolerance]
        return f"body '{held[0]}' at {node}" if held else node


def law_strain(line, tension) -> np.ndarray:
    """Strain of ``line`` at ``tension`` (its tension law inverted; no tension, no strain).

    Parameters
    ----------
    line : kanat.model.LineType
        ``axial_stiffness`` (a linear law ``T = EA e``), or its ``elastic_law`` (a table,
        extrapolated with its last slope, or a polynomial, sampled on strains [0, 1]).
    tension : array_like
        [N].

    Returns
    -------
    ndarray
        Strain [-], inf where a law that stops rising cannot reach the tension.
    """
    T = np.maximum(np.asarray(tension, dtype=float), 0.0)
    law = line.elastic_law
    if law is None:
        return T / line.axial_stiffness
    if law.table is not None:
        strain = np.array([0.0] + [row[0] for row in law.table])
        force = np.array([0.0] + [row[1] for row in law.table])
    else:
        strain = np.linspace(0.0, 1.0, POLYNOMIAL_SAMPLES)
        force = np.maximum.accumulate(sum(c * strain ** (k + 1) for k, c in enumerate(law.polynomial)))
    slope = (force[-1] - force[-2]) / (strain[-1] - strain[-2])
    over = T > force[-1]
    if slope > 0:
        extra = np.where(over, T - force[-1], 0.0) / slope
    else:                                          # a law that stops rising never reaches more
        extra = np.where(over, np.inf, 0.0)
    return np.where(over, strain[-1] + extra, np.interp(T, force, strain))


def strain_bound(line) -> tuple[float, str]:
    """The largest strain ``line`` may take and what sets it (its limit, or its law's table)."""
    limit, what = line.strain_limit(), "the line's limit"
    law = line.elastic_law
    if law is not None and law.table is not None and law.table[-1][0] < limit:
        limit, what = law.table[-1][0], "the last strain of its elastic_law table (beyond it the law is extrapolated)"
    return limit, what


def _finite(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    bad = ~(np.all(np.isfinite(nodes.position), axis=1) & np.isfinite(nodes.tension))
    if not np.any(bad):
        return None
    k = int(np.argmax(bad))
    return (f"{when} is not finite (NaN or inf) at {nodes.where(cable, k)}: the solver diverged; try another "
            "statics method (method: shooting, collocation) or check the loads")


def _strain(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    excess_node, kind = nodes.lenient(lambda line, k: law_strain(line, nodes.tension[k])
                                     - strain_bound(line)[0] * (1 + RELATIVE_TOLERANCE))
    step = np.diff(nodes.s)
    chord = np.linalg.norm(np.diff(nodes.position, axis=0), axis=1)
    stretched = step > 0
    element = np.where(stretched, chord / np.where(stretched, step, 1.0) - 1.0, 0.0)
    element_bound = np.array([strain_bound(nodes.types[i])[0] for i in nodes.element_type])
    excess_element = np.append(element - element_bound * (1 + RELATIVE_TOLERANCE), -np.inf)
    if max(excess_node.max(), excess_element.max()) <= 0:
        return None
    if excess_node.max() >= excess_element.max():
        k = int(np.argmax(excess_node))
        line = nodes.types[kind[k]]
        measured = f"strain {float(law_strain(line, nodes.tension[k])):.4g} (tension {nodes.tension[k]:.4g} N)"
    else:
        j = int(np.argmax(excess_element))
        line = nodes.types[nodes.element_type[j]]
        k = j + 1
        measured = (f"strain {element[j]:.4g} of the element ending there (its nodes {chord[j]:.4g} m apart "
                    f"for {step[j]:.4g} m of line)")
    limit, what = strain_bound(line)
    name = _type_name(case, line)
    return (f"{measured} at {nodes.where(cable, k)} in {when} exceeds {what} {limit:g} of line type "
            f"'{name}': no line stretches so far; check the cable's length against the distance between "
            f"its ends, axial_stiffness and the loads (speed, current, drag, bodies), or set "
            f"line_types.{name}.max_strain")


def _tension(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    ratio, kind = nodes.lenient(lambda line, k: nodes.tension[k] / (line.breaking_load or np.inf))
    for i, line in enumerate(nodes.types):
        mine = np.flatnonzero((kind == i) & (ratio > 1.0))
        if not len(mine):
            continue
        k = int(mine[np.argmax(ratio[mine])])
        name = _type_name(case, line)
        text = (f"tension {nodes.tension[k] / 1e3:.4g} kN at {nodes.where(cable, k)} in {when} is {ratio[k]:.3g} "
                f"times the breaking load {line.breaking_load / 1e3:.4g} kN of line type '{name}'")
        if ratio[k] > ABSURD_BREAKING_MULTIPLE:
            return (f"{text}, more than {ABSURD_BREAKING_MULTIPLE:g} times it: no line carries that; check the "
                    "cable's length, the speed, the current, the drag coefficients and the bodies' loads")
        warnings.append(f"{text}: the line would break")
    return None


def _reach(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    tolerance = PLACEMENT_TOLERANCE + RELATIVE_TOLERANCE * cable.length
    for label, end, k in (("from", cable.from_, 0), ("to", cable.to, len(nodes.s) - 1)):
        if end.kind != "anchor":
            continue
        off = float(np.linalg.norm(nodes.position[k] - np.asarray(end.position, dtype=float)))
        if off > tolerance:
            return (f"the '{label}' end of cable '{cable.name}' is {off:.4g} m from its anchor at "
                    f"{list(end.position)} in {when}: the solver lost the end; try another statics method")
    most = max(strain_bound(line)[0] for line in nodes.types)
    for k_end, along in ((0, nodes.s - nodes.s[0]), (len(nodes.s) - 1, nodes.s[-1] - nodes.s)):
        distance = np.linalg.norm(nodes.position - nodes.position[k_end], axis=1)
        excess = distance - along * (1 + most) * (1 + RELATIVE_TOLERANCE) - tolerance
        k = int(np.argmax(excess))
        if excess[k] > 0:
            return (f"{nodes.where(cable, k)} is {distance[k]:.6g} m from the cable's end at s = "
                    f"{nodes.s[k_end]:.6g} m in {when}, but the {along[k]:.4g} m of line between them reach at "
                    f"most {along[k] * (1 + most):.4g} m stretched by {most:g}: no possible shape; try another "
                    "statics method")
    return None


def _seabed(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    env = case.environment
    seabed = seabed_of(env)
    if seabed is None:
        return None
    depth = seabed.penetration(nodes.position)
    allowed = np.full(len(nodes.s), PENETRATION_FLOOR)
    block = env.seabed
    if block is not None:
        def static(line, k):                       # the static penetration w / (k d), negated: the larger wins
            weight = max(line.weight_in_water_value(env.water_density, env.gravity), 0.0)
            return np.full(len(k), -weight / (block.stiffness * line.diameter))

        allowed -= PENETRATION_MARGIN * nodes.lenient(static)[0]
    k = int(np.argmax(depth - allowed))
    if depth[k] <= allowed[k]:
        return None
    floor = float(seabed.height(nodes.position[k, 0], nodes.position[k, 1]))
    text = (f"{nodes.where(cable, k)} is {depth[k]:.4g} m below the seabed (z = {nodes.position[k, 2]:.6g} m, "
            f"the seabed at z = {floor:.6g} m) in {when}, more than the {allowed[k]:.3g} m ")
    if block is None:
        return text + ("allowed without seabed contact (environment.depth is the seabed): the cable or its body "
                       "hangs through it; shorten the cable, lighten the body, raise the speed or deepen the water, "
                       "or add environment.seabed for a line that rests on it")
    return text + (f"the contact allows ({PENETRATION_MARGIN:g} x its static penetration w / (k d) + "
                   f"{PENETRATION_FLOOR * 1e3:g} mm): the cable or its body hangs through it; shorten the cable, "
                   "lighten the body or raise environment.seabed.stiffness")


def _grounded(case, cable, nodes: _Nodes, when: str, warnings: list) -> str | None:
    grounded = nodes.grounded_length
    if 0.0 <= grounded <= cable.length * (1 + RELATIVE_TOLERANCE) + PLACEMENT_TOLERANCE:
        return None
    return (f"cable '{cable.name}' has {grounded:.6g} m resting on the seabed in {when}, but it is "
            f"{cable.length:g} m long: the solver's touchdown point is off the cable; try another statics "
            "method (method: shooting, collocation) or check the current and the loads")


def _type_name(case, line) -> str:
    return next((name for name, other in case.line_types.items() if other is line), "?")


CHECKS = (_finite, _strain, _tension, _reach, _seabed, _grounded)
"""The checks in the order they are made; each named by its function's name without the ``_``."""


LUMPED_EQUILIBRIUM = "lumped equilibrium"
"""The ``method`` of a network statics result the lumped model's equilibrium solved: its elements
weigh a part above the water in air (their wetted share), so :func:`dry_parts` does not apply."""
DRY_LENGTH_FLOOR = 1e-6
"""A cable's length above the water [m] below which :func:`dry_parts` says nothing (round-off of a
node on the surface)."""


def check_result(result) -> Verdict:
    """:func:`check_steady` on a statics result (:class:`kanat.statics.StaticsResult` or
    :class:`kanat.statics.network_result.NetworkResult`), with :func:`dry_parts`' warnings and
    failure unless the lumped model's equilibrium solved it; Naumov & Agievich's sphere problem, in
    dimensionless groups with its own checks (``physical_warnings``), passes as it is."""
    if result.sphere is not None:
        return Verdict()
    verdict = check_steady(result.case, result.cables, bodies=result.bodies,
                           attitudes=getattr(result, "attitudes", None))
    if result.method == LUMPED_EQUILIBRIUM:
        return verdict
    warnings, lifted = dry_parts(result.case, result.cables)
    failure = verdict.failure or (f"buoyant_above_water: {lifted}" if lifted is not None else None)
    return Verdict(failure, verdict.warnings + warnings)


def dry_parts(case, cables: Mapping[str, CableNodes]) -> tuple[tuple[str, ...], str | None]:
    """The parts of cables above the mean water surface, for the statics solvers that take a whole line
    as submerged (docs/statics.md, "Assumptions"): a warning per such cable, with the length above the
    surface (:mod:`kanat.physics.immersion` eq. 3, unstretched) and the buoyancy it keeps there, its
    weight in air less its weight in water (``m g - w``) per metre, which in the air it would not have,
    against the cable's largest tension; and the failure (``buoyant_above_water``, None when there is
    none) of the first cable with a part of a buoyant line type (``w < 0``) above the surface: the
    solver holds that part up in the air by ``-w`` a metre, where it weighs ``m g``, a shape no line
    takes."""
    env = case.environment
    warnings, failure = [], None
    for cable in case.cables:
        if cable.name not in cables:
            continue
        nodes = _Nodes(case, cable, cables[cable.name])
        if len(nodes.s) < 2:
            continue
        share = dry_shares(nodes.position[:, 2]) * np.diff(nodes.s)
        length = float(np.sum(share))
        if length <= DRY_LENGTH_FLOOR:
            continue
        w = np.array([line.weight_in_water_value(env.water_density, env.gravity)
                      for line in nodes.types])[nodes.element_type]
        air = np.array([line.mass * env.gravity for line in nodes.types])[nodes.element_type]
        buoyancy = float(np.sum((air - w) * share))
        largest = float(np.max(np.abs(nodes.tension)))
        warnings.append(f"cable '{cable.name}': {length:.4g} m of it lies above the water surface, where this solver "
                        f"takes it as submerged: it keeps {buoyancy:.4g} N of buoyancy there "
                        f"({100.0 * buoyancy / max(largest, 1e-300):.2g} % of its largest tension) that it would not "
                        "have in the air; the dynamic models (`kanat run`) weigh that part in air")
        lifted = share * (w < 0.0)
        if failure is None and float(np.sum(lifted)) > DRY_LENGTH_FLOOR:
            failure = (f"cable '{cable.name}': {float(np.sum(lifted)):.4g} m of a buoyant line type lies above the "
                       f"water surface, held up there by {-float(np.sum(w * lifted)):.4g} N of buoyancy it would not "
                       "have in the air (this solver takes a whole line as submerged): no steady state of this "
                       "model; the lumped model (`kanat run` with model: lumped) weighs that part in air, or keep "
                       "the buoyant line under water")
    return tuple(warnings), failure
