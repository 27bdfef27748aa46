"""Dynamics checks (theory/validation-cases.md cases 2, 3, 4, 9): the generalized-α family, wave speeds and natural
frequencies of the continuum model, a steady tow, and Gaisha's Fourier steady state.

Straight weightless cables without drag (as in the continuum tests): a longitudinal step in
end velocity travels at ``sqrt(EA/m)`` with ``dT = sqrt(EA m) dV``; a transverse kink at
``sqrt(T/(m+m_a))``; a taut string rings at ``c_t / 2L``; an axial cable with an end mass
at ``beta c_l / L`` with ``beta tan(beta) = m L / M``.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.validation.core import Tolerance, check


class _Drive:
    """First end moving with ``velocity`` for t > 0 (at rest before), far end held."""

    def __init__(self, velocity=(0.0, 0.0), smooth=False):
        self.velocity, self.smooth = velocity, smooth

    def velocities(self, t):
        if self.smooth:                                      # pulled and swung smoothly from rest
            ramp = 0.5 * (1.0 - math.cos(2 * math.pi * t / 1.5))
            return (-0.05 * ramp, 0.1 * ramp), (0.0, 0.0)
        return (self.velocity if t > 0 else (0.0, 0.0)), (0.0, 0.0)

    def origin(self, t):
        return np.zeros(2) if self.smooth else np.array(self.velocity) * t


def straight_cable(length, segments, tension, stiffness=1e6, mass=1.0, added_mass=0.0, end=None):
    """A straight weightless cable at rest under ``tension`` and its state (planar, no drag)."""
    from kanat.continuum import kernels2d as k
    from kanat.continuum.model2d import EndCondition, PlanarCable, parameters
    from kanat.continuum.stepper import State

    p = parameters(mass, added_mass, 0.0, stiffness, 0.01, 0.0, 0.0, 1025.0, length / segments)
    cable = PlanarCable("c", length, segments, p, EndCondition(k.VELOCITY), end or EndCondition(k.VELOCITY))
    y = np.zeros((segments + 1, 4))
    y[:, 0] = tension
    xz = np.column_stack([cable.s * (1 + tension / stiffness), np.zeros(segments + 1)])
    return cable, State(0.0, y, np.zeros_like(y), xz)


def _march(cable, state, drive, dt, steps, scheme, probe=None):
    from kanat.continuum.stepper import step

    coefficients, trace = scheme.coefficients(), []
    for _ in range(steps):
        state, _ = step(cable, state, dt, coefficients, drive)
        if probe is not None:
            trace.append((state.t, probe(state)))
    return state, np.array(trace)


def _front(s, values, level):
    """Arclength where ``values`` first falls through ``level`` walking from s = 0."""
    i = int(np.argmax(values < level))
    return s[i - 1] + (level - values[i - 1]) / (values[i] - values[i - 1]) * (s[i] - s[i - 1])


def _period(trace):
    t, x = trace[:, 0], trace[:, 1]
    sign = np.signbit(x)
    i = np.nonzero(sign[1:] != sign[:-1])[0]
    crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    return 2.0 * np.mean(np.diff(crossings))


@check("ga-amplification", "7.2", "generalized-α: amplification at infinite frequency equals lambda_inf",
       "spectral radius of the one-step matrix of y' + k y = 0 at k h = 1e10 is |lambda_inf|; worst over "
       "lambda_inf in {-1, -0.7, -0.5, -0.3, 0}", Tolerance(abs=1e-4))
def ga_amplification():
    from kanat.continuum.schemes import GeneralizedAlpha

    worst = 0.0
    for lam in (-1.0, -0.7, -0.5, -0.3, 0.0):
        am, ak, gamma = GeneralizedAlpha(lam).coefficients()
        kh = 1e10
        lhs = np.array([[kh * (1 - ak), 1 - am], [-1 / gamma, 1.0]])
        rhs = np.array([[-kh * ak, -am], [-1 / gamma, -(1 - gamma) / gamma]])
        radius = np.max(np.abs(np.linalg.eigvals(np.linalg.solve(lhs, rhs))))
        worst = max(worst, abs(radius - abs(lam)))
    return worst, 0.0


def _observed_order(scheme):
    steps = np.array([0.004, 0.002, 0.001])
    scale = np.array([1000.0, 0.1, 0.1, 1e-3])

    def final(dt):
        cable, state = straight_cable(50.0, 10, 1000.0, 1e4, 1.0, 0.5)
        return _march(cable, state, _Drive(smooth=True), dt, int(round(0.6 / dt)), scheme)[0].y
    reference = final(0.001 / 8)
    errors = [np.max(np.abs(final(dt) - reference) / scale) for dt in steps]
    return np.polyfit(np.log(steps), np.log(errors), 1)[0]


@check("ga-order", "7.2", "generalized-α (lambda_inf = -0.5) is second order in time",
       "observed slope of the error against dt on a driven taut cable = 2", Tolerance(abs=0.15))
def ga_order():
    from kanat.continuum.schemes import GeneralizedAlpha

    return _observed_order(GeneralizedAlpha(-0.5)), 2.0


@check("backward-euler-order", "7.2", "backward Euler is first order in time",
       "observed slope of the error against dt on a driven taut cable = 1", Tolerance(abs=0.15))
def backward_euler_order():
    from kanat.continuum.schemes import BackwardEuler

    return _observed_order(BackwardEuler()), 1.0


def _longitudinal():
    from kanat.continuum.schemes import GeneralizedAlpha

    ea, m, t0, dv = 1e6, 1.0, 1000.0, 0.1
    cable, state = straight_cable(1000.0, 200, t0, ea, m)
    state, _ = _march(cable, state, _Drive((-dv, 0.0)), 0.0025, 200, GeneralizedAlpha(-0.3))
    jump = math.sqrt(ea * m) * dv
    speed = _front(cable.s, state.y[:, 0], t0 + 0.5 * jump) / state.t
    return speed, np.median(state.y[cable.s < 300.0, 0]) - t0, math.sqrt(ea / m), jump


@check("longitudinal-speed", "7.3", "a longitudinal step travels at the axial wave speed",
       "c = sqrt(EA/m) = 1000 m/s (EA = 1e6 N, m = 1 kg/m)", Tolerance(rel=0.02), "m/s")
def longitudinal_speed():
    speed, _, exact, _ = _longitudinal()
    return speed, exact


@check("longitudinal-jump", "7.3", "the tension jump behind a longitudinal step",
       "dT = sqrt(EA m) dV = 100 N (dV = 0.1 m/s)", Tolerance(rel=0.02), "N")
def longitudinal_jump():
    _, jump, _, exact = _longitudinal()
    return jump, exact


@check("transverse-speed", "7.3", "a transverse kink travels at the transverse wave speed",
       "c = sqrt(T / (m + m_a)) (T = 1000 N, m = 1, m_a = 0.6 kg/m)", Tolerance(rel=0.02), "m/s")
def transverse_speed():
    from kanat.continuum.schemes import GeneralizedAlpha

    t0, m, ma, dv = 1000.0, 1.0, 0.6, 0.05
    cable, state = straight_cable(1000.0, 250, t0, 1e7, m, ma)
    state, _ = _march(cable, state, _Drive((0.0, dv)), 0.05, 200, GeneralizedAlpha(-0.3))
    return _front(cable.s, state.y[:, 2], 0.5 * dv) / state.t, math.sqrt(t0 / (m + ma))


@check("taut-string-frequency", "7.3", "a taut string's fundamental frequency",
       "f = c_t / 2L with c_t = sqrt(T / (m (1 + T/EA)))", Tolerance(rel=0.01), "Hz")
def taut_string_frequency():
    from kanat.continuum.schemes import Box

    length, t0, m = 100.0, 1000.0, 1.0
    cable, state = straight_cable(length, 50, t0, 1e7, m)
    state.y[:, 2] = 0.01 * np.sin(np.pi * cable.s / length)
    _, trace = _march(cable, state, _Drive(), 0.02, 600, Box(), probe=lambda s: s.y[25, 2])
    return 1.0 / _period(trace), math.sqrt(t0 / (m * (1 + t0 / 1e7))) / (2 * length)


@check("axial-end-mass-frequency", "7.3", "axial natural frequency of a cable with an end mass",
       "omega = beta sqrt(EA/m) / L with beta tan(beta) = m L / M (m L / M = 1)", Tolerance(rel=0.01), "rad/s")
def axial_end_mass_frequency():
    from scipy.optimize import brentq

    from kanat.continuum import kernels2d as k
    from kanat.continuum.model2d import EndCondition
    from kanat.continuum.schemes import Box

    length, ea, m, body, force = 100.0, 1e6, 1.0, 100.0, 1000.0
    beta = brentq(lambda b: b * np.tan(b) - m * length / body, 1e-6, np.pi / 2 - 1e-9)
    cable, state = straight_cable(length, 50, force, ea, m, end=EndCondition(k.BODY, mass=body, force=(force, 0.0)))
    state.y[:, 0] = force + 0.01 * ea * beta / length * np.cos(beta * cable.s / length)
    _, trace = _march(cable, state, _Drive(), 0.004, 500, Box(), probe=lambda s: s.y[-1, 1])
    return 2 * np.pi / _period(trace), beta * math.sqrt(ea / m) / length


STEADY_TOW = """
name: steady-tow
model: continuum
environment: {water_density: 1025, depth: 2000}
line_types:
  towcable: {diameter: 0.0173, mass: 1.12, weight_in_water: 8.89, axial_stiffness: 1.2717e7, added_mass: 0.24,
             drag_normal: 1.5, drag_tangential: 0.01}
