"""WHOI Cable's shipped example systems as kanat cases (examples/whoi/), each run and checked.

Oracles, independent of the model that runs the case:

- steady states: the single-cable statics (shooting) or the continuum model's initial state
  against the lumped model's network equilibrium (another discretization and another solver);
- closed forms: force balance at a body at the end of a line, vertical balance of a hanging
  tow, the 3-4-5 and square geometries of the multi-leg moorings (taut legs stretched by T/EA);
- dynamics: the same run at half the time step (a converged grid in time).

WHOI Cable's example files give no results and its manuals no tables of them, so no test
compares with WHOI's own numbers. Cases kanat cannot run yet are marked ``xfail(strict=True)``
with the failure they show today: the mark fails the moment the failure is fixed.
"""
import math
import warnings

import numpy as np
import pytest

import kanat
from kanat.io import load_case

from helpers import EXAMPLES

WHOI = EXAMPLES / "whoi"
CASES = sorted(p.stem for p in WHOI.glob("*.yaml"))


def case_of(name):
    with warnings.catch_warnings():                 # the case checks' notes on ignored keys
        warnings.simplefilter("ignore")
        return load_case(WHOI / f"{name}.yaml")


def quietly(function, *args):
    """``function(*args)`` with the case checks' warnings (expected on these variants) muted."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args)


def initial_state(case, model):
    """The state a run of ``case`` with ``model`` starts from (its steady state), as a dataset.

    The lumped variant drops what the lumped model does not take (bending stiffness, the winch)
    and the vessel's prescribed motion, whose velocity at t = 0 would move the equilibrium."""
    sim = {**case.simulation.model_dump(exclude_none=True), "duration": case.simulation.dt,
           "output_dt": case.simulation.dt}
    changes = {"model": model, "simulation": sim}
    if model != case.model:
        sim["scheme"] = None                    # the model's default
    if model == "lumped":
        sim.pop("dimensions", None)
        changes["line_types"] = {n: {**t.model_dump(exclude_none=True), "bending_stiffness": 0.0}
                                 for n, t in case.line_types.items()}
        changes["winch"] = []
        changes["vessel"] = {**case.vessel.model_dump(exclude_none=True), "motion": []}
    ds = quietly(kanat.simulate, quietly(case.replace, changes))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    return ds.isel(time=0)


def statics(case):
    """The steady state by the statics solvers (the winch's pay-out is after it)."""
    return quietly(kanat.solve_statics, quietly(case.replace, {"model": "statics", "winch": []}))


def element_weight(case, name):
    """The largest weight in water of one element of cable ``name`` [N]."""
    cable = next(c for c in case.cables if c.name == name)
    sections = cable.sections or [cable]
    return max(abs(case.line_types[p.line_type].weight_in_water or 0.0) * p.length / p.segments for p in sections)


def end_tensions(ds):
    """{cable: (tension at 'from', tension at 'to')} of a result."""
    cables = ds["cable"].values
    return {str(c): (float(ds["tension"].values[cables == c][0]), float(ds["tension"].values[cables == c][-1]))
            for c in dict.fromkeys(cables)}


def test_all_27_whoi_examples_are_accounted_for_in_the_readme():
    readme = (WHOI / "README.md").read_text()
    rows = [line for line in readme.splitlines() if line.startswith("| `") and ".cbl`" in line]
    assert len(rows) == 27
    tables = readme + (WHOI / "EVENTS.md").read_text()          # the cases with events have their own page
    for name in CASES:                                          # every case file is in a table
        assert f"[{name}.yaml]" in tables


@pytest.mark.parametrize("name", CASES)
def test_whoi_case_validates(name):
    case = case_of(name)
    assert case.name.startswith("whoi-")
    assert case.model in ("continuum", "lumped")


# Steady state, the model that runs the case against the lumped model's equilibrium ---------------

