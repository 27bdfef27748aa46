"""Start-up ramps (``ramp`` on ``environment.waves``, ``environment.current`` and ``vessel.motion``,
kanat.physics.ramp): the half cosine itself, the loads it scales while it rises, and runs that end
where the same runs without a ramp end."""
import math

import numpy as np
import pytest

from kanat import api
from kanat.continuum.model2d import planar_cable
from kanat.continuum.water import planar_water
from kanat.continuum import kernels2d as k2
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.physics.motion import compile_motion, motion_at
from kanat.physics.motion_samples import motion_series
from kanat.physics.ramp import ramp_factor, ramp_rate, ramp_series

RAMP = 8.0
WAVES = {"type": "regular", "height": 3.0, "period": 7.0, "heading_deg": 20.0}
CURRENT = {"profile": [[0.0, 0.8, 0.2, 0.0], [-60.0, 0.2, 0.0, 0.0]]}
PLANAR = [[0.0, 0.8, 0.0, 0.0], [-60.0, 0.2, 0.0, 0.0]]       # the continuum's 2-D model: in the x-z plane
MOTION = [{"dof": "surge", "amplitude": 2.0, "period": 9.0, "phase_deg": 30.0},
          {"dof": "heave", "amplitude": 1.0, "period": 7.0}, {"dof": "pitch", "amplitude": 3.0, "period": 7.0}]


def test_the_half_cosine():
    """Eq. (1) at its landmarks, eq. (2) its derivative, and the vectorized twin."""
    assert [ramp_factor(t, RAMP) for t in (-1.0, 0.0, RAMP / 4, RAMP / 2, RAMP, 2 * RAMP)] == pytest.approx(
        [0.0, 0.0, (1 - math.sqrt(0.5)) / 2, 0.5, 1.0, 1.0], abs=1e-15)
    assert ramp_factor(3.0, 0.0) == 1.0 and ramp_rate(3.0, 0.0) == 0.0        # no ramp
    times = np.linspace(-1.0, RAMP + 1.0, 101)
    h = 1e-6
    numeric = [(ramp_factor(t + h, RAMP) - ramp_factor(t - h, RAMP)) / (2 * h) for t in times]
    assert [ramp_rate(t, RAMP) for t in times] == pytest.approx(numeric, abs=1e-7)   # h r'' at 0 and T
    r, rate = ramp_series(times, RAMP)
    assert r.tolist() == pytest.approx([ramp_factor(t, RAMP) for t in times], abs=1e-15)
    assert rate.tolist() == pytest.approx([ramp_rate(t, RAMP) for t in times], abs=1e-15)


def lumped_case(waves=None, current=None, motion=None, duration=1.0, drag=1.2):
    line = dict(diameter=0.05, mass=6.0, axial_stiffness=5e6, axial_damping=2e4, added_mass=2.0,
                drag_normal=drag, drag_tangential=0.0)
    return Case.model_validate(dict(
        model="lumped", name="ramped",
        environment={"depth": 100.0, "waves": waves, **({"current": current} if current else {})},
        line_types={"c": line}, vessel={"tow_point": [0.0, 0.0, -3.0], **({"motion": motion} if motion else {})},
        cables=[dict(name="leg", line_type="c", length=95.0, segments=14, **{"from": "anchor:[-50, 0, -60]"},
                     to="vessel")],
        simulation=dict(duration=duration, output_dt=0.5, scheme="rk4")))


def loads(case, t):
    """Nodal forces (n, 3) of ``case``'s lumped model at the still geometry, nodes at rest."""
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = net.x_guess.copy()
    return system.loads(t, x, np.zeros_like(x), 0.0)[0].copy()