bodies: {sled: {mass: 1135, net_buoyancy: -6686, drag_area: 0.3276}}
vessel: {tow_point: [0, 0, 0], track: [{straight: {speed_kn: 6, duration: 100}}]}
cables: [{name: tow, line_type: towcable, length: 1000, segments: 20, from: vessel, to: sled}]
simulation: {scheme: generalized-alpha, lambda_inf: -0.5, duration: 30, dt: 1.0, output_dt: 1.0, dimensions: 2}
"""


@check("steady-tow", "7.4", "a run from the static state at constant speed stays steady",
       "body position relative to the tow point and the tension stay at their initial values; largest "
       "relative change (of 1000 m, of the top tension) over 30 s", Tolerance(abs=1e-6))
def steady_tow():
    from kanat import api

    ds = api.simulate(api.load_case(STEADY_TOW))
    relative = ds["body_position"].values[:, 0] - ds["vessel_position"].values
    drift = np.abs(relative - relative[0]).max() / 1000.0
    tension = np.abs(ds["tension"].values - ds["tension"].values[0]).max() / ds["tension"].values.max()
    return max(drift, tension), 0.0


@check("pitch-fourier-vs-time", "7.9", "Gaisha: Fourier steady state against time integration",
       "periodic orbit by shooting (time integration); worst max|difference| / amplitude over the modes "
       "off, sinusoidal, rectangular (50 harmonics)", Tolerance(abs=0.01))
def pitch_fourier_vs_time():
    from kanat.vessel.pitch import Off, PitchSystem, Rectangular, Sinusoidal, solve_mode

    system, times = PitchSystem(2e7, 0.876, 7e5, 2 * math.pi / 10), np.linspace(0.0, 10.0, 401)
    worst = 0.0
    for law in (Off(), Sinusoidal(), Rectangular()):
        shot = solve_mode(system, law, 1e6, times, method="shooting")
        fourier = solve_mode(system, law, 1e6, times, 50)
        worst = max(worst, np.max(np.abs(fourier.pitch - shot.pitch)) / shot.amplitude)
    return worst, 0.0


@check("pitch-rectangular-mean", "7.9", "Gaisha: mean pitch offset of the rectangular mode",
       "M0 / (2 I_y omega_0^2) (the mean of f_2 = M0/2)", Tolerance(rel=1e-3), "rad")
def pitch_rectangular_mean():
    from kanat.vessel.pitch import PitchSystem, Rectangular, solve_mode

    i_y, w0, m0 = 2e7, 0.876, 1e6
    times = np.linspace(0.0, 10.0, 2001)[:-1]
    response = solve_mode(PitchSystem(i_y, w0, 7e5, 2 * math.pi / 10), Rectangular(), m0, times, 50)
    return np.mean(response.pitch), m0 / (2 * i_y * w0**2)