STATICS_VS_LUMPED = ["mine", "towing", "tow3d", "rov"]                 # rov last (slow)
NETWORKS_IN_STILL_WATER = ["multi_leg", "multi_leg_3d", "loops"]   # network statics takes no current
NETWORKS = ["bimoor", "multi_leg", "multi_leg_3d", "branch", "loops", "horiz"]
CONTINUUM_VS_LUMPED = ["taut", "bottom"]


@pytest.mark.parametrize("name", [*STATICS_VS_LUMPED[:-1], pytest.param("rov", marks=pytest.mark.slow)])
def test_statics_and_the_lumped_equilibrium_agree(name, variant=lambda case: case):
    case = variant(case_of(name))
    a, b = statics(case), initial_state(case, "lumped")
    for body in a["body"].values:                              # body positions to 1 mm in 1 km
        scale = max(1.0, float(np.max(np.abs(a["body_position"].sel(body=body).values))))
        gap = np.max(np.abs(a["body_position"].sel(body=body).values - b["body_position"].sel(body=body).values))
        assert gap < 2e-3 * scale, (body, gap)
    ta, tb = end_tensions(a), end_tensions(b)
    for cable, (t0, t1) in ta.items():     # a lumped end's tension is its element's, half an element in
        slack = 0.6 * element_weight(case, cable) + 1.0
        assert tb[cable][0] == pytest.approx(t0, rel=5e-3, abs=slack)
        assert tb[cable][1] == pytest.approx(t1, rel=5e-3, abs=slack)


def still(case):
    """``case`` in still water."""
    env = {**case.environment.model_dump(exclude_none=True), "current": {"velocity": [0.0, 0.0, 0.0]}}
    return quietly(case.replace, {"environment": env})


@pytest.mark.parametrize("name", NETWORKS_IN_STILL_WATER)
def test_network_statics_and_the_lumped_equilibrium_agree_in_still_water(name):
    test_statics_and_the_lumped_equilibrium_agree(name, still)


def bodies_in_balance(case, ds, tolerance):
    """The line force on each body of result ``ds`` balances its net buoyancy, its drag in the
    current at its height, its own force and its waterplane, to ``tolerance`` [N]."""
    for body in ds["body"].values:
        spec = case.bodies[str(body)]
        u = np.asarray(case.environment.current.at(float(ds["body_position"].sel(body=body).values[2])), dtype=float)
        drag = 0.5 * case.environment.water_density * spec.drag_area * np.linalg.norm(u) * u
        load = np.array([0.0, 0.0, spec.net_buoyancy]) + drag + np.array(spec.force)
        line = ds["body_force"].sel(body=body).values
        if spec.surface_buoy is not None:                     # the waterplane carries the rest
            immersion = -float(ds["body_position"].sel(body=body).values[2])
            load[2] += case.environment.water_density * case.environment.gravity * spec.surface_buoy.waterplane_area * immersion
        assert np.max(np.abs(line + load)) < tolerance, (body, line, load)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["branch", "horiz"])
def test_network_statics_of_an_array_with_inline_floats_goes_to_the_lumped_equilibrium(name):
    """Network statics finds no catenaries for lines split by inline floats ("load continuation
    stalled", "no catenary found"); the front door solves them by the lumped equilibrium and says
    so. Oracles: every body's balance, and the lumped model's own start in still water."""
    case = still(case_of(name))
    ds = statics(case)
    assert ds.attrs["status"] == "ok"
    assert ds.attrs["scheme"] == "lumped equilibrium"
    bodies_in_balance(case, ds, 3.0)
    run = initial_state(case, "lumped")
    gap = np.max(np.abs(ds["body_position"].values - run["body_position"].values))
    assert gap < 1e-6, gap


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.slow) if name == "horiz" else name
                                  for name in NETWORKS])
