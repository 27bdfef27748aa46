"""The start of a run: the marched first guess of the steady state, and what a run imports.

Oracles: the statics' own right-hand side (the march's float twin), the shooting solver
(DOP853 at 1e-11 with root finding) for the marched shape, and the continuum model's steady
state from the shooting guess for the state the march leads to (equal to round-off).
"""
import subprocess
import sys

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat import api
from kanat.continuum import start
from kanat.statics import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties
from kanat.statics.march import march_from_body, scalar_rhs, steady_guess
from kanat.statics.problem import steady_rhs
from kanat.statics.shooting import solve_shooting

LINE = LineProperties(weight=8.89, axial_stiffness=1.2717e7, diameter=0.0173, drag_normal=1.5, drag_tangential=0.01)
SHEAR = FlowProfile(np.array([-800.0, -200.0, 0.0]), np.array([[-4.1, 0.0], [-3.6, 0.1], [-3.09, 0.0]]))
SLED = BodyEnd(net_buoyancy=-6686.0, drag_area=0.3276)
TOW = FixedEnd((0.0, 0.0))
PROBLEMS = {
    "body at s = L, tow": CableBVP(LINE, 1000.0, TOW, SLED, FlowProfile.uniform(-3.09)),
    "body at s = 0, tow": CableBVP(LINE, 1000.0, SLED, TOW, FlowProfile.uniform(-3.09)),
    "sheared current": CableBVP(LINE, 1000.0, TOW, SLED, SHEAR),
    "buoy on a riser": CableBVP(LINE, 300.0, FixedEnd((0.0, -500.0)), BodyEnd(net_buoyancy=20e3, drag_area=1.0),
                                FlowProfile.uniform(0.8)),
}


@pytest.mark.parametrize("name", PROBLEMS)
def test_the_float_right_hand_side_is_the_statics_one(name):
    problem = PROBLEMS[name]
    rhs = scalar_rhs(problem)
    states = np.random.default_rng(3).normal(size=(4, 50)) * np.array([[100.0], [300.0], [5e3], [5e3]])
    states[1] = -np.abs(states[1])
    expected = steady_rhs(problem, states)
    got = np.array([rhs(*states[1:, j]) for j in range(states.shape[1])]).T
    assert np.max(np.abs(got - expected) / (np.abs(expected) + 1.0)) < 1e-12


@pytest.mark.parametrize("name", PROBLEMS)
def test_the_march_follows_the_shooting_solver(name):
    problem = PROBLEMS[name]
    s = np.linspace(0.0, problem.length, 101)
    marched, shot = march_from_body(problem, s), solve_shooting(problem, s)
    assert marched.method == "march"
    scale = np.max(shot.tension)
    assert np.max(np.abs(marched.force - shot.force)) / scale < 1e-5
    assert np.max(np.hypot(marched.x - shot.x, marched.z - shot.z)) / problem.length < 1e-6


def test_what_the_march_cannot_give_is_left_to_the_statics():
    between_points = CableBVP(LINE, 1200.0, FixedEnd((0.0, -1000.0)), TOW, FlowProfile.uniform(0.5))
    assert march_from_body(between_points, np.linspace(0.0, 1200.0, 11)) is None
    assert steady_guess(between_points, np.linspace(0.0, 1200.0, 11)).method != "march"
    no_load = CableBVP(LINE, 100.0, TOW, BodyEnd(), FlowProfile.uniform(0.0))
    assert march_from_body(no_load, np.linspace(0.0, 100.0, 11)) is None      # slack: the statics explain


@pytest.mark.parametrize("example", ["speed_step_2d.yaml", "pitch_tow_10kn.yaml", "factorization_planar80.yaml"])
def test_the_continuum_start_is_the_steady_state_the_shooting_guess_gives(example, monkeypatch):
    case = api.load_case(EXAMPLES / example)
    marched = api.dynamic_model(case).initial()
    from kanat.statics import solve_cable

    monkeypatch.setattr(start, "steady_guess", lambda problem, s: solve_cable(problem, "shooting", s))
    shot = api.dynamic_model(case).initial()
    scale = np.max(np.abs(shot.y), axis=0)
    assert np.max(np.abs(marched.y - shot.y) / np.where(scale > 0, scale, 1.0)) < 1e-12
    assert np.max(np.abs(marched.xz - shot.xz)) < 1e-12 * case.cables[0].length


RUN_PATH = ("scipy.integrate", "scipy.optimize", "xarray", "kanat.statics.driver", "kanat.io.moordyn")
"""Modules a plain 2-D run does not need: SciPy's solvers (the statics of the start), xarray (the
result is streamed by h5netcdf), the statics driver and the MoorDyn reader (a YAML case)."""
VALIDATE = ("numpy", "numba", "scipy")
"""What checking a plain towed cable does not need: no array is computed (NumPy alone is 0.1 s of CPU)."""
STATICS_FILE = ("xarray", "pandas", "dask")
"""What writing a statics result does not need: its table is written by h5netcdf (kanat.io.result_table)."""


def imported(command: list[str], modules) -> list[str]:
    """Which of ``modules`` ``kanat COMMAND`` has imported when it ends, run in a fresh process."""
    code = ("import sys; from kanat.cli import app\n"
            "try:\n    app(%r)\nexcept SystemExit as done:\n    assert not done.code, done.code\n"
            "print('imported:', *(m for m in %r if m in sys.modules))" % (command, modules))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout.splitlines()[-1].split()[1:]


@pytest.mark.parametrize("verb", ["run", "validate"])
def test_a_plain_run_and_its_validation_import_no_solver_they_do_not_use(verb, tmp_path):
    command = [verb, str(EXAMPLES / "speed_step_2d.yaml")] + (["-o", str(tmp_path / "out.nc")] if verb == "run" else [])
    assert imported(command, RUN_PATH) == []


def test_validating_a_towed_cable_computes_no_array():
    assert imported(["validate", str(EXAMPLES / "speed_step_2d.yaml")], VALIDATE) == []


def test_kanat_statics_of_one_cable_writes_its_file_without_xarray(tmp_path):
    assert imported(["statics", str(EXAMPLES / "towed_body.yaml"), "-o", str(tmp_path / "out.nc")], STATICS_FILE) == []
    assert (tmp_path / "out.nc").exists()
