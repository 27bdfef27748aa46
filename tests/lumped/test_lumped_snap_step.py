"""The implicit scheme through snap loads: a released wire falling through its own slack.

A 20 m wire (10 elements, axial nodal period 3.6 ms) with a 1000 N weight hangs from a vessel
point and is released at t = 5 s; with no tangential drag the wire falls faster than the weight,
folds and pulls taut again and again (160 snap events in 4 s). Oracle: rk4 at 10 ms (its safe
step is shorter: it steps at that) — the implicit scheme at 2 ms, shorter than the axial period,
agrees with it; at 10 ms it cannot follow the snaps, and the run must say so (before the note it
said ``ok`` with a peak 12 times rk4's), warning or failing by its time-error estimate. Before the Newton iteration's carried contraction rate
had a floor (``kanat.lumped.fast_implicit.CARRIED_RATE_FLOOR``), the 10 ms run accepted a first
increment 1e8 times the tolerance and failed at t = 1 s after the release with an element
stretched 1,930 %.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import kanat

from helpers import released_fall


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    case = released_fall(tmp_path_factory.mktemp("fall"), drag_tangential=0.0, duration=9, dt=0.01, output_dt=0.5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = {}
        for name, keys in {"rk4": {"simulation.scheme": "rk4"},
                           "implicit 10 ms": {"simulation.scheme": "generalized-alpha-lumped"},
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
    """At 10 ms the folding wire's motion is not the same from one state at the release to another
    a round-off away (its time-error estimate read 62 % in one and 219 % in the other): the run
    must say, either way, that the step does not resolve the motion, and name the step that would."""
    coarse, reference = runs["implicit 10 ms"], runs["rk4"]
    n = min(coarse.time.size, reference.time.size)
    drift = np.abs(coarse.position.values[:n] - reference.position.values[:n]).max()
    assert drift > 1.0                                        # it is not rk4's motion
    said = coarse.attrs["status"] + "; " + coarse.attrs["notes"]
    assert "snap peaks are not converged in the step" in said
    assert f"dt <= {coarse.attrs['axial_period']:.3g} s" in said
    assert "the time step does not resolve the motion" in said
