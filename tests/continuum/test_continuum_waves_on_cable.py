"""Waves on the continuum cable (theory/moorings.md, theory/lumped.md): Airy kinematics in the relative velocity and the fluid
inertia (Morison with Froude–Krylov), a surface buoy riding the waves; against the linear analytic
response of a taut tether, a buoy's heave on a line of known stiffness, and the lumped model."""
import warnings

import numpy as np
import pytest

import kanat
from kanat.continuum.adapter import ContinuumModel
from kanat.continuum.schemes import GeneralizedAlpha
from kanat.continuum.stepper import State
from kanat.physics.drag import cable_drag
from kanat.physics.waves import sea_from_model, wavenumber

from helpers import EXAMPLES

TETHER = """
name: tether-in-waves
model: continuum
environment:
  depth: 100
  waves: {type: regular, height: 0.2, period: 8.0, heading_deg: 0}
line_types:
  tether: {diameter: 0.05, mass: 2.0, weight_in_water: 0.0, axial_stiffness: 1.0e10, added_mass: 1.0,
           drag_normal: 0.0, drag_tangential: 0.0}
bodies:
  buoy: {mass: 1000, net_buoyancy: 20000, drag_area: 0.0, added_mass: 500}
cables:
  - {name: tether, line_type: tether, length: 80, segments: 80, from: "anchor:[0, 0, -100]", to: buoy}
simulation: {duration: 10, dt: 0.08, output_dt: 0.08, dimensions: 2}
"""


def quiet(text):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.load_case(text)


def tether_response(z, depth=100.0, height=0.2, period=8.0, m=2.0, ma=1.0, length=80.0, B=20000.0, mb=1000.0,
                    mab=500.0, g=9.81):
    """Linear steady response ``w(z) sin(omega t)`` of the vertical tether to the wave's horizontal
    acceleration ``a_x = -a omega^2 C(z) sin(omega t)``: ``(m + m_a) w_tt - T w_zz = (m + m_a) a_x``
    (Froude–Krylov plus added mass, the line neutrally buoyant), pinned at the anchor, the buoy
    ``(M_b + M_a) w_tt = -T w_z + (M_a + rho V) a_x``. Closed form: ``W = A sin(kappa (z - z0)) +
    B cos(kappa (z - z0)) + P C(z)``."""
    omega = 2 * np.pi / period
    k = float(wavenumber([omega], g, depth)[0])
    a, T0 = height / 2, B
    C = lambda zz: np.cosh(k * (zz + depth)) / np.sinh(k * depth)           # noqa: E731
    dC = lambda zz: k * np.sinh(k * (zz + depth)) / np.sinh(k * depth)      # noqa: E731
    P = (m + ma) * a * omega**2 / ((m + ma) * omega**2 + T0 * k**2)
    kappa = np.sqrt((m + ma) * omega**2 / T0)
    z0, z1 = -depth, -depth + length
    Bc = -P * C(z0)
    wave_mass, total = mab + (B + mb * g) / g, mb + mab
    s1, c1 = np.sin(kappa * (z1 - z0)), np.cos(kappa * (z1 - z0))
    rest = -total * omega**2 * (Bc * c1 + P * C(z1)) + T0 * (-Bc * kappa * s1 + P * dC(z1)) \
        + wave_mass * a * omega**2 * C(z1)
    A = -rest / (-total * omega**2 * s1 + T0 * kappa * c1)
    return A * np.sin(kappa * (z - z0)) + Bc * np.cos(kappa * (z - z0)) + P * C(z), omega


def test_taut_tether_follows_the_linear_analytic_response():
    """Started on the steady response (straight, moving with its velocity), the tether tracks
    ``w(z_buoy) sin(omega t)`` for 2.4 periods within 1 % of the amplitude (0.4 % measured)."""
    model = ContinuumModel(quiet(TETHER)).cable_model
    start = model.initial()
    W, omega = tether_response(start.xz[:, 1])
    y = start.y.copy()
    y[:, 2] = -omega * W                         # v along n = (-1, 0) on the vertical line
    state = State(0.0, y, np.zeros_like(y), start.xz)
    coefficients = GeneralizedAlpha(-0.9).coefficients()
    x0, errors, amplitude = start.xz[-1, 0], [], abs(W[-1])
    for _ in range(240):
        state, _ = model.step(state, 0.08, coefficients)
        errors.append(state.xz[-1, 0] - x0 - W[-1] * np.sin(omega * state.t))
    assert amplitude > 0.05
    assert np.max(np.abs(errors)) < 0.01 * amplitude


