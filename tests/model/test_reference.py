"""The case-format reference and the JSON Schema are generated from the models and agree with them.

Oracles: the pydantic models themselves (every field of every model reachable from ``Case``
is in the schema and on the page; the loader and the schema accept and refuse the same
mutations of the examples); the committed pages equal what the generator makes now;
the JSON Schema is valid against the draft 2020-12 meta-schema.
"""
import copy
import importlib.util
import json
import sys
from pathlib import Path

import pytest

from kanat.cli_docs import ATTRIBUTES, reference_page
from kanat.errors import CaseError
from kanat.io.yaml_loader import load_yaml
from kanat.model.reference import _model_classes, docstring_attributes, json_schema, schema_text

from helpers import ROOT

jsonschema = pytest.importorskip("jsonschema", reason="the test extra installs jsonschema")

EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))


def _scripts_module():
    spec = importlib.util.spec_from_file_location("docs_reference", ROOT / "scripts" / "docs_reference.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("docs_reference", module)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def schema():
    from kanat.api import SCHEMES

    return json_schema(SCHEMES)


@pytest.fixture(scope="module")
def validator(schema):
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def _data(path: Path):
    """The example as kanat reads it (YAML with 1e7-style floats as numbers)."""
    return load_yaml(path.read_text(encoding="utf-8"), str(path)).data


def test_committed_pages_are_the_generated_ones():
    stale = [path.relative_to(ROOT).as_posix() for path, text in _scripts_module().pages().items()
             if not path.exists() or path.read_text(encoding="utf-8") != text]
    assert not stale, f"regenerate with: python scripts/docs_reference.py ({', '.join(stale)})"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_every_example_validates_against_the_schema(path, validator):
    errors = [f"{list(e.absolute_path)}: {e.message[:200]}" for e in validator.iter_errors(_data(path))]
    assert not errors


def test_every_field_of_every_model_is_in_the_schema_with_its_unit(schema):
    defs = schema["$defs"]
    for name, cls in _model_classes().items():
        node = schema if name == "Case" else defs[name]
        objects = [node] + [b for b in node.get("anyOf", []) if b.get("properties")]
        objects += [p for b in objects for p in b.get("properties", {}).values() if "properties" in p]
        keys = {k for b in objects for k in b.get("properties", {})}
        for field, info in cls.model_fields.items():
            assert (info.alias or field) in keys, f"{name}.{field} missing from the schema"
            unit = (info.json_schema_extra or {}).get("unit") if isinstance(info.json_schema_extra, dict) else None
            if unit:
                text = json.dumps(node)
                assert f'"unit": "{unit}"' in text, f"{name}.{field}: unit {unit} lost"


def test_every_key_on_the_page_has_a_type_and_a_description():
    page = reference_page()
    rows = [r for r in page.splitlines() if r.startswith("| `")]
    case_rows = [r for r in rows if r.count("|") >= 7]
    assert len(case_rows) > 150
    empty = [r.split("|")[1].strip() for r in case_rows if not r.split("|")[6].strip()]
    assert not empty, f"keys without a description: {empty}"
    for name, cls in _model_classes().items():
        assert f"{{#{name.lower()}}}" in page, name


def test_every_result_variable_and_provenance_attribute_is_documented():
    from kanat.io.results import provenance
    from kanat.io.schema import VARIABLES
    from kanat.model import Case

    page = reference_page()
    for name in VARIABLES:
        assert f"| `{name}` |" in page
    case = Case.model_validate({"model": "pitch", "pitch": {"inertia": 1, "natural_frequency": 1,
                                                             "wave_moment_amplitude": 1, "wave_period": 3}})
    documented = {n.strip() for key in ATTRIBUTES for n in key.split(",")}
    assert set(provenance(case, model="pitch", scheme="x")) <= documented


def _loads(data) -> bool:
    """True when kanat loads the case (errors of support or limits aside: not the schema's business)."""
    import warnings

    from kanat.api import load_case

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            load_case(data)
        return True
    except CaseError as error:
        return not any(p.severity == "error" and "not support" not in p.message for p in error.problems)


MUTATIONS = [
    ("unknown top-level key", lambda d: d.update(modle="statics"), False),
    ("unknown line type key", lambda d: next(iter(d["line_types"].values())).update(diameterr=0.1), False),
    ("negative diameter", lambda d: next(iter(d["line_types"].values())).update(diameter=-0.1), False),
    ("anchor as text", lambda d: d["cables"][0].update({"from": "anchor:[0, 0, -150]"}), True),
    ("anchor as mapping", lambda d: d["cables"][0].update({"from": {"anchor": [0, 0, -150]}}), True),
    ("end of a wrong form", lambda d: d["cables"][0].update({"from": {"anchr": [0, 0, -150]}}), False),
    ("empty points section", lambda d: d.update(points=None), True),
    ("model unknown", lambda d: d.update(model="fem"), False),
    ("vector of 2", lambda d: d["vessel"].update(tow_point=[0, 0]), False),
    ("track segment by its key", lambda d: d["vessel"].update(track=[{"straight": {"speed_kn": 6, "duration": 60}}]), True),
    ("unknown track segment", lambda d: d["vessel"].update(track=[{"zigzag": {"duration": 60}}]), False),
    ("knots as text", lambda d: d["vessel"].update(track=[{"straight": {"speed_kn": "six", "duration": 60}}]), False),
]


@pytest.mark.parametrize("label, mutate, valid", MUTATIONS, ids=[m[0] for m in MUTATIONS])
def test_schema_and_loader_agree_on_mutations_of_an_example(label, mutate, valid, validator):
    data = copy.deepcopy(_data(ROOT / "examples" / "towed_body.yaml"))
    data.setdefault("vessel", {})
    mutate(data)
    by_schema = not list(validator.iter_errors(data))
    assert by_schema == valid
    assert _loads(data) == valid


def test_docstring_attributes_are_parsed_per_name():
    doc = """One line.

    Attributes
    ----------
    a, b : float
        Both [m].
    c : str
        Third,
        on two lines.

    Notes
    -----
    not an attribute.
    """
    assert docstring_attributes(doc) == {"a": "Both [m].", "b": "Both [m].", "c": "Third, on two lines."}


def test_schema_command_prints_the_schema():
    import typer
    from typer.testing import CliRunner

    from kanat.cli_docs import register

    app = typer.Typer()
    register(app)
    result = CliRunner().invoke(app, ["schema"])
    assert result.exit_code == 0, result.output
    from kanat.api import SCHEMES

    assert json.loads(result.output) == json.loads(schema_text(SCHEMES))
    markdown = CliRunner().invoke(app, ["schema", "--markdown"])
    assert markdown.output == reference_page()
