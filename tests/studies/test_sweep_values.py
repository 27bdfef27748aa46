"""The value syntax of studies and the editing of case data by key path.

Oracles: lists written out by hand; NumPy's seeded generator called here directly; a case
file edited by hand (text replacement) against the variant built from the key path.
"""
import numpy as np
import pytest

from kanat.errors import KanatError
from kanat.io import parse_case
from kanat.io.results import case_sha256
from kanat.sweep import parse_values, plan_study
from kanat.sweep.variants import parse_key, set_value, short_labels, variant_text, validate_variant

from helpers import EXAMPLES


@pytest.mark.parametrize("text, expected", [
    ("4,6,8", [4, 6, 8]), ("[4, 6.5, 8]", [4, 6.5, 8]), ("box, generalized-alpha", ["box", "generalized-alpha"]),
    ("4:8:2", [4, 6, 8]), ("4:9:2", [4, 6, 8]), ("0:0.3:0.1", [0.0, 0.1, 0.2, 0.3]), ("8:4:-2", [8, 6, 4]),
    ("linspace(0, 1, 5)", [0.0, 0.25, 0.5, 0.75, 1.0]), ("7", [7]), ("1e7, 2e7", [1e7, 2e7]), ("true", [True])])
def test_value_syntax(text, expected):
    assert parse_values(text) == expected


def test_seeded_draws_are_numpys_own():
    assert parse_values("uniform(4, 8, 5, 1)") == np.random.default_rng(1).uniform(4, 8, 5).tolist()
    assert parse_values("normal(6, 0.5, 3, 42)") == np.random.default_rng(42).normal(6, 0.5, 3).tolist()
    assert parse_values("uniform(4, 8, 5, 1)") != parse_values("uniform(4, 8, 5, 2)")
    assert parse_values(np.array([1.0, 2.0])) == [1.0, 2.0] and parse_values((3, 4)) == [3, 4]


@pytest.mark.parametrize("text, message", [
    ("4:8", "a range is start:stop:step"), ("4:8:0", "never goes from 4 to 8"), ("8:4:1", "never goes"),
    ("uniform(1, 2, 3)", r"uniform\(a, b, n, seed\)"), ("uniform(2, 1, 3, 0)", "needs b > a"),
    ("linspace(0, 1, 2.5)", "whole number"), ("0:1e9:1", "at most"), ("", "no values given"),
    ("a:b:c", "not a number")])
def test_value_errors_name_the_key(text, message):
    with pytest.raises(KanatError, match=message) as error:
        parse_values(text, "environment.waves.period")
    assert "environment.waves.period" in str(error.value)


def test_key_paths_and_labels():
    assert parse_key("vessel.track[1].to_speed_kn") == ("vessel", "track", 1, "to_speed_kn")
    with pytest.raises(KanatError, match="not a key path"):
        parse_key("vessel..track")
    assert short_labels(["a.x.speed", "b.y.speed", "c.length"]) == {"a.x.speed": "x.speed", "b.y.speed": "y.speed",
                                                                   "c.length": "length"}


def test_set_value_enters_track_wrappers_and_reports_unreachable_keys():
    data = {"vessel": {"track": [{"straight": {"speed": 1}}, {"speed_step": {"to_speed": 4}}]}, "cables": [{}]}
    set_value(data, "vessel.track[1].to_speed", 3.0)
    set_value(data, "vessel.track[0].straight.duration", 50)
    set_value(data, "environment.waves.period", 5.6)                   # missing mappings are added
    assert data["vessel"]["track"] == [{"straight": {"speed": 1, "duration": 50}}, {"speed_step": {"to_speed": 3.0}}]
    assert data["environment"] == {"waves": {"period": 5.6}}
    with pytest.raises(KanatError, match=r"vessel.track\[5\]: vessel.track has 2 item\(s\)"):
        set_value(data, "vessel.track[5].to_speed", 1)
    with pytest.raises(KanatError, match="needs a list there"):
        set_value(data, "vessel[0]", 1)
    with pytest.raises(KanatError, match="needs a mapping there, but it is the value 3.0"):
        set_value(data, "vessel.track[1].to_speed.x", 1)


def test_variant_is_the_case_edited_by_hand():
    text = (EXAMPLES / "speed_step_2d.yaml").read_text()
    from kanat.sweep.variants import base_data

    data, _ = base_data(EXAMPLES / "speed_step_2d.yaml")
    built, _ = validate_variant(variant_text(data, {"vessel.track[1].to_speed_kn": 8, "cables[0].segments": 40}), "v")
    by_hand = parse_case(text.replace("to_speed_kn: 10", "to_speed_kn: 8").replace("segments: 100", "segments: 40"))
    assert case_sha256(built) == case_sha256(by_hand)
    _, error = validate_variant(variant_text(data, {"line_types.towcable.diamter": 0.02}), "v")
    assert "line_types.towcable.diamter" in error and "diameter" in error


def test_plan_names_cases_and_refuses_an_all_invalid_study():
    plan = plan_study(EXAMPLES / "speed_step_2d.yaml", {"vessel.track[1].to_speed_kn": "8:10:1",
                                                       "environment.water_density": [1025, 1000]})
    assert [c.name for c in plan.cases[:3]] == ["case000_to_speed_kn=8_water_density=1025",
                                                 "case001_to_speed_kn=8_water_density=1000",
                                                 "case002_to_speed_kn=9_water_density=1025"]
    assert len(plan.cases) == 6 and not any(c.error for c in plan.cases)
    with pytest.raises(KanatError, match="(?s)no case of the study is valid.*line_types.towcable.diameter"):
        plan_study(EXAMPLES / "speed_step_2d.yaml", {"line_types.towcable.diameter": [-1, -2]})
    with pytest.raises(KanatError, match="nothing to vary"):
        plan_study(EXAMPLES / "speed_step_2d.yaml", {})
