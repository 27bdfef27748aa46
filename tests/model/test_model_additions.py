"""The case-format additions for moorings and real cable systems, as validated data.

Oracles: the numbers written in each case (read back unchanged), analytic geometry of a
plane (height, normal), exact derivatives (finite differences of the displacement give
the velocity), the rigid-body kinetic energy, and the error-message contract (file, line,
key path, what is valid).
"""
from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest
from pydantic import BaseModel

from kanat.errors import CaseError
from kanat.io import check_text, load_case, parse_case
from kanat.model import Body, Cable, Case, LineType, Point
from kanat.model.body import SIX_DOF_ONLY
from kanat.model.cable import Attachment, CableSection
from kanat.model.components import DEFAULT_MAX_STRAIN, ElasticLaw
from kanat.model.environment import Environment, Seabed
from kanat.model.operations import HarmonicMotion, VesselMotion, WinchStep
from kanat.physics.motion import (
    angular_velocity,
    compile_motion,
    motion_at,
    rigid_point_motion,
    rotation_matrix,
)
from kanat.physics.seabed import PlaneSeabed, seabed_of

from helpers import EXAMPLES


BASE = textwrap.dedent("""\
    name: additions
    model: lumped
    environment:
      depth: 100
    line_types:
      chain: {diameter: 0.1, mass: 150.0, axial_stiffness: 8.0e8}
      poly: {diameter: 0.16, mass: 16.0, axial_stiffness: 1.1e8}
    bodies:
      float1: {mass: 500, net_buoyancy: 20000}
    cables:
      - name: leg1
        from: anchor:[-800, 0, -100]
        to: vessel
        sections:
          - {line_type: chain, length: 500, segments: 50}
          - {line_type: poly, length: 380, segments: 38}
        attachments:
          - {body: float1, s: 300}
    simulation: {duration: 10, dt: 0.1}
    """)


def edit(old: str, new: str, text: str = BASE) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def errors(text: str) -> list:
    return [p for p in check_text(text, "case.yaml") if p.severity == "error"]


def schema_errors(text: str) -> list:
    """Validation errors only (not the support table's: no solver runs these keys yet)."""
    return [p for p in errors(text) if "does not support" not in p.message]


