"""The implicit lumped scheme's local time-integration error estimate (:mod:`kanat.lumped.time_error`).

Oracles:

- eq. (1) against the exact local error of generalized-α on ``x'' = -w^2 x`` (closed form
  ``x_n cos wh + v_n/w sin wh`` from each step's start), for the lumped scheme's coefficients;
- the estimate's order: the local error of a smooth motion falls as ``h^3``;
- the compiled steps against the Python path (their twin) on the same run;
- the steps with and without the estimate's updates: the same states bit for bit (it only observes).
"""
import math
import warnings

import numpy as np
import pytest

import kanat
from kanat.io import load_case
from kanat.lumped import advance, time_error
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.lumped.snap import SnapTracker

from helpers import DATA

WD0050 = DATA / "moordyn" / "wd0050_chain.dat"
MOTION = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]


def oscillator_errors(lambda_inf, wh, periods=3.0):
    """Generalized-α on ``x'' = -x`` (w = 1) at ``h = wh``: each step's true local error (against the
    exact motion from the step's start) and eq. (1)'s estimate, after the first period."""
    scheme = GeneralizedAlphaLumped(lambda_inf=lambda_inf)
    am, af, gamma, beta = scheme.coefficients
    h = wh
    x, v, a = 1.0, 0.0, -1.0
    true, estimate = [], []
    for n in range(int(periods * 2 * math.pi / h)):
        predictor = x + h * v + h * h * (0.5 - beta) * a
        a1 = (-((1 - af) * predictor + af * x) - am * a) / ((1 - am) + (1 - af) * beta * h * h)   # eq. (2), linear
        x1 = predictor + h * h * beta * a1
        v1 = v + h * ((1 - gamma) * a + gamma * a1)
        if n * h > 2 * math.pi:
            true.append(x1 - (x * math.cos(h) + v * math.sin(h)))
            estimate.append(time_error.error_factor(scheme.coefficients) * h * h * (a1 - a))
        x, v, a = x1, v1, a1
    return np.array(true), np.array(estimate)


@pytest.mark.parametrize("lambda_inf", [-1.0, -0.8, -0.5, 0.0])
def test_the_estimate_is_the_local_error_of_an_oscillator(lambda_inf):
    """Largest estimate against largest true local error over two periods at w h = 0.05: within 2 %
    (measured 0.2-1.4 %). Newmark's factor ``beta - 1/6`` alone (without the generalized-α shift
    ``(alpha_m - alpha_f)/2``) would be 2.5 times too large at rho_inf = 0.5."""
    true, estimate = oscillator_errors(lambda_inf, 0.05)
    assert np.max(np.abs(estimate)) == pytest.approx(np.max(np.abs(true)), rel=0.02)
    am, af, _, beta = GeneralizedAlphaLumped(lambda_inf=lambda_inf).coefficients
    if am != af:
        assert abs((beta - 1 / 6) / time_error.error_factor((am, af, 0, beta))) > 1.5


def test_the_local_error_falls_as_the_cube_of_the_step():
    peaks = [np.max(np.abs(oscillator_errors(-0.5, wh)[1])) for wh in (0.1, 0.05)]
    assert peaks[0] / peaks[1] == pytest.approx(8.0, rel=0.02)


def driven(duration, dt):
    with warnings.catch_warnings():                          # the file's MoorDyn solver settings
        warnings.simplefilter("ignore")
        return load_case(WD0050).replace({"model": "lumped", "vessel.motion": MOTION, "simulation.duration": duration,
                                          "simulation.output_dt": 0.5, "simulation.dt": dt,
                                          "simulation.scheme": "generalized-alpha-lumped"})


def steps_of(model, state, steps, path):
    """``steps`` implicit steps of ``model`` from ``state`` by ``path`` ("compiled" or "python"), the
    estimate record from zeros: the new state and the record."""
    estimate = advance.time_error_estimate(model.system)
    estimate[:] = 0.0
    tracker = SnapTracker(state.t, model._tensions(state))
    run = advance.COMPILED[GeneralizedAlphaLumped] if path == "compiled" else advance._python_steps
    new, _ = run(model.scheme, model.system, state, model.dt, steps, tracker, model._tensions)
    return new, estimate.copy()


