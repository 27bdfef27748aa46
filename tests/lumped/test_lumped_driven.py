"""Driven lumped runs with the default scheme: a start at rest in the run's own equations, the
seabed friction's tangent, the explicit fallback, and MoorDyn's WD0050 chain side by side.

The chain is MoorDyn's own test input (``tests/data/moordyn/wd0050_chain.dat``: 410 m of chain,
friction 0.5) with its fairlead moving surge ``-4 cos(2 pi t / 12)`` m and heave
``-cos(2 pi t / 9)`` m (a start at rest), MoorDyn-C (PyPI ``moordyn``) driven by the same
positions and the mean velocity of every 0.05 s coupling step, RK2 at its file's 1 ms.
"""
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from kanat import api
from kanat.io import load_case
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.lumped.system import nowhere
from kanat.physics import contact

import helpers_moordyn
from helpers import DATA, quiet

WD0050 = DATA / "moordyn" / "wd0050_chain.dat"
MOTION = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]


def displacement(t):
    return np.array([-4.0 * math.cos(2 * math.pi * t / 12.0), 0.0, -math.cos(2 * math.pi * t / 9.0)])


def driven(duration, motion=MOTION, **simulation):
    keys = {"model": "lumped", "vessel.motion": motion, "simulation.duration": duration,
            "simulation.output_dt": 0.1, **{f"simulation.{k}": v for k, v in simulation.items()}}
    with warnings.catch_warnings():          # the file's MoorDyn solver settings, not imported
        warnings.simplefilter("ignore")
        return load_case(WD0050).replace(keys)


def fairlead_tension(ds):
    last = int(np.flatnonzero(ds.segment_cable.values == "line1")[-1])
    return ds.time.values, ds.segment_tension.values[:, last]


def moordyn_fairlead_tension(moordyn, path, point, duration, coupling, dt, every=0.1):
    """MoorDyn-C (RK2 at ``dt``) on the file ``path`` with its one coupled point at ``point(t)``, moved
    every ``coupling`` seconds at its mean velocity over the step: rows ``(t, fairlead tension)``
    every ``every`` seconds."""
    return helpers_moordyn.run_moordyn(moordyn, path, duration, coupling, helpers_moordyn.fairlead_tension(moordyn),
                                       int(round(every / coupling)), point=point, scheme="RK2", dt=dt)[1]


def test_a_chain_held_by_friction_starts_at_rest():
    """The start is an equilibrium of the run's own equations: eq. (1)'s accelerations vanish, where
    the friction-held state of statics had 4.3 m/s^2 on the laid chain (friction is regularized in
    velocity and vanishes at rest)."""
    model = LumpedModel(driven(1.0, motion=[]))
    state = model.initial().scheme
    assert np.max(np.abs(state.a)) < 1e-6
    assert np.max(np.abs(state.v)) == 0.0


def test_a_fairlead_that_starts_moving_starts_the_line_quasi_statically():
    """Under a motion moving at t = 0 (``phase_deg: 0``) the line starts with the quasi-static
    velocities of the central difference of equilibria at the motion's places: no element of the
    stiff chain stretches at the start (its strain rate is what the fairlead's 2 m/s would give over
    a kilometre), where every node at the fairlead's speed (a tow's steady frame) would stretch the
    anchor's element at 2 m/s over 5 m, and every node at rest the fairlead's."""
    motion = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": 0.0}]
    model = LumpedModel(driven(1.0, motion=motion))
    state = model.initial().scheme
    x, v = model.system.full(0.0, state.x, state.v)[:2]
    net = model.net
    d = x[net.el_j] - x[net.el_i]
    rate = np.einsum("kr,kr->k", v[net.el_j] - v[net.el_i], d) / np.einsum("kr,kr->k", d, d)
    speed = 4.0 * 2 * math.pi / 12.0
    assert np.linalg.norm(v[net.vessel_nodes[0]]) == pytest.approx(speed)
    assert np.max(np.abs(rate)) < 1e-3 * speed / 5.0


