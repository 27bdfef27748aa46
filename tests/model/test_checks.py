"""Physical sanity checks: each fires on a bad case, with numbers and units, and stays
quiet on good cases."""
from __future__ import annotations

import math
import textwrap

import pytest

from kanat.io import check_case, check_text, parse_case
from kanat.model.checks import CHECKS, physical_checks, wavelength

from helpers import DATA, EXAMPLES

CASES = DATA / "cases"

# A towed sled with a mooring next to it; every check is quiet on it.
GOOD = textwrap.dedent("""\
    name: good
    model: lumped
    environment:
      depth: 1000
      waves: {type: regular, height: 2.0, period: 8.0}
    line_types:
      rope:
        diameter: 0.02
        mass: 1.0
        weight_in_water: 5.0
        axial_stiffness: 1.0e7
        breaking_load: 1.0e6
    bodies:
      sled: {mass: 1000, net_buoyancy: -5000, drag_area: 0.3}
      buoy: {mass: 100, net_buoyancy: 3000}
    vessel:
      track:
        - {straight: {speed: 2.0, duration: 100}}
    cables:
      - name: tow
        line_type: rope
        length: 500
        segments: 50
        from: vessel
        to: sled
      - name: mooring
        line_type: rope
        length: 400
        segments: 40
        from: anchor:[300, 0, -1000]
        to: buoy
    simulation: {duration: 100, dt: 0.1, output_dt: 0.5}
    """)


def edit(old: str, new: str, text: str = GOOD) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def findings(text: str) -> list:
    return check_text(text, "case.yaml")


