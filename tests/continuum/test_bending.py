"""Bending stiffness in the planar continuum model (Gobat & Grosenbaugh's curvature term, theory/moorings.md §6):
a cantilever's deflection, a beam-string's natural frequencies, the flexible limit, and what the
model does with compression (3-D: tests/continuum/test_bending3d.py)."""
import warnings

import numpy as np
import pytest

import kanat
from kanat.continuum import kernels2d as k
from kanat.continuum.grid import Grid, parameters
from kanat.continuum.model2d import EndCondition, PlanarCable, positions
from kanat.continuum.models import model_for
from kanat.continuum.schemes import Box
from kanat.continuum.stepper import State, steady, step

from helpers import EXAMPLES, zero_crossing_period

STEP_CASE = (EXAMPLES / "speed_step_2d.yaml").read_text()


def beam(n, length, mass, weight, ei, start, end, ea=1e9):
    p = parameters(mass, 0.0, weight, ea, 0.05, 0.0, 0.0, 1025.0, length / n, bending=ei)
    grid = Grid(np.linspace(0.0, length, n + 1), np.tile(p, (n, 1)), (), ("beam",))
    return PlanarCable("beam", length, n, p, start, end, grid=grid)


@pytest.mark.parametrize("segments", [10, 40])
def test_cantilever_deflects_as_euler_bernoulli(segments):
    """Clamped horizontally, free tip, own weight w: tip deflection w L^4 / (8 EI), root moment w L^2 / 2."""
    length, w, ei = 10.0, 1.0, 1.0e4
    cable = beam(segments, length, 0.5, w, ei, EndCondition(k.VELOCITY, clamped=True, angle=0.0), EndCondition(k.FREE))
    xz = np.column_stack([np.linspace(0.0, length, segments + 1), np.zeros(segments + 1)])
    y = steady(cable, np.zeros((segments + 1, 6)), ((0.0, 0.0), (0.0, 0.0)), xz)
    tip = positions(cable, y, (0.0, 0.0))[-1]
    assert tip[1] == pytest.approx(-w * length**4 / (8 * ei), rel=1e-3)    # 1.25 % of L: 1e-4 nonlinear
    assert y[0, 5] == pytest.approx(-w * length**2 / 2, rel=1e-3)
    assert y[0, 4] == pytest.approx(-w * length, rel=1e-3)                  # root shear


class Hold:
    def velocities(self, t):
        return (0.0, 0.0), (0.0, 0.0)

    def origin(self, t):
        return np.zeros(2)


@pytest.mark.parametrize("mode", [1, 2, 3])
def test_beam_string_natural_frequencies(mode):
    """Pinned taut string with EI: omega^2 = (T k^2 / (1 + e) + EI k^4 / (1 + e)^2) / m, k = n pi / L."""
    n, length, tension, m, ea, ei = 60, 100.0, 1000.0, 1.0, 1e7, 1e5
    cable = beam(n, length, m, 0.0, ei, EndCondition(k.VELOCITY, position=(0.0, 0.0)),
                 EndCondition(k.VELOCITY, position=(length, 0.0)), ea)
    s = cable.s
    y = np.zeros((n + 1, 6))
    y[:, 0] = tension
    y[:, 2] = 1e-3 * np.sin(mode * np.pi * s / length)                     # the mode shape, as a velocity
    state = State(0.0, y, np.zeros_like(y), np.column_stack([s, 0 * s]))
    e, kk = tension / ea, mode * np.pi / length
    omega = np.sqrt((tension * kk**2 / (1 + e) + ei * kk**4 / (1 + e) ** 2) / m)
    dt, probe = 2 * np.pi / omega / 80, n // (2 * mode)
    times, values = [], []
    for _ in range(600):
        state, _ = step(cable, state, dt, Box().coefficients(), Hold())
        times.append(state.t)
        values.append(state.y[probe, 2])
    measured = 2 * np.pi / zero_crossing_period(np.array(times), np.array(values))
    assert measured == pytest.approx(omega, rel=0.01)
    string = np.sqrt(tension * kk**2 / (1 + e) / m)
    assert omega / string - 1 > 0.04                                        # bending matters: 4.8 % up to 77 %


def with_bending(text, ei, segments=100):
    return text.replace("segments: 100", f"segments: {segments}").replace(
        "    drag_tangential: 0.01\n", f"    drag_tangential: 0.01\n    bending_stiffness: {ei}\n", 1)


def test_no_bending_stiffness_is_the_flexible_model_exactly():
    plain = model_for(kanat.load_case(STEP_CASE))
    zero = model_for(kanat.load_case(with_bending(STEP_CASE, 0.0)))
    assert plain.cable.nv == zero.cable.nv == 4
    a, b = plain.initial(), zero.initial()
    assert np.array_equal(a.y, b.y) and np.array_equal(a.xz, b.xz)


def test_vanishing_bending_stiffness_converges_to_the_flexible_model():
    """EI = 1e-3 N m^2: the bending model's steady tow differs from the flexible one by a discretization
    error that falls with the grid (about 16 times per halving of ds)."""
    differences = []
    for segments in (50, 100, 200):
        flexible = model_for(kanat.load_case(STEP_CASE.replace("segments: 100", f"segments: {segments}"))).initial()
        stiff = model_for(kanat.load_case(with_bending(STEP_CASE, 1e-3, segments))).initial()
        assert stiff.y.shape[1] == 6
        differences.append(np.max(np.abs(stiff.y[:, 0] - flexible.y[:, 0])) / flexible.y[:, 0].max())
    assert differences[2] < 1e-7
    assert differences[0] / differences[1] > 8 and differences[1] / differences[2] > 8


