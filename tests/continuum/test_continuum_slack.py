"""Transient slack in the continuum model (``simulation.slack``, ``simulation.tension_floor``):

* the tension floor of the normal rows (:func:`kanat.continuum.loads2d.transverse_tension`): ``T``
  itself above the floor, C1 at it, ``T_f / 2`` at full compression; the kernels' exact Jacobian
  with intervals below the floor against the complex-step oracle;
* the slack log (:class:`kanat.continuum.slack.SlackLog`) on a written-out tension history;
* a buoy tethered 18 m above its anchor in 3 m waves, whose tether goes slack for a moment near the
  anchor in each wave: the run goes through with ``status: ok``, records the events (result
  variables, attribute, note), and the tension at the buoy agrees with the lumped model's ``rk4``
  (whose elements carry no compression) on the same case: mean within 1 %, extremes within 5 %;
* ``slack: stop`` stops the same run at the first compression, as before; a tow stopped dead goes
  on through its moment of compression;
* a chain rising vertically from the seabed under a buoy in still water (slack where it lies): the
  run starts from a small pull on the buoy, against the elastic catenary on the seabed, and holds
  the buoy with its buoyancy as the lumped model's equilibrium does.
"""
import warnings

import numpy as np
import pytest

from kanat import api, load_case
from kanat.continuum import kernels2d as k
from kanat.continuum import oracle_complex_step2d
from kanat.continuum.model2d import EndCondition, parameters
from kanat.continuum.slack import SlackLog
from kanat.model import Case
from kanat.statics.catenary import elastic_catenary

N = 12


def kernel_args(seed, end_kind):
    """A random planar state of 12 intervals (tensions 12 to 7 kN) and its step data, as the kernel tests'."""
    rng = np.random.default_rng(seed)
    p = parameters(1.12, 0.24, 8.89, 1.2717e7, 0.0173, 1.5, 0.01, 1025.0, 10.0)
    p[[k.AM, k.AK, k.GAMMA, k.DT]] = 1 / 6, 1 / 3, 2 / 3, 0.7
    y = np.column_stack([np.linspace(12e3, 7e3, N + 1), rng.normal(2.0, 0.5, N + 1),
                         rng.normal(-0.5, 0.5, N + 1), rng.normal(-2.9, 0.3, N + 1)])
    x = y + rng.normal(0, 1, y.shape) * [50.0, 0.05, 0.05, 0.01]
    d = rng.normal(0, 1, y.shape) * [20.0, 0.1, 0.1, 0.01]
    env = np.zeros((N + 1, k.NENV))
    env[:, [k.UX, k.UZ]] = rng.normal(0, 0.3, (N + 1, 2))
    b0 = EndCondition(k.VELOCITY).array((3.0, 0.2))
    b1 = {"body": EndCondition(k.BODY, 1135.0, -6686.0, 0.3276, (0.0, -500.0)),
          "free": EndCondition(k.FREE), "anchor": EndCondition(k.VELOCITY)}[end_kind].array((0.0, 0.0))
    return x, y, d, env, np.tile(p, (N, 1)), b0, b1


def assemble(kernel, args):
    res, band = np.empty(args[0].size), np.empty((11, args[0].size))
    if kernel is k.assemble:
        kernel(args[0], k.PlanarStep(*args[1:], None), res, band)
    else:
        kernel(*args, res, band)
    return res, band


def test_the_floor_leaves_tension_above_it_and_is_smooth_at_it():
    p = np.zeros(k.NPAR + 5)
    p[k.TFLOOR] = 4.0
    for T in (4.0, 10.0, 1e4):
        assert k.transverse_tension(T, p) == (T, 1.0)
    below, slope = k.transverse_tension(4.0 - 1e-7, p)
    assert below == pytest.approx(4.0 - 1e-7, abs=1e-12) and slope == pytest.approx(1.0, abs=1e-6)
    assert k.transverse_tension(-1e6, p)[0] == pytest.approx(2.0, abs=1e-12)        # T_f / 2
    held = [k.transverse_tension(T, p)[0] for T in np.linspace(-50.0, 4.0, 200)]
    assert np.all(np.diff(held) > 0) and min(held) > 2.0                        # monotone, above T_f / 2
    p[k.TFLOOR] = 0.0
    assert k.transverse_tension(-30.0, p) == (-30.0, 1.0)                         # no floor: T


@pytest.mark.parametrize("end", ["body", "free", "anchor"])
def test_the_jacobian_below_the_floor_matches_complex_step(end):
    args = kernel_args(2, end)
    x, y, P = args[0], args[1], args[4]
    P[:, k.TFLOOR] = 9.0e3                     # tensions 7-12 kN: intervals on both sides of the floor
    x[5:8, 0], y[5:8, 0] = -300.0, -250.0      # and some in compression
    res, band = assemble(k.assemble, args)
    res2, band2 = assemble(oracle_complex_step2d.jacobian_complex_step, args)
    np.testing.assert_allclose(res, res2, rtol=1e-13, atol=1e-10)
    assert np.max(np.abs(band - band2)) <= 1e-12 * np.max(np.abs(band2))
    P[:, k.TFLOOR] = 0.0
    plain, _ = assemble(k.assemble, args)
    assert np.max(np.abs(plain - res)) > 1.0                                   # the floor acted


