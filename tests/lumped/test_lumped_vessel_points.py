"""The lumped model's vessel points without a track and without rotations (the translational
path of :meth:`kanat.lumped.system.LumpedSystem.vessel_points`):

* harmonics of surge, sway and heave: the points sit at ``r + (surge, sway, heave)`` and move
  at its derivative (written out here), what the general rigid-body sampler
  (:func:`kanat.physics.motion_samples.point_series`, rotations included) gives, ramped or not
  (the compiled :func:`kanat.lumped.fast.harmonic_points` against NumPy's);
* a table without angles: as its scalar twin (:func:`kanat.physics.motion.motion_at`);
* the steady frame of the equilibrium: the points at ``t = 0``, at rest;
* a motion with a rotation takes the general path (:func:`kanat.lumped.system.translational`).
"""
import math

import numpy as np

from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem, translational
from kanat.model import Case
from kanat.physics.motion import compile_motion, motion_at
from kanat.physics.motion_samples import motion_series, point_series

FAIRLEADS = ((20.0, 0.0, -8.0), (-10.0, 17.321, -8.0))
MOTION = [{"dof": "surge", "amplitude": 2.0, "period": 11.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0},
          {"dof": "sway", "amplitude": 0.5, "period": 7.0, "phase_deg": 20.0}]


def two_legs(motion):
    line = dict(diameter=0.1, mass=8.0, weight_in_water=30.0, axial_stiffness=5e6, axial_damping=2e5,
                drag_normal=1.2, drag_tangential=0.01, added_mass=4.0)
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0}, line_types={"rope": line}, vessel={"motion": motion},
        cables=[dict(name=f"leg{k}", line_type="rope", length=126.0, segments=10,
                     **{"from": f"anchor:[{5 * r[0]}, {5 * r[1]}, -100]"}, to={"vessel": list(r)})
                for k, r in enumerate(FAIRLEADS)],
        simulation={"duration": 10.0, "dt": 0.05, "output_dt": 0.5}))


def analytic(t):
    """(surge, sway, heave) and their rates at ``t`` of MOTION."""
    w = [2 * math.pi / 11.0, 2 * math.pi / 7.0, 2 * math.pi / 9.0]
    arg = [w[0] * t - math.pi / 2, w[1] * t + math.radians(20.0), w[2] * t - math.pi / 2]
    amp = [2.0, 0.5, 1.0]
    return (np.array([a * math.sin(p) for a, p in zip(amp, arg)]),
            np.array([a * om * math.cos(p) for a, om, p in zip(amp, w, arg)]))


def test_translational_harmonics_move_every_point_with_the_vessel_origin():
    case = two_legs(MOTION)
    system = LumpedSystem(build_network(case), case)
    assert system._translational and system.track is None
    times = np.linspace(0.0, 30.0, 61)
    pos, vel, heading = system.vessel_points(times)
    arms = system.net.vessel_offset
    for k, t in enumerate(times):
        d, dv = analytic(t)
        np.testing.assert_allclose(pos[k], arms + d, atol=1e-12)
        np.testing.assert_allclose(vel[k], np.broadcast_to(dv, arms.shape), atol=1e-12)
    assert np.all(heading == 0.0)
    q, v = motion_series(system.motion, times)                 # the general sampler: the same numbers
    disp, dvel = point_series(arms, q, v)
    np.testing.assert_array_equal(pos, arms + disp)
    np.testing.assert_array_equal(vel, dvel)


