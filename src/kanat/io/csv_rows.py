"""The one reader of the CSV tables a case names (a motion table, a sea-state table, a RAO table).

A table is a ``.csv`` file of UTF-8 text whose first row (after comments) names its columns, in
any order, each name optionally followed by a unit in parentheses or brackets (``surge (m)``,
``hs [m]``); lines starting with ``#`` are comments; blank lines are skipped. What the columns
are is the caller's (:class:`TableSpec`); this module reads the rows and says, for any fault,
the file, the line and the column:

* the file: not ``.csv``, not a regular file, larger than the spec allows, not UTF-8 text,
  not CSV, empty, more rows than the spec allows;
* the header: a cell that is no column name (quoted only when it looks like one, so that a
  file that is no table, ``/etc/passwd`` say, is never echoed), an unknown column (with the
  nearest known name), a column named twice, a required column missing;
* a row: the wrong number of values; a value that is not a finite number
  (:meth:`Row.number`, quoting at most 20 characters).
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path as FilePath

from ..model._base import suggest

MAX_TABLE_ROWS = 1_000_000
"""Most rows of a table (a day at 0.1 s is 864 000 rows)."""
MAX_TABLE_BYTES = 128 * 1024**2
"""Largest table [bytes]: a million rows of seven 15-character numbers are 112 MB."""
QUOTED_CHARACTERS = 20
"""A bad value is quoted by this many characters at most."""
_UNIT = re.compile(r"\s*[\(\[].*[\)\]]\s*$")
_COLUMN_NAME = re.compile(r"[a-z][a-z0-9_ ]{0,23}")
"""What a header cell looks like once its unit is removed: a short word, quoted in messages."""


class TableError(ValueError):
    """A table that cannot be read; the message names the file, the line and the column."""


@dataclass(frozen=True)
class TableSpec:
    """What a table holds, for the reader and its messages.

    Attributes
    ----------
    what : str
        The table in a message (``motion table``).
    columns : tuple of str
        Every column a table may have, lower case, in the order messages list them.
    required : tuple of str
        The columns every table must have.
    example : str
        A file name for the messages (``motion.csv``).
    max_bytes : int
        Largest file [bytes].
    max_rows : int
        Most data rows.
    """

    what: str
    columns: tuple[str, ...]
    required: tuple[str, ...]
    example: str
    max_bytes: int = MAX_TABLE_BYTES
    max_rows: int = MAX_TABLE_ROWS

    @property
    def listing(self) -> str:
        """The columns as a message lists them."""
        return ", ".join(self.columns)


@dataclass(frozen=True)
class Row:
    """A data row: its file, its line number (1-based, comments counted) and its cells by column."""

    file: str
    line: int
    cells: dict[str, str]

    def where(self, column: str) -> str:
        """``file, line N, column C`` for a message."""
        return f"{self.file}, line {self.line}, column {column}"

    def text(self, column: str, default: str | None = None) -> str | None:
        """The stripped text of ``column`` (``default`` when the table has no such column)."""
        return self.cells[column] if column in self.cells else default

    def number(self, column: str, default: float | None = None) -> float:
        """``column``'s value as a finite number (``default`` when the table has no such column).

        Raises
        ------
        TableError
            Naming the file, the line and the column when the text is no finite number.
        """
        if column not in self.cells:
            return default
        return finite_number(self.cells[column], self.where(column))


def check_csv_file(path: FilePath, spec: TableSpec) -> None:
    """A ``.csv`` name, a regular file, at most ``spec.max_bytes`` (OSError when missing)."""
    if path.suffix.lower() != ".csv":
        raise TableError(f"'{path.name}' is not a .csv file; a {spec.what} is a CSV file ({spec.example}) "
                         f"whose first row names its columns: {spec.listing}")
    size = path.stat().st_size                    # OSError: missing, no permission
    if not path.is_file():
        raise TableError(f"{path.name}: not a regular file (a directory, a device or a pipe)")
    if size > spec.max_bytes:
        raise TableError(f"{path.name}: {size / 1024**2:.0f} MiB, more than the "
                         f"{spec.max_bytes / 1024**2:.0f} MiB a {spec.what} may hold")


def finite_number(text: str, where: str, error: type[TableError] = TableError) -> float:
    """``text`` as a finite number.

    Raises
    ------
    TableError
        Or its subclass ``error``: at ``where`` (file, line and column), quoting the text's first
        :data:`QUOTED_CHARACTERS` characters, when it is no finite number.
    """
    try:
        value = float(text)
    except ValueError:
        raise error(f"{where}: {text.strip()[:QUOTED_CHARACTERS]!r} is not a number") from None
    if not math.isfinite(value):
        raise error(f"{where}: {text.strip()[:QUOTED_CHARACTERS]!r} is not a finite number")
    return value


def read_rows(path: str | FilePath, spec: TableSpec) -> list[Row]:
    """The data rows of the CSV table ``path`` (module docstring).

    Parameters
    ----------
    path : str or Path
    spec : TableSpec

    Returns
    -------
    list of Row
        In file order; a row's cells hold the columns its header names (stripped text).

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        Naming the file, the line and the column of the first fault.
    """
    path = FilePath(path)
    check_csv_file(path, spec)
    lines = _lines(path, spec)
    if not lines:
        raise TableError(f"{path.name}: empty; the first row names the columns ({spec.listing})")
    header = _header(lines[0][1], path.name, spec)
    if len(lines) - 1 > spec.max_rows:
        raise TableError(f"{path.name}: {len(lines) - 1:,} rows, more than {spec.max_rows:,}")
    rows = []
    for number, cells in lines[1:]:
        if len(cells) != len(header):
            raise TableError(f"{path.name}, line {number}: {len(cells)} values for {len(header)} columns")
        rows.append(Row(path.name, number, {name: cell.strip() for name, cell in zip(header, cells)}))
    return rows


def _lines(path: FilePath, spec: TableSpec) -> list[tuple[int, list[str]]]:
    """``(line number, cells)`` of every line that is neither blank nor a comment."""
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            return [(n, row) for n, row in enumerate(csv.reader(handle), 1)
                    if row and not row[0].lstrip().startswith("#")]
    except UnicodeDecodeError:
        raise TableError(f"{path.name}: not a text file (it is not UTF-8); a {spec.what} is a CSV file "
                         f"whose first row names its columns: {spec.listing}") from None
    except csv.Error as error:
        raise TableError(f"{path.name}: not a CSV file ({error})") from None


def _header(cells: list[str], name: str, spec: TableSpec) -> list[str]:
    """The column names of the header row, units removed, checked against ``spec``."""
    names = [_UNIT.sub("", cell).strip().lower() for cell in cells]
    for number, column in enumerate(names, 1):
        if column in spec.columns:
            continue
        if not _COLUMN_NAME.fullmatch(column):      # not a header: say so without quoting the file
            raise TableError(f"{name}: its first row is not a header of column names (column {number} is "
                             f"no column name); a {spec.what} is a CSV file whose first row names its "
                             f"columns: {spec.listing}")
        raise TableError(f"{name}: unknown column '{column}'{suggest(column, list(spec.columns))}; "
                         f"columns: {spec.listing}")
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise TableError(f"{name}: column '{repeated[0]}' appears twice")
    missing = [c for c in spec.required if c not in names]
    if missing:
        raise TableError(f"{name}: needs a '{missing[0]}' column; the header row lacks the column(s) "
                         f"{', '.join(missing)} (a {spec.what}'s columns are {spec.listing})")
    return names


__all__ = ["MAX_TABLE_BYTES", "MAX_TABLE_ROWS", "Row", "TableError", "TableSpec", "check_csv_file", "finite_number",
           "read_rows"]
