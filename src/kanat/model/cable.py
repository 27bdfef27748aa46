"""Cables, their sections, inline attachments and end conditions (case section ``cables``).

An end is written in the case file as ``vessel`` (the tow point), ``{vessel: [x, y, z]}``
(a fairlead in vessel axes), ``free``, ``anchor:[x, y, z]``, ``{anchor: [x, y, z]}``, the
name of a body or point (also ``{body: name}``, ``{point: name}``), or ``{body: name,
offset: [x, y, z]}`` (a fairlead in the body's axes). All forms become a typed
:class:`CableEnd`.

A cable is one line type (``line_type``, ``length``, ``segments``) or several
``sections`` from ``from`` to ``to``; either way it exposes the normalised ``sections``
(one for a single-type cable), the total ``length`` and the total ``segments``.

With bending stiffness an end is pinned (moment-free) unless ``end_a`` (the ``from`` end) or
``end_b`` (the ``to`` end) says ``{clamped: true}``: the line then leaves its anchor, the vessel
or a 6-DOF body along a direction held by it (:class:`EndFixity`, :mod:`kanat.lumped.clamps`).
"""
from __future__ import annotations

import re
from typing import Any, Literal

from pydantic import Field, ValidationInfo, field_validator, model_validator
from pydantic_core import PydanticCustomError

from ._base import KanatModel, Vector3, fmt, listing, quantity, suggest

EndKind = Literal["vessel", "anchor", "body", "point", "free"]
END_FORMS = ("vessel, {vessel: [x, y, z]}, free, anchor:[x, y, z], {anchor: [x, y, z]}, a body "
             "or point name, or {body: name, offset: [x, y, z]}")
_POINT_TEXT = re.compile(r"^(?P<kind>anchor|vessel)\s*:?\s*\[(?P<xyz>.*)\]\s*$")
_NAMED_KINDS = ("body", "point")
_LINE_FORM = ("line_type", "length", "segments")
LENGTH_RTOL = 1e-9
"""Relative tolerance when comparing lengths (sections' total, attachment positions)."""


class CableEnd(KanatModel):
    """Where a cable end is attached.

    Attributes
    ----------
    kind : {"vessel", "anchor", "body", "point", "free"}
    name : str or None
        Body or point name (kinds ``body`` and ``point``).
    position : tuple of 3 float or None
        Anchor position in the global frame [m] (kind ``anchor``).
    offset : tuple of 3 float or None
        Fairlead: in the body's axes from its reference point (kind ``body``), or in vessel
        axes (kind ``vessel``; None: the tow point, ``vessel.tow_point``) [m].
    """

    kind: EndKind
    name: str | None = None
    position: Vector3 | None = quantity(None, unit="m", description="anchor position in the "
                                        "global frame")
    offset: Vector3 | None = quantity(
        None, unit="m", description="fairlead position: in body axes from the body's "
                                    "reference point (body ends), or in vessel axes (vessel "
                                    "ends; None: the tow point)")

    @model_validator(mode="before")
    @classmethod
    def _parse(cls, value: Any, info: ValidationInfo) -> Any:
        return parse_end(value, (info.context or {}).get("names"))

    @model_validator(mode="after")
    def _consistent(self) -> CableEnd:
        if self.kind == "anchor" and self.position is None:
            raise ValueError("an anchor needs a position: anchor:[x, y, z]")
        if self.kind in _NAMED_KINDS and not self.name:
            raise ValueError(f"a {self.kind} end needs the {self.kind}'s name")
        if self.offset is not None and self.kind not in ("body", "vessel"):
            raise ValueError(f"an offset places a fairlead on a body or the vessel, not on "
                             f"a {self.kind} end")
        return self

    @property
    def is_fixed(self) -> bool:
        """True for ends whose motion is prescribed (vessel tow point or fairlead, anchor)."""
        return self.kind in ("vessel", "anchor")

    @property
    def is_fairlead(self) -> bool:
        """True for an end at an offset on a body or on the vessel (not the tow point)."""
        return self.offset is not None

    def __str__(self) -> str:
        if self.kind == "anchor":
            return "anchor:[" + ", ".join(f"{c:g}" for c in self.position) + "]"
        xyz = "" if self.offset is None else "[" + ", ".join(f"{c:g}" for c in self.offset) + "]"
        if self.kind == "vessel":
            return f"vessel:{xyz}" if xyz else "vessel"
        if self.kind in _NAMED_KINDS:
            return f"{self.name} at {xyz}" if xyz else self.name
        return self.kind


