"""A case edited by key paths and validated again (:meth:`kanat.model.Case.replace`).

The case's class comes with the case: this module imports no case module, so the data
(:mod:`kanat.model.case`) uses it without an import circle, and the checks it runs
(:mod:`kanat.model.checks`) sit above the data they check.
"""
from __future__ import annotations

import json
import warnings
from typing import TYPE_CHECKING

from ..errors import CaseError, CaseWarning, KanatError, Problem
from .checks import physical_checks
from .data_problems import number_problems, validate_as
from .paths import set_value

if TYPE_CHECKING:
    from .case import Case


def replaced(case: Case, changes) -> Case:
    """``case`` with every ``key -> value`` of ``changes`` set, validated as a case file would be
    (:meth:`Case.replace`).

    Raises
    ------
    kanat.errors.CaseError
        Every problem, at its key path: a key that cannot be reached, a value that does not
        validate, a sanity check that fails.

    Warns
    -----
    kanat.errors.CaseWarning
        For each sanity warning of the new case.
    """
    model = type(case)
    data = json.loads(case.model_dump_json(by_alias=True, exclude_unset=True))
    problems = []
    for key, value in dict(changes).items():
        try:
            set_value(data, key, value)
        except KanatError as error:
            problems.append(Problem(key, str(error)))
    if problems:
        raise CaseError(problems).located(case.source)
    problems = number_problems(model, data, {}, None)
    new, found = validate_as(model, data)
    problems += found
    if new is not None and not problems:
        problems += physical_checks(new)
    if new is None or any(p.severity == "error" for p in problems):
        raise CaseError(problems).located(case.source)
    for problem in problems:
        warnings.warn(str(problem.located(case.source)), CaseWarning, stacklevel=3)
    new._source = case.source
    return new
