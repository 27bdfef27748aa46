"""Tables a case refers to by file name, read when the case is loaded.

``vessel.motion: {table: motion.csv}`` names a CSV file next to the case file; it is read
here, into the case data (``rows``), before validation, so that the model holds numbers
and no solver opens a file. The CSV has a header row naming its columns (``time`` and any
of ``surge, sway, heave, roll, pitch, yaw``, in any order; a unit in parentheses or
brackets after a name is allowed: ``surge (m)``); missing degrees of freedom are zero;
lines starting with ``#`` are comments. Units: s, m and deg.

The name must end in ``.csv`` and name a regular file of UTF-8 text of at most
:data:`MAX_TABLE_BYTES`; a file that is anything else (``/etc/passwd``, a device, a
binary) is refused without quoting its content: the messages quote a header cell only
when it looks like a column name, and a bad value by its first 20 characters.
"""
from __future__ import annotations

import csv
import re
from pathlib import Path as FilePath
from typing import Any

from ..errors import Problem
from ..model._base import suggest
from ..model.operations import DOFS, TABLE_COLUMNS
from ..model.paths import Path, key_path, line_of

MAX_TABLE_ROWS = 1_000_000
"""Most rows of a motion table (a day at 0.1 s is 864 000 rows)."""
MAX_TABLE_BYTES = 128 * 1024**2
"""Largest motion table [bytes]: a million rows of seven 15-character numbers are 112 MB."""
_UNIT = re.compile(r"\s*[\(\[].*[\)\]]\s*$")
_COLUMN_NAME = re.compile(r"[a-z][a-z0-9_ ]{0,23}")
"""What a header cell looks like once its unit is removed: a short word, quoted in messages."""


class TableError(ValueError):
    """A table that cannot be read; the message names the file, the row and the column."""


def _columns(header: list[str], source: str) -> list[int | None]:
    """For each of :data:`TABLE_COLUMNS`, its index in the CSV (None: absent)."""
    names = [_UNIT.sub("", h).strip().lower() for h in header]
    for number, name in enumerate(names, 1):
        if name in TABLE_COLUMNS:
            continue
        if not _COLUMN_NAME.fullmatch(name):      # not a header: say so without quoting the file
            raise TableError(f"{source}: its first row is not a header of column names (column "
                             f"{number} is no column name); a motion table is a CSV file whose first "
                             f"row names its columns: {', '.join(TABLE_COLUMNS)}")
        raise TableError(f"{source}: unknown column '{name}'{suggest(name, list(TABLE_COLUMNS))}; "
                         f"columns: {', '.join(TABLE_COLUMNS)}")
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise TableError(f"{source}: column '{repeated[0]}' appears twice")
    if "time" not in names:
        raise TableError(f"{source}: needs a 'time' column (s); the header row names the "
                         f"columns: {', '.join(TABLE_COLUMNS)}")
    return [names.index(c) if c in names else None for c in TABLE_COLUMNS]


def check_csv_file(path: FilePath, what: str = "motion table", columns=TABLE_COLUMNS,
                   example: str = "motion.csv") -> None:
    """A ``.csv`` name, a regular file, at most :data:`MAX_TABLE_BYTES` (OSError when missing);
    ``what`` and ``columns`` say in the messages what the file should be."""
    if path.suffix.lower() != ".csv":
        raise TableError(f"'{path.name}' is not a .csv file; a {what} is a CSV file ({example}) "
                         f"whose first row names its columns: {', '.join(columns)}")
    size = path.stat().st_size                    # OSError: missing, no permission
    if not path.is_file():
        raise TableError(f"{path.name}: not a regular file (a directory, a device or a pipe)")
    if size > MAX_TABLE_BYTES:
        raise TableError(f"{path.name}: {size / 1024**2:.0f} MiB, more than the "
                         f"{MAX_TABLE_BYTES / 1024**2:.0f} MiB a {what} may hold")


def read_motion_table(path: str | FilePath) -> list[list[float]]:
    """Rows ``[time, surge, sway, heave, roll, pitch, yaw]`` of a motion CSV file.

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        With the file, the row and the column of the first bad entry.
    """
    path = FilePath(path)
    check_csv_file(path)
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            lines = [(n, row) for n, row in enumerate(csv.reader(handle), 1)
                     if row and not row[0].lstrip().startswith("#")]
    except UnicodeDecodeError:
        raise TableError(f"{path.name}: not a text file (it is not UTF-8); a motion table is a CSV "
                         f"file whose first row names its columns: {', '.join(TABLE_COLUMNS)}") from None
    except csv.Error as error:
        raise TableError(f"{path.name}: not a CSV file ({error})") from None
    if not lines:
        raise TableError(f"{path.name}: empty; the first row names the columns "
                         f"({', '.join(TABLE_COLUMNS)})")
    columns = _columns(lines[0][1], path.name)
    if len(lines) - 1 > MAX_TABLE_ROWS:
        raise TableError(f"{path.name}: {len(lines) - 1:,} rows, more than {MAX_TABLE_ROWS:,}")
    rows = []
    for number, row in lines[1:]:
        if len(row) != len(lines[0][1]):
            raise TableError(f"{path.name}, line {number}: {len(row)} values for "
                             f"{len(lines[0][1])} columns")
        values = []
        for name, index in zip(TABLE_COLUMNS, columns):
            text = row[index].strip() if index is not None else "0"
            try:
                values.append(float(text))
            except ValueError:
                raise TableError(f"{path.name}, line {number}, column {name}: {text[:20]!r} is "
                                 "not a number") from None
        rows.append(values)
    return rows


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
    where: Path = ("vessel", "motion", "table")
    name = motion["table"]
    try:
        motion["rows"] = read_motion_table(base / name)
        return []
    except OSError as error:
        message = (f"cannot read the motion table '{name}' ({error.strerror or error}); the path "
                   f"is relative to the case file's folder {base}")
    except TableError as error:
        message = str(error)
    del motion["table"]            # reported here; the rest of the case is still checked
    return [Problem(key_path(where), message, file, line_of(lines, where))]


def _resolve_raos(motion: dict, base: FilePath, file: str | None, lines: dict[Path, int]) -> list[Problem]:
    """``motion['rao_rows']`` from the RAO file ``motion['rao']`` (:mod:`kanat.io.raos`)."""
    from .raos import RaoError, read_raos

    where: Path = ("vessel", "motion", "rao")
    name = motion["rao"]
    ulen = motion.get("ulen", 1.0)
    try:
        motion["rao_rows"] = read_raos(base / name, ulen if isinstance(ulen, (int, float)) and ulen > 0 else 1.0)
        return []
    except OSError as error:
        message = (f"cannot read the RAO file '{name}' ({error.strerror or error}); the path "
                   f"is relative to the case file's folder {base}")
    except RaoError as error:
        message = str(error)
    del motion["rao"]
    return [Problem(key_path(where), message, file, line_of(lines, where))]


__all__ = ["DOFS", "MAX_TABLE_BYTES", "MAX_TABLE_ROWS", "TableError", "check_csv_file", "read_motion_table",
           "resolve_tables"]
