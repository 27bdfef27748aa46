"""The continuum model driven at its top by the vessel's prescribed motion (``vessel.motion``):

* the first end moves as the lumped model's vessel point does (the same rigid-body motion, turned
  by the heading: :mod:`kanat.physics.motion`), position and velocity;
* a suspended mooring line (160 m wire, top 5 m below the surface, anchor 150 m away) driven in
  surge and heave: top tension against the lumped model's ``rk4`` on the same case, mean and range
  within 1 %, planar and spatial (sway);
* slow surge and heave (3 m and 2 m over 1000 s): the top tension at every instant is the elastic catenary's between
  the anchor and the displaced top (quasi-static oracle, :func:`kanat.statics.catenary.elastic_catenary`).
"""
import math
import warnings

import numpy as np
import pytest

from kanat import api
from kanat.continuum.models import model_for
from kanat.model import Case
from kanat.statics.catenary import elastic_catenary

WEIGHT, EA, LENGTH = 90.0, 2.0e8, 160.0
TOP, ANCHOR = (0.0, 0.0, -5.0), (-120.0, 0.0, -95.0)
SURGE_HEAVE = [{"dof": "surge", "amplitude": 3.0, "period": 14.0, "phase_deg": -90.0},
               {"dof": "heave", "amplitude": 1.5, "period": 10.0, "phase_deg": -90.0}]


def mooring(model, motion, duration=28.0, dt=0.05, scheme=None, dimensions="auto", output_dt=0.25):
    """A wire from the vessel's tow point down to an anchor, hanging clear of the seabed."""
    line = dict(diameter=0.08, mass=12.0, weight_in_water=WEIGHT, axial_stiffness=EA,
                drag_normal=1.2, drag_tangential=0.02, added_mass=1.0)
    simulation = {"duration": duration, "dt": dt, "output_dt": output_dt, "dimensions": dimensions}
    if scheme:
        simulation["scheme"] = scheme
    return Case.model_validate(dict(
        model=model, environment={"depth": 100.0}, line_types={"wire": line},
        vessel={"motion": motion, "tow_point": list(TOP)},
        cables=[dict(name="leg", line_type="wire", length=LENGTH, segments=40,
                     **{"from": "vessel"}, to=f"anchor:{list(ANCHOR)}")],
        simulation=simulation))


