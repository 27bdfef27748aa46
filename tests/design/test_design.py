"""Design checks (kanat design): the damaged condition against the statics of the case with the
line deleted by hand, the utilisation table against the runs' own result files, the fatigue
table against the hand sum over the sea states, the required safety factors against API RP 2SK,
and what is refused (fatigue in a quasi-static check, DNV-OS-E301 with no
consequence class) and reported (a condition with no steady state)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

import kanat
from kanat.analysis.extremes import mpm
from kanat.analysis.fatigue import damage
from kanat.catalog import chain_reference_breaking_load
from kanat.design_checks import design, write_tables
from kanat.design_checks.factors import required_safety_factor
from kanat.errors import CaseError, KanatError

from helpers import EXAMPLES

EXAMPLE = EXAMPLES / "design" / "mooring_design.yaml"
YEAR = 365.25 * 86400.0
SEA_STATES = """name,hs,tp,gamma,heading_deg,probability,duration
calm,1.5,6.0,3.3,0,0.6,40
rough,4.0,8.0,2.0,30,0.05,40
"""


def _case_data(**design) -> dict:
    data = yaml.safe_load(EXAMPLE.read_text())
    data["design"].update(design)
    return data


def _write(folder: Path, data: dict, sea_states: str = SEA_STATES) -> Path:
    (folder / "sea_states.csv").write_text(sea_states)
    path = folder / "case.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


@pytest.fixture(scope="module")
def checked(tmp_path_factory):
    """A tiny check: 2 sea states x (intact, leg2 removed) x 2 seeds of 40 s, into a folder."""
    folder = tmp_path_factory.mktemp("design")
    case = kanat.load_case(_write(folder, _case_data(seeds=2, conditions=["intact", "leg2"])))
    return case, design(case, folder / "out"), folder / "out"


@pytest.mark.slow
def test_damaged_statics_is_the_statics_of_the_case_without_the_line(checked):
    """Oracle: the network statics of the case with leg2 deleted from the file by hand."""
    _, result, _ = checked
    data = _case_data()
    del data["design"]
    data["cables"] = [c for c in data["cables"] if c["name"] != "leg2"]
    by_hand = kanat.solve_statics(kanat.load_case(data))
    damaged = result.statics["damaged:leg2"]
    assert list(np.unique(damaged.cable.values.astype(str))) == ["leg1", "leg3"]
    np.testing.assert_allclose(damaged.tension.values, by_hand.tension.values, rtol=1e-9)
    np.testing.assert_allclose(damaged.position.values, by_hand.position.values, rtol=0, atol=1e-9)
    intact = result.statics["intact"]
    # the buoy moves away from the missing leg2 (towards -y and +x): the remaining legs' tensions change
    assert damaged.body_position.values[0, 1] < intact.body_position.values[0, 1] - 0.1


@pytest.mark.slow
def test_utilisation_agrees_with_the_runs_it_summarises(checked):
    """Oracle: mpm() of each run file's fairlead tension (the more loaded end) after the ramp."""
    case, result, out = checked
    table = result.utilisation
    assert len(table) == 2 * 3 + 2 * 2
    for row in table.itertuples():
        files = sorted((out / "runs" / row.condition.replace(":", "_")).glob(f"{row.sea_state}_seed*.nc"))
        assert len(files) == 2
        records = []
        for file in files:
            ds = kanat.read_result(file)
            ds = ds.sel(time=ds.time[ds.time >= 10.0])           # the waves' ramp
            nodes = np.flatnonzero(ds.cable.values.astype(str) == row.line)
            ends = [ds.tension.isel(node=int(n)) for n in (nodes[0], nodes[-1])]
            records.append(max(ends, key=lambda t: float(t.mean())).values)
        expected = mpm(np.array(records), ds.time.values, 10800.0, "rayleigh").value
        assert row.mpm_tension == pytest.approx(expected, rel=1e-12)
        assert row.mbl == pytest.approx(case.line_types["chain76"].breaking_load, rel=1e-12)
        assert row.safety_factor == pytest.approx(row.mbl / expected, rel=1e-12)
        assert row.required_safety_factor == (1.67 if row.condition == "intact" else 1.25)
        assert row.ok == (row.safety_factor >= row.required_safety_factor)


