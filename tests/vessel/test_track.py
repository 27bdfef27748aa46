"""Vessel track kinematics (theory/vessel.md §1) against closed forms and finite differences."""
import math

import numpy as np
import pytest
from scipy.constants import knot

from kanat.errors import CaseError
from kanat.io import parse_case
from kanat.vessel.track import VesselTrack

KN = knot


def track(segments: str, tow_point="[0, 0, 0]") -> VesselTrack:
    text = f"name: t\nmodel: lumped\nvessel:\n  tow_point: {tow_point}\n  track:\n{segments}"
    text += "line_types: {w: {diameter: 0.01, mass: 1, axial_stiffness: 1e6}}\n"
    text += "cables: [{name: c, line_type: w, length: 100, segments: 2, from: vessel, to: 'anchor:[-5, 0, -5]'}]\n"
    text += "simulation: {duration: 1}\n"           # a lumped case: its tow point may be off y = 0
    return VesselTrack.from_model(parse_case(text).vessel)


def test_straight_then_accelerate_then_hold():
    tr = track("    - {straight: {speed: 2.0, duration: 10}}\n"
               "    - {accelerate: {to_speed: 4.0, acceleration: 0.5, duration: 10}}\n")
    assert tr.state(10.0).position[0] == pytest.approx(20.0)
    assert tr.state(14.0).speed == pytest.approx(4.0)
    assert tr.state(14.0).position[0] == pytest.approx(20.0 + 2 * 4 + 0.25 * 16)
    assert tr.state(17.0).acceleration[0] == pytest.approx(0.0)
    assert tr.duration == pytest.approx(20.0)
    assert tr.state(25.0).position[0] == pytest.approx(tr.state(20.0).position[0] + 20.0)  # straight on


def test_speed_step_is_instant():
    tr = track("    - {straight: {speed: 1.0, duration: 300}}\n    - {speed_step: {to_speed: 4.0}}\n"
               "    - {straight: {duration: 100}}\n")
    assert tr.state(299.999).speed == pytest.approx(1.0)
    assert tr.state(300.0).speed == pytest.approx(4.0)
    assert tr.state(350.0).position[0] == pytest.approx(300.0 + 200.0)


def test_turn_375_stays_on_its_circle_and_ends_at_375_degrees():
    radius, speed = 640.08, 18.5 * KN
    tr = track(f"    - {{straight: {{speed_kn: 18.5, duration: 1}}}}\n"
               f"    - {{turn: {{radius: {radius}, angle_deg: 375}}}}\n    - {{straight: {{duration: 300}}}}\n")
    turn = tr.phases[2]
    assert turn.duration == pytest.approx(math.radians(375) * radius / speed)
    centre = np.array([speed * 1.0, radius])                  # to port of the start point
    for t in np.linspace(1.0, 1.0 + turn.duration, 13):
        assert np.linalg.norm(tr.state(t).position[:2] - centre) == pytest.approx(radius, rel=1e-12)
    end = tr.state(1.0 + turn.duration + 100.0)
    assert math.degrees(end.heading) == pytest.approx(375.0)
    assert end.speed == pytest.approx(speed)


@pytest.mark.parametrize("t", [0.5, 31.0, 200.0, 480.0, 700.0])
def test_tow_point_velocity_and_acceleration_are_derivatives_of_position(t):
    tr = track("    - {straight: {speed: 3.0, duration: 10}}\n"
               "    - {accelerate: {to_speed: 5.0, acceleration: 0.1}}\n"
               "    - {turn: {radius: 300, angle_deg: -90}}\n"
               "    - {heading: {change_deg: 45, rate_deg_s: 0.5}}\n", tow_point="[-40, 3, 2]")
    h = 1e-4
    p = [tr.state(t + k * h).position for k in (-1, 0, 1)]
    v = [tr.state(t + k * h).velocity for k in (-1, 0, 1)]
    assert np.allclose(tr.state(t).velocity, (p[2] - p[0]) / (2 * h), atol=1e-6)
    assert np.allclose(tr.state(t).acceleration, (v[2] - v[0]) / (2 * h), atol=1e-5)
    assert tr.state(t).position[2] == 2.0


def test_heading_to_absolute_value_takes_the_short_way():
    tr = track("    - {straight: {speed: 2.0, duration: 1}}\n    - {heading: {to_deg: -30, rate_deg_s: 1}}\n")
    assert tr.phases[-1].duration == pytest.approx(30.0)
    assert math.degrees(tr.state(100.0).heading) == pytest.approx(-30.0)


def test_turn_of_given_radius_from_rest_is_refused():
    with pytest.raises(CaseError, match="speed > 0"):
        track("    - {turn: {radius: 100, angle_deg: 90}}\n")


def test_pitch_moves_a_stern_tow_point_with_consistent_derivatives():
    tr = track("    - {straight: {speed: 3.0, duration: 10}}\n    - {turn: {radius: 300, angle_deg: 90}}\n",
               tow_point="[-60, 2, 5]")
    amplitude, omega = 0.05, 0.6283
    tr.pitch = lambda t: (amplitude * np.sin(omega * t), amplitude * omega * np.cos(omega * t),
                          -amplitude * omega**2 * np.sin(omega * t))
    quarter = 0.25 * 2 * np.pi / omega                         # bow up at its most
    assert tr.state(quarter).position[2] == pytest.approx(-60 * np.sin(0.05) + 5 * np.cos(0.05))
    for t in (2.0, 37.0, 80.0):
        h = 1e-4
        p = [tr.state(t + k * h).position for k in (-1, 0, 1)]
        v = [tr.state(t + k * h).velocity for k in (-1, 0, 1)]
        assert np.allclose(tr.state(t).velocity, (p[2] - p[0]) / (2 * h), atol=1e-6)
        assert np.allclose(tr.state(t).acceleration, (v[2] - v[0]) / (2 * h), atol=1e-5)


def test_the_knot_is_scipys():
    from kanat.model.vessel import KNOT

    assert KNOT == knot
