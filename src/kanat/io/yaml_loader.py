"""Safe YAML loading that remembers where every key was written.

:func:`load_yaml` returns the data together with a table from key paths
(``("cables", 0, "line_type")``) to 1-based line numbers, so that any validation
error can be reported at its line. Only the safe YAML subset is constructed.
Floats in exponent notation without a dot or an exponent sign (``1e7``,
``1.2717e7``), which YAML 1.1 reads as text, are read as numbers.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import yaml
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

from ..errors import Problem
from ..model.paths import Path, key_path

_FLOAT_E = re.compile(r"""^(?:[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+
                          |[-+]?\.[0-9_]+[eE][-+]?[0-9]+)$""", re.X)


class LineLoader(yaml.SafeLoader):
    """:class:`yaml.SafeLoader` that also resolves ``1e7``-style floats."""


LineLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT_E, list("-+0123456789."))


@dataclass
class YamlDocument:
    """A parsed YAML text.

    Attributes
    ----------
    data : object
        The constructed document (None when the text is empty or has a syntax error).
    lines : dict of Path to int
        1-based line of every mapping key and sequence item, by key path; ``()`` is
        the document start.
    problems : list of Problem
        Syntax errors and duplicate keys (both severity ``error``).
    """

    data: Any = None
    lines: dict[Path, int] = field(default_factory=dict)
    problems: list[Problem] = field(default_factory=list)


_MERGE_TAG = "tag:yaml.org,2002:merge"


def _scalar_key(loader: LineLoader, node: Node) -> Any:
    """The constructed value of a key node (a complex key becomes a placeholder text)."""
    if isinstance(node, ScalarNode):
        return loader.construct_object(node)
    return f"<{node.id} key at line {node.start_mark.line + 1}>"


def _record_lines(loader: LineLoader, node: Node, path: Path, doc: YamlDocument,
                  file: str | None) -> None:
    """Walk the node tree, filling ``doc.lines`` and reporting duplicate keys.

    Runs before construction, so merge keys (``<<``) are still as written.
    """
    if isinstance(node, MappingNode):
        for key_node, value_node in node.value:
            if key_node.tag == _MERGE_TAG:
                continue
            key = _scalar_key(loader, key_node)
            child = path + (key,)
            line = key_node.start_mark.line + 1
            if child in doc.lines and doc.lines[child] != line:
                first = doc.lines[child]
                doc.problems.append(Problem(
                    key_path(child), f"duplicate key '{key}' (lines {first} and {line}); "
                    "keep one of them", file, line))
            else:
                doc.lines[child] = line
            _record_lines(loader, value_node, child, doc, file)
    elif isinstance(node, SequenceNode):
        for index, item in enumerate(node.value):
            doc.lines.setdefault(path + (index,), item.start_mark.line + 1)
            _record_lines(loader, item, path + (index,), doc, file)


def _syntax_problem(exc: yaml.YAMLError, text: str, file: str | None) -> Problem:
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    line = mark.line + 1 if mark is not None else None
    source = text.splitlines()[line - 1] if line and line <= len(text.splitlines()) else ""
    what = getattr(exc, "problem", None) or str(exc)
    context = getattr(exc, "context", None)
    context_mark = getattr(exc, "context_mark", None)
    if context and context_mark is not None and context_mark.line + 1 != line:
        context += f" that starts at line {context_mark.line + 1}"
    message = f"YAML syntax error: {what}" + (f" ({context})" if context else "")
    if "mapping values are not allowed" in str(what):
        message += ("; a value containing ': ' needs quotes or a {...} mapping, e.g. "
                    "anchor:[0, 0, -100] (no space) or {anchor: [0, 0, -100]}")
    elif "anchor:" in source.replace(" ", "") and "{" in source:
        message += ("; inside {...} write an anchor end as {anchor: [x, y, z]} or quote it: "
                    "'anchor:[x, y, z]'")
    return Problem("", message, file, line)


def load_yaml(text: str, file: str | None = None) -> YamlDocument:
    """Parse one YAML document with line numbers.

    Parameters
    ----------
    text : str
        YAML text.
    file : str or None
        File name used in problems.

    Returns
    -------
    YamlDocument
        Data, key-path lines and problems (syntax errors, duplicate keys). Never raises
        for the content of ``text``.
    """
    doc = YamlDocument(lines={(): 1})
    loader = LineLoader(text)
    try:
        node = loader.get_single_node()
        if node is not None:
            _record_lines(loader, node, (), doc, file)
            doc.data = loader.construct_document(node)
    except yaml.YAMLError as exc:
        doc.data = None
        doc.problems.append(_syntax_problem(exc, text, file))
    finally:
        loader.dispose()
    return doc
