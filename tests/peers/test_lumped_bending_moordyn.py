"""Bending stiffness in the lumped model beside MoorDyn-C's (PyPI ``moordyn``), the same MoorDyn file
(its line type's ``EI`` column is kanat's ``bending_stiffness``).

The line is the steep jumper of tests/lumped/test_lumped_driven.py (``helpers_moordyn.jumper_file``: 170 m, d 0.396 m, 165 kg/m, EA 5e8 N,
damping ratio 0.8, Cd 1, Ca 1, 34 segments, from an anchor 100 m away at 55 m depth to a fairlead 5 m
down, in 100 m of water) with EI 2e6 or 2e7 N m^2 (pinned ends in both codes: MoorDyn clamps a line
only where it meets a rod).

**The start.** MoorDyn's own initial state (its dynamic relaxation, ``TmaxIC``) is not the equilibrium
of a line with EI: after its default relaxation its nodes lie 1.2 m (EI 2e6) and 5.5 m (EI 2e7) from
kanat's equilibrium, and 3.8 m (EI 2e7) after 600 s of relaxation with ``threshIC 1e-6`` (measured,
MoorDyn 2.7.2): the bent line creeps towards its shape slowly under the relaxation's scaled drag. So
both codes start from kanat's equilibrium, written into MoorDyn's serialized state (``Serialize``:
the line's interior nodes as rows ``(x, y, z, vx, vy, vz)``, found by their positions; ``Deserialize``)
— and MoorDyn holds it: held still for 20 s its nodes stay within 2 cm of it (the first test), where
its own start was metres away. The second test drives the fairlead as test_lumped_driven.py's jumper
(surge 10 m in 27 s, from rest) with EI and compares the top tension and the middle node's path over
two periods.
"""
import math
import warnings

import numpy as np
import pytest

from kanat import api
from kanat.io import load_case
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.equilibrium import starting_state

from helpers import quiet
from helpers_moordyn import jumper_file, run_moordyn

pytestmark = pytest.mark.slow

SEGMENTS, MIDDLE, PERIOD = 34, 17, 27.0


def surge(t: float) -> np.ndarray:
    """The fairlead: surge ``-10 cos(2 pi t / 27)`` m from (0, 0, -5), at rest at t = 0."""
    return np.array([-10.0 * math.cos(2 * math.pi * t / PERIOD), 0.0, -5.0])


def kanat_case(path, duration: float, motion: bool):
    keys = {"model": "lumped", "simulation": {"duration": duration, "output_dt": 0.1}}
    if motion:
        keys["vessel.motion"] = [{"dof": "surge", "amplitude": 10.0, "period": PERIOD, "phase_deg": -90.0}]
    with warnings.catch_warnings():                  # the file's MoorDyn solver settings, not imported
        warnings.simplefilter("ignore")
        return load_case(path).replace(keys)


def nodes(moordyn, line) -> np.ndarray:
    return np.array([moordyn.GetLineNodePos(line, i) for i in range(SEGMENTS + 1)])


def start_from(moordyn, system, line, x: np.ndarray) -> None:
    """Put the line's interior nodes at ``x[1:-1]`` at rest in MoorDyn's state (module docstring)."""
    now = nodes(moordyn, line)[1:-1]
    state = np.frombuffer(moordyn.Serialize(system), dtype=np.float64).copy()
    n = len(now)
    found = [i for i in range(len(state) - 6 * n + 1)
             if np.array_equal(state[i:i + 6 * n].reshape(n, 6)[:, :3], now)]
    assert len(found) == 1, "the line's nodes are not one block of MoorDyn's state"
    block = state[found[0]:found[0] + 6 * n].reshape(n, 6)
    block[:, :3], block[:, 3:] = x[1:-1], 0.0
    moordyn.Deserialize(system, state.tobytes())


def run_from(moordyn, path, x0, duration, coupling, point, every=0.1):
    """MoorDyn-C (its RK2, 0.5 ms) from ``x0`` at rest, its fairlead at ``point(t)`` moved at its mean velocity
    over each ``coupling`` step: rows ``(t, fairlead tension)`` and the node positions every ``every`` s,
    and its own initial state."""
    def start(system):
        line = moordyn.GetLine(system, 1)
        own = nodes(moordyn, line)
        start_from(moordyn, system, line, x0)
        return own

    def record(system):
        line = moordyn.GetLine(system, 1)
        return [moordyn.GetLineFairTen(line), *nodes(moordyn, line).ravel()]
    own, rows = run_moordyn(moordyn, path, duration, coupling, record, int(round(every / coupling)),
                            point=point, at_start=start)
    return rows[:, :2], rows[:, 2:].reshape(len(rows), SEGMENTS + 1, 3), own


