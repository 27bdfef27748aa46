"""MoorDyn input files (v1 and v2) as kanat cases, and ``kanat import``.

Oracles: the numbers written in the MoorDyn files and MoorDyn's documented conventions
(recomputed here by hand), the same system written in v1 and v2, the YAML written by
``kanat import`` read back, and -- when the ``moordyn`` package is installed -- MoorDyn
itself reading the same files (node counts, lengths, end positions, node weights, point
and body masses, line damping).
"""
from __future__ import annotations

import math
import os
import re
import tempfile
import textwrap
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from kanat.cli_import import register
from kanat.io import check_case, check_text
from kanat.model.validation import validate_data
from kanat.io.moordyn import case_yaml, looks_like_moordyn, read_moordyn
from kanat.io.yaml_loader import load_yaml
from kanat.physics.motion import rotation_matrix

from helpers import ROOT

FOLDER = ROOT / "examples" / "moordyn"
EXAMPLES = sorted(p.name for p in FOLDER.glob("*.dat"))
RHO, G = 1025.0, 9.81


def imported(name: str):
    path = FOLDER / name
    return read_moordyn(path.read_text(), str(path))


def case_of(text: str, file: str = "test.dat"):
    """The validated case of a MoorDyn text (schema only: no solver runs these cases yet)."""
    result = read_moordyn(text, file)
    assert result.data is not None, [str(p) for p in result.problems]
    case, problems = validate_data(result.data, file, result.lines)
    assert problems == [], [str(p) for p in problems]
    return case, result


def errors_of(text: str) -> list:
    return [p for p in read_moordyn(text, "bad.dat").problems if p.severity == "error"]


V2 = textwrap.dedent("""\
    test file
    ---------------------- LINE TYPES ----------------------
    TypeName  Diam   Mass/m  EA      BA/-zeta  EI    Cd    Ca    CdAx  CaAx
    (name)    (m)    (kg/m)  (N)     (N-s/-)   (N-m^2) (-) (-)   (-)   (-)
    wire      0.05   12.0    2.0e8   1.5e5     40.0  1.2   0.9   0.05  0.1
    ---------------------- POINTS --------------------------
    ID  Attachment  X      Y     Z      Mass  Volume  CdA  Ca
    (#) (word)      (m)    (m)   (m)    (kg)  (m^3)   (m^2) (-)
    1   Fixed       -300   10    -80    0     0       0    0
    2   Free        -100   0     -40    150   0.4     0.6  0.7
    3   Coupled     4      -2    -6     0     0       0    0
    ---------------------- LINES ---------------------------
    ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
    (#) (name)    (#)      (#)      (m)       (-)      (-)
    1   wire      1        2        210       21       -
    2   wire      2        3        110       11       -
    ---------------------- OPTIONS -------------------------
    80        WtrDpth
    1020      rho
    9.8       g
    ---------------------- need this line ------------------
    """)


# --- the example files -----------------------------------------------------------------------------

@pytest.mark.parametrize("name", EXAMPLES)
def test_examples_import_validate_and_round_trip_through_yaml(name, tmp_path):
    result = imported(name)
    assert result.data is not None and not [p for p in result.problems if p.severity == "error"]
    case, problems = validate_data(result.data, name, result.lines)
    assert problems == []
    text = case_yaml(result, name)
    assert text.startswith(f"# Imported from {name} (MoorDyn v{result.version}) by kanat import.")
    again, problems = validate_data(load_yaml(text).data)
    assert problems == [] and again == case
    assert [c.name for c in case.cables] == [f"line{k + 1}" for k in range(_line_rows(FOLDER / name))]


def _line_rows(path) -> int:
    """The rows of the LINES (v2) or LINE PROPERTIES (v1) table of a MoorDyn file."""
    rows, inside = 0, False
    for line in path.read_text().splitlines():
        if line.lstrip().startswith("--"):
            title = " ".join(line.upper().replace("-", " ").split())
            inside = title in ("LINES", "LINE PROPERTIES")
        elif inside and line.split() and line.split()[0].isdigit():
            rows += 1
    return rows