@pytest.mark.slow
def test_fatigue_is_the_hand_sum_over_the_sea_states(checked):
    """Oracle: sum over sea states of the seeds' mean Miner damage x probability x year / record."""
    case, result, out = checked
    reference = chain_reference_breaking_load(0.076)
    probability = {"calm": 0.6, "rough": 0.05}
    for line in ("leg1", "leg2", "leg3"):
        rows = result.fatigue[result.fatigue.line == line]
        expected = 0.0
        for sea_state, p in probability.items():
            per_seed = []
            for file in sorted((out / "runs" / "intact").glob(f"{sea_state}_seed*.nc")):
                ds = kanat.read_result(file)
                ds = ds.sel(time=ds.time[ds.time >= 10.0])
                nodes = np.flatnonzero(ds.cable.values.astype(str) == line)
                record = float(ds.time[-1] - ds.time[0])
                per_seed.append([damage(ds.tension.isel(node=int(n)).values, reference, "api-chain-studless")
                                 * p * YEAR / record for n in nodes])
            expected = expected + np.mean(per_seed, axis=0)
        np.testing.assert_allclose(rows.damage_per_year.values, expected, rtol=1e-12)
        np.testing.assert_allclose(rows.life_years.values, 1.0 / expected, rtol=1e-12)
        assert rows.s.values[0] == 0.0 and rows.s.values[-1] == pytest.approx(450.0)


@pytest.mark.slow
def test_the_tables_written_are_the_tables_returned(checked, tmp_path):
    _, result, _ = checked
    utilisation, fatigue = write_tables(result, tmp_path)
    assert list(pd.read_csv(utilisation).columns) == ["condition", "sea_state", "line", "mpm_tension", "mbl",
                                                      "safety_factor", "required_safety_factor", "ok"]
    np.testing.assert_allclose(pd.read_csv(utilisation).mpm_tension, result.utilisation.mpm_tension, rtol=1e-15)
    np.testing.assert_allclose(pd.read_csv(fatigue).damage_per_year, result.fatigue.damage_per_year, rtol=1e-15)


@pytest.mark.slow
def test_the_cli_resumes_from_the_runs_and_writes_the_report(checked):
    """kanat design on the folder of the fixture's check reads its runs back (no new run)."""
    from typer.testing import CliRunner

    from kanat.cli import app

    case, result, out = checked
    before = {p: p.stat().st_mtime_ns for p in (out / "runs").rglob("*.nc")}
    outcome = CliRunner().invoke(app, ["design", str(Path(case.source)), "-o", str(out)])
    assert outcome.exit_code == 0, outcome.output
    assert {p: p.stat().st_mtime_ns for p in (out / "runs").rglob("*.nc")} == before
    np.testing.assert_allclose(pd.read_csv(out / "utilisation.csv").mpm_tension, result.utilisation.mpm_tension,
                               rtol=1e-15)
    page = (out / "report.html").read_text()
    assert "damaged:leg2" in page and "fatigue-range" in page


@pytest.mark.parametrize("condition, analysis, factor", [
    ("intact", "quasi-static", 2.00), ("intact", "dynamic", 1.67),
    ("damaged:leg1", "quasi-static", 1.43), ("damaged", "dynamic", 1.25)])
def test_required_safety_factors_are_api_rp_2sk(condition, analysis, factor):
    """API RP 2SK 3rd ed. Table 6.3: tension limits 50, 60, 70 and 80 % of the MBL."""
    assert required_safety_factor("api-rp-2sk", analysis, condition) == factor


@pytest.mark.parametrize("key, value, words", [
    ("analysis", "quasi-static", "gives no tension cycles"),
    ("standard", "dnv-os-e301", "consequence_class: missing"),
    ("fatigue", {"curve": "dnv-chain-studless"}, "not a T-N curve")])
def test_what_is_not_built_is_refused_before_any_run(tmp_path, key, value, words):
    case = kanat.load_case(_write(tmp_path, _case_data(**{key: value})))
    with pytest.raises(KanatError, match=words):
        design(case)


def test_a_condition_with_no_mooring_left_is_reported_not_raised(tmp_path):
    """Removing the only cable leaves nothing to solve: the condition fails, its row says so."""
    data = _case_data(conditions=["leg1"])
    data["cables"] = data["cables"][:1]
    result = design(kanat.load_case(_write(tmp_path, data)))
    assert "leaves no cable" in result.failures["damaged:leg1"]
    assert result.utilisation.empty and not result.ok


