"""Lumped runs end to end: steady tow stays steady, results streamed, resume gives the same
answer as an uninterrupted run, snap events in the file, failures stop once and keep results."""
import numpy as np
import pytest

from kanat.errors import CaseError, KanatError
from kanat.io.results import read_result
from helpers import killed_run, run
from kanat.model import Case
from kanat.lumped.integrators import SCHEMES
from kanat.schemes import get_scheme


def tow_case(scheme=None, duration=6.0, step_at=2.0, dt=0.05, **sim):
    return Case.model_validate(dict(
        model="lumped", name="tow",
        line_types={"c": dict(diameter=0.02, mass=3.0, axial_stiffness=2e6, axial_damping=2e3, added_mass=0.4,
                              drag_normal=1.5, drag_tangential=0.02)},
        bodies={"b": dict(mass=500, net_buoyancy=-3000, drag_area=0.5)},
        vessel=dict(track=[{"straight": {"speed": 1.0, "duration": step_at}}, {"speed_step": {"to_speed": 2.0}}]),
        cables=[dict(name="tow", line_type="c", length=100, segments=10, **{"from": "vessel"}, to="b")],
        simulation=dict(duration=duration, dt=dt, output_dt=0.5, scheme=scheme, **sim)))


def test_registry_knows_the_lumped_schemes():
    assert {"rk4", "abm4", "generalized-alpha-lumped"} == set(SCHEMES)
    assert get_scheme("generalized-alpha-lumped", SCHEMES, lambda_inf=-0.3).lambda_inf == -0.3
    with pytest.raises(KanatError, match="valid: abm4"):
        get_scheme("rk5", SCHEMES)


@pytest.mark.parametrize("scheme", ["rk4", "abm4", "generalized-alpha-lumped"])
def test_steady_tow_stays_steady_then_responds_to_the_step(scheme, tmp_path):
    summary = run(tow_case(scheme), tmp_path / "r.nc")
    assert summary.ok, summary.status
    ds = read_result(tmp_path / "r.nc")
    top = ds["tension"].values[:, 0]
    before = top[ds["time"].values < 2.0]
    assert np.ptp(before) < 1e-6 * before[0]                     # the equilibrium is steady
    after = top[ds["time"].values > 2.0]
    assert after.max() > 1.08 * before[0] and np.ptp(after) > 500.0   # the step jerks the line
    assert ds.sizes["time"] == 13 and ds.attrs["status"] == "ok" and ds.attrs["scheme"] == scheme
    np.testing.assert_allclose(ds["vessel_position"].values[-1], [2.0 + 2.0 * 4.0, 0.0, 0.0], atol=1e-9)
    assert ds["position"].dims == ("time", "node", "xyz") and ds["segment_tension"].shape == (13, 10)
    if summary.scheme != "generalized-alpha-lumped":
        assert summary.dt < 0.05 and "safe step" in summary.summary()   # explicit: says so


@pytest.mark.slow
def test_schemes_agree_on_the_speed_step(tmp_path):
    tops = {}
    for scheme in ("rk4", "abm4", "generalized-alpha-lumped"):
        case = tow_case(scheme, dt=0.005) if scheme == "generalized-alpha-lumped" else tow_case(scheme)
        run(case, tmp_path / f"{scheme}.nc")
        tops[scheme] = read_result(tmp_path / f"{scheme}.nc")["tension"].values[-1, 0]
    assert tops["abm4"] == pytest.approx(tops["rk4"], rel=1e-5)
    assert tops["generalized-alpha-lumped"] == pytest.approx(tops["rk4"], rel=5e-3)


@pytest.mark.slow
@pytest.mark.parametrize("scheme", ["abm4", "generalized-alpha-lumped"])
def test_resume_gives_the_same_answer_as_an_uninterrupted_run(scheme, tmp_path):
    case = tow_case(scheme)
    run(case, tmp_path / "full.nc")
    killed_run(case, tmp_path / "part.nc", at=3.0, every=2)
    part = read_result(tmp_path / "part.nc.part")
    assert part.attrs["status"] == "running" and part.sizes["time"] == 7
    resumed = run(case, tmp_path / "part.nc", resume=True)
    assert resumed.ok
    a, b = read_result(tmp_path / "full.nc"), read_result(tmp_path / "part.nc")
    np.testing.assert_array_equal(a["time"].values, b["time"].values)
    for name in ("position", "velocity", "tension", "segment_tension"):
        np.testing.assert_allclose(b[name].values, a[name].values, rtol=1e-12, atol=1e-9)
    assert resumed.steps == run(case, tmp_path / "again.nc").steps


