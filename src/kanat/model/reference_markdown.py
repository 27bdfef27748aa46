"""The case format's reference in Markdown, from :func:`kanat.model.reference.json_schema`.

:func:`case_format_markdown` writes every key with its type, unit, default, allowed values
and meaning (``docs/reference/case-format.md``), from the schema, so that the page and the
schema cannot disagree; :func:`support_markdown` the table of :mod:`kanat.model.support`.
The result files' names live in :mod:`kanat.io.schema`, a layer above this one:
:func:`results_markdown` takes that table as an argument (``kanat.cli_docs`` joins the two).
"""
from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping

from .reference import _unit, json_schema

_SPECIAL = {
    "CableEnd": "Written in one of these forms: `vessel` (the tow point), `{vessel: [x, y, z]}` (a "
                "fairlead in vessel axes), `free`, `anchor:[x, y, z]` or `{anchor: [x, y, z]}`, the name "
                "of a body or point (or `{body: NAME}`, `{point: NAME}`), or `{body: NAME, offset: [x, y, "
                "z]}` (a fairlead in the body's axes). `s = 0` is at `from`, `s = length` at `to`.",
    "VesselMotion": "Written as the list of harmonics itself (`motion: [{dof: surge, amplitude: 10, "
                    "period: 27}]`) or as `{table: motion.csv}`.",
}
_EDITOR = """\
Editors that read JSON Schema (VS Code with the YAML extension, PyCharm, any editor using
`yaml-language-server`) complete and check case files against the schema that
`kanat schema > kanat-case.schema.json` writes; put this first line in a case file:

```yaml
# yaml-language-server: $schema=kanat-case.schema.json
```
"""


def _slug(name: str) -> str:
    return name.lower()


def _cell(text) -> str:
    return " ".join(str(text).split()).replace("|", "\\|")


def _value(value) -> str:
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "`true`" if value else "`false`"
    return f"`{json.dumps(value, ensure_ascii=False)}`" if not isinstance(value, str) else f"`{value}`"


def _type(node: dict) -> str:
    """What a schema node accepts, in words (links to the sections of referenced models)."""
    if "$ref" in node:
        name = node["$ref"].rsplit("/", 1)[-1]
        return f"[{name}](#{_slug(name)})"
    branches = node.get("anyOf") or node.get("oneOf")
    if branches:
        kinds = [_type(b) for b in branches if b.get("type") != "null"]
        return " or ".join(dict.fromkeys(kinds))
    if "const" in node:
        return _value(node["const"])
    if "enum" in node:
        return "one of " + ", ".join(_value(v) for v in node["enum"])
    kind = node.get("type")
    if kind == "array":
        return _array_type(node)
    if kind == "object":
        extra = node.get("additionalProperties")
        return f"mapping of name to {_type(extra)}" if isinstance(extra, dict) else "mapping"
    return {"number": "number", "integer": "integer", "string": "text", "boolean": "true or false"}.get(kind, "any")


def _array_type(node: dict) -> str:
    fixed = node.get("prefixItems")
    if fixed and all(item.get("type") == "array" for item in fixed):
        return f"{len(fixed)}×{len(fixed)} rows"
    if fixed:
        inner = {_type(item) for item in fixed}
        return f"[{len(fixed)} {'numbers' if inner == {'number'} else 'values'}]"
    if node.get("minItems") is not None and node.get("minItems") == node.get("maxItems"):
        return f"[{node['minItems']} {_type(node.get('items', {}))}s]"
    return f"list of {_type(node.get('items', {}))}"


def _allowed(node: dict) -> str:
    """Bounds of a number (``> 0``, ``≤ 1``), from every non-null branch."""
    marks = (("exclusiveMinimum", ">"), ("minimum", "≥"), ("exclusiveMaximum", "<"), ("maximum", "≤"))
    found = []
    for branch in [node, *node.get("anyOf", [])]:
        found += [f"{sign} {branch[key]:g}" for key, sign in marks if key in branch]
    return ", ".join(dict.fromkeys(found))


def _default(name: str, prop: dict, required: Iterable[str]) -> str:
    if name in required:
        return "**required**"
    if "default" in prop:
        return _value(prop["default"])
    if "$ref" in prop:
        return "its keys' defaults"
    if prop.get("type") in ("array", "object") or any(b.get("type") in ("array", "object") for b in prop.get("anyOf", [])):
        return "empty"
    return "see description"


def _fields_table(node: dict) -> list[str]:
    """One row per key of an object schema: key, type, unit, default, allowed, meaning."""
    rows = ["| key | type | unit | default | allowed | description |", "|---|---|---|---|---|---|"]
    required = node.get("required", [])
    for name, prop in node.get("properties", {}).items():
        unit = _unit(prop)
        text = re.sub(r"^\[[^\]]*\]\s*", "", prop.get("description", "")) if unit else prop.get("description", "")
        rows.append("| " + " | ".join(_cell(c) for c in (
            f"`{name}`", _type(prop), unit.replace("-", "–") if unit == "-" else unit,
            _default(name, prop, required), _allowed(prop), text)) + " |")
    return rows


def _refs(node, path: str):
    """``(model name, key path)`` of every model a schema node refers to."""
    if isinstance(node, list):
        for item in node:
            yield from _refs(item, path)
        return
    if not isinstance(node, dict):
        return
    if "$ref" in node:
        yield node["$ref"].rsplit("/", 1)[-1], path
    for key in ("anyOf", "oneOf"):
        yield from _refs(node.get(key, []), path)
    if isinstance(node.get("items"), dict):
        yield from _refs(node["items"], path + "[]")
    if isinstance(node.get("additionalProperties"), dict):
        yield from _refs(node["additionalProperties"], path + ".NAME")
    for key, prop in node.get("properties", {}).items():
        yield from _refs(prop, f"{path}.{key}" if path else key)


