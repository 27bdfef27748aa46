"""A heavy free tail longer than the depth: 150 m of chain hung from a fixed point on the surface in
100 m of water must hang 100 m straight down and lay its last 50 m on the seabed.

Closed form (inextensible, still water): the hanging part's tension is ``T(s) = w (100 - s)`` (``w``
the weight in water per metre), ``w 100`` at the top, zero at the touchdown at the foot of the
hanging part and all along the laid part. The lumped model's touchdown node rests wholly on the
seabed, so its discrete answer is the closed form with the touchdown node's half element ``L_e / 2``
taken off the hanging part: the pull at the top is ``w (100 - L_e / 2)``, the contact length
``50 + L_e / 2``, first order in ``L_e``. In still water the laid part's direction is not determined;
kanat lays it along -x (:mod:`kanat.lumped.tow_guess`).

In a uniform current ``U`` a tail whose tension vanishes at its end lies straight at the critical
angle ``phi`` (``R sin^2 phi = w cos phi``, ``R = 0.5 rho d C_n U^2``): the hanging part reaches the
seabed ``100 cot(phi)`` downstream of the top, the laid part trails downstream, and the pull at the top
is ``L_h (w sin phi + 0.5 rho pi d C_t (U cos phi)^2) + T_0``, ``L_h = 100 / sin(phi)``, with
``T_0 = 0.5 rho pi d C_t U^2 (150 - L_h)`` the tangential drag of the laid part (no friction).

The continuum model refuses such a tail (it cannot start from a laid part without tension).
"""
import math

import numpy as np
import pytest

from kanat import api, load_case
from kanat.errors import CaseError

RHO, G, DEPTH, LENGTH = 1025.0, 9.81, 100.0, 150.0
CHAIN = {"diameter": 0.1, "mass": 150.0, "axial_stiffness": 8.0e8, "drag_normal": 2.4, "drag_tangential": 0.4,
         "added_mass": 8.0}
ROPE = {"diameter": 0.03, "mass": 1.2, "weight_in_water": 5.0, "axial_stiffness": 1.0e7, "drag_normal": 1.2,
        "drag_tangential": 0.01, "added_mass": 0.7}
SEABEDS = {"default seabed": None,
           "stiff seabed with friction": {"stiffness": 1.0e7, "friction": 0.6, "lateral_friction": 0.8}}


def hanging_case(line=CHAIN, segments=30, current=0.0, seabed=None, model="lumped"):
    environment = {"depth": DEPTH, "current": {"velocity": [current, 0.0, 0.0]}}
    if seabed is not None:
        environment["seabed"] = seabed
    return load_case({
        "name": "hanging-tail", "model": model, "environment": environment, "line_types": {"line": line},
        "cables": [{"name": "tail", "line_type": "line", "length": LENGTH, "segments": segments,
                    "from": "anchor:[0, 0, 0]", "to": "free"}],
        "simulation": {"duration": 2.0, "dt": 0.1, "output_dt": 1.0}})


def start(case):
    """The lumped model's initial state: the model, its outputs, and its own checks' verdict (None: ok)."""
    model = api.dynamic_model(case)
    state = model.initial()
    out = model.outputs(state)
    return model, out, model.check(state, out)


def weight(line):
    """Weight in water per metre ``w`` [N/m]."""
    return hanging_case(line).line_types["line"].weight_in_water_value(RHO, G)