def line_of(text: str, needle: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


# --- every new field is documented ---------------------------------------------------------

NEW_FIELDS = [
    (Seabed, ["stiffness", "damping", "friction", "lateral_friction", "slope_deg"]),
    (Environment, ["seabed"]),
    (LineType, ["bending_stiffness", "max_strain", "added_mass_tangential"]),
    (Cable, ["line_type", "length", "segments", "sections", "attachments", "from_", "to"]),
    (CableSection, ["line_type", "length", "segments"]),
    (Attachment, ["body", "s"]),
    (HarmonicMotion, ["dof", "amplitude", "period", "phase_deg"]),
    (VesselMotion, ["harmonics", "table", "rows"]),
    (WinchStep, ["start", "duration", "rate"]),
    (Body, ["dof", *SIX_DOF_ONLY]),
    (Point, ["position", "mass", "volume", "drag_area", "added_mass", "force"]),
    (Case, ["winch"]),
]


@pytest.mark.parametrize("model, names", NEW_FIELDS, ids=[m.__name__ for m, _ in NEW_FIELDS])
def test_every_new_field_has_a_description(model: type[BaseModel], names):
    for name in names:
        assert len(model.model_fields[name].description or "") > 15, f"{model.__name__}.{name}"


# --- existing cases keep their meaning ----------------------------------------------------------

# The examples written after the additions, to show them; every other example predates them.
USING_ADDITIONS = {"lazy_wave.yaml", "mooring_3leg.yaml", "mooring_buoy_decay.yaml", "mooring_buoy_waves.yaml",
                   "subsurface_mooring.yaml", "surface_mooring_waves.yaml", "tow_payout_turn.yaml"}


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.yaml") if p.name not in USING_ADDITIONS))
def test_examples_use_none_of_the_additions(name):
    case = load_case(EXAMPLES / name)
    assert case.environment.seabed is None and case.winch == ()
    assert not case.vessel.motion.is_used
    for cable in case.cables:
        assert len(cable.sections) == 1 and cable.attachments == ()
        assert (cable.sections[0].line_type, cable.sections[0].length, cable.sections[0].segments) == (
            cable.line_type, cable.length, cable.segments)
        assert all(e.offset is None for e in cable.ends)
    assert all(b.dof == 3 for b in case.bodies.values())
    for line in case.line_types.values():
        assert (line.bending_stiffness, line.max_strain, line.added_mass_tangential) == (0.0, None, 0.0)


# --- seabed --------------------------------------------------------------------------------------

def test_seabed_defaults_and_values():
    case = Case.model_validate(__import__("yaml").safe_load(BASE))
    assert case.environment.seabed is None
    text = edit("  depth: 100\n", "  depth: 100\n  seabed: {friction: 0.6, slope_deg: 2.5}\n")
    seabed = Case.model_validate(__import__("yaml").safe_load(text)).environment.seabed
    assert (seabed.stiffness, seabed.damping, seabed.friction, seabed.lateral_friction,
            seabed.slope_deg) == (3.0e6, 3.0e5, 0.6, 0.0, 2.5)


def test_seabed_needs_depth_at_its_line():
    text = edit("  depth: 100\n", "  seabed: {stiffness: 1.0e6}\n")
    (problem,) = schema_errors(text)
    assert (problem.key, problem.line) == ("environment.seabed", 4)
    assert "needs environment.depth" in problem.message


@pytest.mark.parametrize("value, words", [("slope_deg: 60", "at most 45"),
                                          ("stiffness: -1", "greater than 0"),
                                          ("frictoin: 0.3", "did you mean 'friction'")])
def test_seabed_values_are_checked(value, words):
    text = edit("  depth: 100\n", f"  depth: 100\n  seabed: {{{value}}}\n")
    (problem,) = schema_errors(text)
    assert problem.line == 5 and words in problem.message


def test_plane_seabed_height_and_normal():
    bed = PlaneSeabed(100.0, 10.0)
    x = np.array([[-50.0, 0.0], [30.0, 200.0]])
    y = np.array([1.0, -7.0])
    z = bed.height(x, y)
    assert z.shape == (2, 2)
    assert z == pytest.approx(-100.0 + x * math.tan(math.radians(10.0)), rel=1e-15)
    n = bed.normal(x, y)
    assert n.shape == (2, 2, 3)
    assert np.linalg.norm(n, axis=-1) == pytest.approx(1.0)
    along = np.array([1.0, 0.0, math.tan(math.radians(10.0))])    # a line lying on the plane
    assert np.abs(n @ along).max() < 1e-15
    assert n[..., 2].min() > 0                                       # upward
    above = np.array([0.0, 0.0, -90.0])
    assert bed.penetration(above) == pytest.approx(-10.0 * math.cos(math.radians(10.0)))
    flat = seabed_of(Environment(depth=50.0))
    assert flat.height(3.0, 4.0) == -50.0 and flat.normal(0, 0).tolist() == [0.0, 0.0, 1.0]
    assert seabed_of(Environment()) is None
    with pytest.raises(ValueError, match="depth must be positive"):
        PlaneSeabed(0.0)


# --- line types --------------------------------------------------------------------------------

def test_bending_stiffness_and_strain_limit():
    line = LineType(diameter=0.1, mass=10, axial_stiffness=1e8)
    assert line.bending_stiffness == 0.0 and line.strain_limit() == DEFAULT_MAX_STRAIN == 0.1
    assert LineType(diameter=0.1, mass=10, axial_stiffness=1e8, max_strain=0.02).strain_limit() == 0.02
    table = ElasticLaw(table=[[0.01, 1e5], [0.05, 8e5], [0.12, 3e6]])
    assert LineType(diameter=0.1, mass=10, axial_stiffness=1e8, elastic_law=table).strain_limit() == 0.12
    poly = ElasticLaw(polynomial=[1e7, 5e7])
    assert LineType(diameter=0.1, mass=10, axial_stiffness=1e8, elastic_law=poly).strain_limit() == 0.1
    (problem,) = schema_errors(edit("axial_stiffness: 8.0e8}", "axial_stiffness: 8.0e8, "
                                    "bending_stiffness: -5}"))
    assert problem.key == "line_types.chain.bending_stiffness" and problem.line == 6
    assert "at least 0" in problem.message and "N m^2" in problem.message


# --- sections and attachments --------------------------------------------------------------------

def test_sections_give_totals_and_single_type_cables_one_section():
    case = Case.model_validate(__import__("yaml").safe_load(BASE))
    leg = case.cables[0]
    assert (leg.line_type, leg.length, leg.segments) == ("chain", 880.0, 88)
    assert leg.line_types == ("chain", "poly")
    assert leg.section_bounds() == [(0.0, 500.0), (500.0, 880.0)]
    single = Cable.model_validate({"name": "a", "line_type": "chain", "length": 10, "segments": 2,
                                   "from": "vessel", "to": "free"})
    assert single.sections == (CableSection(line_type="chain", length=10, segments=2),)
    assert single.model_dump(exclude_unset=True, by_alias=True).keys() == {
        "name", "line_type", "length", "segments", "from", "to"}
    assert "line_type" not in leg.model_dump(exclude_unset=True)


@pytest.mark.parametrize("cable", ["leg", "single"])
def test_cables_round_trip_through_full_and_written_dumps(cable):
    case = Case.model_validate(__import__("yaml").safe_load(BASE))
    if cable == "single":
        case = load_case(EXAMPLES / "mooring_current.yaml")
    assert Case.model_validate_json(case.model_dump_json(by_alias=True)) == case
    assert Case.model_validate(case.model_dump(by_alias=True, exclude_unset=True)) == case


def test_both_forms_is_an_error_at_the_cable():
    text = edit("    from: anchor:[-800", "    length: 900\n    from: anchor:[-800")
    (problem,) = schema_errors(text)
    assert problem.key == "cables[0]" and problem.line == line_of(text, "name: leg1")
    assert "give either sections or line_type, length and segments, not both" in problem.message
    assert "length 900 differs from the sections' total 880.0" in problem.message


def test_section_line_type_is_checked_with_suggestion_and_line():
    text = edit("{line_type: poly,", "{line_type: polly,")
    (problem,) = schema_errors(text)
    assert problem.key == "cables[0].sections[1].line_type"
    assert problem.line == line_of(text, "polly")
    assert "'polly' is not a line type; known: chain, poly (did you mean 'poly'?)" in problem.message


def test_missing_form_and_empty_sections():
    text = edit("    sections:\n      - {line_type: chain, length: 500, segments: 50}\n"
                "      - {line_type: poly, length: 380, segments: 38}\n", "")
    found = {p.message for p in schema_errors(text)}
    assert {"missing required key 'line_type'", "missing required key 'length' [m]",
            "missing required key 'segments'"} <= found
    empty = edit("    sections:\n      - {line_type: chain, length: 500, segments: 50}\n"
                 "      - {line_type: poly, length: 380, segments: 38}\n", "    sections: []\n")
    (problem,) = schema_errors(empty)
    assert "sections is empty" in problem.message


@pytest.mark.parametrize("old, new, key, words", [
    ("{body: float1, s: 300}", "{body: flaot1, s: 300}", "cables[0].attachments[0].body",
     "'flaot1' is not a body; known: float1 (did you mean 'float1'?)"),
    ("{body: float1, s: 300}", "{body: float1, s: 900}", "cables[0]",
     "attachments[0].s = 900 m is beyond the cable's length 880 m"),
    ("{body: float1, s: 300}", "{body: float1, s: -1}", "cables[0].attachments[0].s",
     "must be at least 0"),
])
def test_attachments_are_checked(old, new, key, words):
    text = edit(old, new)
    (problem,) = schema_errors(text)
    assert problem.key == key and words in problem.message
    assert problem.line in (line_of(text, new.split(",")[0]), line_of(text, "name: leg1"))


def test_attachments_in_order_and_python_construction_checks_references():
    with pytest.raises(ValueError, match="'ghost' is not a body"):
        Case(model="statics", line_types={"c": LineType(diameter=0.1, mass=1, axial_stiffness=1e6)},
             cables=[{"name": "a", "line_type": "c", "length": 10, "segments": 2, "from": "vessel",
                      "to": "free", "attachments": [{"body": "ghost", "s": 5}]}])
    with pytest.raises(ValueError, match="in order of s"):
        Cable.model_validate({"name": "a", "line_type": "c", "length": 10, "segments": 2,
                              "from": "vessel", "to": "free",
                              "attachments": [{"body": "x", "s": 5}, {"body": "y", "s": 1}]})


# --- fairleads ------------------------------------------------------------------------------------

@pytest.mark.parametrize("written, kind, name, offset", [
    ({"body": "buoy", "offset": [1, 2, -3]}, "body", "buoy", (1.0, 2.0, -3.0)),
    ({"vessel": [20, 0, -8]}, "vessel", None, (20.0, 0.0, -8.0)),
    ("vessel:[20, 0, -8]", "vessel", None, (20.0, 0.0, -8.0)),
    ("vessel", "vessel", None, None),
])
def test_fairlead_end_forms(written, kind, name, offset):
    cable = Cable.model_validate({"name": "a", "line_type": "c", "length": 10, "segments": 2,
                                  "from": "anchor:[0, 0, -100]", "to": written})
    assert (cable.to.kind, cable.to.name, cable.to.offset) == (kind, name, offset)
    assert cable.to.is_fairlead == (offset is not None)


def test_fairlead_errors():
    text = edit("    to: vessel\n", "    to: {body: flaot1, offset: [0, 0, -1]}\n")
    (problem,) = schema_errors(text)
    assert problem.key == "cables[0].to" and problem.line == line_of(text, "flaot1")
    assert "'flaot1' is not a body; known bodies: float1 (did you mean 'float1'?)" in problem.message
    with pytest.raises(ValueError, match="offset places a fairlead on a body or the vessel"):
        Cable.model_validate({"name": "a", "line_type": "c", "length": 10, "segments": 2,
                              "from": {"kind": "anchor", "position": [0, 0, 0], "offset": [1, 0, 0]},
                              "to": "vessel"})
    two = Cable.model_validate({"name": "bridle", "line_type": "c", "length": 10, "segments": 2,
                                "from": {"body": "b", "offset": [1, 0, 0]},
                                "to": {"body": "b", "offset": [-1, 0, 0]}})
    assert two.from_.name == two.to.name == "b"


# --- vessel motion ---------------------------------------------------------------------------------

MOTION = edit("    sections:", "    sections:", BASE).replace(
    "simulation:", "vessel:\n  motion:\n    - {dof: surge, amplitude: 10.0, period: 27.0}\n"
    "    - {dof: pitch, amplitude: 3.0, period: 9.0, phase_deg: 90}\nsimulation:")


def test_harmonic_motion_is_read_and_evaluated():
    case = Case.model_validate(__import__("yaml").safe_load(MOTION))
    harmonics = case.vessel.motion.harmonics
    assert [(h.dof, h.amplitude, h.period, h.phase_deg) for h in harmonics] == [
        ("surge", 10.0, 27.0, 0.0), ("pitch", 3.0, 9.0, 90.0)]
    motion = compile_motion(case.vessel.motion)
    for t in (0.0, 4.0, 13.3):
        q, v = motion_at(motion, t)
        assert q[0] == pytest.approx(10.0 * math.sin(2 * math.pi * t / 27.0), abs=1e-12)
        assert q[4] == pytest.approx(math.radians(3.0) * math.sin(2 * math.pi * t / 9.0 + math.pi / 2))
        h = 1e-6                                                      # velocity = dq/dt
        dq = (motion_at(motion, t + h)[0] - motion_at(motion, t - h)[0]) / (2 * h)
        assert v == pytest.approx(dq, abs=1e-8)
        assert q[[1, 2, 3, 5]].tolist() == [0.0] * 4


def test_motion_dof_error_suggests():
    text = MOTION.replace("dof: pitch", "dof: ptch")
    (problem,) = schema_errors(text)
    assert problem.key == "vessel.motion[1].dof" and problem.line == line_of(text, "ptch")
    assert "(did you mean 'pitch'?)" in problem.message


def test_motion_table_is_read_next_to_the_case(tmp_path):
    (tmp_path / "motion.csv").write_text("# a test table\ntime, surge (m), heave [m], yaw\n"
                                         "0, 0, 0, 0\n10, 2.0, -1.0, 4.0\n20, 0, 0, 0\n")
    case_file = tmp_path / "case.yaml"
    case_file.write_text(BASE.replace("simulation:", "vessel:\n  motion: {table: motion.csv}\nsimulation:"))
    problems = [p for p in check_text(case_file.read_text(), str(case_file))
                if "does not support" not in p.message and p.severity == "error"]
    assert problems == []
    from kanat.io.case_source import read_document
    from kanat.model.validation import validate_data

    doc = read_document(case_file.read_text(), str(case_file))
    case, found = validate_data(doc.data, str(case_file), doc.lines)
    assert found == [] and case.vessel.motion.table == "motion.csv"
    assert case.vessel.motion.rows == ((0.0,) * 7, (10.0, 2.0, 0.0, -1.0, 0.0, 0.0, 4.0), (20.0,) + (0.0,) * 6)
    q, v = motion_at(compile_motion(case.vessel.motion), 5.0)
    assert q.tolist() == pytest.approx([1.0, 0.0, -0.5, 0.0, 0.0, math.radians(2.0)])
    assert v.tolist() == pytest.approx([0.2, 0.0, -0.1, 0.0, 0.0, math.radians(0.4)])
    assert motion_at(compile_motion(case.vessel.motion), 30.0)[1].tolist() == [0.0] * 6


@pytest.mark.parametrize("content, words", [
    (None, "cannot read the motion table 'motion.csv'"),
    ("time, surge, swey\n0, 0, 0\n1, 1, 1\n", "unknown column 'swey' (did you mean 'sway'?)"),
    ("surge, sway\n0, 0\n1, 1\n", "needs a 'time' column"),
    ("time, surge\n0, 0\n1, abc\n", "motion.csv, line 3, column surge: 'abc' is not a number"),
])
def test_motion_table_errors_name_the_key_and_line(tmp_path, content, words):
    if content is not None:
        (tmp_path / "motion.csv").write_text(content)
    text = BASE.replace("simulation:", "vessel:\n  motion: {table: motion.csv}\nsimulation:")
    (problem,) = [p for p in errors_at(text, tmp_path) if p.key.startswith("vessel")]
    assert problem.key == "vessel.motion.table" and problem.line == line_of(text, "motion.csv")
    assert words in problem.message


SECRET = "root:x:0:0:root:/root:/bin/bash"


@pytest.mark.parametrize("name, content, words", [
    ("passwd", SECRET + "\n", "'passwd' is not a .csv file; a motion table is a CSV file (motion.csv)"),
    ("passwd.csv", SECRET + "\n", "passwd.csv: its first row is not a header of column names (column 1"),
    ("image.csv", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "image.csv: not a text file (it is not UTF-8)"),
    ("nul.csv", "time, surge\n0, 1\x00\n", "'1\\x00' is not a number"),
    ("folder.csv", None, "folder.csv: not a regular file"),
])
def test_a_motion_table_must_be_a_csv_of_the_columns_and_is_not_echoed(tmp_path, name, content, words):
    target = tmp_path / name
    if content is None:
        target.mkdir()
    else:
        (target.write_bytes if isinstance(content, bytes) else target.write_text)(content)
    text = BASE.replace("simulation:", f"vessel:\n  motion: {{table: {name}}}\nsimulation:")
    (problem,) = [p for p in errors_at(text, tmp_path) if p.key.startswith("vessel")]
    assert problem.key == "vessel.motion.table" and problem.line == line_of(text, name)
    assert words in problem.message
    assert "root:" not in problem.message and "PNG" not in problem.message


def errors_at(text: str, folder: Path) -> list:
    path = folder / "case.yaml"
    path.write_text(text)
    return [p for p in check_text(text, str(path)) if p.severity == "error"]


def test_motion_rows_must_increase_and_forms_exclude_each_other():
    with pytest.raises(ValueError, match="time must increase"):
        VesselMotion(rows=[[0, 0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0]])
    with pytest.raises(ValueError, match="either harmonics"):
        VesselMotion(harmonics=[{"dof": "heave", "amplitude": 1, "period": 5}],
                     rows=[[0] * 7, [1] + [0] * 6])
    with pytest.raises(ValueError, match="was not read"):
        VesselMotion(table="m.csv")


def test_rigid_point_motion_matches_finite_differences():
    rng = np.random.default_rng(3)
    offsets = rng.normal(size=(4, 3)) * 20
    motion = compile_motion(VesselMotion.model_validate([
        {"dof": d, "amplitude": a, "period": p, "phase_deg": f} for d, a, p, f in
        [("surge", 3, 20, 0), ("sway", 1, 13, 40), ("heave", 2, 9, 10),
         ("roll", 5, 11, 0), ("pitch", 4, 8, 70), ("yaw", 6, 30, 20)]]))
    for t in (0.0, 3.7):
        q, v = motion_at(motion, t)
        d, u = rigid_point_motion(offsets, q, v)
        h = 1e-6
        dp = (rigid_point_motion(offsets, *motion_at(motion, t + h))[0]
              - rigid_point_motion(offsets, *motion_at(motion, t - h))[0]) / (2 * h)
        assert u == pytest.approx(dp, abs=1e-7)
        rot = rotation_matrix(*q[3:])
        assert rot @ rot.T == pytest.approx(np.eye(3), abs=1e-15)
        assert d == pytest.approx(q[:3] + offsets @ rot.T - offsets, abs=1e-12)


def test_rotation_conventions_are_right_handed():
    bow = np.array([1.0, 0.0, 0.0])
    assert rotation_matrix(0, math.radians(10), 0) @ bow == pytest.approx(
        [math.cos(math.radians(10)), 0, -math.sin(math.radians(10))])       # pitch: bow down
    assert (rotation_matrix(math.radians(10), 0, 0) @ [0, 1, 0])[2] > 0    # roll: port up
    assert (rotation_matrix(0, 0, math.radians(10)) @ bow)[1] > 0          # yaw: bow to port
    angles, rates = np.array([0.3, -0.2, 1.1]), np.array([0.05, 0.02, -0.03])
    h = 1e-7
    dr = (rotation_matrix(*(angles + h * rates)) - rotation_matrix(*(angles - h * rates))) / (2 * h)
    w = angular_velocity(angles, rates)
    skew = dr @ rotation_matrix(*angles).T
    assert [skew[2, 1], skew[0, 2], skew[1, 0]] == pytest.approx(w, abs=1e-8)


# --- winch ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("steps, words", [
    ("[{start: 10, duration: 20, rate: 1}, {start: 20, duration: 5, rate: -1}]",
     "step 1 starts at 20 s, before step 0 ends at 30 s"),
    ("[{start: 0, duration: 100, rate: -9}]", "hauls in 900 m of cable 'leg1', which is only 880 m long"),
    ("[{start: 0, duration: 0, rate: 1}]", "must be greater than 0"),
])
def test_winch_steps_are_checked(steps, words):
    text = BASE + f"winch: {steps}\n"
    (problem,) = schema_errors(text)
    assert problem.key.startswith("winch") and words in problem.message
    assert problem.line == line_of(text, "winch:")


