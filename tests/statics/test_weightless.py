"""Weightless lines and bodies in still water: the right answer where there is one, a clear error
where there is none (the audit's ZeroDivisionError in the piecewise vertical catenary).

Oracle: a weightless line pulled by a buoy hangs straight and vertical at the buoy's net buoyancy,
stretched by ``T L / EA`` section by section; and the limit of the piecewise catenary as the
weight goes to zero.
"""
import pytest
import yaml

import kanat
from kanat.errors import SolverError
from kanat.statics.piecewise import suspended_piece

from helpers import EXAMPLES


def example(name, still=True, **changes):
    data = yaml.safe_load((EXAMPLES / name).read_text())
    if still:
        data["environment"]["current"] = {"velocity": [0, 0, 0]}
    for key, value in changes.items():
        *parents, last = key.split(".")
        node = data
        for part in parents:
            node = node[part]
        node[last] = value
    return kanat.load_case(data)


@pytest.mark.parametrize("V", [1e-7, 1.0, 6000.0])
def test_a_weightless_vertical_piece_is_the_weight_limit_of_a_heavy_one(V):
    l, EA = 150.0, 1.5e6
    dx, dz, partials = suspended_piece(0.0, V, l, 0.0, EA)
    assert (dx, dz) == (0.0, pytest.approx(l + l * V / EA, rel=1e-15))
    assert partials[0] == pytest.approx(l / V + l / EA, rel=1e-15)        # d x / d H of a straight line
    light = suspended_piece(0.0, V, l, 1e-9 * V / l, EA)[2][0]
    assert partials[0] == pytest.approx(light, rel=1e-8)


def test_weightless_sections_under_buoys_hang_straight_up():
    """subsurface_mooring.yaml in still water, its wire and nylon weightless (network statics)."""
    case = example("subsurface_mooring.yaml", **{"line_types.wire.weight_in_water": 0,
                                                  "line_types.nylon.weight_in_water": 0})
    result = kanat.solve_statics(case)
    top = result["body_position"].sel(body="top_buoy").values
    wire = 300 * (1 + (6000 + 1500) / 1.0e7)          # the float's and the buoy's pull
    nylon = 150 * (1 + 6000 / 1.5e6)                  # the buoy's alone
    assert top == pytest.approx([0.0, 0.0, -500 + wire + nylon], abs=1e-6)
    assert float(result["tension"].max()) == pytest.approx(7500.0, rel=1e-9)
    assert float(result["tension"].min()) == pytest.approx(6000.0, rel=1e-9)


def test_a_weightless_line_under_a_buoy_hangs_straight_up():
    """subsurface_buoy.yaml in still water, its wire weightless (single-cable statics)."""
    case = example("subsurface_buoy.yaml", **{"line_types.wire.weight_in_water": 0})
    result = kanat.solve_statics(case)
    assert result["body_position"].sel(body="buoy").values == pytest.approx(
        [0.0, 0.0, -500 + 400 * (1 + 8500 / 1.3e7)], abs=1e-6)


def test_nothing_loading_a_network_is_a_clear_error():
    case = example("subsurface_mooring.yaml", **{
        "line_types.wire.weight_in_water": 0, "line_types.nylon.weight_in_water": 0,
        "bodies.glass_balls.net_buoyancy": 0, "bodies.top_buoy.net_buoyancy": 0})
    with pytest.raises(SolverError, match="nothing loads this network: its lines weigh nothing in water"):
        kanat.solve_statics(case)


def test_a_weightless_line_to_an_inert_body_is_a_clear_error():
    case = example("subsurface_buoy.yaml", **{"line_types.wire.weight_in_water": 0,
                                               "bodies.buoy.net_buoyancy": 0})
    with pytest.raises(SolverError, match="the body exerts no force on the cable"):
        kanat.solve_statics(case)
