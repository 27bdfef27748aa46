"""Quasi-static design check (design.analysis: quasi-static): the design offset against a hand
calculation from the RAOs and the JONSWAP spectrum, the line tensions against the statics of the
case written with its fairleads moved to that offset and solved afresh, and the required safety
factors of API RP 2SK for a quasi-static analysis (2.00 intact, 1.43 damaged)."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy import integrate

import kanat
from kanat.design_checks import design
from kanat.errors import KanatError

from helpers import EXAMPLES

FAIRLEADS = [(20.0, 0.0, -8.0), (-10.0, 17.321, -8.0), (-10.0, -17.321, -8.0)]
ANCHORS = [(600.0, 0.0, -120.0), (-300.0, 519.615, -120.0), (-300.0, -519.615, -120.0)]
HS, TP, GAMMA, HEADING, STORM = 6.0, 11.0, 3.3, 30.0, 10800.0
# RAOs constant in frequency, different at 0 and 90 deg: at 30 deg they are 2/3 and 1/3 of them
RAOS = """omega,heading_deg,dof,amplitude,phase_deg
0.1,0,surge,0.8,10
3.0,0,surge,0.8,10
0.1,90,surge,0.4,-20
3.0,90,surge,0.4,-20
0.1,0,sway,0.1,0
3.0,0,sway,0.1,0
0.1,90,sway,0.9,45
3.0,90,sway,0.9,45
"""
SEA_STATES = f"""name,hs,tp,gamma,heading_deg,probability,duration
storm,{HS},{TP},{GAMMA},{HEADING},0.01,3600
"""


def _case(shift=(0.0, 0.0), design_block: str = "", cables=(0, 1, 2)) -> str:
    ends = [f"{{vessel: [{x + shift[0]:.12g}, {y + shift[1]:.12g}, {z}]}}" for x, y, z in FAIRLEADS]
    legs = "\n".join(f'  - {{name: leg{k + 1}, line_type: chain, length: 620, segments: 20, '
                     f'from: "anchor:{list(ANCHORS[k])}", to: {ends[k]}}}' for k in cables)
    return f"""
name: quasi-static
model: lumped
environment: {{depth: 120, seabed: {{}}, waves: {{type: jonswap, hs: {HS}, tp: {TP}, heading_deg: {HEADING}}}}}
line_types:
  chain: {{catalog: studless_chain, grade: R3, nominal_diameter: 0.076}}
vessel:
  motion: {{rao: raos.csv}}
cables:
{legs}
simulation: {{duration: 10, output_dt: 0.5}}
{design_block}
"""


DESIGN = f"""design:
  analysis: quasi-static
  sea_states: sea_states.csv
  storm_duration: {STORM}
  mean_offset: {{intact: 5.0, damaged: 9.0}}
  conditions: [intact, leg1]
