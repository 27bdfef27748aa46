"""A line at rest is no finding: the time-error estimate and the snap notes have floors of the line's scale.

* Eq. (2) of :mod:`kanat.lumped.time_error` divides a step's error by at least ``d_0 sqrt(n_free)``,
  ``d_0 = max(1e-6 m, RESOLUTION l_min)``: checked by hand on one step (the Python twin), and on a run of a
  150 m chain hung from a point on the surface in 100 m of water, its last 50 m laid on the seabed, nothing
  moving (its nodes move by micrometres in 2 s, the oracle that it is at rest): with the floor at 1e-6 m
  alone it read 19.9 % of a step's displacement and warned; with ``d_0`` it reads under 1 % and says
  nothing. Where a step does not resolve the motion the estimate still warns (``test_time_error.py``,
  ``tests/whoi/test_whoi_time_error.py``).
* Snap notes speak of the events whose peak passes ``WEIGHT_FRACTION |w0| L0``
  (:func:`kanat.lumped.snap.significant`): the laid chain's flickering elements (peaks of tens of
  newtons on elements of 6.4 kN in water) are kept as events but noted by none; a released wire's snaps
  still are (``test_lumped_snap_step.py``).
"""
import math
import warnings

import numpy as np
import pytest
import yaml

from kanat import api, load_case
from kanat.lumped import snap, time_error
from kanat.lumped.integrators import GeneralizedAlphaLumped

from helpers import EXAMPLES
from test_free_tail_seabed import hanging_case


def test_a_step_of_a_line_at_rest_is_judged_against_the_floor():
    """Eq. (2) by hand: 4 free nodes moving 1e-7 m, each in error by 1e-6 m, on 5 m elements (``d_0`` =
    5e-5 m): ``||e|| / (d_0 sqrt(4)) = 2e-6 / 1e-4 = 0.02``, not ``2e-6 / (1e-6 sqrt(4)) = 1`` as without it."""
    coefficients = GeneralizedAlphaLumped().coefficients
    h = 0.1
    error = 1e-6
    a1 = np.zeros((4, 3))
    a1[:, 0] = error / (time_error.error_factor(coefficients) * h * h)            # eq. (1): e = 1e-6 m along x
    x0 = np.zeros((4, 3))
    x = x0 + [1e-7, 0.0, 0.0]
    for floor, expected in ((time_error.motion_floor(np.full(4, 5.0)), 0.02), (time_error.MOTION_FLOOR, 1.0)):
        record = time_error.empty(floor)
        record[5] = 0.0                                                             # past the start's steps
        time_error.observe(record, 1.0, h, coefficients, x0, np.zeros((4, 3)), a1, x)
        assert record[3] == pytest.approx(expected, rel=1e-9)
        assert record[0] == pytest.approx(error, rel=1e-9)
    assert time_error.motion_floor(np.array([5.0, 0.01])) == time_error.MOTION_FLOOR   # short elements: 1e-6 m


def test_only_snaps_past_a_tenth_of_their_elements_weight_are_findings():
    events = {"time": np.array([1.0, 2.0, 3.0]), "element": np.array([0, 1, 1]),
              "peak_tension": np.array([61.0, 2160.0, 3.0]), "rise_rate": np.array([1e3, 1e5, 10.0])}
    weight = np.array([6400.0, 40.0])                                  # |w0| L0 of each element [N]
    found = snap.significant(events, weight)
    assert list(found["time"]) == [2.0] and list(found["peak_tension"]) == [2160.0]


def quiet_run(case):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = api.run(case).dataset
    return ds, [str(w.message) for w in caught]


@pytest.mark.slow
def test_a_chain_laid_at_rest_gives_no_time_error_warning_and_no_snap_note(monkeypatch):
    case = hanging_case(segments=30).replace({"simulation.duration": 2.0})
    ds, caught = quiet_run(case)
    assert ds.attrs["status"] == "ok" and ds.attrs["scheme"] == "generalized-alpha-lumped"
    assert np.max(np.abs(ds.position.values - ds.position.values[0])) < 1e-4          # at rest: the oracle
    assert ds.attrs["time_error_estimate"] < 0.5 * time_error.WARNING                # measured 0.0040
    assert "does not resolve" not in ds.attrs["notes"] and not any("does not resolve" in w for w in caught)
    assert ds.attrs["snap_events"] > 0 and "snap load" not in ds.attrs["notes"]     # kept, not noted
    w0 = case.line_types["line"].weight_in_water_value(1025.0, 9.81)
    assert np.max(ds.event_peak_tension.values) < snap.WEIGHT_FRACTION * w0 * 5.0
    # the reproduction: with the floor at 1e-6 m alone the same run warns
    monkeypatch.setattr(time_error, "RESOLUTION", 0.0)
    bare, caught = quiet_run(case)
    assert bare.attrs["time_error_estimate"] > time_error.WARNING                   # measured 0.199
    assert any("does not resolve the motion" in w for w in caught)


def test_a_laid_mooring_leg_at_rest_says_nothing():
    """``examples/mooring_current.yaml`` without its current, in the lumped model: 700 m of chain between an
    anchor and a fairlead, part of it on the seabed, at its equilibrium (it moves by less than 1e-9 m)."""
    data = yaml.safe_load((EXAMPLES / "mooring_current.yaml").read_text())
    data["model"] = "lumped"
    del data["environment"]["current"]
    data["simulation"] = {"duration": 2.0, "output_dt": 1.0}
    ds, caught = quiet_run(load_case(data))
    assert ds.attrs["status"] == "ok"
    assert np.max(np.abs(ds.position.values - ds.position.values[0])) < 1e-9
    assert ds.attrs["time_error_estimate"] < 0.5 * time_error.WARNING
    assert not caught and "does not resolve" not in ds.attrs["notes"] and "snap" not in ds.attrs["notes"]
    assert math.isfinite(ds.attrs["time_error_estimate"])
