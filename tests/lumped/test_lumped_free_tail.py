"""The lumped model's steady tow of a cable with a free tail (examples/towed_array.yaml), against the
closed form of a straight tail at the critical angle and the continuum model side by side; its first
guess (:func:`kanat.lumped.tow_guess.free_tail_guess`) against the same closed form.

In a uniform relative flow ``U`` an inextensible free tail lies straight at the critical angle
``phi`` (``R sin^2 phi = w cos phi``, ``R = 0.5 rho d C_n U^2``), and its tension at the tow point
is the weight and tangential drag along it::

    T_top = L (w sin(phi) + 0.5 rho pi d C_t U^2 cos^2(phi))

With the array's own axial stiffness the drag grows with ``sqrt(1 + e)`` (the continuum model's
steady state, exact for a straight line on any grid); the lumped model's box-free nodal loads
converge to it at second order in the element length.
"""
import math

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat import api, load_case
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import GUESS_STRETCH, build_network
from kanat.lumped.tow_guess import free_tail_guess
from kanat.physics.drag import critical_angle

RHO = 1025.0
SPEED = 8 * 1852 / 3600          # m/s, the example's initial tow speed


def array_case(model="lumped", segments=60, **changes):
    return load_case(EXAMPLES / "towed_array.yaml").replace({"model": model, "cables[0].segments": segments,
                                                             **changes})


def steady(case):
    """The initial steady tow of a dynamic model: node positions (n, 3) and tensions (n,)."""
    model = api.dynamic_model(case)
    out = model.outputs(model.initial())
    return out["position"], out["tension"]


def closed_form(case, speed=SPEED):
    """``(phi, T_top)`` of the inextensible straight tail (module docstring) in a flow of ``speed`` [m/s]."""
    lt = case.line_types["array"]
    w = lt.weight_in_water_value(RHO, 9.81)
    r = 0.5 * RHO * lt.diameter * lt.drag_normal * speed**2           # R sin^2 phi = w cos phi
    phi = math.acos((-w + math.sqrt(w * w + 4 * r * r)) / (2 * r))
    assert r * math.sin(phi) ** 2 == pytest.approx(w * math.cos(phi), rel=1e-12)
    assert critical_angle(w, r / speed**2, speed) == pytest.approx(phi, rel=1e-12)
    length = case.cables[0].length
    drag = 0.5 * RHO * np.pi * lt.diameter * lt.drag_tangential * (speed * np.cos(phi)) ** 2
    return phi, length * (w * np.sin(phi) + drag)


def test_the_example_finds_its_steady_tow_from_the_free_tail_guess():
    case = array_case()
    model = api.dynamic_model(case)
    start = case.model_copy(update={"environment": case.environment.at_start()})
    _, info = equilibrium(model.net, start, friction=False)
    assert info["first_guess"] == "free tail"
    assert info["residual"] < 1e-6 * closed_form(case)[1]
    assert info["taut_iterations"] <= 10


STILL_TOP = [[0.0, 0.0, 0.0, 0.0], [-350.0, 0.0, 0.0, 0.0], [-400.0, 0.5, 0.0, 0.0]]
CURRENTS = {"none": ({"velocity": [0.0, 0.0, 0.0]}, 0.0),
            "still profile": ({"profile": [[0.0, 0.0, 0.0, 0.0], [-400.0, 0.0, 0.0, 0.0]]}, 0.0),
            "uniform profile": ({"profile": [[0.0, 0.5, 0.0, 0.0], [-400.0, 0.5, 0.0, 0.0]]}, 0.5),
            "current below the tail only": ({"profile": STILL_TOP}, 0.0)}


