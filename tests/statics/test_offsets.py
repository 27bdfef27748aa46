"""The offset curve (kanat.offsets, kanat offsets): restoring force and line tensions against
the vessel's offset.

Oracles: the statics of the same mooring written with its fairleads moved, solved afresh
at each offset (a new case, a new first guess); MoorPy 1.3 side by side (the vessel a
coupled body moved to each offset, ``solveEquilibrium``); and the curve's slope at zero
offset against the coupled stiffness.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from kanat.api import load_case, offsets, solve_statics

FAIRLEADS = [(20.0, 0.0, -8.0), (-10.0, 17.321, -8.0), (-10.0, -17.321, -8.0)]
ANCHORS = [(600.0, 0.0, -120.0), (-300.0, 519.615, -120.0), (-300.0, -519.615, -120.0)]
DIRECTION, TO, STEPS = 30.0, 24.0, 4


def _spread(shift=(0.0, 0.0)) -> str:
    """A three-leg chain mooring with a subsurface buoy (a free point) on leg 1, its fairleads moved by ``shift``."""
    ends = [f"{{vessel: [{x + shift[0]:.12g}, {y + shift[1]:.12g}, {z}]}}" for x, y, z in FAIRLEADS]
    return f"""
name: spread
model: statics
environment: {{water_density: 1025, depth: 120}}
line_types:
  chain: {{diameter: 0.137, mass: 115.0, axial_stiffness: 4.93e8}}
points:
  buoy: {{mass: 20000.0, volume: 40.0, position: [300, 0, -80]}}
cables:
  - {{name: leg1a, line_type: chain, length: 300, segments: 20, from: "anchor:{list(ANCHORS[0])}", to: buoy}}
  - {{name: leg1b, line_type: chain, length: 300, segments: 20, from: buoy, to: {ends[0]}}}
  - {{name: leg2, line_type: chain, length: 620, segments: 20, from: "anchor:{list(ANCHORS[1])}", to: {ends[1]}}}
  - {{name: leg3, line_type: chain, length: 620, segments: 20, from: "anchor:{list(ANCHORS[2])}", to: {ends[2]}}}
"""


def _load(text):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(text)


@pytest.fixture(scope="module")
def curve():
    return offsets(_load(_spread()), direction=DIRECTION, to=TO, steps=STEPS)


def _unit():
    return np.array([math.cos(math.radians(DIRECTION)), math.sin(math.radians(DIRECTION))])


def test_every_offset_is_the_statics_solved_afresh(curve):
    for d in curve.offset.values[1:]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = solve_statics(_load(_spread(tuple(d * _unit()))))
        at = curve.sel(offset=d)
        np.testing.assert_allclose(at.restoring_force.values, ds.body_force.sel(body="vessel").values,
                                   rtol=1e-7, atol=1e-3)
        for cable in curve.cable.values:
            T = ds.tension.values[ds.cable.values == cable]
            np.testing.assert_allclose(at.end_tension.sel(cable=cable).values, [T[0], T[-1]], rtol=1e-7)


def test_the_curve_matches_moorpy(curve):
    moorpy = pytest.importorskip("moorpy")  # noqa: F841
    from moorpy_systems import moorpy_system, solve

    ms, names = moorpy_system(_load(_spread()), vessel="body")
    body = ms.bodyList[0]
    for d in curve.offset.values:
        body.setPosition([*(d * _unit()), 0.0, 0.0, 0.0, 0.0])
        solve(ms, tol=1e-10, max_iterations=20000)
        force = body.getForces(lines_only=True)
        at = curve.sel(offset=d)
        np.testing.assert_allclose(at.restoring_force.values, force[:3], atol=1e-6 * abs(force[2]))
        np.testing.assert_allclose(at.restoring_moment.values, force[3:], atol=1e-6 * abs(force[2]) * 20)
        for cable, numbers in names["lines"].items():
            TA, TB = ms.lineList[numbers[0] - 1].TA, ms.lineList[numbers[-1] - 1].TB
            np.testing.assert_allclose(at.end_tension.sel(cable=cable).values, [TA, TB], rtol=1e-6)
    assert np.linalg.norm(curve.restoring_force.values[-1, :2]) > 2e5        # N: a real offset was compared


def test_the_slope_at_zero_is_the_coupled_stiffness():
    """Central difference of two offsets of +-STEP against K_xx, K_yx of the vessel (the
    difference's error is K'' STEP^2 / 6)."""
    step = 1e-3
    case = _load(_spread())
    K = solve_statics(case).body_stiffness.sel(body="vessel").values
    plus = offsets(case, direction=0.0, to=step, steps=1).restoring_force.values[-1]
    minus = offsets(case, direction=180.0, to=step, steps=1).restoring_force.values[-1]
    np.testing.assert_allclose(-(plus - minus) / (2 * step), K[:3, 0], atol=1e-5 * K[0, 0])


def test_the_command_writes_the_curve(tmp_path):
    from typer.testing import CliRunner

    from kanat.cli import app

    case = tmp_path / "spread.yaml"
    case.write_text(_spread())
    runner = CliRunner()
    for name in ("curve.csv", "curve.nc"):
        out = runner.invoke(app, ["offsets", str(case), "--direction", "0", "--to", "10", "--steps", "2",
                                  "-o", str(tmp_path / name)])
        assert out.exit_code == 0, out.output
    rows = np.genfromtxt(tmp_path / "curve.csv", delimiter=",", names=True)
    expected = offsets(_load(_spread()), direction=0.0, to=10.0, steps=2)
    np.testing.assert_allclose(rows["offset"], [0.0, 5.0, 10.0])
    np.testing.assert_allclose(rows["restoring_force_x"], expected.restoring_force.sel(xyz="x").values)
    np.testing.assert_allclose(rows["tension_leg2_to"], expected.end_tension.sel(cable="leg2", end="to").values)
    import xarray as xr

    with xr.open_dataset(tmp_path / "curve.nc") as ds:
        np.testing.assert_allclose(ds.end_tension.values, expected.end_tension.values)
        assert ds.attrs["direction_deg"] == 0.0


def test_a_case_without_a_vessel_end_is_refused():
    from kanat.errors import CaseError

    import re

    text = re.sub(r"\{vessel: (\[[^\]]*\])\}", r'"anchor:\1"', _spread())      # the fairleads become anchors
    assert "vessel" not in text
    with pytest.raises(CaseError, match="no cable ends at the vessel"):
        offsets(_load(text), direction=0.0, to=5.0)


def test_a_case_in_a_current_is_refused_with_the_reason():
    """The catenary network carries no drag: a current is refused, at its key."""
    from kanat.errors import CaseError

    text = _spread().replace("environment: {water_density: 1025, depth: 120}",
                             "environment: {water_density: 1025, depth: 120, current: {velocity: [0.5, 0, 0]}}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(text, solver="lumped")
    with pytest.raises(CaseError, match="current"):
        offsets(case, direction=0.0, to=5.0)
