"""The Python examples run as a user runs them, and print what the API computes."""
import re
import subprocess
import sys

import numpy as np
import pytest

import kanat

from helpers import EXAMPLES

SCRIPTS = sorted((EXAMPLES / "python").glob("*.py"))


def current_step_settles_on_the_statics(printed: str) -> None:
    """subsurface_current_step.py: after 1500 s in the doubled current the top buoy is within 0.2 m of the
    3-D statics of that current (0.047 m measured, over a 90 m move from its first steady state)."""
    status, start, end, distance = re.search(
        r"status: (\w+); top buoy from \[(.*?)\] m to \[(.*?)\] m; .*\(difference ([\d.]+) m\)", printed).groups()
    moved = np.linalg.norm(np.array(end.split(), float) - np.array(start.split(), float))
    assert status == "ok" and moved > 50.0
    assert float(distance) < 0.2


def coupled_float_swings_at_its_mooring_period(printed: str) -> None:
    """coupled_float.py: the platform's surge period under kanat.Coupling within 5 % of 2 pi sqrt((m + a) / k),
    k from kanat's equilibria either side (measured 109.9 s against 107.3 s: the lines' own inertia and
    drag add to the body's), and the free surge decays."""
    period, expected, start, end = (float(v) for v in re.search(
        r"surge period ([\d.]+) s; .*: ([\d.]+) s; surge from ([\d.-]+) m to ([\d.-]+) m", printed).groups())
    assert period == pytest.approx(expected, rel=0.05)
    assert abs(end) < 0.8 * abs(start)


PRINTED = {"subsurface_current_step.py": current_step_settles_on_the_statics,
           "coupled_float.py": coupled_float_swings_at_its_mooring_period}
"""What a script prints, checked beside its run (the other scripts' numbers are checked below)."""


@pytest.mark.slow
@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_python_example_runs(script, tmp_path):
    done = subprocess.run([sys.executable, str(script), str(tmp_path / "picture.png")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (tmp_path / "picture.png").stat().st_size > 20_000
    assert sorted(p.name for p in tmp_path.iterdir()) == ["picture.png"]      # nothing else written
    PRINTED.get(script.name, lambda printed: None)(done.stdout)


@pytest.mark.slow
def test_vary_and_plot_prints_the_apis_numbers(tmp_path):
    done = subprocess.run([sys.executable, str(EXAMPLES / "python" / "vary_and_plot.py"), str(tmp_path / "p.png")],
                          capture_output=True, text=True, timeout=600)
    printed = {float(cn): float(kn) for cn, kn in re.findall(r"C_n = ([\d.]+): top tension up to ([\d.]+) kN",
                                                              done.stdout)}
    base = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace({"simulation.duration": 240})
    ds = kanat.simulate(base.replace({"line_types.towcable.drag_normal": 1.8}))
    assert printed[1.8] == pytest.approx(float(ds.tension.isel(node=0).max()) / 1e3, abs=5e-4)
    depths = dict(re.findall(r"C_n = ([\d.]+): .*body from (-?[\d.]+) m", done.stdout))
    assert float(depths["1.8"]) > float(depths["1.2"])     # more normal drag streams the cable: a shallower body
