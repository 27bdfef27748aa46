"""The fused compiled stepping (kanat.lumped.fast) against its twin, the Python path of
LumpedSystem driven step by step: same accelerations, same states after many steps, same
snap events; the vectorized track sampler against VesselTrack.state."""

import dataclasses

import numpy as np
import pytest

from kanat.lumped import fast
from kanat.lumped.advance import (
    FusedArrays,
    advance,
    element_tensions,
    supports,
    track_samples,
)
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.system import LumpedSystem
from kanat.model import Case
from kanat.lumped.integrators import SCHEMES, GeneralizedAlphaLumped, ImplicitState
from kanat.schemes import get_scheme

from helpers import EXAMPLES

WAVES = {"regular": {"type": "regular", "height": 3.0, "period": 6.0, "heading_deg": 150.0},
         "jonswap": {"type": "jonswap", "hs": 2.5, "tp": 7.0, "heading_deg": 200.0, "seed": 4}}


def network_case(waves="regular", depth=None, profile=True, stretching="none", ramp=0.0):
    line = dict(diameter=0.02, mass=3.0, axial_stiffness=2e5, axial_damping=400.0, added_mass=0.4,
                drag_normal=1.4, drag_tangential=0.03)
    env = {"waves": dict(WAVES[waves], stretching=stretching, ramp=ramp) if waves else None, "depth": depth,
           "current": dict({"profile": [[0, 0.6, 0.2, 0], [-30, 0.3, 0.1, 0.01], [-80, 0, 0, 0]]} if profile
                           else {"velocity": [0.3, -0.1, 0.0]}, ramp=ramp)}
    return Case.model_validate(dict(
        model="lumped", environment=env, line_types={"c": line},
        points={"p": dict(position=[-40, 0, -15], mass=5.0)},
        bodies={"board": dict(mass=80, net_buoyancy=-300, drag_area=0.4, added_mass=30, spreading_force=600,
                              position=[-60, 20, -20]),
                "buoy": dict(mass=100, net_buoyancy=-981, drag_area=0.3, added_mass=40, position=[-50, 0, -0.5],
                             surface_buoy={"waterplane_area": 1.0, "height": 2.0})},
        vessel={"tow_point": [-5, 1, 0], "track": [{"straight": {"speed": 1.5, "duration": 0.5}},
                                                    {"turn": {"radius": 50, "angle_deg": 30}},
                                                    {"speed_step": {"to_speed": 2.5}}]},
        cables=[dict(name="tow", line_type="c", length=45, segments=6, **{"from": "vessel"}, to="p"),
                dict(name="bridle", line_type="c", length=25, segments=4, **{"from": "p"}, to="board"),
                dict(name="buoy_line", line_type="c", length=16, segments=3, **{"from": "p"}, to="buoy"),
                dict(name="tail", line_type="c", length=10, segments=2, **{"from": "board"}, to="free")],
        simulation=dict(duration=1, dt=0.01)))


def start(case):
    net = build_network(case)
    x = equilibrium(net, case)[0]
    system = LumpedSystem(net, case)
    rng = np.random.default_rng(1)
    v = rng.normal(0.0, 0.5, x.shape)                # stir it so that every term is exercised
    return net, system, x, v


@pytest.mark.parametrize("waves, depth, profile, stretching, ramp", [
    ("regular", None, True, "none", 0.0), ("jonswap", 60.0, False, "none", 0.0), (None, None, False, "none", 0.0),
    ("regular", 60.0, True, "wheeler", 4.0), ("jonswap", None, False, "wheeler", 0.0),
    (None, None, False, "none", 4.0)])
def test_fused_acceleration_matches_the_system(waves, depth, profile, stretching, ramp):
    """Also with Wheeler stretching and ramps on the waves and the current (both ramped over 4 s:
    0.3 s and 2.7 s are inside the ramp)."""
    case = network_case(waves, depth, profile, stretching, ramp)
    _, system, x, v = start(case)
    arrays = FusedArrays(system)
    free = system.free_index
    for t in (0.3, 2.7):
        samples = track_samples(system, np.array([t]))
        y = np.concatenate([x[free].ravel(), v[free].ravel()])
        dy = np.zeros_like(y)
        fast.derivative_at(t, y, 0, samples, arrays.nodes, arrays.el, arrays.bodies, arrays.env, arrays.work, dy)
        want = system.rhs(t, y)
        np.testing.assert_allclose(dy, want, rtol=1e-11, atol=1e-11 * np.max(np.abs(want)))
        np.testing.assert_allclose(arrays.work.tension, system.tension, rtol=1e-12, atol=1e-9)   # and the tensions