def test_waves_move_the_cable():
    """Waves were once accepted and ignored by the continuum model: the wave run now differs."""
    calm = kanat.simulate(quiet(TETHER.replace("  waves: {type: regular, height: 0.2, period: 8.0, heading_deg: 0}\n",
                                               "")))
    waves = kanat.simulate(quiet(TETHER))
    assert calm.attrs["status"] == waves.attrs["status"] == "ok"
    assert np.ptp(calm.body_position.values[:, 0, 0]) < 1e-9
    assert np.ptp(waves.body_position.values[:, 0, 0]) > 0.05


HEAVE = """
name: surface-buoy-heave
model: continuum
environment:
  depth: 60
  waves: {type: regular, height: 0.5, period: 20.0, heading_deg: 0}
line_types:
  rope: {diameter: 0.02, mass: 0.3, weight_in_water: 0.0, axial_stiffness: 1.0e6, drag_normal: 0.0,
         drag_tangential: 0.0}
bodies:
  buoy: {mass: 500, net_buoyancy: -4905, surface_buoy: {waterplane_area: 1.0, height: 4.0}}
cables:
  - {name: rope, line_type: rope, length: 57, segments: 19, from: "anchor:[0, 0, -60]", to: buoy}
simulation: {duration: 200, dt: 0.2, output_dt: 0.2, dimensions: 2}
"""


def test_a_surface_buoy_rides_the_waves_on_its_waterplane():
    """Heave of a buoy (waterplane stiffness rho g A_w) on a rope (EA / L) in long waves: the quasi-static
    spring-in-series response ``a rho g A_w / (rho g A_w + EA / L - M omega^2)``, and its draft."""
    ds = kanat.simulate(quiet(HEAVE))
    assert ds.attrs["status"] == "ok"
    z = ds.body_position.values[:, 0, 2]
    water, rope = 1025 * 9.81 * 1.0, 1.0e6 / 57
    tension = float(ds.tension.values[0, -1])
    assert -z[0] == pytest.approx((tension + 4905) / water, rel=1e-6)          # draft from the balance
    omega, mass = 2 * np.pi / 20.0, 500 + 0.3 * 57 / 3
    expected = 0.25 * water / (water + rope - mass * omega**2)
    assert np.ptp(z[ds.time.values > 100]) / 2 == pytest.approx(expected, rel=0.01)


LINE = """
name: line-in-waves
model: MODEL
environment:
  depth: 100
  waves: {type: regular, height: 2.0, period: 8.0, heading_deg: 0}
line_types:
  rope: {diameter: 0.05, mass: 2.0, weight_in_water: 5.0, axial_stiffness: 5.0e6, added_mass: 2.0, drag_normal: 1.2,
         drag_tangential: 0.01}
cables:
  - {name: rope, line_type: rope, length: 198, segments: 40, from: "anchor:[-100, 0, -12]", to: "anchor:[100, 0, -12]"}
simulation: {scheme: SCHEME, duration: 64, dt: DT, output_dt: 0.25, dimensions: 2}
"""


def wave_energy_flux(ds, case):
    """Mean power the waves give the line's drag, ``<sum f_drag(U - V) . (U - V) ds>`` over the last 4
    periods, from the outputs (positions, velocities, tensions) and the Airy kinematics."""
    sea, lt = sea_from_model(case.environment), case.line_types["rope"]
    powers = []
    for i in np.flatnonzero(ds.time.values >= 32):
        x, v, T = ds.position.values[i], ds.velocity.values[i], ds.tension.values[i]
        U = sea.velocity(x, float(ds.time.values[i]))
        chord = np.diff(x, axis=0)
        length = np.linalg.norm(chord, axis=1)
        mean_t = 0.5 * (T[1:] + T[:-1])
        rel = 0.5 * (U[1:] + U[:-1]) - 0.5 * (v[1:] + v[:-1])
        f = cable_drag(chord / length[:, None], rel, mean_t / lt.axial_stiffness, lt.diameter, lt.drag_normal,
                       lt.drag_tangential, 1025.0)
        powers.append(np.sum(np.sum(f * rel, axis=1) * length / (1 + mean_t / lt.axial_stiffness)))
    return float(np.mean(powers))