def run(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = api.run(case)
    assert result.summary.ok, result.summary.status
    return result.dataset


def analytic(t, motion):
    """Top position and velocity of translations ``A sin(w t + phase)`` along x, y, z."""
    axis = {"surge": 0, "sway": 1, "heave": 2}
    position, velocity = np.array(TOP), np.zeros(3)
    for h in motion:
        w, phase = 2 * math.pi / h["period"], math.radians(h.get("phase_deg", 0.0))
        position[axis[h["dof"]]] += h["amplitude"] * math.sin(w * t + phase)
        velocity[axis[h["dof"]]] += h["amplitude"] * w * math.cos(w * t + phase)
    return position, velocity


@pytest.mark.parametrize("dimensions", [2, 3])
def test_the_first_end_follows_the_prescribed_motion(dimensions):
    motion = SURGE_HEAVE + ([{"dof": "sway", "amplitude": 2.0, "period": 12.0}] if dimensions == 3 else [])
    model = model_for(mooring("continuum", motion, dimensions=dimensions))
    assert model.dimensions == dimensions
    for t in (0.0, 1.3, 4.0, 9.7):
        position, velocity = analytic(t, motion)
        np.testing.assert_allclose(model.origin(t), position, atol=1e-12)
        np.testing.assert_allclose(model.velocities(t)[0], velocity, atol=1e-12)
        np.testing.assert_allclose(model.velocities(t)[1], 0.0)


def test_a_pitching_vessel_moves_a_lever_arm_tow_point():
    """Pitch of 2 degrees about the vessel origin turns a tow point 20 m aft: the end follows
    ``R r`` (bow down positive about +y: x' = x cos a + z sin a, z' = -x sin a + z cos a)."""
    motion = [{"dof": "pitch", "amplitude": 2.0, "period": 8.0}]
    case = mooring("continuum", motion)
    case = case.model_copy(update={"vessel": case.vessel.model_copy(update={"tow_point": (-20.0, 0.0, -5.0)})})
    model = model_for(case)
    for t in (1.0, 3.0):
        a = math.radians(2.0) * math.sin(2 * math.pi * t / 8.0)
        want = np.array([-20.0 * math.cos(a) - 5.0 * math.sin(a), 0.0, 20.0 * math.sin(a) - 5.0 * math.cos(a)])
        np.testing.assert_allclose(model.origin(t), want, atol=1e-12)


SURGE_SWAY = SURGE_HEAVE[:1] + [{"dof": "sway", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0}]


@pytest.mark.slow
@pytest.mark.parametrize("motion", [SURGE_HEAVE, SURGE_SWAY], ids=["surge-heave", "surge-sway"])
def test_a_driven_mooring_line_agrees_with_the_lumped_model(motion):
    continuum = run(mooring("continuum", motion))
    lumped = run(mooring("lumped", motion, dt=0.001, scheme="rk4"))
    np.testing.assert_allclose(continuum.time.values, lumped.time.values)
    np.testing.assert_allclose(continuum.position.values[:, 0], lumped.position.values[:, 0], atol=1e-9)
    top = {name: ds.tension.values[:, 0] for name, ds in (("continuum", continuum), ("lumped", lumped))}
    assert np.ptp(top["lumped"]) > 0.15 * np.mean(top["lumped"])          # the motion is felt
    assert np.mean(top["continuum"]) == pytest.approx(np.mean(top["lumped"]), rel=0.01)
    assert np.ptp(top["continuum"]) == pytest.approx(np.ptp(top["lumped"]), rel=0.01)
    settled = continuum.time.values > 5.0          # rk4 rings axially at the start; the implicit scheme damps it
    assert np.max(np.abs(top["continuum"] - top["lumped"])[settled]) < 0.02 * np.max(top["lumped"])


def test_slow_motion_follows_the_elastic_catenary():
    slow = [{"dof": "surge", "amplitude": 3.0, "period": 1000.0}, {"dof": "heave", "amplitude": 2.0, "period": 1000.0}]
    ds = run(mooring("continuum", slow, duration=500.0, dt=1.0, output_dt=25.0))
    errors = []
    for k in range(len(ds.time)):
        top = ds.position.values[k, 0]
        exact = elastic_catenary(top[0] - ANCHOR[0], top[2] - ANCHOR[2], LENGTH, WEIGHT, EA)
        errors.append(abs(ds.tension.values[k, 0] - exact.tension_upper) / exact.tension_upper)
    swing = np.ptp(ds.tension.values[:, 0]) / ds.tension.values[:, 0].mean()
    assert swing > 0.1                                           # the motion changes the tension
    assert max(errors) < 1e-3, errors


@pytest.mark.parametrize("rows, planar", [([[0, 1, 0, 0.5, 0, 2, 0], [10, -1, 0, 0, 0, 0, 0]], True),
                                          ([[0, 0, 0.5, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0, 0]], False),
                                          ([[0, 0, 0, 0, 0, 0, 3], [10, 0, 0, 0, 0, 0, 0]], False)],
                         ids=["surge-heave-pitch", "sway", "yaw"])
def test_a_motion_table_leaves_the_plane_only_with_sway_roll_or_yaw(rows, planar):
    model = model_for(mooring("continuum", {"rows": rows}))
    assert model.dimensions == (2 if planar else 3)
    if planar:                      # halfway (linear): surge 0, heave 0.25 m, pitch 1 deg turning the arm (0, 0, -5)
        a = math.radians(1.0)
        want = np.array([-5.0 * math.sin(a), 0.0, 0.25 - 5.0 * math.cos(a)])
        np.testing.assert_allclose(model.origin(5.0), want, atol=1e-12)
        slope = (np.array(rows[1][1:4]) - np.array(rows[0][1:4])) / 10.0           # the table's velocity
        assert model.velocities(5.0)[0][[0, 2]] == pytest.approx(slope[[0, 2]] + [-5.0 * math.cos(a) * math.radians(
            -0.2), 5.0 * math.sin(a) * math.radians(-0.2)], abs=1e-12)