@pytest.mark.parametrize("t", [1.0, 3.0, 6.5])
def test_wave_loads_scale_by_the_ramp(t):
    """Without drag the wave loads on lines at rest are linear in the kinematics: ramped, the part
    the waves add is ``r(t)`` times the unramped one."""
    still = loads(lumped_case(drag=0.0), t)
    full = loads(lumped_case(WAVES, drag=0.0), t) - still
    ramped = loads(lumped_case(dict(WAVES, ramp=RAMP), drag=0.0), t) - still
    assert np.max(np.abs(full)) > 1.0                        # the waves load the line
    np.testing.assert_allclose(ramped, ramp_factor(t, RAMP) * full, rtol=1e-10, atol=1e-9)


@pytest.mark.parametrize("t", [1.0, 3.0, 6.5])
def test_current_drag_scales_by_the_ramp_squared(t):
    """Drag on lines at rest is quadratic in the current: ramped, ``r(t)^2`` times the unramped."""
    still = loads(lumped_case(), t)
    full = loads(lumped_case(current=CURRENT), t) - still
    ramped = loads(lumped_case(current=dict(CURRENT, ramp=RAMP)), t) - still
    assert np.max(np.abs(full)) > 1.0
    np.testing.assert_allclose(ramped, ramp_factor(t, RAMP) ** 2 * full, rtol=1e-10, atol=1e-9)


def test_the_continuum_water_ramps():
    """A continuum cable's water (kanat.continuum.water): current and waves times ``r(t)``."""
    def water(ramp, t):
        case = Case.model_validate(dict(
            model="continuum", environment={"depth": 100.0, "current": {"profile": PLANAR, "ramp": ramp},
                                            "waves": dict(WAVES, heading_deg=0.0, ramp=ramp)},
            line_types={"c": dict(diameter=0.05, mass=6.0, axial_stiffness=5e6, drag_normal=1.2)},
            cables=[dict(name="c", line_type="c", length=70.0, segments=10, **{"from": "anchor:[-50, 0, -60]"},
                         to="anchor:[0, 0, -3]")],
            simulation=dict(duration=1.0, dt=0.1)))
        xz = np.column_stack([np.linspace(-50, 0, 11), np.linspace(-60, -3, 11)])
        return planar_water(planar_cable(case), xz, np.zeros_like(xz), t, 0.0, (0.0, 0.0, 1.0))
    for t in (0.0, 2.0, 5.0):
        full, ramped = water(0.0, t), water(RAMP, t)
        for columns in ([k2.UX, k2.UZ], [k2.AX, k2.AZ]):
            np.testing.assert_allclose(ramped[:, columns], ramp_factor(t, RAMP) * full[:, columns], atol=1e-12)


@pytest.mark.parametrize("form", ["harmonics", "table"])
def test_motion_ramps_and_its_velocity_is_the_derivative(form):
    """``{harmonics: [...], ramp: T}`` and ``{table: ..., ramp: T}``: the displacement is ``r q``,
    the velocity its time derivative (central differences), the vectorized series the same."""
    times = np.linspace(0.0, 12.0, 7)
    if form == "harmonics":
        motion = {"harmonics": MOTION, "ramp": RAMP}
    else:
        rows = [[t, 2 * math.sin(t / 2), 0.0, math.cos(t / 3) - 1, 0.0, 4 * math.sin(t / 5), 0.0]
                for t in np.linspace(0.0, 20.0, 401)]
        motion = {"rows": rows, "ramp": RAMP}
    plain = compile_motion(lumped_case(motion={**motion, "ramp": 0.0}).vessel.motion)
    ramped = compile_motion(lumped_case(motion=motion).vessel.motion)
    h = 1e-6
    for t in times:
        q, v = motion_at(ramped, t)
        assert q == pytest.approx(ramp_factor(t, RAMP) * motion_at(plain, t)[0], abs=1e-14)
        if form == "harmonics" and 0 < t:
            numeric = (motion_at(ramped, t + h)[0] - motion_at(ramped, t - h)[0]) / (2 * h)
            assert v == pytest.approx(numeric, abs=1e-7)
    q, v = motion_series(ramped, times)
    for i, t in enumerate(times):
        np.testing.assert_allclose(q[i], motion_at(ramped, t)[0], atol=1e-14)
        np.testing.assert_allclose(v[i], motion_at(ramped, t)[1], atol=1e-14)


