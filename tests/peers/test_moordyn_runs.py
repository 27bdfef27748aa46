"""MoorDyn input files run through kanat's lumped model (``kanat run FILE``), and agree with
MoorDyn-C (PyPI ``moordyn``) run side by side on the same file.

* every dynamic MoorDyn example runs from the command line to ``status: ok``;
* the static states agree with MoorDyn's initial condition on the same file (node positions
  within 1 cm, the fairlead segment's tension within 0.5 %);
* optional (``moordyn`` installed; slow): the three-leg chain mooring with the vessel moving
  as in waves, 120 s — fairlead tension mean and range over 60-120 s within 1 % and 5 % of
  MoorDyn's RK2 at 1 ms, kanat on RK4 at its safe step (measured on 2026-11-25: mean 0.02-0.04 %,
  range 0.03-0.2 %; kanat's implicit scheme at 0.05 s: 0.05-0.13 % and 2.6-5.4 %, at 0.1 s 0.13-0.25 %
  and 14-26 %: its numerical damping flattens the tension's peaks; benchmarks/RESULTS.md).
"""
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from kanat import api
from kanat.cli import app
from kanat.io import load_case
from kanat.io.results import read_result
from kanat.lumped.adapter import LumpedModel

from helpers import EXAMPLES, quiet
from helpers_moordyn import run_moordyn

FILES = EXAMPLES / "moordyn"
CHAIN = FILES / "three_leg_chain_50.dat"
BASE = np.array([[20.0, 0.0, -8.0], [-10.0, 17.321, -8.0], [-10.0, -17.321, -8.0]])
MOTION = [{"dof": "surge", "amplitude": 2.0, "period": 11.0, "phase_deg": -90.0},
          {"dof": "heave", "amplitude": 1.0, "period": 9.0, "phase_deg": -90.0}]


def displacement(t):
    return np.array([-2.0 * math.cos(2 * math.pi * t / 11.0), 0.0, -1.0 * math.cos(2 * math.pi * t / 9.0)])


@pytest.mark.parametrize("name", ["three_leg_chain_50.dat", "buoy_spread_mooring.dat"])
def test_kanat_run_takes_a_moordyn_file(name, tmp_path, monkeypatch):
    """The file as it is, shortened to 2 s (an environment override of the run's length is not
    a case key: the test writes the file with a shorter TMax)."""
    text = (FILES / name).read_text()
    short = tmp_path / name
    short.write_text(text.replace("600.0      TMax", "2.0        TMax"))
    out = tmp_path / "out.nc"
    result = CliRunner().invoke(app, ["run", str(short), "-o", str(out)])
    assert result.exit_code == 0, result.output
    ds = read_result(out)
    assert ds.attrs["status"] == "ok"
    assert ds.attrs["model"] == "lumped"
    assert np.all(ds.seabed_contact_length.values > 100.0)          # the chains rest on the seabed


def test_the_static_state_agrees_with_moordyns_initial_condition(moordyn, moordyn_folder):
    copy = moordyn_folder(CHAIN)
    with quiet():
        system = moordyn.Create(str(copy))
        moordyn.Init(system, list((BASE + displacement(0.0)).ravel()), [0.0] * 9)
        lines = [moordyn.GetLine(system, i) for i in (1, 2, 3)]
        theirs = [moordyn.GetLineFairTen(line) for line in lines]
        nodes = np.array([moordyn.GetLineNodePos(lines[0], k) for k in range(51)])
        moordyn.Close(system)
    case = load_case(CHAIN).replace({"vessel.motion": MOTION, "simulation.scheme": "rk4"})
    model = LumpedModel(case)
    values = model.outputs(model.initial())
    ours = [values["segment_tension"][model.net.cable_first_element[c] + 49] for c in range(3)]
    np.testing.assert_allclose(ours, theirs, rtol=5e-3)
    mine = values["position"][model.net.node_cable == "line1"]
    assert np.max(np.linalg.norm(mine - nodes, axis=1)) < 0.01


@pytest.mark.slow
def test_a_moored_vessel_in_waves_agrees_with_moordyn_side_by_side(moordyn, moordyn_folder):
    duration, coupling = 120.0, 0.05
    copy = moordyn_folder(CHAIN)
    _, theirs = run_moordyn(
        moordyn, copy, duration, coupling,
        lambda system: [moordyn.GetLineFairTen(moordyn.GetLine(system, i)) for i in (1, 2, 3)], 10,
        point=lambda t: (BASE + displacement(t)).ravel(),
        velocity=lambda t: np.tile((displacement(t + coupling) - displacement(t)) / coupling, 3),
        scheme="RK2", dt=0.001)
    for scheme in ("rk4", None):                   # rk4 at its safe step, and the default (implicit) scheme
        case = load_case(CHAIN).replace({"vessel.motion": MOTION, "simulation.duration": duration,
                                         "simulation.output_dt": 0.5, "simulation.scheme": scheme})
        ds = api.run(case).dataset
        assert ds.attrs["status"] == "ok"
        last = [int(np.flatnonzero(ds.segment_cable.values == f"line{c}")[-1]) for c in (1, 2, 3)]
        t = ds.time.values
        window_ours = (t >= duration / 2) & (t <= duration)
        window_theirs = theirs[:, 0] >= duration / 2
        for c, k in enumerate(last):
            ours = ds.segment_tension.values[window_ours, k]
            ref = theirs[window_theirs, c + 1]
            assert ours.mean() == pytest.approx(ref.mean(), rel=1e-2)
            assert np.ptp(ours) == pytest.approx(np.ptp(ref), rel=3e-2)
            assert ours.max() == pytest.approx(ref.max(), rel=3e-2)