@pytest.mark.slow
def test_compiled_and_python_steps_estimate_alike():
    """MoorDyn's WD0050 chain driven at its fairlead, its first six steps of 0.1 s by each path, each from
    the same state (the compiled modified Newton and the Python full Newton agree to their tolerance):
    the same node for the largest error, eqs. (1) and (2) within 0.1 % (measured 2e-4)."""
    model = LumpedModel(driven(1.0, 0.1))
    state = model.initial().scheme
    for _ in range(6):
        compiled_state, compiled = steps_of(model, state, 1, "compiled")
        _, python = steps_of(model, state, 1, "python")
        assert compiled[[1, 2, 4]] == pytest.approx(python[[1, 2, 4]], abs=1e-9)   # times, node
        assert compiled[[0, 3]] == pytest.approx(python[[0, 3]], rel=1e-3)
        assert compiled[3] > 0.0
        state = compiled_state


def test_the_estimate_only_observes():
    """The compiled steps with the record full (nothing to update) and from zeros: the same states."""
    model = LumpedModel(driven(2.0, 0.1))
    start = model.initial().scheme
    observed, record = steps_of(model, start, 20, "compiled")
    estimate = advance.time_error_estimate(model.system)
    estimate[:] = np.inf
    tracker = SnapTracker(start.t, model._tensions(start))
    blind, _ = advance.COMPILED[GeneralizedAlphaLumped](model.scheme, model.system, start, model.dt, 20, tracker,
                                                        model._tensions)
    assert np.array_equal(observed.x, blind.x) and np.array_equal(observed.v, blind.v)
    assert np.array_equal(observed.a, blind.a)
    assert np.all(record[[0, 3]] > 0.0)


@pytest.fixture(scope="module")
def fall(tmp_path_factory):
    from helpers import released_fall

    return released_fall(tmp_path_factory.mktemp("fall"), drag_tangential=0.0, duration=9, dt=0.01, output_dt=0.5)


@pytest.mark.slow
@pytest.mark.parametrize("dt, verdict", [(0.025, "failed"), (0.005, "warned")])
def test_a_step_through_snaps_warns_or_fails(fall, dt, verdict):
    """A 20 m wire released at t = 5 s falls through its own slack, snapping taut again and again (axial
    period 3.6 ms; rk4 and the implicit scheme at 2 ms agree, tests/lumped/test_lumped_snap_step.py). At
    5 ms eq. (2) reads 0.22 (a warning); at 25 ms 7.2 (the run fails, its outputs up to then kept). At
    10 ms it read 0.62 or 2.2 (a warning or a failure) as the state at the release moved by round-off
    (the hanging wire stepped by rk4 or by the implicit scheme before it): the folding wire's motion
    at that step is not the same from one start to the next."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.run(fall.replace({"simulation.dt": dt})).dataset
    status, estimate = ds.attrs["status"], ds.attrs["time_error_estimate"]
    if verdict == "failed":
        assert status.startswith("failed: the time step does not resolve the motion")
        assert estimate > time_error.FAILURE and "rerun with dt <= " in status
        assert 5.0 < ds.time.values[-1] < 9.0                        # stopped after the release, outputs kept
        said = float(status.split("displacement at t = ")[1].split(" s")[0])    # on the run's clock, not the
        assert said == pytest.approx(ds.attrs["time_error_time"], abs=1e-5)      # released phase's (from 0)
    else:
        assert status == "ok"
        assert time_error.WARNING < estimate < time_error.FAILURE
        assert "the time step does not resolve the motion" in ds.attrs["notes"]
    assert ds.attrs["time_error_time"] > 5.0                         # after the release, on the run's clock


def test_the_verdict_reads_the_thresholds():
    record = time_error.empty()
    record[3:5] = 0.5 * time_error.WARNING, 1.0
    assert time_error.verdict(record, 0.1, str) is None
    record[3] = 2.0 * time_error.WARNING
    kind, text = time_error.verdict(record, 0.1, str)
    assert kind == "warning" and f"rerun with dt <= {time_error.suggested_step(0.1, record[3]):.3g} s" in text
    assert time_error.suggested_step(0.1, record[3]) == pytest.approx(0.1 * (time_error.TARGET / record[3]) ** 0.5)
    record[3] = 2.0 * time_error.FAILURE
    assert time_error.verdict(record, 0.1, str)[0] == "failure"