def test_each_body_of_a_network_is_in_balance(name):
    """The force the lines' ends exert on each body balances its net buoyancy, its drag in the
    (uniform) current and its own force, to 0.01 N, in the lumped model's equilibrium (the case's sea
    left out: at t = 0 it would already pull on the bodies)."""
    case = case_of(name)
    calm = quietly(case.replace, {"environment": {**case.environment.model_dump(exclude_none=True), "waves": None}})
    bodies_in_balance(calm, initial_state(calm, "lumped"), 0.01)


@pytest.mark.parametrize("name", CONTINUUM_VS_LUMPED)
def test_the_continuum_start_and_the_lumped_equilibrium_agree_on_a_surface_mooring(name):
    case = case_of(name)
    a, b = initial_state(case, "continuum"), initial_state(case, "lumped")
    for body in a["body"].values:
        gap = np.max(np.abs(a["body_position"].sel(body=body).values - b["body_position"].sel(body=body).values))
        assert gap < 0.05, (body, gap)
    buoy_end = [t[1] for t in end_tensions(a).values()], [t[1] for t in end_tensions(b).values()]
    assert buoy_end[1] == pytest.approx(buoy_end[0], rel=2e-3)


# Closed forms ------------------------------------------------------------------------------------

def test_mine_tether_holds_the_buoyancy_and_drag_of_the_sphere():
    case = case_of("mine")
    ds = statics(case)
    mine, z = case.bodies["mine"], float(ds["body_position"].sel(body="mine").values[2])
    u = 0.2 * np.exp(-0.055 * -z)                             # the example's current at the sphere
    profile = np.array(case.environment.current.profile)
    u_profile = np.interp(-z, -profile[:, 0], profile[:, 1])
    assert u_profile == pytest.approx(u, rel=0.01)            # the sampled profile is the expression
    drag = 0.5 * case.environment.water_density * mine.drag_area * np.hypot(u_profile, u_profile) * u_profile
    expected = np.hypot(np.hypot(drag, drag), mine.net_buoyancy)
    assert end_tensions(ds)["tether"][1] == pytest.approx(expected, rel=1e-6)


def test_towing_top_tension_is_the_weight_of_sled_and_cable():
    case = case_of("towing")
    top = end_tensions(statics(case))["tow"][0]
    weight = -case.bodies["sled"].net_buoyancy + 1000 * case.line_types["cable"].weight_in_water
    # a 0.05 m/s current barely tilts it; the line's EI makes statics the lumped equilibrium, whose
    # top tension is its first element's, half an element's weight below the end
    assert top == pytest.approx(weight, rel=1e-4, abs=0.6 * element_weight(case, "tow"))


def test_multi_leg_sphere_sits_at_the_3_4_5_apex_with_legs_stretched_by_their_tension():
    case = case_of("multi_leg")
    ds = initial_state(case, "lumped")
    x, _, z = ds["body_position"].sel(body="sphere").values
    ea = case.line_types["wire_10mm"].axial_stiffness
    t = {c: np.mean(v) for c, v in end_tensions(ds).items()}
    stretched = {c: length * (1 + t[c] / ea) for c, length in (("leg_0", 50), ("leg_30", 40), ("leg_60", 50))}
    for cable, anchor_x in (("leg_0", 0.0), ("leg_30", 30.0), ("leg_60", 60.0)):
        chord = np.hypot(x - anchor_x, z + 44.0)
        assert chord == pytest.approx(stretched[cable], abs=0.01)   # taut: sag of 2.6 N/m under 4 kN
    assert x == pytest.approx(30.0, abs=0.05)


def test_multi_leg_3d_sphere_stands_over_the_square_centre():
    case = case_of("multi_leg_3d")
    ds = initial_state(case, "lumped")
    x, y, z = ds["body_position"].sel(body="sphere").values
    t = np.mean([np.mean(v) for v in end_tensions(ds).values()])
    leg = 50 * (1 + t / case.line_types["wire_10mm"].axial_stiffness)
    assert abs(y) < 1e-6 and abs(x) < 0.05                      # the current along x pushes it 2 cm
    assert z + 44.0 == pytest.approx(np.sqrt(leg**2 - 2 * 30.0**2), abs=0.01)


