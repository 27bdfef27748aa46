"""The cost of a run, estimated by ``kanat validate`` and checked exactly by the model before it
allocates: a long run is warned of, one past the limit refused unless the limit is raised.

Reproducers of the audit: 10,000 segments a leg under rk4 at its safe step (no estimate, hours of
computing), and a line of 1e-6 kg/m with EA 5e8 (a MemoryError allocating 273 GiB for the explicit
safe step). Oracles: the lumped model's own safe step (the estimate must match it), and the limits.
"""
import numpy as np
import pytest
import yaml

import kanat
from kanat.api import dynamic_model
from kanat.errors import CaseError
from kanat.io import check_text
from kanat.model import limits
from kanat.model.run_cost import run_cost

from helpers import EXAMPLES

DECAY = yaml.safe_load((EXAMPLES / "mooring_buoy_decay.yaml").read_text())


def decay(segments=None, **line) -> str:
    """mooring_buoy_decay.yaml (rk4 at its safe step) with ``segments`` a leg and line-type changes."""
    data = yaml.safe_load(yaml.safe_dump(DECAY))
    data["line_types"]["chain76"].update(line)
    for cable in data["cables"]:
        cable["segments"] = segments or cable["segments"]
    return yaml.safe_dump(data, sort_keys=False)


def errors(text):
    return [p for p in check_text(text) if p.severity == "error"]


@pytest.mark.parametrize("name", ["mooring_buoy_decay.yaml", "trawl_head_8s_1to2.yaml"])
def test_the_estimated_safe_step_is_the_models(name):
    """Seabed contact sets the first's step, the line's axial stiffness the second's."""
    case = kanat.load_case(EXAMPLES / name)
    model = dynamic_model(case)
    estimate = run_cost(case).step
    assert model.dt <= estimate * (1 + 1e-12)                 # the model fits its step to the outputs
    assert estimate == pytest.approx(model.dt, rel=0.01)


def test_the_estimate_follows_the_axial_stiffness_on_a_fine_grid():
    case = kanat.load_case(decay(segments=1000, axial_damping=0.0))
    cost = run_cost(case)
    assert "axial stiffness" in cost.why
    assert cost.step == pytest.approx(dynamic_model(case).dt, rel=1e-3)


def test_10000_segments_under_rk4_are_refused_with_the_estimate():
    found = errors(decay(segments=10_000))
    assert len(found) == 1 and found[0].key == "simulation.duration"
    assert "more than the limit of 2e+08 steps" in found[0].message
    assert "rk4's safe step" in found[0].message and "implicit scheme" in found[0].message


def test_a_featherweight_stiff_line_is_refused_before_any_allocation():
    found = errors(decay(mass=1e-6, weight_in_water=5e-6, added_mass=1e-6, added_mass_tangential=1e-6,
                         axial_stiffness=5e8))
    # the model's step, from the audit's MemoryError: 2 x 1.835e10 steps + 1 samples an output second
    assert len(found) == 1 and "2.2e+12 time steps of 5.45e-11 s" in found[0].message
    assert "set by the seabed contact of cable 'leg1'" in found[0].message


def test_a_long_run_is_refused_above_the_limit_and_runs_when_it_is_raised(monkeypatch):
    text = decay(segments=10_000, axial_damping=0.0)       # 5e6 steps x 30,003 nodes = 1.5e11
    found = errors(text)
    assert len(found) == 1 and "1.5e+11 node-steps, more than the limit of 2e+10" in found[0].message
    assert limits.NODE_STEPS_ENV in found[0].message
    monkeypatch.setenv(limits.NODE_STEPS_ENV, "1e12")
    problems = check_text(text)
    assert not [p for p in problems if p.severity == "error"]
    assert any("a long run" in p.message and "251 minutes" in p.message for p in problems)


def test_the_model_checks_its_exact_count_before_allocating(monkeypatch):
    case = kanat.load_case(decay(segments=1000, axial_damping=0.0))   # 1.5e9 node-steps: accepted
    monkeypatch.setenv(limits.NODE_STEPS_ENV, "1e9")
    with pytest.raises(CaseError, match=r"5.01e\+05 time steps of 0.000239 s \(rk4's safe step, from the "
                                        r"shortest axial nodal period .*node-steps, more than the limit of 1e\+09"):
        dynamic_model(case)


def test_a_run_just_above_the_warning_is_warned_of():
    problems = check_text(decay(segments=1000, axial_damping=0.0))   # 1.5e9 node-steps
    assert [p.severity for p in problems if "a long run" in p.message] == ["warning"]
    assert not [p for p in check_text(decay()) if "a long run" in p.message]


def test_a_bad_limit_in_the_environment_is_named(monkeypatch):
    monkeypatch.setenv(limits.NODE_STEPS_ENV, "lots")
    assert any(f"{limits.NODE_STEPS_ENV}='lots'" in p.message for p in errors(decay()))


@pytest.mark.parametrize("name, tolerance", [("mooring_buoy_decay.yaml", 0.0),
                                             pytest.param("lazy_wave.yaml", 1e-5, marks=pytest.mark.slow)])
def test_compiled_calls_in_batches_give_the_same_run(monkeypatch, name, tolerance):
    """Steps are taken in compiled calls of at most ``CALL_STEPS`` (Ctrl-C is handled between two,
    and the vessel's samples stay small): rk4 in batches of 7 is the same run bit for bit; the
    implicit scheme, whose Newton iterations start afresh each call, agrees to its tolerance."""
    from kanat import api
    from kanat.lumped import advance

    data = yaml.safe_load((EXAMPLES / name).read_text())
    data["simulation"]["duration"] = 6
    case = kanat.load_case(data)
    whole = api.run(case).dataset
    monkeypatch.setattr(advance, "CALL_STEPS", 7)
    batched = api.run(case).dataset
    assert whole.attrs["status"] == batched.attrs["status"] == "ok"
    np.testing.assert_allclose(batched["position"].values, whole["position"].values, rtol=0, atol=tolerance)


def test_the_command_line_raises_the_limit_for_one_command(tmp_path, monkeypatch):
    from typer.testing import CliRunner

    from kanat.cli import app

    monkeypatch.setenv(limits.NODE_STEPS_ENV, repr(limits.MAX_NODE_STEPS))   # restored after the test
    path = tmp_path / "long.yaml"
    path.write_text(decay(segments=10_000, axial_damping=0.0))
    refused = CliRunner().invoke(app, ["validate", str(path)])
    assert refused.exit_code == 1 and "node-steps, more than the limit of 2e+10" in refused.output
    raised = CliRunner().invoke(app, ["validate", str(path), "--max-node-steps", "1e12"])
    assert raised.exit_code == 0 and "a long run" in raised.output and "valid (4 warning(s))" in raised.output
