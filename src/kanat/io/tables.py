"""Tables a case refers to by file name, read when the case is loaded.

``vessel.motion: {table: motion.csv}`` names a CSV file next to the case file; it is read
here, into the case data (``rows``), before validation, so that the model holds numbers
and no solver opens a file. The CSV has a header row naming its columns (``time`` and any
of ``surge, sway, heave, roll, pitch, yaw``, in any order; a unit in parentheses or
brackets after a name is allowed: ``surge (m)``); missing degrees of freedom are zero;
lines starting with ``#`` are comments. Units: s, m and deg. The rows are read by
:func:`kanat.io.csv_rows.read_rows`, as every table of a case is.

The name must end in ``.csv`` and name a regular file of UTF-8 text of at most
:data:`MAX_TABLE_BYTES`; a file that is anything else (``/etc/passwd``, a device, a
binary) is refused without quoting its content: the messages quote a header cell only
when it looks like a column name, and a bad value by its first 20 characters.
"""
from __future__ import annotations

from pathlib import Path as FilePath
from typing import Any

from ..errors import Problem
from ..model.operations import DOFS, TABLE_COLUMNS
from ..model.paths import Path, key_path, line_of
from .raos import read_raos
from .csv_rows import MAX_TABLE_BYTES, MAX_TABLE_ROWS, TableError, TableSpec, read_rows

MOTION_TABLE = TableSpec("motion table", TABLE_COLUMNS, ("time",), "motion.csv")
"""A motion table's columns: ``time`` [s] and any of the six degrees of freedom [m, deg]."""


def read_motion_table(path: str | FilePath) -> list[list[float]]:
    """Rows ``[time, surge, sway, heave, roll, pitch, yaw]`` of a motion CSV file (missing
    degrees of freedom are zero).

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        With the file, the row and the column of the first bad entry.
    """
    return [[row.number(name, 0.0) for name in TABLE_COLUMNS] for row in read_rows(path, MOTION_TABLE)]


def resolve_tables(data: Any, base: FilePath, file: str | None,
                   lines: dict[Path, int]) -> list[Problem]:
    """Read the tables ``data`` names (in place: ``rows`` beside ``table``).

    Parameters
    ----------
    data : object
        Case data as loaded from YAML.
    base : Path
        Directory the file names are relative to (the case file's).
    file : str or None
        Case file, for the problems.
    lines : dict
        Key-path lines of the case file.

    Returns
    -------
    list of Problem
        One per table that cannot be read, at its key.
    """
    vessel = data.get("vessel") if isinstance(data, dict) else None
    motion = vessel.get("motion") if isinstance(vessel, dict) else None
    if isinstance(motion, dict) and isinstance(motion.get("rao"), str) and motion.get("rao_rows") is None:
        return _resolve_raos(motion, base, file, lines)
    if not isinstance(motion, dict) or not isinstance(motion.get("table"), str) \
            or motion.get("rows") is not None:
        return []
    return read_named_table(motion, "table", "rows", ("vessel", "motion", "table"), read_motion_table,
                            "motion table", base, file, lines)


def _resolve_raos(motion: dict, base: FilePath, file: str | None, lines: dict[Path, int]) -> list[Problem]:
    """``motion['rao_rows']`` from the RAO file ``motion['rao']`` (:mod:`kanat.io.raos`)."""
    ulen = motion.get("ulen", 1.0)
    ulen = ulen if isinstance(ulen, (int, float)) and ulen > 0 else 1.0
    return read_named_table(motion, "rao", "rao_rows", ("vessel", "motion", "rao"), lambda path: read_raos(path, ulen),
                            "RAO file", base, file, lines)


def read_named_table(section: dict, key: str, into: str, where: Path, read, what: str, base: FilePath,
                     file: str | None, lines: dict[Path, int]) -> list[Problem]:
    """Read the file named at ``section[key]`` (relative to ``base``) by ``read(path)`` into ``section[into]``.

    Returns
    -------
    list of Problem
        Empty once read; else the problem at the key path ``where``, naming the ``what`` (``"motion
        table"``) and why it cannot be read. The key is then dropped (reported here; the rest of the
        case is still checked).
    """
    name = section[key]
    try:
        section[into] = read(base / name)
        return []
    except OSError as error:
        message = (f"cannot read the {what} '{name}' ({error.strerror or error}); the path "
                   f"is relative to the case file's folder {base}")
    except TableError as error:                    # RaoError is one
        message = str(error)
    del section[key]
    return [Problem(key_path(where), message, file, line_of(lines, where))]


__all__ = ["DOFS", "MAX_TABLE_BYTES", "MAX_TABLE_ROWS", "MOTION_TABLE", "TableError", "read_motion_table",
           "read_named_table", "resolve_tables"]