def test_winch_values():
    case = Case.model_validate(__import__("yaml").safe_load(
        BASE + "winch: [{start: 100, duration: 60, rate: 1.0}, {start: 200, duration: 10, rate: -2}]\n"))
    assert [(w.start, w.end, w.change) for w in case.winch] == [(100, 160, 60), (200, 210, -20)]


# --- bodies with six degrees of freedom -----------------------------------------------------------

def rigid(**extra):
    return Body(mass=2000.0, net_buoyancy=5000.0, dof=6, inertia=[800, 900, 1200],
                center_of_gravity=[0.2, -0.1, -0.5], **extra)


def test_rigid_body_mass_matrix_gives_the_kinetic_energy():
    body = rigid()
    m = body.rigid_body_mass_matrix()
    rng = np.random.default_rng(1)
    c, inertia = np.array(body.center_of_gravity), np.diag([800.0, 900.0, 1200.0])
    for _ in range(3):
        v, w = rng.normal(size=3), rng.normal(size=3)
        energy = 0.5 * body.mass * np.sum((v + np.cross(w, c)) ** 2) + 0.5 * w @ inertia @ w
        assert 0.5 * np.concatenate([v, w]) @ m @ np.concatenate([v, w]) == pytest.approx(energy, rel=1e-12)
    assert m == pytest.approx(m.T)


