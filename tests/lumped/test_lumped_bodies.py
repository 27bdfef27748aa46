"""Bodies, waves and current inside lumped runs, against independent oracles (issue 5):

* otter boards: two boards spread symmetrically; lateral offset and tensions from the
  force balance of weightless, dragless bridles (closed form);
* a surface buoy in regular waves below resonance: heave of a point mass on a spring
  of stiffness ``rho g A_w`` (closed form), and its free flight when dropped from above
  the surface (buoyancy lost out of the water; ballistic flight, then the spring);
* a JONSWAP sea: the same seed gives the same run; a wave-rider buoy measures the
  significant height within the statistical scatter of a record of that length;
* a steady line in a sheared current against the statics solver (0.5 %).
"""
import math

import numpy as np
import pytest

from kanat.io.results import read_result
from helpers import run, scatter_of_mean_square
from kanat.model import Case
from kanat.physics.waves import sea_from_model
from kanat.statics import solve_cable
from kanat.statics.setup import cable_problems

G, RHO = 9.81, 1025.0


def lumped_case(**parts):
    sim = {"duration": 1.0, "dt": 0.01, "output_dt": 0.1, **parts.pop("simulation", {})}
    return Case.model_validate(dict(model="lumped", name="t", simulation=sim, **parts))


# --- otter boards --------------------------------------------------------------------------
def otter_case(speed, spreading, drag_area, ea, tow=60.0, bridle=40.0):
    line = dict(diameter=0.01, mass=1.0, weight_in_water=0.0, axial_stiffness=ea, axial_damping=ea * 1e-3,
                drag_normal=0.0, drag_tangential=0.0)
    board = dict(mass=50.0, net_buoyancy=0.0, drag_area=drag_area)
    return lumped_case(
        line_types={"c": line},
        points={"branch": {"position": [-tow, 0, -1]}},
        bodies={"port": {**board, "spreading_force": spreading, "position": [-tow - 20, 30, -1]},
                "stbd": {**board, "spreading_force": -spreading, "position": [-tow - 20, -30, -1]}},
        vessel={"tow_point": [0, 0, -1],          # 1 m down: weightless lines wholly wet (partial submergence)
                "track": [{"straight": {"speed": speed, "duration": 10.0}}]},
        cables=[dict(name="tow", line_type="c", length=tow, segments=max(2, round(tow / 10)), **{"from": "vessel"}, to="branch"),
                dict(name="bridle_port", line_type="c", length=bridle, segments=4, **{"from": "branch"}, to="port"),
                dict(name="bridle_stbd", line_type="c", length=bridle, segments=4, **{"from": "branch"}, to="stbd")],
        simulation={"duration": 5.0, "dt": 0.01, "output_dt": 0.5, "scheme": "rk4"})