def test_the_friction_tangent_is_the_derivative_at_the_slip():
    """Eqs. (5)-(6) of kanat.physics.contact against central differences of eqs. (3)-(4) in
    velocity, for a node sliding along and across the line at a few v_s."""
    x = np.array([[0.0, 0.0, -100.0], [5.0, 0.0, -100.01], [10.0, 0.3, -100.0]])
    el_i, el_j = np.array([0, 1]), np.array([1, 2])
    area = np.array([0.0, 1.0, 0.0])
    bed = contact.bed_of(contact.PlaneSeabed(depth=100.0))
    law = contact.ContactLaw(stiffness=1e5, damping=0.0, friction_axial=0.5, friction_lateral=0.3,
                             slip_velocity=contact.SLIP_VELOCITY, equilibrium=False,
                             slip_displacement=contact.SLIP_DISPLACEMENT)
    empty = nowhere(3)                                      # no equilibrium friction (kanat.lumped.entries.Laid)
    v = np.zeros((3, 3))
    v[1] = [2.5e-3, -1.5e-3, 0.0]

    def force(v):
        F, N, tangent = np.zeros((3, 3)), np.zeros(3), np.zeros((3, 3))
        contact.contact_forces(x, v, el_i, el_j, area, bed, law, empty, tangent, F, N)
        return F, N, tangent

    _, N, tangent = force(v)
    K, C = np.zeros((3, 3, 3)), np.zeros((3, 3, 3))
    contact.contact_tangent(x, v, area, bed, law, N, tangent, K, C)
    step = 1e-7
    numeric = np.zeros((3, 3))
    for q in range(2):                                   # in the seabed plane (the normal's is damping)
        up, down = v.copy(), v.copy()
        up[1, q] += step
        down[1, q] -= step
        numeric[:, q] = -(force(up)[0][1] - force(down)[0][1]) / (2 * step)
    np.testing.assert_allclose(C[1][:2, :2], numeric[:2, :2], rtol=1e-5, atol=1e-6 * np.abs(numeric).max())


def test_a_step_the_implicit_scheme_cannot_take_is_taken_by_rk4():
    """A scheme whose Newton iteration may not iterate (one iteration, a tolerance nothing meets) fails
    every step: each is taken by rk4 at its safe step, and the run is rk4's to round-off."""
    case = driven(2.0, dt=0.05)
    hopeless = GeneralizedAlphaLumped(max_iterations=1, tolerance=1e-300)
    with quiet():
        ours = api.run(case, scheme=hopeless)
        theirs = api.run(case.replace({"simulation.dt": None}), scheme="rk4")
    assert ours.dataset.attrs["status"] == "ok"
    assert ours.dataset.attrs["explicit_steps"] > 0
    assert "rk4 steps at the explicit safe step" in ours.dataset.attrs["notes"]
    t, mine = fairlead_tension(ours.dataset)
    _, ref = fairlead_tension(theirs.dataset)
    np.testing.assert_allclose(mine, ref, rtol=2e-3)


def test_the_default_scheme_runs_the_driven_chain_as_rk4_does():
    """MoorDyn's WD0050 with its fairlead driven: the default scheme (implicit, step from the motion's
    period) starts and finishes and agrees with rk4 at its safe step (10 s)."""
    with quiet():
        ours = api.run(driven(10.0)).dataset
        ref = api.run(driven(10.0), scheme="rk4").dataset
    assert ours.attrs["status"] == "ok", ours.attrs["status"]
    assert ours.attrs["scheme"] == "generalized-alpha-lumped"
    t, mine = fairlead_tension(ours)
    _, theirs = fairlead_tension(ref)
    window = t >= 2.0
    assert mine[window].mean() == pytest.approx(theirs[window].mean(), rel=1e-2)
    assert mine[window].max() == pytest.approx(theirs[window].max(), rel=3e-2)


@pytest.mark.slow
def test_the_driven_chain_agrees_with_moordyn_side_by_side(moordyn, moordyn_folder):
    """WD0050 driven for 100 s, default kanat scheme against MoorDyn RK2 at 1 ms: fairlead tension mean
    within 1 %, range and maximum within 3 % over 50-100 s (measured at 200 s: -0.03 %, +0.22 %,
    -0.46 %; docs/lumped.md)."""
    duration = 100.0
    copy = moordyn_folder(WD0050)
    theirs = moordyn_fairlead_tension(moordyn, copy, displacement, duration, coupling=0.05, dt=0.001)
    with quiet():
        ds = api.run(driven(duration)).dataset
    assert ds.attrs["status"] == "ok"
    t, ours = fairlead_tension(ds)
    mine, ref = ours[t >= duration / 2], theirs[theirs[:, 0] >= duration / 2, 1]
    assert mine.mean() == pytest.approx(ref.mean(), rel=1e-2)
    assert np.ptp(mine) == pytest.approx(np.ptp(ref), rel=3e-2)
    assert mine.max() == pytest.approx(ref.max(), rel=3e-2)


