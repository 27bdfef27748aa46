"""What several test modules share: the repository's folders, case builders, runs, output cleaning.

Test modules import from here, never from each other. The test modules sit one folder down, by
area (tests/README.md); ``pythonpath = ["tests"]`` in pyproject.toml's pytest options puts this
folder on ``sys.path`` so that ``from helpers import ...`` works from any of them.
"""
import math
import os
import re
import signal
import sys
import warnings
from pathlib import Path

import numpy as np

from kanat import api, dynamics
from kanat.continuum.stepper import step
from kanat.io import load_case
from kanat.io.results import case_sha256
from kanat.io.stream import ResultStream

ROOT = Path(__file__).resolve().parents[1]
"""The repository's root: every path a test reads is written from here, never from its own file."""
EXAMPLES = ROOT / "examples"
DATA = ROOT / "tests" / "data"
"""Reference data of the tests, with its source written beside it."""
STEP_CASE = (EXAMPLES / "speed_step_2d.yaml").read_text()


def plain(output: str) -> str:
    """Command output as one line of words: panel borders removed, wrapped lines joined."""
    return " ".join(re.sub("[│╭╮╰╯─]", " ", output).split())


def _ctrl_c_as_in_a_terminal() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)


CTRL_C = {"preexec_fn": _ctrl_c_as_in_a_terminal}
"""Popen keywords giving the child Ctrl-C as a terminal would: a pytest-xdist worker ignores SIGINT,
and a child inherits that (Python then installs no KeyboardInterrupt handler)."""


def kanat_command(*args) -> list[str]:
    """The command line ``kanat ARGS`` for :mod:`subprocess`, run by this interpreter."""
    return [sys.executable, "-m", "kanat.cli", *map(str, args)]


def run(case, output=None, **options):
    """Run ``case`` through :func:`kanat.api.run` (to ``output`` if given) and return its
    :class:`kanat.dynamics.RunSummary`."""
    return api.run(case, output=output, **options).summary


class _Killed(BaseException):
    """Stands for a kill -9 in an in-process run."""


def killed_run(case, output, at: float, every: int):
    """Run ``case`` to ``output`` with a checkpoint every ``every`` outputs and stop it dead at
    simulated time ``at``, as a kill would: the stream's unflushed outputs are lost and the file
    keeps ``status: running``. Returns the time reached."""
    stream = ResultStream(output)
    checkpoints = dynamics.Checkpointer(output, case_sha256(case), every, before=[stream])

    class Kill:
        def start(self, layout, resume_at=None):
            pass

        def record(self, point):
            if point.time >= at - 1e-9:
                raise _Killed

        def flush(self):
            pass

        def finish(self, status, final, attrs):
            pass
    try:
        dynamics.run(lambda: api.dynamic_model(case), [stream, checkpoints, Kill()])
    except _Killed:
        stream.abandon()
    return at


RELEASED_FALL = """
name: released-fall
model: lumped
environment: {{water_density: 1000, gravity: 10}}
line_types:
  wire: {{diameter: 0.01, mass: 0.5, weight_in_water: 2.0, axial_stiffness: 1.0e6,
         drag_normal: 1.2, drag_tangential: {drag_tangential}}}
bodies:
  weight: {{mass: 200, net_buoyancy: -1000, drag_area: 0.5}}
vessel: {{tow_point: [0, 0, -5]}}
cables:
  - {{name: wire, line_type: wire, length: 20, segments: 10, from: vessel, to: weight,
     end_a: {{release_at: 5}}}}
simulation: {{duration: {duration}, dt: {dt}, output_dt: {output_dt}}}
"""


def released_fall(folder, drag_tangential, duration, dt, output_dt):
    """A weight falling on its wire: a 20 m wire (10 elements, 0.5 kg/m, 2 N/m in water, EA 1e6 N)
    hangs a 1000 N weight (200 kg, C_D S 0.5 m^2) from a vessel point 5 m down, in still water, and
    the vessel lets go of it at t = 5 s. With tangential drag the line falls at the terminal
    velocity of its weight; with none the wire falls faster than the weight and folds through its
    own slack, pulled taut again and again. The case is written to ``folder`` and loaded with the
    case checks' notes (a vessel without a track) muted."""
    path = Path(folder) / "released_fall.yaml"
    path.write_text(RELEASED_FALL.format(drag_tangential=drag_tangential, duration=duration, dt=dt,
                                         output_dt=output_dt))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path)


def step_case_text(duration=600, dt=1.0, segments=100, before=60, to_kn=10, extra=""):
    """``examples/speed_step_2d.yaml`` with its duration, step, grid and speed step changed."""
    text = STEP_CASE.replace("duration: 600\n", f"duration: {duration}\n").replace("dt: 1.0\n", f"dt: {dt}\n")
    text = text.replace("output_dt: 1.0", f"output_dt: {dt}").replace("segments: 100", f"segments: {segments}")
    text = text.replace("speed_kn: 6, duration: 60", f"speed_kn: 6, duration: {before}")
    return text.replace("to_speed_kn: 10", f"to_speed_kn: {to_kn}") + extra