# Dynamics: the same run at half the time step ---------------------------------------------------

def run_for(case, duration, dt, output_dt, model=None):
    """A run of ``case`` cut to ``duration`` at step ``dt``; by ``model`` (its default scheme)
    instead of the case's own if given."""
    sim = {**case.simulation.model_dump(exclude_none=True), "duration": duration, "dt": dt, "output_dt": output_dt}
    changes = {"simulation": sim}
    if model not in (None, case.model):
        sim["scheme"] = None
        sim.pop("dimensions", None)
        changes["model"] = model
    return quietly(kanat.simulate, quietly(case.replace, changes))


DYNAMIC = {     # name: (duration, dt, output_dt, tolerance on the tensions at each output[, model])
    "towing": (20.0, 0.5, 1.0, 0.25),      # the winch starts at full rate: the cable rings axially
    "multi_leg": (10.0, 0.05, 0.5, 0.05),  # a 4.5 m sea on taut wire legs; the sphere's Froude–Krylov pull
    # (rho V a_w, 1.6 m^3) rings them: peaks differ 6.2 % between dt 0.1 and 0.05, 3.6 % between 0.05 and 0.025
    "loops": (5.0, 0.05, 0.5, 0.02),
    "mine": (10.0, 0.1, 0.1, 0.05, "lumped"),      # through the slack instant that stops the continuum
}
# Not here: rov and stratus2 run, but their runs at dt and dt/2 disagree: see README.md.
SLOW_DYNAMIC = {
    "bottom": (10.0, 0.01, 0.1, 0.05),     # WHOI's 16 s wave ramp; 20 s: peaks 1.5 %, means 0.03 % apart
    "taut": (10.0, 0.01, 0.1, 0.05),       # WHOI's 10 s wave ramp, through slack instants from 5 s on;
    # 20 s: peaks 2.0 %, means 0.005 % apart (continuum)
    "tow3d": (300.0, 1.0, 5.0, 0.02),
    "multi_leg_3d": (20.0, 0.1, 0.5, 0.05),
    "branch": (5.0, 0.01, 0.1, 0.05),
    "cmo": (10.0, 0.1, 0.5, 0.05),
    "swex": (10.0, 0.05, 0.5, 0.05),
    "bimoor": (10.0, 0.01, 0.1, 0.05),
    "horiz": (10.0, 0.5, 1.0, 0.05),
}


def _half_step_agrees(name, duration, dt, output_dt, peak_tolerance, model=None):
    """The run at ``dt`` against the run at ``dt / 2``: body positions to 2 % of their
    motion (at least 1 m)), the time-mean tension at every node to 1 %, the tensions at every output to
    ``peak_tolerance`` of the largest."""
    case = case_of(name)
    coarse, fine = run_for(case, duration, dt, output_dt, model), run_for(case, duration, dt / 2, output_dt, model)
    assert coarse.attrs["status"] == "ok", coarse.attrs["status"]
    assert fine.attrs["status"] == "ok", fine.attrs["status"]
    tension = coarse["tension"].values, fine["tension"].values
    scale = np.max(np.abs(tension[1]))
    assert np.max(np.abs(tension[0].mean(axis=0) - tension[1].mean(axis=0))) < 0.01 * scale
    assert np.max(np.abs(tension[0] - tension[1])) < peak_tolerance * scale
    if "body_position" in coarse:
        span = max(1.0, float(np.max(np.ptp(fine["body_position"].values, axis=0))))
        assert np.max(np.abs(coarse["body_position"].values - fine["body_position"].values)) < 0.02 * span
    return coarse


@pytest.mark.parametrize("name", sorted(DYNAMIC))
def test_a_short_run_is_converged_in_its_time_step(name):
    _half_step_agrees(name, *DYNAMIC[name])


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_DYNAMIC))
def test_a_longer_run_is_converged_in_its_time_step(name):
    _half_step_agrees(name, *SLOW_DYNAMIC[name])


