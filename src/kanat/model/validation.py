"""Case data (nested dicts and lists, as YAML gives them) -> :class:`~kanat.model.Case`, with every
problem at its key path and line.

:func:`validate_data` turns pydantic's errors into :class:`~kanat.errors.Problem` records that
name the key path, the line (when the data came with lines), what was given and what would
be valid, with units where the model declares them; :func:`number_problems` catches numbers
written ``yes``/``no`` or quoted (``'100'``). Both are :mod:`kanat.model.data_problems`' for the
class :class:`~kanat.model.Case`. The YAML reading is in :mod:`kanat.io.case_file`;
:meth:`Case.replace` validates its edited data in :mod:`kanat.model.edit`.
"""
from __future__ import annotations

from typing import Any

from ..errors import Problem
from . import data_problems
from .case import Case
from .paths import Path


def validate_data(data: Any, file: str | None = None,
                  lines: dict[Path, int] | None = None) -> tuple[Case | None, list[Problem]]:
    """Validate loaded YAML data against :class:`Case`.

    Returns
    -------
    case : Case or None
        The case, when it validated.
    problems : list of Problem
        Every validation error, at its key path and line.
    """
    return data_problems.validate_as(Case, data, file, lines)


def number_problems(data: Any, lines: dict[Path, int], file: str | None, path: Path = ()) -> list[Problem]:
    """Numbers a case writes as something else where the case wants a number
    (:func:`kanat.model.data_problems.number_problems`)."""
    return data_problems.number_problems(Case, data, lines, file, path)
