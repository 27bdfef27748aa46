"""The line catalogue against the published formulas, value by value, and MoorPy side by side.

The expected values are written here from the formulas as the sources print them (kN and mm
for chain, as DNV-OS-E302 and DNV-OS-E301 do), not from kanat's code. Sources:

* chain MBL: DNV-OS-E302, ``c d^2 (44 - 0.08 d)`` kN, d in mm; c = 0.0223, 0.0249, 0.0274,
  0.0304, 0.0320 for R3, R3S, R4, R4S, R5 (the same factors in ddjokic/Mooring-Line-Properties
  moorchain.py, and MoorPy's R4 coefficients);
* chain EA: DNV-OS-E301 effective modulus on two bars ``2 pi d^2 / 4``: studless
  (5.40 - 0.0040 d) 1e7 kN/m^2 (R3), (5.45 - 0.0025 d) 1e7 (R4), (6.0 - 0.0033 d) 1e7 (R5);
  studlink 5.6e7 kN/m^2;
* chain mass 19.9 d^2 t/m (studless), 21.9 d^2 t/m (studlink), d in m (Vryhof, OrcaFlex);
* six-strand wire (OrcaFlex, ddjokic moorwire.py): mass 3.9897 d^2 t/m, EA 4.04e7 d^2 kN,
  MBL 633358 d^2 kN, d in m.
"""
import math

import pytest
import yaml
from typer.testing import CliRunner

import kanat
from kanat import catalog
from kanat.cli import app
from kanat.errors import CaseError
from kanat.model.components import LineType

from helpers import EXAMPLES

DNV_E302_FACTOR = {"R3": 0.0223, "R3S": 0.0249, "R4": 0.0274, "R4S": 0.0304, "R5": 0.0320}
DNV_E301_STUDLESS = {"R3": (5.40, 0.0040), "R4": (5.45, 0.0025), "R5": (6.0, 0.0033)}
CHAIN_DIAMETERS_MM = (32.0, 76.0, 120.0, 157.0, 200.0)


@pytest.mark.parametrize("grade", list(DNV_E302_FACTOR))
@pytest.mark.parametrize("d_mm", CHAIN_DIAMETERS_MM)
@pytest.mark.parametrize("name", ["studless_chain", "studlink_chain"])
def test_chain_breaking_load_is_dnv_os_e302(name, grade, d_mm):
    expected_kn = DNV_E302_FACTOR[grade] * d_mm**2 * (44.0 - 0.08 * d_mm)
    keys = catalog.line_type(name, d_mm / 1000.0, grade=grade)
    assert keys["breaking_load"] == pytest.approx(expected_kn * 1e3, rel=1e-12)


@pytest.mark.parametrize("grade", list(DNV_E301_STUDLESS))
@pytest.mark.parametrize("d_mm", CHAIN_DIAMETERS_MM)
def test_studless_chain_stiffness_is_dnv_os_e301(grade, d_mm):
    a, b = DNV_E301_STUDLESS[grade]
    modulus_kn_m2 = (a - b * d_mm) * 1e7
    area_m2 = 2.0 * math.pi * (d_mm / 1000.0) ** 2 / 4.0
    keys = catalog.line_type("studless_chain", d_mm / 1000.0, grade=grade)
    assert keys["axial_stiffness"] == pytest.approx(modulus_kn_m2 * area_m2 * 1e3, rel=1e-12)


@pytest.mark.parametrize("d_mm", CHAIN_DIAMETERS_MM)
def test_chain_mass_volume_and_studlink_stiffness(d_mm):
    d = d_mm / 1000.0
    studless = catalog.line_type("studless_chain", d, grade="R4")
    studlink = catalog.line_type("studlink_chain", d, grade="R4")
    assert studless["mass"] == pytest.approx(19.9 * d**2 * 1000.0, rel=1e-12)
    assert studlink["mass"] == pytest.approx(21.9 * d**2 * 1000.0, rel=1e-12)
    assert studlink["axial_stiffness"] == pytest.approx(5.6e7 * 2 * math.pi * d**2 / 4 * 1e3, rel=1e-12)
    # the volume-equivalent diameter displaces the chain's steel (7850 kg/m^3), to the rounding
    # of the ratios 1.80 and 1.89 (0.4 and 0.6 %)
    for keys in (studless, studlink):
        steel_area = keys["mass"] / 7850.0
        assert math.pi * keys["diameter"] ** 2 / 4 == pytest.approx(steel_area, rel=6e-3)


