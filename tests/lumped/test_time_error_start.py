"""The implicit lumped scheme's start check, eq. (3) of :mod:`kanat.lumped.time_error`, and the time-step
error estimate of a coupling (:class:`kanat.Coupling`).

Oracles:

- a step from rest: eq. (2) is ``(beta - 1/6 + alpha_m/2) / beta`` (the step moves by ``beta h^2 a_1``,
  the estimate is ``(beta - 1/6 + alpha_m/2) h^2 a_1``) whatever the step: why eq. (2) passes over a start;
- eq. (3) against its own definition computed from two separate runs, at dt and at dt/2, through the
  whole run loop (the tensions at the outputs over the start's steps): the same number, and past
  :data:`~kanat.lumped.time_error.WARNING` exactly where those runs differ by more;
- the steps with and without the check: the same states bit for bit (it only observes);
- a coupling against the same coupling at half its substep (the forces it returns).
"""
import math
import warnings

import numpy as np
import pytest

import kanat
from kanat.errors import CaseWarning
from kanat.io import load_case
from kanat.lumped import advance, time_error
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.lumped.snap import SnapTracker

from helpers import DATA, EXAMPLES, quiet
from test_coupling import coupled, wd0050

MOTION = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
CASES = {   # name: (file, changes); MoorDyn's WD0050 chain driven from rest; the lazy wave's own motion at full
            # strength from t = 0 (its ramp taken off) and as the example ramps it (over 10 s)
    "wd0050": (DATA / "moordyn" / "wd0050_chain.dat",
               {"model": "lumped", "vessel.motion": MOTION, "simulation.scheme": "generalized-alpha-lumped"}),
    "lazy_wave": (EXAMPLES / "lazy_wave.yaml", {"vessel.motion.ramp": 0.0}),
    "lazy_wave_ramped": (EXAMPLES / "lazy_wave.yaml", {}),
}


def case_at(name, dt, duration):
    path, changes = CASES[name]
    with warnings.catch_warnings():              # WD0050's MoorDyn solver settings, not imported
        warnings.simplefilter("ignore")
        return load_case(path).replace({**changes, "simulation.dt": dt, "simulation.duration": duration,
                                        "simulation.output_dt": dt})


def first_step_ratio(dt):
    """Eq. (2) of the first implicit step of WD0050 from rest at ``dt``, and the start's largest
    acceleration [m/s^2]."""
    model = LumpedModel(case_at("wd0050", dt, 10 * dt))
    state = model.initial().scheme
    estimate = advance.time_error_estimate(model.system)
    estimate[:] = 0.0                                                   # nothing passed over, no pair
    tracker = SnapTracker(state.t, model._tensions(state))
    advance.COMPILED[GeneralizedAlphaLumped](model.scheme, model.system, state, dt, 1, tracker, model._tensions)
    return estimate[3], np.max(np.abs(state.a))


def test_a_step_from_rest_reads_the_same_whatever_the_step():
    """WD0050 starts in equilibrium at rest: its first step's eq. (2) is the scheme's constant (1/4 at the
    default) at 0.1 and 0.05 s alike, to 1e-6: it says nothing of the step, so eq. (2) passes over it."""
    am, af, _, beta = GeneralizedAlphaLumped().coefficients
    constant = time_error.error_factor((am, af, 0.0, beta)) / beta
    for dt in (0.1, 0.05):
        ratio, start_acceleration = first_step_ratio(dt)
        assert start_acceleration < 1e-6
        assert ratio == pytest.approx(constant, abs=1e-6)
    assert constant == pytest.approx(0.25)


def test_the_start_check_only_observes():
    """15 steps of WD0050 at 0.1 s with the start check and without it (marked done): the same states
    bit for bit, the same force count and eqs. (1)-(2); the check's eq. (3) is kept."""
    runs = []
    for check in (True, False):
        model = LumpedModel(case_at("wd0050", 0.1, 2.0))
        state = model.initial().scheme
        estimate = advance.time_error_estimate(model.system)
        if not check:
            estimate[6:8] = 0.0
        tracker = SnapTracker(state.t, model._tensions(state))
        new, _ = advance.advance(model.scheme, model.system, state, 0.1, 15, tracker, model._tensions)
        runs.append((new, estimate.copy(), model.system.evaluations))
    (checked, with_check, count), (plain, without, plain_count) = runs
    for name in ("x", "v", "a"):
        assert np.array_equal(getattr(checked, name), getattr(plain, name))
    assert count == plain_count
    assert np.array_equal(with_check[:6], without[:6])
    assert 0.0 < with_check[6] < time_error.WARNING and with_check[7] > 0.0


def difference(coarse, fine):
    """Eq. (3) from two runs' outputs: the tensions' largest difference at the coarse run's outputs
    after the start, over the fine run's largest tension there."""
    common = np.isin(np.round(fine.time.values, 9), np.round(coarse.time.values, 9))
    tension = coarse.segment_tension.values[1:], fine.segment_tension.values[common][1:]
    return float(np.max(np.abs(tension[0] - tension[1])) / np.max(np.abs(tension[1])))