@pytest.mark.parametrize("stiffness", [2e6, 2e7])
def test_moordyn_holds_the_equilibrium_kanat_finds_for_a_line_with_bending(tmp_path, stiffness):
    """kanat's equilibrium, written into MoorDyn's state, held still for 20 s: MoorDyn's nodes move less
    than 2 cm (measured 0.7 cm at EI 2e6, 1.3 cm at 2e7) and its top tension stays within 0.1 % of
    kanat's (kanat's is the top element's, MoorDyn's the fairlead node's), where MoorDyn's own start
    lies 1.2 m and 5.5 m away and a line without EI would lie 0.9 m and 3.7 m away."""
    moordyn = pytest.importorskip("moordyn")
    path = tmp_path / "jumper.dat"
    path.write_text(jumper_file(stiffness, SEGMENTS))
    case = kanat_case(path, 1.0, motion=False)
    model = LumpedModel(case)
    x = starting_state(model.net, case, model.system)[0][model.net.node_index]
    flexible = kanat_case(path, 1.0, motion=False).replace({"line_types.flex.bending_stiffness": 0.0})
    plain = LumpedModel(flexible)
    x_flexible = starting_state(plain.net, flexible, plain.system)[0][plain.net.node_index]
    rows, shapes, own = run_from(moordyn, path, x, 20.0, 0.1, lambda t: np.array([0.0, 0.0, -5.0]), every=5.0)
    drift = np.abs(shapes - x).max()
    assert drift < 0.02
    bent = np.abs(x - x_flexible).max()
    assert np.abs(own - x).max() > 0.5 * bent > 20 * drift         # MoorDyn's own start is off by metres
    with quiet():
        ds = api.run(case, scheme="rk4").dataset
    top = ds.segment_tension.values[0, -1]
    assert rows[-1, 1] == pytest.approx(top, rel=1e-3)


def test_a_driven_line_with_bending_moves_as_moordyn_s(tmp_path):
    """EI 2e6 N m^2, the fairlead surging 10 m in 27 s from rest, both codes from kanat's equilibrium,
    54 s; MoorDyn coupled every 2 ms (tests/lumped/test_lumped_driven.py's jumper). Top tension over the second
    period: mean within 1 %, range and maximum within 3 %; the middle node's path within 0.5 % of its
    excursion at every output (0.1 s). Measured (the default scheme): mean -0.02 %, range +0.60 %,
    maximum +0.04 % (42.1 kN, range 10.4 kN); every node within 1.0 cm of MoorDyn's all along, the
    middle one's excursion 6.9 m. The line stays taut (8 kN at least); at EI 2e7 its sag goes slack
    from 17 s (the beam would carry compression there, which neither code's elements take), the two
    codes part there by up to 0.6 m, and kanat's run snaps (107 kN) at 31.6 s where MoorDyn's does not
    (docs/lumped.md)."""
    moordyn = pytest.importorskip("moordyn")
    path = tmp_path / "jumper.dat"
    path.write_text(jumper_file(2e6, SEGMENTS))
    duration = 2 * PERIOD
    case = kanat_case(path, duration, motion=True)
    model = LumpedModel(case)
    x0 = starting_state(model.net, case, model.system)[0][model.net.node_index]
    theirs, shapes, _ = run_from(moordyn, path, x0, duration, 0.002, surge)
    with quiet():
        ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    t = np.round(ds.time.values, 6)
    ours = ds.segment_tension.values[:, -1]
    late = t >= PERIOD - 1e-9
    mine, ref = ours[late], theirs[np.round(theirs[:, 0], 6) >= PERIOD - 1e-9, 1]
    assert mine.mean() == pytest.approx(ref.mean(), rel=1e-2)
    assert np.ptp(mine) == pytest.approx(np.ptp(ref), rel=3e-2)
    assert mine.max() == pytest.approx(ref.max(), rel=3e-2)
    path_ours = ds.position.values[np.isin(t, np.round(theirs[:, 0], 6)), MIDDLE]
    path_theirs = shapes[:, MIDDLE]
    excursion = np.ptp(path_theirs, axis=0).max()
    assert excursion > 5.0
    assert np.abs(path_ours - path_theirs).max() < 0.005 * excursion


def test_a_line_with_bending_whose_sag_goes_slack_says_so(tmp_path):
    """The driven jumper at EI 2e7 N m^2 (20 s): its sag goes slack at 17 s, where the two codes part
    (the driven test's docstring); the run says so in its notes, where the taut EI 2e6 line's does not."""
    notes = {}
    for stiffness in (2e6, 2e7):
        path = tmp_path / f"jumper_{stiffness:g}.dat"
        path.write_text(jumper_file(stiffness, SEGMENTS))
        with quiet():
            ds = api.run(kanat_case(path, 20.0, motion=True), scheme="rk4").dataset
        slack = ds.segment_tension.values.min()
        notes[stiffness] = ("went slack" in ds.attrs["notes"], slack)
    assert notes[2e6][0] is False and notes[2e6][1] > 5e3
    assert notes[2e7][0] is True and notes[2e7][1] == 0.0
