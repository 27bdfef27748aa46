"""The text layer of MoorDyn input files: sections, table rows and options, with lines.

A MoorDyn input file (v1 and v2) is divided by header lines of dashes around a section
name (``---------- LINE TYPES ----------``). Table sections have two lines of column names
and units, then one row per item; the options section has one ``value key [comment]``
per line. ``#``, ``!`` and ``%`` start comments. This module only cuts the text into
:class:`Row` records that remember their line; :mod:`kanat.io.moordyn` gives them meaning.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

SECTIONS = {
    "line_types": ("LINE TYPES", "LINE DICTIONARY", "LINE TYPE"),
    "rod_types": ("ROD TYPES", "ROD DICTIONARY"),
    "bodies": ("BODIES", "BODY LIST", "BODY PROPERTIES"),
    "rods": ("RODS", "ROD LIST", "ROD PROPERTIES"),
    "points": ("POINTS", "POINT LIST", "POINT PROPERTIES", "CONNECTION PROPERTIES",
               "CONNECTIONS", "NODE PROPERTIES", "NODES"),
    "lines": ("LINES", "LINE LIST", "LINE PROPERTIES"),
    "failure": ("FAILURE",),
    "control": ("CONTROL",),
    "external_loads": ("EXTERNAL LOADS",),
    "syrope": ("SYROPE IC",),
    "options": ("OPTIONS", "SOLVER OPTIONS"),
    "outputs": ("OUTPUTS", "OUTPUT"),
}
"""Section names by kanat's key, with every header MoorDyn v1 and v2 use for them."""
UNTABLED = ("options", "outputs")
"""Sections without the two lines of column names and units."""
_HEADER = re.compile(r"^\s*-{3,}")
_COMMENT = re.compile(r"[#!%]")
_WORDS = re.compile(r"[^A-Z]+")


@dataclass(frozen=True)
class Row:
    """One row of a section: its values as written and its 1-based line in the file."""

    line: int
    values: tuple[str, ...]


@dataclass
class MoorDynText:
    """A MoorDyn file cut into sections.

    Attributes
    ----------
    sections : dict of str to list of Row
        Rows by section key (:data:`SECTIONS`); header, column-name and unit lines removed.
    headers : dict of str to int
        Line of each section's header.
    """

    sections: dict[str, list[Row]] = field(default_factory=dict)
    headers: dict[str, int] = field(default_factory=dict)


def section_of(line: str) -> str | None:
    """The section key a header line opens (None: not a known section, or not a header)."""
    if not _HEADER.match(line):
        return None
    words = " ".join(_WORDS.sub(" ", line.upper()).split())
    if not words:
        return None
    best, size = None, 0
    for key, names in SECTIONS.items():
        for name in names:
            if re.search(rf"\b{name}\b", words) and len(name) > size:
                best, size = key, len(name)
    return best


def is_header(line: str) -> bool:
    """True for a line of dashes (a section header or an end marker)."""
    return bool(_HEADER.match(line))


def looks_like_moordyn(text: str) -> bool:
    """True when ``text`` has the headers of a MoorDyn input file: line types and lines, or options
    and another of its sections (a file of rods or bodies alone, which the reader then refuses by name,
    is MoorDyn's too)."""
    found = {section_of(line) for line in text.splitlines()[:5000] if is_header(line)}
    return ("line_types" in found and "lines" in found) or (
        "options" in found and bool(found & {"rod_types", "rods", "bodies", "points", "lines"}))


def split(text: str) -> MoorDynText:
    """Cut a MoorDyn file into its sections (module docstring)."""
    out = MoorDynText()
    current, skip = None, 0
    for number, raw in enumerate(text.splitlines(), 1):
        if is_header(raw):
            current = section_of(raw)
            if current is not None:
                out.headers.setdefault(current, number)
                out.sections.setdefault(current, [])
                skip = 0 if current in UNTABLED else 2
            continue
        if current is None or not raw.strip():
            continue                       # front matter, a section kanat does not know, blank
        if skip:
            skip -= 1                      # the column names, then the units
            continue
        values = tuple(_COMMENT.split(raw, maxsplit=1)[0].split())
        if not values:
            continue
        if current == "outputs" and values[0].upper() == "END":
            current = None
            continue
        out.sections[current].append(Row(number, values))
    return out
