"""Key paths of a case (``cables[0].line_type``) and their lines in the case file."""
from __future__ import annotations

from collections.abc import Mapping, Sequence

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
