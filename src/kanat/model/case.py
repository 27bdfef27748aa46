"""The whole case: what to model and with which data.

Cross-references (a cable's line type, the bodies and points it is attached to) are
checked field by field when the case is validated with a context dict
(``Case.model_validate(data, context={})``, as :mod:`kanat.io.case_file` does), so that
every mistake is reported at its own key; without a context they are checked once the
case is built.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Literal

from pydantic import Field, PrivateAttr, ValidationInfo, field_validator, model_validator

from ._base import KanatModel, fmt, listing, suggest
from .cable import Cable
from .components import Body, LineType, Point
from .design import Design
from .environment import Environment
from .operations import WinchStep
from .problems import PitchModel, SphereTwoCables
from .simulation import Simulation
from .vessel import Vessel
from ..schemes import DYNAMIC_MODELS, MODELS

ModelName = Literal[MODELS]
_SECTIONS = ("environment", "line_types", "bodies", "points", "vessel", "cables")


def _names(section: Any) -> list[str] | None:
    return [k for k in section if isinstance(k, str)] if isinstance(section, dict) else None


def _resolve_named_ends(data: dict[str, Any], bodies: list[str], points: list[str]) -> None:
    """Rewrite bare body/point names of cable ends as ``{body: x}`` / ``{point: x}``."""
    cables = data.get("cables")
    if not isinstance(cables, list):
        return
    bodies, points = set(bodies), set(points)  # O(1) lookups: cases may have thousands
    resolved = []
    for cable in cables:
        if isinstance(cable, dict):
            cable = dict(cable)
            for key in ("from", "to"):
                end = cable.get(key)
                if isinstance(end, str) and end in bodies:
                    cable[key] = {"body": end}
                elif isinstance(end, str) and end in points:
                    cable[key] = {"point": end}
        resolved.append(cable)
    data["cables"] = resolved


class Case(KanatModel):
    """A validated case (see ``docs/reference/case-format.md``).

    Attributes
    ----------
    name : str
    model : {"statics", "continuum", "lumped", "pitch"}
    environment : Environment
    line_types : dict of str to LineType
    bodies : dict of str to Body
    points : dict of str to Point
    vessel : Vessel
    cables : list of Cable
    simulation : Simulation or None
        Required by the dynamic models (continuum, lumped).
    sphere_two_cables : SphereTwoCables or None
    pitch : PitchModel or None
        Required by ``model: pitch``.
    winch : tuple of WinchStep
        Pay-out and haul-in of the first cable at its ``from`` end, in time order.
    design : Design or None
        The design checks ``kanat design`` runs (:mod:`kanat.design_checks`).
    """

    name: str = ""
    model: ModelName
    environment: Environment = Field(default_factory=Environment)
    line_types: dict[str, LineType] = Field(default_factory=dict)
    bodies: dict[str, Body] = Field(default_factory=dict)
    points: dict[str, Point] = Field(default_factory=dict)
    vessel: Vessel = Field(default_factory=Vessel)
    cables: list[Cable] = Field(default_factory=list, validate_default=True)
    simulation: Simulation | None = Field(None, validate_default=True)
    sphere_two_cables: SphereTwoCables | None = Field(None, validate_default=True)
    pitch: PitchModel | None = Field(None, validate_default=True)
    winch: tuple[WinchStep, ...] = Field(
        (), description="pay-out (rate > 0) and haul-in (rate < 0) of the first cable at its "
                        "'from' end: steps {start, duration, rate} in time order, not "
                        "overlapping")
    design: Design | None = Field(
        None, description="design checks (kanat design): standard, analysis, sea_states, "
                          "storm_duration, seeds, conditions, extremes, fatigue")

    @model_validator(mode="before")
    @classmethod
    def _collect_names(cls, data: Any, info: ValidationInfo) -> Any:
        if not isinstance(data, dict):
            return data
        # an empty section (``points:`` with nothing under it) reads as null: use the default
        data = {k: v for k, v in data.items() if not (v is None and k in _SECTIONS)}
        bodies = _names(data.get("bodies")) or []
        points = _names(data.get("points")) or []
        _resolve_named_ends(data, bodies, points)
        if isinstance(info.context, dict):
            info.context["names"] = {"line_types": _names(data.get("line_types", {})),
                                     "bodies": bodies, "points": points}
            density = (data.get("environment") or {}).get("water_density") \
                if isinstance(data.get("environment"), dict) else None
            if isinstance(density, (int, float)) and not isinstance(density, bool) and 0 < density < 1e300:
                info.context["water_density"] = float(density)  # catalogue added masses (a huge int: the
                # field's own check refuses it)
        return data

    @field_validator("points")
    @classmethod
    def _distinct_names(cls, points: dict[str, Point], info: ValidationInfo) -> Any:
        both = sorted(set(points) & set(info.data.get("bodies") or {}))
        if both:
            raise ValueError(f"'{both[0]}' names both a body and a point; rename one")
        return points

    @field_validator("cables")
    @classmethod
    def _cables_needed(cls, cables: list[Cable], info: ValidationInfo) -> list[Cable]:
        model = info.data.get("model")
        if model in DYNAMIC_MODELS and not cables:
            raise ValueError(f"model '{model}' needs at least one cable")
        seen: dict[str, int] = {}
        for i, cable in enumerate(cables):
            if cable.name in seen:
                raise ValueError(f"cable name '{cable.name}' is used by cables[{seen[cable.name]}]"
                                 f" and cables[{i}]; names must be unique")
            seen[cable.name] = i
        return cables

    @field_validator("simulation")
    @classmethod
    def _simulation_needed(cls, value: Simulation | None, info: ValidationInfo) -> Any:
        model = info.data.get("model")
        if value is None and model in DYNAMIC_MODELS:
            raise ValueError(f"model '{model}' needs a 'simulation' block "
                             "{duration, dt, ...}")
        return value

    @field_validator("sphere_two_cables")
    @classmethod
    def _statics_needs_system(cls, value: SphereTwoCables | None, info: ValidationInfo) -> Any:
        if (value is None and info.data.get("model") == "statics"
                and "cables" in info.data and not info.data["cables"]):
            raise ValueError("model 'statics' needs a 'sphere_two_cables' block or at least "
                             "one cable")
        return value

    @field_validator("pitch")
    @classmethod
    def _pitch_needed(cls, value: PitchModel | None, info: ValidationInfo) -> Any:
        if value is None and info.data.get("model") == "pitch":
            raise ValueError("model 'pitch' needs a 'pitch' block {inertia, natural_frequency, "
                             "wave_moment_amplitude, wave_period, ...}")
        return value

    @field_validator("winch")
    @classmethod
    def _winch_steps(cls, steps: tuple[WinchStep, ...], info: ValidationInfo) -> Any:
        if not steps:
            return steps
        cables = info.data.get("cables")
        if cables is not None and not cables:
            raise ValueError("a winch acts on the first cable, but the case has no cables")
        for i in range(1, len(steps)):
            if steps[i].start < steps[i - 1].end * (1 - 1e-12):
                raise ValueError(f"step {i} starts at {fmt(steps[i].start)} s, before step "
                                 f"{i - 1} ends at {fmt(steps[i - 1].end)} s; list the steps "
                                 "in time order without overlap")
        if cables:
            length, lowest = cables[0].length, 0.0
            paid = 0.0
            for step in steps:
                paid += step.change
                lowest = min(lowest, paid)
            if length + lowest <= 0:
                raise ValueError(f"the winch hauls in {fmt(-lowest)} m of cable "
                                 f"'{cables[0].name}', which is only {fmt(length)} m long")
        return steps

    _source: str | None = PrivateAttr(default=None)

    @property
    def source(self) -> str | None:
        """The file the case was read from (``<text>``, ``<dict>`` for YAML text or a mapping), or
        None: problems found later (by :meth:`replace`, or when a model is built) name it."""
        return self._source

    def __eq__(self, other) -> bool:
        """Cases with the same keys are equal, wherever they were read from (``source`` aside)."""
        if not isinstance(other, Case):
            return NotImplemented
        return self.__dict__ == other.__dict__ and self.__pydantic_extra__ == other.__pydantic_extra__

    __hash__ = None

    def replace(self, changes: Mapping[str, Any]) -> Case:
        """A validated copy of the case with some keys set.

        Parameters
        ----------
        changes : mapping of str to object
            Key paths as written in the case file and in ``kanat sweep --vary``
            (``"cables[0].length"``, ``"vessel.track[1].to_speed_kn"``,
            ``"line_types.towcable.drag_normal"``) and their new values, in case-file units.

        Returns
        -------
        Case

        Raises
        ------
        kanat.errors.CaseError
            Every problem at its key path, as for a case file (values out of range, unknown
            keys, failed sanity checks).

        Warns
        -----
        kanat.errors.CaseWarning
            For a case that runs but probably not as meant.
        """
        from .edit import replaced

        return replaced(self, changes)

    def with_seabed_contact(self) -> Case:
        """This case with :meth:`Environment.with_seabed_contact` where a cable can reach the seabed
        (:func:`kanat.model.support.seabed_reacher`): the seabed the continuum model applies, which the
        lumped model takes its case through, so that ``depth`` alone means the same contact in both.
        This case itself when nothing changes (a line that cannot reach the seabed gets no contact
        model, whose stiffness would only shorten the lumped model's stable step)."""
        from .support import seabed_reacher

        environment = self.environment.with_seabed_contact()
        if environment is self.environment or seabed_reacher(self) is None:
            return self
        return self.model_copy(update={"environment": environment})

    @model_validator(mode="after")
    def _cross_references(self) -> Case:
        messages = reference_errors(self)
        if messages:
            raise ValueError("; ".join(messages))
        return self


def _line_type_errors(case: Case, i: int) -> list[str]:
    cable, known = case.cables[i], list(case.line_types)
    single = len(cable.sections) == 1 and "sections" not in cable.model_fields_set
    keys = ([f"cables[{i}].line_type"] if single else
            [f"cables[{i}].sections[{j}].line_type" for j in range(len(cable.sections))])
    return [f"{key}: '{section.line_type}' is not a line type; known: "
            f"{listing(known)}{suggest(section.line_type, known)}"
            for key, section in zip(keys, cable.sections) if section.line_type not in known]


def reference_errors(case: Case) -> list[str]:
    """Messages for cables naming line types, bodies or points the case lacks."""
    messages = []
    for i, cable in enumerate(case.cables):
        messages += _line_type_errors(case, i)
        for j, item in enumerate(cable.attachments):
            if item.body not in case.bodies:
                messages.append(f"cables[{i}].attachments[{j}].body: '{item.body}' is not a "
                                f"body; known: {listing(case.bodies)}"
                                f"{suggest(item.body, list(case.bodies))}")
        for key, end in (("from", cable.from_), ("to", cable.to)):
            group = {"body": case.bodies, "point": case.points}.get(end.kind)
            if group is not None and end.name not in group:
                messages.append(f"cables[{i}].{key}: '{end.name}' is not a {end.kind}; known: "
                                f"{listing(group)}{suggest(end.name, list(group))}")
    return messages + _condition_errors(case)


def _condition_errors(case: Case) -> list[str]:
    """Messages for design conditions that are neither intact, damaged nor a cable's name."""
    if case.design is None:
        return []
    cables = [c.name for c in case.cables]
    return [f"design.conditions[{j}]: '{entry}' is neither intact, damaged nor a cable; cables: "
            f"{listing(cables)}{suggest(entry, cables)}"
            for j, entry in enumerate(case.design.conditions)
            if entry not in ("intact", "damaged") and entry not in cables]
