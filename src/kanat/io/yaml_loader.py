"""Safe YAML loading that remembers where every key was written, with bounded work.

:func:`load_yaml` returns the data together with a table from key paths
(``("cables", 0, "line_type")``) to 1-based line numbers, so that any validation
error can be reported at its line. Only the safe YAML subset is constructed.
Floats in exponent notation without a dot or an exponent sign (``1e7``,
``1.2717e7``), which YAML 1.1 reads as text, are read as numbers.

A case file is untrusted input, so the work is bounded before anything is built
(:mod:`kanat.model.limits`): the text's size, control characters (a NUL byte means a
binary file), then, on the parser's event stream, the nesting depth, the number of
alias uses and the number of values after expanding aliases (a "billion laughs" file
is refused from its few hundred bytes, never expanded). Values that the YAML
constructors cannot build (a 5000-digit integer, a 13th month) are reported at their
line. :func:`load_yaml` never raises for the content of the text.

Why not ruamel.yaml (its round-trip loader keeps line numbers too): the work has to be
bounded on the event stream, before a node graph is composed or aliased data is walked,
which neither library's loaders do; the line table here is by key path, the form every
validation message uses, not positions hung on ruamel's own container types; PyYAML's
safe loader, already a dependency, does the parsing and constructing; and ruamel's YAML
1.2 default reads some YAML 1.1 values differently (``yes``, ``on``, ``010``).
"""
from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass, field
from typing import Any

import yaml
from yaml.events import (AliasEvent, CollectionEndEvent, CollectionStartEvent,
                         ScalarEvent)
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

from ..errors import Problem
from ..model import limits
from ..model.paths import Path, key_path

_FLOAT_E = re.compile(r"""^(?:[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+
                          |[-+]?\.[0-9_]+[eE][-+]?[0-9]+)$""", re.X)
_NON_PRINTABLE = re.compile("[^\x09\x0A\x0D\x20-\x7E\x85\xA0-\uD7FF\uE000-\uFFFD"
                            "\U00010000-\U0010FFFF]")
"""Characters YAML does not allow in a document (its ``c-printable`` complement)."""


class _ValueError(yaml.constructor.ConstructorError):
    """A scalar that its YAML type cannot hold (a 5000-digit integer, a 13th month)."""


class _BuildErrors:
    """Mixin: a value that a constructor cannot build is a YAML error at its line."""

    def construct_object(self, node: Node, deep: bool = False) -> Any:
        try:
            return super().construct_object(node, deep)
        except (ValueError, OverflowError) as exc:
            shown = str(node.value) if isinstance(node, ScalarNode) else node.id
            shown = shown if len(shown) <= 40 else f"{shown[:20]}...{shown[-8:]} ({len(shown)} characters)"
            raise _ValueError(
                None, None, f"cannot read the value {shown!r} as {node.tag.rsplit(':', 1)[-1]}: "
                f"{str(exc).split(';')[0]}", node.start_mark) from None


class LineLoader(_BuildErrors, yaml.SafeLoader):
    """:class:`yaml.SafeLoader` that also resolves ``1e7``-style floats."""


LineLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT_E, list("-+0123456789."))

if getattr(yaml, "__with_libyaml__", False):
    class _FastLoader(_BuildErrors, yaml.CSafeLoader):
        """The same with libyaml's parser (about 10 times faster)."""

    _FastLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT_E, list("-+0123456789."))