def test_track_samples_match_the_vessel_track():
    case = network_case()
    system = LumpedSystem(build_network(case), case)
    times = np.linspace(0.0, 3.0, 61)
    pos, vel, heading = track_samples(system, times)
    assert pos.shape == (len(times), 1, 3)                       # one vessel node: the tow point
    for k, t in enumerate(times):
        st = system.track.state(t)
        np.testing.assert_allclose(pos[k, 0], st.position, atol=1e-12)
        np.testing.assert_allclose(vel[k, 0], st.velocity, atol=1e-12)
        assert heading[k] == pytest.approx(st.heading, abs=1e-14)


@pytest.mark.parametrize("name", ["rk4", "abm4"])
def test_fused_steps_match_python_steps_and_record_the_same_snaps(name):
    case = network_case("regular")
    net, system, x, v = start(case)
    scheme = get_scheme(name, SCHEMES)
    assert supports(system, scheme)
    free, h, steps = system.free_index, 0.002, 600
    state0 = scheme.start(system, 0.0, x[free], v[free], h)
    T = np.zeros(net.n_elements)

    def tensions(state):
        return element_tensions(system, state, T)

    python_tracker, fused_tracker = SnapTracker(0.0, np.zeros(net.n_elements)), SnapTracker(0.0, np.zeros(net.n_elements))
    state = state0
    for _ in range(steps):
        state = scheme.step(system, state, h)
        python_tracker.update(state.t, tensions(state))
    fused, taken = advance(scheme, system, state0, h, steps, fused_tracker, tensions)
    assert taken == steps and fused.t == pytest.approx(state.t, abs=1e-12)
    np.testing.assert_allclose(fused.y, state.y, rtol=1e-9, atol=1e-9)
    a, b = python_tracker.events(), fused_tracker.events()
    assert len(a["time"]) > 0                                   # the stirred network snaps
    for key in a:
        np.testing.assert_allclose(b[key], a[key], rtol=1e-6, atol=1e-6)
    np.testing.assert_array_equal(state0.y, scheme.start(system, 0.0, x[free], v[free], h).y)  # untouched


def test_fused_path_is_not_used_for_the_consistent_mass():
    case = network_case()
    net = build_network(case)
    assert not supports(LumpedSystem(net, case, "consistent"), get_scheme("rk4", SCHEMES))
    assert supports(LumpedSystem(net, case), get_scheme("generalized-alpha-lumped", SCHEMES))


def test_fused_implicit_steps_match_the_python_scheme():
    """The compiled generalized-α (modified Newton, band LU in RCM order) against implicit.py's (full
    Newton, SuperLU), both converged to 1e-10: the same states and snap events."""
    case = network_case("regular")
    net, system, x, v = start(case)
    scheme = GeneralizedAlphaLumped(lambda_inf=-0.3, tolerance=1e-10)
    free, h, steps = system.free_index, 0.01, 60
    state0 = scheme.start(system, 0.0, x[free], v[free], h)
    T = np.zeros(net.n_elements)
    python_tracker, fused_tracker = SnapTracker(0.0, np.zeros(net.n_elements)), SnapTracker(0.0, np.zeros(net.n_elements))
    state = state0
    for _ in range(steps):
        state = scheme.step(system, state, h)
        python_tracker.update(state.t, element_tensions(system, state, T))
    fused, taken = advance(scheme, system, state0, h, steps, fused_tracker, lambda st: element_tensions(system, st, T))
    assert taken == steps
    for key in ("x", "v"):
        np.testing.assert_allclose(getattr(fused, key), getattr(state, key), rtol=1e-7, atol=1e-7)
    a, b = python_tracker.events(), fused_tracker.events()
    assert len(a["time"]) > 0
    for key in a:
        np.testing.assert_allclose(b[key], a[key], rtol=1e-5, atol=1e-5)


