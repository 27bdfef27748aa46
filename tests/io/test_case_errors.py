"""Error messages: every problem names the file, the line, the key path and what is valid."""
from __future__ import annotations

import textwrap

import pytest

from kanat.errors import CaseError
from kanat.io import check_text, parse_case

from helpers import EXAMPLES

# Line numbers of BASE (1-based) used by the tests below.
BASE = textwrap.dedent("""\
    name: errors
    model: lumped
    environment:
      depth: 2000
      waves: {type: regular, height: 1.0, period: 8.0}
    line_types:
      towcable:
        diameter: 0.0173
        mass: 1.12
        axial_stiffness: 1.2717e7
    bodies:
      sled: {mass: 1135, net_buoyancy: -4448, drag_area: 0.33}
    vessel:
      track:
        - {straight: {speed: 3.0, duration: 100}}
    cables:
      - name: tow
        line_type: towcable
        length: 1000
        segments: 100
        from: vessel
        to: sled
    simulation:
      duration: 600
      dt: 1.0
      output_dt: 1.0
    """)


def edit(old: str, new: str, text: str = BASE) -> str:
    """Replace one exact occurrence of ``old``."""
    assert text.count(old) == 1, old
    return text.replace(old, new)


def errors_of(text: str) -> list:
    return [p for p in check_text(text, "case.yaml") if p.severity == "error"]


def only_error(text: str):
    found = errors_of(text)
    assert len(found) == 1, [str(p) for p in found]
    return found[0]


def test_base_is_valid():
    assert check_text(BASE) == []


@pytest.mark.parametrize("old, new, key, line, words", [
    # value out of range, with the unit of the field
    ("length: 1000", "length: -5", "cables[0].length", 19,
     ["must be greater than 0 (got -5 m)"]),
    ("diameter: 0.0173", "diameter: 0", "line_types.towcable.diameter", 8,
     ["must be greater than 0 (got 0 m)"]),
    # not a number
    ("  dt: 1.0", "  dt: abc", "simulation.dt", 25, ["must be a number (got 'abc')"]),
    ("segments: 100", "segments: 2.5", "cables[0].segments", 20,
     ["must be a whole number (got 2.5)"]),
    # misspelt key: suggestion and the list of valid keys
    ("drag_area: 0.33", "drag_aera: 0.33", "bodies.sled.drag_aera", 12,
     ["unknown key 'drag_aera'; did you mean 'drag_area'?",
      "valid keys: mass, net_buoyancy, drag_area, added_mass, force"]),
    # unknown names, with the known ones and a suggestion
    ("line_type: towcable", "line_type: towcabel", "cables[0].line_type", 18,
     ["'towcabel' is not a line type; known: towcable (did you mean 'towcable'?)"]),
    ("to: sled", "to: sledd", "cables[0].to", 22,
     ["'sledd' is not a body or point", "bodies: sled", "(did you mean 'sled'?)"]),
    # enum values
    ("model: lumped", "model: lumpd", "model", 2,
     ["'lumpd' is not one of: statics, continuum, lumped, pitch",
      "(did you mean 'lumped'?)"]),
    ("type: regular", "type: regullar", "environment.waves.type", 5,
     ["'regullar' is not a valid type; valid: regular, jonswap, components (did you mean 'regular'?)"]),
    ("{straight: {speed", "{stright: {speed", "vessel.track[0].stright", 15,
     ["'stright' is not a valid track segment", "straight, accelerate, speed_step, turn, "
      "heading", "(did you mean 'straight'?)"]),
    # vectors and end forms
    ("to: sled", "to: {anchor: [1, 2]}", "cables[0].to.position", 22,
     ["must be a list of 3 numbers [x, y, z] (got 2 values)"]),
    ("to: sled", "to: anchor:[0, x, -1]", "cables[0].to", 22,
     ["anchor coordinates must be 3 numbers"]),
    ("to: sled", "to: free\n    extra: 1", "cables[0].extra", 23,
     ["unknown key 'extra'; valid keys: name, line_type, length, segments, sections, "
      "attachments, from, to"]),
    # cross-field rules inside a block
    ("{straight: {speed: 3.0,", "{straight: {speed: 3.0, speed_kn: 6,", "vessel.track[0].straight",
     15, ["give either 'speed' (m/s) or 'speed_kn' (knots), not both"]),
    ("waves: {type: regular, height: 1.0, period: 8.0}", "current: {velocity: [1, 0, 0], "
     "profile: [[0, 1, 0, 0]]}", "environment.current", 5, ["not both"]),
    # wrong container type
    ("bodies:\n  sled: {mass: 1135, net_buoyancy: -4448, drag_area: 0.33}",
     "bodies:\n  sled: 5", "bodies.sled", 12, ["must be a mapping of keys (got 5)"]),
])
def test_error_names_key_and_line(old, new, key, line, words):
    problem = only_error(edit(old, new))
    assert problem.key == key
    assert problem.line == line
    assert problem.file == "case.yaml"
    text = str(problem)
    assert text.startswith(f"case.yaml:{line}: error: {key}: ")
    for word in words:
        assert word in text


