"""Exceptions and problem reports shared by the whole package.

Problems with input are collected as :class:`Problem` records so that a case file
with several mistakes reports all of them at once (``kanat validate``).
"""
from __future__ import annotations

from dataclasses import dataclass, replace


@dataclass(frozen=True)
class Problem:
    """One finding about a case: an error that stops it, or a warning.

    Attributes
    ----------
    key : str
        Key path in the case, e.g. ``cables[0].line_type``; empty for the whole file.
    message : str
        What is wrong and what would be valid, with numbers and units.
    file : str or None
        Case file path, when the case came from a file.
    line : int or None
        1-based line in ``file`` where ``key`` is written, when known.
    severity : {"error", "warning"}
    """

    key: str
    message: str
    file: str | None = None
    line: int | None = None
    severity: str = "error"

    def __str__(self) -> str:
        where = self.file or "<case>"
        if self.line is not None:
            where += f":{self.line}"
        key = f" {self.key}:" if self.key else ""
        return f"{where}: {self.severity}:{key} {self.message}"

    def located(self, source: str | None) -> Problem:
        """This problem naming ``source`` (the case's file, found after it was read) when it names
        no file of its own."""
        return self if self.file is not None or source is None else replace(self, file=source)


class CaseWarning(UserWarning):
    """A case that can run but probably not as meant (a physical sanity warning)."""


class KanatError(Exception):
    """Base class of every error kanat raises on purpose."""


class CaseError(KanatError, ValueError):
    """A case that cannot be run; carries every problem found."""

    def __init__(self, problems: list[Problem]):
        self.problems = list(problems)
        errors = [p for p in self.problems if p.severity == "error"]
        head = f"{len(errors)} problem(s) in the case:" if len(errors) != 1 else "a problem in the case:"
        super().__init__("\n".join([head, *("  " + str(p) for p in self.problems)]))

    def located(self, source: str | None) -> CaseError:
        """The same problems, those that name no file naming ``source`` (the case's file, found
        after it was read), or this error itself when ``source`` is None."""
        if source is None or all(p.file is not None for p in self.problems):
            return self
        return CaseError([p.located(source) for p in self.problems])


class OutputWriteError(KanatError, OSError):
    """A result or checkpoint that could not be written (a full disk, a quota, an I/O error).

    Raised before anything is half-written where it can be foreseen (the free space is checked
    before each block), so that the file keeps every output up to its last complete block and
    the checkpoint stays the last complete one: a run continues with ``--resume`` once the
    cause is gone.
    """


class SolverError(KanatError, RuntimeError):
    """A solver that did not converge; the message says where and what to try."""