def test_resume_refuses_a_changed_case(tmp_path):
    killed_run(tow_case("rk4", duration=1.0), tmp_path / "r.nc", at=0.5, every=1)
    with pytest.raises(KanatError, match="different case"):
        run(tow_case("rk4", duration=2.0), tmp_path / "r.nc", resume=True)


def test_a_line_that_goes_slack_records_snap_events_in_the_file(tmp_path):
    # the tow point stops dead: the heavy body runs on, the line goes slack, then snaps taut
    case = tow_case("rk4", duration=12.0, step_at=1.0)
    case = case.model_copy(update={"vessel": case.vessel.model_validate(
        dict(track=[{"straight": {"speed": 2.0, "duration": 1.0}}, {"speed_step": {"to_speed": 0.0}}]))})
    summary = run(case, tmp_path / "r.nc", progress=lambda t, info: None)
    ds = read_result(tmp_path / "r.nc")
    events = summary.extra["snap_events"]
    assert events > 0 and ds.attrs["snap_events"] == events
    assert ds.sizes["event"] == events
    assert np.all(ds["event_peak_tension"].values >= 0) and np.all(np.diff(ds["event_time"].values) >= 0)
    assert set(ds["event_segment"].values) <= set(range(10))
    assert ds["segment_tension"].values.min() == 0.0              # slack seen in the output too


def test_progress_is_called_every_output(tmp_path):
    calls = []
    run(tow_case("rk4", duration=1.0), tmp_path / "r.nc", progress=lambda t, info: calls.append((t, info)))
    assert [t for t, _ in calls] == pytest.approx([0.0, 0.5, 1.0])
    assert calls[-1][1]["steps"] > 0


def test_a_failing_run_stops_once_keeps_results_and_says_where(tmp_path):
    # a 20-tonne weight hung on a soft line from its unstretched place: strain runs past 50 %
    case = Case.model_validate(dict(
        model="lumped", line_types={"soft": dict(diameter=0.02, mass=1.0, axial_stiffness=1e5)},
        bodies={"weight": dict(mass=2e4, net_buoyancy=-2e5, position=[0, 0, -20])},
        cables=[dict(name="hanger", line_type="soft", length=20, segments=4, **{"from": "anchor:[0,0,0]"},
                     to="weight")],
        simulation=dict(duration=20, dt=0.01, output_dt=0.5, scheme="rk4", initial_state="as_given")))
    summary = run(case, tmp_path / "r.nc")
    assert summary.status.startswith("failed: element stretched")
    assert "cable 'hanger' element" in summary.status and "t = " in summary.status
    ds = read_result(tmp_path / "r.nc")
    assert ds.attrs["status"] == summary.status and ds.sizes["time"] >= 2


def test_dynamic_model_refuses_steady_models():
    from kanat import api

    case = tow_case().model_copy(update={"model": "statics"})
    with pytest.raises(KanatError, match="not a dynamic model"):
        api.dynamic_model(case)


def test_new_model_fields_validate():
    from kanat.model import Body, ElasticLaw, LineType
    with pytest.raises(ValueError, match="exactly one"):
        ElasticLaw(polynomial=[1.0], table=[[0.1, 1.0]])
    with pytest.raises(ValueError, match="ascending"):
        ElasticLaw(table=[[0.1, 1.0], [0.05, 2.0]])
    with pytest.raises(ValueError, match="never pushes"):
        ElasticLaw(table=[[0.1, 10.0], [0.2, 5.0]])
    with pytest.raises(ValueError):
        Body(mass=1, net_buoyancy=0, surface_buoy={"waterplane_area": -1})
    line = LineType(diameter=0.0195, mass=3, axial_stiffness=1e7, drag_normal_coefficient=15.6)
    assert line.drag_normal_coefficient == 15.6 and line.elastic_law is None
    with pytest.raises(CaseError):
        from kanat.io import parse_case
        parse_case("model: lumped\nline_types: {c: {diameter: 0.02, mass: 1, axial_stiffness: 1,"
                   " elastic_law: {table: [[0.1, -1]]}}}\ncables: []\nsimulation: {duration: 1, dt: 0.1}\n")
