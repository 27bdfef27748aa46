"""6-DOF bodies in the lumped model (kanat.lumped.rigid) against closed forms:

* free heave of a surface body on its waterplane: period ``2 pi sqrt((M + A33) / (rho g A_w))``;
* free pitch of a submerged body whose buoyancy acts above its centre of gravity: period
  ``2 pi sqrt((I_yy + A55) / (B h))`` (``h`` from G to B);
* a moored body's offset-restoring: under a steady horizontal force the 3-leg spread mooring's
  equilibrium offset balances the force (the lines' force on the body, ``body_force``);
* the fairlead kinematics ``x_f = r + R p`` (module eq. 1) and the attitude output.
"""
import math

import numpy as np
import pytest

from kanat import api
from kanat.model import Case

RHO, G = 1025.0, 9.81
TETHER = dict(diameter=0.001, mass=1e-3, weight_in_water=0.0, axial_stiffness=1.0, drag_normal=0.0,
              drag_tangential=0.0, max_strain=1.0)


def body_case(body, duration, dt=0.005):
    """A body and a slack, nearly massless tether to a free end (it gives the body a fairlead)."""
    return Case.model_validate(dict(
        model="lumped", line_types={"tether": TETHER}, bodies={"b": body},
        cables=[dict(name="t", line_type="tether", length=5.0, segments=1, **{"from": {"body": "b", "offset": [0, 0, 0]}},
                     to="free")],
        simulation={"duration": duration, "dt": dt, "output_dt": 0.05, "scheme": "rk4",
                    "initial_state": "as_given"}))


def period(t, signal):
    s = signal - signal.mean()
    idx = np.flatnonzero((s[1:] > 0) & (s[:-1] <= 0))
    crossings = t[idx] - s[idx] * (t[idx + 1] - t[idx]) / (s[idx + 1] - s[idx])
    return np.mean(np.diff(crossings))


def test_free_heave_period_is_that_of_the_waterplane_spring():
    mass, a33, area, push = 1e5, 5e4, 50.0, 2e4
    body = dict(dof=6, mass=mass, net_buoyancy=0.0, position=[0, 0, -1], inertia=[1e6, 1e6, 1e6],
                waterplane_area=area, metacentric_heights=[2.0, 2.0],
                added_mass_matrix=[0, 0, a33, 0, 0, 0], force=[0, 0, push])
    ds = api.run(body_case(body, 20.0)).dataset
    assert ds.attrs["status"] == "ok"
    z = ds.body_position.values[:, 0, 2]
    c33 = RHO * G * area
    assert period(ds.time.values, z) == pytest.approx(2 * math.pi * math.sqrt((mass + a33) / c33), rel=5e-3)
    assert z.mean() == pytest.approx(-1.0 + push / c33, rel=2e-2)       # oscillates about the offset
    assert np.ptp(z) == pytest.approx(2 * push / c33, rel=1e-2)


def test_free_pitch_period_is_that_of_the_buoyancy_pendulum():
    mass, iyy, a55, h = 2e4, 3e5, 1e5, 1.5
    weight = mass * G
    body = dict(dof=6, mass=mass, net_buoyancy=0.0, position=[0, 0, -30], orientation_deg=[0, 5, 0],
                inertia=[3e5, iyy, 3e5], center_of_buoyancy=[0, 0, h], added_mass_matrix=[0, 0, 0, 0, a55, 0])
    ds = api.run(body_case(body, 30.0)).dataset
    assert ds.attrs["status"] == "ok"
    pitch = ds.body_attitude.values[:, 0, 1]
    assert period(ds.time.values, pitch) == pytest.approx(2 * math.pi * math.sqrt((iyy + a55) / (weight * h)),
                                                          rel=1e-2)
    assert np.max(np.abs(pitch)) == pytest.approx(math.radians(5.0), rel=1e-2)
    # the reference point (the centre of gravity here) stays put: no net force on a neutral body
    assert np.max(np.abs(ds.body_position.values[:, 0] - [0, 0, -30])) < 1e-3
    # the tether's node rides on the body: x_f = r + R p with p = 0
    np.testing.assert_allclose(ds.position.values[:, 0], ds.body_position.values[:, 0], atol=1e-9)


def spread_mooring(force_x):
    chain = dict(diameter=0.1, mass=150.0, weight_in_water=1300.0, axial_stiffness=8e8, drag_normal=1.2,
                 drag_tangential=0.5, added_mass=8.0)
    body = dict(dof=6, mass=5e4, net_buoyancy=3.5e5, position=[0, 0, -5], inertia=[2e5, 2e5, 3e5],
                force=[force_x, 0, 0])
    cables = []
    for k in range(3):
        angle = 2 * math.pi * k / 3
        anchor = [400 * math.cos(angle), 400 * math.sin(angle), -100]
        fair = [3 * math.cos(angle), 3 * math.sin(angle), -2]
        cables.append(dict(name=f"leg{k + 1}", line_type="chain", length=420.0, segments=30,
                           **{"from": f"anchor:{anchor}"}, to={"body": "b", "offset": fair}))
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0, "seabed": {}}, line_types={"chain": chain},
        bodies={"b": body}, cables=cables,
        simulation={"duration": 0.5, "dt": 0.002, "output_dt": 0.5, "scheme": "rk4"}))


def test_a_moored_body_s_offset_restoring_balances_the_applied_force():
    """The equilibrium under a horizontal force: the lines pull back exactly that force, and the
    offset grows with it (the restoring curve is monotonic)."""
    offsets = []
    for push in (0.0, 5e4, 1e5):
        ds = api.run(spread_mooring(push)).dataset
        assert ds.attrs["status"] == "ok"
        lines = ds.body_force.values[0, 0]
        assert lines[0] == pytest.approx(-push, abs=1e-3 * 3.5e5)
        assert lines[2] == pytest.approx(-3.5e5, rel=1e-6)             # the lines hold the net buoyancy
        offsets.append(ds.body_position.values[0, 0, 0])
    assert 0.0 < offsets[1] < offsets[2] and abs(offsets[0]) < 1e-6
