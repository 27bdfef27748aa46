"""A griffe extension that renders the docstrings' cross-reference roles as links (mkdocs.yml).

kanat's NumPy docstrings name other objects with the roles numpydoc and Sphinx read --
``:func:`kanat.simulate```, ``:class:`~kanat.io.result_table.ResultTable```, ``:data:`MODELS```,
``:mod:`kanat.dynamics``` -- which mkdocstrings would show as raw text. This extension, loaded by
mkdocstrings' python handler (``extensions: [scripts/griffe_roles.py]``), rewrites each role
into an optional cross-reference of mkdocs-autorefs: a link when the target is documented
on the site, its name in code font otherwise (never a broken link, never a warning). A target
without dots is looked up beside the object first (its class, then its module), as Sphinx
does; ``~`` shows the last part of the name only.
"""
from __future__ import annotations

import html
import re

import griffe

ROLE = re.compile(r":(?:py:)?(?:func|meth|class|mod|data|attr|obj|exc|const):`(~?)([\w.]+)(?:\(\))?`")
"""A role with its target: ``:func:`name```, ``:class:`~a.b.C```, ``:meth:`f()```."""


def _resolve(obj: griffe.Object, target: str) -> str:
    """The full path of ``target`` seen from ``obj``: itself when it names a loaded object,
    else the first of the object's parents holding a member of that name."""
    scope = obj
    while scope is not None:
        candidate = f"{scope.path}.{target}"
        try:
            scope.modules_collection.get_member(candidate)
            return candidate
        except (KeyError, ValueError, AttributeError, griffe.AliasResolutionError, griffe.CyclicAliasError):
            scope = scope.parent
    return target


def rewrite(text: str, obj: griffe.Object) -> str:
    """``text`` with every role replaced by an optional autorefs link (module docstring)."""
    def link(match: re.Match) -> str:
        short, target = match.group(1) == "~", match.group(2)
        shown = target.rsplit(".", 1)[-1] if short else target
        identifier = html.escape(_resolve(obj, target), quote=True)
        return f'<autoref identifier="{identifier}" optional><code>{html.escape(shown)}</code></autoref>'

    return ROLE.sub(link, text)


class Roles(griffe.Extension):
    """Rewrite the roles of every docstring of a loaded package."""

    def on_package(self, *, pkg: griffe.Module, **kwargs) -> None:
        self._visit(pkg, set())

    def _visit(self, obj, seen: set) -> None:
        if obj.path in seen or obj.is_alias:
            return
        seen.add(obj.path)
        if obj.docstring is not None:
            obj.docstring.value = rewrite(obj.docstring.value, obj)
        for member in obj.members.values():
            if not member.is_alias:
                self._visit(member, seen)