def three_chain_mooring(tmp_path, length: float) -> Path:
    """A floating-wind mooring of the OC4 class: three chains from anchors 837.6 m out in 200 m of
    water to fairleads 40.868 m out, 14 m down, on the vessel, which heaves 2 m in 12 s."""
    import yaml

    cables = []
    for k, angle in enumerate((180.0, 60.0, 300.0)):
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        cables.append({"name": f"line{k + 1}", "line_type": "chain", "length": length, "segments": 40,
                       "from": {"anchor": [837.6 * c, 837.6 * s, -200.0]},
                       "to": {"vessel": [40.868 * c, 40.868 * s, -14.0]}})
    case = {"name": "three-chain", "model": "lumped",
            "environment": {"depth": 200.0, "seabed": {"stiffness": 3e6, "damping": 3e5}},
            "line_types": {"chain": {"diameter": 0.0766, "mass": 113.35, "axial_stiffness": 7.536e8,
                                     "drag_normal": 2.0, "drag_tangential": 0.4}},
            "cables": cables,
            "vessel": {"motion": [{"dof": "heave", "amplitude": 2.0, "period": 12.0, "phase_deg": -90.0}]},
            "simulation": {"duration": 6.0, "output_dt": 0.5}}
    path = tmp_path / "three_chain.yaml"
    path.write_text(yaml.safe_dump(case, sort_keys=False))
    return path


def test_the_span_check_measures_to_the_fairleads_own_point(tmp_path):
    """A vessel end's span is measured to its own point moved by the motion at t = 0 (heave -2 m), not
    to the tow point: 835.35 m chains reach (no warning), 800 m ones must stretch by the span the
    test computes."""
    span = math.dist((-837.6, 0.0, -200.0), (-40.868, 0.0, -16.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        load_case(three_chain_mooring(tmp_path, 835.35))
    with pytest.warns(UserWarning, match=f"are {span:.6g} m apart but it is 800 m long"):
        load_case(three_chain_mooring(tmp_path, 800.0))


def test_a_heaving_three_chain_mooring_runs_with_the_implicit_scheme(tmp_path):
    """The case that stopped at t = 0 ("a node is 0.11 m below the seabed") runs, implicit, and its
    fairlead tensions agree with rk4's (6 s)."""
    case = load_case(three_chain_mooring(tmp_path, 835.35))
    with quiet():
        ours = api.run(case, scheme="generalized-alpha-lumped").dataset
        ref = api.run(case, scheme="rk4").dataset
    assert ours.attrs["status"] == "ok", ours.attrs["status"]
    t, mine = fairlead_tension(ours)
    _, theirs = fairlead_tension(ref)
    np.testing.assert_allclose(mine, theirs, rtol=5e-3)


@pytest.mark.slow
def test_a_steep_jumper_surged_agrees_with_moordyn_side_by_side(moordyn, case_file):
    """The steep jumper whose fairlead surges 10 m in 27 s (it stopped the default scheme at t = 0.03 s):
    the default scheme and the implicit one at its default step start and finish, and their fairlead
    tension agrees with MoorDyn (RK2, 0.5 ms) over 54-81 s: mean within 1 %, range and maximum within
    3 %. MoorDyn is coupled every 2 ms: at the 0.05 s of the chain tests its piecewise-linear fairlead
    (a constant velocity per coupling step) rings the stiff line, and its own range comes out 35 %
    lower than with 1-5 ms (measured)."""
    path = case_file(helpers_moordyn.jumper_file(), "jumper.dat")
    duration = 81.0

    def surge(t):
        return np.array([-10.0 * math.cos(2 * math.pi * t / 27.0), 0.0, -5.0])

    theirs = moordyn_fairlead_tension(moordyn, path, surge, duration, coupling=0.002, dt=0.0005)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(path).replace({"model": "lumped", "simulation.duration": duration,
                                        "simulation.output_dt": 0.1, "vessel.motion": [
                                            {"dof": "surge", "amplitude": 10.0, "period": 27.0, "phase_deg": -90.0}]})
    for scheme in (None, "generalized-alpha-lumped"):          # the default, and the implicit scheme's own step
        with quiet():
            ds = api.run(case, scheme=scheme).dataset
        assert ds.attrs["status"] == "ok"
        t, ours = fairlead_tension(ds)
        mine, ref = ours[t >= 54.0 - 1e-9], theirs[theirs[:, 0] >= 54.0 - 1e-9, 1]
        assert mine.mean() == pytest.approx(ref.mean(), rel=1e-2)
        assert np.ptp(mine) == pytest.approx(np.ptp(ref), rel=3e-2)
        assert mine.max() == pytest.approx(ref.max(), rel=3e-2)