def test_spread_mooring_numbers():
    case, result = case_of((FOLDER / "buoy_spread_mooring.dat").read_text())
    chain = case.line_types["chain76"]
    area = math.pi * 0.137**2 / 4
    assert (chain.diameter, chain.mass, chain.axial_stiffness) == (0.137, 115.0, 4.93e8)
    assert (chain.drag_normal, chain.drag_tangential) == (1.33, 0.64)
    assert chain.added_mass == pytest.approx(1.0 * 1025 * area, rel=1e-15)
    assert chain.added_mass_tangential == pytest.approx(0.5 * 1025 * area, rel=1e-15)
    # BA = -0.8 is a damping ratio: 0.8 (L/N) sqrt(EA m) with L/N = 640/32 m (MoorDyn's rule)
    assert chain.axial_damping == pytest.approx(0.8 * 20.0 * math.sqrt(4.93e8 * 115.0), rel=1e-14)
    assert chain.weight_in_water_value(1025.0, 9.81) == pytest.approx((115.0 - 1025 * area) * 9.81)
    buoy = case.bodies["body1"]
    assert (buoy.dof, buoy.mass, buoy.position, buoy.center_of_gravity) == (6, 45100.0, (0, 0, -2.0), (0, 0, -0.5))
    assert buoy.net_buoyancy == pytest.approx((1025 * 100.0 - 45100.0) * 9.81)
    assert np.diag(buoy.inertia).tolist() == [1.2e5, 1.2e5, 2.0e5]
    assert buoy.drag_areas == (20, 20, 20, 10, 10, 10)
    assert np.diag(buoy.added_mass_matrix).tolist() == [0.8 * 1025 * 100] * 3 + [0.0] * 3
    assert [c.to.offset for c in case.cables] == [(3, 0, -3), (-1.5, 2.598, -3), (-1.5, -2.598, -3)]
    assert case.cables[1].from_.position == (-300.0, 519.615, -120.0)
    env, sim = case.environment, case.simulation
    assert (env.depth, env.seabed.stiffness, env.seabed.damping, env.gravity) == (120, 3e6, 3e5, 9.81)
    assert (case.model, sim.duration, sim.dt, sim.output_dt) == ("lumped", 600, None, 0.5)   # dtM: reported
    notes = {p.key for p in result.problems}
    assert notes == {"OPTIONS.dtIC", "OPTIONS.TmaxIC", "OPTIONS.dtM", "OUTPUTS", "BODIES 1.CG"}   # the CG: buoyancy_at stated
    assert buoy.buoyancy_at == "cg" and buoy.buoyancy_point == buoy.center_of_gravity


def test_clump_and_float_numbers():
    case, result = case_of((FOLDER / "clump_and_float.dat").read_text())
    clump, float_ = case.points["point2"], case.points["point3"]
    assert (clump.mass, clump.volume, clump.drag_area, clump.position) == (4000, 0.5, 1.0, (-600, 0, -140))
    assert clump.added_mass == pytest.approx(1.0 * 1025 * 0.5)
    assert float_.added_mass == pytest.approx(0.8 * 1025 * 8.0)
    assert float_.net_buoyancy(1025, 9.80665) == pytest.approx((1025 * 8 - 2500) * 9.80665)
    assert [(c.from_.kind, c.to.kind) for c in case.cables] == [("anchor", "point"), ("point", "point"),
                                                                 ("point", "vessel")]
    assert case.cables[2].to.offset == (-5.0, 0.0, -10.0)
    assert case.line_types["polyester"].axial_damping == 2.0e6
    assert (case.environment.seabed.friction, case.environment.seabed.lateral_friction) == (0.3, 0.3)
    assert case.model == "statics" and case.simulation is None
    assert [p.key for p in result.problems] == ["OPTIONS.dtM"]