def test_the_slack_log_keeps_each_event_and_its_lowest_tension():
    log = SlackLog()
    history = [(0.1, [5.0, 3.0, 4.0]), (0.2, [5.0, -2.0, 4.0]), (0.3, [-6.0, -1.0, 4.0]), (0.4, [-1.0, 2.0, 4.0]),
               (0.5, [1.0, 2.0, 4.0]), (0.6, [1.0, 2.0, -0.5]), (0.7, [1.0, 2.0, -0.01])]
    for t, tension in history:
        log.observe(t, np.array(tension), np.zeros(3), 0.1)
    np.testing.assert_allclose(log.events, [[0.2, 0.4, 0, -6.0], [0.6, 0.6, 2, -0.5]])
    again = SlackLog(log.events)                                             # a resumed run's
    np.testing.assert_array_equal(again.events, log.events)
    assert "went slack 2 time(s)" in log.note(np.array([0.0, 1.0, 2.0]), "tether")
    assert SlackLog().note(np.zeros(3), "tether") is None


def tethered_buoy(model, slack="continue", scheme=None):
    """A small buoy (net buoyancy 95 N, drag area 0.5 m^2) on 18 m of light rope from an anchor in 30 m
    of water, in regular waves of 3 m and 8 s: the drag of the wave's downward flow over the buoy
    exceeds its buoyancy for a moment in each wave, and the lower tether goes slack."""
    rope = dict(diameter=0.02, mass=0.5, weight_in_water=2.0, axial_stiffness=2e6,
                drag_normal=1.2, drag_tangential=0.02, added_mass=0.3)
    simulation = {"duration": 40.0, "dt": 0.02, "output_dt": 0.1, "slack": slack}
    if scheme:
        simulation.update(scheme=scheme, dt=None)
    return Case.model_validate(dict(
        model=model, environment={"depth": 30.0, "waves": {"type": "regular", "height": 3.0, "period": 8.0}},
        line_types={"rope": rope},
        bodies={"buoy": {"mass": 10.0, "net_buoyancy": 95.0, "drag_area": 0.5, "added_mass": 10.0}},
        cables=[dict(name="tether", line_type="rope", length=18.0, segments=20,
                     **{"from": "anchor:[0, 0, -30]"}, to="buoy")],
        simulation=simulation))


