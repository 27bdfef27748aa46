"""The sea-state table of a design block (``design: {sea_states: sea_states.csv}``).

Read when the case is loaded, into ``design.sea_state_rows``, like a vessel's motion table
(:mod:`kanat.io.tables`) and by the same reader (:func:`kanat.io.csv_rows.read_rows`): a CSV
file whose first row names the columns :data:`kanat.model.design.SEA_STATE_COLUMNS` (any order; ``gamma`` and
``heading_deg`` may be left out: 3.3 and 0); lines starting with ``#`` are comments.
"""
from __future__ import annotations

from pathlib import Path as FilePath
from typing import Any

from ..errors import Problem
from ..model.design import SEA_STATE_COLUMNS
from ..model.paths import Path
from .csv_rows import TableSpec, read_rows
from .tables import read_named_table

OPTIONAL = {"gamma": 3.3, "heading_deg": 0.0}
"""Columns a table may leave out, and their values."""
SEA_STATE_TABLE = TableSpec("sea-state table", SEA_STATE_COLUMNS,
                            tuple(c for c in SEA_STATE_COLUMNS if c not in OPTIONAL), "sea_states.csv")
"""A sea-state table's columns (:data:`kanat.model.design.SEA_STATE_COLUMNS`)."""
TEXT_COLUMNS = ("name",)
"""Columns read as text; the others are numbers."""


def read_sea_states(path: str | FilePath) -> list[dict[str, Any]]:
    """The rows of a sea-state CSV file, as mappings of :data:`SEA_STATE_COLUMNS`.

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        With the file, the line and the column of the first bad entry.
    """
    return [{column: row.text(column) if column in TEXT_COLUMNS else row.number(column, OPTIONAL.get(column))
             for column in SEA_STATE_COLUMNS}
            for row in read_rows(path, SEA_STATE_TABLE)]


def resolve_sea_states(data: Any, base: FilePath, file: str | None,
                       lines: dict[Path, int]) -> list[Problem]:
    """Read ``design.sea_states`` into ``design.sea_state_rows`` (in place).

    Returns
    -------
    list of Problem
        The table's problem at its key, if it cannot be read.
    """
    design = data.get("design") if isinstance(data, dict) else None
    if not isinstance(design, dict) or not isinstance(design.get("sea_states"), str) \
            or design.get("sea_state_rows") is not None:
        return []
    return read_named_table(design, "sea_states", "sea_state_rows", ("design", "sea_states"), read_sea_states,
                            "sea-state table", base, file, lines)


__all__ = ["OPTIONAL", "SEA_STATE_TABLE", "read_sea_states", "resolve_sea_states"]