def line_with(text: str, needle: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


@pytest.mark.parametrize("name", ["full.yaml", "sphere.yaml", "sphere_dimensional.yaml",
                                  "pitch.yaml", "mooring.yaml"])
def test_quiet_on_good_files(name):
    assert check_case(CASES / name) == []


def test_quiet_on_good_case():
    assert findings(GOOD) == []


def test_every_check_runs_on_a_programmatic_case_without_lines():
    case = parse_case(GOOD)
    assert physical_checks(case) == []
    assert len(CHECKS) >= 15


# Each row: an edit of GOOD, then the expected key, severity, needle for the line, and
# substrings with the numbers the message must state.
BAD = {
    "line heavier in water than in air": (
        "weight_in_water: 5.0", "weight_in_water: 12.0", "line_types.rope.weight_in_water",
        "error", "weight_in_water", ["weight in water 12 N/m exceeds the weight in air 9.81 N/m"]),
    "negative buoyancy": (
        "net_buoyancy: -5000", "net_buoyancy: -20000", "bodies.sled.net_buoyancy", "error",
        "sled:", ["net buoyancy -20000 N is below -(mass × g) = -9810 N"]),
    "anchor below the seabed": (
        "anchor:[300, 0, -1000]", "anchor:[300, 0, -1200]", "cables[1].from", "error",
        "anchor:[300", ["z = -1200 m is below the seabed at z = -1000 m"]),
    "anchor above the surface": (
        "anchor:[300, 0, -1000]", "anchor:[300, 0, 10]", "cables[1].from", "warning",
        "anchor:[300", ["z = 10 m is above the free surface"]),
    "buoy too weak for its mooring": (
        "net_buoyancy: 3000", "net_buoyancy: 1000", "bodies.buoy.net_buoyancy", "warning",
        "buoy:", ["net buoyancy 1000 N", "2000 N", "'mooring'", "will sink"]),
    "body and cable above the breaking load": (
        "breaking_load: 1.0e6", "breaking_load: 7000", "cables[0]", "error", "name: tow",
        ["submerged weight 5 kN", "2.5 kN", "up to 7.5 kN", "breaking load 7 kN"]),
    "static strain above 10 %": (
        "axial_stiffness: 1.0e7", "axial_stiffness: 5.0e4", "cables[0]", "error", "name: tow",
        ["static strain of 15 %", "EA 50 kN"]),
    "output_dt not a multiple of dt": (
        "output_dt: 0.5", "output_dt: 0.25", "simulation.output_dt", "error", "simulation:",
        ["output_dt 0.25 s is not a multiple of dt 0.1 s (2.5 steps)", "0.2 s or 0.3 s"]),
    "elements shorter than the diameter": (
        "segments: 50\n", "segments: 50000\n", "cables[0].segments", "warning", "segments: 50",
        ["elements are 0.01 m long (500 m / 50000 segments)", "diameter 0.02 m",
         "at most 25000 segments"]),
    "regular wave steeper than 1/7": (
        "period: 8.0", "period: 1.0", "environment.waves.height", "warning", "waves:",
        ["height 2 m over the wavelength 1.561 m", "steepness of 1.28", "1/7"]),
    "one wave component steeper than 1/7": (
        "waves: {type: regular, height: 2.0, period: 8.0}",
        "waves: {type: components, components: [[0.7854, 1.0, 0, 0], [6.283185307, 1.0, 0, 0]]}",
        "environment.waves.components", "warning", "waves:",
        ["components 2 m over the wavelength 1.561 m", "period 2 pi/omega 1 s", "steepness of 1.28"]),
    "JONSWAP sea steeper than 1/7": (
        "waves: {type: regular, height: 2.0, period: 8.0}", "waves: {type: jonswap, hs: 2.0, tp: 1.0, seed: 1}",
        "environment.waves.hs", "warning", "waves:",
        ["hs 2 m over the wavelength 1.561 m", "tp 1 s", "steepness of 1.28", "1/7"]),
    "JONSWAP sea higher than the depth allows": (
        "depth: 1000\n  waves: {type: regular, height: 2.0, period: 8.0}",
        "depth: 10\n  waves: {type: jonswap, hs: 9.0, tp: 30.0, seed: 1}",
        "environment.waves.hs", "warning", "waves:", ["hs 9 m exceeds 0.78 × depth = 7.8 m"]),
    "body 400 m below a 1000 m seabed": (
        "buoy: {mass: 100, net_buoyancy: 3000}", "buoy: {mass: 100, net_buoyancy: 3000, position: [300, 0, -1400]}",
        "bodies.buoy.position", "error", "buoy:",
        ["body 'buoy' at z = -1400 m is 400 m below the seabed at z = -1000 m", "deepen environment.depth"]),
    "towed cable without a track": (
        "  track:\n    - {straight: {speed: 2.0, duration: 100}}\n", "  tow_point: [0, 0, 0]\n",
        "vessel.track", "warning", "vessel:", ["vessel has no track", "0 m/s"]),
    "body attached to nothing": (
        "  buoy: {mass: 100, net_buoyancy: 3000}\n",
        "  buoy: {mass: 100, net_buoyancy: 3000}\n  spare: {mass: 1, net_buoyancy: 0}\n",
        "bodies.spare", "warning", "spare:", ["body 'spare' is not attached to any cable"]),
}


@pytest.mark.parametrize("old, new, key, severity, needle, words", BAD.values(), ids=BAD.keys())
def test_check_fires_with_numbers(old, new, key, severity, needle, words):
    text = edit(old, new)
    found = [p for p in findings(text) if p.key == key]
    assert len(found) == 1, [str(p) for p in findings(text)]
    problem = found[0]
    assert problem.severity == severity
    assert problem.line == line_with(text, needle)
    for word in words:
        assert word in problem.message, problem.message


SPAN = GOOD.replace("simulation:", textwrap.indent(textwrap.dedent("""\
    - name: span
      line_type: rope
      length: 100
      segments: 10
      from: anchor:[0, 0, -900]
      to: anchor:[DX, 0, -900]
    """), "  ") + "simulation:")


@pytest.mark.parametrize("dx, breaking, severity, words", [
    (105, "1.0e6", "warning", ["105 m apart but it is 100 m long", "stretch 5 %",
                               "tension of 500 kN (EA 1e+04 kN × strain 0.05)"]),
    (130, "1.0e6", "error", ["stretch 30 %", "3000 kN", "above the breaking load 1000 kN",
                             "more than 20% stretch"]),
    (110, "5.0e5", "error", ["stretch 10 %", "1000 kN", "above the breaking load 500 kN"]),
])
def test_fixed_ends_too_far_apart(dx, breaking, severity, words):
    text = SPAN.replace("DX", str(dx)).replace("breaking_load: 1.0e6", f"breaking_load: {breaking}")
    found = [p for p in findings(text) if p.key == "cables[2].length"]
    assert len(found) == 1 and found[0].severity == severity
    assert found[0].line == line_with(text, "length: 100")
    for word in words:
        assert word in found[0].message, found[0].message


def test_fixed_ends_within_reach_are_quiet():
    assert findings(SPAN.replace("DX", "99")) == []


def test_vessel_to_anchor_uses_the_tow_point():
    text = edit("  track:", "  tow_point: [-20, 0, 10]\n  track:", edit(
        "anchor:[300, 0, -1000]\n    to: buoy", "anchor:[0, 0, -400]\n    to: vessel"))
    problem = next(p for p in findings(text) if p.key == "cables[1].length")
    assert "410.488 m apart but it is 400 m long" in problem.message
    assert problem.severity == "warning"


def test_dt_longer_than_duration():
    problem = next(p for p in findings(edit("dt: 0.1", "dt: 200")) if p.key == "simulation.dt")
    assert problem.severity == "error"
    assert "dt 200 s is longer than the duration 100 s" in problem.message


def test_depth_limited_breaking():
    text = edit("depth: 1000", "depth: 10", edit("height: 2.0, period: 8.0",
                                                 "height: 9.0, period: 20.0"))
    text = text.replace("-1000]", "-10]")
    found = [p for p in findings(text) if p.key == "environment.waves.height"]
    assert len(found) == 1 and "exceeds 0.78 × depth = 7.8 m" in found[0].message


def test_jonswap_steepness():
    text = edit("{type: regular, height: 2.0, period: 8.0}", "{type: jonswap, hs: 3.0, tp: 1.5}")
    problem = next(p for p in findings(text) if p.key == "environment.waves.hs")
    assert "hs 3 m over the wavelength 3.513 m" in problem.message


def test_statics_tow_at_zero_speed():
    text = edit("model: lumped", "model: statics", edit("speed: 2.0", "speed: 0"))
    problem = next(p for p in findings(text) if p.key == "vessel.track[0]")
    assert problem.severity == "warning" and "initial tow speed is 0 m/s" in problem.message


def test_planar_model_with_a_turn():
    text = edit("output_dt: 0.5}", "output_dt: 0.5, dimensions: 2}", edit(
        "duration: 100}}", "duration: 100}}\n    - {turn: {radius: 500, angle_deg: 90}}"))
    problem = next(p for p in findings(text) if p.key == "simulation.dimensions")
    assert problem.severity == "error"
    assert "vessel.track[1] is a turn" in problem.message and "dimensions: 3" in problem.message
    quiet = edit("output_dt: 0.5}", "output_dt: 0.5, dimensions: 2}")
    assert findings(quiet) == []


@pytest.mark.parametrize("block, key, words", [
    ("dimensionless: {Psi: 0.02, LoL: 2.0, x_C: -3.5, QkL: 0.45, RkL: 0.4}",
     "sphere_two_cables.dimensionless.x_C", ["|x_C| = 3.5 cable lengths", "reach only 3"]),
    ("dimensional: {flow_speed: 1, sphere_diameter: 1, net_buoyancy: 2000, cable_diameter: 0.02,"
     " cable_length: 100, cable_weight: 2, line_length: 200, anchor_x: -350}",
     "sphere_two_cables.dimensional.anchor_x", ["350 m apart", "reach only 300 m"]),
])
def test_sphere_anchors_out_of_reach(block, key, words):
    text = f"model: statics\nsphere_two_cables:\n  {block}\n"
    (problem,) = findings(text)
    assert (problem.key, problem.line, problem.severity) == (key, 3, "error")
    for word in words:
        assert word in problem.message


PITCH = (CASES / "pitch.yaml").read_text()


def test_pitch_resonance_is_an_error_without_damping():
    omega0 = 2 * 2 * math.pi / 10
    text = PITCH.replace("natural_frequency: 1.0", f"natural_frequency: {omega0!r}")
    (problem,) = findings(text)
    assert problem.key == "pitch.natural_frequency" and problem.severity == "error"
    assert "harmonic n = 2" in problem.message and "1.257 rad/s" in problem.message


def test_pitch_near_resonance_is_a_warning():
    text = PITCH.replace("natural_frequency: 1.0", "natural_frequency: 1.28")
    (problem,) = findings(text)
    assert problem.severity == "warning" and "amplified" in problem.message
    gain = 1 / abs(1 - (2 * 2 * math.pi / 10 / 1.28) ** 2)
    assert f"{gain:.3g} times" in problem.message


def test_stabilizer_without_moment():
    text = PITCH.replace("max_moment: 1.0e6", "max_moment: 0")
    (problem,) = findings(text)
    assert problem.key == "pitch.stabilizer.max_moment" and problem.severity == "warning"


def test_ignored_sections_warn():
    text = GOOD + (CASES / "pitch.yaml").read_text().split("model: pitch\n")[1]
    problem = next(p for p in findings(text) if p.key == "pitch")
    assert problem.severity == "warning" and "ignored by model 'lumped'" in problem.message


@pytest.mark.parametrize("period, depth, expected", [
    (8.0, None, 9.81 * 64 / (2 * math.pi)),
    (8.0, 5000.0, 9.81 * 64 / (2 * math.pi)),
    (20.0, 1.0, 20.0 * math.sqrt(9.81)),          # shallow water: c = sqrt(g h)
])
def test_wavelength(period, depth, expected):
    assert wavelength(period, 9.81, depth) == pytest.approx(expected, rel=2e-3)


def test_the_audits_body_below_the_seabed_fails_in_validate():
    """mooring_buoy_decay.yaml with its buoy 400 m below the 100 m seabed: refused by validate
    (the run used to fail later, as an element stretched by 1510 %)."""
    text = (EXAMPLES / "mooring_buoy_decay.yaml").read_text()
    text = edit("position: [12, 0, -2]", "position: [12, 0, -500]", text)
    errors = [p for p in findings(text) if p.severity == "error"]
    assert [(p.key, p.line) for p in errors] == [("bodies.buoy.position", line_with(text, "position: [12"))]
    assert "is 400 m below the seabed at z = -100 m (depth 100 m)" in errors[0].message


def test_a_surface_buoy_s_hull_lifts_its_mooring_before_it_is_said_to_sink():
    """WHOI Cable's bimoor buoy (examples/whoi/bimoor.yaml) weighs more than it displaces below its
    waterline (a negative net buoyancy) but floats on its hull, rho g A h above it: no warning that
    it sinks; a hull 1 cm high would not hold the lines and is warned."""
    import warnings

    from kanat.io import load_case

    path = EXAMPLES / "whoi" / "bimoor.yaml"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        case = load_case(path)
    assert not [w for w in caught if "will sink" in str(w.message)]
    buoy = next(name for name, body in case.bodies.items() if body.surface_buoy is not None)
    with pytest.warns(Warning, match="from its hull awash.*it will sink"):
        case.replace({f"bodies.{buoy}.surface_buoy.height": 0.01})
