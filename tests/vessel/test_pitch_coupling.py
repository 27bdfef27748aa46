"""The tow vessel's pitch as a motion, and the tow point it moves (issue 6.5, theory/vessel.md §2).

Oracles: a stern tow point's height follows ``x sin(phi) + z cos(phi)`` exactly; rate and
acceleration are the finite differences of angle and rate; each mode's motion has the
pitch solver's amplitude and passes through its samples; ``phase_deg`` shifts time.
"""
import math

import numpy as np
import pytest
from pydantic import ValidationError

from kanat.io import load_case
from kanat.model import PitchModel
from kanat.model.problems import STABILIZER_MODES
from kanat.model.vessel import Vessel, VesselPitch
from kanat.vessel.pitch import solve_pitch
from kanat.studies.pitch_tow import (
    rest_phase_deg,
    snap_events,
    statistics_window,
    tension_statistics,
    with_stabilizer_mode,
)
from kanat.vessel.pitch.motion import pitch_motion, series_from_samples
from kanat.vessel.track import VesselTrack

from helpers import EXAMPLES

EXAMPLE = load_case(EXAMPLES / "pitch_tow_6kn.yaml")


def block(mode="rectangular", **changes):
    pitch = with_stabilizer_mode(EXAMPLE, mode).vessel.pitch
    return pitch.model_copy(update=changes)


def as_pitch_model(b):
    """The same ship as a ``model: pitch`` block, for the pitch solver."""
    return PitchModel(**b.model_dump(exclude={"phase_deg", "modes"}))


@pytest.fixture(scope="module")
def motions():
    return {mode: pitch_motion(block(mode)) for mode in STABILIZER_MODES}


def test_the_example_has_a_validated_vessel_pitch_block():
    pitch = EXAMPLE.vessel.pitch
    assert isinstance(pitch, VesselPitch)
    assert pitch.stabilizer.mode == "rectangular" and pitch.omega0 == 0.876 and pitch.phase_deg == 90
    assert Vessel(pitch=None).pitch is None


@pytest.mark.parametrize("bad, message", [
    ({"modes": ["off", "sinusoidal"]}, "'modes' is for model: pitch"),
    ({"natural_frequency": None}, "exactly one of 'natural_frequency'"),
    ({"stabilizer": {"mode": "sideways"}}, "'off', 'sinusoidal', 'rectangular', 'feedback' or 'optimal'"),
])
def test_the_vessel_pitch_block_refuses(bad, message):
    fields = {**EXAMPLE.vessel.pitch.model_dump(), **bad}
    with pytest.raises(ValidationError) as info:
        VesselPitch(**fields)
    assert message in str(info.value)


@pytest.mark.parametrize("mode", STABILIZER_MODES)
def test_a_stern_tow_point_rises_by_lever_arm_times_sin_pitch(mode, motions):
    vessel = EXAMPLE.vessel.model_copy(update={"tow_point": (-60.0, 0.0, 0.0), "pitch": block(mode)})
    track = VesselTrack.from_model(vessel)
    assert isinstance(track.pitch, type(motions[mode]))
    for t in np.linspace(0.0, 20.0, 23):
        angle = track.pitch(t)[0]
        assert track.state(t).position[2] == pytest.approx(-60.0 * math.sin(angle), abs=1e-12)
    example = VesselTrack.from_model(EXAMPLE.vessel)           # tow point [-60, 0, 5]
    angle = example.pitch(7.3)[0]
    assert example.state(7.3).position[2] == pytest.approx(-60 * math.sin(angle) + 5 * math.cos(angle))


@pytest.mark.parametrize("mode", STABILIZER_MODES)
def test_rate_and_acceleration_are_the_derivatives(mode, motions):
    motion, h = motions[mode], 1e-4
    t = np.linspace(0.0, 10.0, 37)
    _, rate, accel = motion.evaluate(t)
    up, down = motion.evaluate(t + h), motion.evaluate(t - h)
    assert np.max(np.abs((up[0] - down[0]) / (2 * h) - rate)) < 1e-7 * np.ptp(rate)
    assert np.max(np.abs((up[1] - down[1]) / (2 * h) - accel)) < 1e-6 * np.ptp(accel)
    track = VesselTrack.from_model(EXAMPLE.vessel.model_copy(update={"pitch": block(mode)}))
    for s in (3.0, 41.7):
        p = [track.state(s + k * h).position for k in (-1, 1)]
        v = [track.state(s + k * h).velocity for k in (-1, 1)]
        assert np.allclose(track.state(s).velocity, (p[1] - p[0]) / (2 * h), atol=1e-7)
        assert np.allclose(track.state(s).acceleration, (v[1] - v[0]) / (2 * h), atol=1e-6)