@pytest.mark.slow
@pytest.mark.parametrize("name, dt, flagged", [
    ("lazy_wave", 0.2, True),       # eq. (3) 0.076: the top tension rings (0.25 s period) for a second
    ("lazy_wave", 0.05, True),      # 0.036: five steps a period do not follow the ringing
    ("lazy_wave", 0.025, False),    # 0.014
    ("lazy_wave_ramped", 0.05, False),  # 0.0087: the example's own motion, ramped up over 10 s
    ("wd0050", 0.1, False),         # 0.0062: the chain's smooth start
])
def test_the_start_check_is_the_difference_of_the_runs_at_dt_and_half_dt(name, dt, flagged):
    """The lazy wave's fairlead, its ramp taken off, accelerates at once (0.79 m/s^2 in heave from rest):
    its top tension rings from 42 to 54 kN and back within 0.2 s; the example's 10 s ramp resolves it. Eq. (3) equals the runs' own difference at
    the outputs within 2 % (measured 0.1 %), and both are past the warning threshold where the start is
    flagged, with the note; eq. (2) stays below it on every case (it cannot see the start)."""
    duration = time_error.START_STEPS * dt
    with quiet():
        coarse, fine = (kanat.simulate(case_at(name, step, duration)) for step in (dt, dt / 2))
    estimate = coarse.attrs["time_error_start"]
    assert coarse.attrs["status"] == "ok"
    assert estimate == pytest.approx(difference(coarse, fine), rel=0.02)
    assert (estimate > time_error.WARNING) == flagged
    assert ("the time step does not resolve the start" in coarse.attrs["notes"]) == flagged
    assert coarse.attrs["time_error_estimate"] < time_error.WARNING


def lazy_path(t):
    """The lazy wave's fairlead under its vessel's motion (heave 2 m / 10 s, surge 3 m / 60 s, from rest)."""
    return np.array([[-3.0 * math.cos(2 * math.pi * t / 60.0), 0.0, -10.0 - 2.0 * math.cos(2 * math.pi * t / 10.0)]])


def wd0050_path(t):
    return np.array([[-4.0 * math.cos(2 * math.pi * t / 12.0), 0.0, -math.cos(2 * math.pi * t / 9.0)]])


def coupled_forces(case, path, dt, steps, substep):
    """The forces of a coupling of ``case`` at ``substep`` driven along ``path`` by its secants, the
    coupling and its time-step warnings."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        coupling = kanat.Coupling(case, substep=substep)
        forces = [coupling.initialize(path(0.0))]
        for k in range(steps):
            t = k * dt
            forces.append(coupling.step(t, dt, path(t), (path(t + dt) - path(t)) / dt))
    found = [str(w.message) for w in caught if issubclass(w.category, CaseWarning) and "time step" in str(w.message)]
    return np.array(forces)[:, 0], coupling, found


def relative_gap(forces, finer):
    return float(np.max(np.linalg.norm(forces - finer, axis=1)) / np.max(np.linalg.norm(finer, axis=1)))


@pytest.mark.slow
def test_a_coupling_reports_its_time_error_and_warns_as_a_run_does():
    """The lazy wave coupled at 0.2 s, its fairlead moved along the secants of its motion from a line at
    rest (a velocity jump at every step): eq. (3) reads 0.43, the coupling warns once for the start and
    keeps the note, and the forces it returns at substep 0.1 s differ by 54 % of the largest (oracle)."""
    case = load_case(EXAMPLES / "lazy_wave.yaml")
    forces, coupling, found = coupled_forces(case, lazy_path, 0.2, 10, 0.2)
    finer = coupled_forces(case, lazy_path, 0.2, 10, 0.1)[0]
    attributes = coupling.time_error
    assert set(attributes) == {"time_error_estimate", "time_error_time", "time_error_displacement",
                               "time_error_start", "time_error_start_time"}
    assert attributes["time_error_start"] > time_error.WARNING
    assert relative_gap(forces, finer) > time_error.WARNING
    assert len(found) == 1 and found[0].startswith("the time step does not resolve the start")
    assert found[0] in coupling.notes


def test_a_resolved_coupling_does_not_warn():
    """WD0050 coupled at 0.1 s along its motion's secants (from rest): eqs. (2) and (3) below the warning
    threshold (measured 0.0087, 0.015), no warning; the forces at substep 0.05 s agree within 3 % of the
    largest (measured 2.7 %: the secants' velocity kinks every coupling step, which the finer substep
    follows more closely; the unresolved coupling above differs by 54 %)."""
    forces, coupling, found = coupled_forces(wd0050(), wd0050_path, 0.1, 20, 0.1)
    finer = coupled_forces(wd0050(), wd0050_path, 0.1, 20, 0.05)[0]
    attributes = coupling.time_error
    assert attributes["time_error_estimate"] < time_error.WARNING
    assert 0.0 < attributes["time_error_start"] < time_error.WARNING
    assert not found and not any("time step" in note for note in coupling.notes)
    assert relative_gap(forces, finer) < 0.03
