"""The case format's reference, generated from the pydantic models: a JSON Schema and Markdown.

The models of :mod:`kanat.model` are the only definition of the case file: their field
names are the keys, their annotations the types, :func:`~kanat.model._base.quantity` the
units, their constraints the allowed values, and the ``Attributes`` sections of their
NumPy docstrings (or the fields' own ``description``) what each key means. This module
turns them into

* :func:`json_schema` -- a JSON Schema (draft 2020-12) that YAML editors use to complete
  and check case files (``kanat schema > kanat-case.schema.json``); every property carries
  its ``unit`` and a description that starts with the unit;
* the key-by-key reference and the support table in Markdown
  (:mod:`kanat.model.reference_markdown`, built on the schema).

Pydantic's own schema describes the models' internal form. The case file accepts more
written forms, which the validators turn into that form; :func:`json_schema` adds them:
cable ends written as text (``vessel``, ``anchor:[x, y, z]``, a body name) or one-key
mappings, track segments as one-key mappings (``{turn: {...}}``), the vessel motion as a
plain list of harmonics, square matrices as their diagonal, empty sections (``points:``)
and YAML 1.1's reading of a bare ``off`` as ``false``.

"""
from __future__ import annotations

import copy
import json
import re
from collections.abc import Callable, Iterable, Mapping

from ._base import UNIT_KEY
from .cable import END_FORMS
from .case import Case
from .vessel import SEGMENT_TYPES