def short_case(duration=60, segments=20, before=10):
    """speed_step_2d.yaml shortened: 6 kn for ``before`` s, then the step; ``segments`` elements."""
    text = STEP_CASE.replace("duration: 600\n", f"duration: {duration}\n").replace("segments: 100", f"segments: {segments}")
    return text.replace("speed_kn: 6, duration: 60", f"speed_kn: 6, duration: {before}")


class StepDrive:
    """First end moving with velocity ``velocity`` for t > 0 (at rest before), far end held."""

    def __init__(self, velocity):
        self.velocity = velocity

    def velocities(self, t):
        return (self.velocity if t > 0 else (0.0, 0.0)), (0.0, 0.0)

    def origin(self, t):
        return np.array([self.velocity[0] * t, self.velocity[1] * t])


def march(cable, state, drive, dt, steps, scheme):
    """``steps`` planar steps of ``dt`` with a generalized-α family ``scheme``."""
    coefficients = scheme.coefficients()
    for _ in range(steps):
        state, _ = step(cable, state, dt, coefficients, drive)
    return state


def front(s, values, level):
    """Arclength where ``values`` first falls through ``level`` walking from s = 0."""
    i = np.argmax(values < level)
    return s[i - 1] + (level - values[i - 1]) / (values[i] - values[i - 1]) * (s[i] - s[i - 1])


class quiet:
    """Silence MoorDyn's console output (C-level stdout)."""

    def __enter__(self):
        sys.stdout.flush()
        self.saved = os.dup(1)
        self.null = open(os.devnull, "w")
        os.dup2(self.null.fileno(), 1)

    def __exit__(self, *exc):
        os.dup2(self.saved, 1)
        os.close(self.saved)
        self.null.close()


class RotatedDrive:
    """A 3-D continuum model's tow point motion rotated by ``rotation`` about the vertical."""

    def __init__(self, model, rotation):
        self.model, self.rotation = model, rotation

    def velocities(self, t):
        v0, v1 = self.model.velocities(t)
        return self.rotation @ v0, v1

    def origin(self, t):
        return self.rotation @ self.model.origin(t)


def step_rotated(model, state, angle_deg: float, steps: int = 20):
    """``steps`` steps of 1 s of a 3-D continuum ``state`` and of the same state (positions, chart and
    tow point motion) rotated by ``angle_deg`` about the vertical: ``(plain, turned, rotation)``."""
    from kanat.continuum.schemes import GeneralizedAlpha
    from kanat.continuum.spatial import SpatialState, step3

    a = np.radians(angle_deg)
    rotation = np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])
    turned = SpatialState(state.t, state.y, state.rate, state.xyz @ rotation.T, rotation @ state.chart)
    coefficients, plain = GeneralizedAlpha().coefficients(), state
    for _ in range(steps):
        plain, _ = model.step(plain, 1.0, coefficients)
        turned, _ = step3(model.cable, turned, 1.0, coefficients, RotatedDrive(model, rotation))
    return plain, turned, rotation


def zero_crossing_period(t, signal) -> float:
    """The mean period of ``signal`` sampled at times ``t``: twice the mean interval between its zero
    crossings, each placed by linear interpolation."""
    sign = np.signbit(signal)
    idx = np.nonzero(sign[1:] != sign[:-1])[0]
    times = t[idx] - signal[idx] * (t[idx + 1] - t[idx]) / (signal[idx + 1] - signal[idx])
    return 2.0 * np.mean(np.diff(times))


def scatter_of_mean_square(b, omega, t):
    """Standard deviation of the record mean of ``(sum b cos(w t - phi))^2`` over the equally
    spaced times ``t`` when the phases ``phi`` are independent and uniform: each product of
    components averages to ``b_j b_k / 2`` times the record mean of ``cos(W t - psi)``,
    ``W = w_j +- w_k``, whose variance is ``|mean exp(i W t)|^2 / 2``; different products are
    uncorrelated. Over ``N`` samples ``dt`` apart ``|mean exp(i W t)| = |sin(N W dt / 2) /
    (N sin(W dt / 2))|`` (Dirichlet's kernel), whatever the spacing of the frequencies."""
    t = np.asarray(t, float)
    dt, count = (t[-1] - t[0]) / (len(t) - 1), len(t)
    np.testing.assert_allclose(np.diff(t), dt, rtol=1e-6, atol=1e-9)

    def power(w):
        half = 0.5 * np.asarray(w) * dt
        den = count * np.sin(half)
        tiny = np.abs(den) < 1e-12
        return np.where(tiny, 1.0, np.sin(count * half) / np.where(tiny, 1.0, den)) ** 2

    var = np.sum((b**2 / 2) ** 2 * 0.5 * power(2 * omega))
    j, k = np.triu_indices(len(b), 1)
    var += np.sum((b[j] * b[k]) ** 2 * 0.5 * (power(omega[j] - omega[k]) + power(omega[j] + omega[k])))
    return math.sqrt(var)


