"""The storm benchmark (benchmarks/bench_storm_moordyn.py) feeds MoorDyn the motion kanat's vessel
points follow, so that the two codes are compared on the same motion.

Oracles:

* kanat's own run of the benchmark's case (RAO-driven fairleads in the JONSWAP storm): the
  recorded positions and velocities of the fairlead nodes are the benchmark's
  :func:`fairlead_motion` at the output times, to 1e-9 m and 1e-9 m/s; also with pitch, roll and
  yaw RAOs added, so that the fairleads' lever arms are exercised;
* MoorDyn-C itself, driven as the benchmark drives it: after each coupling step its coupled
  points are at the positions kanat's motion gives at that instant, to 1e-9 m, and its waves
  (``WaveKin 7`` from the benchmark's ``wave_frequencies.txt``) are kanat's sea, elevation and
  stretched kinematics to 1e-6 (1.7e-7 m seen; tests/physics/test_wave_stretching.py holds the two codes'
  WaveKin 7 seas to 1e-7).

The RAO table is the benchmark's closed-form cylinder: its long-wave limits are checked too
(surge amplitude 1 with phase 90 deg, the water particles' displacement, zero under the crest;
heave 1 in phase with the crest) and its heave lags its force by 90 deg at resonance.
"""
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from helpers import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
import bench_storm_moordyn as bench  # noqa: E402

from kanat.api import simulate  # noqa: E402
from kanat.io.case_file import load_case  # noqa: E402
from kanat.physics.waves import sea_from_model  # noqa: E402

DURATION, OUTPUT_DT, SEGMENTS = 0.5, 0.05, 6
MOORDYN_DT = 0.005     # s: MoorDyn's inner step here (the points' motion does not depend on it)
SEA_POINTS = [(20.0, 0.0, -8.0), (-10.0, 17.321, -2.0), (300.0, -100.0, -60.0)]    # m: where the seas are compared
ROTATIONS = [("roll", 1.5, 20.0), ("pitch", 2.0, -60.0), ("yaw", 0.8, 45.0)]     # deg/m, deg: a test table


def _case(tmp_path: Path, raos: Path):
    """The benchmark's case, short, with fewer segments per leg (the vessel's motion is the same)."""
    import yaml

    data = bench.case_dict(DURATION)
    data["simulation"]["output_dt"] = OUTPUT_DT
    data["vessel"]["motion"]["rao"] = str(raos)
    for cable in data["cables"]:
        cable.pop("segments", None)
        for section in cable.get("sections", ()):
            section["segments"] = SEGMENTS
    path = tmp_path / "storm.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return load_case(path)


def _with_rotations(tmp_path: Path) -> Path:
    """The benchmark's RAO table with roll, pitch and yaw rows added at every frequency and heading."""
    text = bench.RAOS.read_text().rstrip("\n").splitlines()
    keys = sorted({tuple(line.split(",")[:2]) for line in text if line and line[0].isdigit()})
    extra = [f"{w},{b},{dof},{amplitude},{phase}" for w, b in keys for dof, amplitude, phase in ROTATIONS]
    path = tmp_path / "raos_rotating.csv"
    path.write_text("\n".join(text + extra) + "\n")
    return path


def _fairlead_nodes(result) -> list[int]:
    """Indices of the vessel end (the last node) of each cable, in cable order."""
    cables = result.cable.values
    return [int(np.flatnonzero(cables == name)[-1]) for name in ("line1", "line2", "line3")]


@pytest.mark.parametrize("rotating", [False, True], ids=["benchmark_raos", "with_rotations"])
def test_fairlead_motion_is_kanats_vessel_point_motion(tmp_path, rotating):
    raos = _with_rotations(tmp_path) if rotating else bench.RAOS
    case = _case(tmp_path, raos)
    result = simulate(case)
    assert result.attrs["status"] == "ok", result.attrs["status"]
    nodes = _fairlead_nodes(result)
    times = result.time.values
    positions, velocities = bench.fairlead_motion(case, times)
    kanat_positions = result.position.values[:, nodes, :]
    kanat_velocities = result.velocity.values[:, nodes, :]
    assert np.abs(positions - kanat_positions).max() < 1e-9
    assert np.abs(velocities - kanat_velocities).max() < 1e-9
    moved = np.abs(positions - positions[:1]).max()
    assert moved > 0.01, moved                      # the storm moves the fairleads within the run
    if rotating:                                    # the lever arms turn the three fairleads differently
        assert np.abs(np.diff(positions[:, :, 2] - positions[:1, :, 2], axis=1)).max() > 1e-3


def test_moordyn_points_follow_kanats_motion(tmp_path):
    moordyn = pytest.importorskip("moordyn")
    case = _case(tmp_path, bench.RAOS)
    steps = 4
    positions, velocities = bench.moordyn_drive(case, steps * bench.COUPLING)
    expected, _ = bench.fairlead_motion(case, np.arange(steps + 1) * bench.COUPLING)
    assert np.abs(positions - expected.reshape(steps + 1, -1)).max() < 1e-12
    sea = sea_from_model(case.environment)
    system = moordyn.Create(str(bench.moordyn_file(tmp_path, case)))
    try:
        moordyn.SetDt(system, MOORDYN_DT)
        moordyn.Init(system, list(positions[0]), [0.0] * positions.shape[1])
        points = [moordyn.GetPoint(system, number) for number in (4, 5, 6)]
        waves = moordyn.GetWaves(system)
        for k in range(steps):
            t = k * bench.COUPLING
            for where in SEA_POINTS:                # the same sea: kanat's components, MoorDyn's WaveKin 7
                velocity, acceleration, elevation, _ = moordyn.GetWavesKin(waves, *where)
                point = np.array([where])
                assert abs(elevation - sea.elevation(point[:, 0], point[:, 1], t)[0]) < 1e-6
                assert np.abs(np.asarray(velocity) - sea.velocity(point, t)[0]).max() < 1e-6
                assert np.abs(np.asarray(acceleration) - sea.acceleration(point, t)[0]).max() < 1e-6
            moordyn.Step(system, list(positions[k]), list(velocities[k]), k * bench.COUPLING, bench.COUPLING)
            reached = np.concatenate([moordyn.GetPointPos(point) for point in points])
            assert np.abs(reached - expected[k + 1].ravel()).max() < 1e-9, k
    finally:
        moordyn.Close(system)


def test_cylinder_raos_long_wave_limits():
    rows = bench.cylinder_raos([1e-3], [0.0, 90.0])
    by = {(b, dof): (amplitude, phase) for _, b, dof, amplitude, phase in rows}
    assert by[(0.0, "surge")][0] == pytest.approx(1.0, abs=1e-6)
    assert by[(0.0, "surge")][1] == pytest.approx(90.0)
    assert by[(90.0, "sway")][0] == pytest.approx(1.0, abs=1e-6)
    assert by[(90.0, "surge")][0] == pytest.approx(0.0, abs=1e-9)
    assert by[(0.0, "heave")][0] == pytest.approx(1.0, abs=1e-5)
    assert by[(0.0, "heave")][1] == pytest.approx(0.0, abs=1e-3)
    natural = math.sqrt(bench.RHO * bench.G * math.pi * bench.RADIUS**2 / (
        bench.RHO * math.pi * bench.RADIUS**2 * bench.DRAFT + 4 / 3 * bench.RHO * bench.RADIUS**3))
    at_resonance = bench.cylinder_raos([natural], [0.0])
    assert at_resonance[2][4] == pytest.approx(90.0, abs=1e-9)    # heave lags the force by 90 deg