def test_a_ramped_motion_is_the_general_samplers_in_its_ramp_and_after():
    """The ramp (``r q``, ``r q_dot + r' q``) in the compiled sampler against NumPy's, before the start,
    through the ramp's 6 s and after; a rotation's harmonic of no amplitude left out."""
    motion = dict(harmonics=MOTION + [{"dof": "roll", "amplitude": 0.0, "period": 5.0}], ramp=6.0)
    case = two_legs(motion)
    system = LumpedSystem(build_network(case), case)
    assert system._harmonics is not None and len(system._harmonics[0]) == 3
    times = np.linspace(-1.0, 9.0, 41)
    arms = np.array([[0.0, 0.0, 0.0], [3.0, -2.0, -8.0]])
    pos, vel, _ = system.vessel_points(times, arms)
    q, v = motion_series(system.motion, times)
    disp, dvel = point_series(arms, q, v)
    np.testing.assert_allclose(pos, arms + disp, rtol=0, atol=1e-14)
    np.testing.assert_allclose(vel, dvel, rtol=0, atol=1e-14)
    assert np.all(pos[times <= 0.0] == arms) and np.all(vel[times <= 0.0] == 0.0)
    ramped = np.abs(vel[:, 0, 0] - analytic_rate(times)) > 1e-9
    assert np.any(ramped) and np.all(times[ramped] < 6.0)         # the ramp is felt, and only in its 6 s


def analytic_rate(times):
    return np.array([analytic(t)[1][0] for t in times])


def test_a_table_without_angles_follows_its_scalar_twin():
    rows = [[0, 0, 0, 0, 0, 0, 0], [5, 1, 0, 2, 0, 0, 0], [10, 0, 1, 0, 0, 0, 0]]
    case = two_legs({"rows": rows})
    system = LumpedSystem(build_network(case), case)
    assert system._translational
    times = np.array([-1.0, 0.0, 2.5, 5.0, 7.3, 10.0, 12.0])
    pos, vel, _ = system.vessel_points(times)
    arms = system.net.vessel_offset
    for k, t in enumerate(times):
        qk, vk = motion_at(system.motion, t)
        np.testing.assert_allclose(pos[k], arms + qk[:3], atol=1e-13)
        np.testing.assert_allclose(vel[k], np.broadcast_to(vk[:3], arms.shape), atol=1e-13)


def test_the_steady_frame_holds_the_points_at_their_start_at_rest():
    case = two_legs(MOTION)
    system = LumpedSystem(build_network(case), case, steady_velocity=np.zeros(3))
    pos, vel, _ = system.vessel_points(np.array([0.0, 3.0, 7.0]))
    d, _ = analytic(0.0)
    np.testing.assert_allclose(pos, np.broadcast_to(system.net.vessel_offset + d, pos.shape), atol=1e-12)
    assert np.all(vel == 0.0)


def test_a_rotation_takes_the_general_path():
    assert translational(None)
    assert translational(compile_motion(two_legs(MOTION).vessel.motion))
    assert not translational(compile_motion(two_legs(MOTION + [{"dof": "pitch", "amplitude": 2.0,
                                                                    "period": 9.0}]).vessel.motion))
    assert not translational(compile_motion(two_legs({"rows": [[0, 0, 0, 0, 0, 0, 0],
                                                                [5, 0, 0, 0, 0, 0, 1]]}).vessel.motion))


def test_single_time_samples_keep_up_with_the_time_asked():
    """An output samples the vessel twice at one time (its nodes, then the tow point): the motion's sample
    of that time is kept. Asked at other times in turn, every sample is still the motion at the time asked
    (written out), and bit for bit the one a fresh system gives."""
    case = two_legs(MOTION)
    system, fresh = LumpedSystem(build_network(case), case), LumpedSystem(build_network(case), case)
    arms = system.net.vessel_offset
    for t in (0.0, 0.7, 0.7, 2.1, 0.7, 13.4):
        pos, vel, _ = system.vessel_points([t])
        tow = system.vessel(t)
        d, dv = analytic(t)
        np.testing.assert_allclose(pos[0], arms + d, atol=1e-12)
        np.testing.assert_allclose(vel[0], np.broadcast_to(dv, arms.shape), atol=1e-12)
        np.testing.assert_allclose(tow[0], np.asarray(case.vessel.tow_point) + d, atol=1e-12)
        again = LumpedSystem(build_network(case), case)
        np.testing.assert_array_equal(pos, again.vessel_points([t])[0])
        np.testing.assert_array_equal(vel, fresh.vessel_points(np.array([t, t + 1.0]))[1][:1])
