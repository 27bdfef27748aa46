"""A free tail lighter than water in the continuum model (examples/towed_array.yaml with the array's
weight in water reversed): the start, the steady state, and NaN never reported as ok.

Oracles:

* still water: a free tail hangs straight down (heavy) or stands straight up (buoyant) from the
  tow point, its tension the weight in water (the buoyancy) of the part beyond,
  ``T(s) = |w| (L - s)``, and its end ``L + |w| L^2 / (2 EA)`` from the tow point (the stretch of
  that tension: exact on any grid of the box scheme, whose positions integrate ``(1 + T/EA)``
  over straight intervals with linear tension);
* in flow (a tow, a current, a tow against a current, a cross current in 3-D, a heavy tow cable
  with a buoyant tail): the lumped model's equilibrium of the same case. Both models converge at
  second order in the element length (tests/lumped/test_lumped_free_tail.py; a straight tail of
  one line type is exact on any grid of the continuum model): at 30 and 60 elements they differ
  by less than their own grid changes, and their Richardson extrapolations agree;
* a buoyant tail is the mirror image of a heavy one about the tow point's depth;
* a still buoyant tail too long for its tow depth stands out of the water by the closed form's
  height (its dry part weighing its weight in air), which the model's check refuses at t = 0 (half
  a diameter plus 2 mm under the surface: ok).
"""
import numpy as np
import pytest
from scipy.optimize import brentq

from helpers_tail import BUOYANT, FLOWS, STILL, array_case, richardson, steady, with_segments
from kanat import api
from kanat.api import RunFailedWarning
from kanat.continuum.adapter import ContinuumModel
from kanat.continuum.tail import free_tail_guess

@pytest.mark.parametrize("weight", [2.0, -2.0], ids=["heavy", "buoyant"])
def test_a_still_free_tail_hangs_plumb_with_the_tension_of_the_part_beyond(weight):
    case = array_case(**{**BUOYANT, "line_types.array.weight_in_water": weight, "vessel.track": STILL,
                         "vessel.tow_point": [0, 0, -400.0 if weight < 0 else -2.0]})
    cable, lt = case.cables[0], case.line_types["array"]
    x, tension = steady(case)
    s = np.linspace(0.0, cable.length, cable.segments + 1)
    np.testing.assert_allclose(tension, abs(weight) * (cable.length - s), rtol=1e-9, atol=1e-9)
    stretched = cable.length + abs(weight) * cable.length**2 / (2 * lt.axial_stiffness)
    np.testing.assert_allclose(x[-1], x[0] + [0.0, 0.0, -np.sign(weight) * stretched], atol=1e-8)
    np.testing.assert_allclose(x[:, :2], 0.0, atol=1e-8)


@pytest.mark.parametrize("flow", FLOWS, ids=list(FLOWS))
def test_a_buoyant_tail_in_flow_meets_the_lumped_equilibrium_within_their_grid_convergence(flow):
    """Both models at 30 and 60 elements: at 60 they differ by less than their own changes from 30, and
    their Richardson extrapolations (second order) agree to 1e-6 of the tension and 0.1 mm at the tail."""
    changes = {**BUOYANT, **FLOWS[flow]}
    if "line_types" in changes:                                         # the whole block: no per-type key
        del changes["line_types.array.weight_in_water"]
    tops, tails = {}, {}
    for model in ("continuum", "lumped"):
        runs = [steady(array_case(model, **with_segments(changes, n))) for n in (30, 60)]
        tops[model] = np.array([tension[0] for _, tension in runs])
        tails[model] = np.array([x[-1] for x, _ in runs])
        lowest = np.min(runs[1][0][:, 2])
    fine = {model: (tops[model][1], tails[model][1]) for model in tops}
    change = {model: (abs(np.diff(tops[model])[0]), np.max(np.abs(np.diff(tails[model], axis=0)))) for model in tops}
    assert abs(fine["lumped"][0] - fine["continuum"][0]) <= change["lumped"][0] + change["continuum"][0]
    assert np.max(np.abs(fine["lumped"][1] - fine["continuum"][1])) <= change["lumped"][1] + change["continuum"][1]
    extrapolated = {model: (richardson(tops[model]), richardson(tails[model])) for model in tops}
    assert extrapolated["lumped"][0] == pytest.approx(extrapolated["continuum"][0], rel=1e-6)
    np.testing.assert_allclose(extrapolated["lumped"][1], extrapolated["continuum"][1], atol=1e-4)
    assert fine["continuum"][1][2] > lowest + 1.0                                   # the tail rises


