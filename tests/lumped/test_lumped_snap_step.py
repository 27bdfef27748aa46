"""The implicit scheme through snap loads: a released wire falling through its own slack.

A 20 m wire (10 elements, axial nodal period 3.6 ms) with a 1000 N weight hangs from a vessel
point and is released at t = 5 s; with no tangential drag the wire falls faster than the weight,
folds and pulls taut again and again (160 snap events in 4 s). Oracle: rk4 at 10 ms (its safe
step is shorter: it steps at that) — the implicit scheme at 2 ms, shorter than the axial period,
agrees with it; at 10 ms it cannot follow the snaps, and the run must say so (before the note it
said ``ok`` with a peak 12 times rk4's). Before the Newton iteration's carried contraction rate
had a floor (``kanat.lumped.fast_implicit.CARRIED_RATE_FLOOR``), the 10 ms run accepted a first
increment 1e8 times the tolerance and failed at t = 1 s after the release with an element
stretched 1,930 %.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import kanat
from kanat.io import load_case

FALL = """
name: slack-fall
model: lumped
environment: {water_density: 1000, gravity: 10}
line_types:
  wire: {diameter: 0.01, mass: 0.5, weight_in_water: 2.0, axial_stiffness: 1.0e6,
         drag_normal: 1.2, drag_tangential: 0.0}
bodies:
  weight: {mass: 200, net_buoyancy: -1000, drag_area: 0.5}
vessel: {tow_point: [0, 0, -5]}
cables:
  - {name: wire, line_type: wire, length: 20, segments: 10, from: vessel, to: weight,
     end_a: {release_at: 5}}
simulation: {duration: 9, dt: 0.01, output_dt: 0.5}
"""


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    path = tmp_path_factory.mktemp("fall") / "fall.yaml"
    path.write_text(FALL)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(path)
        out = {}
        for name, keys in {"rk4": {"simulation.scheme": "rk4"}, "implicit 10 ms": {},
                           "implicit 2 ms": {"simulation.dt": 0.002}}.items():
            result = kanat.run(case.replace(keys))
            out[name] = result.dataset if hasattr(result, "dataset") else result
    return out


def test_a_step_shorter_than_the_axial_period_follows_the_snaps(runs):
    reference, fine = runs["rk4"], runs["implicit 2 ms"]
    assert fine.attrs["status"] == "ok"
    peak, peak_rk4 = fine.segment_tension.values.max(), reference.segment_tension.values.max()
    assert peak == pytest.approx(peak_rk4, rel=0.01)
    assert np.abs(fine.position.values - reference.position.values).max() < 0.05
    assert "snap load" not in fine.attrs.get("notes", "")


def test_a_longer_step_through_snaps_says_its_peaks_are_not_converged(runs):
    coarse = runs["implicit 10 ms"]
    assert coarse.attrs["status"] == "ok"                     # every check of the model passes
    drift = np.abs(coarse.position.values - runs["rk4"].position.values).max()
    assert drift > 1.0                                        # and yet it is not rk4's motion
    notes = coarse.attrs["notes"]
    assert "snap peaks are not converged in the step" in notes
    assert f"dt <= {coarse.attrs['axial_period']:.3g} s" in notes
