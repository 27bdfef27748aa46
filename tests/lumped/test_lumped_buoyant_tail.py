"""The lumped model's equilibrium of a buoyant free tail (examples/towed_array.yaml with the array's weight
in water reversed, tests/helpers_tail.py): still and submerged, floating at the surface under way, and
refused floating on still water.

Oracles:

* still water: the tail stands plumb (hangs plumb, heavy), each element carrying the nodal loads beyond it,
  ``T = |w| (L - s_mid)`` at its mid-station (exact on any grid), its end ``L + |w| L^2 / (2 EA)`` from the
  tow point; and the continuum model's steady state of the same case, exact on any grid as well;
* floating under way: the floating part's own equilibrium. Horizontal along the flow at the draft where the
  buoyancy of its wetted fraction carries its weight in air, ``phi (m g - w) = m g``, its centreline at
  ``z = d / 2 - phi d`` (the wetted fraction of a horizontal element, :func:`kanat.lumped.kernels.wetted_fraction`);
  its tension the tangential drag on the wetted fraction beyond, element by element from the tail,
  ``T_k = c sum_j a_kj L0 sqrt(1 + T_j / EA)``, ``c = phi 0.5 rho pi d C_t U^2``, ``a_kk = 1/2`` (the element's
  own far half) and 1 beyond;
* floating on still water: refused at the start with the plumb top's height above the surface, 270 m (the
  continuum model refuses it too, tests/continuum/test_continuum_buoyant_tail.py).
"""
import numpy as np
import pytest

from helpers_tail import BUOYANT, STILL, array_case, steady
from kanat import api
from kanat.api import RunFailedWarning
from kanat.errors import SolverError
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import build_network

RHO, G = 1025.0, 9.81
ARRAY = {"d": 0.08, "m": 5.2, "w": -2.0, "EA": 2.0e6, "Ct": 0.008}     # examples/towed_array.yaml, buoyant


def solved(case):
    """The lumped equilibrium of ``case`` at its start: positions (n, 3), element tensions (m,) and info."""
    net = build_network(case)
    start = case.model_copy(update={"environment": case.environment.at_start()})
    x, info = equilibrium(net, start, friction=False)
    model = api.dynamic_model(case)
    out = model.outputs(model.initial())
    np.testing.assert_allclose(out["position"], x, atol=1e-12)
    return x, out["segment_tension"], info


@pytest.mark.parametrize("weight, depth", [(-2.0, 400.0), (2.0, 2.0)], ids=["buoyant", "heavy"])
def test_a_still_tail_stands_plumb_with_the_weight_beyond_and_meets_the_continuum(weight, depth):
    """From the free-tail guess, plumb up (buoyant) or down (heavy), the taut Newton phase converges in one
    iteration; before it the buoyant tail started 45 degrees down and failed in 400 (residual 88 N)."""
    changes = {**BUOYANT, "line_types.array.weight_in_water": weight, "vessel.track": STILL,
               "vessel.tow_point": [0, 0, -depth]}
    case = array_case("lumped", 30, **changes)
    x, tension, info = solved(case)
    assert info["first_guess"] == "free tail" and info["taut_iterations"] <= 2, info
    length, segments = case.cables[0].length, case.cables[0].segments
    middle = (np.arange(segments) + 0.5) * length / segments
    np.testing.assert_allclose(tension, abs(weight) * (length - middle), rtol=1e-8, atol=1e-6)
    stretched = length + abs(weight) * length**2 / (2 * ARRAY["EA"])
    np.testing.assert_allclose(x[-1], x[0] + [0.0, 0.0, -np.sign(weight) * stretched], atol=1e-7)
    np.testing.assert_allclose(x[:, :2], 0.0, atol=1e-9)
    x_continuum, _ = steady(array_case("continuum", 30, **changes))
    np.testing.assert_allclose(x, x_continuum, atol=1e-7)


def floating_oracle(speed: float, segments: int, length: float) -> tuple[float, np.ndarray]:
    """The floating part's draft ``z`` [m] and element tensions from the tail (module docstring) [N]."""
    weight_in_air = ARRAY["m"] * G
    phi = weight_in_air / (weight_in_air - ARRAY["w"])                 # wetted fraction's buoyancy = weight
    c = phi * 0.5 * RHO * np.pi * ARRAY["d"] * ARRAY["Ct"] * speed**2
    l0 = length / segments
    tension, beyond = np.zeros(segments), 0.0
    for k in range(segments - 1, -1, -1):
        for _ in range(50):                                            # T_k = beyond + c l0/2 sqrt(1 + T_k/EA)
            tension[k] = beyond + 0.5 * c * l0 * np.sqrt(1.0 + tension[k] / ARRAY["EA"])
        beyond += c * l0 * np.sqrt(1.0 + tension[k] / ARRAY["EA"])
    return 0.5 * ARRAY["d"] - phi * ARRAY["d"], tension


