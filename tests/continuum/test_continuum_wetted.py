"""The wetted fraction of continuum intervals crossing the water surface (kanat.continuum.wetted).

Oracles: the share of a straight chord under the surface (its height over ``sin`` of its angle);
the exact elastic catenary of a line from a point above the water to an anchor, its dry part
weighing its weight in air and its wet part its weight in water (closed form per part, the
crossing and the end forces by root finding), which the continuum steady state must approach at
the box scheme's second order; the 2-D and 3-D models on the same case; and the lumped model on
a fine grid for a tow from a point above the water.
"""
from __future__ import annotations

import contextlib
import io
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

import kanat
from kanat.continuum import kernels2d as k
from kanat.continuum.wetted import wet_fractions, wet_rows

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
G = 9.81                                       # the case's gravity (the default)
MASS, WET_WEIGHT, EA = 1.12, 8.89, 1.2717e7    # kg/m, N/m, N: examples/towed_body.yaml's cable
LENGTH, TOP, ANCHOR = 400.0, 20.0, (300.0, -200.0)


def _rows(n: int) -> np.ndarray:
    rows = np.zeros((n, k.NPAR))
    rows[:, [k.M, k.MA, k.W0, k.DIAM, k.CN, k.CT, k.GRAV]] = MASS, 0.24, WET_WEIGHT, 0.0173, 1.5, 0.01, G
    return rows


@pytest.mark.parametrize("top", [0.0, 3.0, 12.5])
def test_the_wet_share_of_a_straight_line_is_its_chord_under_the_surface(top):
    """A straight line 30 degrees down from ``top``: its wet length is its length less ``top / sin 30``."""
    s = np.linspace(0.0, 40.0, 9)
    position = np.column_stack([s * math.cos(math.radians(30.0)), top - s * 0.5])
    phi = wet_fractions(_rows(8), position, None, 0.0)
    assert np.sum(phi * np.diff(s)) == pytest.approx(40.0 - top / 0.5, abs=1e-12)


def test_a_wholly_wet_interval_keeps_its_row_bit_for_bit_and_a_dry_one_weighs_its_weight_in_air():
    rows = _rows(3)
    P = rows.copy()
    wet_rows(P, np.array([1.0, 0.25, 0.0]))
    assert np.array_equal(P[0], rows[0])
    assert P[2, k.W0] == pytest.approx(MASS * G, rel=1e-15)                     # eq. (2), dry
    assert P[1, k.W0] == pytest.approx(0.25 * WET_WEIGHT + 0.75 * MASS * G, rel=1e-15)
    displaced = P[:, k.M] - P[:, k.W0] / P[:, k.GRAV]                           # the kernels' rho A
    assert displaced[1:] == pytest.approx(np.array([0.25, 0.0]) * (MASS - WET_WEIGHT / G), abs=1e-15)
    assert P[1, [k.MA, k.CN, k.CT]] == pytest.approx(0.25 * rows[1, [k.MA, k.CN, k.CT]], rel=1e-15)
    assert len({P[1, k.SECTION], P[2, k.SECTION], P[0, k.SECTION]}) == 3         # their own sections


def _catenary(w: float, H: float, V0: float, s: float):
    """Rise ``(x, z)`` and end vertical force of an elastic catenary of weight ``w`` per unstretched
    length over ``s`` from the vertical force ``V0`` (Irvine 1981, eqs. 2.18-2.19 per part)."""
    V1 = V0 + w * s
    x = H / w * (math.asinh(V1 / H) - math.asinh(V0 / H)) + H * s / EA
    z = (math.hypot(H, V1) - math.hypot(H, V0)) / w + (V0 * s + 0.5 * w * s * s) / EA
    return x, z, V1


def exact_top_tension() -> float:
    """The line from the anchor up to the point ``TOP`` m above the water: wet part ``w_c`` long
    weighing ``WET_WEIGHT``, dry part ``MASS g`` (unknowns ``H``, ``V0`` at the anchor and ``w_c``)."""
    def gaps(u):
        H, V0, wet = u
        x1, z1, V1 = _catenary(WET_WEIGHT, H, V0, wet)
        x2, z2, _ = _catenary(MASS * G, H, V1, LENGTH - wet)
        return [x1 + x2 - ANCHOR[0], ANCHOR[1] + z1, ANCHOR[1] + z1 + z2 - TOP]
    H, V0, wet = fsolve(gaps, [1000.0, 500.0, 0.9 * LENGTH], xtol=1e-13)
    assert np.max(np.abs(gaps([H, V0, wet]))) < 1e-9                   # m
    return math.hypot(H, V0 + WET_WEIGHT * wet + MASS * G * (LENGTH - wet))