def test_hydrostatics_from_the_waterplane():
    body = rigid(waterplane_area=12.0, metacentric_heights=[1.5, 2.0])
    k = body.hydrostatic_stiffness_matrix(1025.0, 9.81)
    buoyancy = 5000.0 + 2000.0 * 9.81
    assert (k[2, 2], k[3, 3], k[4, 4]) == pytest.approx((1025 * 9.81 * 12.0, buoyancy * 1.5, buoyancy * 2.0))
    assert np.count_nonzero(k) == 3
    given = rigid(hydrostatic_stiffness=[0, 0, 1e5, 2e6, 3e6, 0])
    assert given.hydrostatic_stiffness_matrix(1025, 9.81)[3, 3] == 2e6


@pytest.mark.parametrize("keys, words", [
    ({"dof": 3, "inertia": [1, 1, 1]}, "inertia is for rigid bodies: add dof: 6"),
    ({"dof": 6}, "needs its inertia"),
    ({"dof": 6, "inertia": [1, -1, 1]}, "must not be negative"),
    ({"dof": 6, "inertia": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}, "inertia must be symmetric"),
    ({"dof": 6, "inertia": [1, 1, 1], "waterplane_area": 3.0}, "together"),
    ({"dof": 6, "inertia": [1, 1, 1], "drag_area": 2.0}, "drag_areas (6 values)"),
    ({"dof": 6, "inertia": [1, 1, 1], "linear_damping": [1, 1, -1, 0, 0, 0]}, "must not be negative"),
    ({"dof": 6, "inertia": [1, 1, 1], "added_mass_matrix": [1, 2, 3]}, "6 numbers (a diagonal)"),
])
def test_rigid_body_rules(keys, words):
    with pytest.raises(ValueError) as info:
        Body.model_validate({"mass": 10, "net_buoyancy": 0, **keys})
    assert words in str(info.value)


