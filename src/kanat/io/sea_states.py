"""The sea-state table of a design block (``design: {sea_states: sea_states.csv}``).

Read when the case is loaded, into ``design.sea_state_rows``, like a vessel's motion table
(:mod:`kanat.io.tables`, whose file checks it shares): a CSV file whose first row names the
columns :data:`kanat.model.design.SEA_STATE_COLUMNS` (any order; ``gamma`` and
``heading_deg`` may be left out: 3.3 and 0); lines starting with ``#`` are comments.
"""
from __future__ import annotations

import csv
from pathlib import Path as FilePath
from typing import Any

from ..errors import Problem
from ..model._base import suggest
from ..model.design import SEA_STATE_COLUMNS
from ..model.paths import Path, key_path, line_of
from .tables import TableError, check_csv_file

OPTIONAL = {"gamma": 3.3, "heading_deg": 0.0}
"""Columns a table may leave out, and their values."""


def _header(row: list[str], name: str) -> list[str]:
    columns = [cell.strip().lower() for cell in row]
    for column in columns:
        if column not in SEA_STATE_COLUMNS:
            raise TableError(f"{name}: unknown column '{column[:24]}'"
                             f"{suggest(column, list(SEA_STATE_COLUMNS))}; columns: "
                             f"{', '.join(SEA_STATE_COLUMNS)}")
    missing = [c for c in SEA_STATE_COLUMNS if c not in columns and c not in OPTIONAL]
    if missing:
        raise TableError(f"{name}: no '{missing[0]}' column; columns: {', '.join(SEA_STATE_COLUMNS)}")
    return columns


def read_sea_states(path: str | FilePath) -> list[dict[str, Any]]:
    """The rows of a sea-state CSV file, as mappings of :data:`SEA_STATE_COLUMNS`.

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        With the file, the line and the column of the first bad entry.
    """
    path = FilePath(path)
    check_csv_file(path, "sea-state table", SEA_STATE_COLUMNS, "sea_states.csv")
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            lines = [(n, row) for n, row in enumerate(csv.reader(handle), 1)
                     if row and not row[0].lstrip().startswith("#")]
    except (UnicodeDecodeError, csv.Error):
        raise TableError(f"{path.name}: not a CSV text file") from None
    if not lines:
        raise TableError(f"{path.name}: empty; the first row names the columns "
                         f"({', '.join(SEA_STATE_COLUMNS)})")
    columns = _header(lines[0][1], path.name)
    rows = []
    for number, row in lines[1:]:
        if len(row) != len(columns):
            raise TableError(f"{path.name}, line {number}: {len(row)} values for {len(columns)} columns")
        entry: dict[str, Any] = dict(OPTIONAL)
        for column, text in zip(columns, row):
            text = text.strip()
            if column == "name":
                entry[column] = text
                continue
            try:
                entry[column] = float(text)
            except ValueError:
                raise TableError(f"{path.name}, line {number}, column {column}: {text[:20]!r} is "
                                 "not a number") from None
        rows.append(entry)
    return rows


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
    where: Path = ("design", "sea_states")
    name = design["sea_states"]
    try:
        design["sea_state_rows"] = read_sea_states(base / name)
        return []
    except OSError as error:
        message = (f"cannot read the sea-state table '{name}' ({error.strerror or error}); the "
                   f"path is relative to the case file's folder {base}")
    except TableError as error:
        message = str(error)
    del design["sea_states"]
    return [Problem(key_path(where), message, file, line_of(lines, where))]


__all__ = ["OPTIONAL", "read_sea_states", "resolve_sea_states"]