def test_the_v1_file_is_the_same_system_as_its_v2_twin():
    v1, _ = case_of((FOLDER / "three_leg_vessel_v1.dat").read_text())
    twin = (FOLDER / "three_leg_vessel_v1.dat").read_text()
    twin = twin.replace("LINE DICTIONARY", "LINE TYPES").replace(
        "chain76   0.137   115.0         4.93e8    -0.8      1.0   0.5   1.33   0.64",
        "chain76   0.137   115.0  4.93e8  -0.8  0  1.33  1.0  0.64  0.5")
    rows = re.findall(r"^(\d)\s+(Fixed|Vessel)\s+(\S+)\s+(\S+)\s+(\S+)\s.*$", twin, re.M)
    points = "\n".join(f"{i} {'Coupled' if k == 'Vessel' else k} {x} {y} {z} 0 0 0 0" for i, k, x, y, z in rows)
    twin = re.sub(r"(NODE PROPERTIES[^\n]*\n[^\n]*\n[^\n]*\n)(.*?)(-{5})", lambda m: m[1] + points + "\n" + m[3],
                  twin, flags=re.S).replace("NODE PROPERTIES", "POINTS")
    twin = re.sub(r"^(\d)\s+chain76\s+620.0\s+31\s+(\d)\s+(\d)\s+p$", r"\1 chain76 \2 \3 620.0 31 p", twin,
                  flags=re.M)
    v2, result = case_of(twin)
    assert result.version == 2
    assert v2.model_copy(update={"name": v1.name}) == v1
    assert v1.line_types["chain76"].added_mass_tangential == pytest.approx(0.5 * 1025 * math.pi * 0.137**2 / 4)


# --- every construct the importer accepts -----------------------------------------------------------

def test_v2_constructs():
    case, result = case_of(V2)
    wire = case.line_types["wire"]
    area = math.pi * 0.05**2 / 4
    assert (wire.axial_damping, wire.bending_stiffness, wire.drag_tangential) == (1.5e5, 40.0, 0.05)
    assert wire.added_mass == pytest.approx(0.9 * 1020 * area)
    assert case.environment.water_density == 1020 and case.environment.gravity == 9.8
    assert case.environment.seabed.stiffness == 3.0e6 and case.environment.seabed.damping == 3.0e5
    assert str(case.cables[0].from_) == "anchor:[-300, 10, -80]"
    assert case.cables[0].to.name == "point2" and case.cables[1].to.offset == (4, -2, -6)
    assert case.points["point2"].added_mass == pytest.approx(0.7 * 1020 * 0.4)
    assert result.problems == []


def test_negative_length_is_a_multiple_of_the_end_distance():
    text = V2.replace("1   wire      1        2        210", "1   wire      1        2        -1.1")
    case, result = case_of(text)
    chord = math.dist((-300, 10, -80), (-100, 0, -40))
    assert case.cables[0].length == pytest.approx(1.1 * chord)
    assert [p.key for p in result.problems] == ["LINES 1.UnstrLen"]


def test_damping_ratio_of_lines_with_different_segments_gives_each_line_its_type():
    text = V2.replace("1.5e5     40.0", "-0.5      40.0")
    case, result = case_of(text)
    for cable, segment in zip(case.cables, (210 / 21, 110 / 11)):
        assert cable.line_type == "wire"                              # both 10 m segments: one type
        assert case.line_types["wire"].axial_damping == pytest.approx(0.5 * segment * math.sqrt(2e8 * 12))
    text = text.replace("110       11", "110       22")
    case, result = case_of(text)
    assert [c.line_type for c in case.cables] == ["wire_line1", "wire_line2"]
    assert case.line_types["wire_line2"].axial_damping == pytest.approx(0.5 * 5.0 * math.sqrt(2e8 * 12))
    assert "LINE TYPES wire.BA" in [p.key for p in result.problems]


BODIES = textwrap.dedent("""\
    ---------------------- BODIES ----------------------
    ID  Attachment  X0   Y0   Z0   r0   p0   y0   Mass   CG      I          Volume  CdA       Ca
    (#) (word)      (m)  (m)  (m)  (deg) (deg) (deg) (kg) (m)    (kg-m^2)   (m^3)   (m^2)     (-)
    1   Coupled     10   5    0    0    0    30   0      0       0          0       0         0
    2   Fixed       -50  0    -80  0    20   0    0      0       0          0       0         0
    3   Free        0    40   -10  2    3    4    800    0.1|0|-0.3 500     2.0     1|2|3     0.5|0.6|0.7
    """)


