"""What the checks of a case (:mod:`kanat.model.checks`) record, and how they write numbers."""
from __future__ import annotations

from collections.abc import Mapping

from ..errors import Problem
from .paths import Path, key_path, line_of


class Findings:
    """Collects problems with their key paths and lines."""

    def __init__(self, file: str | None, lines: Mapping[Path, int] | None,
                 max_output_bytes: float | str | None = None):
        self.file = file
        self.lines = lines
        self.max_output_bytes = max_output_bytes
        self.problems: list[Problem] = []

    def add(self, path: Path, message: str, severity: str) -> None:
        """Record one problem at ``path``."""
        self.problems.append(Problem(key_path(path), message, self.file,
                                     line_of(self.lines, path), severity))

    def error(self, path: Path, message: str) -> None:
        """Record an error at ``path``."""
        self.add(path, message, "error")

    def warning(self, path: Path, message: str) -> None:
        """Record a warning at ``path``."""
        self.add(path, message, "warning")


def kn(force: float) -> str:
    """A force [N] in kN, to 4 significant digits."""
    return f"{force / 1e3:.4g} kN"


def byte_size(n_bytes: float) -> str:
    """A size in bytes in the largest binary unit it fills (``2.5 GiB``)."""
    for unit, scale in (("TiB", 1024**4), ("GiB", 1024**3), ("MiB", 1024**2), ("kiB", 1024)):
        if n_bytes >= scale:
            return f"{n_bytes / scale:.3g} {unit}"
    return f"{n_bytes:.0f} bytes"