def test_compression_beyond_a_segments_euler_load_stops_the_run():
    """A line with EI is a rod: it may carry compression up to the Euler load of one segment; a run
    pushed beyond it stops (simulation.slack: stop), and says so, with what to do."""
    from kanat.continuum.adapter import ContinuumModel

    model = ContinuumModel(kanat.load_case(with_bending(STEP_CASE, 50.0, 20) + "  slack: stop\n"))
    state = model.initial()
    values = model.outputs(state)
    assert model.check(state, values) is None
    values["tension"] = values["tension"].copy()
    euler = np.pi**2 * 50.0 / (2 * 50.0) ** 2
    values["tension"][5] = -0.5 * euler                        # within the rod's reach
    values["tension"][-1] = -0.5 * euler                       # the end nodes too
    assert model.check(state, values) is None
    values["tension"][5] = -2.0 * euler - 1e-3 * np.max(values["tension"])
    message = model.check(state, values)
    assert "compression" in message and "Euler load of one segment" in message and "use more segments" in message
    assert "(at most 35.4 m long, now 50 m)" in message          # 1/sqrt(2) as long: twice the Euler load
    flexible = ContinuumModel(kanat.load_case(STEP_CASE.replace("segments: 100", "segments: 20") + "  slack: stop\n"))
    values["tension"][5] = -0.01 * np.max(values["tension"])
    assert "perfectly flexible cable cannot carry" in flexible.check(flexible.initial(), values)


def test_a_bending_case_runs_and_stays_steady():
    text = with_bending(STEP_CASE, 300.0).replace("duration: 600\n", "duration: 20\n").replace(
        "speed_kn: 6, duration: 60", "speed_kn: 6, duration: 100")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(text))
    assert ds.attrs["status"] == "ok"
    drift = np.max(np.abs(ds.tension.values[-1] - ds.tension.values[0])) / ds.tension.values.max()
    assert drift < 1e-9


STOP = """
name: tow-stops
model: continuum
line_types:
  towcable: {diameter: 0.0173, mass: 1.12, weight_in_water: 8.89, axial_stiffness: 1.2717e7, added_mass: 0.24,
             drag_normal: 1.5, drag_tangential: 0.01, bending_stiffness: 50}
bodies:
  sled: {mass: 1135, net_buoyancy: -6686, drag_area: 0.3276}
vessel:
  tow_point: [0, 0, 0]
  track:
    - {straight: {speed_kn: 10, duration: 5}}
    - {speed_step: {to_speed_kn: 0}}
    - {straight: {duration: 60}}
cables:
  - {name: tow, line_type: towcable, length: 200, segments: SEG, from: vessel, to: sled}
simulation: {scheme: generalized-alpha, duration: 60, dt: 0.5, output_dt: 0.5, dimensions: 2, slack: stop}
"""


@pytest.mark.parametrize("segments, grid", [(20, "0.151 m, now 10 m"), (200, "0.118 m, now 1 m")])
def test_a_tow_stopping_dead_goes_slack_and_the_run_says_so(segments, grid):
    """A 10 kn tow stopping dead in 0.5 s: the sled runs on up the cable, kilonewtons of compression in a line of
    EI = 50 N m^2 whose segments' Euler loads are 1.2 N (10 m) and 123 N (1 m). No grid carries that (at 1000
    segments the compression is still -5168 N, at 2000 Newton fails): the run stops and says the line goes
    slack, for the lumped model, not "more segments". Measured: T = -5415 N with 20 segments (a segment of
    0.151 m would carry it: 66 times shorter), -8940 N with 200 (0.118 m: 6.8 diameters)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(STOP.replace("SEG", str(segments))))
    status = ds.attrs["status"]
    assert status.startswith("failed: the cable went into compression") and "at t = 5 s" in status
    assert float(status.split("(T = ")[1].split(" N")[0]) < -5000.0
    assert "the line goes slack" in status and "more segments cannot resolve" in status
    assert "model: lumped, which carries slack" in status and "use more segments" not in status
    assert "times the Euler load of the whole line (pi^2 EI / L^2 = 0.0123 N)" in status
    assert f"segments of {grid}" in status
    assert ds.time.values[-1] == 5.0 and np.all(ds.tension.values[0] > 0)      # kept up to the failure



def test_the_stop_on_a_grid_of_2000_segments_says_the_line_goes_slack():
    """At 10 cm segments (5.8 diameters) the rod's Euler load counts a segment as 10 diameters long (4122 N,
    not the 12.3 kN of a 10 cm column, which Euler's slender-column load does not describe): the stop's
    -5167 N fails the run with the slack message and the lumped model (it said ``ok`` once the tow point's
    dry share was counted, where Newton had failed before)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(STOP.replace("SEG", "2000")))
    status = ds.attrs["status"]
    assert status.startswith("failed: the cable went into compression") and "at t = 5 s" in status
    assert "one segment (4122 N, a segment counted 10 diameters long)" in status
    assert "the line goes slack" in status and "model: lumped, which carries slack" in status