else:  # pragma: no cover - PyYAML built without libyaml
    _FastLoader = LineLoader


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
        Syntax errors, exceeded limits and duplicate keys (all severity ``error``).
    refused : bool
        True when the text was refused as a whole, before or while parsing: too large,
        a character YAML forbids (a binary file), too deep, too many values or aliases.
        Its problem says why; it is not worth guessing what else the text might be.
    """

    data: Any = None
    lines: dict[Path, int] = field(default_factory=dict)
    problems: list[Problem] = field(default_factory=list)
    refused: bool = False


_MERGE_TAG = "tag:yaml.org,2002:merge"


class _LimitError(yaml.MarkedYAMLError):
    """A limit of :mod:`kanat.model.limits` exceeded while reading the events."""


def _limit(message: str, mark: Any) -> _LimitError:
    return _LimitError(None, None, message, mark)


class _Sizes:
    """Expanded value counts of the open collections and of the anchors (bottom-up)."""

    def __init__(self) -> None:
        self.stack: list[list[Any]] = []       # [values so far, anchor] per open collection
        self.anchors: dict[str, int] = {}      # anchor -> expanded values
        self.aliases = 0

    def add(self, count: int, mark: Any) -> None:
        if self.stack:
            self.stack[-1][0] += count
            if self.stack[-1][0] > limits.MAX_YAML_NODES:
                raise _limit(f"the document holds more than {limits.MAX_YAML_NODES:,} values "
                             "(counting each alias *name as a copy of what it names): refused "
                             "before expanding it", mark)

    def alias(self, anchor: str, mark: Any) -> None:
        self.aliases += 1
        if self.aliases > limits.MAX_YAML_ALIASES:
            raise _limit(f"more than {limits.MAX_YAML_ALIASES:,} aliases (*name)", mark)
        if any(anchor == open_anchor for _, open_anchor in self.stack):
            raise _limit(f"the alias *{anchor} is inside the collection &{anchor} that it names "
                         "(a recursive structure); a case cannot contain itself", mark)
        self.add(self.anchors.get(anchor, 1), mark)   # an undefined alias: the composer says so


def _check_events(text: str) -> None:
    """Raise a YAML error when the text nests too deep or expands to too many values.

    Reads the parser's events only (no node is built), counting for each anchor the
    values it stands for, so that an alias costs what it would expand to.
    """
    loader = _FastLoader(text)
    sizes = _Sizes()
    try:
        while loader.check_event():
            event = loader.get_event()
            if isinstance(event, CollectionStartEvent):
                if len(sizes.stack) >= limits.MAX_YAML_DEPTH:
                    raise _limit(f"nested more than {limits.MAX_YAML_DEPTH} levels deep; a case "
                                 "needs at most 6 (line_types.NAME.elastic_law.table[i][j])",
                                 event.start_mark)
                sizes.stack.append([1, event.anchor])
            elif isinstance(event, CollectionEndEvent):
                count, anchor = sizes.stack.pop()
                if anchor is not None:
                    sizes.anchors[anchor] = count
                sizes.add(count, event.start_mark)
            elif isinstance(event, ScalarEvent):
                if event.anchor is not None:
                    sizes.anchors[event.anchor] = 1
                sizes.add(1, event.start_mark)
            elif isinstance(event, AliasEvent):
                sizes.alias(event.anchor, event.start_mark)
    finally:
        loader.dispose()


def _scalar_key(loader: Any, node: Node) -> Any:
    """The constructed value of a key node (a complex key becomes a placeholder text)."""
    if isinstance(node, ScalarNode):
        return loader.construct_object(node)
    return f"<{node.id} key at line {node.start_mark.line + 1}>"


def _record_lines(loader: Any, node: Node, path: Path, doc: YamlDocument,
                  file: str | None) -> None:
    """Walk the node tree, filling ``doc.lines`` and reporting duplicate keys.

    Runs before construction, so merge keys (``<<``) are still as written. The tree is
    at most :data:`~kanat.model.limits.MAX_YAML_DEPTH` deep (:func:`_check_events`).
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
    if isinstance(exc, (_LimitError, _ValueError)):
        return Problem("", str(exc.problem), file, line)
    source = text.splitlines()[line - 1] if line and line <= len(text.splitlines()) else ""
    what = getattr(exc, "problem", None) or str(exc)
    if "maximum nesting depth" in what:  # libyaml's own guard, reached before ours
        return Problem("", f"nested more than {limits.MAX_YAML_DEPTH} levels deep; a case needs "
                       "at most 6 (line_types.NAME.elastic_law.table[i][j])", file, line)
    context = getattr(exc, "context", None)
    context_mark = getattr(exc, "context_mark", None)
    if what == "second occurrence" and context_mark is not None:  # a duplicate anchor
        return Problem("", f"the anchor (&name) at line {line} is already defined at line "
                       f"{context_mark.line + 1}; give each anchor its own name", file, line)
    if "undefined alias" in what:
        return Problem("", "YAML syntax error: found an alias (*name) whose anchor (&name) is "
                       "not defined before it", file, line)
    if context and context_mark is not None and context_mark.line + 1 != line:
        context += f" that starts at line {context_mark.line + 1}"
    message = f"YAML syntax error: {what}" + (f" ({context})" if context else "")
    if "mapping values are not allowed" in str(what):
        message += ("; a value containing ': ' needs quotes or a {...} mapping, e.g. "
                    "anchor:[0, 0, -100] (no space) or {anchor: [0, 0, -100]}")
    elif "\t" in source:
        message += "; YAML indents with spaces, never tabs"
    elif "anchor:" in source.replace(" ", "") and "{" in source:
        message += ("; inside {...} write an anchor end as {anchor: [x, y, z]} or quote it: "
                    "'anchor:[x, y, z]'")
    return Problem("", message, file, line)


