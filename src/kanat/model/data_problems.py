"""Loaded case data (nested dicts and lists, as YAML gives them) checked against a model class, with
every problem at its key path and line.

:func:`validate_as` turns pydantic's errors into :class:`~kanat.errors.Problem` records that
name the key path, the line (when the data came with lines), what was given and what would
be valid, with units where the model declares them; :func:`number_problems` catches numbers
written ``yes``/``no`` or quoted (``'100'``). The model class is a parameter: this module knows
no case, so the case's own edit (:meth:`Case.replace`, :mod:`kanat.model.edit`) can use it;
:mod:`kanat.model.validation` binds it to :class:`~kanat.model.Case`.
"""
from __future__ import annotations

import math
import types
from typing import Annotated, Any, Literal, Union, get_args, get_origin

from pydantic import BaseModel, ValidationError

from ..errors import Problem
from ._base import field_keys, fmt, suggest, unit_of
from .paths import Path, key_path, line_of

_COMPARISONS = {"greater_than": ("gt", "greater than"),
                "greater_than_equal": ("ge", "at least"),
                "less_than": ("lt", "less than"),
                "less_than_equal": ("le", "at most")}
_CONTAINERS = {"dict_type": "a mapping of keys", "model_type": "a mapping of keys",
               "model_attributes_type": "a mapping of keys", "list_type": "a list",
               "tuple_type": "a list", "string_type": "text", "bool_type": "true or false",
               "bool_parsing": "true or false", "finite_number": "a finite number"}


# --- locating a pydantic error in the model classes and in the YAML data -------------

def _unwrap(tp: Any) -> Any:
    """Strip ``Annotated`` and ``Optional`` from a type annotation."""
    while True:
        origin = get_origin(tp)
        if origin is Annotated:
            tp = get_args(tp)[0]
        elif origin in (Union, types.UnionType):
            args = [a for a in get_args(tp) if a is not type(None)]
            if len(args) != 1:
                return tp
            tp = args[0]
        else:
            return tp


def _is_model(tp: Any) -> bool:
    return isinstance(tp, type) and issubclass(tp, BaseModel)


def _tags(model: type[BaseModel]) -> set[Any]:
    """Values that select ``model`` in a tagged union (its KEY or single-value literals)."""
    tags = {getattr(model, "KEY", None), model.__name__}
    for info in model.model_fields.values():
        if get_origin(info.annotation) is Literal and len(get_args(info.annotation)) == 1:
            tags.add(get_args(info.annotation)[0])
    return tags


def _step(tp: Any, elem: Any) -> Any:
    """Type reached from ``tp`` by one element of an error location."""
    origin = get_origin(tp)
    if origin is dict:
        return get_args(tp)[1]
    if origin in (list, tuple):
        args = get_args(tp)
        if len(args) == 1 or (len(args) == 2 and args[1] is Ellipsis):
            return args[0]
        return args[elem] if isinstance(elem, int) and 0 <= elem < len(args) else None
    if origin in (Union, types.UnionType):
        members = [_unwrap(a) for a in get_args(tp)]
        return next((m for m in members if _is_model(m) and elem in _tags(m)), None)
    return None


def field_at(root: type[BaseModel], loc: tuple[Any, ...]) -> tuple[type[BaseModel] | None, str | None, Any, Any]:
    """Model class, key and annotation of the last model field along ``loc``.

    Parameters
    ----------
    loc : tuple
        Pydantic error location from the top of ``root`` (the data's model class).

    Returns
    -------
    owner : type or None
        Model whose field (or unknown key) ``loc`` ends in.
    key : str or None
        That field's key.
    annotation : type or None
        The field's annotation (None for an unknown key).
    reached : type or None
        The type at the end of ``loc`` (inside the field's containers).
    """
    tp: Any = root
    owner = key = annotation = None
    for elem in loc:
        tp = _unwrap(tp)
        if _is_model(tp):
            owner, key, annotation = tp, elem, None
            for name, info in tp.model_fields.items():
                if elem in (name, info.alias):
                    annotation = info.annotation
            tp = annotation
        elif tp is not None:
            tp = _step(tp, elem)
    return owner, key, annotation, tp


def data_path(loc: tuple[Any, ...], data: Any) -> Path:
    """YAML key path of an error location: drop union tags that are not written keys."""
    path: list[Any] = []
    node = data
    for i, elem in enumerate(loc):
        if isinstance(node, dict) and elem in node:
            node = node[elem]
        elif isinstance(node, list) and isinstance(elem, int) and 0 <= elem < len(node):
            node = node[elem]
        elif i == len(loc) - 1:
            node = None
        else:
            continue
        path.append(elem)
    return tuple(path)