@pytest.mark.parametrize("mode", STABILIZER_MODES)
def test_the_motion_has_the_amplitude_the_pitch_solver_reports(mode, motions):
    b = block(mode, phase_deg=0.0)
    response = solve_pitch(as_pitch_model(b), modes=(mode,)).responses[mode]
    motion = pitch_motion(b)
    fine = motion.evaluate(np.linspace(0.0, 10.0, 8001))[0]
    assert 0.5 * np.ptp(fine) == pytest.approx(response.amplitude, rel=2e-4)
    exact = 1e-12 if motion.method == "fourier" else 1e-4           # feedback: series of the samples
    assert np.max(np.abs(motion.evaluate(response.time)[0] - response.pitch)) < exact * response.amplitude
    assert motion.method == ("samples" if mode == "feedback" else "fourier")


def test_the_phase_shifts_time(motions):
    motion = motions["sinusoidal"]                                  # phase_deg 90
    at_zero = pitch_motion(block("sinusoidal", phase_deg=0.0))
    t = np.linspace(0.0, 30.0, 61)
    assert np.allclose(motion.evaluate(t)[0], at_zero.evaluate(t + 2.5)[0], atol=1e-14)
    assert motions["off"](0.0)[0] == pytest.approx(-motions["off"].amplitude)      # bow down, at rest
    assert motions["off"](0.0)[1] == pytest.approx(0.0, abs=1e-14)


def test_start_at_rest_finds_a_zero_of_the_pitch_rate():
    for mode in ("off", "rectangular"):                             # symmetric about T/4: rest at 90 deg
        assert rest_phase_deg(block(mode)) == 90.0
    phase = rest_phase_deg(block("feedback"))
    assert 90.0 < phase < 270.0
    assert pitch_motion(block("feedback", phase_deg=phase))(0.0)[1] == pytest.approx(0.0, abs=1e-12)


def test_from_model_takes_a_given_pitch_over_the_block_and_none_without_one():
    def hook(t):
        return 0.01, 0.0, 0.0

    assert VesselTrack.from_model(EXAMPLE.vessel, hook).pitch is hook
    assert VesselTrack.from_model(EXAMPLE.vessel.model_copy(update={"pitch": None})).pitch is None


def test_series_from_samples_recovers_harmonics():
    omega, m = 0.6283, 400
    t = np.linspace(0.0, 2 * np.pi / omega, m + 1)
    values = 0.3 + 0.2 * np.cos(omega * t) - 0.05 * np.sin(3 * omega * t)
    s = series_from_samples(values, omega, 10)
    assert s.mean == pytest.approx(0.3) and s.cos[0] == pytest.approx(0.2) and s.sin[2] == pytest.approx(-0.05)
    assert np.allclose(s(t), values, atol=1e-14)


def test_snap_events_count_completed_drops_below_the_threshold():
    time = np.arange(10.0)
    tension = np.array([10, 10, 0.2, 10, 10, 0.1, 0.1, 10, 10, 0.3])
    assert list(snap_events(time, tension, 0.5)) == [3.0, 7.0]     # the last drop never returns
    stats = tension_statistics(time, tension, 0.0)
    assert stats.snaps == 2 and stats.threshold == pytest.approx(0.05 * tension.mean())
    assert stats.range == pytest.approx(9.9)


def test_the_statistics_window_is_whole_wave_periods_ending_at_the_end():
    assert statistics_window(360.0, 10.0) == (120.0, 360.0)
    assert statistics_window(365.0, 10.0, transient=100.0) == (105.0, 365.0)
    with pytest.raises(Exception, match="less than one wave period"):
        statistics_window(50.0, 10.0, transient=45.0)