def test_bodies_coupled_fixed_and_free():
    text = V2.replace("---------------------- POINTS", BODIES + "---------------------- POINTS").replace(
        "3   Coupled     4      -2    -6", "3   Body1       4      -2    -6").replace(
        "1   Fixed       -300   10    -80", "1   Body2       3      0     1").replace(
        "2   Free        -100   0     -40    150   0.4     0.6  0.7", "2   Body3  1 0 0  0 0 0 0")
    case, result = case_of(text)
    vessel_end = np.array([10, 5, 0]) + rotation_matrix(0, 0, math.radians(30)) @ [4, -2, -6]
    anchor = np.array([-50, 0, -80]) + rotation_matrix(0, math.radians(20), 0) @ [3, 0, 1]
    assert case.cables[1].to.kind == "vessel" and case.cables[1].to.offset == pytest.approx(vessel_end)
    assert case.cables[0].from_.kind == "anchor" and case.cables[0].from_.position == pytest.approx(anchor)
    assert (case.cables[0].to.name, case.cables[0].to.offset) == ("body3", (1, 0, 0))
    body = case.bodies["body3"]
    assert list(case.bodies) == ["body3"] and body.orientation_deg == (2, 3, 4)
    assert body.center_of_gravity == (0.1, 0, -0.3) and np.diag(body.inertia).tolist() == [500] * 3
    assert body.drag_areas == (1, 2, 3, 1, 2, 3)
    assert np.diag(body.added_mass_matrix) == pytest.approx([1020 * 2 * c for c in (0.5, 0.6, 0.7)] + [0] * 3)
    assert body.net_buoyancy == pytest.approx((1020 * 2 - 800) * 9.8)


@pytest.mark.parametrize("cda, expected", [("4", [4] * 6), ("4|5", [4, 4, 4, 5, 5, 5]),
                                           ("1|2|3|4|5|6", [1, 2, 3, 4, 5, 6])])
def test_body_drag_area_forms(cda, expected):
    text = V2.replace("---------------------- POINTS", BODIES.replace("1|2|3     0.5|0.6|0.7",
                      f"{cda}  0.5") + "---------------------- POINTS").replace(
        "2   Free        -100   0     -40    150   0.4     0.6  0.7", "2   Body3  1 0 0  0 0 0 0")
    case, _ = case_of(text)
    assert list(case.bodies["body3"].drag_areas) == expected
    assert np.diag(case.bodies["body3"].added_mass_matrix)[:3] == pytest.approx([1020 * 2 * 0.5] * 3)


def test_options_and_simulation():
    text = V2.replace("80        WtrDpth\n1020      rho\n9.8       g\n", textwrap.dedent("""\
        80        WaterDepth
        1030      WtrDnsty
        9.80665   gravity
        2.5e6     kb
        1.0e5     cb
        0.4       MU_KA
        0.7       MU_KT
        0.001     dtM
        300       TMax
        0         dtOut
        RK4       tScheme
        7         mystery
        0         WaveKin
        0.001     TmaxIC
        """))
    case, result = case_of(text)
    env, seabed = case.environment, case.environment.seabed
    assert (env.depth, env.water_density, env.gravity) == (80, 1030, 9.80665)
    assert (seabed.stiffness, seabed.damping, seabed.friction, seabed.lateral_friction) == (2.5e6, 1e5, 0.4, 0.7)
    assert (case.model, case.simulation.duration, case.simulation.dt, case.simulation.output_dt) == (
        "lumped", 300, None, None)
    messages = {p.key: p.message for p in result.problems}
    assert "MoorDyn's step for its own scheme (0.001 s) is not imported" in messages["OPTIONS.dtM"]
    assert "solver setting" in messages["OPTIONS.tScheme"]
    assert "unknown MoorDyn option 'mystery'" in messages["OPTIONS.mystery"]
    assert "simulation.initial_state: as_given" in messages["OPTIONS.TmaxIC"]      # no settling in MoorDyn
    assert case.simulation.initial_state == "equilibrium"
    assert all(p.severity == "warning" for p in result.problems)


def test_v1_point_forces_and_connect_points():
    text = (FOLDER / "three_leg_vessel_v1.dat").read_text().replace(
        "4     Vessel    20.0     0.0         -8.0    0     0     0     0     0",
        "4     Connect   20.0     0.0         -8.0    50    0.1   10    0     -20")
    case, _ = case_of(text)
    point = case.points["point4"]
    assert (point.mass, point.volume, point.force, point.position) == (50, 0.1, (10, 0, -20), (20, 0, -8))


# --- what cannot be imported is an error at its row -------------------------------------------------