"""


def _load(folder, text):
    (folder / "raos.csv").write_text(RAOS)
    (folder / "sea_states.csv").write_text(SEA_STATES)
    (folder / "case.yaml").write_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.load_case(folder / "case.yaml")


def jonswap(omega):
    """DNV-RP-C205 eq. 3.5.5, written again here."""
    wp = 2 * math.pi / TP
    sigma = 0.07 if omega <= wp else 0.09
    return (5 / 16 * HS**2 * wp**4 * omega**-5 * math.exp(-1.25 * (wp / omega) ** 4)
            * GAMMA ** math.exp(-((omega - wp) ** 2) / (2 * sigma**2 * wp**2)) * (1 - 0.287 * math.log(GAMMA)))


def wave_frequency_offset() -> float:
    """sigma sqrt(2 ln(T / T_z)) of the surge-sway motion along 30 deg, by hand."""
    def z(at0, at90):
        return (2 / 3) * at0[0] * np.exp(1j * math.radians(at0[1])) + (1 / 3) * at90[0] * np.exp(1j * math.radians(at90[1]))
    beta = math.radians(HEADING)
    rao = abs(z((0.8, 10), (0.4, -20)) * math.cos(beta) + z((0.1, 0), (0.9, 45)) * math.sin(beta))
    m0 = rao**2 * integrate.quad(jonswap, 0.1, 3.0, limit=200, points=[2 * math.pi / TP])[0]
    m2 = rao**2 * integrate.quad(lambda w: w * w * jonswap(w), 0.1, 3.0, limit=200, points=[2 * math.pi / TP])[0]
    tz = 2 * math.pi * math.sqrt(m0 / m2)
    return math.sqrt(m0) * math.sqrt(2 * math.log(STORM / tz))


@pytest.fixture(scope="module")
def checked(tmp_path_factory):
    folder = tmp_path_factory.mktemp("quasi-static")
    return folder, design(_load(folder, _case(design_block=DESIGN)))


def test_the_design_offset_is_the_mean_plus_the_rayleigh_mpm_of_the_rao_motion(checked):
    _, result = checked
    expected = wave_frequency_offset()
    for kind, mean in (("intact", 5.0), ("damaged", 9.0)):
        offset = result.offsets[(kind, "storm")]
        assert offset.wave_frequency_max == pytest.approx(expected, rel=1e-5)
        assert offset.total == pytest.approx(mean + expected, rel=1e-5)


def test_tensions_are_the_statics_solved_afresh_at_the_design_offset(checked, tmp_path):
    _, result = checked
    unit = np.array([math.cos(math.radians(HEADING)), math.sin(math.radians(HEADING))])
    for condition, kind, cables in (("intact", "intact", (0, 1, 2)), ("damaged:leg1", "damaged", (1, 2))):
        shift = result.offsets[(kind, "storm")].total * unit
        ds = kanat.solve_statics(_load(tmp_path, _case(tuple(shift), cables=cables)))
        rows = result.utilisation[result.utilisation.condition == condition]
        assert sorted(rows.line) == [f"leg{k + 1}" for k in cables]
        for row in rows.itertuples():
            tension = ds.tension.values[ds.cable.values == row.line]
            assert row.mpm_tension == pytest.approx(max(tension[0], tension[-1]), rel=1e-6)
            assert row.safety_factor == pytest.approx(row.mbl / row.mpm_tension)
            assert row.required_safety_factor == (2.00 if kind == "intact" else 1.43)
            assert row.ok == (row.safety_factor >= row.required_safety_factor)
    # the broken leg lets the vessel drift further (9 m against 5 m): leg3, downwind, pulls harder
    leg3 = result.utilisation.set_index(["condition", "line"]).mpm_tension
    assert leg3[("damaged:leg1", "leg3")] > leg3[("intact", "leg3")]


@pytest.mark.parametrize("change, words", [
    ({"mean_offset": None}, "design.mean_offset: missing"),
    ({"mean_offset": {"intact": 5.0}}, "design.mean_offset.damaged: missing"),
    ({"fatigue": {"curve": "api-chain-studless"}}, "gives no tension cycles"),
    ({"standard": "dnv-os-e301", "consequence_class": 1}, "quasi-static factors are not verified"),
])
def test_what_a_quasi_static_check_cannot_do_is_refused_before_any_statics(tmp_path, change, words):
    import yaml

    data = yaml.safe_load(_case(design_block=DESIGN))
    for key, value in change.items():
        if value is None:
            data["design"].pop(key)
        else:
            data["design"][key] = value
    case = _load(tmp_path, yaml.safe_dump(data, sort_keys=False))
    with pytest.raises(KanatError, match=words):
        design(case)


def test_rao_table_too_narrow_for_the_sea_is_refused(tmp_path):
    case = _load(tmp_path, _case(design_block=DESIGN))
    (tmp_path / "raos.csv").write_text(RAOS.replace("0.1,", "0.6,"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        narrow = kanat.load_case(tmp_path / "case.yaml")
    assert case.vessel.motion.rao_rows != narrow.vessel.motion.rao_rows
    with pytest.raises(KanatError, match="% of its variance outside"):
        design(narrow)


def test_the_example_runs_from_the_command_line_and_its_offsets_are_the_hand_ones(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner

    from kanat.cli import app
    from kanat.design_checks.quasi_static import design_offset

    example = EXAMPLES / "design" / "quasi_static.yaml"
    out = tmp_path / "out"
    outcome = CliRunner().invoke(app, ["design", str(example), "-o", str(out)])
    assert outcome.exit_code == 0, outcome.output
    table = pd.read_csv(out / "utilisation.csv")
    assert len(table) == 2 * (3 + 3 * 2) and table.ok.all()
    case = kanat.load_case(example)
    head = next(s for s in case.design.sea_state_rows if s.name == "head")
    # head seas (0 deg): surge alone, |Z| tabulated; the offset is 5 m plus the Rayleigh MPM
    # the RAOs interpolate linearly in frequency as complex numbers
    omega = np.linspace(0.1, 3.0, 400)
    table_omega = [0.1, 0.4, 0.6, 0.8, 1.2, 3.0]
    table_z = [a * np.exp(1j * np.radians(p)) for a, p in [(1.0, 0), (0.9, 5), (0.6, 15), (0.3, 30), (0.08, 60), (0.0, 90)]]
    z = np.interp(omega, table_omega, np.real(table_z)) + 1j * np.interp(omega, table_omega, np.imag(table_z))
    sea = np.array([jonswap_at(w, head.hs, head.tp, head.gamma) for w in omega])
    m0, m2 = (np.trapezoid(omega**n * np.abs(z) ** 2 * sea, omega) for n in (0, 2))
    largest = math.sqrt(m0) * math.sqrt(2 * math.log(STORM * math.sqrt(m2 / m0) / (2 * math.pi)))
    assert design_offset(case, head).total == pytest.approx(5.0 + largest, rel=1e-6)


def jonswap_at(omega, hs, tp, gamma):
    wp = 2 * math.pi / tp
    sigma = 0.07 if omega <= wp else 0.09
    return (5 / 16 * hs**2 * wp**4 * omega**-5 * math.exp(-1.25 * (wp / omega) ** 4)
            * gamma ** math.exp(-((omega - wp) ** 2) / (2 * sigma**2 * wp**2)) * (1 - 0.287 * math.log(gamma)))


def test_bad_design_keys_are_reported_at_file_line_and_key(tmp_path):
    from kanat.errors import CaseError

    text = _case(design_block=DESIGN.replace("{intact: 5.0, damaged: 9.0}", "{intact: 5.0, broken: 9.0}")
                 + "  consequence_class: 3\n")
    with pytest.raises(CaseError) as error:
        _load(tmp_path, text)
    message = str(error.value)
    assert "case.yaml" in message and "design.mean_offset: 'broken' is not a kind of condition" in message
    assert "design.consequence_class: 3 is not one of: 1, 2" in message
    lines = text.splitlines()
    number = next(k for k, line in enumerate(lines, 1) if "broken" in line)
    assert f":{number}:" in message