def test_towing_winch_pays_out_one_metre_a_second():
    ds = run_for(case_of("towing"), 20.0, 0.5, 1.0)
    assert ds.attrs["status"] == "ok"
    assert float(ds["winch_length"].values[-1] - ds["winch_length"].values[0]) == pytest.approx(20.0, rel=1e-6)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["deep_s", "surface"])
def test_lumped_equilibrium_of_a_mooring_with_many_floats(name):
    """The S-tether (3500 m of water, a 13.35 kN subsurface float at s = 3413.5 m, a weakly restrained
    surface float): Newton's method stalls and dynamic relaxation places it (about a minute).
    Oracle: the balance of each body (line force, net buoyancy, drag in the current at its depth,
    the surface float's waterplane) to 3 N; the subsurface float on its 3413.5 m of line from the
    anchor nearly straight up, between the unstretched line's reach and its reach stretched 0.3 % (the
    wire's strain at the float's 13.35 kN); the surface float's keel in the water; no node under the
    default seabed (``environment.depth`` alone: stiffness 3e6 Pa/m) that the run applies."""
    case = case_of(name)
    assert case.environment.seabed is None and case.with_seabed_contact().environment.seabed is not None
    ds = initial_state(case, "lumped")
    assert float(ds["position"].values[..., 2].min()) >= -3500.0
    bodies_in_balance(case, ds, 3.0)
    z = float(ds["body_position"].sel(body="ssf").values[2])
    assert -3500.0 + 3413.5 < z < -3500.0 + 3413.5 * 1.003, z          # the wire: 3.0e-3 strain at 13.35 kN
    assert -case.bodies["float"].surface_buoy.height < float(ds["body_position"].sel(body="float").values[2]) < 0.0


# What kanat cannot run yet (product failures; see README.md) -----------------------------------

def test_mine_in_waves_runs_through_its_slack_instant():
    ds = run_for(case_of("mine"), 10.0, 0.1, 0.1)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]


def test_taut_mooring_in_waves_runs_in_the_continuum_model():
    ds = run_for(case_of("taut"), 1.0, 0.01, 0.1)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]


@pytest.mark.slow
def test_bottom_mooring_in_waves_runs_in_the_lumped_model():
    ds = run_for(case_of("bottom"), 1.0, 0.01, 0.1)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]


def cap_share(z, diameter):
    """Submerged share of a sphere of ``diameter`` centred at height ``z`` under a still surface: its
    cap of height h = clip(D/2 - z, 0, D) holds pi h^2 (3a - h) / 3 of the sphere's 4 pi a^3 / 3."""
    a = diameter / 2
    h = min(max(a - z, 0.0), diameter)
    return (math.pi * h * h * (3 * a - h) / 3) / (4 * math.pi * a**3 / 3)


def cap_height(share, diameter):
    """The centre's height [m] at which a sphere's cap holds ``share`` (0 < share < 1) of its
    volume: the root h in [0, D] of h^3 - 3 a h^2 + 4 share a^3 = 0, then z = a - h."""
    a = diameter / 2
    roots = np.roots([1.0, -3.0 * a, 0.0, 4.0 * share * a**3])
    (h,) = [r.real for r in roots if abs(r.imag) < 1e-9 and 0.0 <= r.real <= diameter]
    return a - h


def lines_pull_on_floats(case, x):
    """The vertical force on each spherical float's node at positions ``x`` (n, 3) from everything
    but its buoyancy (its lines, their weight and drag, its own weight) [N], by the lumped model's
    loads for the case with the floats' buoyancy taken away (``net_buoyancy = -m g``)."""
    from kanat.lumped.network import build_network
    from kanat.lumped.system import LumpedSystem

    g = case.environment.gravity
    bodies = {n: {**b.model_dump(exclude_none=True), **({"net_buoyancy": -b.mass * g} if b.diameter else {})}
              for n, b in case.bodies.items()}
    bare = quietly(case.replace, {"bodies": bodies})
    net = build_network(bare)
    system = LumpedSystem(net, bare, waves=False)
    system = LumpedSystem(net, bare, waves=False, steady_velocity=system.frame_velocity())
    full, v, _, heading = system.full(0.0, x[system.free_index], np.zeros_like(x[system.free_index]))
    F, _ = system.loads(0.0, full, v, heading)
    return {n: float(F[node, 2]) for n, node in zip(net.body_names, net.body_node) if case.bodies[n].diameter}


