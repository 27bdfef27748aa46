"""Loading valid case files: models, cable ends, track, current, YAML with lines."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from pydantic import ValidationError
from scipy.constants import knot

from kanat.errors import CaseError
from kanat.io import CaseWarning, check_case, load_case, parse_case
from kanat.io.yaml_loader import load_yaml
from kanat.model import (
    Accelerate,
    Body,
    Cable,
    CableEnd,
    Case,
    Current,
    JonswapWaves,
    LineType,
    RegularWaves,
    Straight,
    Turn,
    Vessel,
)

from helpers import DATA

CASES = DATA / "cases"
VALID = ["full.yaml", "sphere.yaml", "sphere_dimensional.yaml", "pitch.yaml", "mooring.yaml"]


@pytest.mark.parametrize("name", VALID)
def test_valid_cases_load_without_problems(name):
    assert check_case(CASES / name) == []
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert isinstance(load_case(CASES / name), Case)


def test_case_format_example_fields():
    case = load_case(CASES / "full.yaml")
    assert case.name == "sled-speed-step" and case.model == "lumped"
    assert case.environment.depth == 2000
    assert isinstance(case.environment.waves, RegularWaves)
    assert case.environment.waves.heading_deg == 180
    line = case.line_types["towcable"]
    assert line.axial_stiffness == pytest.approx(1.2717e7)  # 1.2717e7 read as a number
    assert line.weight_in_water_value(1025, 9.81) == 8.89
    assert case.bodies["sled"].net_buoyancy == -4448
    cable = case.cables[0]
    assert cable.from_ == CableEnd(kind="vessel")
    assert cable.to == CableEnd(kind="body", name="sled")
    kinds = [s.kind for s in case.vessel.track]
    assert kinds == ["straight", "accelerate", "turn", "straight"]
    assert isinstance(case.vessel.track[2], Turn) and case.vessel.track[2].angle_deg == 375
    assert case.vessel.track[3].speed_ms is None  # keeps the previous speed
    assert case.vessel.initial_speed == pytest.approx(3.086)
    assert case.simulation.dimensions == "auto" and case.simulation.output_interval == 1.0


def test_full_case_with_sphere_and_pitch_blocks_loads_with_ignored_warnings():
    blocks = "".join((CASES / f).read_text().split("\nmodel: ")[1].split("\n", 1)[1]
                     for f in ("sphere.yaml", "pitch.yaml"))
    text = (CASES / "full.yaml").read_text() + blocks
    with pytest.warns(CaseWarning) as record:
        case = parse_case(text, "combined.yaml")
    assert case.sphere_two_cables.dimensionless.QkL == 0.45
    assert case.pitch.stabilizer.max_moment == 1e6
    messages = [str(w.message) for w in record]
    assert any("sphere_two_cables: ignored by model 'lumped'" in m for m in messages)
    assert any("pitch: ignored by model 'lumped'" in m for m in messages)


def test_sphere_and_pitch_blocks():
    sphere = load_case(CASES / "sphere.yaml").sphere_two_cables
    assert sphere.convention == "published" and sphere.n_nodes == 101
    assert (sphere.dimensionless.Psi, sphere.dimensionless.x_C) == (0.02, -1.732)
    dims = load_case(CASES / "sphere_dimensional.yaml").sphere_two_cables
    assert dims.dimensionless is None and dims.dimensional.anchor_x == -173.2
    pitch = load_case(CASES / "pitch.yaml").pitch
    assert pitch.omega0 == 1.0 and pitch.restoring_value == pytest.approx(2e7)
    assert pitch.wave_frequency == pytest.approx(2 * math.pi / 10)


@pytest.mark.parametrize("written, expected", [
    ("vessel", CableEnd(kind="vessel")),
    ("free", CableEnd(kind="free")),
    ("anchor:[0, 0, -100]", CableEnd(kind="anchor", position=(0, 0, -100))),
    ("anchor: [1.5, -2, -3e2]", CableEnd(kind="anchor", position=(1.5, -2, -300))),
    ({"anchor": [0, 0, -100]}, CableEnd(kind="anchor", position=(0, 0, -100))),
    ({"body": "sled"}, CableEnd(kind="body", name="sled")),
])
def test_cable_end_forms(written, expected):
    cable = Cable.model_validate({"name": "c", "line_type": "t", "length": 1, "segments": 1,
                                  "from": written, "to": "free" if written != "free" else "vessel"})
    assert cable.from_ == expected


def test_anchor_string_and_mapping_forms_in_yaml():
    text = (CASES / "mooring.yaml").read_text()
    case = parse_case(text)
    assert case.cables[0].from_ == CableEnd(kind="anchor", position=(0.0, 0.0, -100.0))
    assert case.cables[1].from_ == CableEnd(kind="anchor", position=(5.0, 0.0, -100.0))
    assert case.cables[0].to == CableEnd(kind="point", name="junction")
    assert str(case.cables[0].from_) == "anchor:[0, 0, -100]"
    assert case.cables[0].from_.is_fixed and not case.cables[0].to.is_fixed
    assert isinstance(case.environment.waves, JonswapWaves)
    assert case.environment.waves.seed == 7 and case.environment.waves.gamma == 3.3


def test_current_profile_sorted_and_interpolated():
    current = Current(profile=[[-100, 0.1, 0, 0], [0, 0.5, 0, 0], [-50, 0.3, 0.1, 0]])
    assert [row[0] for row in current.profile] == [0, -50, -100]
    np.testing.assert_allclose(current.at(-25), [0.4, 0.05, 0])
    np.testing.assert_allclose(current.at(5), [0.5, 0, 0])      # constant above
    np.testing.assert_allclose(current.at(-500), [0.1, 0, 0])   # and below
    assert current.at(np.array([0.0, -50.0, -75.0])).shape == (3, 3)
    np.testing.assert_allclose(Current(velocity=[1, 2, 3]).at(-7), [1, 2, 3])
    np.testing.assert_allclose(Current().at([0, -1]), np.zeros((2, 3)))


def test_line_weight_from_mass_and_diameter():
    line = LineType(diameter=0.02, mass=1.0, axial_stiffness=1e6)
    expected = 1.0 * 9.81 - 1025 * 9.81 * math.pi * 0.02**2 / 4
    assert line.weight_in_water_value(1025, 9.81) == pytest.approx(expected)
    assert line.drag_normal == 1.2 and line.drag_tangential == 0.0 and line.breaking_load is None


def test_track_speeds_in_knots_and_initial_speed():
    vessel = Vessel(track=[{"straight": {"speed_kn": 10, "duration": 5}},
                           {"accelerate": {"to_speed_kn": 15, "acceleration": 0.01}}])
    assert vessel.initial_speed == pytest.approx(5.14444)
    assert isinstance(vessel.track[1], Accelerate)
    assert vessel.track[1].to_speed_ms == pytest.approx(15 * knot)
    assert Vessel().initial_speed == 0.0
    assert Vessel(track=[{"accelerate": {"to_speed": 1.5, "acceleration": 0.9}}]).initial_speed == 0
    assert Straight(duration=3).speed_ms is None


def test_models_are_frozen_and_round_trip():
    case = load_case(CASES / "full.yaml")
    with pytest.raises(ValidationError, match="frozen"):
        case.name = "other"
    again = Case.model_validate_json(case.model_dump_json(by_alias=True))
    assert again == case


def test_python_construction_checks_references():
    with pytest.raises(ValueError, match="'rope' is not a line type"):
        Case(model="statics", cables=[{"name": "a", "line_type": "rope", "length": 1,
                                       "segments": 1, "from": "vessel", "to": "sled"}],
             bodies={"sled": Body(mass=1, net_buoyancy=0)})


def test_yaml_loader_records_lines_and_reads_exponents():
    doc = load_yaml("a: 1\nlist:\n  - x: 1e7\n  - {y: 2.5E-3}\nb:\n  c: .5e1\n")
    assert doc.problems == []
    assert doc.data == {"a": 1, "list": [{"x": 1e7}, {"y": 0.0025}], "b": {"c": 5.0}}
    assert doc.lines[("list", 0, "x")] == 3
    assert doc.lines[("list", 1)] == 4 and doc.lines[("list", 1, "y")] == 4
    assert doc.lines[("b", "c")] == 6


def test_yaml_loader_is_safe():
    doc = load_yaml("x: !!python/object/apply:os.system ['echo hi']\n")
    assert doc.data is None and "constructor" in doc.problems[0].message


def test_check_case_never_raises_for_content(tmp_path):
    path = tmp_path / "broken.yaml"
    path.write_text("model: [unclosed\n")
    problems = check_case(path)
    assert len(problems) == 1 and problems[0].file == str(path) and problems[0].line == 2
    with pytest.raises(CaseError) as info:
        load_case(path)
    assert info.value.problems == problems


def test_load_case_warns_with_case_warning(tmp_path):
    path = tmp_path / "still.yaml"
    path.write_text((CASES / "full.yaml").read_text().replace("model: lumped",
                                                              "model: statics")
                    .replace("speed: 3.086", "speed: 0"))
    with pytest.warns(CaseWarning, match=r"initial tow speed is 0 m/s"):
        load_case(path)
