"""Read case files: YAML -> :class:`kanat.model.Case`, with every problem at its line.

Public functions
----------------
load_case(path)
    Read and validate a case file; raise :class:`~kanat.errors.CaseError` with all
    problems, or warn (:class:`CaseWarning`) and return the case.
parse_case(text, file=None)
    The same for YAML text.
check_case(path), check_text(text, file=None)
    Every error and warning as a list of :class:`~kanat.errors.Problem`; never raise,
    not even for a file that cannot be read (a missing file, a directory, a binary file
    are problems too).

Each problem names the file, the line, the key path (``cables[0].line_type``) and what
would be valid, with units where the model declares them.

Every function takes ``max_output_bytes``: the largest estimated result of a dynamic
run (bytes, or a string such as ``"8G"``); by default the environment variable
``KANAT_MAX_OUTPUT_BYTES``, else 2 GiB (:mod:`kanat.model.limits`, where every limit on
a case's size and numbers is named with its reason).
"""
from __future__ import annotations

import warnings
from os import PathLike

from ..errors import CaseError, CaseWarning, Problem
from ..model import Case
from ..model.checks import physical_checks
from ..model.support import unsupported
from ..model.validation import number_problems, validate_data
from .case_partial import checks_past_errors
from .case_source import read_document
from .case_read import read_case_text

# --- public entry points ----------------------------------------------------------

def _check(text: str, file: str | None, max_output_bytes: float | str | None = None,
           solver: str | None = None) -> tuple[Case | None, list[Problem]]:
    doc = read_document(text, file)  # YAML (its tables read), or a MoorDyn file mapped
    problems = list(doc.problems)
    if doc.data is None and problems:
        return None, problems
    problems += number_problems(doc.data, doc.lines, file)
    case, found = validate_data(doc.data, file, doc.lines)
    problems += found
    if case is not None:
        problems += _for_solver(physical_checks(case, file, doc.lines, max_output_bytes), case, solver,
                                file, doc.lines)
    elif not any(p.severity == "error" for p in problems if p not in found):
        problems += checks_past_errors(doc.data, file, doc.lines, max_output_bytes)  # every problem at once
    return case, sorted(problems, key=lambda p: p.line or 0)


def _for_solver(problems: list[Problem], case: Case, solver: str | None, file, lines) -> list[Problem]:
    """The support problems of ``solver`` instead of the case's own model's (``kanat statics``
    of a dynamic case is solved by statics, whatever ``model`` says)."""
    if solver is None or solver == case.model:
        return problems
    own = unsupported(case, case.model, file, lines)
    return [p for p in problems if p not in own] + unsupported(case, solver, file, lines)


def check_text(text: str, file: str | None = None, *,
               max_output_bytes: float | str | None = None) -> list[Problem]:
    """Every error and warning of a case given as YAML text (never raises for content)."""
    return _check(text, file, max_output_bytes)[1]


def check_case(path: str | PathLike[str], *,
               max_output_bytes: float | str | None = None) -> list[Problem]:
    """Every error and warning of a case file, sorted by line.

    Parameters
    ----------
    path : str or path-like
    max_output_bytes : float, str or None
        Largest estimated result of a dynamic run (module docstring).

    Returns
    -------
    list of Problem
        Problems reading the file (missing, a directory, unreadable, too large, not UTF-8
        text), syntax errors, validation errors and the limit and sanity checks
        (:func:`kanat.model.checks.physical_checks`). Never raises for the file or its
        content.
    """
    text, problems = read_case_text(path)
    if text is None:
        return problems
    return check_text(text, str(path), max_output_bytes=max_output_bytes)


def _accept(case: Case | None, problems: list[Problem], file: str | None = None) -> Case:
    """Raise on errors; otherwise emit the warnings and return the case, which remembers ``file``."""
    if case is None or any(p.severity == "error" for p in problems):
        raise CaseError(problems)
    for problem in problems:
        warnings.warn(str(problem), CaseWarning, stacklevel=3)
    case._source = file
    return case


def parse_case(text: str, file: str | None = None, *,
               max_output_bytes: float | str | None = None, solver: str | None = None) -> Case:
    """Validate a case given as YAML text.

    Parameters
    ----------
    text : str
        The case in YAML.
    file : str or None
        Name used in messages.
    max_output_bytes : float, str or None
        Largest estimated result of a dynamic run (module docstring).
    solver : str or None
        Check what this solver supports instead of the case's ``model`` (``statics`` for
        the steady state of a dynamic case, as ``kanat statics`` does).

    Returns
    -------
    Case

    Raises
    ------
    CaseError
        With every problem found (warnings included) when any is an error.

    Warns
    -----
    CaseWarning
        One per sanity warning, when there is no error.
    """
    return _accept(*_check(text, file, max_output_bytes, solver), file)


def load_case(path: str | PathLike[str], *,
              max_output_bytes: float | str | None = None, solver: str | None = None) -> Case:
    """Read and validate a case file (see :func:`parse_case`); a file that cannot be read
    raises :class:`~kanat.errors.CaseError` too."""
    text, problems = read_case_text(path)
    if text is None:
        raise CaseError(problems)
    return _accept(*_check(text, str(path), max_output_bytes, solver), str(path))


def import_moordyn(path: str | PathLike[str]):
    """Read, map and validate a MoorDyn input file.

    Returns
    -------
    kanat.model.Case

    Raises
    ------
    CaseError
        With every problem, when the file cannot be imported or the case is invalid.
    """
    return load_case(path)
