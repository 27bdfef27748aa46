"""Prescribed vessel motion (``vessel.motion``) in the lumped model:

* every vessel point follows ``(surge, sway, heave) + R r`` with ``R`` the rotation of roll,
  pitch and yaw (written out here, independently of kanat.physics.motion), the vectorized
  sampler agrees with the scalar motion functions, and a run's fairlead node follows it;
* a taut line's fairlead tension under slow heave equals the elastic catenary's at each
  displaced fairlead position (quasi-static oracle, kanat.statics.catenary), within 0.5 %.
"""
import math

import numpy as np
import pytest

from kanat import api
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.physics.motion import compile_motion, motion_at, rigid_point_motion
from kanat.physics.motion_samples import motion_series, point_series
from kanat.statics.catenary import elastic_catenary

FAIRLEAD = (20.0, 0.0, -8.0)
MOTION = [{"dof": "heave", "amplitude": 2.0, "period": 12.0},
          {"dof": "pitch", "amplitude": 3.0, "period": 9.0, "phase_deg": 30.0},
          {"dof": "surge", "amplitude": 1.5, "period": 20.0}]


def moored(motion, length=126.0, ea=5e6, duration=30.0):
    line = dict(diameter=0.1, mass=8.0, weight_in_water=30.0, axial_stiffness=ea, axial_damping=2e5,
                drag_normal=1.2, drag_tangential=0.01, added_mass=4.0)
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0}, line_types={"rope": line},
        vessel={"motion": motion},
        cables=[dict(name="leg", line_type="rope", length=length, segments=20,
                     **{"from": "anchor:[-70, 0, -100]"}, to={"vessel": list(FAIRLEAD)})],
        simulation={"duration": duration, "dt": 0.05, "output_dt": 0.5}))


def analytic(t):
    """Fairlead position at ``t``: pitch about y (bow down positive), then heave and surge."""
    heave = 2.0 * math.sin(2 * math.pi * t / 12.0)
    pitch = math.radians(3.0) * math.sin(2 * math.pi * t / 9.0 + math.radians(30.0))
    surge = 1.5 * math.sin(2 * math.pi * t / 20.0)
    x, _, z = FAIRLEAD
    return np.array([surge + x * math.cos(pitch) + z * math.sin(pitch), 0.0,
                     heave - x * math.sin(pitch) + z * math.cos(pitch)])


def test_vessel_points_follow_the_rigid_body_motion():
    case = moored(MOTION)
    system = LumpedSystem(build_network(case), case)
    times = np.linspace(0.0, 30.0, 61)
    pos, vel, _ = system.vessel_points(times)
    want = np.array([analytic(t) for t in times])
    np.testing.assert_allclose(pos[:, 0], want, atol=1e-12)
    slope = np.array([(analytic(t + 1e-6) - analytic(t - 1e-6)) / 2e-6 for t in times])   # central differences
    np.testing.assert_allclose(vel[:, 0], slope, atol=1e-7)
    motion = compile_motion(case.vessel.motion)                   # the sampler vs the scalar functions
    q, v = motion_series(motion, times)
    disp, dvel = point_series([FAIRLEAD], q, v)
    for k, t in enumerate(times):
        qk, vk = motion_at(motion, t)
        d, dv = rigid_point_motion(np.array(FAIRLEAD), qk, vk)
        np.testing.assert_allclose(disp[k, 0], d, atol=1e-13)
        np.testing.assert_allclose(dvel[k, 0], dv, atol=1e-13)


def test_a_table_motion_is_interpolated_like_the_scalar_twin():
    rows = [[0, 0, 0, 0, 0, 0, 0], [5, 1, 0, 2, 0, 3, 0], [10, 0, 1, 0, 2, 0, 5]]
    motion = compile_motion(moored({"rows": rows}).vessel.motion)
    times = np.array([-1.0, 0.0, 2.5, 5.0, 7.3, 10.0, 12.0])
    q, v = motion_series(motion, times)
    for k, t in enumerate(times):
        qk, vk = motion_at(motion, t)
        np.testing.assert_allclose(q[k], qk, atol=1e-14)
        np.testing.assert_allclose(v[k], vk, atol=1e-14)


def test_the_fairlead_node_of_a_run_moves_with_the_vessel():
    ds = api.run(moored(MOTION, duration=10.0)).dataset
    assert ds.attrs["status"] == "ok"
    top = ds.position.values[:, -1]
    want = np.array([analytic(t) for t in ds.time.values])
    np.testing.assert_allclose(top, want, atol=1e-9)


def test_a_taut_line_follows_the_quasi_static_catenary_in_slow_heave():
    """Heave of 1 m over 200 s: inertia and drag are negligible, the tension at each instant is
    the static one at the fairlead's place (elastic catenary between anchor and fairlead)."""
    heave = [{"dof": "heave", "amplitude": 1.0, "period": 200.0}]
    case = moored(heave, duration=100.0)
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    w, ea = 30.0, 5e6
    errors = []
    for k in range(20, len(ds.time), 20):
        top = ds.position.values[k, -1]
        exact = elastic_catenary(top[0] + 70.0, top[2] + 100.0, 126.0, w, ea)
        errors.append(abs(ds.tension.values[k, -1] - exact.tension_upper) / exact.tension_upper)
    swing = np.ptp(ds.tension.values[:, -1]) / ds.tension.values[:, -1].mean()
    assert swing > 0.05                                          # the heave changes the tension
    assert max(errors) < 5e-3, errors