DIALECT = "https://json-schema.org/draft/2020-12/schema"
SECTIONS = ("environment", "line_types", "bodies", "points", "vessel", "cables")
"""Top-level sections that may be written empty (``points:`` reads as null: the default)."""
DESCRIPTIONS = {
    "Case.name": "free text naming the case; results carry it as case_name",
    "Case.model": "the model that runs the case: continuum (cable PDE), lumped (Lagrangian network), "
                  "statics (steady state) or pitch (ship pitch with a stabilizer)",
    "Case.environment": "water, seabed, current and waves",
    "Case.line_types": "cable properties per unit length, by name (cables refer to them)",
    "Case.bodies": "towed bodies, buoys, depressors, otter boards, clump weights, by name",
    "Case.points": "network junction points by name (lumped model)",
    "Case.vessel": "the towing vessel: tow point, track, pitch, prescribed motion",
    "Case.cables": "the cables, each between two ends",
    "Case.sphere_two_cables": "Naumov & Agievich's problem: a sphere held by two cables in a uniform flow (model: statics)",
    "Body.mass": "mass of the body in air",
    "Cable.name": "name of the cable, unique in the case (results label its nodes with it)",
    "SurfaceBuoy.waterplane_area": "waterplane area of the buoy",
    "Environment.water_density": "density of the water",
    "Environment.gravity": "acceleration of gravity",
    "Environment.current": "steady current: uniform or a depth profile",
    "Environment.waves": "regular (Airy) or irregular (JONSWAP) waves; none: still water",
    "SphereTwoCables.convention": "published: the paper's signs (sphere drag against the cable's flow); "
                                  "physical: one flow direction for cable and sphere",
    "SphereTwoCables.dimensionless": "the problem as the paper's dimensionless groups",
    "SphereTwoCables.dimensional": "the problem in physical units, mapped to the groups",
    "SphereTwoCables.n_nodes": "nodes along the heavy cable in the result",
    "PitchModel.inertia": "pitch moment of inertia I_y (with added inertia)",
    "PitchModel.natural_frequency": "undamped natural frequency omega_0 of pitch; or give restoring",
    "PitchModel.restoring": "restoring stiffness k = I_y omega_0^2; or give natural_frequency",
    "PitchModel.wave_moment_amplitude": "amplitude M_m of the wave moment M_m sin(omega t + pi)",
    "PitchModel.wave_period": "period of the regular head waves, 2 pi / omega",
    "PitchModel.damping_ratio": "linear damping as a fraction of critical, c = 2 zeta I_y omega_0",
    "PitchModel.stabilizer": "the reactive stabilizer: control mode and largest moment",
    "PitchModel.harmonics": "harmonics N of the Fourier steady state",
    "Stabilizer.mode": "control mode: off; sinusoidal (M0 sin(omega t)) or rectangular (M0) over the "
                       "first half period; feedback on the pitch rate; optimal half-period shape",
    "Stabilizer.max_moment": "largest stabilizer moment M0",
    "Stabilizer.feedback_gain": "gain of the feedback mode, clip(-gain dphi/dt, 0, M0); default 2 I_y omega_0",
    "Stabilizer.shape_nodes": "pieces of the optimal mode's piecewise-linear half-period shape",
    "Stabilizer.objective": "what the optimal mode minimises: the pitch amplitude or the largest |pitch|",
    "RegularWaves.type": "regular: linear (Airy) waves of one height and period",
    "RegularWaves.period": "wave period",
    "JonswapWaves.type": "jonswap: irregular waves from a JONSWAP spectrum",
    "JonswapWaves.heading_deg": "direction the waves travel to, from +x, counter-clockwise seen from above",
    "Straight.speed": "speed over the segment; none: keep the previous speed",
    "Straight.speed_kn": "the speed in knots (instead of speed)",
    "Straight.duration": "how long the vessel runs straight",
    "Accelerate.to_speed": "target speed",
    "Accelerate.to_speed_kn": "target speed in knots (instead of to_speed)",
    "Accelerate.acceleration": "rate of the speed change (a magnitude: the speed rises or falls to the target)",
    "Accelerate.duration": "length of the segment (the target speed is held once reached); none: it ends "
                           "at the target speed",
    "SpeedStep.to_speed": "the speed after the instant step",
    "SpeedStep.to_speed_kn": "the speed after the step, in knots (instead of to_speed)",
    "Turn.radius": "turn radius (give angle_deg with it); or give rate_deg_s",
    "Turn.rate_deg_s": "signed turn rate, positive to port; or give radius",
    "Turn.angle_deg": "signed angle turned, positive to port (counter-clockwise seen from above); or give duration",
    "Turn.duration": "how long the turn lasts; or give angle_deg",
    "Turn.speed": "speed in the turn; none: keep the previous speed",
    "Turn.speed_kn": "speed in the turn in knots (instead of speed)",
    "Heading.to_deg": "heading to turn to, counter-clockwise from +x; or give change_deg",
    "Heading.change_deg": "signed change of heading, positive to port; or give to_deg",
    "Heading.rate_deg_s": "turn rate (a magnitude)",
    "SphereDimensionless.Psi": "cable weight group q / k1",
    "SphereDimensionless.LoL": "length of the line AC over the cable length, L0 / L",
    "SphereDimensionless.x_C": "anchor C of the line, X_C / L",
    "SphereDimensionless.QkL": "sphere net buoyancy group Q / (k1 L)",
    "SphereDimensionless.RkL": "sphere drag group R0 / (k1 L)",
    "SphereDimensionless.chi": "ratio of the cable's drag coefficients C_0 / C_90",
    "SphereDimensional.flow_speed": "speed V of the uniform flow",
    "SphereDimensional.sphere_diameter": "sphere diameter D",
    "SphereDimensional.net_buoyancy": "sphere buoyancy minus weight Q",
    "SphereDimensional.cable_diameter": "diameter delta of the heavy cable AOB",
    "SphereDimensional.cable_length": "length L of the heavy cable AOB",
    "SphereDimensional.line_length": "length L0 of the weightless line AC",
    "SphereDimensional.water_density": "water density; none: environment.water_density",
}
"""What a key means where neither its field nor its class docstring says it, by
``Class.field`` (a field's own ``description`` comes first)."""
_VECTOR3 = {"type": "array", "minItems": 3, "maxItems": 3, "items": {"type": "number"}}
_NAME = {"type": "string", "minLength": 1}


# --- descriptions from the docstrings -----------------------------------------------------

def docstring_attributes(doc: str | None) -> dict[str, str]:
    """The ``Attributes`` section of a NumPy docstring: ``{name: text}``.

    A line ``a, b : float`` documents both names. Double back-quotes become single ones.
    """
    if not doc:
        return {}
    lines = _dedent(doc).splitlines()
    try:
        start = next(i for i, line in enumerate(lines[:-1])
                     if line.strip() == "Attributes" and set(lines[i + 1].strip()) == {"-"})
    except StopIteration:
        return {}
    found: dict[str, list[str]] = {}
    names: list[str] = []
    for line in lines[start + 2:]:
        if line.strip() and not line.startswith(" ") and ":" not in line and names:
            break                                    # the next section's title
        if line.strip() and not line.startswith(" "):
            names = [n.strip() for n in line.split(":")[0].split(",") if n.strip()]
            for name in names:
                found.setdefault(name, [])
        elif line.strip():
            for name in names:
                found[name].append(line.strip())
    return {k: " ".join(v).replace("``", "`") for k, v in found.items() if v}