def test_missing_key_points_at_its_block():
    problem = only_error(edit("    length: 1000\n", ""))
    assert (problem.key, problem.line) == ("cables[0]", 17)
    assert problem.message == "missing required key 'length' [m]"


def test_missing_model_lists_choices():
    problem = only_error(edit("model: lumped\n", ""))
    assert problem.key == "" and problem.line == 1
    assert "missing required key 'model'; one of: statics, continuum, lumped, pitch" in str(problem)


def test_missing_required_section_points_at_model_line():
    text = edit("simulation:\n  duration: 600\n  dt: 1.0\n  output_dt: 1.0\n", "")
    problem = only_error(text)
    assert (problem.key, problem.line) == ("simulation", 2)
    assert "model 'lumped' needs a 'simulation' block" in problem.message


def test_duplicate_key_names_both_lines():
    problem = only_error(edit("mass: 1.12\n", "mass: 1.12\n    mass: 1.2\n"))
    assert problem.key == "line_types.towcable.mass" and problem.line == 10
    assert "duplicate key 'mass' (lines 9 and 10)" in problem.message


def test_yaml_syntax_error_has_line():
    problem = only_error(edit("length: 1000", "length: [1000"))
    assert problem.line is not None and problem.line >= 19
    assert "YAML syntax error" in problem.message and "starts at line 19" in problem.message


def test_anchor_with_space_in_flow_mapping_explains_the_fix():
    problem = only_error(edit("to: sled", "to: sled\n  - {name: b, from: anchor:[0, 0, -1]}"))
    assert problem.line == 23
    assert "{anchor: [x, y, z]}" in problem.message


def test_top_level_must_be_a_mapping():
    problem = only_error("- 1\n- 2\n")
    assert "a case must be a mapping of keys" in problem.message and "got a list" in problem.message


def test_track_segment_with_two_keys():
    problem = only_error(edit("{straight: {speed: 3.0, duration: 100}}",
                              "{straight: {duration: 1}, turn: {radius: 5, angle_deg: 90}}"))
    assert (problem.key, problem.line) == ("vessel.track[0]", 15)
    assert "one-key mapping" in problem.message and "keys straight, turn" in problem.message


@pytest.mark.parametrize("segment, words", [
    ("{turn: {radius: 600, duration: 30}}", "with 'radius', give 'angle_deg'"),
    ("{turn: {angle_deg: 90}}", "exactly one of 'radius' (m) or 'rate_deg_s'"),
    ("{turn: {rate_deg_s: -1, angle_deg: 90}}", "turn opposite ways"),
    ("{accelerate: {acceleration: 0.1}}", "needs a target speed"),
    ("{heading: {rate_deg_s: 1}}", "exactly one of 'to_deg'"),
])
def test_track_segment_rules(segment, words):
    problem = only_error(edit("{straight: {speed: 3.0, duration: 100}}", segment))
    assert problem.line == 15 and problem.key.startswith("vessel.track[0].")
    assert words in problem.message


def test_misspelt_required_key_is_one_problem():
    unknown = only_error(edit("diameter: 0.0173", "diamter: 0.0173"))
    assert (unknown.key, unknown.line) == ("line_types.towcable.diamter", 8)
    assert unknown.message.startswith("unknown key 'diamter'; did you mean 'diameter'? "
                                      "valid keys: diameter, mass, weight_in_water,")