@pytest.mark.parametrize("seabed", SEABEDS.values(), ids=SEABEDS.keys())
@pytest.mark.parametrize("segments", [30, 60])
def test_a_chain_hung_in_still_water_hangs_to_the_seabed_and_lays_the_rest_along_minus_x(seabed, segments):
    case = hanging_case(segments=segments, seabed=seabed)
    w, element = weight(CHAIN), LENGTH / segments
    model, out, verdict = start(case)
    assert verdict is None
    x = out["position"]
    hanging = int(round(DEPTH / element))                         # the touchdown node
    s = np.arange(segments + 1) * element
    np.testing.assert_allclose(x[:hanging, :2], 0.0, atol=1e-6)
    stretched = element * (1.0 + w * (DEPTH - s[1:hanging + 1]) / CHAIN["axial_stiffness"])   # each at its tension
    np.testing.assert_allclose(x[1:hanging, 2], -np.cumsum(stretched)[:-1], rtol=1e-7)
    laid = x[hanging:]
    depth = -DEPTH - laid[:, 2]
    assert np.all(depth >= 0.0) and np.all(depth <= model.penetration[hanging:])
    np.testing.assert_allclose(laid[:, 1], 0.0, atol=1e-9)
    np.testing.assert_allclose(np.diff(laid[:, 0]), -element, rtol=1e-6)       # unstretched, along -x
    assert laid[-1, 0] == pytest.approx(-(LENGTH - DEPTH), abs=0.02)
    top = out["anchor_force"][0]
    # 3.9 N more: the top element is partly dry within half a diameter of the surface (its lost buoyancy)
    assert abs(top[0]) < 1e-6 * w and top[2] == pytest.approx(-w * (DEPTH - element / 2), rel=5e-5)
    assert abs(-top[2] - w * DEPTH) <= w * element / 2 * (1 + 1e-6)       # first order towards w * 100
    tension = out["segment_tension"]
    closed = w * (DEPTH - s[1:hanging + 1])                        # at each element's lower end, whose node it holds
    np.testing.assert_allclose(tension[1:hanging], closed[1:], rtol=1e-6, atol=1e-6 * w)
    assert tension[0] == pytest.approx(closed[0], rel=5e-5)       # the partly dry top element again
    assert np.all(np.abs(tension[hanging:]) < 1e-6 * w * DEPTH)
    assert out["seabed_contact_length"][0] == pytest.approx(LENGTH - DEPTH + element / 2, rel=1e-9)


RUNS = {"chain in still water": (CHAIN, 0.0), "chain in 0.3 m/s": (CHAIN, 0.3), "rope in 0.3 m/s": (ROPE, 0.3)}


@pytest.mark.slow
@pytest.mark.parametrize("line, current", RUNS.values(), ids=RUNS.keys())
def test_the_tail_stays_where_it_started_and_the_run_is_ok(line, current):
    """The starting state is an equilibrium of the run's own equations: 2 s later nothing has moved."""
    result = api.simulate(hanging_case(line, current=current))
    assert result.attrs["status"] == "ok"
    x = result["position"].values
    assert np.max(np.abs(x[-1] - x[0])) < 1e-3


def closed_form(line, current):
    """``(touchdown x, pull at the top)`` of the straight tail at the critical angle (module docstring)."""
    w = weight(line)
    r = 0.5 * RHO * line["diameter"] * line["drag_normal"] * current**2
    cos = (-w + math.sqrt(w * w + 4 * r * r)) / (2 * r)
    sin = math.sqrt(1.0 - cos**2)
    tangential = 0.5 * RHO * math.pi * line["diameter"] * line["drag_tangential"]
    hanging = DEPTH / sin
    pull = hanging * (w * sin + tangential * (current * cos) ** 2) + tangential * current**2 * (LENGTH - hanging)
    return DEPTH * cos / sin, pull


LINES = {"chain": CHAIN, "light rope": ROPE}


@pytest.mark.parametrize("line", LINES.values(), ids=LINES.keys())
def test_a_tail_in_a_current_hangs_at_the_critical_angle_and_trails_downstream_on_the_seabed(line):
    """Touchdown within one element of ``100 cot(phi)`` (0.80 m for the chain, 31.7 m for the rope), the
    pull at the top within the touchdown node's half element of weight of the closed form."""
    case = hanging_case(line, current=0.3)
    w, element = weight(line), LENGTH / 30
    touchdown, pull = closed_form(line, 0.3)
    model, out, verdict = start(case)
    assert verdict is None
    x = out["position"]
    on = x[:, 2] + DEPTH < 0.01                      # within 1 cm of the seabed
    first = int(np.argmax(on))
    assert np.all(on[first:]) and not np.any(on[:first])
    assert np.all(-DEPTH - x[:, 2] <= model.penetration)
    assert np.all(np.diff(x[first:, 0]) > 0.99 * element)                      # laid straight downstream
    assert x[first, 0] == pytest.approx(touchdown, abs=element)
    assert np.linalg.norm(out["anchor_force"][0]) == pytest.approx(pull, abs=w * element)


def test_the_continuum_model_refuses_a_free_tail_that_reaches_the_seabed():
    with pytest.raises(CaseError, match=r"cables\[0\]\.to: the free tail of cable 'tail' reaches the seabed.*"
                                        r"model: lumped"):
        api.simulate(hanging_case(model="continuum"))
