"""Cross-check of the lumped model against the continuum model (issue 5): the towed-body speed
step of examples/speed_step_2d.yaml (1000 m cable, 100 elements, 6 -> 10 kn at 60 s) run by
both, agreeing within 2 % on body depth and top tension."""

import numpy as np
import pytest

from kanat.io import load_case
from kanat.io.results import read_result

from helpers import EXAMPLES, run as run_continuum
from helpers import run as run_lumped

EXAMPLE = EXAMPLES / "speed_step_2d.yaml"
STEP_AT, DURATION = 60.0, 150.0


@pytest.fixture(scope="module")
def continuum(tmp_path_factory):
    case = load_case(EXAMPLE)
    case = case.model_copy(update={"simulation": case.simulation.model_copy(
        update={"duration": DURATION, "dt": 0.25, "output_dt": 1.0})})
    path = tmp_path_factory.mktemp("continuum") / "c.nc"
    run_continuum(case, path)
    return case, read_result(path)


@pytest.mark.parametrize("scheme, dt", [("rk4", 0.05), ("generalized-alpha-lumped", 0.05)])
def test_lumped_and_continuum_agree_on_the_towed_body_speed_step(continuum, scheme, dt, tmp_path):
    case, ref = continuum
    lumped = case.model_copy(update={"model": "lumped", "simulation": case.simulation.model_copy(
        update={"scheme": scheme, "dt": dt, "dimensions": "auto"})})
    summary = run_lumped(lumped, tmp_path / "l.nc")
    assert summary.ok, summary.status
    ds = read_result(tmp_path / "l.nc")
    np.testing.assert_allclose(ds["time"].values, ref["time"].values)
    t = ref["time"].values
    depth = {k: r["body_position"].values[:, 0, 2] for k, r in (("c", ref), ("l", ds))}
    top = {k: r["tension"].values[:, 0] for k, r in (("c", ref), ("l", ds))}
    # at the instant of the step the continuum reports the tension just after the impedance jump
    # (its implicit step ends with the new speed), the lumped model the one just before it
    away = t != STEP_AT
    depth_error = np.max(np.abs(depth["l"] - depth["c"])[away]) / np.max(np.abs(depth["c"]))
    tension_error = np.max(np.abs(top["l"] - top["c"])[away]) / np.max(top["c"])
    assert depth_error < 0.02 and tension_error < 0.02, (depth_error, tension_error)
    assert depth["l"][0] == pytest.approx(depth["c"][0], rel=1e-3)        # the same steady state before
    assert top["l"][0] == pytest.approx(top["c"][0], rel=1e-3)
    assert depth["c"][-1] - depth["c"][0] > 50.0                         # the body rose: a real transient
    assert np.max(top["c"][t > STEP_AT]) > 1.5 * top["c"][0]
