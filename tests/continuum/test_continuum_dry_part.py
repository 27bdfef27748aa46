"""The note on a heavy continuum cable above the water surface (kanat.continuum.surface.DryLength).

Oracles: eq. (1) is exact for a straight line, whose length above the surface is its height over
``sin`` of its angle; a run from a tow point 5 m above the water says how much of its cable was
above it, and the run's own top node positions give the same length to the grid's interpolation.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import kanat
from kanat.continuum.surface import DryLength
from kanat.physics.immersion import dry_length, heights

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("angle_deg", [10.0, 35.0, 90.0])
@pytest.mark.parametrize("top", [0.0, 2.5, 7.3])
def test_the_length_above_the_surface_of_a_straight_line_is_its_height_over_its_sine(angle_deg, top):
    s = np.linspace(0.0, 100.0, 17)               # long enough to reach the water from every top
    a = math.radians(angle_deg)
    position = np.column_stack([s * math.cos(a), np.zeros_like(s), top - s * math.sin(a)])
    assert dry_length(s, heights(position, None, 0.0)) == pytest.approx(top / math.sin(a), abs=1e-12)


def test_a_line_wholly_under_the_water_has_nothing_above_it_and_no_note():
    s = np.linspace(0.0, 10.0, 5)
    position = np.column_stack([s, np.zeros(5), -1.0 - s])
    dry = DryLength()
    dry.observe(s, heights(position, None, 0.0), 0.0)
    assert dry.length == 0.0 and dry.note("tow") is None


def test_a_run_from_a_tow_point_above_the_water_says_how_much_cable_was_above_it():
    case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace(
        {"vessel.tow_point": [0.0, 0.0, 5.0], "simulation.duration": 4.0})
    ds = kanat.simulate(case)
    assert ds.attrs["status"] == "ok"
    note = [n for n in ds.attrs["notes"].split("\n") if "above the water surface" in n]
    assert len(note) == 1 and "cable 'tow'" in note[0]
    said = float(note[0].split("up to ")[1].split(" m")[0])
    x = ds["position"].values                                   # (time, node, 3)
    s = ds["s"].values
    expected = max(dry_length(s, x[k, :, 2]) for k in range(len(ds.time)))
    assert said == pytest.approx(expected, rel=1e-3)            # the note's 4 significant digits
    top = x[0, :3]                                              # the top's straight run from 5 m up
    slope = (top[0, 2] - top[1, 2]) / np.hypot(*(top[0] - top[1])[[0, 2]])
    assert said == pytest.approx(5.0 / slope, rel=0.02)         # a near-straight top: 5 m / sin(angle)