class EndFixity(KanatModel):
    """How a cable end holds the line's direction (with ``bending_stiffness``), and when it lets go.

    Attributes
    ----------
    clamped : bool
        False: pinned, moment-free (the default). True: the line leaves the end along
        ``direction``, which turns with the vessel or the 6-DOF body the end is on.
    direction : tuple of 3 float or None
        The clamp's direction, pointing from the end into the line: in the global frame at an
        anchor, in vessel axes at a vessel end, in body axes at a body end. None: along the
        line's end element in the network's first guess (the line laid straight or sagging
        between its end positions, on the seabed where it would dip below it).
    release_at : float or None
        Time [s] at which a vessel or anchor end lets go of the line: from then on the end is a
        free node, starting from the place and velocity it had (:mod:`kanat.release`). None: held
        for the whole run.
    """

    clamped: bool = Field(False, description="the line leaves this end clamped: the end holds its "
                          "direction (with bending_stiffness; an anchor, the vessel or a dof 6 body); "
                          "false: pinned, moment-free")
    direction: Vector3 | None = Field(
        None, description="clamp direction from the end into the line: global at an anchor, vessel "
                          "axes at a vessel end, body axes at a body end; default: along the line's "
                          "end element in the first guess")
    release_at: float | None = quantity(
        None, unit="s", gt=0, description="time at which this end (the vessel or an anchor) lets go of the "
                                          "line, which goes on from there with a free end (lumped model); "
                                          "default: held for the whole run")

    @model_validator(mode="after")
    def _direction(self) -> EndFixity:
        if self.direction is not None:
            if not self.clamped:
                raise ValueError("a direction needs clamped: true (a pinned end holds no direction)")
            if sum(c * c for c in self.direction) == 0.0:
                raise ValueError("direction is the zero vector; give the direction the line leaves the end")
        return self


def _point_from_text(text: str) -> dict[str, Any]:
    match = _POINT_TEXT.match(text)
    if match is None:
        raise ValueError(f"'{text}' is not an end; write anchor:[x, y, z] or vessel:[x, y, z]")
    parts = [p.strip() for p in match["xyz"].split(",")]
    try:
        xyz = [float(p) for p in parts]
    except ValueError:
        raise ValueError(f"'{text}': {match['kind']} coordinates must be 3 numbers, "
                         f"as in {match['kind']}:[0, 0, -100]") from None
    if len(xyz) != 3:
        raise ValueError(f"'{text}': needs 3 coordinates [x, y, z] (got {len(xyz)})")
    kind = match["kind"]
    return {"kind": kind, "position" if kind == "anchor" else "offset": xyz}


def _unknown_name(name: str, names: dict[str, list[str]] | None) -> ValueError:
    names = names or {}
    bodies = names.get("bodies") or []
    points = names.get("points") or []
    known = listing(bodies)
    known_points = listing(points)
    hint = suggest(name, [*bodies, *points, "vessel", "free", "anchor"])
    return ValueError(f"'{name}' is not a body or point; valid ends: {END_FORMS} "
                      f"(bodies: {known}; points: {known_points}){hint}")