def _character_name(char: str) -> str:
    if char == "\x00":
        return "a NUL byte"
    name = unicodedata.name(char, "")
    return f"the character U+{ord(char):04X}" + (f" ({name.lower()})" if name else "")


def text_problem(text: str, file: str | None = None) -> Problem | None:
    """The first reason why ``text`` cannot be a case file at all, or None.

    Too many bytes (:data:`~kanat.model.limits.MAX_DOCUMENT_BYTES`), or a character that
    YAML does not allow (a NUL byte: a binary file), with its line and column.
    """
    size = len(text.encode("utf-8", "surrogatepass"))
    if size > limits.MAX_DOCUMENT_BYTES:
        return Problem("", f"the text is {size:,} bytes, more than the limit of "
                       f"{limits.MAX_DOCUMENT_BYTES:,} for a case file (cases are a few kB; put "
                       "long tables in their own files)", file, None)
    bad = _NON_PRINTABLE.search(text)
    if bad is None:
        return None
    line = text.count("\n", 0, bad.start()) + 1
    column = bad.start() - (text.rfind("\n", 0, bad.start()) + 1) + 1
    return Problem("", f"{_character_name(bad.group())} at line {line}, column {column}: a "
                   "case file is plain UTF-8 text (was a binary file given?)", file, line)


def load_yaml(text: str, file: str | None = None) -> YamlDocument:
    """Parse one YAML document with line numbers, within the limits of the module docstring.

    Parameters
    ----------
    text : str
        YAML text.
    file : str or None
        File name used in problems.

    Returns
    -------
    YamlDocument
        Data, key-path lines and problems (syntax errors, exceeded limits, duplicate
        keys). Never raises for the content of ``text``.
    """
    doc = YamlDocument(lines={(): 1})
    problem = text_problem(text, file)
    if problem is not None:
        doc.problems.append(problem)
        doc.refused = True
        return doc
    loader = None
    try:
        _check_events(text)
        loader = _FastLoader(text)
        node = loader.get_single_node()
        if node is not None:
            _record_lines(loader, node, (), doc, file)
            doc.data = loader.construct_document(node)
    except yaml.YAMLError as exc:
        doc.data = None
        doc.problems.append(_syntax_problem(exc, text, file))
        doc.refused = isinstance(exc, _LimitError) or "maximum nesting depth" in str(exc)
    finally:
        if loader is not None:
            loader.dispose()
    return doc