def _sections(schema: dict) -> tuple[list[str], dict[str, list[str]]]:
    """Models in the order a reader meets them from the top, and the key paths of each."""
    defs, order, where = schema["$defs"], [], {}
    queue = list(_refs(schema, ""))
    while queue:
        name, path = queue.pop(0)
        where.setdefault(name, [])
        if path not in where[name]:
            where[name].append(path)
        if name not in order:
            order.append(name)
            queue += list(_refs(defs[name], path))
    return order, where


def _model_section(name: str, node: dict, paths: list[str]) -> list[str]:
    lines = [f"### {name} {{#{_slug(name)}}}", "", "Key path: " + ", ".join(f"`{p}`" for p in paths) + ".", ""]
    if name in _SPECIAL:
        lines += [_SPECIAL[name], ""]
    elif node.get("description"):
        lines += [_cell(node["description"]), ""]
    body = node if name != "CableEnd" else {}
    if not node.get("properties") and node.get("anyOf"):          # written forms
        objects = [b for b in node["anyOf"] if b.get("properties")]
        wrapped = [b for b in objects if len(b["properties"]) == 1
                   and "properties" in next(iter(b["properties"].values()))]
        if wrapped:                                                # {KEY: {fields}}
            key, body = next(iter(wrapped[0]["properties"].items()))
            lines += [f"Written `{{{key}: {{...}}}}` in the list.", ""]
        else:
            body = next((b for b in objects if "kind" not in b["properties"]), {})
    if body.get("properties") and name != "CableEnd":
        lines += _fields_table(body) + [""]
    return lines


def case_format_markdown(schemes: Iterable[str] | None = None) -> str:
    """The case-format reference: every key with its type, unit, default, allowed values and
    meaning, from :func:`json_schema` (so the page and the schema cannot disagree).

    Parameters
    ----------
    schemes : iterable of str, optional
        Scheme names for ``simulation.scheme`` (see :func:`json_schema`).
    """
    schema = json_schema(schemes)
    order, where = _sections(schema)
    lines = ["## Case file (YAML)", "",
             "A case is one YAML mapping. Keys are case-sensitive; an unknown key is an error that "
             "names the key and the closest valid one. Units are SI unless the key says otherwise "
             "(`_deg`, `_kn`). Headings below name the model classes of `kanat.model`.", "",
             _EDITOR, "### Top level {#case}", ""]
    lines += _fields_table(schema) + [""]
    for name in order:
        lines += _model_section(name, schema["$defs"][name], where[name])
    return "\n".join(lines).rstrip() + "\n"


def results_markdown(variables: Mapping, coordinates: Mapping, attributes: Mapping[str, str]) -> str:
    """The result file's names: coordinates, variables and global attributes.

    Parameters
    ----------
    variables : mapping of str to Variable
        :data:`kanat.io.schema.VARIABLES` (objects with ``dims``, ``units``, ``long_name``,
        ``standard_name``); the time series carry ``time`` before these dimensions.
    coordinates : mapping of str to (dims, units, meaning)
    attributes : mapping of str to str
        Global attribute names and what they hold.
    """
    lines = ["## Result file (netCDF)", "",
             "`kanat run` and `kanat statics` write one netCDF file (CF conventions) per run; "
             "`kanat.simulate` returns the same `xarray.Dataset` in memory. Dynamic results put "
             "`time` first on every time series; statics results have no `time`. Dimensions: "
             "`time`, `node` (all cables' nodes, cable after cable), `segment` (all cables' "
             "elements), `xyz`, `body`, `event` (snap events), `mode` (pitch).", "",
             "### Coordinates {#result-coordinates}", "",
             "| name | dims | units | meaning |", "|---|---|---|---|"]
    for name, (dims, units, meaning) in coordinates.items():
        lines.append(f"| `{name}` | {', '.join(dims)} | {units} | {_cell(meaning)} |")
    lines += ["", "### Variables {#result-variables}", "",
              "| name | dims (after `time`) | units | meaning | CF standard name |", "|---|---|---|---|---|"]
    for name, var in variables.items():
        dims = ", ".join(var.dims) or "–"
        lines.append(f"| `{name}` | {dims} | {var.units} | {_cell(var.long_name)} | "
                     f"{var.standard_name or ''} |")
    lines += ["", "### Global attributes {#result-attributes}", "", "| name | meaning |", "|---|---|"]
    lines += [f"| `{name}` | {_cell(text)} |" for name, text in attributes.items()]
    return "\n".join(lines) + "\n"


def support_markdown() -> str:
    """The table of :mod:`kanat.model.support`: which model takes which feature of a case."""
    from .support import FEATURES, IGNORED, NO, SOLVERS, YES

    mark = {YES: "yes", NO: "**no**", IGNORED: "ignored"}
    lines = ["| feature | " + " | ".join(SOLVERS) + " | note |", "|---" * (len(SOLVERS) + 2) + "|"]
    for row in FEATURES:
        note = row.note if isinstance(row.note, str) else "; ".join(f"{k}: {v}" for k, v in row.note.items())
        lines.append(f"| {_cell(row.title)} | " + " | ".join(mark[row.level(s)] for s in SOLVERS)
                     + f" | {_cell(note)} |")
    return "\n".join(lines) + "\n"
