"""Which solver supports which feature of a case: one table, and the check built on it.

:data:`FEATURES` is the table. Each row names a feature, says where a case uses it (a
detector returning key paths) and, for each solver (``statics``, ``continuum``,
``lumped``, ``pitch``), one of

* :data:`YES` -- the solver models it;
* :data:`NO` -- the solver cannot: a case using it is an error for that solver;
* :data:`IGNORED` -- the solver runs without it by design (the statics of a case with
  waves is the still-water steady state): a warning that says so.

:func:`unsupported` turns the rows a case uses into problems at their key paths; ``kanat
validate`` runs it for ``case.model`` (:func:`check_support`, in the check list of
:mod:`kanat.model.checks`), and a solver calls :func:`require_supported` with its own name
(the statics of a dynamic case is solver ``statics``), so that validation and the solvers
accept the same cases. When a solver learns a feature, flip its entry here; the tests
compare the table with what the solvers do.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..errors import CaseError, Problem
from ..schemes import MODELS
from ._base import fmt
from .paths import Path, key_path, line_of

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

YES, NO, IGNORED = "yes", "no", "ignored"
SOLVERS = MODELS
"""Solver names: the case models; ``statics`` also solves the steady state of a dynamic case."""

Use = tuple[Path, str]
"""Where a case uses a feature: its key path and a short detail for the message."""


@dataclass(frozen=True)
class Feature:
    """One row of the support table.

    Attributes
    ----------
    name : str
        Identifier (``waves``, ``sections``, ...).
    title : str
        What it is, as messages and the reference table say it.
    uses : callable
        ``uses(case) -> list of (key path, detail)`` where the case uses the feature.
    statics, continuum, lumped, pitch : {"yes", "no", "ignored"}
    note : str or mapping of solver to str
        Why a solver does not model it (said in its messages): one text for all, or one
        per solver.
    """

    name: str
    title: str
    uses: Callable[[Case], list[Use]]
    statics: str
    continuum: str
    lumped: str
    pitch: str = IGNORED
    note: str | Mapping[str, str] = ""

    def level(self, solver: str) -> str:
        """``yes``, ``no`` or ``ignored`` for ``solver``."""
        if solver not in SOLVERS:
            raise ValueError(f"unknown solver '{solver}'; valid: {', '.join(SOLVERS)}")
        return getattr(self, solver)

    def why(self, solver: str) -> str:
        """The note for ``solver`` ("" when there is none)."""
        return self.note.get(solver, "") if isinstance(self.note, Mapping) else self.note

    def supported_by(self) -> list[str]:
        """Solvers that model the feature."""
        return [s for s in SOLVERS if self.level(s) == YES]


# --- where a case uses each feature -------------------------------------------------------

def _ends(case: Case):
    for i, cable in enumerate(case.cables):
        for key, end in (("from", cable.from_), ("to", cable.to)):
            yield i, key, end


def _several_cables(case: Case) -> list[Use]:
    n = len(case.cables)
    return [(("cables",), f" ({n} cables)")] if n > 1 else []


def _points(case: Case) -> list[Use]:
    return [(("cables", i, key), f" (point '{end.name}')") for i, key, end in _ends(case)
            if end.kind == "point"]


def _shared_bodies(case: Case) -> list[Use]:
    seen, found = set(), []
    for i, key, end in _ends(case):
        if end.kind == "body":
            if end.name in seen:
                found.append((("cables", i, key), f" (body '{end.name}' ends another cable too)"))
            seen.add(end.name)
    return found


def _free_ends(case: Case) -> list[Use]:
    return [(("cables", i, key), "") for i, key, end in _ends(case) if end.kind == "free"]


def _loose_first_ends(case: Case) -> list[Use]:
    return [(("cables", i, "from"), f" ({c.from_.kind})") for i, c in enumerate(case.cables)
            if c.from_.kind in ("body", "point", "free")]


def _waves(case: Case) -> list[Use]:
    waves = case.environment.waves
    return [(("environment", "waves"), f" ({waves.type})")] if waves is not None else []


def _current_rows(case: Case) -> list[tuple[float, ...]]:
    current = case.environment.current
    return list(current.profile or ((0.0, *(current.velocity or (0.0, 0.0, 0.0))),))


def _current_y(case: Case) -> list[Use]:
    largest = max(abs(r[2]) for r in _current_rows(case))
    return [(("environment", "current"), f" (up to {fmt(largest)} m/s)")] if largest else []


def _out_of_plane(case: Case) -> list[Use]:
    """Anchors off y = 0, and the tow point and body forces off it where a cable uses them."""
    ends = list(_ends(case))
    found = [(("cables", i, key), f" (y = {fmt(end.position[1])} m)") for i, key, end in ends
             if end.kind == "anchor" and end.position[1] != 0]
    towed = any(end.kind == "vessel" and end.offset is None for _, _, end in ends)
    if towed and case.vessel.tow_point[1] != 0:
        found.append((("vessel", "tow_point"), f" (y = {fmt(case.vessel.tow_point[1])} m)"))
    held = {end.name for _, _, end in ends if end.kind == "body"}
    found += [(("bodies", n, "force"), f" (y = {fmt(b.force[1])} N)")
              for n, b in case.bodies.items() if b.force[1] != 0 and n in held]
    return found


def _networks(case: Case) -> list[list[int]]:
    """Cables grouped by the bodies and points that join them (indices into case.cables)."""
    group = list(range(len(case.cables)))

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    owner: dict[str, int] = {}
    for i, _, end in _ends(case):
        if end.kind in ("body", "point"):
            if end.name in owner:
                group[root(i)] = root(owner[end.name])
            owner[end.name] = i
    found: dict[int, list[int]] = {}
    for i in range(len(case.cables)):
        found.setdefault(root(i), []).append(i)
    return list(found.values())


def _lowest_reach(case: Case, cables: list[int]) -> float | None:
    """Lowest height a group of joined cables can reach [m]; None when nothing holds it.

    When its bodies and points lift more than its cables weigh in water, the group floats
    up from its fixed ends and stays above the lowest of them; otherwise it may hang its
    whole length below it.
    """
    env = case.environment
    rho, g = env.water_density, env.gravity
    heights, nodes, weight, length = [], set(), 0.0, 0.0
    for i in cables:
        cable = case.cables[i]
        length += cable.length
        weight += sum(case.line_types[s.line_type].weight_in_water_value(rho, g) * s.length
                      for s in cable.sections if s.line_type in case.line_types)
        for end in cable.ends:
            if end.kind == "anchor":
                heights.append(end.position[2])
            elif end.kind == "vessel":
                heights.append(case.vessel.tow_point[2])
            elif end.kind in ("body", "point"):
                nodes.add((end.kind, end.name))
    if not heights:
        return None
    lift = sum(case.bodies[n].net_buoyancy if k == "body" else case.points[n].net_buoyancy(rho, g)
               for k, n in nodes if n in (case.bodies if k == "body" else case.points))
    return min(heights) if lift > weight else min(heights) - length


def seabed_reacher(case: Case) -> str | None:
    """The name of the first cable whose network can reach the seabed at ``z = -depth``
    (:func:`_lowest_reach`), or None (none can, or no ``depth``)."""
    depth = case.environment.depth
    if depth is None:
        return None
    for group in _networks(case):
        reach = _lowest_reach(case, group)
        if reach is None or reach < -depth * (1 + 1e-9):
            return case.cables[group[0]].name
    return None


def _seabed_reach(case: Case) -> list[Use]:
    if case.environment.seabed is not None:
        return []
    name = seabed_reacher(case)
    if name is None:
        return []
    return [(("environment", "depth"), f" (cable '{name}' can reach the seabed at z = {fmt(-case.environment.depth)} m)")]


def _line_type_key(key: str, test) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        return [(("line_types", name, key), "") for name, line in case.line_types.items()
                if test(getattr(line, key))]
    return uses


def _released_ends(case: Case) -> list[Use]:
    return [(("cables", i, key, "release_at"), f" (at t = {fmt(getattr(cable, key).release_at)} s)")
            for i, cable in enumerate(case.cables) for key in ("end_a", "end_b")
            if getattr(cable, key).release_at is not None]


def _clamped_ends(case: Case) -> list[Use]:
    return [(("cables", i, key, "clamped"), "") for i, cable in enumerate(case.cables)
            for key in ("end_a", "end_b") if getattr(cable, key).clamped]


def _dimensional_drag(case: Case) -> list[Use]:
    return [(("line_types", name, key), "") for name, line in case.line_types.items()
            for key in ("drag_normal_coefficient", "drag_tangential_coefficient")
            if getattr(line, key) is not None]


def _body_key(key: str, test) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        return [(("bodies", name, key), "") for name, body in case.bodies.items()
                if test(getattr(body, key))]
    return uses


def _without_inertia(case: Case) -> list[Use]:
    return [(("bodies", name, "inertia"), "") for name, body in case.bodies.items() if not body.has_inertia]


def _vessel_pitch(case: Case) -> list[Use]:
    return [(("vessel", "pitch"), "")] if case.vessel.pitch is not None else []


def _simulation(key: str, default) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        sim = case.simulation
        value = getattr(sim, key) if sim is not None else default
        return [(("simulation", key), f" ({value})")] if value != default else []
    return uses


def _seabed(test, key: str | None = None) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        seabed = case.environment.seabed
        if seabed is None or not test(seabed):
            return []
        return [(("environment", "seabed", key) if key else ("environment", "seabed"), "")]
    return uses


def _sections(case: Case) -> list[Use]:
    return [(("cables", i, "sections"), f" ({len(c.sections)} sections)")
            for i, c in enumerate(case.cables) if len(c.sections) > 1]


def _attachments(case: Case) -> list[Use]:
    return [(("cables", i, "attachments"), f" ({len(c.attachments)})")
            for i, c in enumerate(case.cables) if c.attachments]


def _inline_surface_buoys(case: Case) -> list[Use]:
    return [(("cables", i, "attachments", j), f" (body '{a.body}')") for i, c in enumerate(case.cables)
            for j, a in enumerate(c.attachments) if a.body in case.bodies and case.bodies[a.body].surface_buoy is not None]


def _float_diameters(at_ends: bool) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        names = {e.name for c in case.cables for e in c.ends if e.kind == "body"}
        return [(("bodies", name, "diameter"), "") for name, body in case.bodies.items()
                if body.diameter is not None and (name in names) == at_ends]
    return uses


def _vessel_motion(case: Case) -> list[Use]:
    return [(("vessel", "motion"), "")] if case.vessel.motion.is_used else []


def _winch(case: Case) -> list[Use]:
    return [(("winch",), f" ({len(case.winch)} steps)")] if case.winch else []


def _fairleads(kind: str) -> Callable[[Case], list[Use]]:
    def uses(case: Case) -> list[Use]:
        return [(("cables", i, key), f" (offset {list(end.offset)} m)")
                for i, key, end in _ends(case) if end.kind == kind and end.offset is not None]
    return uses


POINT_EXTRAS = ("volume", "drag_area", "added_mass", "force")
"""Point keys beyond position and mass (MoorDyn's free points)."""


def _point_extras(case: Case) -> list[Use]:
    return [(("points", name, key), "") for name, point in case.points.items()
            for key in POINT_EXTRAS if getattr(point, key) not in (0.0, (0.0, 0.0, 0.0))]


NETWORK_FEATURES = ("points", "shared_bodies", "current_y", "out_of_plane", "seabed_friction",
                    "seabed_slope", "sections", "attachments", "six_dof_bodies", "body_fairleads",
                    "vessel_fairleads", "point_properties")
"""Rows that only network statics solves; a case using none of them is solved cable by cable
in the x-z plane (shooting, collocation or the closed-form catenary, also in a current)."""


def needs_network(case: Case) -> bool:
    """True when statics must solve ``case`` as a 3-D network (:data:`NETWORK_FEATURES`)."""
    return any(feature(name).uses(case) for name in NETWORK_FEATURES)


def has_drag(case: Case) -> bool:
    """True when a current or the vessel's initial speed drags on the lines."""
    return bool(case.vessel.initial_speed or any(any(row[1:]) for row in _current_rows(case)))


NO_STEADY_EFFECT = ("axial_damping", "tangential_added_mass", "consistent_mass",
                    "initial_state_as_given", "frame_pole", "slack_stop")
"""Rows that do not change a steady state (damping, added mass, solver settings)."""


def single_cable(case: Case) -> bool:
    """One cable between the vessel's tow point, anchors and point bodies (no fairleads, points or 6-DOF
    bodies): the 3-D single-cable statics solves it in a current too (:mod:`kanat.statics.shooting3d`)."""
    if len(case.cables) != 1 or case.points:
        return False
    cable = case.cables[0]
    for end in cable.ends:
        if end.offset is not None or end.kind in ("point", "free"):
            return False
        if end.kind == "body" and end.name in case.bodies and case.bodies[end.name].dof != 3:
            return False
    return all(a.body in case.bodies and case.bodies[a.body].dof == 3 for a in cable.attachments)


def _drag_without_fallback(case: Case) -> list[Use]:
    """A network in a current or under tow, where it uses what the lumped equilibrium lacks
    (a row the lumped model does not support, or a seabed given by ``depth`` alone: statics'
    seabed is rigid there, the lumped model's the compliant default); a single cable is the 3-D
    single-cable statics' and needs no fallback."""
    if not (has_drag(case) and needs_network(case)) or single_cable(case):
        return []
    return [(path, f" ({row.title}{detail})") for row in FEATURES
            if row.statics == YES and row.name not in NO_STEADY_EFFECT
            and (row.lumped == NO or row.name == "seabed_contact")
            for path, detail in row.uses(case)]


# --- the table ----------------------------------------------------------------------------

_NOT_NONE = (lambda v: v is not None)
_NONZERO = (lambda v: bool(v))
STEADY = "its steady state is the mean, still-water state at t = 0"

FEATURES: tuple[Feature, ...] = (
    # what the solvers do today with the keys they have had
    Feature("several_cables", "several cables", _several_cables,
            statics=YES, continuum=NO, lumped=YES, note="the continuum model takes one cable"),
    Feature("points", "a cable end at a network point", _points,
            statics=YES, continuum=NO, lumped=YES),
    Feature("shared_bodies", "a body ending several cables", _shared_bodies,
            statics=YES, continuum=NO, lumped=YES, note="the continuum model takes one cable"),
    Feature("free_end", "a free cable end", _free_ends, statics=NO, continuum=YES, lumped=YES,
            note="a free end's steady direction is undefined; end the cable at a small body"),
    Feature("loose_first_end", "a cable whose 'from' end is not the vessel or an anchor",
            _loose_first_ends, statics=YES, continuum=NO, lumped=YES,
            note="the continuum model builds positions from a fixed first end; swap from and to"),
    Feature("waves", "waves", _waves, statics=IGNORED, continuum=YES, lumped=YES,
            note={"statics": STEADY}),
    Feature("current_y", "a current with a y component", _current_y,
            statics=YES, continuum=YES, lumped=YES),
    Feature("out_of_plane", "a position or force off the x-z plane",
            _out_of_plane, statics=YES, continuum=YES, lumped=YES),
    Feature("seabed_contact", "seabed contact", _seabed_reach,
            statics=YES, continuum=YES, lumped=YES,
            note={"statics": "without environment.seabed a rigid seabed at z = -depth",
                  "continuum": "without environment.seabed the default one (stiffness 3e6 Pa/m, damping "
                               "3e5 Pa s/m, no friction)",
                  "lumped": "as the continuum model"}),
    Feature("elastic_law", "a nonlinear elastic law", _line_type_key("elastic_law", _NOT_NONE),
            statics=NO, continuum=YES, lumped=YES, note="statics uses the linear axial_stiffness"),
    Feature("dimensional_drag", "dimensional drag coefficients", _dimensional_drag,
            statics=NO, continuum=NO, lumped=YES),
    Feature("axial_damping", "axial damping", _line_type_key("axial_damping", _NONZERO),
            statics=YES, continuum=NO, lumped=YES),
    Feature("spreading_force", "an otter board's spreading force",
            _body_key("spreading_force", _NONZERO), statics=NO, continuum=NO, lumped=YES),
    Feature("surface_buoy", "a surface buoy's waterplane", _body_key("surface_buoy", _NOT_NONE),
            statics=NO, continuum=YES, lumped=YES),
    Feature("inline_surface_buoy", "a surface buoy clamped inside a cable", _inline_surface_buoys,
            statics=NO, continuum=NO, lumped=NO,
            note="a surface buoy rides the waves at a cable's end; inline bodies have no waterplane"),
    Feature("float_diameter", "a float whose buoyancy follows its immersion (diameter)", _float_diameters(False),
            statics=NO, continuum=YES, lumped=YES,
            note="network statics keeps a float's full buoyancy in the air; the initial state of a run "
                 "(model: lumped or continuum) honours it"),
    Feature("end_float_diameter", "a float with a diameter at a cable's end", _float_diameters(True),
            statics=NO, continuum=NO, lumped=NO,
            note="a body riding the surface at a cable's end is a surface_buoy (waterplane_area, height)"),
    Feature("vessel_pitch", "the vessel's pitch", _vessel_pitch,
            statics=IGNORED, continuum=YES, lumped=YES, note="its steady state is level"),
    Feature("consistent_mass", "the consistent mass matrix", _simulation("mass_matrix", "lumped"),
            statics=YES, continuum=IGNORED, lumped=YES,
            note="a lumped-model setting; the continuum model has its own discretization"),
    Feature("frequency_domain", "the frequency domain (linearised about the equilibrium)", _simulation("method", "time"),
            statics=IGNORED, continuum=YES, lumped=YES,
            note={"statics": "the steady state is the equilibrium the frequency domain linearises about; "
                             "run the case with model: lumped for its response",
                  "continuum": "the lines are linearised as the lumped model discretizes them (a warning "
                               "says so)"}),
    Feature("initial_state_as_given", "starting from the given positions at rest",
            _simulation("initial_state", "equilibrium"), statics=YES, continuum=IGNORED,
            lumped=YES, note="the continuum model starts from its steady state"),
    Feature("frame_pole", "a chosen frame pole", _simulation("frame_pole", "auto"),
            statics=YES, continuum=YES, lumped=IGNORED, note="a 3-D continuum setting"),
    Feature("slack_stop", "stopping a run when the cable goes slack", _simulation("slack", "continue"),
            statics=IGNORED, continuum=YES, lumped=IGNORED,
            note={"statics": "a continuum-model setting",
                  "lumped": "its elements carry no compression: a run goes on through slack and records "
                            "the snap events"}),
    # the additions for moorings and real cable systems
    Feature("seabed", "seabed contact properties", _seabed(bool),
            statics=YES, continuum=YES, lumped=YES),
    Feature("seabed_friction", "seabed friction", _seabed(lambda s: s.friction > 0, "friction"),
            statics=YES, continuum=YES, lumped=YES),
    Feature("seabed_lateral_friction", "lateral seabed friction",
            _seabed(lambda s: s.lateral_friction > 0, "lateral_friction"),
            statics=IGNORED, continuum=YES, lumped=YES,
            note={"statics": "statics lays each grounded line straight in its own vertical plane, so "
                             "nothing pushes it sideways for lateral friction to resist"}),
    Feature("zero_inertia", "a rigid body without inertia (zero, as MoorPy writes it)", _without_inertia,
            statics=YES, continuum=NO, lumped=NO,
            note="a dynamic run turns the body, which needs its moments of inertia [Ixx, Iyy, Izz] (kg m^2) "
                 "about the centre of gravity; statics does not use them"),
    Feature("seabed_slope", "a sloping seabed", _seabed(lambda s: s.slope_deg != 0, "slope_deg"),
            statics=YES, continuum=YES, lumped=YES),
    Feature("bending_stiffness", "bending stiffness", _line_type_key("bending_stiffness", _NONZERO),
            statics=YES, continuum=YES, lumped=YES,
            note={"statics": "statics solves a case with bending by the lumped model's equilibrium"}),
    Feature("compression_stiffness", "compression carried by a line with bending stiffness",
            _line_type_key("compression_stiffness", _NONZERO),
            statics=NO, continuum=IGNORED, lumped=YES,
            note={"statics": "statics reports tension-only lines (compression clipped at 0): run the lumped "
                             "model, whose first output is the equilibrium",
                  "continuum": "the continuum model carries compression its own way (simulation.slack)"}),
    Feature("clamped_end", "a clamped cable end", _clamped_ends,
            statics=YES, continuum=NO, lumped=YES,
            note={"statics": "statics solves a case with bending by the lumped model's equilibrium",
                  "continuum": "the continuum model's cable ends are pinned"}),
    Feature("body_seabed_area", "a body's bearing area on the seabed", _body_key("seabed_area", _NONZERO),
            statics=IGNORED, continuum=NO, lumped=YES,
            note={"statics": "statics does not set bodies on the seabed",
                  "continuum": "the continuum model's seabed contact is its cable's"}),
    Feature("end_release", "a cable end released at a time", _released_ends,
            statics=IGNORED, continuum=NO, lumped=YES, pitch=NO,
            note={"statics": "its steady state is before the release",
                  "continuum": "the continuum model's ends stay where the case puts them; run the lumped model",
                  "pitch": "the pitch model holds its tow cable"}),
    Feature("max_strain", "a strain limit", _line_type_key("max_strain", _NOT_NONE),
            statics=IGNORED, continuum=YES, lumped=YES,
            note="statics reports the tensions; the dynamic models stop a run that exceeds the limit"),
    Feature("tangential_added_mass", "tangential added mass",
            _line_type_key("added_mass_tangential", _NONZERO), statics=YES, continuum=NO, lumped=YES,
            note={"continuum": "a catalogue line gives one: write added_mass_tangential: 0 to leave it out"}),
    Feature("sections", "a cable of several sections", _sections, statics=YES, continuum=YES, lumped=YES),
    Feature("attachments", "bodies attached along a cable", _attachments,
            statics=YES, continuum=YES, lumped=YES),
    Feature("vessel_motion", "the vessel's prescribed motion", _vessel_motion,
            statics=IGNORED, continuum=YES, lumped=YES, note=STEADY),
    Feature("winch", "a winch", _winch, statics=IGNORED, continuum=YES, lumped=NO,
            note="its steady state is before the winch turns"),
    Feature("six_dof_bodies", "a body with 6 degrees of freedom", _body_key("dof", lambda v: v == 6),
            statics=YES, continuum=NO, lumped=YES),
    Feature("body_fairleads", "a cable end at a fairlead on a body", _fairleads("body"),
            statics=YES, continuum=NO, lumped=YES),
    Feature("vessel_fairleads", "a cable end at a fairlead on the vessel", _fairleads("vessel"),
            statics=YES, continuum=NO, lumped=YES),
    Feature("point_properties", "a point's volume, drag, added mass or force", _point_extras,
            statics=YES, continuum=NO, lumped=YES),
    # statics in a current: a network goes to the lumped model's equilibrium, which must take it
    Feature("drag_on_network", "a current or tow speed on a network", _drag_without_fallback,
            statics=NO, continuum=YES, lumped=YES, pitch=YES,
            note="the catenary lines of network statics carry no drag, so statics hands a network "
                 "in a current or under tow to the lumped model's equilibrium, which lacks this"),
)
"""The support table (module docstring). The ``pitch`` model solves its own block only:
everything else is ignored by it."""


def feature(name: str) -> Feature:
    """The row called ``name``."""
    for row in FEATURES:
        if row.name == name:
            return row
    raise KeyError(f"no feature '{name}'; known: {', '.join(f.name for f in FEATURES)}")


def _message(row: Feature, solver: str, detail: str) -> tuple[str, str]:
    level = row.level(solver)
    others = [s for s in row.supported_by() if s != solver]
    where = f"supported by: {', '.join(others)}" if others else "no model supports it yet"
    if level == IGNORED:
        why = row.why(solver) or f"model '{solver}' solves its own problem block only"
        return "warning", (f"{row.title}{detail} is not applied by model '{solver}' ({why}); "
                           f"{where}")
    why = f" ({row.why(solver)})" if row.why(solver) else ""
    return "error", f"{row.title}{detail}: model '{solver}' does not support it{why}; {where}"


def unsupported(case: Case, solver: str, file: str | None = None,
                lines: Mapping[Path, int] | None = None) -> list[Problem]:
    """One problem per use of a feature that ``solver`` does not model.

    Parameters
    ----------
    case : Case
    solver : {"statics", "continuum", "lumped", "pitch"}
    file : str or None
        Case file for the problems.
    lines : mapping of key path to int, optional
        Lines of the case file's keys.

    Returns
    -------
    list of Problem
        Errors for :data:`NO` entries, warnings for :data:`IGNORED` ones, each at the key
        path that uses the feature, naming the models that do support it (or none yet).
    """
    found = []
    for row in FEATURES:
        if row.level(solver) == YES:
            continue
        for path, detail in row.uses(case):
            severity, message = _message(row, solver, detail)
            found.append(Problem(key_path(path), message, file, line_of(lines, path), severity))
    return found


def require_supported(case: Case, solver: str) -> list[Problem]:
    """Raise :class:`~kanat.errors.CaseError` when ``solver`` cannot take ``case``.

    Returns
    -------
    list of Problem
        The warnings (features the solver runs without by design).
    """
    problems = unsupported(case, solver)
    if any(p.severity == "error" for p in problems):
        raise CaseError(problems)
    return problems


def check_support(case: Case, out) -> None:
    """Check-list entry (:mod:`kanat.model.checks`): :func:`unsupported` for ``case.model``."""
    for problem in unsupported(case, case.model, out.file, out.lines):
        out.problems.append(problem)


def table_rows() -> list[tuple[str, ...]]:
    """The table as rows ``(feature title, statics, continuum, lumped, pitch)``."""
    return [(row.title, *(row.level(s) for s in SOLVERS)) for row in FEATURES]


def markdown_table() -> str:
    """The table in Markdown, for the reference documentation."""
    head = "| feature | " + " | ".join(SOLVERS) + " |"
    rule = "|---" * (len(SOLVERS) + 1) + "|"
    return "\n".join([head, rule] + ["| " + " | ".join(row) + " |" for row in table_rows()])
