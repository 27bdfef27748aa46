"""The spatial continuum model: planar equivalence, re-charting, rotation invariance and the
tight low-speed turn through the pole singularity (theory/continuum.md §2, theory/validation-cases.md)."""

import numpy as np
import pytest

from kanat.continuum.chart import choose_chart, frames, rechart
from kanat.continuum.models import SpatialModel
from kanat.continuum.schemes import GeneralizedAlpha
from kanat.continuum.spatial import SpatialState
from kanat.io import parse_case
from kanat.io.results import read_result

from helpers import EXAMPLES, run, step_rotated

STEP = (EXAMPLES / "speed_step_2d.yaml").read_text().replace("duration: 600\n", "duration: 200\n")
TURN = (EXAMPLES / "turn_360_3d.yaml").read_text()


def test_spatial_model_reduces_to_planar_to_round_off(tmp_path):
    for dims in (2, 3):
        run(parse_case(STEP.replace("dimensions: 2", f"dimensions: {dims}")), tmp_path / f"{dims}.nc")
    a, b = read_result(tmp_path / "2.nc"), read_result(tmp_path / "3.nc")
    assert b.attrs["dimensions"] == 3
    assert np.max(np.abs(a.tension.values - b.tension.values)) < 1e-12 * a.tension.values.max()
    assert np.max(np.abs(a.position.values - b.position.values)) < 1e-9


def turning_state(seconds=150):
    model = SpatialModel(parse_case(TURN))
    state = model.initial()
    coefficients = GeneralizedAlpha().coefficients()
    for _ in range(seconds):
        state, _ = model.step(state, 1.0, coefficients)
    return model, state


def test_rechart_is_exact_both_ways_and_a_step_agrees_to_truncation_error():
    """Re-charting is exact; a step taken in another chart is the same physics discretized with
    other angle averages, so it agrees to the truncation error, which falls with the grid."""
    model, state = turning_state()
    rng = np.random.default_rng(4)
    other = choose_chart(rng.normal(size=(5, 3)))
    y2, rate2 = rechart(state.y, state.rate, state.chart, other)
    y3, rate3 = rechart(y2, rate2, other, state.chart)
    np.testing.assert_allclose(y3, state.y, atol=1e-9)
    np.testing.assert_allclose(rate3, state.rate, atol=1e-9)
    np.testing.assert_allclose(frames(y2, other)[0], frames(state.y, state.chart)[0], atol=1e-12)
    coefficients = GeneralizedAlpha().coefficients()
    differences = []
    for segments in (100, 200):
        m = SpatialModel(parse_case(TURN.replace("segments: 100", f"segments: {segments}")))
        s = m.initial()
        for _ in range(150):
            s, _ = m.step(s, 1.0, coefficients)
        y2, rate2 = rechart(s.y, s.rate, s.chart, other)
        a, _ = m.step(s, 1.0, coefficients)
        b, _ = m.step(SpatialState(s.t, y2, rate2, s.xyz, other), 1.0, coefficients)
        differences.append(np.max(np.abs(b.y[:, 0] - a.y[:, 0])) / np.max(a.y[:, 0]))
    assert differences[0] < 1e-3
    assert differences[1] < 0.5 * differences[0]


@pytest.mark.parametrize("angle_deg", [37.0, 180.0])
def test_rigid_rotation_about_the_vertical_leaves_tensions_unchanged(angle_deg):
    model, state = turning_state()
    plain, turned, rotation = step_rotated(model, state, angle_deg)
    np.testing.assert_allclose(turned.y[:, 0], plain.y[:, 0], rtol=1e-9)
    np.testing.assert_allclose(turned.xyz, plain.xyz @ rotation.T, atol=1e-7)


def test_tight_low_speed_turn_survives_the_pole(tmp_path):
    """2 kn on a 150 m circle with 1000 m of cable: the body sinks until the lower cable hangs
    vertical while the upper cable trails in every horizontal direction in turn."""
    text = TURN.replace("speed_kn: 6", "speed_kn: 2").replace("radius: 294.5, angle_deg: 360",
                                                             "radius: 150, angle_deg: 540")
    text = text.replace("duration: 1200\n", "duration: 2100\n").replace("output_dt: 5.0", "output_dt: 10.0")
    summary = run(parse_case(text), tmp_path / "tight.nc")
    assert summary.ok, summary.status
    ds = read_result(tmp_path / "tight.nc")
    xyz = ds.position.values
    lower = xyz[:, -1] - xyz[:, -11]                                    # lowest 100 m of cable
    from_vertical = np.degrees(np.arccos(np.abs(lower[:, 2]) / np.linalg.norm(lower, axis=1)))
    assert from_vertical.min() < 5.0                                   # hangs (nearly) vertical
    upper = xyz[:, 1] - xyz[:, 0]
    heading = np.degrees(np.unwrap(np.arctan2(upper[:, 1], upper[:, 0])))
    assert np.ptp(heading) > 360.0                                     # trails in every direction
