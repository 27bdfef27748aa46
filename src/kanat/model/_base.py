"""Shared building blocks of the case models: base class, quantities, vectors.

Every model forbids unknown keys and is frozen. A field's physical unit is declared
where the field is, with :func:`quantity`, so that error messages and sanity checks
can quote values with their units (:func:`unit_of`).
"""
from __future__ import annotations

import difflib
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field
from pydantic_core import PydanticUndefined

UNIT_KEY = "unit"


class KanatModel(BaseModel):
    """Base of every case model: unknown keys are errors, instances are immutable.

    Validators are built on first use (``defer_build``), not at import: validating a case builds
    :class:`~kanat.model.case.Case`'s, nested models' schemas included, and only the few models
    used on their own build theirs (``kanat validate``: 4 of 39; about 0.008 s less CPU).
    """

    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=True,
                              allow_inf_nan=False, defer_build=True)


def quantity(default: Any = PydanticUndefined, *, unit: str, **constraints: Any) -> Any:
    """A pydantic field that carries its physical unit.

    Parameters
    ----------
    default : object, optional
        Default value; omit for a required field.
    unit : str
        SI unit as written in messages, e.g. ``"m"``, ``"kg/m"``, ``"N"``.
    **constraints
        Passed to :func:`pydantic.Field` (``gt``, ``ge``, ``description``, ...).
    """
    return Field(default, json_schema_extra={UNIT_KEY: unit}, **constraints)


def unit_of(model: type[BaseModel], name: str) -> str | None:
    """Unit declared for field ``name`` (attribute name or alias) of ``model``, if any."""
    for field_name, info in model.model_fields.items():
        if name in (field_name, info.alias):
            extra = info.json_schema_extra
            return extra.get(UNIT_KEY) if isinstance(extra, dict) else None
    return None


def field_keys(model: type[BaseModel]) -> list[str]:
    """Keys a case file may use for ``model`` (aliases where defined), in order."""
    return [info.alias or name for name, info in model.model_fields.items()]


def suggest(word: object, options: list[str] | tuple[str, ...]) -> str:
    """`` (did you mean 'x'?)`` for the closest option to ``word``, or ``""``."""
    if not isinstance(word, str) or len(options) > MAX_SUGGEST_OPTIONS:
        return ""
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.6)
    return f" (did you mean '{close[0]}'?)" if close else ""


MAX_SUGGEST_OPTIONS = 200
"""Longest list :func:`suggest` searches (difflib costs ~5 us an option; a case with
thousands of wrong names must not take minutes to report them)."""
MAX_LISTED = 12
"""Most names :func:`listing` writes out."""


def listing(names, empty: str = "none") -> str:
    """``a, b, c`` for the names in a message, at most :data:`MAX_LISTED` of them."""
    names = list(names)
    if len(names) > MAX_LISTED:
        return ", ".join(map(str, names[:MAX_LISTED])) + f", ... ({len(names)} in all)"
    return ", ".join(map(str, names)) or empty


def fmt(value: object) -> str:
    """Compact number formatting for messages (``-5.0 -> '-5'``, 6 significant digits)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return f"{value:.6g}" if isinstance(value, float) else str(value)


def _as_vector3(value: Any) -> Any:
    """Accept any 3-sequence of numbers; reject other lengths with a plain message."""
    if isinstance(value, (list, tuple)) and len(value) != 3:
        raise ValueError(f"must be a list of 3 numbers [x, y, z] (got {len(value)} values)")
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__"):
        raise ValueError(f"must be a list of 3 numbers [x, y, z] (got {value!r})")
    return tuple(value)


Vector3 = Annotated[tuple[float, float, float], BeforeValidator(_as_vector3)]
"""Three components ``(x, y, z)`` in the global or vessel frame."""

ZERO3: tuple[float, float, float] = (0.0, 0.0, 0.0)


def _as_vector6(value: Any) -> Any:
    """Accept any 6-sequence of numbers (surge, sway, heave, roll, pitch, yaw)."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__") or len(value) != 6:
        got = f"{len(value)} values" if isinstance(value, (list, tuple)) else repr(value)
        raise ValueError(f"must be a list of 6 numbers, one per degree of freedom "
                         f"(surge, sway, heave, roll, pitch, yaw) (got {got})")
    return tuple(value)


Vector6 = Annotated[tuple[float, float, float, float, float, float], BeforeValidator(_as_vector6)]
"""Six components, one per degree of freedom: surge, sway, heave, roll, pitch, yaw."""


def square_matrix(size: int, names: str):
    """Before-validator: ``size`` numbers (a diagonal) or ``size`` rows of ``size`` -> rows.

    Parameters
    ----------
    size : int
        3 or 6.
    names : str
        What the rows and columns are, for the message (``"x, y, z"``).
    """
    def parse(value: Any) -> Any:
        if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__"):
            raise ValueError(f"must be {size} numbers (a diagonal) or {size} rows of {size} "
                             f"numbers ({names}) (got {value!r})")
        rows = list(value)
        if len(rows) == size and all(not hasattr(r, "__len__") for r in rows):
            return tuple(tuple(rows[i] if i == j else 0.0 for j in range(size))
                         for i in range(size))
        if len(rows) != size or any(isinstance(r, (str, bytes, dict)) or not hasattr(r, "__len__")
                                    or len(r) != size for r in rows):
            raise ValueError(f"must be {size} numbers (a diagonal) or {size} rows of {size} "
                             f"numbers ({names})")
        return tuple(tuple(r) for r in rows)
    return BeforeValidator(parse)


Matrix3 = Annotated[tuple[Vector3, Vector3, Vector3], square_matrix(3, "x, y, z")]
"""A 3x3 matrix, written as 3 numbers (its diagonal) or 3 rows of 3."""

_Row6 = tuple[float, float, float, float, float, float]
Matrix6 = Annotated[tuple[_Row6, _Row6, _Row6, _Row6, _Row6, _Row6],
                    square_matrix(6, "surge, sway, heave, roll, pitch, yaw")]
"""A 6x6 matrix over the degrees of freedom (surge, sway, heave, roll, pitch, yaw),
written as 6 numbers (its diagonal) or 6 rows of 6."""
