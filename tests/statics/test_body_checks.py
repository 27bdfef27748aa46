"""Bodies in the steady checks (kanat.statics.body_checks): a body is where its cables hold it,
never above the water when its loads are those of a submerged body, never wholly under the seabed.

Oracles: a vertical line's length stretched by its mean tension over EA (a buoy on a line longer
than the water is deep), the chord a fairlead moves when its body turns, a wall-sided body's
draft B / (rho g A_w), the seabed's depth, and the statics of the same tow in deep water (how far
a towed body in 100 m of water would hang under the seabed).
"""
import math
import re
import warnings

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat import load_case
from kanat.physics.motion import rotation_matrix
from kanat.statics import solve_statics
from kanat.statics.steady_checks import NodeArrays, check_steady

WHOI = EXAMPLES / "whoi"


def case_of(path, changes=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(path)
        return case.replace(changes) if changes else case


def number(text, label):
    """The number after ``label`` in a message."""
    return float(re.search(re.escape(label) + r" (-?[0-9.e+-]+)", text).group(1))


def test_a_buoy_on_a_line_longer_than_the_water_is_deep_fails_above_the_surface():
    case = case_of(EXAMPLES / "subsurface_buoy.yaml",
                   {"cables[0].length": 600, "environment.current": {"velocity": [0, 0, 0]}})
    verdict = solve_statics(case).verdict
    assert verdict.status.startswith("failed: bodies: body 'buoy' at ")
    assert "above the water surface (z = 0 m)" in verdict.status and "net_buoyancy 8500 N" in verdict.status
    # a vertical wire: 600 m stretched by its mean tension (8500 N at the buoy less half its weight) over EA
    w = (1.0 - 1025 * math.pi * 0.016 ** 2 / 4) * 9.81
    height = -500 + 600 * (1 + (8500 - w * 300) / 1.3e7)
    assert number(verdict.status, "is") == pytest.approx(height, abs=1e-3)


def test_a_sinking_body_hanging_in_the_air_is_a_warning():
    case = case_of(EXAMPLES / "towed_body.yaml", {"vessel.tow_point": [0, 0, 60], "cables[0].length": 20,
                                                  "cables[0].segments": 10})
    verdict = solve_statics(case).verdict
    assert verdict.status == "ok"
    [warning] = [w for w in verdict.warnings if "above the water" in w and "weighs m g" in w]
    assert "body 'sled'" in warning
    [cable] = [w for w in verdict.warnings if w.startswith("cable 'tow'")]       # kanat.statics.steady_checks.dry_parts
    assert number(cable, "cable 'tow':") == pytest.approx(20.0, rel=1e-3)        # the whole cable, unstretched
    assert number(warning, "weighs m g =") == pytest.approx(1135 * 9.81, rel=1e-3)


def _mpl_standing_up(height):
    """WHOI's MPL mooring with its umbilical straight up from the anchor to z = ``height``."""
    case = case_of(WHOI / "mpl.yaml")
    s = np.union1d(np.linspace(0.0, 150.0, 151), [a.s for a in case.cables[0].attachments])
    position = np.column_stack([np.zeros_like(s), np.zeros_like(s), -100.0 + s * (height + 100.0) / 150.0])
    nodes = {"umbilical": NodeArrays(s, position, np.full_like(s, 100.0))}
    bodies = {"float": position[-1]}
    bodies.update({a.body: np.interp(a.s, s, position[:, 2]) * np.array([0, 0, 1.0])
                   for a in case.cables[0].attachments})
    return case, nodes, bodies


def test_a_surface_buoy_out_of_the_water_fails_naming_it():
    case, nodes, bodies = _mpl_standing_up(50.0)
    verdict = check_steady(case, nodes, only=("bodies",), bodies=bodies)
    assert verdict.status.startswith("failed: bodies: body 'float' at (0, 0, 50) m is 50 m above the water")
    assert "its keel is out of the water" in verdict.status


def test_floats_under_the_surface_pass_and_a_crest_raises_the_surface():
    case, nodes, bodies = _mpl_standing_up(-1.0)
    assert check_steady(case, nodes, only=("bodies",), bodies=bodies).status == "ok"
    case, nodes, bodies = _mpl_standing_up(0.9)
    assert check_steady(case, nodes, only=("bodies",), bodies=bodies).status.startswith("failed: bodies: ")
    waves = case.replace({"environment.waves": {"type": "regular", "height": 2.0, "period": 8.0}})
    assert check_steady(waves, nodes, only=("bodies",), bodies=bodies).status == "ok"    # a 1 m crest


def test_a_body_off_the_end_of_its_cable_fails_by_the_distance():
    case, nodes, bodies = _mpl_standing_up(-1.0)
    bodies["panther3"] = bodies["panther3"] + np.array([2.0, 0.0, 0.0])
    verdict = check_steady(case, nodes, only=("bodies",), bodies=bodies)
    assert verdict.status.startswith("failed: bodies: body 'panther3' at ")
    assert number(verdict.status, ") m is") == pytest.approx(2.0, abs=1e-9)
    assert "from where cable 'umbilical' holds it" in verdict.status


@pytest.fixture(scope="module")
def three_legs():
    case = case_of(EXAMPLES / "mooring_3leg.yaml")
    result = solve_statics(case)
    assert result.verdict.status == "ok"
    return case, result


def _moved(result, rotation=np.eye(3), shift=np.zeros(3)):
    """The cables' nodes turned by ``rotation`` about the buoy's reference point, then shifted."""
    centre = result.bodies["buoy"]
    return {name: NodeArrays(c.s, (np.asarray(c.position) - centre) @ rotation.T + centre + shift, c.tension)
            for name, c in result.cables.items()}


def test_a_rigid_bodys_fairleads_turn_with_its_attitude(three_legs):
    case, result = three_legs
    yaw = math.radians(30.0)
    nodes = _moved(result, rotation_matrix(0.0, 0.0, yaw))
    turned = {"buoy": result.attitudes["buoy"] + np.array([0.0, 0.0, yaw])}
    assert check_steady(case, nodes, only=("bodies",), bodies=result.bodies, attitudes=turned).status == "ok"
    assert check_steady(case, nodes, only=("bodies",), bodies=result.bodies).status == "ok"   # |offset| kept
    verdict = check_steady(case, nodes, only=("bodies",), bodies=result.bodies, attitudes=result.attitudes)
    assert verdict.status.startswith("failed: bodies: body 'buoy' at ")
    # leg1's fairlead [2.5, 0, -4] turned by 30 deg about z moves along a chord 2 r sin(15 deg)
    assert number(verdict.status, ") m is") == pytest.approx(2 * 2.5 * math.sin(yaw / 2), rel=1e-3)


def test_a_surface_piercing_rigid_body_lifted_beyond_its_draft_fails(three_legs):
    case, result = three_legs
    body, env = case.bodies["buoy"], case.environment
    draft = (body.net_buoyancy + body.mass * env.gravity) / (env.water_density * env.gravity * body.waterplane_area)
    for rise, ok in ((draft - 0.05, True), (draft + 0.05, False)):
        up = np.array([0.0, 0.0, rise + float(body.position[2]) - float(result.bodies["buoy"][2])])
        bodies = {"buoy": result.bodies["buoy"] + up}
        verdict = check_steady(case, _moved(result, shift=up), only=("bodies",), bodies=bodies,
                               attitudes=result.attitudes)
        assert (verdict.status == "ok") == ok, verdict.status
    assert number(verdict.status, "B / (rho g A_w) =") == pytest.approx(draft, rel=1e-3)


def test_a_rigid_body_wholly_under_the_seabed_fails(three_legs):
    case, result = three_legs
    down = np.array([0.0, 0.0, -130.0])
    bodies = {"buoy": result.bodies["buoy"] + down}
    verdict = check_steady(case, _moved(result, shift=down), only=("bodies",), bodies=bodies,
                           attitudes=result.attitudes)
    assert verdict.status.startswith("failed: bodies: body 'buoy' has its reference point at ")
    assert number(verdict.status, ") m,") == pytest.approx(-120.0 - bodies["buoy"][2], abs=1e-3)
    reach = float(re.search(r"fairleads reach \(([0-9.]+) m\)", verdict.status).group(1))
    assert reach == pytest.approx(math.hypot(2.5, 4.0), rel=1e-3)


@pytest.mark.slow
def test_a_continuum_tow_into_the_seabed_says_where_the_body_would_be():
    from kanat import simulate

    deep = solve_statics(case_of(EXAMPLES / "towed_body.yaml"))            # 2000 m: the same shape, no seabed
    case = case_of(EXAMPLES / "towed_body.yaml", {
        "environment.depth": 100, "model": "continuum",
        "simulation": {"duration": 0.2, "dt": 0.1, "output_dt": 0.1}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        status = simulate(case).attrs["status"]
    assert status.startswith("failed: no initial state: the case's steady state fails its checks (seabed: "
                             "body 'sled' at cable 'tow' node 100 (s = 1000 m) is ")
    assert number(status, "m) is") == pytest.approx(-deep.bodies["sled"][2] - 100.0, rel=1e-3)
    assert "the continuum model's own start: " in status


def test_a_rigid_body_without_a_position_is_checked_against_its_hydrostatic_reference(three_legs):
    """No ``position``: the hydrostatics balance at the origin (as network statics takes it), so
    the body fails once it rose more than its draft B / (rho g A_w) above z = 0."""
    case, result = three_legs
    unplaced = case.replace({"bodies.buoy.position": None})
    assert unplaced.bodies["buoy"].position is None
    moved = solve_statics(unplaced)
    assert moved.verdict.status == "ok"                        # the example's position is the origin
    assert np.allclose(moved.bodies["buoy"], result.bodies["buoy"], atol=1e-6)
    body, env = case.bodies["buoy"], case.environment
    draft = (body.net_buoyancy + body.mass * env.gravity) / (env.water_density * env.gravity * body.waterplane_area)
    for rise, ok in ((draft - 0.05, True), (draft + 0.05, False)):
        up = np.array([0.0, 0.0, rise - float(result.bodies["buoy"][2])])
        bodies = {"buoy": result.bodies["buoy"] + up}
        verdict = check_steady(unplaced, _moved(result, shift=up), only=("bodies",), bodies=bodies,
                               attitudes=result.attitudes)
        assert (verdict.status == "ok") == ok, verdict.status
    assert "above its hydrostatic reference z = 0 (no position given)" in verdict.status
    assert number(verdict.status, "rose") == pytest.approx(draft + 0.05, abs=1e-3)
    assert number(verdict.status, "B / (rho g A_w) =") == pytest.approx(draft, rel=1e-3)


@pytest.mark.parametrize("initial_state, start, checked", [
    ("as_given", True, False),        # a run's start as given is no steady state: bodies anywhere
    ("as_given", False, True),        # the same case's statics is one
    ("equilibrium", True, True),      # a run started from its equilibrium
])
def test_a_start_as_given_skips_the_bodies_check_and_nothing_else(initial_state, start, checked):
    case, nodes, bodies = _mpl_standing_up(50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                # the continuum model starts from its steady state
        case = case.replace({"simulation.initial_state": initial_state})
    verdict = check_steady(case, nodes, bodies=bodies, start=start)
    alone = check_steady(case, nodes, only=("bodies",), bodies=bodies).status
    assert alone.startswith("failed: bodies: body 'float' at (0, 0, 50) m is 50 m above the water")
    if checked:
        assert verdict.status.startswith("failed: bodies: ") and verdict.status == alone
        return
    # without the bodies, the standing umbilical fails the first cable check as it would alone
    cables_only = ("finite", "strain", "tension", "reach", "seabed", "grounded")
    assert verdict.status == check_steady(case, nodes, only=cables_only, bodies=bodies).status
    assert "bodies" not in verdict.status