def _known(kind: str, name: Any, names: dict[str, list[str]] | None) -> None:
    """Raise for a body or point name the case does not have (when the names are known)."""
    group = (names or {}).get("bodies" if kind == "body" else "points")
    if group is not None and isinstance(name, str) and name not in group:
        plural = "bodies" if kind == "body" else "points"
        raise ValueError(f"'{name}' is not a {kind}; known {plural}: {', '.join(group) or 'none'}"
                         f"{suggest(name, group)}")


def _end_from_mapping(value: dict, names: dict[str, list[str]] | None) -> dict[str, Any]:
    keys = set(value)
    if keys == {"body", "offset"}:
        _known("body", value["body"], names)
        return {"kind": "body", "name": value["body"], "offset": value["offset"]}
    if len(value) != 1:
        raise ValueError(f"must be one of {END_FORMS} (got a mapping with keys "
                         f"{', '.join(map(str, value))})")
    (key, item), = value.items()
    if key == "anchor":
        return {"kind": "anchor", "position": item}
    if key == "vessel":
        return {"kind": "vessel", "offset": item}
    if key in _NAMED_KINDS:
        _known(key, item, names)
        return {"kind": key, "name": item}
    raise ValueError(f"unknown end form '{key}'"
                     f"{suggest(key, ['anchor', 'vessel', 'body', 'point'])}; valid: {END_FORMS}")


def parse_end(value: Any, names: dict[str, list[str]] | None = None) -> Any:
    """Turn any accepted way of writing a cable end into ``CableEnd`` fields.

    Parameters
    ----------
    value : str, dict or CableEnd
        The end as written in the case.
    names : dict or None
        ``{"bodies": [...], "points": [...]}`` known in the case, to resolve a bare
        name; None when unknown (a bare name is then taken as a body).

    Returns
    -------
    dict or CableEnd
        Fields for :class:`CableEnd` (``kind``, ``name``, ``position``, ``offset``).
    """
    if isinstance(value, CableEnd) or (isinstance(value, dict) and "kind" in value):
        return value
    if isinstance(value, dict):
        return _end_from_mapping(value, names)
    if not isinstance(value, str):
        raise ValueError(f"must be one of {END_FORMS} (got {value!r})")
    text = value.strip()
    if text in ("vessel", "free"):
        return {"kind": text}
    if text.startswith(("anchor", "vessel")):
        return _point_from_text(text)
    if names is None:
        return {"kind": "body", "name": text}
    for kind, group in (("body", "bodies"), ("point", "points")):
        if text in (names.get(group) or []):
            return {"kind": kind, "name": text}
    raise _unknown_name(text, names)


def _known_line_type(value: str, info: ValidationInfo) -> str:
    """A line type name checked against the case's ``line_types`` (when validated in context)."""
    known = ((info.context or {}).get("names") or {}).get("line_types")
    if known is not None and value not in known:
        raise PydanticCustomError(
            "unknown_name", "'{name}' is not a line type; known: {known}{hint}",
            {"name": value, "known": listing(known, "none (add a line_types section)"),
             "hint": suggest(value, known)})
    return value


class CableSection(KanatModel):
    """A stretch of one line type within a cable.

    Attributes
    ----------
    line_type : str
        Key of ``Case.line_types``.
    length : float
        Unstretched length [m].
    segments : int
        Number of elements of the section.
    """

    line_type: str = Field(description="name of a line type in line_types")
    length: float = quantity(unit="m", gt=0, description="unstretched length of the section")
    segments: int = Field(ge=1, description="number of elements of the section")

    @field_validator("line_type")
    @classmethod
    def _known(cls, value: str, info: ValidationInfo) -> str:
        return _known_line_type(value, info)