def test_a_list_of_harmonics_still_means_no_ramp():
    """The list form (every existing case) is unchanged: ramp 0."""
    assert lumped_case(motion=MOTION).vessel.motion.ramp == 0.0
    assert lumped_case(current=CURRENT).environment.current.ramp == 0.0
    assert lumped_case(WAVES).environment.waves.ramp == 0.0


def top_tension(case):
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    top = int(np.flatnonzero(ds.segment_cable.values == "leg")[-1])
    return ds.time.values, ds.segment_tension.values[:, top]


@pytest.mark.slow
def test_a_ramped_run_ends_where_the_unramped_one_does():
    """Waves, current and motion ramped over 8 s: the run starts from the still-water equilibrium
    and over 49-63 s (two periods of both) its top tension is the unramped run's to 1 % of its
    range."""
    duration = 63.0
    plain = lumped_case(WAVES, CURRENT, MOTION, duration)
    ramped = lumped_case(dict(WAVES, ramp=RAMP), dict(CURRENT, ramp=RAMP), {"harmonics": MOTION, "ramp": RAMP},
                         duration)
    t, ours = top_tension(ramped)
    _, theirs = top_tension(plain)
    _, still = top_tension(lumped_case(duration=0.5))
    assert ours[0] == pytest.approx(still[0], rel=1e-4)        # started in still water, at rest (two
    # equilibria met to their force tolerance, 1e-9 of the load scale, on a line of EA 1e8 N: 4e-5 apart)
    late = t >= duration - 14.0
    spread = np.ptp(theirs[late])
    assert spread > 100.0
    assert np.max(np.abs(ours[late] - theirs[late])) < 0.01 * spread
    early = (t > 0) & (t <= 2.0)                              # and the start was gentler
    assert np.ptp(ours[early]) < 0.5 * np.ptp(theirs[early])


def continuum_case(environment: dict, duration: float) -> Case:
    """A 95 m cable between two anchors, 2-D continuum, in ``environment`` (100 m of water)."""
    return Case.model_validate(dict(
        model="continuum", environment={"depth": 100.0, **environment},
        line_types={"c": dict(diameter=0.05, mass=6.0, axial_stiffness=5e6, drag_normal=1.2)},
        cables=[dict(name="c", line_type="c", length=95.0, segments=20, **{"from": "anchor:[-50, 0, -60]"},
                     to="anchor:[0, 0, -3]")],
        simulation=dict(duration=duration, dt=0.1, output_dt=0.5)))


def continuum_top_tension(case) -> tuple[np.ndarray, np.ndarray]:
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    return ds.time.values, ds.tension.values[:, -1]


@pytest.mark.slow
def test_a_ramped_continuum_run_starts_in_still_water_and_ends_where_the_unramped_one_does():
    """The continuum model with current and waves ramped over 10 s: it starts from the still-water
    steady state (the current is 0 at t = 0) and over 46-60 s its top tension is the unramped run's
    to 1 % of the range."""
    def sea(ramp):
        return {"current": {"profile": PLANAR, "ramp": ramp}, "waves": dict(WAVES, heading_deg=0.0, ramp=ramp)}
    t, ramped = continuum_top_tension(continuum_case(sea(10.0), 60.0))
    _, plain = continuum_top_tension(continuum_case(sea(0.0), 60.0))
    _, still = continuum_top_tension(continuum_case({}, 0.5))
    assert ramped[0] == pytest.approx(still[0], rel=1e-6)
    assert abs(plain[0] - still[0]) > 10.0                    # the current matters at the start
    late = t >= 46.0
    assert np.max(np.abs(ramped[late] - plain[late])) < 0.01 * np.ptp(plain[late])
