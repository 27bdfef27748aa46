"""The winch (theory/moorings.md §9; WHOI Cable's pay-out): the first interval grows from the winch and is split
every segment length, or shrinks and merges when hauling in. Oracles: the length (and mass) of cable in
the water is the schedule's, a slow lowering follows the statics at each length within 0.5 %, a tow
paying out settles on the statics of its final length, and a checkpoint restores the moving grid
exactly."""
import warnings

import numpy as np
import pytest

import kanat
from kanat.continuum import kernels2d as k
from kanat.continuum.adapter import ContinuumModel

LOWERING = """
name: winch-lowering
model: continuum
environment: {water_density: 1025, depth: 3000}
line_types:
  wire: {diameter: 0.0173, mass: 1.12, weight_in_water: 8.89, axial_stiffness: 1.2717e7, added_mass: 0.24,
         drag_normal: 1.5, drag_tangential: 0.01}
bodies:
  sled: {mass: 1135, net_buoyancy: -6686, drag_area: 0.3276, added_mass: 500}
vessel:
  tow_point: [0, 0, 0]
  track:
    - {straight: {speed: 0, duration: 3000}}
cables:
  - {name: wire, line_type: wire, length: 500, segments: 50, from: vessel, to: sled}
winch:
  - {start: 10, duration: 2000, rate: 0.1}
simulation: {scheme: generalized-alpha, duration: 2100, dt: 1.0, output_dt: 100, dimensions: 2}
"""


def run(text):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.simulate(kanat.load_case(text))


def test_slow_lowering_follows_the_statics_at_each_length():
    """Lowering at 0.1 m/s: the winch tension is the weight in water of the body and the cable paid out,
    ``6686 + w L(t)`` (statics of each length), within 0.5 % (0.03 % measured)."""
    ds = run(LOWERING)
    assert ds.attrs["status"] == "ok"
    length, tension = ds.winch_length.values, ds.winch_tension.values
    assert length[0] == 500.0 and length[-1] == pytest.approx(700.0, rel=1e-12)
    statics = 6686.0 + 8.89 * length
    assert np.max(np.abs(tension / statics - 1)) < 0.005
    depth = -ds.body_position.sel(body="sled", xyz="z").values
    stretch = np.array([np.sum(8.89 * np.linspace(0, L, 1001) + 6686.0) * L / 1001 / 1.2717e7 for L in length])
    assert np.max(np.abs(depth - (length + stretch))) < 0.005 * length.min()


TOW_PAYOUT = LOWERING.replace("speed: 0, duration: 3000", "speed_kn: 6, duration: 1500").replace(
    "length: 500, segments: 50", "length: 600, segments: 60").replace(
    "{start: 10, duration: 2000, rate: 0.1}", "{start: 10, duration: 200, rate: 1.0}").replace(
    "duration: 2100, dt: 1.0, output_dt: 100", "duration: 1500, dt: 1.0, output_dt: 100")


def test_a_tow_paying_out_settles_on_the_statics_of_the_final_length():
    """A 6 kn tow pays out 600 -> 800 m at 1 m/s, then tows on: the sled sinks from 224.5 m past its new
    depth (318 m at the end of the pay-out) and settles on the statics of an 800 m cable, within 0.1 %
    (measured after 1500 s: top tension 11158.1 vs 11157.0 N, 0.009 %; depth 277.045 vs 277.077 m, -0.012 %)."""
    ds = run(TOW_PAYOUT)
    assert ds.attrs["status"] == "ok"
    assert ds.winch_length.values[-1] == pytest.approx(800.0, rel=1e-12)
    statics_text = TOW_PAYOUT.replace("model: continuum", "model: statics").replace(
        "length: 600, segments: 60", "length: 800, segments: 80").replace(
        "winch:\n  - {start: 10, duration: 200, rate: 1.0}\n", "")
    statics = kanat.solve_statics(kanat.load_case(statics_text))
    tension, depth = ds.winch_tension.values, -ds.body_position.sel(body="sled", xyz="z").values
    expected_depth = -float(statics.body_position.sel(body="sled", xyz="z"))
    assert depth[0] < expected_depth - 50.0 and depth.max() > expected_depth + 30.0   # it moved, and overshot
    assert tension[-1] == pytest.approx(float(statics.tension.values[0]), rel=1e-3)
    assert depth[-1] == pytest.approx(expected_depth, rel=1e-3)
    assert abs(tension[-1] / tension[-2] - 1) < 1e-4                                   # settled


PAYOUT_AND_HAUL = LOWERING.replace("  - {start: 10, duration: 2000, rate: 0.1}\n",
                                   "  - {start: 10, duration: 100, rate: 1.0}\n"
                                   "  - {start: 200, duration: 130, rate: -0.5}\n").replace(
    "duration: 2100, dt: 1.0, output_dt: 100", "duration: 400, dt: 0.5, output_dt: 10")


def test_the_cable_in_the_water_is_the_schedules_and_its_grid_follows():
    """Mass conservation: the unstretched length held by the grid (so the mass ``m L``) is the initial
    length plus what the schedule paid out, through splits (pay-out) and merges (haul-in)."""
    case = kanat.load_case(PAYOUT_AND_HAUL)
    model = ContinuumModel(case)
    winch = model.cable_model.cable.winch
    state = model.initial()
    lengths, counts = [], []
    for t_end in np.arange(10.0, 401.0, 10.0):
        state, _ = model.advance(state, t_end)
        rows = state.rows
        cable = rows[rows[:, k.KIND] != k.JUNCTION]
        lengths.append((t_end, float(np.sum(cable[:, k.DS]))))
        counts.append(len(state.y))
        assert np.all(cable[1:, k.DS] == pytest.approx(winch.segment))        # interior nodes on the material grid
        assert 0.5 * winch.segment <= cable[0, k.DS] <= 1.5 * winch.segment   # the first interval in bounds
    for t, held in lengths:
        assert held == pytest.approx(500.0 + winch.paid(t), abs=1e-9)
    assert max(counts) == 61 and counts[-1] in (54, 55)               # 100 m out: 10 nodes; 65 m in
    mass = 1.12 * np.array([held for _, held in lengths])
    assert mass[-1] == pytest.approx(1.12 * (500.0 + 100.0 - 65.0), abs=1e-9)


def test_outputs_sit_on_fixed_material_stations():
    ds = run(PAYOUT_AND_HAUL)
    assert ds.attrs["status"] == "ok"
    s = ds.s.values
    assert s[0] == 0.0 and np.all(np.diff(s[1:]) > 0) and s[1] < 0        # stations paid out later: negative s
    on_drum = ds.position.isel(time=0).values[1:][s[1:] < 0]
    assert np.allclose(on_drum, ds.position.isel(time=0).values[0])       # at the winch before they are paid out
    assert ds.winch_tension.values[0] == pytest.approx(ds.tension.isel(time=0, node=0).item())


def test_a_checkpoint_restores_the_moving_grid():
    model = ContinuumModel(kanat.load_case(PAYOUT_AND_HAUL))
    state, _ = model.advance(model.initial(), 60.0)
    again = model.restore(model.save(state))
    a, _ = model.advance(state, 80.0)
    b, _ = model.advance(again, 80.0)
    assert np.array_equal(a.y, b.y) and np.array_equal(a.rows, b.rows) and np.array_equal(a.s, b.s)
