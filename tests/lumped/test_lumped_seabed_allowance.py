"""The penetration the lumped model's seabed check allows (kanat.lumped.mooring_outputs):
``PENETRATION_MARGIN max(W, 0) / (k A) + PENETRATION_FLOOR`` per node, never below the floor: a
node of a line lighter than water presses on nothing (it was once allowed a negative depth, so a
buoyant section resting at the seabed failed the check and its message worded a negative
allowance).

Oracle: the formula by hand from the line's weight in water, diameter and element length, on
the lazy-wave example (a buoyant section of -450 N/m between heavy ones)."""
import warnings

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat import api, load_case
from kanat.physics.contact import PENETRATION_FLOOR, PENETRATION_MARGIN


@pytest.fixture(scope="module")
def lazy_wave():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(EXAMPLES / "lazy_wave.yaml")
    return case, api.dynamic_model(case)


def test_a_node_lighter_than_water_is_allowed_the_floor_and_a_heavy_one_its_static_penetration(lazy_wave):
    case, model = lazy_wave
    net, allowed = model.net, model.penetration
    assert np.all(allowed >= PENETRATION_FLOOR)
    riser = np.asarray(net.node_index)                 # the cable's nodes, anchor first, 10 m elements
    stiffness = case.environment.seabed.stiffness
    heavy = 380.0 * 10.0 / (stiffness * 0.25 * 10.0)   # w L0 / (k d L0): a flowline node inside its section
    assert allowed[riser[5]] == pytest.approx(PENETRATION_MARGIN * heavy + PENETRATION_FLOOR, rel=1e-9)
    buoyant = riser[23 + 10]                           # inside the buoyant section: -450 N/m
    assert net.node_weight[buoyant] < 0.0
    assert allowed[buoyant] == PENETRATION_FLOOR


def test_the_message_words_the_allowance_with_its_floor(lazy_wave):
    case, model = lazy_wave
    net = model.net
    buoyant = np.asarray(net.node_index)[23 + 10]
    x = np.array(net.x_guess, dtype=float)
    for depth, fails in ((0.5 * PENETRATION_FLOOR, False), (2.0 * PENETRATION_FLOOR, True)):
        x[buoyant, 2] = -case.environment.depth - depth
        problem = model._below_seabed(x, 0.0)
        assert (problem is not None) == fails, problem
    assert problem.startswith(f"a node is {2.0 * PENETRATION_FLOOR:.4g} m below the seabed at t = 0 s")
    assert f"more than the contact allows ({PENETRATION_FLOOR:.3g} m: " in problem
    assert f"+ {PENETRATION_FLOOR * 1e3:g} mm)" in problem and "(-" not in problem