def _dedent(doc: str) -> str:
    import inspect

    return inspect.cleandoc(doc)


def _summary(doc: str | None) -> str:
    """The first paragraph of a docstring, on one line."""
    if not doc:
        return ""
    return " ".join(_dedent(doc).split("\n\n")[0].split()).replace("``", "`")


def plain_text(text: str) -> str:
    """A docstring's text as plain Markdown: Sphinx roles and references to the specification out."""
    text = re.sub(r":(?:func|class|mod|data|meth|attr):`~?([^`]+)`", r"`\1`", text.replace("``", "`"))
    text = re.sub(r"\s*\(theory/[\w-]+\.md(?: (?:§[\d–]+|eqs?\. \([A-Z]\d+\)))*(?:, theory/[\w-]+\.md(?: (?:§[\d–]+|eqs?\. \([A-Z]\d+\)))*)*\)|,? ?theory/[\w-]+\.md(?: (?:§[\d–]+|eqs?\. \([A-Z]\d+\)))*,?", "", text)
    return " ".join(text.split()).replace("( ", "(").replace(" )", ")")


def _strip_unit(text: str, unit: str) -> str:
    """``text`` without its ``[unit]`` marks; "" when nothing else is left."""
    if unit:
        text = re.sub(r"\s*\[" + re.escape(unit) + r"\]", "", text).strip()
    return text if text.strip(" .;,") else ""


def _unit(prop: dict) -> str:
    """The unit of a property (also inside an ``anyOf`` with null)."""
    return prop.get(UNIT_KEY) or next((b[UNIT_KEY] for b in prop.get("anyOf", []) if UNIT_KEY in b), "")


def _model_classes() -> dict[str, type]:
    """Every model class reachable from :class:`Case`, by its schema name."""
    found: dict[str, type] = {}

    def visit(cls) -> None:
        if cls.__name__ in found:
            return
        found[cls.__name__] = cls
        for info in cls.model_fields.values():
            for inner in _classes_in(info.annotation):
                visit(inner)
    visit(Case)
    return found


def _classes_in(annotation) -> list[type]:
    from typing import get_args

    from pydantic import BaseModel

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    return [c for arg in get_args(annotation) for c in _classes_in(arg)]


def _describe(defs: dict, classes: Mapping[str, type]) -> None:
    """Model summaries and field descriptions (from the docstrings when the field has none),
    each field's starting with its unit."""
    for name, node in defs.items():
        cls = classes.get(name)
        if cls is None:
            continue
        node["description"] = plain_text(_summary(cls.__doc__))
        attributes = docstring_attributes(cls.__doc__)
        for key, prop in node.get("properties", {}).items():
            unit = _unit(prop)
            candidates = [prop.get("description"), attributes.get(key), attributes.get(f"{key}_"),
                          *(DESCRIPTIONS.get(f"{base.__name__}.{key}") for base in cls.__mro__)]
            text = next((t for t in (_strip_unit(plain_text(c or ""), unit) for c in candidates) if t), "")
            if unit and unit != "-":
                text = f"[{unit}] {text}".strip()
            if text:
                prop["description"] = text
            prop.pop("title", None)
        node.pop("title", None)


# --- the written forms the validators accept ---------------------------------------------

def _end_forms(defs: dict) -> None:
    """A cable end: text (``vessel``, ``free``, ``anchor:[x, y, z]``, a name), a one-key
    mapping, ``{body: NAME, offset: [x, y, z]}``, or the stored form ``{kind: ...}``."""
    stored = defs["CableEnd"]
    defs["CableEnd"] = {
        "description": "where a cable end is attached: " + END_FORMS,
        "anyOf": [
            {"type": "string", "minLength": 1,
             "description": "vessel | free | anchor:[x, y, z] | vessel:[x, y, z] | a body or point name"},
            _one_key("anchor", {**_VECTOR3, "description": "[m] anchor position in the global frame"}),
            _one_key("vessel", {**_VECTOR3, "description": "[m] fairlead in vessel axes"}),
            _one_key("body", {**_NAME, "description": "name of a body in bodies"}),
            _one_key("point", {**_NAME, "description": "name of a point in points"}),
            {"type": "object", "additionalProperties": False, "required": ["body", "offset"],
             "properties": {"body": _NAME, "offset": {
                 **_VECTOR3, "description": "[m] fairlead in the body's axes from its reference point"}}},
            stored,
        ],
    }


def _one_key(key: str, value: dict) -> dict:
    return {"type": "object", "additionalProperties": False, "required": [key],
            "properties": {key: value}}