def _value_at(data: Any, path: Path) -> Any:
    for elem in path:
        data = data[elem]
    return data


# --- pydantic error -> plain English ------------------------------------------------

def _got(value: Any, unit: str | None = None) -> str:
    """``got ...`` for an input value, with its unit for numbers."""
    if isinstance(value, dict):
        return "got a mapping"
    if isinstance(value, list):
        return "got a list"
    if value is None:
        return "got nothing (null)"
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"got {fmt(value)}" + (f" {unit}" if unit and unit != "-" else "")
    return f"got {value!r}"


def _options(annotation: Any, ctx: dict[str, Any]) -> list[str]:
    """Valid values of a literal field, from its annotation or the error context."""
    annotation = _unwrap(annotation)
    if get_origin(annotation) is Literal:
        return [str(a) for a in get_args(annotation)]
    return [t.strip(" '") for t in str(ctx.get("expected", "")).replace(" or ", ", ").split(",")]


def _union_tags(annotation: Any) -> list[str]:
    """Names that select the members of a tagged union annotation."""
    union = _unwrap(annotation)
    members = [_unwrap(a) for a in get_args(union)] if get_origin(union) in (
        Union, types.UnionType) else []
    return [str(t) for m in members if _is_model(m)
            for t in sorted(_tags(m) - {m.__name__, None, ""}, key=str)]


def _tag_message(err: dict[str, Any], annotation: Any) -> str:
    ctx = err.get("ctx", {})
    tags = _union_tags(annotation)
    field_tag = str(ctx.get("discriminator", "")).startswith("'")
    what = f"{ctx.get('discriminator', '').strip(chr(39))}" if field_tag else "track segment"
    value = err.get("input")
    if err["type"] == "union_tag_not_found":
        if field_tag:
            return f"missing required key '{what}'; one of: {', '.join(tags)}"
        got = (f"got a mapping with keys {', '.join(map(str, value))}; put each segment in its "
               "own list item" if isinstance(value, dict) else _got(value))
        return ("each track segment is a one-key mapping such as "
                f"{{straight: {{speed: 2.0, duration: 60}}}}, one of: {', '.join(tags)} ({got})")
    tag = ctx.get("tag")
    return (f"'{tag}' is not a valid {what}; valid: {', '.join(tags)}{suggest(tag, tags)}")


def _message(err: dict[str, Any], owner: Any, key: Any, annotation: Any) -> str:
    """Plain-English text of one pydantic error."""
    kind, value, ctx = err["type"], err.get("input"), err.get("ctx", {})
    unit = unit_of(owner, key) if owner is not None and isinstance(key, str) else None
    if kind == "missing":
        text = f"missing required key '{key}'" + (f" [{unit}]" if unit and unit != "-" else "")
        if get_origin(_unwrap(annotation)) is Literal:
            text += f"; one of: {', '.join(_options(annotation, ctx))}"
        return text
    if kind == "extra_forbidden":
        valid = field_keys(owner) if owner is not None else []
        close = suggest(key, valid)
        hint = f"; did you mean '{close.split(chr(39))[1]}'?" if close else ";"
        return f"unknown key '{key}'{hint} valid keys: {', '.join(valid)}"
    if kind in _COMPARISONS:
        bound_key, words = _COMPARISONS[kind]
        return f"must be {words} {fmt(ctx.get(bound_key))} ({_got(value, unit)})"
    if kind.startswith(("float_", "int_")) or kind in ("int_from_float",):
        whole = kind.startswith("int")
        return f"must be a {'whole ' if whole else ''}number ({_got(value, unit)})"
    if kind in _CONTAINERS:
        return f"must be {_CONTAINERS[kind]} ({_got(value, unit)})"
    if kind == "literal_error":
        options = _options(annotation, ctx)
        return f"{value!r} is not one of: {', '.join(options)}{suggest(str(value), options)}"
    if kind in ("union_tag_invalid", "union_tag_not_found"):
        return _tag_message(err, annotation)
    if kind in ("value_error", "assertion_error") and "error" in ctx:
        return str(ctx["error"])
    if kind in ("too_short", "too_long"):
        return f"{err['msg'][0].lower()}{err['msg'][1:]}"
    return err["msg"]


