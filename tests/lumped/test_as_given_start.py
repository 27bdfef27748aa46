"""A lumped run started as given (``simulation.initial_state: as_given``) starts at rest with each cable
laid unstretched between its ends (:func:`kanat.lumped.network.given_positions`): no tension at t = 0.

Oracles: geometry (the nodes on the chord, or on a sag whose polyline is as long as the cable and no
longer; none under the seabed) and the elastic law (an element no longer than its unstretched length
carries nothing, with the nodes at rest). The equilibrium's first guess stretches every cable by
``GUESS_STRETCH`` (1e-4), which as a start was a tension of ``EA 1e-4`` in every element: 500 N here, 100 kN
on MoorDyn's pendulum test file (a 1e9 N line), and bowed a vertical line 4.4 m sideways.
"""
import numpy as np

from kanat import api
from kanat.model import Case

LINE = dict(diameter=0.1, mass=8.0, weight_in_water=30.0, axial_stiffness=5e6, axial_damping=2e5,
            drag_normal=1.2, drag_tangential=0.01, added_mass=4.0)


def started(anchor, length, depth=300.0, segments=20):
    case = Case.model_validate(dict(
        model="lumped", environment={"depth": depth}, line_types={"rope": LINE}, vessel={"tow_point": [0, 0, 0]},
        cables=[dict(name="leg", line_type="rope", length=length, segments=segments,
                     **{"from": f"anchor:{list(anchor)}"}, to="vessel")],
        simulation={"duration": 0.2, "output_dt": 0.1, "scheme": "rk4", "initial_state": "as_given"}))
    out = api.run(case)
    assert out.status == "ok", out.status
    first = out.dataset.isel(time=0)
    return first.position.values, first.segment_tension.values


def chords(x):
    return np.linalg.norm(np.diff(x, axis=0), axis=1)


def test_a_vertical_slack_line_starts_straight_and_slack():
    """Its ends 99 m apart, one above the other, on 100 m: straight (a U bows only a chord under half the
    length, as WHOI deploy's wire between a clump and a mine 1.34 m apart, tests/whoi)."""
    x, tension = started((0.0, 0.0, -99.0), 100.0)
    np.testing.assert_array_equal(x[:, :2], 0.0)                     # on the chord, not bowed sideways
    np.testing.assert_allclose(chords(x), 99.0 / 20, rtol=1e-12)
    assert np.all(tension == 0.0)


def test_a_sagging_line_starts_at_its_own_length_without_tension():
    x, tension = started((80.0, 0.0, -60.0), 120.0)
    assert 120.0 * (1 - 1e-3) < chords(x).sum() <= 120.0
    assert np.all(chords(x) <= 120.0 / 20 * (1 + 1e-12))
    middle = x[len(x) // 2]
    assert middle[2] < -30.0 - 5.0                                    # sagging below the chord's midpoint
    assert np.all(tension == 0.0), tension.max()


def test_a_sag_that_would_dip_below_the_seabed_lies_on_it():
    depth = 60.0
    x, tension = started((150.0, 0.0, -depth), 200.0, depth=depth)
    assert np.all(x[:, 2] >= -depth - 1e-9)
    assert np.count_nonzero(np.isclose(x[:, 2], -depth)) >= 3
    assert np.all(tension == 0.0)