def _track_forms(defs: dict) -> None:
    """A track segment is written ``{KEY: {fields}}`` (or stored as ``{kind: KEY, fields}``)."""
    for key, cls in SEGMENT_TYPES.items():
        inner = defs[cls.__name__]
        stored = copy.deepcopy(inner)
        stored["properties"] = {"kind": {"const": key}, **stored.get("properties", {})}
        stored["required"] = ["kind", *stored.get("required", [])]
        stored.pop("description", None)
        defs[cls.__name__] = {"description": inner.get("description", ""),
                              "anyOf": [_one_key(key, {k: v for k, v in inner.items()
                                                       if k != "description"}), stored]}


def _motion_forms(defs: dict) -> None:
    """``vessel.motion`` may be the list of harmonics itself."""
    stored = defs["VesselMotion"]
    defs["VesselMotion"] = {
        "description": stored.get("description", ""),
        "anyOf": [{"type": "array", "items": {"$ref": "#/$defs/HarmonicMotion"},
                   "description": "harmonics: [{dof, amplitude, period, phase_deg}, ...]"},
                  {k: v for k, v in stored.items() if k != "description"}],
    }


def _cable_forms(defs: dict) -> None:
    """A cable is ``line_type``, ``length`` and ``segments``, or ``sections``."""
    cable = defs["Cable"]
    line_form = [k for k in ("line_type", "length", "segments") if k in cable.get("required", [])]
    cable["required"] = [k for k in cable.get("required", []) if k not in line_form]
    cable["anyOf"] = [{"required": line_form}, {"required": ["sections"]}]


def _walk(node, visit: Callable[[dict], None]) -> None:
    """Call ``visit`` on every mapping of a schema, children first (so what it adds is not
    visited again)."""
    if isinstance(node, dict):
        for value in list(node.values()):
            _walk(value, visit)
        visit(node)
    elif isinstance(node, list):
        for value in node:
            _walk(value, visit)


def _diagonal_matrices(node: dict) -> None:
    """A square matrix (rows of ``n`` numbers) may also be written as its diagonal."""
    rows = node.get("prefixItems")
    if node.get("type") != "array" or not rows or "anyOf" in node:
        return
    n = len(rows)
    if n in (3, 6) and all(r.get("type") == "array" and len(r.get("prefixItems", ())) == n for r in rows):
        square = {k: node.pop(k) for k in list(node) if k in ("type", "prefixItems", "minItems", "maxItems")}
        node["anyOf"] = [{"type": "array", "minItems": n, "maxItems": n, "items": {"type": "number"},
                          "description": "the diagonal"}, square]


def _off_mode(node: dict) -> None:
    """YAML 1.1 reads a bare ``off`` as ``false``; the stabilizer modes take it as ``off``."""
    if node.get("enum") and "off" in node["enum"] and False not in node["enum"]:
        node["enum"] = [*node["enum"], False]
        node.pop("type", None)


def json_schema(schemes: Iterable[str] | None = None) -> dict:
    """The JSON Schema of a case file (draft 2020-12).

    Parameters
    ----------
    schemes : iterable of str, optional
        The scheme names (``kanat.api.SCHEMES``), listed as the values of
        ``simulation.scheme``; without them any text is accepted there.

    Returns
    -------
    dict
        The schema; ``json.dumps`` it to a file that editors load.
    """
    schema = Case.model_json_schema(by_alias=True)
    defs = schema["$defs"]
    _describe(defs, _model_classes())
    _describe({"Case": schema}, {"Case": Case})
    _end_forms(defs)
    _track_forms(defs)
    _motion_forms(defs)
    _cable_forms(defs)
    _walk(schema, _diagonal_matrices)
    _walk(schema, _off_mode)
    for key in SECTIONS:
        prop = schema["properties"][key]
        schema["properties"][key] = {"description": prop.pop("description", ""),
                                     "anyOf": [prop, {"type": "null"}]}
    if schemes is not None:
        scheme = defs["Simulation"]["properties"]["scheme"]
        scheme["anyOf"] = [{"enum": sorted(schemes)}, {"type": "null"}]
        scheme["description"] = "time scheme by name; null: the model's default"
    return {"$schema": DIALECT, "title": "kanat case file", **schema}


def schema_text(schemes: Iterable[str] | None = None) -> str:
    """:func:`json_schema` as indented JSON text (what ``kanat schema`` prints)."""
    return json.dumps(json_schema(schemes), indent=2, ensure_ascii=False) + "\n"