@pytest.mark.parametrize("d_mm", (12.0, 40.0, 76.0, 127.0))
def test_six_strand_wire_is_the_published_formula(d_mm):
    d = d_mm / 1000.0
    keys = catalog.line_type("wire_six_strand", d)
    assert keys["mass"] == pytest.approx(3.9897 * d**2 * 1000.0, rel=1e-12)
    assert keys["axial_stiffness"] == pytest.approx(4.04e7 * d**2 * 1e3, rel=1e-12)
    assert keys["breaking_load"] == pytest.approx(633358.0 * d**2 * 1e3, rel=1e-12)
    assert keys["diameter"] == pytest.approx(0.80 * d, rel=1e-12)


def test_orq_reference_strength_and_a_published_table_value():
    # ORQ chain, 76 mm: 0.0211 x 76^2 x (44 - 6.08) kN
    assert catalog.chain_reference_breaking_load(0.076) == pytest.approx(0.0211 * 76**2 * 37.92e3, rel=1e-12)
    # the docstring's example and the chain makers' tables: 76 mm R3 chain, 4884 kN
    assert catalog.line_type("studless_chain", 0.076, "R3")["breaking_load"] / 1e3 == pytest.approx(4884.3, abs=0.1)


# --- MoorPy side by side ------------------------------------------------------------------

MOORPY_NAME = {"studless_chain": "chain", "studlink_chain": "chain_studlink", "wire_spiral": "wire",
               "polyester": "polyester", "nylon": "nylon", "hmpe": "hmpe"}
ROPE_DIAMETERS_MM = (48.0, 96.0, 160.0)


def _moorpy(name, d_mm):
    moorpy_helpers = pytest.importorskip("moorpy.helpers")
    return moorpy_helpers.getLineProps(d_mm, MOORPY_NAME[name], source="default", rho=1025.0, g=9.81)


@pytest.mark.parametrize("d_mm", ROPE_DIAMETERS_MM)
@pytest.mark.parametrize("name", ["wire_spiral", "polyester", "nylon", "hmpe"])
def test_ropes_agree_with_moorpy(name, d_mm):
    """MoorPy's default coefficients are the source: every value agrees to rounding."""
    mp = _moorpy(name, d_mm)
    p = catalog.properties(name, d_mm / 1000.0)
    keys = catalog.line_type(name, d_mm / 1000.0, water_density=1025.0)
    line = LineType(**keys)
    assert p.diameter == pytest.approx(mp["d_vol"], rel=1e-12)
    assert p.mass == pytest.approx(mp["m"], rel=1e-12)
    assert p.breaking_load == pytest.approx(mp["MBL"], rel=1e-12)
    assert p.axial_stiffness == pytest.approx(mp["EA"], rel=1e-12)
    assert line.weight_in_water_value(1025.0, 9.81) == pytest.approx(mp["w"], rel=1e-9)
    assert p.drag_normal == pytest.approx(mp["Cd"], rel=5e-3)  # MoorPy prints 4 digits
    assert p.added_mass_coefficient == mp["Ca"] or name == "wire_spiral"  # MoorPy's wire has none
    if p.dynamic_stiffness_per_mbl:
        assert p.dynamic_axial_stiffness(0.0) == pytest.approx(mp["EAd"], rel=1e-12)
        mean = 0.2 * p.breaking_load
        assert p.dynamic_axial_stiffness(mean) == pytest.approx(mp["EAd"] + mp["EAd_Lm"] * mean, rel=1e-12)


@pytest.mark.parametrize("d_mm", CHAIN_DIAMETERS_MM)
def test_r4_chain_agrees_with_moorpy(d_mm):
    """MoorPy's chain is R4: its MBL is DNV-OS-E302's with 3-digit coefficients (+ 911 d N),
    its mass 20.0 d^2 t/m against 19.9, and its EA DNV-OS-E301's d^2 term with a d^3 term
    1000 times smaller than the standard's (-3.93e7 against -pi/2 x 0.0025e10 x 1e3 = -3.93e10)."""
    d = d_mm / 1000.0
    mp = _moorpy("studless_chain", d_mm)
    p = catalog.properties("studless_chain", d, grade="R4")
    assert p.breaking_load == pytest.approx(mp["MBL"], rel=7e-3)
    assert p.mass == pytest.approx(mp["m"], rel=0.2 / 20.0 + 1e-12)
    assert p.diameter == pytest.approx(mp["d_vol"], rel=1e-12)
    assert p.axial_stiffness == pytest.approx(mp["EA"] + 3.93e7 * d**3 - math.pi / 2 * 0.0025e13 * d**3, rel=1e-3)
    assert (p.drag_normal, p.drag_tangential) == pytest.approx((mp["Cd"], mp["CdAx"]), rel=1e-3)
    assert (p.added_mass_coefficient, p.added_mass_tangential_coefficient) == (mp["Ca"], mp["CaAx"])
    studlink = catalog.properties("studlink_chain", d, grade="R4")
    mp_link = _moorpy("studlink_chain", d_mm)
    assert studlink.mass == pytest.approx(mp_link["m"], rel=1e-12)
    assert studlink.axial_stiffness == pytest.approx(mp_link["EA"], rel=1e-3)


