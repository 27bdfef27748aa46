"""A 6-DOF body on a single element to an anchor: a cable with no free node of its own.

The body's own dynamics set the explicit step (:func:`kanat.lumped.rigid.fairlead_mobility`, eq. 5:
the fairlead moves with the body's mass; :mod:`kanat.lumped.stepping` eq. 1). Closed forms of a buoyant
body of mass ``m`` and added mass ``m_a`` on a taut, nearly massless tether of axial stiffness ``EA``,
unstretched length ``L0``, stretched length ``L`` and tension ``T``:

* heave on the tether's axial spring ``k = EA / L0``: ``T_heave = 2 pi sqrt((m + m_a) / k)``;
* surge as an inverted pendulum on the geometric stiffness ``T / L``:
  ``T_surge = 2 pi sqrt((m + m_a) / (T / L))``.

The lumped model puts half the element's mass on the fairlead (``m_line / 2``; a continuous spring's
is ``m_line / 3``): the tether weighs 0.8 % of the body, so either moves the periods by under 0.5 %.
The same system with 2-4 segments gives the same periods.
"""
import math

import numpy as np
import pytest

from kanat import api, load_case
from kanat.errors import CaseWarning

MASS, ADDED, NET_BUOYANCY, INERTIA = 2000.0, 1000.0, 3.0e4, 1.0e3
EA, LENGTH, LINE_MASS, LINE_WEIGHT = 2.0e6, 50.0, 0.5, 2.0
ANCHOR_Z = -100.0


def tether_case(position, segments=1, scheme="rk4", duration=10.0, output_dt=0.01):
    sim = {"duration": duration, "output_dt": output_dt, "initial_state": "as_given"}
    if scheme is not None:
        sim["scheme"] = scheme
    return load_case({
        "name": "buoy-on-one-element", "model": "lumped", "environment": {"depth": 100},
        "line_types": {"wire": {"diameter": 0.02, "mass": LINE_MASS, "weight_in_water": LINE_WEIGHT,
                                "axial_stiffness": EA, "drag_normal": 0.0, "drag_tangential": 0.0}},
        "bodies": {"buoy": {"dof": 6, "mass": MASS, "net_buoyancy": NET_BUOYANCY, "position": list(position),
                            "inertia": [INERTIA] * 3, "added_mass_matrix": [ADDED] * 3 + [0, 0, 0]}},
        "cables": [{"name": "tether", "line_type": "wire", "length": LENGTH, "segments": segments,
                    "from": f"anchor:[0, 0, {ANCHOR_Z}]", "to": {"body": "buoy", "offset": [0, 0, 0]}}],
        "simulation": sim})


def period(t, signal):
    """Mean period between upward crossings of the mean (linear interpolation)."""
    s = signal - signal.mean()
    idx = np.flatnonzero((s[1:] > 0) & (s[:-1] <= 0))
    crossings = t[idx] - s[idx] * (t[idx + 1] - t[idx]) / (s[idx + 1] - s[idx])
    return np.mean(np.diff(crossings))


def tension():
    """The tether's tension at rest: the net buoyancy less half the (one) element's weight [N]."""
    return NET_BUOYANCY - 0.5 * LINE_WEIGHT * LENGTH


def heave(segments, scheme="rk4"):
    """A run released 0.5 m below its rest height (the tether stretched by less than at rest, still taut)."""
    return api.run(tether_case([0, 0, ANCHOR_Z + LENGTH + 0.5], segments, scheme)).dataset


def surge(segments):
    """A run released 2 m off in surge, at the height of the stretched tether."""
    stretched = LENGTH * (1.0 + tension() / EA)
    z = ANCHOR_Z + math.sqrt(stretched**2 - 2.0**2)
    return api.run(tether_case([2.0, 0, z], segments, duration=45.0, output_dt=0.05)).dataset


@pytest.mark.parametrize("scheme", ["rk4", "abm4", None])
def test_heave_on_one_element_has_the_period_of_the_axial_spring(scheme):
    ds = heave(1, scheme)
    assert ds.attrs["status"] == "ok"
    z = ds.body_position.values[:, 0, 2]
    assert np.all(ds.segment_tension.values > 0.0)                     # taut throughout: a linear spring
    effective = MASS + ADDED + 0.5 * LINE_MASS * LENGTH
    assert period(ds.time.values, z) == pytest.approx(2 * math.pi * math.sqrt(effective / (EA / LENGTH)), rel=5e-3)
    # the step is the body's: eq. (1) with the fairlead's mobility, 1 / (m + m_a + m_f) here
    assert ds.attrs["dt"] <= 0.01 and ds.attrs["axial_period"] < 10.0


def test_surge_on_one_element_has_the_period_of_the_geometric_stiffness():
    ds = surge(1)
    assert ds.attrs["status"] == "ok"
    x = ds.body_position.values[:, 0, 0]
    stretched = LENGTH * (1.0 + tension() / EA)
    expected = 2 * math.pi * math.sqrt((MASS + ADDED) / (tension() / stretched))
    assert period(ds.time.values, x) == pytest.approx(expected, rel=5e-3)
    assert np.max(x) == pytest.approx(2.0, rel=1e-2)                   # undamped: no drag on the system


@pytest.mark.slow
@pytest.mark.parametrize("segments", [2, 3, 4])
def test_more_segments_give_the_same_periods(segments):
    one, many = heave(1), heave(segments)
    assert many.attrs["status"] == "ok"
    z1, zn = one.body_position.values[:, 0, 2], many.body_position.values[:, 0, 2]
    assert period(many.time.values, zn) == pytest.approx(period(one.time.values, z1), rel=3e-3)
    x1, xn = surge(1).body_position.values[:, 0, 0], surge(segments).body_position.values[:, 0, 0]
    t = np.arange(len(x1)) * 0.05
    assert period(t, xn) == pytest.approx(period(t, x1), rel=3e-3)


def test_a_cable_between_two_anchors_runs_with_nothing_to_integrate():
    """One element, both ends prescribed: no free node and no body; the step is the output interval and
    the tension is the element's own, ``EA (l / L0 - 1)``."""
    with pytest.warns(CaseWarning, match="must stretch 1 %"):          # the validator's word on a taut bar
        case = load_case({
            "name": "anchored-element", "model": "lumped", "environment": {"depth": 100},
            "line_types": {"wire": {"diameter": 0.02, "mass": LINE_MASS, "weight_in_water": LINE_WEIGHT,
                                    "axial_stiffness": EA}},
            "cables": [{"name": "bar", "line_type": "wire", "length": LENGTH, "segments": 1,
                        "from": "anchor:[0, 0, -100]", "to": "anchor:[0, 0, -49.5]"}],
            "simulation": {"duration": 2.0, "output_dt": 0.5, "scheme": "rk4"}})
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok" and ds.attrs["dt"] == 0.5
    np.testing.assert_allclose(ds.segment_tension.values, EA * (50.5 / LENGTH - 1.0), rtol=1e-12)


def test_the_equilibrium_start_of_a_body_on_one_element_is_at_rest():
    """``initial_state: equilibrium`` on one element: the body floats where the tether's stretch carries
    its net buoyancy less half the element's weight, ``L = L0 (1 + T / EA)``, and stays there."""
    case = tether_case([0, 0, -45.0], duration=2.0, output_dt=0.5)
    case = case.model_copy(update={"simulation": case.simulation.model_copy(update={"initial_state": "equilibrium"})})
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    z = ds.body_position.values[:, 0, 2]
    np.testing.assert_allclose(z, ANCHOR_Z + LENGTH * (1.0 + tension() / EA), atol=1e-6)