def test_cable_rules():
    problem = only_error(edit("from: vessel\n    to: sled", "from: free\n    to: free"))
    assert (problem.key, problem.line) == ("cables[0]", 17)
    assert "both ends are 'free'" in problem.message
    dup = BASE.replace("simulation:", "  - {name: tow, line_type: towcable, length: 5, segments: 1,"
                       " from: vessel, to: free}\nsimulation:")
    problem = only_error(dup)
    assert problem.key == "cables" and "'tow' is used by cables[0] and cables[1]" in problem.message


def test_three_mistakes_give_three_problems():
    text = edit("diameter: 0.0173", "diamter: 0.0173",
                edit("line_type: towcable", "line_type: towcabel",
                     edit("length: 1000", "length: -5")))
    found = errors_of(text)
    assert [(p.key, p.line) for p in found] == [
        ("line_types.towcable.diamter", 8), ("cables[0].line_type", 18), ("cables[0].length", 19)]
    with pytest.raises(CaseError) as info:
        parse_case(text, "case.yaml")
    assert len(info.value.problems) == 3
    assert str(info.value).startswith("3 problem(s) in the case:")
    assert "case.yaml:18: error: cables[0].line_type:" in str(info.value)


def test_three_independent_mistakes_in_three_sections():
    text = edit("  dt: 1.0", "  dt: -1", edit("model: lumped", "model: lumpd",
                                          edit("net_buoyancy: -4448", "net_buoyancy: heavy")))
    found = errors_of(text)
    assert [(p.key, p.line) for p in found] == [("model", 2), ("bodies.sled.net_buoyancy", 12),
                                               ("simulation.dt", 25)]


def test_warnings_are_included_in_the_error_when_errors_exist():
    text = edit("segments: 100", "segments: 100000", edit("  dt: 1.0", "  dt: 0"))
    with pytest.raises(CaseError) as info:
        parse_case(text)
    found = sorted((p.key, p.severity) for p in info.value.problems)
    # every problem at once: the whole-case checks run past the bad dt (its default stands in)
    assert found == [("simulation.dt", "error"), ("simulation.output_dt", "error")]
    # 60 000 segments: elements shorter than the diameter, result within the 2 GiB limit
    text = edit("segments: 100", "segments: 60000", edit("output_dt: 1.0", "output_dt: 1.5"))
    with pytest.raises(CaseError) as info:
        parse_case(text)
    assert sorted(p.severity for p in info.value.problems) == ["error", "warning"]


def test_problems_found_after_reading_name_the_file(tmp_path):
    """A case read from a file remembers it: a bad ``replace`` and a model that refuses the case
    when it is built (both after reading, with no line to give) name the file, not ``<case>``."""
    import kanat

    path = tmp_path / "three_legs.yaml"
    path.write_text((EXAMPLES / "mooring_buoy_decay.yaml").read_text())
    case = kanat.load_case(path)
    assert case.source == str(path) and case.replace({"simulation.duration": 2.0}).source == str(path)
    with pytest.raises(CaseError) as replaced:
        case.replace({"simulation.output_dt": 1.0e4})
    with pytest.raises(CaseError) as built:
        kanat.run(case.replace({"model": "continuum", "simulation.dt": 0.5}))
    for error in (replaced.value, built.value):
        assert error.problems and all(p.file == str(path) for p in error.problems)
        assert "<case>" not in str(error) and f"{path}: error:" in str(error)
    assert parse_case(BASE).source is None and parse_case(BASE, file="<text>").source == "<text>"


def test_a_vector_written_as_a_mapping_with_a_negative_key_is_a_clear_error():
    """``offset: {-4: 1.0}`` (found by the fuzz test): the error's location holds -4, which once
    indexed the vector's item types from the end and raised IndexError instead of the message."""
    import yaml

    from kanat.errors import CaseError
    from kanat.io.case_file import parse_case

    from helpers import EXAMPLES

    data = yaml.safe_load((EXAMPLES / "mooring_buoy_waves.yaml").read_text())
    data["cables"][-1]["to"] = {**data["cables"][-1]["to"], "offset": {-4: 1.0}}
    with pytest.raises(CaseError, match=r"x.yaml:\d+: error: cables\[2\]\.to\.offset: must be a list of 3 numbers"):
        parse_case(yaml.safe_dump(data), "x.yaml")