def hanging_case(segments: int, dimensions: int = 2):
    return kanat.load_case({
        "name": "line-from-above-the-water", "model": "continuum",
        "environment": {"water_density": 1025, "depth": 1000},
        "line_types": {"wire": {"diameter": 0.0173, "mass": MASS, "weight_in_water": WET_WEIGHT,
                                "axial_stiffness": EA, "added_mass": 0.24, "drag_normal": 1.5,
                                "drag_tangential": 0.01}},
        "vessel": {"tow_point": [0, 0, TOP], "track": [{"straight": {"speed_kn": 0, "duration": 10}}]},
        "cables": [{"name": "wire", "line_type": "wire", "length": LENGTH, "segments": segments,
                    "from": "vessel", "to": f"anchor:[{ANCHOR[0]}, 0, {ANCHOR[1]}]"}],
        "simulation": {"duration": 1.0, "dt": 0.5, "output_dt": 0.5, "dimensions": dimensions}})


def top_tension(case) -> float:
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        ds = kanat.simulate(case)
    assert ds.attrs["status"] == "ok"
    return float(ds["tension"].values[0, 0])                   # t = 0: the continuum steady state


def test_a_line_hanging_from_above_the_water_converges_to_its_two_part_catenary_at_second_order():
    """Measured: relative errors 2.76e-4, 6.96e-5, 1.69e-5 (30, 60, 120 segments; orders 1.99, 2.04;
    4.38e-6 at 240). With the dry part wet (its 22.5 m weighing 8.89 N/m, not 10.99) the top tension
    was 1.15 % light at 30 segments and 1.18 % at 120, converging to that offset."""
    exact = exact_top_tension()
    errors = [abs(top_tension(hanging_case(n)) / exact - 1.0) for n in (30, 60, 120)]
    orders = np.log2(np.array(errors[:-1]) / errors[1:])
    assert errors[-1] < 2.5e-5
    assert np.all(orders > 1.8)


def test_the_planar_and_spatial_models_agree_on_a_line_from_above_the_water():
    planar, spatial = top_tension(hanging_case(40)), top_tension(hanging_case(40, dimensions=3))
    assert spatial == pytest.approx(planar, rel=1e-9)
    assert spatial == pytest.approx(exact_top_tension(), rel=2e-4)


def tow_tension(model: str, segments: int) -> float:
    """The top tension at t = 0 of examples/speed_step_2d.yaml (a sled on 1000 m at 6 kn) towed
    from 5 m above the water."""
    changes = {"vessel.tow_point": [0.0, 0.0, 5.0], "simulation.duration": 1.0, "simulation.output_dt": 1.0,
               "model": model, "cables[0].segments": segments}
    if model == "lumped":
        changes["simulation.scheme"] = "generalized-alpha-lumped"
    return top_tension(kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace(changes))


def test_a_tow_from_above_the_water_converges_to_the_lumped_model_at_second_order():
    """Measured against the lumped model at 960 elements (12081.614 N): relative differences 8.6e-4,
    2.3e-4, 6.0e-5, 1.4e-5 at 30, 60, 120, 240 segments (orders 1.89, 1.95, 2.08); with the dry part
    wet, 3.6e-3 at 30 segments to 2.8e-3 at 480, converging to a 34 N offset instead."""
    lumped = tow_tension("lumped", 960)
    errors = np.array([abs(tow_tension("continuum", n) / lumped - 1.0) for n in (30, 60, 120, 240)])
    orders = np.log2(errors[:-1] / errors[1:])
    assert errors[-1] < 2.5e-5
    assert np.all(orders[:2] > 1.8)


def test_a_speed_step_from_above_the_water_runs_alike_in_the_planar_and_spatial_models():
    """The sled of examples/speed_step_2d.yaml towed from 5 m above the water through its speed step
    (6 to 10 kn at 60 s), 90 s: the crossing moves down the line as it steepens, and the planar and
    spatial models keep the same tension at the vessel at every output (measured: to 1e-12). Newton
    takes at most 4 iterations a step, as with the tow point on the surface (the wet share is a
    constant of each step's iteration)."""
    base = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace(
        {"vessel.tow_point": [0.0, 0.0, 5.0], "simulation.duration": 90.0, "simulation.output_dt": 1.0})
    runs = []
    for dimensions in (2, 3):
        with contextlib.redirect_stdout(io.StringIO()):
            ds = kanat.simulate(base.replace({"simulation.dimensions": dimensions}))
        assert ds.attrs["status"] == "ok"
        assert int(ds["newton_iterations"].max()) <= 4
        runs.append(ds["tension"].values[:, 0])
    np.testing.assert_allclose(runs[1], runs[0], rtol=1e-9)
    assert np.max(runs[0]) > 1.5 * runs[0][0]              # the step did happen (drag at 10 kn)