# --- in a case -------------------------------------------------------------------------------

def _case(line_type: dict, water_density: float = 1025.0) -> dict:
    data = yaml.safe_load((EXAMPLES / "mooring_3leg.yaml").read_text())
    data["environment"]["water_density"] = water_density
    data["line_types"]["chain76"] = line_type
    return data


def test_catalogue_fills_missing_keys_and_explicit_keys_override():
    case = kanat.load_case(_case({"catalog": "studless_chain", "grade": "R3", "nominal_diameter": 0.076,
                                  "breaking_load": 5.2e6, "drag_normal": 1.2}, water_density=1000.0))
    line = case.line_types["chain76"]
    expected = catalog.line_type("studless_chain", 0.076, "R3", water_density=1000.0)
    assert line.breaking_load == 5.2e6 and line.drag_normal == 1.2
    for key in ("diameter", "mass", "axial_stiffness", "drag_tangential", "added_mass", "added_mass_tangential"):
        assert getattr(line, key) == pytest.approx(expected[key], rel=1e-12), key
    # the added mass is rho pi d_vol^2 / 4 at the case's water density
    assert line.added_mass == pytest.approx(1000.0 * math.pi * 0.1368**2 / 4, rel=1e-12)


@pytest.mark.parametrize("line_type, key, words", [
    ({"catalog": "studles_chain", "grade": "R3", "nominal_diameter": 0.076}, "catalog",
     "did you mean 'studless_chain'"),
    ({"catalog": "studless_chain", "nominal_diameter": 0.076}, "grade", "needs a grade"),
    ({"catalog": "studless_chain", "grade": "R6", "nominal_diameter": 0.076}, "grade", "R3, R3S, R4, R4S, R5"),
    ({"catalog": "polyester", "grade": "R4", "nominal_diameter": 0.12}, "grade", "only chains have a grade"),
    ({"catalog": "polyester", "nominal_diameter": 120}, "nominal_diameter", "outside the range"),
    ({"catalog": "hmpe"}, "nominal_diameter", "needs the nominal_diameter"),
    ({"diameter": 0.1, "mass": 10, "axial_stiffness": 1e8, "grade": "R4"}, "grade", "add catalog"),
])
def test_catalogue_errors_name_the_key(line_type, key, words):
    with pytest.raises(CaseError) as error:
        kanat.load_case(_case(line_type))
    problems = [p for p in error.value.problems if p.severity == "error"]
    assert len(problems) == 1, problems
    assert problems[0].key == f"line_types.chain76.{key}"
    assert words in str(problems[0])


def test_cli_lists_the_catalogue_and_prints_a_line():
    runner = CliRunner()
    listing = runner.invoke(app, ["catalog"])
    assert listing.exit_code == 0
    assert all(name in listing.output for name in catalog.CATALOG)
    one = runner.invoke(app, ["catalog", "studless_chain", "-d", "0.076", "-g", "R3"])
    assert one.exit_code == 0
    printed = yaml.safe_load(one.output)
    assert printed["breaking_load"] == pytest.approx(4884278.0, rel=1e-6)
    assert LineType(**printed).mass == pytest.approx(114.942, rel=1e-5)
    bad = runner.invoke(app, ["catalog", "nylon", "-d", "0.1", "-g", "R3"])
    assert bad.exit_code == 2 and "only chains have a grade" in bad.output


def test_continuum_case_says_how_to_use_a_catalogue_line():
    """The continuum model has no tangential added mass: the catalogue's is refused at its key
    with the way out, and writing it as 0 runs the line."""
    data = yaml.safe_load((EXAMPLES / "factorization_accel.yaml").read_text())
    name = next(iter(data["line_types"]))
    data["line_types"][name] = {"catalog": "polyester", "nominal_diameter": 0.05}
    with pytest.raises(CaseError, match="write added_mass_tangential: 0"):
        kanat.load_case(data)
    data["line_types"][name]["added_mass_tangential"] = 0
    line = kanat.load_case(data).line_types[name]
    assert line.mass == pytest.approx(679.0 * 0.05**2, rel=1e-12) and line.added_mass_tangential == 0.0
