"""Cables and their end conditions (case section ``cables``).

An end is written in the case file as ``vessel``, ``free``, ``anchor:[x, y, z]``,
``{anchor: [x, y, z]}``, or the name of a body or point (also ``{body: name}``,
``{point: name}``). All forms become a typed :class:`CableEnd`.
"""
from __future__ import annotations

import re
from typing import Any, Literal

from pydantic import Field, ValidationInfo, field_validator, model_validator
from pydantic_core import PydanticCustomError

from ._base import KanatModel, Vector3, quantity, suggest

EndKind = Literal["vessel", "anchor", "body", "point", "free"]
END_FORMS = "vessel, free, anchor:[x, y, z], {anchor: [x, y, z]}, or a body or point name"
_ANCHOR_TEXT = re.compile(r"^anchor\s*:?\s*\[(?P<xyz>.*)\]\s*$")
_NAMED_KINDS = ("body", "point")


class CableEnd(KanatModel):
    """Where a cable end is attached.

    Attributes
    ----------
    kind : {"vessel", "anchor", "body", "point", "free"}
    name : str or None
        Body or point name (kinds ``body`` and ``point``).
    position : tuple of 3 float or None
        Anchor position in the global frame [m] (kind ``anchor``).
    """

    kind: EndKind
    name: str | None = None
    position: Vector3 | None = quantity(None, unit="m")

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
        return self

    @property
    def is_fixed(self) -> bool:
        """True for ends whose motion is prescribed (vessel tow point, anchor)."""
        return self.kind in ("vessel", "anchor")

    def __str__(self) -> str:
        if self.kind == "anchor":
            return "anchor:[" + ", ".join(f"{c:g}" for c in self.position) + "]"
        return self.name if self.kind in _NAMED_KINDS else self.kind


def _anchor_from_text(text: str) -> dict[str, Any]:
    match = _ANCHOR_TEXT.match(text)
    if match is None:
        raise ValueError(f"'{text}' is not an anchor; write anchor:[x, y, z]")
    parts = [p.strip() for p in match["xyz"].split(",")]
    try:
        xyz = [float(p) for p in parts]
    except ValueError:
        raise ValueError(f"'{text}': anchor coordinates must be 3 numbers, "
                         "as in anchor:[0, 0, -100]") from None
    if len(xyz) != 3:
        raise ValueError(f"'{text}': an anchor needs 3 coordinates [x, y, z] (got {len(xyz)})")
    return {"kind": "anchor", "position": xyz}


def _unknown_name(name: str, names: dict[str, list[str]] | None) -> ValueError:
    names = names or {}
    bodies = names.get("bodies") or []
    points = names.get("points") or []
    known = ", ".join(bodies) or "none"
    known_points = ", ".join(points) or "none"
    hint = suggest(name, [*bodies, *points, "vessel", "free", "anchor"])
    return ValueError(f"'{name}' is not a body or point; valid ends: {END_FORMS} "
                      f"(bodies: {known}; points: {known_points}){hint}")


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
        Fields for :class:`CableEnd` (``kind``, ``name``, ``position``).
    """
    if isinstance(value, CableEnd) or (isinstance(value, dict) and "kind" in value):
        return value
    if isinstance(value, dict):
        if len(value) != 1:
            raise ValueError(f"must be one of {END_FORMS} (got a mapping with keys "
                             f"{', '.join(map(str, value))})")
        (key, item), = value.items()
        if key == "anchor":
            return {"kind": "anchor", "position": item}
        if key in _NAMED_KINDS:
            return {"kind": key, "name": item}
        raise ValueError(f"unknown end form '{key}'{suggest(key, ['anchor', 'body', 'point'])}; "
                         f"valid: {END_FORMS}")
    if not isinstance(value, str):
        raise ValueError(f"must be one of {END_FORMS} (got {value!r})")
    text = value.strip()
    if text in ("vessel", "free"):
        return {"kind": text}
    if text.startswith("anchor"):
        return _anchor_from_text(text)
    if names is None:
        return {"kind": "body", "name": text}
    for kind, group in (("body", "bodies"), ("point", "points")):
        if text in (names.get(group) or []):
            return {"kind": kind, "name": text}
    raise _unknown_name(text, names)


class Cable(KanatModel):
    """One cable: a line type, a length, a discretization and two ends.

    Attributes
    ----------
    name : str
    line_type : str
        Key of ``Case.line_types``.
    length : float
        Unstretched length [m].
    segments : int
        Number of elements (nodes = segments + 1).
    from_ : CableEnd
        First end (``s = 0``), written ``from`` in the case file.
    to : CableEnd
        Second end (``s = length``).
    """

    name: str
    line_type: str
    length: float = quantity(unit="m", gt=0)
    segments: int = Field(ge=1)
    from_: CableEnd = Field(alias="from")
    to: CableEnd

    @field_validator("line_type")
    @classmethod
    def _known_line_type(cls, value: str, info: ValidationInfo) -> str:
        known = ((info.context or {}).get("names") or {}).get("line_types")
        if known is not None and value not in known:
            raise PydanticCustomError(
                "unknown_name", "'{name}' is not a line type; known: {known}{hint}",
                {"name": value, "known": ", ".join(known) or "none (add a line_types section)",
                 "hint": suggest(value, known)})
        return value

    @model_validator(mode="after")
    def _distinct_ends(self) -> Cable:
        if self.from_.kind == "free" and self.to.kind == "free":
            raise ValueError("both ends are 'free': attach at least one end to the vessel, "
                             "an anchor, a body or a point")
        if self.from_.kind in _NAMED_KINDS and self.from_ == self.to:
            raise ValueError(f"both ends are attached to '{self.to.name}'; "
                             "a cable must join two different places")
        return self

    @property
    def ends(self) -> tuple[CableEnd, CableEnd]:
        """``(from_, to)``."""
        return self.from_, self.to
