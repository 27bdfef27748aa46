"""The values a study gives a varied key: lists, ranges and seeded random draws.

Syntax (the same text works on the command line, ``--vary KEY=VALUES``, and from Python,
where a list, tuple or NumPy array may also be passed as it is):

=========================  ==============================================================
``4,6,8``                  a list (YAML scalars: numbers, ``true``, names; ``[4, 6, 8]``
                           with brackets works too)
``4:8:2``                  a range ``start:stop:step``, the stop **included** when it
                           falls on the grid (within 1e-9 of a step): ``4, 6, 8``
``linspace(4, 8, 5)``      ``n`` evenly spaced values from ``a`` to ``b`` inclusive
``uniform(4, 8, 5, 1)``    ``n`` random draws from the uniform distribution on ``[a, b)``
                           with the seed ``seed`` (NumPy ``default_rng(seed)``): the same
                           seed gives the same values on every machine
``normal(6, 0.5, 5, 1)``   ``n`` draws from ``N(mean, std)``, seeded likewise
=========================  ==============================================================

A single value (``6``) is a list of one. Random draws are returned in the order drawn.
"""
from __future__ import annotations

import math
import re
from collections.abc import Sequence

import numpy as np
import yaml

from kanat.errors import KanatError

GRID_TOLERANCE = 1e-9
"""Fraction of a step within which a range's stop counts as on the grid (and is included)."""

MAX_VALUES = 100_000
"""Largest number of values one key may take (a guard against ``0:1e9:1`` typos)."""

_CALL = re.compile(r"^\s*(linspace|uniform|normal)\s*\((.*)\)\s*$")


def _number(text: str, where: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise KanatError(f"{where}: '{text.strip()}' is not a number") from None


def _arguments(name: str, text: str, where: str) -> list[float]:
    args = [_number(a, where) for a in text.split(",")] if text.strip() else []
    if len(args) != 4 - (name == "linspace"):
        usage = {"linspace": "linspace(a, b, n)", "uniform": "uniform(a, b, n, seed)",
                 "normal": "normal(mean, std, n, seed)"}[name]
        raise KanatError(f"{where}: {name} takes {usage}, got {len(args)} argument(s)")
    count = args[2]
    if count != int(count) or not 1 <= count <= MAX_VALUES:
        raise KanatError(f"{where}: n must be a whole number from 1 to {MAX_VALUES}, got {count:g}")
    if name != "linspace" and args[3] != int(args[3]):
        raise KanatError(f"{where}: the seed must be a whole number, got {args[3]:g}")
    return args


def _call(name: str, text: str, where: str) -> list:
    args = _arguments(name, text, where)
    n = int(args[2])
    if name == "linspace":
        return np.linspace(args[0], args[1], n).tolist()
    rng = np.random.default_rng(int(args[3]))
    if name == "uniform":
        if not args[1] > args[0]:
            raise KanatError(f"{where}: uniform(a, b, n, seed) needs b > a, got a = {args[0]:g}, b = {args[1]:g}")
        return rng.uniform(args[0], args[1], n).tolist()
    if args[1] < 0:
        raise KanatError(f"{where}: normal(mean, std, n, seed) needs std >= 0, got {args[1]:g}")
    return rng.normal(args[0], args[1], n).tolist()


def _range(text: str, where: str) -> list[float]:
    parts = text.split(":")
    if len(parts) != 3:
        raise KanatError(f"{where}: a range is start:stop:step (three numbers), got '{text}'")
    start, stop, step = (_number(p, where) for p in parts)
    if step == 0 or (stop - start) * step < 0:
        raise KanatError(f"{where}: step {step:g} never goes from {start:g} to {stop:g}")
    count = math.floor((stop - start) / step + GRID_TOLERANCE) + 1
    if count > MAX_VALUES:
        raise KanatError(f"{where}: {count} values; at most {MAX_VALUES} per key")
    values = start + step * np.arange(count)
    if all(re.fullmatch(r"\s*[-+]?\d+\s*", p) for p in parts):
        return [int(v) for v in values]              # 1:5:1 gives integers, 1:5:0.5 floats
    return [float(f"{v:.12g}") for v in values]     # 0.1 * 3 is 0.3, not 0.30000000000000004


def parse_values(spec, key: str = "") -> list:
    """The list of values a study gives one key.

    Parameters
    ----------
    spec : str, sequence, numpy.ndarray or scalar
        Text in the syntax of the module docstring, or the values themselves.
    key : str
        The key path, used in error messages.

    Returns
    -------
    list
        Plain Python values (floats, ints, strings, booleans), at least one.

    Raises
    ------
    KanatError
        Naming the key and what is wrong with its values.
    """
    where = f"--vary {key}" if key else "values"
    if isinstance(spec, np.ndarray):
        spec = spec.tolist()
    if isinstance(spec, Sequence) and not isinstance(spec, str):
        values = [v.item() if isinstance(v, np.generic) else v for v in spec]
    elif isinstance(spec, str):
        values = _parse_text(spec.strip(), where)
    else:
        values = [spec.item() if isinstance(spec, np.generic) else spec]
    if not values:
        raise KanatError(f"{where}: no values given")
    return values


def _parse_text(text: str, where: str) -> list:
    if not text:
        raise KanatError(f"{where}: no values given; write a list (4,6,8), a range (4:8:2), "
                         "linspace(a,b,n), uniform(a,b,n,seed) or normal(mean,std,n,seed)")
    call = _CALL.match(text)
    if call:
        return _call(call.group(1), call.group(2), where)
    if ":" in text and not text.startswith("["):
        return _range(text, where)
    flow = text if text.startswith("[") else f"[{text}]"
    from kanat.io.yaml_loader import LineLoader

    try:
        values = yaml.load(flow, Loader=LineLoader)  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as error:
        raise KanatError(f"{where}: cannot read '{text}' as a list of values ({error.problem})") from None
    if not isinstance(values, list):
        raise KanatError(f"{where}: '{text}' is not a list of values")
    return values


def format_value(value) -> str:
    """Short text of a value for file names and labels (``%g`` for numbers)."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)
