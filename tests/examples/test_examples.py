"""Every example in examples/ runs, and its numbers pass their oracles.

Oracles: shooting and collocation agree to 1e-6 on every statics example (theory/validation-cases.md §1,
§3.1); Naumov & Agievich's published values; force balance at bodies; seabed contact.
"""

import numpy as np
import pytest
from scipy.constants import knot
from typer.testing import CliRunner

from kanat.cli import app
from kanat.io import load_case
from kanat.io.results import read_result
from kanat.model.support import needs_network
from kanat.statics import solve_statics

from helpers import EXAMPLES

ALL = sorted(p.name for p in EXAMPLES.glob("*.yaml"))
SLOW_RUNS = {"trawl_head_5.6s_1to4.yaml", "trawl_following_4.5s_1to2.yaml", "trawl_head_8s_1to2.yaml"}  # 600 s each
runner = CliRunner()


def test_there_are_examples():
    assert {"towed_body.yaml", "mooring_current.yaml", "sphere_two_cables.yaml"} <= set(ALL)


def test_the_slow_runs_name_examples_that_exist():
    """A renamed example leaves no slow run unmarked in the fast selection."""
    assert SLOW_RUNS <= set(ALL)


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.slow) if name in SLOW_RUNS else name
                                  for name in ALL])
def test_example_validates_and_runs_from_the_command_line(name, tmp_path):
    assert runner.invoke(app, ["validate", str(EXAMPLES / name)]).exit_code == 0
    out, png = tmp_path / "out.nc", tmp_path / "out.png"
    result = runner.invoke(app, ["run", str(EXAMPLES / name), "-o", str(out), "--plot", str(png)])
    assert result.exit_code == 0, result.output
    ds = read_result(out)
    assert ds.attrs["status"] == "ok"
    assert ds.attrs["case_name"] == load_case(EXAMPLES / name).name
    assert png.stat().st_size > 10_000


STATIC_MODELS = ("statics", "continuum")   # cases whose steady state the statics solvers give


@pytest.mark.parametrize("name", ALL)
def test_shooting_and_collocation_agree_on_every_example(name):
    case = load_case(EXAMPLES / name)
    if case.model not in STATIC_MODELS or any(c.to.kind == "free" for c in case.cables) or needs_network(case):
        pytest.skip(f"{case.model} case without single-cable statics (pitch, a network or a free tail)")
    a, b = solve_statics(case, "shooting"), solve_statics(case, "collocation")
    if a.sphere is not None:
        assert a.sphere.alpha0 == pytest.approx(b.sphere.alpha0, abs=1e-6)
        assert a.sphere.tau0 == pytest.approx(b.sphere.tau0, abs=1e-6)
        assert np.max(np.abs(a.sphere.y - b.sphere.y)) < 1e-6
        return
    for cable in a.cables:
        sa, sb = a.cables[cable], b.cables[cable]
        assert np.max(np.abs(sa.tension - sb.tension)) / sa.tension.max() < 1e-6
        assert np.max(np.hypot(sa.x - sb.x, sa.z - sb.z)) / sa.s[-1] < 1e-6


def test_towed_body_balance_at_the_body():
    case = load_case(EXAMPLES / "towed_body.yaml")
    sol = solve_statics(case).cables["tow"]
    speed = 6 * knot
    drag = 0.5 * 1025 * 0.3276 * speed**2                     # body drag, flow astern
    assert sol.force[-1] == pytest.approx([-drag, -6686.0], rel=1e-9)
    assert sol.z[-1] < -300.0 and sol.x[-1] < -900.0           # trails astern and deep


def test_mooring_example_rests_on_the_seabed_and_anchor_sees_horizontal_pull():
    sol = solve_statics(load_case(EXAMPLES / "mooring_current.yaml")).cables["mooring"]
    assert 400.0 < sol.grounded_length < 650.0
    assert sol.force[0, 1] == 0.0 and sol.z[0] == -150.0
    assert np.min(sol.z) >= -150.0 - 1e-9


def test_subsurface_buoy_holds_its_line_up():
    case = load_case(EXAMPLES / "subsurface_buoy.yaml")
    result = solve_statics(case)
    buoy = result.bodies["buoy"]
    assert buoy[2] > -500.0 + 390.0 * 0.95                     # line stands nearly upright
    assert result.cables["riser"].tension[-1] > 8500.0          # buoyancy plus drag


def test_sphere_examples_reproduce_the_paper():
    one = solve_statics(load_case(EXAMPLES / "sphere_two_cables.yaml")).sphere
    two = solve_statics(load_case(EXAMPLES / "sphere_two_cables_case2.yaml")).sphere
    assert np.degrees(one.alpha0) == pytest.approx(46.9, abs=0.1)
    assert one.tau0 == pytest.approx(0.6066, abs=5e-4)
    assert abs(one.eps1_percent) < 0.01 and abs(one.eps2_percent) < 0.01
    assert two.y_A < one.y_A                                     # deeper sphere
    assert two.alpha0 < one.alpha0 and two.alpha[-1] > one.alpha[-1]


def test_sphere_dimensional_example_maps_to_the_published_groups():
    sol = solve_statics(load_case(EXAMPLES / "sphere_two_cables_dimensional.yaml")).sphere
    g = sol.groups
    assert (g.Psi, g.LoL, g.x_C) == pytest.approx((0.02, 2.0, -1.732), rel=1e-3)
    assert (g.QkL, g.RkL) == pytest.approx((0.45, 0.4), rel=2e-3)
    assert sol.convention == "physical"
    assert sol.T[0] == pytest.approx(sol.tau0 * sol.scales.k1 * sol.scales.L)