@pytest.mark.parametrize("old, new, key, words", [
    ("0.9   0.05  0.1\n", "0.9   0.05  0.1  0.8\n", "LINE TYPES wire.Cl", "vortex-induced vibration"),
    ("2.0e8   1.5e5", "poly.dat   1.5e5", "LINE TYPES wire.EA", "'poly.dat' is not a number"),
    ("2   wire      2        3", "2   wire      2        R1A", "LINES 2.AttachB", "rod ends cannot be imported"),
    ("2   wire      2        3", "2   wire      2        7", "LINES 2.AttachB", "there is no point 7"),
    ("2   wire      2        3", "2   wyre      2        3", "LINES 2.LineType", "'wyre' is not in LINE TYPES"),
    ("3   Coupled", "3   Turbine1", "POINTS 3.Attachment", "'Turbine1' points cannot be imported"),
    ("110       11", "110       x", "LINES 2.NumSegs", "'x' is not a whole number"),
    ("80        WtrDpth", "bathy.txt WtrDpth", "OPTIONS.WtrDpth", "a bathymetry file cannot be imported"),
    ("9.8       g\n", "9.8       g\nsea.txt   SeafloorFile\n", "OPTIONS.SeafloorFile",
     "a bathymetry file cannot be imported; kanat's seabed is a plane: give environment.depth and "
     "environment.seabed.slope_deg"),
    ("9.8       g\n", "9.8       g\n1         WaveKin\n", "OPTIONS.WaveKin", "ExternalWaveKinSet"),
    ("1   Fixed       -300   10    -80    0     0       0    0",
     "1   Fixed       -300   10    -80    0     0       0", "POINTS", "8 values on this row"),
])
def test_errors_name_the_row_and_column(old, new, key, words):
    text = V2.replace(old, new)
    assert text != V2
    found = errors_of(text)
    assert [p.key for p in found] == [key], [str(p) for p in found]
    assert words in found[0].message and found[0].line == text.splitlines().index(
        next(line for line in text.splitlines() if new.split("\n")[-2 if new.endswith("\n") else -1].strip()[:12]
             in line)) + 1


def test_unsupported_sections_are_errors():
    text = V2.replace("---------------------- LINES", "---------------------- RODS ---\nID RodType\n(#) (-)\n"
                      "1 can Fixed 0 0 0 0 0 1 2 -\n---------------------- LINES")
    (problem,) = errors_of(text)
    assert problem.key == "RODS" and "rods cannot be imported" in problem.message


def test_statics_takes_the_static_part_of_a_viscoelastic_line_and_a_run_refuses_it():
    """MoorPy's MoordynSemiTautUpd.dat gives its polyester ``EA`` and ``BA`` as ``static|dynamic``:
    statics takes the static parts, as MoorPy's statics does (its coupled stiffness then agrees with
    MoorPy's to 1e-6), and says what it left out; a dynamic run (``TMax``) refuses them."""
    text = V2.replace("2.0e8   1.5e5", "1.424e8|1.586e8 4e9|11e6")
    case, result = case_of(text)
    assert case.line_types["wire"].axial_stiffness == 1.424e8
    assert case.line_types["wire"].axial_damping == 4e9
    messages = {p.key: p.message for p in result.problems}
    assert "takes the static part 1.424e8" in messages["LINE TYPES wire.EA"]
    assert "leaves out the dynamic 11e6" in messages["LINE TYPES wire.BA"]
    found = errors_of(text.replace("9.8       g\n", "9.8       g\n300       TMax\n"))
    assert [p.key for p in found] == ["LINE TYPES wire.EA", "LINE TYPES wire.BA"]
    assert "not a table file or a '|' list" in found[0].message


def test_a_file_of_rods_and_bodies_alone_is_moordyns_and_says_what_it_lacks():
    """MoorDyn's tests/Mooring/body_tests/floatingBodies.txt (bodies and rods, no lines) read as
    "neither a YAML case nor a MoorDyn input file"; it is MoorDyn's, refused for its rods."""
    text = textwrap.dedent("""\
        --------------------- MoorDyn Input File ---------------------
        floating rods
        ---------------------- ROD TYPES -----------------------------
        TypeName  Diam  Mass/m  Cd  Ca  CdEnd  CaEnd
        (name)    (m)   (kg/m)  (-) (-) (-)    (-)
        can       2.0   4000    0.6 1.0 0.6    1.0
        ---------------------- RODS ----------------------------------
        ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
        (#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
        1  can     Free  0 0 -5 0 0 5 4 -
        ---------------------- SOLVER OPTIONS ------------------------
        100       WtrDpth
        --------------------------- need this line -------------------
        """)
    assert looks_like_moordyn(text)
    found = errors_of(text)
    assert [p.key for p in found] == ["RODS", "ROD_TYPES", "LINE TYPES", "LINES"], [str(p) for p in found]
    assert "rods cannot be imported" in found[0].message and found[0].line == 10      # its first rod