FLOATING = {"2 kn, 10 m": (2, 10.0, 1e-6, 1e-8), "8 kn, 10 m": (8, 10.0, 1e-5, 3e-6), "8 kn, 5 m": (8, 5.0, 1e-8, 1e-9)}


@pytest.mark.parametrize("knots, depth, z_atol, t_rtol", FLOATING.values(), ids=FLOATING.keys())
def test_a_tail_floating_under_way_lies_at_its_draft_with_the_drag_beyond(knots, depth, z_atol, t_rtol):
    """The buoyant array towed from ``depth`` rises to the surface and floats there (from 10 m: before the
    floating guess its equilibrium stopped at 0.6 N at 2 kn and 3.2 N at 8 kn after 400 iterations). The
    nodes within 1 mm of the draft are the tail's end; its last 5 nodes lie at the draft and its last 5
    elements carry the drag beyond. Where the line meets the surface steeply (from 10 m) it leaves a
    sawtooth on the floating part, decaying by about 3 per node pair (an element's wetted fraction depends
    on its highest and lowest points only, so the sawtooth is the floating line's softest mode): measured
    6.5e-5 m six nodes from the tail at 8 kn, 7e-6 m five from it; from 5 m the floating part is flat to 1e-10 m."""
    case = array_case("lumped", 30, **{**BUOYANT, "vessel.tow_point": [0, 0, -depth],
                                       "vessel.track": [{"straight": {"speed_kn": knots, "duration": 200}}]})
    x, tension, info = solved(case)
    assert info["first_guess"] == "free tail" and info["residual"] < 1e-6, info
    draft, expected = floating_oracle(knots * 1852 / 3600, 30, case.cables[0].length)
    afloat = np.flatnonzero(np.abs(x[:, 2] - draft) < 1e-3)
    assert afloat[-1] == 30 and np.all(np.diff(afloat) == 1) and len(afloat) >= 5, afloat
    np.testing.assert_allclose(x[-5:, 2], draft, atol=z_atol)
    np.testing.assert_allclose(x[afloat, 1], 0.0, atol=1e-12)
    assert np.all(np.diff(x[afloat, 0]) < 0.0)                          # astern, along the flow
    np.testing.assert_allclose(tension[-5:], expected[-5:], rtol=t_rtol)
    assert np.all(tension[:afloat[0]] > expected[:afloat[0]])           # the rising part: its buoyancy as well


def test_a_tail_floating_under_way_runs_with_status_ok():
    case = array_case("lumped", 30, **{**BUOYANT, "vessel.tow_point": [0, 0, -10.0], "simulation.duration": 5.0,
                                       "vessel.track": [{"straight": {"speed_kn": 8, "duration": 200}}]})
    result = api.simulate(case)
    assert result.attrs["status"] == "ok", result.attrs["status"]
    draft, _ = floating_oracle(8 * 1852 / 3600, 30, 300.0)
    assert result.position.values[-1, -1, 2] == pytest.approx(draft, abs=1e-5)     # still afloat, at rest


def test_a_tail_floating_on_still_water_is_refused_with_its_plumb_height():
    """30 m down, the 300 m buoyant tail would stand 270 m out of the water; afloat on still water its place
    and shape are not determined (from a flat start the iteration ended in a sawtooth, nodes alternately at
    the surface and 1 m down, residual 3e-9 N), so the equilibrium refuses it and the run fails at t = 0."""
    changes = {**BUOYANT, "vessel.tow_point": [0, 0, -30.0], "vessel.track": STILL, "simulation.duration": 2.0}
    case = array_case("lumped", 30, **changes)
    with pytest.raises(SolverError, match=r"cable 'array' is a buoyant free tail in still water that would stand "
                                          r"straight up to 270\.000 m above the surface"):
        equilibrium(build_network(case), case, friction=False)
    with pytest.warns(RunFailedWarning):
        status = api.simulate(case).attrs["status"]
    assert status.startswith("failed: no initial state: cable 'array' is a buoyant free tail"), status


def test_a_tail_reaching_still_surface_water_over_a_current_below_is_refused():
    """The vessel still, a 0.5 m/s current only below 350 m: the buoyant tail, 100 m down, stands up through
    the still water above it and would float on still water, so it is refused as on still water."""
    profile = [[0.0, 0.0, 0.0, 0.0], [-350.0, 0.0, 0.0, 0.0], [-400.0, 0.5, 0.0, 0.0]]
    case = array_case("lumped", 10, **{**BUOYANT, "vessel.track": STILL, "environment.current": {"profile": profile}})
    with pytest.raises(SolverError, match=r"cable 'array' is a buoyant free tail that reaches the surface where "
                                          r"the water is still"):
        equilibrium(build_network(case), case, friction=False)