@pytest.mark.slow
@pytest.mark.parametrize("name, surfaced", [("shallow_s", 4), ("seatex", 40)])
def test_floats_at_the_surface_float_at_the_draft_their_lines_load_gives(name, surfaced):
    """Lines held up by floats that lift more than the lines weigh (shallow_s: 14 x 200 N against
    1456 N of umbilical; seatex: 100 x 39.6 N against 1634 N of chain): the floats' buoyancy
    follows their immersion (``diameter``), and the lumped equilibrium (by dynamic relaxation,
    first for such floats) puts some of them at the surface. Oracle, at every float: the vertical
    pull of everything but its buoyancy (the model's loads with its buoyancy taken away) is what its
    submerged cap carries, so its height is the cap's (volume pi h^2 (3a - h) / 3, the cubic solved
    here) to 1e-6 m where it floats at the surface, and a float under water carries its whole
    buoyancy. The run starts from that state (no float refused above the water) and, in its
    steady current, stays there (the compiled kernels' floats against the equilibrium's)."""
    from kanat.lumped.equilibrium import equilibrium
    from kanat.lumped.network import build_network

    case = case_of(name)
    start = case.model_copy(update={"environment": case.environment.at_start()})
    net = build_network(start)
    x, info = quietly(equilibrium, net, start)
    assert info["fallback"] == "dynamic relaxation"
    pull = lines_pull_on_floats(start, x)
    at_surface = 0
    for body, node in zip(net.body_names, net.body_node):
        spec = case.bodies[body]
        if spec.diameter is None:
            continue
        share = -pull[body] / spec.buoyancy(case.environment.gravity)
        z = float(x[node, 2])
        if z > -spec.diameter / 2:                                     # at the surface
            at_surface += 1
            assert 0.0 < share < 1.0, (body, share)
            assert z == pytest.approx(cap_height(share, spec.diameter), abs=1e-6), body
        else:                                                          # under water: its whole buoyancy
            assert share == pytest.approx(1.0, abs=1e-6), (body, share)
        assert cap_share(z, spec.diameter) == pytest.approx(share, abs=1e-6), body
    assert at_surface >= surfaced
    ds = run_for(case, 10.0, case.simulation.dt, 1.0)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    assert "initial equilibrium by dynamic relaxation" in ds.attrs["notes"]
    drift = np.max(np.abs(ds["body_position"].values - ds["body_position"].values[0]))
    assert drift < 1e-3, drift          # the run's compiled loads hold the equilibrium's floats where they are