@pytest.mark.parametrize("weight", [2.0, -2.0], ids=["heavy", "buoyant"])
def test_the_guess_trails_at_the_critical_angle_above_or_below_the_flow(weight):
    """The inextensible straight tail: ``R sin^2 phi = |w| cos phi`` and
    ``T_top = L (|w| sin phi + 0.5 rho pi d C_t U^2 cos^2 phi)`` (tests/lumped/test_lumped_free_tail.py)."""
    case = array_case(**{**BUOYANT, "line_types.array.weight_in_water": weight})
    rho, lt, length = case.environment.water_density, case.line_types["array"], case.cables[0].length
    speed = case.vessel.initial_speed
    r = 0.5 * rho * lt.diameter * lt.drag_normal * speed**2
    phi = np.arccos((-abs(weight) + np.sqrt(weight**2 + 4 * r * r)) / (2 * r))
    drag = 0.5 * rho * np.pi * lt.diameter * lt.drag_tangential * (speed * np.cos(phi))**2
    top = length * (abs(weight) * np.sin(phi) + drag)
    guess = free_tail_guess(case, np.linspace(0.0, length, 31))
    assert guess.tension[0] == pytest.approx(top, rel=1e-12)
    np.testing.assert_allclose(guess.angle, np.pi - phi if weight < 0 else phi - np.pi, atol=1e-12)
    assert guess.z[-1] - guess.z[0] == pytest.approx(-np.sign(weight) * length * np.sin(phi), rel=1e-12)
    assert guess.tension[-1] == pytest.approx(1e-6 * top, rel=1e-9)          # the floor: an angle at the tail


def test_a_buoyant_tail_rises_as_the_mirror_image_of_a_heavy_one():
    heavy_x, heavy_t = steady(array_case(**{"vessel.tow_point": [0, 0, -2.0]}))
    light_x, light_t = steady(array_case(**{**BUOYANT, "vessel.tow_point": [0, 0, -30.0]}))
    np.testing.assert_allclose(light_t, heavy_t, rtol=1e-9)
    np.testing.assert_allclose(light_x[:, 2] + 30.0, -(heavy_x[:, 2] + 2.0), atol=1e-7)
    np.testing.assert_allclose(light_x[:, 0], heavy_x[:, 0], atol=1e-7)


def test_a_buoyant_tail_runs_with_status_ok():
    case = array_case(segments=30, **{**BUOYANT, "simulation.duration": 4.0})
    result = api.simulate(case)
    assert result.attrs["status"] == "ok", result.attrs["status"]
    assert np.all(np.isfinite(result.tension.values))
    assert result.position.values[-1, -1, 2] > -100.0 + 1.0


@pytest.mark.parametrize("where", ["tension", "angle"])
def test_a_state_holding_nan_fails_the_models_check(where):
    model = ContinuumModel(array_case(segments=30, **BUOYANT))
    state = model.initial()
    assert model.check(state, model.outputs(state)) is None
    y = state.y.copy()
    y[7, 0 if where == "tension" else 3] = np.nan
    broken = type(state)(state.t, y, state.rate, state.xz)
    problem = model.check(broken, model.outputs(broken))
    assert problem is not None and "not finite" in problem and "node 7" in problem


def standing_height(depth: float, length=300.0, buoyancy=2.0, weight_in_air=5.2 * 9.81, stiffness=2.0e6) -> float:
    """Height [m] above the surface of the top of a still buoyant tail standing straight up from a tow
    point ``depth`` deep, its part above the water weighing its weight in air: with ``l`` the length
    out of the water, the tension ``-w_a s'`` at ``s'`` from the top (compression) above the surface
    and ``-w_a l + |w| (s' - l)`` under it, ``depth = (L - l) + (|w| (L - l)^2 / 2 - w_a l (L - l)) / EA``
    and the height ``l - w_a l^2 / (2 EA)``."""
    def under(out):
        return (length - out) + (buoyancy * (length - out)**2 / 2 - weight_in_air * out * (length - out)) / stiffness - depth
    out = brentq(under, 0.0, length)
    return out - weight_in_air * out**2 / (2 * stiffness)


@pytest.mark.parametrize("tow_depth", [30.0, 299.0], ids=["far out", "just out"])
def test_a_still_buoyant_tail_that_reaches_out_of_the_water_fails_at_the_start(tow_depth):
    """A still buoyant tail too long for its tow depth stands straight up from the tow point, out of
    the water, its dry part weighing its weight in air (:func:`standing_height`: 268.864 m and
    1.0368 m; 270.045 m and 1.045 m were it buoyant out of the water too). The run fails at t = 0
    naming the node and the height."""
    case = array_case(segments=30, **{**BUOYANT, "vessel.tow_point": [0, 0, -tow_depth], "simulation.duration": 2.0,
                                      "vessel.track": STILL})
    with pytest.warns(RunFailedWarning):
        status = api.simulate(case).attrs["status"]
    assert status.startswith("failed: node 30 of cable 'array' (s = 300 m), on its buoyant part, is "), status
    assert float(status.split(" is ")[1].split(" m above")[0]) == pytest.approx(standing_height(tow_depth), abs=1e-3)


def test_a_buoyant_tail_just_under_the_surface_passes_the_check():
    """The same still tail with its top half a diameter (plus 2 mm) under the surface: ok."""
    lt_diameter, stretched = 0.08, 300.0 + 2.0 * 300.0**2 / (2 * 2.0e6)
    depth = stretched + 0.5 * lt_diameter + 0.002
    case = array_case(segments=30, **{**BUOYANT, "vessel.tow_point": [0, 0, -depth], "simulation.duration": 2.0,
                                      "vessel.track": STILL})
    result = api.simulate(case)
    assert result.attrs["status"] == "ok", result.attrs["status"]
    assert result.position.values[0, -1, 2] == pytest.approx(-0.5 * lt_diameter - 0.002, abs=1e-8)