@pytest.mark.parametrize("current, speed", CURRENTS.values(), ids=CURRENTS.keys())
def test_the_free_tail_guess_trails_in_the_flow_at_each_node_and_hangs_plumb_in_still_water(current, speed):
    """The array held still (no way on) in a current: in a uniform 0.5 m/s profile every element trails
    downstream at the closed form's critical angle; with no current, a current table that never flows, or
    a current that flows only below 350 m, where no node of the 300 m tail reaches, the tail hangs
    straight down, eq. (1) at ``U = 0`` (``phi = pi / 2``). Each element is stretched by the network
    guess's factor."""
    case = array_case(segments=10, **{"environment.current": current})
    net = build_network(case)
    x = free_tail_guess(net, case, net.x_guess, np.zeros(3))
    along = np.diff(x[net.node_index], axis=0)
    phi = closed_form(case, speed)[0] if speed > 0.0 else 0.5 * np.pi
    expected = 30.0 * GUESS_STRETCH * np.array([np.cos(phi), 0.0, -np.sin(phi)])     # 10 elements of 30 m
    np.testing.assert_allclose(along, np.broadcast_to(expected, along.shape), atol=1e-9)


def test_a_stiff_tail_lies_straight_at_the_critical_angle_with_the_closed_form_tension():
    case = array_case(**{"line_types.array.axial_stiffness": 2.0e10, "vessel.tow_point": [0, 0, -2.0]})
    phi, tension = closed_form(case)
    x, T = steady(case)
    along = x - x[0]
    assert np.arctan2(-along[1:, 2], -along[1:, 0]) == pytest.approx(phi, abs=1e-7)
    assert T[0] == pytest.approx(tension, rel=1e-6)
    assert T[-1] == pytest.approx(0.0, abs=1e-6 * tension)


def test_the_lumped_tow_converges_to_the_continuum_steady_state_at_second_order():
    tow = {"vessel.tow_point": [0, 0, -2.0]}           # submerged: no element crosses the surface
    x_ref, T_ref = steady(array_case("continuum", 60, **tow))
    assert T_ref[0] == pytest.approx(closed_form(array_case())[1], rel=2e-3)    # stretch: sqrt(1 + e) ~ 1.0007
    errors = []
    for n in (15, 30, 60):
        x, T = steady(array_case("lumped", n, **tow))
        errors.append((abs(T[0] - T_ref[0]), np.max(np.abs(x - x_ref[::60 // n]))))    # at the lumped nodes
    errors = np.array(errors)
    slopes = np.log2(errors[:-1] / errors[1:])
    assert np.all(slopes > 1.8), slopes
    assert errors[-1, 0] < 1e-6 * T_ref[0] and errors[-1, 1] < 1e-6


def test_a_surface_tow_point_differs_from_the_continuum_by_the_dry_top_element():
    """At a tow point on the surface the lumped model's top elements are partly dry (no buoyancy,
    no drag on the dry part; the continuum model keeps the whole line wet): the tension at the
    vessel falls by about the lost drag and buoyancy of the part within half a diameter of the
    surface, 0.1-0.2 % of the tow at 60 elements. The difference shrinks as the grid refines (the
    partly dry top element's share of the line shrinks with it): measured -0.142 % at 30 elements,
    -0.126 % at 60, -0.103 % at 120, -0.075 % at 240, -0.065 % at 480."""
    _, T_ref = steady(array_case("continuum", 60))
    _, T = steady(array_case("lumped", 60))
    assert -3e-3 < T[0] / T_ref[0] - 1.0 < -5e-4


def test_a_buoyant_tail_rises_as_the_mirror_image_of_a_heavy_one():
    """Weight -w instead of w (the tow point deep enough for the tail to stay under water): the same
    tensions, the shape mirrored about the tow point's depth."""
    heavy_x, heavy_T = steady(array_case(**{"vessel.tow_point": [0, 0, -2.0]}))
    light_x, light_T = steady(array_case(**{"vessel.tow_point": [0, 0, -30.0],
                                            "line_types.array.weight_in_water": -2.0}))
    np.testing.assert_allclose(light_T, heavy_T, rtol=1e-9)
    np.testing.assert_allclose(light_x[:, 2] + 30.0, -(heavy_x[:, 2] + 2.0), atol=1e-7)
    np.testing.assert_allclose(light_x[:, 0], heavy_x[:, 0], atol=1e-7)