SURFACE_FLOATS_IN_WAVES = {     # name: (dt, tensions at every output, their means, positions [m]) as fractions
    "shallow_s": (0.05, 1e-3, 1e-4, 1e-3),     # measured: 3.6e-5, 1e-6, 5.9e-5 m of 1.72 m of motion
    "seatex": (0.01, 0.1, 0.01, 1e-3),         # 5.7e-2, 2.3e-3, 1.4e-4 m of 1.02 m; at the case's 0.05 s the
    # chain's snap peaks differ by 46 % of the largest tension between dt and dt/2 (positions 4e-4 m)
}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SURFACE_FLOATS_IN_WAVES))
def test_floats_at_the_surface_ride_a_wave_converged_in_the_time_step(name):
    """The floats that float at the surface ride a 1 m, 8 s wave (ramped over 4 s; the examples
    have none) through 12 s: the run at dt against the run at dt/2, tensions at every output and
    their means to fractions of the largest, body positions in metres (table above)."""
    dt, peaks, means, positions = SURFACE_FLOATS_IN_WAVES[name]
    case = case_of(name)
    waves = {"type": "regular", "height": 1.0, "period": 8.0, "heading_deg": 0.0, "ramp": 4.0}
    case = quietly(case.replace, {"environment": {**case.environment.model_dump(exclude_none=True), "waves": waves}})
    coarse, fine = run_for(case, 12.0, dt, 0.5), run_for(case, 12.0, dt / 2, 0.5)
    assert coarse.attrs["status"] == "ok", coarse.attrs["status"]
    assert fine.attrs["status"] == "ok", fine.attrs["status"]
    tension = coarse["tension"].values, fine["tension"].values
    scale = np.max(np.abs(tension[1]))
    assert np.max(np.abs(tension[0] - tension[1])) < peaks * scale
    assert np.max(np.abs(tension[0].mean(axis=0) - tension[1].mean(axis=0))) < means * scale
    z = fine["body_position"].values[..., 2]
    assert np.max(np.abs(coarse["body_position"].values - fine["body_position"].values)) < positions
    assert np.max(z) > 0.3                                    # floats ride the crests (0.5 m)


@pytest.mark.slow
def test_floats_that_keep_their_buoyancy_in_the_air_are_still_refused():
    """The same floats without a diameter keep their full net buoyancy out of the water (a point
    body's constant), so the equilibrium stands seatex's chain up through the surface; the run
    refuses it at t = 0, naming a float above the water."""
    case = case_of("seatex")
    bodies = {n: b.model_dump(exclude_none=True) for n, b in case.bodies.items()}
    for body in bodies.values():
        body.pop("diameter", None)
    case = quietly(case.replace, {"bodies": bodies})
    ds = run_for(case, case.simulation.dt, case.simulation.dt, case.simulation.dt)
    assert "above the water surface" in ds.attrs["status"]
    assert "where this model would still give it its full buoyancy" in ds.attrs["status"]


def mpl_flexible(case):
    """``case`` (mpl) without its bending stiffness: shallow_s's line, whose equilibrium mpl starts from."""
    return quietly(case.replace, {"line_types.umbilical.bending_stiffness": 0.0,
                                  "line_types.umbilical.compression_stiffness": 0.0})


@pytest.mark.slow
def test_mpl_floats_that_keep_their_buoyancy_above_the_water_fail_the_continuum_models_start():
    """Written as point bodies without a ``diameter``, the Panther floats keep their net buoyancy out of
    the water (a constant), so their 2800 N of lift beats the umbilical's 1456 N of weight and the
    continuum model's steady state stands the line up from the anchor; the run says so at t = 0.
    Oracle: the line's 146.98 m to the top Panther nearly vertical from the anchor 100 m down (the
    0.12 m/s current tilts it by ~2 deg)."""
    case = case_of("mpl")
    bodies = {n: b.model_dump(exclude_none=True) for n, b in case.bodies.items()}
    for body in bodies.values():
        body.pop("diameter", None)
    sim = {**case.simulation.model_dump(exclude_none=True), "duration": 0.05, "output_dt": 0.05,
           "scheme": "generalized-alpha", "dimensions": 2}
    case = quietly(case.replace, {"model": "continuum", "bodies": bodies, "simulation": sim,
                                  "line_types.umbilical.compression_stiffness": 0.0})
    status = quietly(kanat.simulate, case).attrs["status"]
    assert status.startswith("failed: bodies: body 'panther14' at ")
    assert "above the water surface (z = 0 m) in the initial state (t = 0)" in status
    height = float(status.split(") m is ")[1].split(" ")[0])
    assert 146.98 * math.cos(math.radians(3.0)) - 100.0 < height < 146.98 - 100.0