class Attachment(KanatModel):
    """A body clamped to a cable at an unstretched arclength (a float or a clump weight).

    Attributes
    ----------
    body : str
        Key of ``Case.bodies``.
    s : float
        Unstretched arclength from the cable's ``from`` end [m], in ``[0, length]``.
    """

    body: str = Field(description="name of a body in bodies")
    s: float = quantity(unit="m", ge=0, description="unstretched arclength from the cable's "
                                                    "'from' end, in [0, length]")

    @field_validator("body")
    @classmethod
    def _known_body(cls, value: str, info: ValidationInfo) -> str:
        bodies = ((info.context or {}).get("names") or {}).get("bodies")
        if bodies is not None and value not in bodies:
            raise PydanticCustomError(
                "unknown_name", "'{name}' is not a body; known: {known}{hint}",
                {"name": value, "known": listing(bodies, "none (add a bodies section)"),
                 "hint": suggest(value, bodies)})
        return value


_FROM_SECTIONS = "<from sections>"
"""Placeholder ``line_type`` of a cable written with ``sections`` until they are validated."""


class Cable(KanatModel):
    """One cable: one line type or several sections, two ends, inline attachments.

    Write either ``line_type``, ``length`` and ``segments`` (a single-type cable) or
    ``sections``. After validation every cable has both: ``sections`` (one for a
    single-type cable), ``length`` and ``segments`` (the totals) and ``line_type`` (the
    type at ``s = 0``: the only type of a single-type cable). The derived values are not
    counted as written (``model_dump(exclude_unset=True)`` gives the form the user wrote;
    a full dump gives both, which validate again as they agree). Change a validated cable
    with ``model_validate``, not ``model_copy``, so that the two stay consistent.

    Attributes
    ----------
    name : str
    line_type : str
        Key of ``Case.line_types`` (the first section's, for a cable of several).
    length : float
        Unstretched length [m] (total).
    segments : int
        Number of elements (total; nodes = segments + 1).
    sections : tuple of CableSection
        From ``from`` to ``to``.
    attachments : tuple of Attachment
        Bodies clamped to the cable, ordered by ``s``.
    from_ : CableEnd
        First end (``s = 0``), written ``from`` in the case file.
    to : CableEnd
        Second end (``s = length``).
    end_a, end_b : EndFixity
        Whether the ``from`` and ``to`` ends are pinned (default) or clamped.
    """

    name: str
    line_type: str = Field(description="name of a line type in line_types (a single-type "
                           "cable; or give sections)")
    length: float = quantity(unit="m", gt=0, description="unstretched length (a single-type "
                             "cable; or give sections)")
    segments: int = Field(ge=1, description="number of elements (a single-type cable; or give "
                          "sections)")
    sections: tuple[CableSection, ...] | None = Field(
        None, description="the line made of several line types, from 'from' to 'to'; replaces "
                          "line_type, length and segments")
    attachments: tuple[Attachment, ...] = Field(
        (), description="bodies clamped to the cable (floats, clump weights), each at an "
                        "unstretched arclength s from 'from', in order of s")
    from_: CableEnd = Field(alias="from", description="first end (s = 0)")
    to: CableEnd = Field(description="second end (s = length)")
    end_a: EndFixity = Field(EndFixity(), description="the 'from' end: {clamped: true} "
                             "holds the line's direction there (with bending; default pinned); "
                             "{release_at: t} lets the line go at time t")
    end_b: EndFixity = Field(EndFixity(), description="the 'to' end: {clamped: true} "
                             "holds the line's direction there (with bending; default pinned); "
                             "{release_at: t} lets the line go at time t")

    @field_validator("line_type")
    @classmethod
    def _known(cls, value: str, info: ValidationInfo) -> str:
        return value if value == _FROM_SECTIONS else _known_line_type(value, info)

    @model_validator(mode="before")
    @classmethod
    def _one_form(cls, data: Any) -> Any:
        if not isinstance(data, dict) or data.get("sections") is None:
            return data
        written = [k for k in _LINE_FORM if data.get(k) is not None]
        if written:
            mismatch = _disagreement(data, written)
            if mismatch:
                raise ValueError(f"give either sections or line_type, length and segments, not "
                                 f"both ({mismatch})")
        # placeholders that validate; the totals replace them once the sections are valid
        return {**data, "line_type": _FROM_SECTIONS, "length": 1.0, "segments": 1}

    @model_validator(mode="after")
    def _normalise(self) -> Cable:
        if self.line_type == _FROM_SECTIONS:
            if not self.sections:
                raise ValueError("sections is empty; give at least one {line_type, length, "
                                 "segments}")
            object.__setattr__(self, "line_type", self.sections[0].line_type)
            object.__setattr__(self, "length", sum(s.length for s in self.sections))
            object.__setattr__(self, "segments", sum(s.segments for s in self.sections))
            self.__pydantic_fields_set__.difference_update(_LINE_FORM)
        else:
            section = CableSection.model_construct(line_type=self.line_type, length=self.length,
                                                   segments=self.segments)
            object.__setattr__(self, "sections", (section,))
            self.__pydantic_fields_set__.discard("sections")
        self._check_attachments()
        self._distinct_ends()
        self._releasable()
        return self

    def _releasable(self) -> None:
        for key, end in (("end_a", self.from_), ("end_b", self.to)):
            fixity = getattr(self, key)
            if fixity.release_at is None:
                continue
            if end.kind not in ("vessel", "anchor"):
                raise ValueError(f"{key}.release_at: only a vessel or an anchor end can be released (this end "
                                 f"is {end}); a {end.kind} end is already free to move")
            if fixity.clamped:
                raise ValueError(f"{key}: a released end cannot be clamped too (give release_at or clamped)")

    def _check_attachments(self) -> None:
        for i, item in enumerate(self.attachments):
            if item.s > self.length * (1 + LENGTH_RTOL):
                raise ValueError(f"attachments[{i}].s = {fmt(item.s)} m is beyond the cable's "
                                 f"length {fmt(self.length)} m (s runs from 0 at 'from' to the "
                                 "length at 'to')")
        s_values = [a.s for a in self.attachments]
        if s_values != sorted(s_values):
            raise ValueError("attachments must be listed in order of s (from 'from' to 'to')")

    def _distinct_ends(self) -> None:
        if self.from_.kind == "free" and self.to.kind == "free":
            raise ValueError("both ends are 'free': attach at least one end to the vessel, "
                             "an anchor, a body or a point")
        if self.from_.kind in _NAMED_KINDS and self.from_ == self.to:
            raise ValueError(f"both ends are attached to '{self.to.name}' at the same place; "
                             "a cable must join two different places")

    @property
    def ends(self) -> tuple[CableEnd, CableEnd]:
        """``(from_, to)``."""
        return self.from_, self.to

    @property
    def line_types(self) -> tuple[str, ...]:
        """Line type of every section, from ``from`` to ``to``."""
        return tuple(s.line_type for s in self.sections)

    def section_bounds(self) -> list[tuple[float, float]]:
        """Unstretched arclength ``(start, end)`` of every section [m]."""
        bounds, start = [], 0.0
        for section in self.sections:
            bounds.append((start, start + section.length))
            start += section.length
        return bounds


def _disagreement(data: dict, written: list[str]) -> str:
    """Why line-form keys written beside ``sections`` do not repeat the sections' totals
    (as kanat's own full dump of a validated cable does); "" when they agree."""
    try:
        rows = [s if isinstance(s, dict) else s.model_dump() for s in data["sections"]]
        total = {"line_type": rows[0]["line_type"],
                 "length": sum(float(r["length"]) for r in rows),
                 "segments": sum(int(r["segments"]) for r in rows)}
    except (KeyError, TypeError, ValueError, AttributeError, IndexError):
        return f"found sections and {', '.join(written)}"
    for key in written:
        value, expected = data[key], total[key]
        if key == "length":
            same = isinstance(value, (int, float)) and abs(value - expected) <= LENGTH_RTOL * expected
        else:
            same = value == expected
        if not same:
            return (f"{key} {value!r} differs from the sections' "
                    f"{'first line type' if key == 'line_type' else 'total'} {expected!r}")
    return ""
