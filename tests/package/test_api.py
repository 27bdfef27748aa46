"""The front door (kanat.api): in-memory runs equal the command line's files, for every model;
nothing is written without an output; the model table and the scheme registry by import."""
import os
import warnings

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

import kanat
from kanat.cli import app
from kanat.errors import CaseError, KanatError

from helpers import EXAMPLES, short_case

LUMPED = (EXAMPLES / "trawl_head_8s_1to2.yaml").read_text().replace("duration: 600", "duration: 10")


@pytest.mark.parametrize("text", [short_case(duration=30), LUMPED, (EXAMPLES / "towed_body.yaml").read_text(),
                                  (EXAMPLES / "pitch_stabilizer.yaml").read_text()],
                         ids=["continuum", "lumped", "statics", "pitch"])
def test_in_memory_result_equals_the_command_lines_file(text, tmp_path, monkeypatch):
    case_path = tmp_path / "case.yaml"
    case_path.write_text(text)
    monkeypatch.chdir(tmp_path)
    before = set(os.listdir(tmp_path))
    memory = kanat.simulate(kanat.load_case(case_path))
    assert set(os.listdir(tmp_path)) == before                     # no file written
    assert memory.attrs["status"] == "ok"
    result = CliRunner().invoke(app, ["run", str(case_path), "-o", "out.nc"])
    assert result.exit_code == 0, result.output
    written = kanat.read_result("out.nc")
    xr.testing.assert_allclose(memory.drop_attrs(), written.drop_attrs(), rtol=1e-12, atol=0)
    timing = {"wall_time_s", "setup_time_s", "solver_time_s", "compile_time_s"}
    assert {k: v for k, v in memory.attrs.items() if k not in timing} == \
        {k: v for k, v in written.attrs.items() if k not in timing}


def test_load_case_takes_a_path_yaml_text_or_a_mapping():
    path = EXAMPLES / "towed_body.yaml"
    text = path.read_text()
    import yaml

    cases = [kanat.load_case(path), kanat.load_case(str(path)), kanat.load_case(text),
             kanat.load_case(yaml.safe_load(text))]
    assert len({c.model_dump_json() for c in cases}) == 1
    with pytest.raises(CaseError, match="diameter"):
        kanat.load_case(text.replace("diameter: 0.0173", "diameter: -1"))


def test_a_failed_run_warns_and_keeps_what_it_computed():
    text = short_case(duration=60, before=20).replace("speed_kn: 6", "speed_kn: 10").replace(
        "to_speed_kn: 10", "to_speed_kn: 0")
    with pytest.warns(kanat.RunFailedWarning, match="compression"):      # a run told to stop on slack
        ds = kanat.simulate(kanat.load_case(text).replace({"simulation.slack": "stop"}))
    assert ds.attrs["status"].startswith("failed:") and 2 <= ds.sizes["time"] < 61
    assert np.all(np.isfinite(ds.tension.values))


def test_statics_of_a_dynamic_case_and_the_model_table():
    case = kanat.load_case(short_case())
    ds = kanat.solve_statics(case)
    assert "time" not in ds.dims and ds.attrs["model"] == "statics" and ds.attrs["status"] == "ok"
    assert set(kanat.MODELS) == {"statics", "pitch", "continuum", "lumped"}
    with pytest.raises(KanatError, match="not a dynamic model"):
        kanat.api.dynamic_model(kanat.load_case(EXAMPLES / "towed_body.yaml"))


def test_a_scheme_object_works_where_a_name_does():
    from kanat.continuum.schemes import GeneralizedAlpha

    case = kanat.load_case(short_case(duration=10))
    by_name = kanat.simulate(case, scheme="backward-euler")
    assert by_name.attrs["scheme"] == "backward-euler"
    by_object = kanat.simulate(case, scheme=GeneralizedAlpha(lambda_inf=-0.3))
    assert by_object.attrs["scheme_lambda_inf"] == -0.3
    with pytest.raises(KanatError, match="unknown continuum scheme 'rk4'"):
        kanat.simulate(case, scheme="rk4")


def test_resume_needs_an_output():
    with pytest.raises(KanatError, match="resume needs"), warnings.catch_warnings():
        kanat.simulate(kanat.load_case(short_case(duration=10)), resume=True)


def test_a_result_carries_its_case_and_runs_again_from_it(tmp_path):
    from kanat.io.results import case_sha256

    case = kanat.load_case(short_case(duration=10))
    first = kanat.simulate(case, output=tmp_path / "a.nc")
    assert case_sha256(kanat.api.case_of(tmp_path / "a.nc")) == case_sha256(case)
    result = CliRunner().invoke(app, ["run", "--from-result", str(tmp_path / "a.nc"), "-o", str(tmp_path / "b.nc")])
    assert result.exit_code == 0, result.output
    again = kanat.read_result(tmp_path / "b.nc")
    np.testing.assert_array_equal(first.tension.values, again.tension.values)
    assert first.position.attrs["positive"] == "up" and first.time.attrs["standard_name"] == "time"


def test_case_replace_gives_a_validated_variant():
    case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml")
    longer = case.replace({"cables[0].length": 1200, "vessel.track[1].to_speed_kn": 8,
                           "line_types.towcable.drag_normal": 1.6})
    assert longer.cables[0].length == 1200 and case.cables[0].length == 1000          # a new case
    assert longer.vessel.track[1].to_speed_kn == 8 and longer.line_types["towcable"].drag_normal == 1.6
    with pytest.raises(CaseError) as error:
        case.replace({"line_types.towcable.diameter": -0.01, "cables[0].segments": 2.5})
    keys = {p.key for p in error.value.problems}
    assert {"line_types.towcable.diameter", "cables[0].segments"} <= keys
    with pytest.raises(CaseError, match="cables\\[3\\]"):
        case.replace({"cables[3].length": 10})
    with pytest.raises(CaseError, match="drag_nromal"):
        case.replace({"line_types.towcable.drag_nromal": 1.0})        # an unknown key is named


def test_report_of_a_result_in_memory_is_the_report_of_its_file(tmp_path):
    ds = kanat.simulate(kanat.load_case(short_case(duration=20, segments=10)))
    ds.to_netcdf(tmp_path / "r.nc")
    memory = kanat.report(ds, tmp_path / "memory.html")
    from_file = kanat.report(tmp_path / "r.nc", tmp_path / "file.html")
    page = memory.read_text(encoding="utf-8")
    assert "a result in memory" in page
    assert page.replace("a result in memory", str(tmp_path / "r.nc")) == from_file.read_text(encoding="utf-8")
    with pytest.raises(KanatError, match="directory"):
        kanat.report(ds, tmp_path)