@pytest.mark.slow
def test_mpl_starts_with_its_float_at_the_draft_its_line_pulls_it_to():
    """mpl's start, the flexible line's equilibrium (lumped, by dynamic relaxation, with the Panthers'
    buoyancy following their immersion): the end float rides the surface (its keel between the
    waterline and its height, 0.667 m), at the draft ``d`` its line pulls it to,
    ``rho g A_w d = m g - F_z`` with ``F_z`` the vertical force its line's end exerts on it
    (``body_force``), to 1e-6 N; its line's horizontal force holds
    its drag in the 0.12 m/s current, ``0.5 rho C_D S u^2``, to 1e-6 N. The Panthers above it are
    checked at their cap heights by the shallow_s test (the same line)."""
    case = mpl_flexible(case_of("mpl"))
    ds = run_for(case, case.simulation.dt, case.simulation.dt, case.simulation.dt)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    spec, env = case.bodies["float"], case.environment
    z = float(ds["body_position"].sel(body="float").values[0, 2])
    force = ds["body_force"].sel(body="float").values[0]
    assert -spec.surface_buoy.height < z < 0.0
    draft = (spec.mass * env.gravity - force[2]) / (env.water_density * env.gravity * spec.surface_buoy.waterplane_area)
    assert draft == pytest.approx(-z, abs=1e-6 / (env.water_density * env.gravity * spec.surface_buoy.waterplane_area))
    assert -force[0] == pytest.approx(0.5 * env.water_density * spec.drag_area * 0.12**2, abs=1e-6)
    assert draft < 0.01                                     # the line barely pulls on it: 3 mm


MPL_RUN = (10.0, 0.05)   # seconds, dt: the run with bending stiffness from the flexible line's equilibrium
MPL_POSITIONS, MPL_PEAKS, MPL_MEANS = 0.05, 0.05, 0.01
"""Of the bodies' motion and of the largest tension; measured: 3.6 % (0.16 m of 4.53 m, at t = 1 s), 2.5 %
and 0.23 % (of 1234 N)."""


@pytest.mark.slow
def test_mpl_runs_with_its_bending_stiffness_converged_in_its_time_step():
    """From the flexible line's equilibrium, the umbilical's bending stiffness (2000 N m^2, with its axial
    stiffness in compression) straightens the kinks at the floats, throwing the Panthers up to 0.84 m
    and the end float 0.17 m out of the water in the first second, and the line drifts on downstream
    (4.5 m in 10 s): not yet its steady state. Oracle: the run at dt against the run at dt/2, body
    positions to :data:`MPL_POSITIONS` of their motion, tensions at every output to
    :data:`MPL_PEAKS` and their means to :data:`MPL_MEANS` of the largest."""
    duration, dt = MPL_RUN
    case = case_of("mpl")
    runs = []
    for step in (dt, dt / 2):
        sim = {**case.simulation.model_dump(exclude_none=True), "duration": duration, "dt": step, "output_dt": 1.0}
        variant = quietly(case.replace, {"simulation": sim})
        runs.append(quietly(lambda: kanat.simulate(variant, start=mpl_flexible(variant))))
    coarse, fine = runs
    assert coarse.attrs["status"] == "ok", coarse.attrs["status"]
    assert fine.attrs["status"] == "ok", fine.attrs["status"]
    span = float(np.max(np.ptp(fine["body_position"].values, axis=0)))
    gap = np.max(np.abs(coarse["body_position"].values - fine["body_position"].values))
    assert span > 1.0 and gap < MPL_POSITIONS * span, (gap, span)
    tension = coarse["tension"].values, fine["tension"].values
    scale = np.max(np.abs(tension[1]))
    assert np.max(np.abs(tension[0] - tension[1])) < MPL_PEAKS * scale
    assert np.max(np.abs(tension[0].mean(axis=0) - tension[1].mean(axis=0))) < MPL_MEANS * scale
    assert np.all(fine["body_position"].sel(body="float").values[-5:, 2] < 0.0)      # afloat again