def test_a_bad_sea_state_table_is_reported_at_its_key(tmp_path):
    path = _write(tmp_path, _case_data(), SEA_STATES.replace("probability", "probabilty"))
    with pytest.raises(CaseError) as error:
        kanat.load_case(path)
    text = str(error.value)
    assert "design.sea_states" in text and "probabilty" in text and "probability" in text


def test_sea_state_probabilities_over_one_are_refused(tmp_path):
    path = _write(tmp_path, _case_data(), SEA_STATES.replace("0.6", "0.99"))
    with pytest.raises(CaseError, match="add up to 1.04"):
        kanat.load_case(path)


def test_unknown_condition_is_reported_at_its_key_with_the_cables(tmp_path):
    path = _write(tmp_path, _case_data(conditions=["intact", "leg9"]))
    with pytest.raises(CaseError) as error:
        kanat.load_case(path)
    text = str(error.value)
    assert "design.conditions[1]" in text and "'leg9'" in text and "leg1" in text and "leg3" in text


@pytest.mark.slow
def test_the_tables_are_the_same_whatever_engine_ran_the_runs(checked, tmp_path):
    """The intact runs again on a local pool of 2 worker processes: the same numbers."""
    case, serial, _ = checked
    intact = case.replace({"design.conditions": ["intact"]})
    pooled = design(intact, tmp_path, workers=2)
    assert "2 worker processes" in pooled.engine
    rows = serial.utilisation[serial.utilisation.condition == "intact"].reset_index(drop=True)
    pd.testing.assert_frame_equal(pooled.utilisation, rows, check_exact=True)
    pd.testing.assert_frame_equal(pooled.fatigue, serial.fatigue, check_exact=True)


@pytest.mark.slow
def test_offsets_and_uplifts_are_the_largest_in_the_run_files(checked):
    """Oracle: the run files' body positions against the intact statics, and their anchor forces."""
    _, result, out = checked
    neutral = result.statics["intact"].body_position.sel(body="buoy").values
    table = result.excursions
    assert len(table) == 2 * (1 + 3) + 2 * (1 + 2)     # (buoy + anchors) per condition and sea state
    for row in table.itertuples():
        files = sorted((out / "runs" / row.condition.replace(":", "_")).glob(f"{row.sea_state}_seed*.nc"))
        sets = [kanat.read_result(f) for f in files]
        sets = [ds.sel(time=ds.time[ds.time >= 10.0]) for ds in sets]
        if row.quantity == "offset":
            moved = [np.linalg.norm(ds.body_position.sel(body="buoy").values[:, :2] - neutral[:2], axis=1).max()
                     for ds in sets]
        else:
            moved = [ds.anchor_force.sel(anchor=row.item).values[:, 2].max() for ds in sets]
        assert row.largest == pytest.approx(max(moved), rel=1e-12)


@pytest.mark.slow
def test_mirror_damaged_conditions_give_mirror_tensions(tmp_path):
    """Invariant: waves along x, the mooring symmetric about the x axis: removing leg2 or its
    mirror leg3 gives leg1 the same MPM, and the remaining mirror legs swap their values."""
    data = _case_data(conditions=["leg2", "leg3"], fatigue=None)
    case = kanat.load_case(_write(tmp_path, data, "name,hs,tp,probability,duration\nhead,3.0,8.0,0.5,40\n"))
    table = design(case).utilisation.set_index(["condition", "line"]).mpm_tension
    assert table[("damaged:leg2", "leg1")] == pytest.approx(table[("damaged:leg3", "leg1")], rel=1e-9)
    assert table[("damaged:leg2", "leg3")] == pytest.approx(table[("damaged:leg3", "leg2")], rel=1e-9)
    assert table[("damaged:leg2", "leg1")] != pytest.approx(table[("damaged:leg2", "leg3")], rel=1e-4)


def test_the_exit_status_tells_a_failing_check_from_one_that_could_not_be_made():
    """0 all pass; 3 a check fails; 4 a condition's runs failed, even beside passing and failing checks."""
    from types import SimpleNamespace

    from kanat.cli_design import DESIGN_FAILS, NOT_CHECKED, design_status

    assert design_status(SimpleNamespace(failures={}, ok=True)) == 0
    assert design_status(SimpleNamespace(failures={}, ok=False)) == DESIGN_FAILS == 3
    assert design_status(SimpleNamespace(failures={"damaged:leg2/storm": "failed"}, ok=False)) == NOT_CHECKED == 4
    assert 1 not in (DESIGN_FAILS, NOT_CHECKED)                    # 1: the case could not be run (cli_common.fail)