def test_validation_problems_point_at_the_moordyn_row(tmp_path):
    path = tmp_path / "bad.dat"
    path.write_text(V2.replace("wire      0.05   12.0", "wire      0.05   0.0"))
    problems = [p for p in check_case(path) if "does not support" not in p.message]
    assert [(p.key, p.line, p.severity) for p in problems] == [("line_types.wire.mass", 5, "error")]
    assert "must be greater than 0 (got 0 kg/m)" in problems[0].message


# --- neither YAML nor MoorDyn -----------------------------------------------------------------------

@pytest.mark.parametrize("text", [
    "These are my notes about the mooring.\nThey are not a case.\n",
    "time,surge,sway\n0,1,2\n1,2,3\n",
    "@@@ : : ::\n\tnot: [closed\n",
])
def test_a_file_that_is_neither_gets_one_sentence(text):
    (problem,) = check_text(text, "notes.txt")
    assert problem.message.startswith("notes.txt is neither a YAML case") and problem.message.count(".") <= 1
    assert "MoorDyn input file" in problem.message and text.splitlines()[0] not in problem.message


def test_a_broken_yaml_case_keeps_its_syntax_error():
    (problem,) = check_text("name: x\nmodel: [statics\n", "case.yaml")
    assert "YAML syntax error" in problem.message
    assert looks_like_moordyn(V2) and not looks_like_moordyn("model: statics\n")


# --- kanat import -----------------------------------------------------------------------------------

def cli():
    app = typer.Typer()

    @app.callback()
    def main():
        """kanat."""

    register(app)
    return app