@pytest.mark.parametrize("speed, spreading", [(1.0, 1000.0), (3.0, 400.0)])
def test_otter_boards_spread_symmetrically_to_the_force_balance(speed, spreading, tmp_path):
    """Each weightless, dragless bridle is straight along its board's load ``(-D, +-F0)``,
    ``D = rho S U^2 / 2``; the tow line carries ``2 D`` straight astern, all stretched by T/EA."""
    tow, bridle, drag_area, ea = 60.0, 40.0, 0.4, 2e5
    run(otter_case(speed, spreading, drag_area, ea), tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    assert ds.attrs["status"] == "ok"
    drag = 0.5 * RHO * drag_area * speed**2
    t_bridle = math.hypot(drag, spreading)
    lateral = bridle * (1 + t_bridle / ea) * spreading / t_bridle
    astern = tow * (1 + 2 * drag / ea) + bridle * (1 + t_bridle / ea) * drag / t_bridle
    bodies = list(ds["body"].values)
    for when in (0, -1):                                         # the equilibrium, and after 5 s of towing
        rel = ds["body_position"].values[when] - ds["vessel_position"].values[when]
        port, stbd = rel[bodies.index("port")], rel[bodies.index("stbd")]
        np.testing.assert_allclose(port, [-astern, lateral, 0.0], atol=1e-9 * bridle)
        np.testing.assert_allclose(stbd, port * [1, -1, 1], atol=1e-9 * bridle)    # mirror images
    tension = ds["tension"].values[-1]
    cable = ds["cable"].values
    assert tension[cable == "tow"][0] == pytest.approx(2 * drag, rel=1e-9)
    np.testing.assert_allclose(tension[cable == "bridle_port"], t_bridle, rtol=1e-9)
    np.testing.assert_allclose(tension[cable == "bridle_stbd"], t_bridle, rtol=1e-9)


def test_otter_boards_spread_across_the_heading_after_a_turn(tmp_path):
    """After a quarter turn to port the boards spread along x (perpendicular to the new
    heading, +y), mirror images about the tow line once the swing has died out."""
    speed, spreading, drag_area, ea, bridle = 2.0, 1000.0, 0.4, 2e5, 40.0
    case = otter_case(speed, spreading, drag_area, ea, tow=15.0)       # short tow: the swing dies fast
    track = [{"straight": {"speed": speed, "duration": 2.0}}, {"turn": {"radius": 20.0, "angle_deg": 90}},
             {"straight": {"duration": 200.0}}]
    case = case.model_copy(update={
        "vessel": case.vessel.model_validate({"track": track}),
        "simulation": case.simulation.model_copy(update={"duration": 200.0, "dt": 0.02, "output_dt": 5.0})})
    run(case, tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    assert ds["vessel_heading"].values[-1] == pytest.approx(math.pi / 2)
    rel = ds["body_position"].values[-1] - ds["vessel_position"].values[-1]
    port, stbd = rel[list(ds["body"].values).index("port")], rel[list(ds["body"].values).index("stbd")]
    t_bridle = math.hypot(0.5 * RHO * drag_area * speed**2, spreading)
    lateral = bridle * (1 + t_bridle / ea) * spreading / t_bridle
    assert -port[0] == pytest.approx(lateral, rel=5e-3) and stbd[0] == pytest.approx(lateral, rel=5e-3)
    assert port[1] == pytest.approx(stbd[1], abs=0.1) and port[1] < -15.0      # both astern, level


# --- surface buoy ------------------------------------------------------------------------------
def buoy_case(mass, area, z0, waves=None, duration=10.0, dt=0.005, height=5.0, output_dt=0.1, tether_length=20.0, tether_to="free"):
    """A surface buoy (keel at ``z0``, at rest) with a slack, massless-in-effect tether to a
    free end: the buoy feels only gravity and its waterplane buoyancy (the tether is a nominal,
    very soft line; its free end may stretch it freely)."""
    tether = dict(diameter=0.001, mass=1e-3, weight_in_water=0.0, axial_stiffness=1.0,
                  drag_normal=0.0, drag_tangential=0.0, max_strain=1.0)
    return lumped_case(
        environment={"waves": waves} if waves else {},
        line_types={"tether": tether},
        bodies={"buoy": {"mass": mass, "net_buoyancy": -mass * G, "position": [0, 0, z0],
                         "surface_buoy": {"waterplane_area": area, "height": height}}},
        cables=[dict(name="tether", line_type="tether", length=tether_length, segments=1, **{"from": "buoy"}, to=tether_to)],
        simulation={"duration": duration, "dt": dt, "output_dt": output_dt, "scheme": "rk4",
                    "initial_state": "as_given"})


BUOY_MASS_EFFECTIVE = 1e-3 * 20.0 / 2                   # half the tether's mass rides on the buoy


@pytest.mark.parametrize("mass, area, period", [(100.0, 1.0, 8.0), (1000.0, 0.4, 6.0)],
                         ids=["far-below-resonance", "half-resonance"])
def test_surface_buoy_heave_is_a_mass_on_a_waterplane_spring(mass, area, period, tmp_path):
    """``m z'' = -m g + rho g A (eta - z)``, ``eta = a cos(w t)`` at the buoy: started on the
    forced response, ``z = -m g / (rho g A) + a R cos(w t)``, ``R = 1 / (1 - (w / w0)^2)``."""
    height = 1.0
    a, omega = height / 2, 2 * math.pi / period
    m_eff = mass + BUOY_MASS_EFFECTIVE
    omega0 = math.sqrt(RHO * G * area / m_eff)
    gain = 1.0 / (1.0 - (omega / omega0) ** 2)
    draft = mass / (RHO * area)
    waves = {"type": "regular", "height": height, "period": period, "heading_deg": 0.0}
    case = buoy_case(mass, area, -draft + a * gain, waves, duration=2.5 * period, dt=0.01, output_dt=0.2)
    run(case, tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    t, z = ds["time"].values, ds["body_position"].values[:, 0, 2]
    np.testing.assert_allclose(z, -draft + a * gain * np.cos(omega * t), atol=2e-4 * a)
    # no sway; surge only from the wave inertia (normal and Froude-Krylov along it) of the tether's
    # 0.01 kg riding on the buoy
    np.testing.assert_allclose(ds["body_position"].values[:, 0, :2], 0.0, atol=2e-3)
    assert (gain > 1.3) == (period == 6.0)                      # the second case is not trivially eta


def test_a_dropped_buoy_flies_ballistically_then_bounces_on_its_waterplane(tmp_path):
    """Released at rest with its keel ``z0`` above calm water: free fall ``z0 - g t^2 / 2``
    (no buoyancy out of the water), then ``z = -delta + A cos(w0 tau + theta)`` in the water,
    ``delta = g / w0^2``; without damping it leaves the water and returns to ``z0``."""
    mass, area, z0 = 100.0, 1.0, 0.5
    m_eff = mass + BUOY_MASS_EFFECTIVE
    omega0 = math.sqrt(RHO * G * area / m_eff)
    weight_fall = mass * G / m_eff                           # the tether's share of mass has no weight
    t_fall = math.sqrt(2 * z0 / weight_fall)
    delta = weight_fall / omega0**2
    v_in = weight_fall * t_fall
    amp = math.hypot(delta, v_in / omega0)
    theta = math.acos(delta / amp)
    t_water = (2 * math.pi - 2 * theta) / omega0
    bounce = 2 * t_fall + t_water

    case = buoy_case(mass, area, z0, duration=3.2 * bounce, dt=0.001, output_dt=0.01)
    run(case, tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    t, z = ds["time"].values, ds["body_position"].values[:, 0, 2]
    phase = np.mod(t, bounce)                                   # t = 0: at rest at the top
    in_air_down = phase <= t_fall
    in_water = (phase > t_fall) & (phase < t_fall + t_water)
    expected = np.where(in_air_down, z0 - 0.5 * weight_fall * phase**2, 0.0)
    tau = phase - t_fall
    expected = np.where(in_water, -delta + amp * np.cos(omega0 * tau + theta), expected)
    rising = phase >= t_fall + t_water
    up = bounce - phase
    expected = np.where(rising, z0 - 0.5 * weight_fall * up**2, expected)
    np.testing.assert_allclose(z, expected, atol=2e-3 * z0)
    assert np.max(z[t > bounce]) == pytest.approx(z0, abs=2e-3 * z0)      # flies back to z0
    assert np.min(z) == pytest.approx(-delta - amp, abs=2e-3 * z0)       # deepest immersion


# --- irregular sea -------------------------------------------------------------------------------
def jonswap_waves(seed, hs=2.0, tp=4.0, ramp=0.0):
    return {"type": "jonswap", "hs": hs, "tp": tp, "gamma": 3.3, "heading_deg": 0.0, "seed": seed, "ramp": ramp}


RIDER_RAMP = 20.0      # s of the waves' ramp: the buoy starts at rest in still water, on its forced response


@pytest.mark.parametrize("keel, flies", [(1.5, False), (2.5, True)], ids=["dropped-in", "thrown-clear"])
def test_a_surface_buoy_thrown_clear_of_the_water_fails(keel, flies, tmp_path):
    """A surface buoy's keel more than its height (2 m) above the water is outside its waterplane
    model: refused at once, the height named; dropped from 1.5 m it falls in, its keel reaching the
    water at ``sqrt(2 h / g)`` (free fall, no buoyancy and no drag in the air)."""
    case = buoy_case(200.0, 20.0, keel, duration=1.0, dt=0.001, height=2.0, output_dt=0.01)
    summary = run(case, tmp_path / "drop.nc")
    if flies:
        assert summary.status.startswith("failed: surface buoy 'buoy''s keel is 2.5 m above the water surface at t = 0 s")
        return
    assert summary.status == "ok"
    ds = read_result(tmp_path / "drop.nc")
    z = ds["body_position"].values[:, 0, 2]
    t = ds["time"].values
    wet = int(np.argmax(z <= 0.0))
    assert t[wet - 1] < math.sqrt(2 * keel / G) <= t[wet]


@pytest.mark.slow
def test_a_wave_rider_started_off_its_forced_heave_bounces_clear_and_fails(tmp_path):
    """The wave rider of the test below started abruptly (no ramp): at rest on a sea surface
    that moves, it oscillates freely at its waterplane frequency three times its 1 cm draft, bounces
    on the surface and gains energy from it until it is thrown clear, which no floating buoy does
    (no radiation or slamming damping in the model): the run fails there instead of going on
    (it once reached 27 m with ``status: ok``)."""
    mass, area, tether = 200.0, 20.0, 400.0
    sea = sea_from_model(lumped_case(environment={"waves": jonswap_waves(11)}, line_types={"c": {
        "diameter": 0.01, "mass": 1, "axial_stiffness": 1}}, cables=[dict(
            name="c", line_type="c", length=1, segments=1, **{"from": "anchor:[0,0,0]"}, to="free")]).environment)
    omega0 = math.sqrt(RHO * G * area / (mass + BUOY_MASS_EFFECTIVE * tether / 20.0))
    b = sea.amplitude / (1.0 - (sea.omega / omega0) ** 2)
    start = -mass / (RHO * area) + np.sum(b * np.cos(sea.phase))     # on the forced heave, at rest
    case = buoy_case(mass, area, start, jonswap_waves(11), duration=400.0, dt=0.01, height=2.0,
                     output_dt=0.25, tether_length=tether, tether_to="anchor:[0, 0, -300]")
    summary = run(case, tmp_path / "bounce.nc")
    assert "surface buoy 'buoy''s keel is" in summary.status and "thrown clear of the water" in summary.status
    keel = float(summary.status.split("keel is ")[1].split(" m above")[0])
    assert 2.0 < keel < 2.5                                     # caught as it passes its height


@pytest.mark.slow
def test_jonswap_run_is_reproducible_and_a_wave_rider_measures_its_hs(tmp_path):
    """A light buoy on a stiff waterplane (w0 = 31.7 rad/s, 5x the highest sea component)
    rides the surface: its heave is the elevation times ``R_j = 1 / (1 - (w_j / w0)^2)`` per
    component, so ``4 sqrt(m0)`` of the heave record after the waves' ramp is
    ``4 sqrt(sum (a_j R_j)^2 / 2)`` within 3 standard deviations of a record of that length
    (``scatter_of_mean_square``).

    The oracle holds while the buoy stays in the water: its draft is ``g / w0^2`` (1 cm), so a
    heave free oscillation (undamped, at w0) must not be started, and the forced heave's
    downward acceleration must stay under g (checked on the record). The sea is ramped in over
    RIDER_RAMP seconds from still water: started abruptly on the forced displacement but at rest,
    the buoy would oscillate freely at 3.5 cm, three times its draft, bounce on the surface and
    gain energy from it (Fermi's bouncing ball) whatever the sea. The record is 600 s long: the
    scatter of its mean square (4.4 % of m0 here) shrinks with its length; components at the
    bins' centres repeated every 200 Tp / 3.5 = 229 s, and a record of about that length then
    looked far less scattered than a sea's record is."""
    mass, area, duration = 200.0, 20.0, 600.0 + RIDER_RAMP
    draft = mass / (RHO * area)
    waves = jonswap_waves(11, ramp=RIDER_RAMP)
    sea = sea_from_model(lumped_case(environment={"waves": waves}, line_types={"c": {
        "diameter": 0.01, "mass": 1, "axial_stiffness": 1}}, cables=[dict(
            name="c", line_type="c", length=1, segments=1, **{"from": "anchor:[0,0,0]"}, to="free")]).environment)
    tether = 400.0                     # slack to an anchor 300 m down: the buoy's heave alone
    omega0 = math.sqrt(RHO * G * area / (mass + BUOY_MASS_EFFECTIVE * tether / 20.0))
    b = sea.amplitude / (1.0 - (sea.omega / omega0) ** 2)
    case = buoy_case(mass, area, -draft, waves, duration=duration, dt=0.01, height=2.0, output_dt=0.25,
                     tether_length=tether, tether_to="anchor:[0, 0, -300]")
    run(case, tmp_path / "long.nc")
    ds = read_result(tmp_path / "long.nc")
    keep = ds["time"].values >= RIDER_RAMP
    t, heave = ds["time"].values[keep], ds["body_position"].values[keep, 0, 2] + draft
    forced = np.cos(np.multiply.outer(t, -sea.omega) + sea.phase)
    assert np.min(forced @ (-b * sea.omega**2)) > -0.95 * G       # never pulled out of the water
    m0, expected = np.mean(heave**2), np.sum(b**2) / 2
    sigma = scatter_of_mean_square(b, sea.omega, t)
    assert abs(m0 - expected) < 3 * sigma, f"Hs {4 * math.sqrt(m0):.4f} m vs {4 * math.sqrt(expected):.4f} m"
    assert 0.01 < sigma / expected < 0.05                        # the test can tell: 3 sigma is < 15 % of m0
    assert 4 * math.sqrt(expected) == pytest.approx(2.0, rel=0.01)   # R_j barely above 1
    np.testing.assert_allclose(heave, forced @ b, atol=1e-3 * math.sqrt(expected))   # and rides each wave
    short = {}
    for name, seed in (("a", 11), ("b", 11), ("c", 12)):
        each = sea_from_model(lumped_case(environment={"waves": jonswap_waves(seed)}, line_types={"c": {
            "diameter": 0.01, "mass": 1, "axial_stiffness": 1}}, cables=[dict(
                name="c", line_type="c", length=1, segments=1, **{"from": "anchor:[0,0,0]"}, to="free")]).environment)
        start = -draft + np.sum(each.amplitude / (1.0 - (each.omega / omega0) ** 2) * np.cos(each.phase))
        run(buoy_case(mass, area, start, jonswap_waves(seed), duration=5.0, dt=0.01, height=2.0),
            tmp_path / f"{name}.nc")                            # each on its own sea's forced heave at t = 0
        short[name] = read_result(tmp_path / f"{name}.nc")["body_position"].values
    np.testing.assert_array_equal(short["a"], short["b"])      # same seed, same run, bit for bit
    assert np.max(np.abs(short["a"] - short["c"])) > 0.05      # another seed, another sea


# --- current profile ------------------------------------------------------------------------------
CURRENT_LINE = dict(diameter=0.05, mass=4.0, axial_stiffness=2e6, axial_damping=2e4, added_mass=2.0,
                    drag_normal=1.2, drag_tangential=0.02)
PROFILE = [[0.0, 1.2, 0, 0], [-60.0, 0.8, 0, 0], [-150.0, 0.1, 0, 0]]


def current_cases():
    riser = lumped_case(
        environment={"current": {"profile": PROFILE}},
        line_types={"c": CURRENT_LINE},
        bodies={"float": {"mass": 400, "net_buoyancy": 3000, "drag_area": 0.8, "added_mass": 300,
                          "position": [30, 0, -60]}},
        cables=[dict(name="riser", line_type="c", length=120.0, segments=40, **{"from": "anchor:[0,0,-150]"},
                     to="float")],
        simulation={"duration": 20.0, "dt": 0.05, "output_dt": 1.0, "scheme": "generalized-alpha-lumped"})
    tow = lumped_case(
        environment={"current": {"profile": PROFILE}},
        line_types={"c": CURRENT_LINE},
        bodies={"fish": {"mass": 600, "net_buoyancy": -4000, "drag_area": 0.4, "added_mass": 200}},
        vessel={"track": [{"straight": {"speed": 2.0, "duration": 20.0}}]},
        cables=[dict(name="tow", line_type="c", length=200.0, segments=40, **{"from": "vessel"}, to="fish")],
        simulation={"duration": 20.0, "dt": 0.05, "output_dt": 1.0, "scheme": "generalized-alpha-lumped"})
    return {"riser": riser, "tow": tow}


@pytest.mark.parametrize("name", ["riser", "tow"])
def test_steady_line_in_sheared_current_matches_the_statics_solver(name, tmp_path):
    """The line found by the network equilibrium and held for 20 s of simulated time agrees
    with the 2-D statics solver (shooting or collocation, continuous in s) on the same line,
    current profile and end body: end tensions and body position within 0.5 %."""
    case = current_cases()[name]
    cable = case.cables[0]
    run(case, tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    sol = solve_cable(cable_problems(case)[cable.name], s_out=np.linspace(0, cable.length, cable.segments + 1))
    origin = ds["vessel_position"].values[-1] if name == "tow" else np.zeros(3)
    body = ds["body_position"].values[-1, 0] - origin
    tension = ds["tension"].values[-1]
    for end in (0, -1):
        assert tension[end] == pytest.approx(sol.tension[end], rel=5e-3)
    np.testing.assert_allclose(body[[0, 2]], sol.position[-1, [0, 2]], atol=5e-3 * cable.length)
    assert abs(body[1]) < 1e-9
    positions = ds["position"].values[:, :, [0, 2]] - ds["vessel_position"].values[:, None, [0, 2]] * (name == "tow")
    assert np.max(np.abs(positions[-1] - positions[0])) < 1e-3 * cable.length   # and it stays there


@pytest.mark.parametrize("length, above", [(40.0, None), (80.0, 30.0)])
def test_a_float_out_of_the_water_stops_the_run(length, above):
    """A float (5 kN net buoyancy, no waterplane) on a tether from an anchor 50 m down stands
    straight above it at z = -50 m + L (1 + T / EA). On 40 m it floats 10 m under water and the
    run is ok; on 80 m it would stand 30 m above the surface, still buoyed by this model: the
    run fails at t = 0 and says by how much."""
    import warnings

    import kanat

    case = kanat.load_case({
        "name": "tethered-float", "model": "lumped",
        "line_types": {"rope": {"diameter": 0.02, "mass": 0.3, "axial_stiffness": 1.0e8}},
        "bodies": {"float": {"mass": 100.0, "net_buoyancy": 5000.0, "drag_area": 0.5}},
        "cables": [{"name": "tether", "line_type": "rope", "length": length, "segments": 8,
                    "from": "anchor:[0, 0, -50]", "to": "float"}],
        "simulation": {"duration": 1.0, "dt": 0.01, "output_dt": 0.5}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(case)
    if above is None:
        assert ds.attrs["status"] == "ok"
        tension = float(ds.tension.isel(time=0).values[-1])
        assert float(ds.body_position.isel(time=0).values[0, 2]) == pytest.approx(
            -50.0 + length * (1 + tension / 1.0e8), abs=1e-3)
    else:
        status = ds.attrs["status"]
        assert status.startswith("failed: body 'float' is") and "above the water surface at t = 0 s" in status
        height = float(status.split(" is ")[1].split(" m above")[0])
        assert height == pytest.approx(above, abs=0.05)