def simulate(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return api.run(case)


@pytest.fixture(scope="module")
def slack_run():
    return simulate(tethered_buoy("continuum"))


def test_a_tether_going_slack_in_waves_runs_through_and_says_so(slack_run):
    summary, ds = slack_run.summary, slack_run.dataset
    assert summary.ok, summary.status
    count = int(ds.attrs["slack_events"])
    assert count >= 3 and ds.sizes["slack_event"] == count                 # about one a wave
    start, end = ds.slack_start.values, ds.slack_end.values
    assert np.all(end >= start) and np.all(start[1:] > end[:-1]) and start[0] > 0.0
    assert np.all(ds.slack_tension.values < 0.0)
    assert -0.1 * 95.0 < ds.slack_tension.values.min()                   # a small compression
    assert np.all(ds.slack_node.values < 10)                                # the lower tether
    note = next(n for n in summary.notes if n.startswith("slack:"))
    assert f"went slack {count} time(s)" in note and "slack" in ds.attrs["notes"]
    lowest = ds.tension.values.min()
    assert lowest < 0.0 and lowest >= ds.slack_tension.values.min() - 1e-9   # outputs within the log


@pytest.mark.slow
def test_the_tension_at_the_buoy_agrees_with_the_lumped_model(slack_run):
    lumped = simulate(tethered_buoy("lumped", scheme="rk4"))
    assert lumped.summary.ok, lumped.summary.status
    ours, theirs = slack_run.dataset.tension.values[:, -1], lumped.dataset.tension.values[:, -1]
    assert lumped.dataset.tension.values[:, 0].min() == 0.0                 # slack in the lumped model too
    assert np.mean(ours) == pytest.approx(np.mean(theirs), rel=0.01)
    assert np.max(ours) == pytest.approx(np.max(theirs), rel=0.05)
    # The lowest tension is not compared: it falls inside the slack events, where the continuum run
    # carries a floored compression and the lumped elements none, and it moved from +7.5 % to -43 % of
    # the lumped model's when that model's drag went to each end's own velocity (both runs still 'ok';
    # the buoy's missing Froude-Krylov term in the lumped model is the other difference, noted there).


def test_slack_stop_ends_the_run_at_the_first_compression(slack_run):
    stopped = simulate(tethered_buoy("continuum", slack="stop"))
    assert stopped.summary.status.startswith("failed: the cable went into compression")
    assert "slack_events" not in stopped.dataset.attrs
    first = slack_run.dataset.slack_start.values[0]
    assert stopped.dataset.time.values[-1] == pytest.approx(first, abs=0.1 + 1e-9)


def test_a_tow_stopped_dead_records_its_slack_and_goes_on():
    """10 kn to 0 in one step of 1 s: the top goes into compression for that step, then the cable hangs
    from the stopped vessel again (its top tension the hanging weight, below the 10 kn tow's)."""
    from helpers import step_case_text

    text = step_case_text(duration=60, before=20, to_kn=0).replace("speed_kn: 6", "speed_kn: 10")
    result = simulate(load_case(text))
    ds = result.dataset
    assert result.summary.ok, result.summary.status
    assert int(ds.attrs["slack_events"]) == 1 and ds.slack_start.values[0] == pytest.approx(20.0)
    assert ds.slack_tension.values[0] < 0.0 and ds.slack_node.values[0] == 0
    top = ds.tension.values[:, 0]
    assert np.all(top[ds.time.values > 20.5] > 0.0) and top[-1] < 0.6 * top[0]


def grounded_buoy(model, duration=20.0):
    """A chain (77 N/m in water, 80 m) from an anchor in 50 m of water to a buoy of 2000 N net buoyancy,
    in still water: it rises vertically under the buoy (2000 / 77 = 26 m of it) and the rest lies slack
    on the seabed, wherever the buoy drifts."""
    chain = dict(diameter=0.04, mass=9.0, weight_in_water=77.0, axial_stiffness=8.0e7, added_mass=1.3,
                 drag_normal=2.4, drag_tangential=0.4)
    simulation = {"duration": duration, "dt": 0.1, "output_dt": 1.0}
    return Case.model_validate(dict(
        model=model, environment={"depth": 50.0, "seabed": {"stiffness": 3.0e6, "damping": 3.0e5}},
        line_types={"chain": chain},
        bodies={"buoy": {"mass": 100.0, "net_buoyancy": 2000.0, "drag_area": 1.0, "added_mass": 100.0}},
        cables=[dict(name="riser", line_type="chain", length=80.0, segments=40,
                     **{"from": "anchor:[-40, 0, -50]"}, to="buoy")],
        simulation=simulation))


@pytest.fixture(scope="module")
def grounded_run():
    return simulate(grounded_buoy("continuum"))


def test_a_slack_grounded_line_starts_from_a_small_pull(grounded_run):
    """The start is the steady state under a pull of 1 % of the chain's weight (61.6 N): the elastic
    catenary on the seabed between the anchor and that start's buoy has that horizontal tension and the
    start's top tension; released, the buoy drifts back and its line carries its buoyancy."""
    summary, ds = grounded_run.summary, grounded_run.dataset
    assert summary.ok, summary.status
    assert any("lies slack on the seabed" in note and "61.6 N" in note for note in summary.notes)
    buoy = ds.body_position.values[0, 0]
    exact = elastic_catenary(buoy[0] + 40.0, buoy[2] + 50.0, 80.0, 77.0, 8.0e7, seabed=True)
    assert exact.horizontal_tension == pytest.approx(0.01 * 77.0 * 80.0, rel=0.05)
    assert ds.tension.values[0, -1] == pytest.approx(exact.tension_upper, rel=0.01)
    assert ds.tension.values[-1, -1] == pytest.approx(2000.0, rel=0.005)      # the buoy's line holds it
    assert ds.body_position.values[-1, 0, 0] < buoy[0] - 2.0                     # drifting back, pull gone


@pytest.mark.slow
def test_a_slack_grounded_line_agrees_with_the_lumped_equilibrium(grounded_run):
    lumped = simulate(grounded_buoy("lumped", duration=1.0))
    assert lumped.summary.ok, lumped.summary.status
    theirs = lumped.dataset
    assert theirs.tension.values[0, 0] == 0.0                                  # slack on the seabed
    ours = grounded_run.dataset
    assert ours.tension.values[-1, -1] == pytest.approx(theirs.tension.values[0, -1], rel=0.005)
    assert ours.body_position.values[-1, 0, 2] == pytest.approx(theirs.body_position.values[0, 0, 2], abs=1.0)


def test_slack_stop_keeps_refusing_a_slack_grounded_line():
    case = grounded_buoy("continuum")
    case = case.model_copy(update={"simulation": case.simulation.model_copy(update={"slack": "stop"})})
    result = simulate(case)
    assert result.summary.status.startswith("failed: no initial state") and "slack" in result.summary.status
