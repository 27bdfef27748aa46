"""Checks past the first errors: the problems of the rest of a case whose keys do not all validate.

Pydantic reports every bad key of a case at once, but the checks that need a whole case
(:func:`kanat.model.checks.physical_checks`: the scheme, the network, the sea ...) cannot run
on a case that did not validate, so ``duration: -5`` would hide a bad ``scheme``. Here the
keys in error are set aside -- a key with a default is dropped (the default stands in), a
required number is replaced by a value its own bounds accept -- and the case is validated
again; when it validates, the checks run on it. A stand-in number is no one's value, so the
checks run twice, with two stand-ins far apart (:data:`STAND_INS`), and only the problems
found both times, word for word, are reported: a check that reads a stand-in (a strain from a
stand-in diameter, an output size from a stand-in duration) says something else each time
and is left out. Problems at a key set aside are left out too (already reported). When a key
in error can be set aside neither way (a required key that is not a bounded number, a missing
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
from ..model.data_problems import data_path, field_at

UNSET = object()
"""No value can stand in for a key."""
STAND_INS = (1.0, 1000.0)
"""The two values a required number in error is replaced by, when its bounds allow them."""


def _stand_in(field, k: int) -> Any:
    """Stand-in ``k`` (0 or 1) of a number field: :data:`STAND_INS` ``[k]`` when the field's own
    bounds (``gt``, ``ge``, ``lt``, ``le``) take it, else a point of its range that differs with
    ``k``; :data:`UNSET` for a field that is not a number."""
    if field.annotation not in (float, int):
        return UNSET
    low, high = -float("inf"), float("inf")
    for bound in field.metadata:
        if isinstance(bound, (Gt, Ge)):
            low = float(bound.gt if isinstance(bound, Gt) else bound.ge)
        if isinstance(bound, (Lt, Le)):
            high = float(bound.lt if isinstance(bound, Lt) else bound.le)
    value = STAND_INS[k]
    if not low < value < high:
        finite = abs(low) < float("inf"), abs(high) < float("inf")
        value = (low + (0.25, 0.75)[k] * (high - low) if all(finite)
                 else low + STAND_INS[k] if finite[0] else high - STAND_INS[k])
    value = field.annotation(value)
    return value if low < value < high else UNSET


def _set_aside(data: dict, err: dict, stand_in: int) -> tuple | None:
    """Drop the key of one error in ``data`` or put its stand-in number ``stand_in`` (0 or 1)
    there (in place); its path, or None when it cannot."""
    loc = tuple(err["loc"])
    path = data_path(loc, data)
    owner, key, _, _ = field_at(Case, loc)
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
    value = _stand_in(field, stand_in)
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
    found = [_checks_with(data, errors, k, file, lines, max_output_bytes) for k in range(len(STAND_INS))]
    if any(f is None for f in found):
        return []
    return [p for p in found[0] if p in found[1]]


def _checks_with(data: dict, errors: list, stand_in: int, file, lines, max_output_bytes) -> list[Problem] | None:
    """The checks' problems of ``data`` with its keys in error set aside (stand-in number
    ``stand_in`` for a required number), less those at a key set aside; None when they cannot
    be set aside."""
    repaired, aside = copy.deepcopy(data), []
    for err in errors:
        path = _set_aside(repaired, err, stand_in)
        if path is None:
            return None
        aside.append(key_path(path))
    try:
        case = Case.model_validate(repaired, context={})
    except ValidationError:
        return None
    return [p for p in physical_checks(case, file, lines, max_output_bytes)
            if not any(p.key == a or p.key.startswith((a + ".", a + "[")) for a in aside)]