def test_rigid_body_errors_in_a_case_name_the_body_and_line():
    text = BASE.replace("float1: {mass: 500, net_buoyancy: 20000}",
                        "float1: {mass: 500, net_buoyancy: 20000, dof: 6, inertia: [10, 10]}")
    (problem,) = schema_errors(text)
    assert problem.key == "bodies.float1.inertia" and problem.line == line_of(text, "float1:")
    assert "3 numbers (a diagonal) or 3 rows of 3" in problem.message


# --- points ---------------------------------------------------------------------------------------

def test_point_properties():
    point = Point(mass=4000, volume=0.5, drag_area=1.0, added_mass=512.5, force=[0, 0, -100])
    assert point.net_buoyancy(1025.0, 9.81) == pytest.approx((1025 * 0.5 - 4000) * 9.81)
    with pytest.raises(ValueError, match="greater than or equal to 0"):
        Point(volume=-1)


def test_case_error_lists_every_problem_of_the_additions():
    text = edit("{body: float1, s: 300}", "{body: flaot1, s: 300}",
                edit("{line_type: poly,", "{line_type: polly,"))
    with pytest.raises(CaseError) as info:
        parse_case(text, "case.yaml")
    keys = [p.key for p in info.value.problems]
    assert "cables[0].sections[1].line_type" in keys and "cables[0].attachments[0].body" in keys