def harmonic_fit(t, values, omega):
    """Mean and complex amplitude ``X`` (``|X| cos(omega t + arg X)``) of ``values`` (k, ...) at ``t``
    (k,), by least squares; ``omega`` a frequency, or several fitted together (``X`` then has a
    leading frequency axis)."""
    columns = [np.ones_like(t)] + [f(w * t) for w in np.atleast_1d(omega) for f in (np.cos, np.sin)]
    coef = np.linalg.lstsq(np.column_stack(columns), values.reshape(len(t), -1), rcond=None)[0]
    amplitude = coef[1::2] - 1j * coef[2::2]
    return coef[0], amplitude if np.ndim(omega) else amplitude[0]


def phase_gap(a, b):
    """``a - b`` wrapped to (-pi, pi] [rad]."""
    return np.angle(np.exp(1j * (np.asarray(a) - np.asarray(b))))


def assert_tensions_agree(fd, td, omega, window: float, rtol=0.05, atol: float = 0.05):
    """Every node's tension amplitude in the frequency-domain result ``fd`` within ``rtol`` and its
    phase within ``atol`` [rad] of the time-domain run ``td``'s, fitted at ``omega`` [rad/s] (a
    frequency, or several fitted together, ``rtol`` then one or one per frequency) over its last
    ``window`` seconds."""
    t = td.time.values
    keep = t >= t[-1] - window
    _, fitted = harmonic_fit(t[keep], td.tension.values[keep], omega)
    fitted = fitted.reshape(np.size(omega), -1)
    for f, (tension, tolerance) in enumerate(zip(fitted, np.broadcast_to(rtol, len(fitted)))):
        np.testing.assert_allclose(fd.tension_amplitude.values[f], np.abs(tension), rtol=tolerance)
        np.testing.assert_allclose(phase_gap(fd.tension_phase.values[f], np.angle(tension)), 0.0, atol=atol)


def frequency_and_time(frequency_case, time_case=None):
    """The frequency-domain solution of ``frequency_case`` and the time-domain run of ``time_case``
    (default: the same case with ``simulation.method: time``), warnings and progress silenced."""
    from kanat import solve_frequency
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fd = solve_frequency(frequency_case)
        with quiet():
            td = api.run(time_case or frequency_case.replace({"simulation.method": "time"})).dataset
    return fd, td


def grounded_catenary(span, rise, length, weight, stiffness):
    """Horizontal tension ``H`` [N] and suspended length ``L_s`` [m] of the elastic catenary with a
    grounded part (no friction): ``X = L - L_s + (H/w) asinh(w L_s / H) + H L / EA``,
    ``Z = (H/w)(sqrt(1 + (w L_s / H)^2) - 1) + w L_s^2 / (2 EA)`` (Irvine 1981, the line meeting the
    seabed tangentially)."""
    from scipy.optimize import fsolve

    def equations(unknowns):
        horizontal, suspended = unknowns
        a, v = horizontal / weight, weight * suspended / horizontal
        return [length - suspended + a * np.arcsinh(v) + horizontal * length / stiffness - span,
                a * (np.sqrt(1.0 + v * v) - 1.0) + weight * suspended ** 2 / (2.0 * stiffness) - rise]
    horizontal, suspended = fsolve(equations, [1e5, 300.0], xtol=1e-13)
    assert np.allclose(equations([horizontal, suspended]), 0.0, atol=1e-6)
    return horizontal, suspended


def turned_mooring_buoy(degrees: float, changes: dict):
    """``examples/mooring_3leg.yaml`` (solved by statics) with ``changes`` (seabed, body keys) and the
    buoy's heading and its anchors turned by ``degrees`` about the vertical; a ``bodies.buoy.force``
    in ``changes`` is turned with them. Returns the case and the turn (3, 3)."""
    angle = math.radians(degrees)
    turn = np.array([[math.cos(angle), -math.sin(angle), 0.0], [math.sin(angle), math.cos(angle), 0.0],
                     [0.0, 0.0, 1.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(EXAMPLES / "mooring_3leg.yaml", solver="statics")
    changes = {**changes, "bodies.buoy.orientation_deg": [0.0, 0.0, degrees]}
    if "bodies.buoy.force" in changes:
        changes["bodies.buoy.force"] = (turn @ np.asarray(changes["bodies.buoy.force"], dtype=float)).tolist()
    for k, cable in enumerate(case.cables):
        changes[f"cables[{k}].from"] = {"anchor": (turn @ np.asarray(cable.from_.position)).tolist()}
    return case.replace(changes), turn


def assert_network_jacobian_is_its_central_difference(problem, q, rtol=0.0):
    """Network statics' Jacobian dR/dq at ``q`` (:func:`kanat.statics.network.assemble`) within
    ``2e-5`` of its largest entry (and ``rtol``) of central differences (steps 1e-6 m, 1e-8 rad)."""
    from kanat.statics.network import assemble
    _, J, _, _ = assemble(problem, q)
    fd = np.zeros_like(J)
    for k in range(len(q)):
        step = np.zeros(len(q))
        step[k] = 1e-6 if k < 3 else 1e-8
        fd[:, k] = (assemble(problem, q + step)[0] - assemble(problem, q - step)[0]) / (2 * step[k])
    np.testing.assert_allclose(J, fd, rtol=rtol, atol=2e-5 * np.max(np.abs(fd)))