@pytest.mark.parametrize("name", EXAMPLES)
def test_kanat_import_writes_a_case_that_loads_back(name, tmp_path):
    out = tmp_path / "case.yaml"
    result = CliRunner().invoke(cli(), ["import", str(FOLDER / name), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert f"wrote {out}" in result.output.replace("\n", "")
    doc = load_yaml(out.read_text())
    case, problems = validate_data(doc.data)
    direct, _ = validate_data(imported(name).data)
    assert problems == [] and case == direct


def test_kanat_import_refuses_other_files_and_bad_rows(tmp_path):
    notes = tmp_path / "notes.txt"
    notes.write_text("just some text\n")
    result = CliRunner().invoke(cli(), ["import", str(notes), "-o", str(tmp_path / "c.yaml")])
    assert result.exit_code == 1 and "is not a MoorDyn input file" in " ".join(result.output.split())
    bad = tmp_path / "bad.dat"
    bad.write_text(V2.replace("2   wire      2        3", "2   wire      2        R1A"))
    result = CliRunner().invoke(cli(), ["import", str(bad), "-o", str(tmp_path / "c.yaml")])
    assert result.exit_code == 1 and "not imported (1 error(s))" in " ".join(result.output.split())
    assert not (tmp_path / "c.yaml").exists()
    result = CliRunner().invoke(cli(), ["import", str(bad), "-o", str(bad)])
    assert result.exit_code == 1


# --- MoorDyn itself reading the same files (optional) ----------------------------------------------

MOORDYN_V2 = ["buoy_spread_mooring.dat", "clump_and_float.dat"]        # MoorDyn-C reads v2 files


class Captured:
    """MoorDyn's own log (C-level stdout), captured while it reads a file."""

    def __enter__(self):
        self.file = tempfile.TemporaryFile(mode="w+b")
        self.saved = os.dup(1)
        os.dup2(self.file.fileno(), 1)
        return self

    def __exit__(self, *exc):
        os.dup2(self.saved, 1)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read().decode(errors="replace")
        self.file.close()


def moordyn_system(moordyn, name: str, case, folder: Path):
    """MoorDyn's system of a file (a copy in ``folder``: MoorDyn writes its output files
    beside its input), initialised without its equilibrium search; its log."""
    coupled = [e.offset for c in case.cables for e in c.ends if e.kind == "vessel"]
    x = np.array([v for point in coupled for v in point], dtype=float)
    copy = folder / name
    copy.write_text((FOLDER / name).read_text())
    with Captured() as log:
        system = moordyn.Create(str(copy))
        moordyn.Init_NoIC(system, x, np.zeros_like(x))
    return system, log.text, x


def step(moordyn, system, x) -> None:
    """One tiny step, after which MoorDyn has computed weights and masses."""
    with Captured():
        moordyn.Step(system, x, np.zeros_like(x), 0.0, 1e-4)


def end_position(case, end):
    if end.kind == "anchor":
        return np.array(end.position)
    if end.kind == "vessel":
        return np.array(end.offset)
    if end.kind == "point":
        return np.array(case.points[end.name].position)
    body = case.bodies[end.name]
    return np.array(body.position) + rotation_matrix(*np.radians(body.orientation_deg)) @ end.offset


@pytest.mark.parametrize("name", MOORDYN_V2)
def test_moordyn_reads_the_same_lines(name, tmp_path, moordyn):
    """Node counts, lengths, end positions, weights per node and converted dampings."""
    case, _ = case_of((FOLDER / name).read_text(), name)
    system, log, x = moordyn_system(moordyn, name, case, tmp_path)
    try:
        env = case.environment
        assert moordyn.GetNumberLines(system) == len(case.cables)
        for number, cable in enumerate(case.cables, 1):
            line = moordyn.GetLine(system, number)
            n = moordyn.GetLineN(line)
            assert (moordyn.GetLineNumberNodes(line), n) == (cable.segments + 1, cable.segments)
            assert moordyn.GetLineUnstretchedLength(line) == pytest.approx(cable.length, rel=1e-12)
            for node, end in ((0, cable.from_), (n, cable.to)):
                got = np.array(moordyn.GetLineNodePos(line, node))
                assert np.abs(got - end_position(case, end)).max() < 1e-9, (number, node)
        step(moordyn, system, x)
        compared = 0
        for number, cable in enumerate(case.cables, 1):
            line, n = moordyn.GetLine(system, number), cable.segments
            weight = case.line_types[cable.line_type].weight_in_water_value(env.water_density, env.gravity)
            assert moordyn.GetLineNodeWeight(line, 1)[2] == pytest.approx(-weight * cable.length / n, rel=1e-12)
            ratio = re.search(rf"Line {number} damping set to \S+ Pa-s = (\S+) Ns", log)
            if ratio:                          # MoorDyn logs the BA it makes of a damping ratio
                assert case.line_types[cable.line_type].axial_damping == pytest.approx(
                    float(ratio[1]), rel=1e-5)
                compared += 1
        assert compared == {"buoy_spread_mooring.dat": 3, "clump_and_float.dat": 1}[name]
    finally:
        moordyn.Close(system)


def test_moordyn_masses_of_points_and_bodies(tmp_path, moordyn):
    case, _ = case_of((FOLDER / "clump_and_float.dat").read_text())
    system, _, x = moordyn_system(moordyn, "clump_and_float.dat", case, tmp_path)
    step(moordyn, system, x)
    try:
        lines = [moordyn.GetLine(system, i) for i in (1, 2, 3)]
        for number, (a, b) in ((2, (0, 1)), (3, (1, 2))):
            own = np.array(moordyn.GetPointM(moordyn.GetPoint(system, number)))
            own = own - np.array(moordyn.GetLineNodeM(lines[a], moordyn.GetLineN(lines[a])))
            own = own - np.array(moordyn.GetLineNodeM(lines[b], 0))
            point = case.points[f"point{number}"]
            assert own == pytest.approx((point.mass + point.added_mass) * np.eye(3), abs=1e-6)
    finally:
        moordyn.Close(system)
    case, _ = case_of((FOLDER / "buoy_spread_mooring.dat").read_text())
    system, _, x = moordyn_system(moordyn, "buoy_spread_mooring.dat", case, tmp_path)
    step(moordyn, system, x)
    try:
        total = np.array(moordyn.GetBodyM(moordyn.GetBody(system, 1)))[:3, :3]
        for i in (1, 2, 3):
            line = moordyn.GetLine(system, i)
            total -= np.array(moordyn.GetLineNodeM(line, moordyn.GetLineN(line)))
        body = case.bodies["body1"]
        expected = body.rigid_body_mass_matrix()[:3, :3] + np.asarray(body.added_mass_matrix)[:3, :3]
        assert total == pytest.approx(expected, abs=1e-6)
    finally:
        moordyn.Close(system)