def _problem_for(root: type[BaseModel], err: dict[str, Any], data: Any, lines: dict[Path, int],
                 file: str | None) -> Problem:
    """One pydantic error as a :class:`Problem` at its key path and line."""
    loc = tuple(err["loc"])
    if loc and loc[-1] == "[key]":  # a mapping key of the wrong type (a name written as 1)
        path = data_path(loc[:-1], data)
        return Problem(key_path(path), f"a name must be text ({_got(err.get('input'))}); "
                       "quote it", file, line_of(lines, path))
    owner, key, annotation, reached = field_at(root, loc)
    path = data_path(loc, data)
    if err["type"].startswith("union_tag"):
        annotation = reached
    message = _message(err, owner, key, annotation)
    line_path = path
    if path and path[0] not in data and "model" in data:
        line_path = ("model",)  # a section the model needs is absent: point at the model
    elif err["type"] == "missing":
        path = path[:-1]
        line_path = path
    elif err["type"].startswith("union_tag"):
        node = _value_at(data, path)
        discriminator = str(err.get("ctx", {}).get("discriminator", "")).strip("'")
        if isinstance(node, dict) and discriminator in node:
            path = path + (discriminator,)
        elif isinstance(node, dict) and len(node) == 1:
            path = path + (next(iter(node)),)
        line_path = path
    return Problem(key_path(path), message, file, line_of(lines, line_path))


def validate_as(root: type[BaseModel], data: Any, file: str | None = None,
                lines: dict[Path, int] | None = None) -> tuple[BaseModel | None, list[Problem]]:
    """Validate loaded YAML data against the model class ``root`` (:class:`~kanat.model.Case`).

    Returns
    -------
    value : root or None
        The validated data, when it validated.
    problems : list of Problem
        Every validation error, at its key path and line.
    """
    if not isinstance(data, dict):
        what = "an empty file" if data is None else _got(data)[4:]
        return None, [Problem("", f"a case must be a mapping of keys (name, model, "
                              f"environment, ...); got {what}", file, 1)]
    try:
        return root.model_validate(data, context={}), []
    except ValidationError as exc:
        errors = exc.errors()
    misspelt = _misspelt(root, errors)
    return None, [_problem_for(root, err, data, lines or {}, file) for err in errors
                  if not (err["type"] == "missing" and tuple(err["loc"]) in misspelt)]


def _misspelt(root: type[BaseModel], errors: list[dict[str, Any]]) -> set[tuple[Any, ...]]:
    """Locations of missing keys that an unknown key next to them probably misspells.

    Reporting ``unknown key 'diamter'; did you mean 'diameter'?`` is enough; the
    consequent ``missing required key 'diameter'`` would be the same mistake twice.
    """
    found = set()
    for err in errors:
        if err["type"] == "extra_forbidden":
            loc = tuple(err["loc"])
            owner, key, _, _ = field_at(root, loc)
            close = suggest(key, field_keys(owner)) if owner is not None else ""
            if close:
                found.add(loc[:-1] + (close.split("'")[1],))
    return found


# --- numbers written as true/false or as quoted text ----------------------------------

def _is_number_type(tp: Any) -> bool:
    tp = _unwrap(tp)
    if get_origin(tp) in (Union, types.UnionType):   # float | Law: a number is one choice
        members = [_unwrap(a) for a in get_args(tp)]
        return any(_is_number_type(m) for m in members) and str not in members
    return isinstance(tp, type) and issubclass(tp, (int, float)) and tp is not bool


def _reads_as_number(text: str) -> bool:
    """True for text that reads as a finite number: ``'100'``, ``' 1e3'``, ``'-0.5'`` (``'nan'``
    and ``'inf'`` are left to the schema, which asks for a finite number)."""
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def number_problems(root: type[BaseModel], data: Any, lines: dict[Path, int], file: str | None,
                    path: Path = ()) -> list[Problem]:
    """Numbers a case writes as something else where the case wants a number.

    ``diameter: yes``: YAML reads yes/no/on/off/true/false as booleans, which pydantic
    would take as the numbers 1 and 0. ``length: '100'``: a quoted number is text, which
    pydantic would read as the number. Both are errors at the key (text that is no number
    at all is left to the schema, which says what it wanted).
    """
    if isinstance(data, (bool, str)):
        if not path or not _is_number_type(field_at(root, path)[3]):
            return []
        if isinstance(data, bool):
            written = "true (or yes/on)" if data else "false (or no/off)"
            message = f"must be a number, not {written}"
        elif _reads_as_number(data):
            message = (f"must be a number, not the text {data!r}: write it without quotes "
                       f"({data.strip()})")
        else:
            return []
        return [Problem(key_path(path), message, file, line_of(lines, path))]
    items = (data.items() if isinstance(data, dict)
             else enumerate(data) if isinstance(data, list) else ())
    found: list[Problem] = []
    for key, value in items:
        found += number_problems(root, value, lines, file, path + (key,))
    return found
