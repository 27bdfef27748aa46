"""The implicit lumped scheme's time-error estimate (:mod:`kanat.lumped.time_error`) on runs whose step
does not resolve the motion (WHOI's seatex chain snapping in a wave, WHOI's breaking tow falling slack
after its release) and on resolved runs (MoorDyn's WD0050 chain driven at its fairlead, the default
step; ``examples/lazy_wave.yaml``).

Oracle: each run at dt against the same run at dt/2 (the tensions' largest difference at the outputs,
as a fraction of the largest tension): the estimate is past its warning threshold exactly where the
two differ by tens of per cent, and the difference (after the start's steps, which the estimate passes
over) is 1 to 25 times the estimate on every case.
"""
import warnings

import numpy as np
import pytest

import kanat
from kanat.errors import CaseWarning
from kanat.io import load_case
from kanat.lumped import time_error

from helpers import DATA, EXAMPLES

WAVE = {"type": "regular", "height": 1.0, "period": 8.0, "heading_deg": 0.0, "ramp": 4.0}
MOTION = [{"dof": "surge", "amplitude": 4.0, "period": 12.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]
CASES = {   # name: (file, changes, resolved); measured eq. (2) and tension difference at dt/2 in the comments
    "seatex": (EXAMPLES / "whoi" / "seatex.yaml",                 # 0.043 at t = 12 s; 45 % apart
               {"environment.waves": WAVE, "simulation.duration": 12, "simulation.output_dt": 0.5}, False),
    "breaking": (EXAMPLES / "whoi" / "breaking.yaml", {"simulation.duration": 200}, False),   # 0.065; 56 %
    "wd0050": (DATA / "moordyn" / "wd0050_chain.dat",             # 0.0094; 1.2 %
               {"model": "lumped", "vessel.motion": MOTION, "simulation.duration": 10, "simulation.output_dt": 0.1,
                "simulation.dt": 0.1}, True),
    "lazy_wave": (EXAMPLES / "lazy_wave.yaml",                     # 0.0017; 0.42 % (top element at 0.6 s; its
                                                                   # motion ramped up over 10 s as shipped)
                  {"simulation.duration": 10, "simulation.output_dt": 0.05}, True),
}


def quietly(function, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args)


@pytest.fixture(scope="module")
def pairs():
    """Each case at its dt and at dt/2: ``name -> (coarse, fine)`` results."""
    out = {}
    for name, (path, changes, _) in CASES.items():
        case = quietly(lambda: load_case(path).replace(changes))
        dt = case.simulation.dt
        out[name] = tuple(quietly(kanat.simulate, case.replace({"simulation.dt": dt / k})) for k in (1, 2))
    return out


def difference(coarse, fine) -> float:
    """The tensions' largest difference at the common outputs after the start's steps (those the estimate
    passes over, :data:`kanat.lumped.time_error.START_STEPS`), over the fine run's largest tension."""
    n = min(len(coarse.time), len(fine.time))
    after = coarse.time.values[:n] > time_error.START_STEPS * coarse.attrs["dt"]
    tension = coarse.segment_tension.values[:n][after], fine.segment_tension.values[:n][after]
    return float(np.max(np.abs(tension[0] - tension[1])) / np.max(np.abs(tension[1])))


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_estimate_warns_where_the_step_does_not_resolve_the_motion(pairs, name):
    coarse, fine = pairs[name]
    resolved = CASES[name][2]
    estimate = coarse.attrs["time_error_estimate"]
    assert coarse.attrs["status"] == "ok", coarse.attrs["status"]
    if resolved:
        assert estimate < 0.5 * time_error.WARNING
        assert "does not resolve the motion" not in coarse.attrs["notes"]
    else:
        assert time_error.WARNING < estimate < time_error.FAILURE
        assert "the time step does not resolve the motion" in coarse.attrs["notes"]
        assert difference(coarse, fine) > 0.3                    # 45 % and 56 %


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_estimate_follows_the_difference_between_dt_and_half_dt(pairs, name):
    """Measured: the difference is 1.3 (wd0050), 2.4 (lazy_wave, its motion ramped up; 19 with the ramp taken
    off, the start's axial ringing in the top element) and 10 (seatex, breaking) times the estimate."""
    coarse, fine = pairs[name]
    ratio = difference(coarse, fine) / coarse.attrs["time_error_estimate"]
    assert 1.0 < ratio < 25.0


@pytest.mark.slow
def test_a_run_that_does_not_resolve_its_motion_says_so_as_a_case_warning():
    path, changes, _ = CASES["seatex"]
    case = quietly(lambda: load_case(path).replace(changes))
    with pytest.warns(CaseWarning, match="rerun with dt <= "):
        kanat.simulate(case)
