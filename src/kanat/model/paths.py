"""Key paths of a case (``cables[0].line_type``), their lines in the case file, and setting a key
in case data by its path (:meth:`kanat.model.Case.replace`, ``kanat sweep --vary``).

Key paths are written as in the case file and in kanat's error messages:
``environment.waves.period``, ``line_types.towcable.axial_stiffness``, ``cables[0].length``,
``vessel.track[1].to_speed_kn``. A track segment written as a one-key mapping
(``{speed_step: {to_speed_kn: 10}}``) is entered without naming its key, so
``vessel.track[1].to_speed_kn`` reaches ``to_speed_kn`` there; naming it
(``vessel.track[1].speed_step.to_speed_kn``) works too. The last key of a path may be absent
from the data (it is added, and validation says whether it is a valid key); missing mappings
on the way are added too.
"""
from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

from ..errors import KanatError

Path = tuple[object, ...]
"""Keys and list indices from the top of the case, e.g. ``("cables", 0, "line_type")``."""


def key_path(path: Sequence[object]) -> str:
    """Render a path as written in messages: ``cables[0].line_type``."""
    text = ""
    for part in path:
        if isinstance(part, int) and not isinstance(part, bool):
            text += f"[{part}]"
        else:
            text += f".{part}" if text else str(part)
    return text


def line_of(lines: Mapping[Path, int] | None, path: Sequence[object]) -> int | None:
    """1-based line where ``path`` is written, else that of its nearest written parent."""
    if not lines:
        return None
    path = tuple(path)
    while path:
        if path in lines:
            return lines[path]
        path = path[:-1]
    return lines.get(())


_TOKEN = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def parse_key(key: str) -> tuple:
    """``"vessel.track[1].to_speed_kn"`` -> ``("vessel", "track", 1, "to_speed_kn")``.

    Raises
    ------
    KanatError
        For an empty key or one that does not read back as written.
    """
    path = tuple(int(index) if index else name for name, index in _TOKEN.findall(key.strip()))
    if not path or key_path(path) != key.strip():
        raise KanatError(f"'{key}' is not a key path; write it as in the case file, e.g. "
                         "environment.waves.period or vessel.track[1].to_speed_kn")
    return path


def _child(node, elem, done: tuple, last: bool):
    """The container holding ``elem`` below ``node`` (entering one-key wrappers), creating it if needed."""
    where = key_path(done) or "the case"
    if isinstance(elem, int):
        if not isinstance(node, list):
            raise KanatError(f"{where}: [{elem}] needs a list there, but it is {_kind(node)}")
        if not 0 <= elem < len(node):
            raise KanatError(f"{key_path(done + (elem,))}: {where} has {len(node)} item(s), "
                             f"indices 0 to {len(node) - 1}")
        return node
    if not isinstance(node, dict):
        raise KanatError(f"{where}: '{elem}' needs a mapping there, but it is {_kind(node)}")
    if elem in node:
        return node
    if len(node) == 1:
        (wrapped,) = node.values()
        if isinstance(wrapped, dict) and (elem in wrapped or last):
            return wrapped                              # {speed_step: {to_speed_kn: ...}}
    if not last:
        node[elem] = {}
    return node


def _kind(value) -> str:
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a mapping"
    return f"the value {value!r}"


def set_value(data: dict, key: str, value) -> None:
    """Set ``key`` (a key path) to ``value`` in case data, in place.

    Raises
    ------
    KanatError
        Naming the key path when it cannot be reached in the data.
    """
    path = parse_key(key)
    node = data
    for i, elem in enumerate(path):
        last = i == len(path) - 1
        node = _child(node, elem, path[:i], last)
        if last:
            node[elem] = value
        else:
            node = node[elem]