def test_band_order_keeps_a_network_narrow():
    from kanat.lumped.fast_implicit import band_order
    net = build_network(network_case())
    position, bandwidth = band_order(net, np.flatnonzero(net.free))
    assert sorted(position[net.free]) == list(range(np.count_nonzero(net.free)))
    assert bandwidth <= 3                                      # a tree of short branches: 3 nodes wide at most


def test_block_band_lu_solves_as_a_dense_solver_does():
    """The implicit scheme's block LU (3 x 3 node blocks, two blocks either side) against NumPy's
    dense solve of the same matrix: a mass-dominated block band with non-symmetric couplings."""
    from kanat.lumped.fast_implicit import band_factor, band_substitute
    rng = np.random.default_rng(4)
    nb, half = 40, 2
    band = rng.normal(size=(nb, 2 * half + 1, 3, 3))
    band[:, half] += 20.0 * np.eye(3)
    for p in range(nb):                                       # blocks outside the matrix stay zero
        for d in range(2 * half + 1):
            if not 0 <= p + d - half < nb:
                band[p, d] = 0.0
    dense = np.zeros((3 * nb, 3 * nb))
    for p in range(nb):
        for d in range(2 * half + 1):
            q = p + d - half
            if 0 <= q < nb:
                dense[3 * p:3 * p + 3, 3 * q:3 * q + 3] = band[p, d]
    b = rng.normal(size=3 * nb)
    x = b.copy()
    assert band_factor(band, half)
    band_substitute(band, half, x)
    np.testing.assert_allclose(x, np.linalg.solve(dense, b), rtol=1e-12, atol=1e-14)
    singular = np.zeros((2, 3, 3, 3))
    assert not band_factor(singular, 1)


def test_a_run_counts_the_steps_it_halved():
    """Three-leg chain mooring (examples/moordyn) at 12.5 ms with two Newton iterations a step: the
    compiled iteration fails on some steps, which are retaken in halves (and by rk4 where the halves
    fail too); the run's ``step_cuts`` is the number of failed attempts a spy on the compiled steps
    sees."""
    import warnings

    import kanat
    from kanat.io import load_case
    from kanat.lumped import advance
    from kanat.lumped.integrators import GeneralizedAlphaLumped

    path = EXAMPLES / "moordyn" / "three_leg_chain_50.dat"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                        # the file's MoorDyn-only options
        case = load_case(path)
    case = case.replace({"vessel.motion": [{"dof": "surge", "amplitude": 2.0, "period": 11.0, "phase_deg": -90.0},
                                           {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}],
                         "simulation.duration": 16.0, "simulation.output_dt": 0.5,
                         "simulation.scheme": "generalized-alpha-lumped", "simulation.dt": 0.0125})
    failures = []
    compiled = advance._fused_implicit

    def spy(*args):
        new, done, iterations, failed = compiled(*args)
        failures.append(failed)
        return new, done, iterations, failed

    with pytest.MonkeyPatch.context() as patch:           # two iterations a step: some steps fail
        patch.setattr(advance, "_fused_implicit", spy)
        result = kanat.run(case, scheme=GeneralizedAlphaLumped(max_iterations=2))
    assert result.dataset.attrs["status"] == "ok"
    assert sum(failures) >= 1
    assert result.dataset.attrs["step_cuts"] == sum(failures)


@pytest.mark.parametrize("fails_above, cuts", [(0.5, 1), (0.25, 3)])
def test_the_python_scheme_counts_its_halvings(fails_above, cuts, monkeypatch):
    """A Newton iteration that fails on steps above ``fails_above * h``: one halving (two half
    steps), or three (each half halved again)."""
    from kanat.lumped import implicit

    def attempt(scheme, system, state, h):
        if h > fails_above * 0.1 + 1e-12:
            return None, scheme.max_iterations
        return dataclasses.replace(state, t=state.t + h), 1

    monkeypatch.setattr(implicit, "_attempt", attempt)
    state = ImplicitState(0.0)
    new = implicit.generalized_alpha_step(GeneralizedAlphaLumped(), None, state, 0.1)
    assert new.t == pytest.approx(0.1)
    assert new.cuts == cuts
