"""The text of a case file as data with lines, whatever its format.

:func:`read_document` is what :mod:`kanat.io.case_file` validates: a YAML case (with the
tables it names read next to it, :mod:`kanat.io.tables`), or a MoorDyn input file mapped
to case data (:mod:`kanat.io.moordyn`). A text that is neither gets one sentence saying
so, never its own content quoted back.
"""
from __future__ import annotations

import re
from pathlib import Path as FilePath

from ..errors import Problem
from ..model import Case
from .moordyn_text import looks_like_moordyn
from .sea_states import resolve_sea_states
from .tables import resolve_tables
from .yaml_loader import YamlDocument, load_yaml

_TOP_KEY = re.compile(r"^(?P<key>[A-Za-z_][A-Za-z0-9_]*)\s*:", re.M)
CASE_KEYS = frozenset(info.alias or name for name, info in Case.model_fields.items())
"""Top-level keys of a YAML case."""


def neither_sentence(file: str | None) -> str:
    """The one sentence for a text that is neither a YAML case nor a MoorDyn file."""
    return (f"{FilePath(file).name if file else 'this text'} is neither a YAML case (a mapping "
            "of keys such as name, model and cables) nor a MoorDyn input file (sections "
            "headed like '--- LINE TYPES ---'); kanat reads those two")


def _mentions_case_keys(text: str) -> bool:
    return any(m["key"] in CASE_KEYS for m in _TOP_KEY.finditer(text))


def read_document(text: str, file: str | None = None) -> YamlDocument:
    """Data, key-path lines and problems of a case file's text (module docstring).

    Parameters
    ----------
    text : str
        YAML case or MoorDyn input file.
    file : str or None
        Its path: names problems; relative table files are read next to it.
    """
    if looks_like_moordyn(text):
        from .moordyn import moordyn_document       # the MoorDyn reader, only for MoorDyn files

        return moordyn_document(text, file)
    doc = load_yaml(text, file)
    if doc.refused:  # too large, binary, too deep, billion laughs: its own message says why
        return doc
    broken = doc.problems and doc.data is None
    if (broken or isinstance(doc.data, str)) and not _mentions_case_keys(text):
        return YamlDocument(None, {(): 1}, [Problem("", neither_sentence(file), file, None)])
    if isinstance(doc.data, dict):
        base = FilePath(file).parent if file else FilePath(".")
        doc.problems.extend(resolve_tables(doc.data, base, file, doc.lines))
        doc.problems.extend(resolve_sea_states(doc.data, base, file, doc.lines))
    return doc