@pytest.mark.slow
def test_wave_energy_flux_and_response_agree_with_the_lumped_model():
    results = {}
    for model, scheme, dt in (("continuum", "generalized-alpha", 0.05), ("lumped", "generalized-alpha-lumped", 0.025)):
        case = quiet(LINE.replace("MODEL", model).replace("SCHEME", scheme).replace("DT", str(dt)))
        ds = kanat.simulate(case)
        assert ds.attrs["status"] == "ok"
        tail = ds.time.values >= 32
        mid = ds.position.isel(node=ds.sizes["node"] // 2).values[tail]
        results[model] = (wave_energy_flux(ds, case), np.ptp(mid[:, 2]), np.ptp(ds.tension.values[tail, 0]))
    for a, b in zip(results["continuum"], results["lumped"]):
        assert a == pytest.approx(b, rel=0.02)
    assert results["continuum"][0] > 100.0                                    # W: the flux is not nothing


SURFACE_MOORING = (EXAMPLES / "surface_mooring_waves.yaml").read_text().replace("duration: 60", "duration: 100")


@pytest.mark.slow
def test_surface_mooring_in_waves_agrees_with_the_lumped_model():
    """examples/surface_mooring_waves.yaml (chain on the seabed, nylon up to a surface buoy; waves of 1.5 m,
    10 s and a current) against the lumped model (RK4) on the same case, over 6 wave periods after a 40 s
    transient: mean, extremes and range of the top tension and the buoy's heave.

    The lumped model starts from its own equilibrium, first guessed by the still-water catenaries of network
    statics corrected once for the current's drag (kanat.lumped.catenary_guess), then 23 taut Newton
    iterations (kanat.lumped.taut_newton).

    Measured, continuum vs lumped, t = 40-100 s: top tension mean 4038.2 vs 4038.7 N (0.013 %), 3494.4-4644.0
    vs 3477.8-4653.5 N (range 1149.5 vs 1175.7 N, 2.2 %: the lumped model's extremes scatter by
    some 15 N a period), buoy heave -1.1471-0.3578 vs -1.1461-0.3584 m, mean -0.3876 m both
    (continuum 3 s, lumped 30 s of wall time).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        continuum = kanat.simulate(kanat.load_case(SURFACE_MOORING))
        lumped = kanat.simulate(kanat.load_case(SURFACE_MOORING.replace("model: continuum", "model: lumped").replace(
            "scheme: generalized-alpha", "scheme: rk4")))
    assert continuum.attrs["status"] == lumped.attrs["status"] == "ok"
    assert lumped.sizes["node"] == continuum.sizes["node"] == 91
    figures = {}
    for name, ds in (("continuum", continuum), ("lumped", lumped)):
        after = ds.time.values >= 40.0
        top = ds.tension.isel(node=-1).values[after]
        heave = ds.body_position.sel(body="buoy", xyz="z").values[after]
        figures[name] = top, heave
    (top_c, heave_c), (top_l, heave_l) = figures["continuum"], figures["lumped"]
    assert np.ptp(top_c) > 1000.0 and np.ptp(heave_c) > 1.4                  # the waves drive both
    assert np.mean(top_l) == pytest.approx(np.mean(top_c), rel=2e-3)
    assert top_l.max() == pytest.approx(top_c.max(), rel=0.01)
    assert top_l.min() == pytest.approx(top_c.min(), rel=0.01)
    assert np.ptp(top_l) == pytest.approx(np.ptp(top_c), rel=0.05)
    assert heave_l.max() == pytest.approx(heave_c.max(), abs=5e-3)
    assert heave_l.min() == pytest.approx(heave_c.min(), abs=5e-3)
    assert np.mean(heave_l) == pytest.approx(np.mean(heave_c), abs=2e-3)
