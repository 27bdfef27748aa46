"""Checks past the first errors: the problems of the rest of a case whose keys do not all validate.

Pydantic reports every bad key of a case at once, but the checks that need a whole case
(:func:`kanat.model.checks.physical_checks`: the scheme, the network, the sea ...) cannot run
on a case that did not validate, so ``duration: -5`` would hide a bad ``scheme``. Here the
keys in error are set aside -- a key with a default is dropped (the default stands in), a
required number is replaced by a value its own bounds accept -- and the case is validated
again; when it validates, the checks run on it and report every problem that is not at a key
set aside (those are already reported, and the stand-in values are no one's). When a key in
error can be set aside neither way (a required key that is not a bounded number, a missing
section), the whole-case checks do not run, as before.
"""
from __future__ import annotations

import copy
from typing import Any

from annotated_types import Ge, Gt, Le, Lt
from pydantic import ValidationError

from ..errors import Problem
from ..model import Case
from ..model.checks import physical_checks
from ..model.paths import key_path
from ..model.validation import data_path, field_at

UNSET = object()
"""No value can stand in for a key."""
STAND_IN = 1.0
"""A required number in error is replaced by this when its bounds allow it, else by a bound."""


def _stand_in(field) -> Any:
    """A number the field's own bounds accept (``gt``, ``ge``, ``lt``, ``le``), or :data:`UNSET`."""
    low, high, value = -float("inf"), float("inf"), STAND_IN
    for bound in field.metadata:
        if isinstance(bound, (Gt, Ge)):
            low = float(bound.gt if isinstance(bound, Gt) else bound.ge)
        if isinstance(bound, (Lt, Le)):
            high = float(bound.lt if isinstance(bound, Lt) else bound.le)
    if field.annotation not in (float, int):
        return UNSET
    if not low < value < high:
        value = low + 1.0 if high == float("inf") else (high - 1.0 if low == -float("inf") else 0.5 * (low + high))
    return field.annotation(value) if low < value < high or value in (low, high) else UNSET


def _set_aside(data: dict, err: dict) -> tuple | None:
    """Drop or replace the key of one error in ``data`` (in place); its path, or None when it cannot."""
    loc = tuple(err["loc"])
    path = data_path(loc, data)
    owner, key, _, _ = field_at(loc)
    if err["type"] == "missing" or path != loc or not loc or loc[-1] != key:
        return None
    parent = data
    for elem in loc[:-1]:
        parent = parent[elem]
    if not isinstance(parent, dict):
        return None
    field = owner.model_fields.get(key) if owner is not None else None
    if field is None or not field.is_required():
        parent.pop(key, None)                 # an unknown key, or one whose default stands in
        return path
    value = _stand_in(field)
    if value is UNSET:
        return None
    parent[key] = value
    return path


def checks_past_errors(data: Any, file: str | None, lines, max_output_bytes=None) -> list[Problem]:
    """The whole-case checks' problems of ``data`` once its keys in error are set aside (module
    docstring); empty when they cannot be set aside or the rest does not validate.

    Parameters
    ----------
    data : dict
        The case as read (YAML mapping), which failed validation.
    file, lines, max_output_bytes
        As :func:`kanat.model.checks.physical_checks`.
    """
    if not isinstance(data, dict):
        return []
    try:
        Case.model_validate(data, context={})
        return []
    except ValidationError as exc:
        errors = exc.errors()
    repaired, aside = copy.deepcopy(data), []
    for err in errors:
        path = _set_aside(repaired, err)
        if path is None:
            return []
        aside.append(key_path(path))
    try:
        case = Case.model_validate(repaired, context={})
    except ValidationError:
        return []
    return [p for p in physical_checks(case, file, lines, max_output_bytes)
            if not any(p.key == a or p.key.startswith((a + ".", a + "[")) for a in aside)]
