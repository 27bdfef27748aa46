"""A MoorDyn file brings its waves: ``WaveKin`` 2, 3 and 7 (and ``Currents 1``) imported from the
wave files beside it (:mod:`kanat.io.moordyn_waves`), checked against MoorDyn-C (PyPI ``moordyn``)
run on the same files.

* The translated sea (``stretching: wheeler``, as MoorDyn) against MoorDyn's own kinematics
  (``GetWavesKin``) at four points and eight times: WaveKin 7
  elevation, velocity and acceleration to 1e-8 m, m/s, m/s^2; WaveKin 2 and 3 (grid modes) at the
  grid's times: elevation to 1e-6 m, kinematics to 0.1 % of their largest value (MoorDyn
  interpolates them linearly on a 0.5 m grid in z). The WaveKin 7 component also against an
  independent sum (MoorDyn's documented ``|A| sin(omega t - k x + arg A)``, ``k`` by bisection).
* The example ``examples/moordyn/waves/taut_line_in_waves.dat`` (WaveKin 7: H 4 m, T 8 s along
  +x and 1 m, 12 s at 30 deg) run by ``kanat run`` and, slow, beside MoorDyn (RK2 at 1 ms; kanat
  RK4 at its safe step) over 48-72 s. Measured on 2026-11-28 with MoorDyn 2.7.2 (kanat with the
  importer's ``stretching: wheeler``):

  =============================  ==========  ==========  ========
  top tension                    kanat       MoorDyn     kanat vs
  =============================  ==========  ==========  ========
  mean                           155.565 kN  155.565 kN  +0.000 %
  range                          4115 N      4101 N      +0.35 %
  first harmonic (8 s)           1815 N      1808 N      +0.40 %
  component at 12 s              448.3 N     446.9 N     +0.31 %
  midpoint horizontal range      0.4365 m    0.4352 m    +0.31 %
  wave-induced mean              78.9 N      78.3 N      +0.78 %
  =============================  ==========  ==========  ========

  Tolerances: 0.05 % on the mean, 1 % on the rest. The wave-induced mean (0.05 % of the tension)
  is where Wheeler stretching shows: MoorDyn fed the same sea unstretched (``WaveKin 1``) gives
  119.8 N; kanat's stretched run is within 3 % of MoorDyn's own (asserted).
* The continuum model runs a one-row component sea as the regular wave it is (same tensions).
* Errors name the file, line and key: WaveKin 1 (set through MoorDyn's API), modes MoorDyn does
  not implement, missing and malformed wave files; Currents 1 is the current profile.
"""
import math
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from kanat import api
from kanat.cli import app
from kanat.errors import CaseError
from kanat.io import load_case
from kanat.io.moordyn import read_moordyn
from kanat.io.results import read_result
from kanat.physics.waves import component_sea, regular_wave, sea_from_model

import helpers_moordyn
from helpers import EXAMPLES, quiet

EXAMPLE = EXAMPLES / "moordyn" / "waves"
DEPTH = 100.0
G = 9.80665                                   # MoorDyn-C's gravity when the file gives none
LINE = """--------------------- MoorDyn Input File ------------------------------------------------
A short line to read a sea with.
---------------------- LINE TYPES -------------------------------------------------------
TypeName   Diam    Mass/m   EA        BA/-zeta   EI      Cd     Ca     CdAx   CaAx
(name)     (m)     (kg/m)   (N)       (N-s/-)    (N-m^2) (-)    (-)    (-)    (-)
taut       0.25    120.0    2.0e7     2.0e4      0       1.2    1.0    0.01   0.0
---------------------- POINTS -----------------------------------------------------------
ID   Attachment  X        Y         Z        Mass   Volume  CdA   Ca
(#)  (word)      (m)      (m)       (m)      (kg)   (m^3)   (m^2) (-)
1    Fixed       0.0      0.0       -100.0   0      0       0     0
2    Fixed       10.0     0.0       -10.0    0      0       0     0
---------------------- LINES ------------------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)     (#)      (#)      (m)       (-)      (-)
1    taut       1        2        90.6      4        -
---------------------- OPTIONS ----------------------------------------------------------
0.001      dtM          time step of the integration (s)
100.0      WtrDpth      water depth (m)
{options}---------------------- need this line ---------------------------------------------------
"""
FREQUENCIES_7 = "0.0 0 0\n0.5 0.3 0.4 0.3\n0.785398 1.0 -0.5 0.0\n1.1 -0.2 0.3 -1.0\n1.1 0.1 0.1 2.0\n"
GRID = "--- grid ---\nx y z\n\n1\n-20 0 5 13\n1\n-7 0 3 10\n2\n-100 0 201\n"
POINTS = np.array([[0.0, 0.0, -10.0], [5.0, 3.0, -30.0], [-20.0, 10.0, -60.0], [13.0, -7.0, -90.0]])


def frequencies_2() -> str:
    """An even spectrum 0-2 rad/s, directions 0.2 rad, zero at its highest (Nyquist) row."""
    rows = ["0.0 0 0"]
    for j in range(1, 20):
        w = 0.1 * j
        rows.append(f"{w:.1f} {0.5 * math.exp(-((w - 0.8) / 0.3) ** 2):.6f} {0.3 * math.sin(j):.6f} 0.2")
    return "\n".join(rows + ["2.0 0 0 0.2"]) + "\n"


def elevation_3() -> str:
    t = np.arange(2001) * 0.1                 # 200 s: MoorDyn resamples 400 values at 0.5 s
    w = 2 * math.pi / 200.0                   # whole periods over them: no mean level
    eta = 1.2 * np.cos(22 * w * t + 0.3) + 0.5 * np.sin(41 * w * t)
    return "".join(f"{a:.2f} {b:.6f}\n" for a, b in zip(t, eta))


MODES = {7: ("7 WaveKin\n", {"wave_frequencies.txt": FREQUENCIES_7}, 1.3),
         2: ("2 WaveKin\n", {"wave_frequencies.txt": frequencies_2(), "water_grid.txt": GRID}, math.pi / 2),
         3: ("3 WaveKin\n0.5 dtWave\n", {"wave_elevation.txt": elevation_3(), "water_grid.txt": GRID}, 0.5)}
"""WaveKin -> options, files, and a step that lands on MoorDyn's wave grid times (2: 2 pi / dw / nt)."""


def write(folder: Path, options: str, files: dict) -> Path:
    for name, text in files.items():
        (folder / name).write_text(text)
    path = folder / "line.dat"
    path.write_text(LINE.format(options=options))
    return path


def imported_sea(path: Path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return sea_from_model(load_case(path).environment)


@pytest.mark.parametrize("mode", sorted(MODES))
def test_the_imported_sea_is_moordyns(mode, tmp_path, moordyn):
    """kanat's stretched components against MoorDyn's GetWavesKin (module docstring)."""
    options, files, step = MODES[mode]
    path = write(tmp_path, options, files)
    sea = imported_sea(path)
    errors, scale = np.zeros(3), np.zeros(3)
    with quiet():
        system = moordyn.Create(str(path))
        moordyn.Init(system, [], [])
        waves = moordyn.GetWaves(system)
        for k in range(8):
            t = k * step
            for p in POINTS:
                u, a, eta, _ = moordyn.GetWavesKin(waves, *p)
                point = np.array([p])
                ours = (sea.elevation(p[:1], p[1:2], t)[0], sea.velocity(point, t)[0],
                        sea.acceleration(point, t)[0])
                for i, (mine, theirs) in enumerate(zip(ours, (eta, u, a))):
                    errors[i] = max(errors[i], np.max(np.abs(mine - np.asarray(theirs))))
                    scale[i] = max(scale[i], np.max(np.abs(theirs)))
            moordyn.Step(system, [], [], t, step)
        moordyn.Close(system)
    assert scale[0] > 1.0                                   # a real sea, not still water
    if mode == 7:
        assert np.all(errors < 1e-8)
    else:
        assert errors[0] < 1e-6
        assert np.all(errors[1:] < 1e-3 * scale[1:])


def test_a_component_is_moordyns_documented_sum(tmp_path):
    """One WaveKin 7 row against ``|A| sin(omega t - k (x cos b + y sin b) + arg A)`` with ``k`` from
    ``omega^2 = g k tanh(k h)`` by bisection, and its velocity ``|A| omega cosh/sinh`` profile at the
    Wheeler-stretched depth."""
    omega, re, im, beta = 0.9, -0.6, 0.8, 0.7
    path = write(tmp_path, "7 WaveKin\n", {"wave_frequencies.txt": f"0 0 0\n{omega} {re} {im} {beta}\n"})
    sea = imported_sea(path)
    low, high = 1e-6, 1.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if G * mid * math.tanh(mid * DEPTH) < omega**2 else (low, mid)
    k, amplitude = 0.5 * (low + high), abs(complex(re, im))
    for t in (0.0, 1.7, 4.2):
        for x, y, z in POINTS:
            theta = omega * t - k * (x * math.cos(beta) + y * math.sin(beta)) + math.atan2(im, re)
            assert sea.elevation(np.array([x]), np.array([y]), t)[0] == pytest.approx(
                amplitude * math.sin(theta), abs=1e-9)
            eta = amplitude * math.sin(theta)
            zs = DEPTH * (z + DEPTH) / (DEPTH + eta) - DEPTH          # Wheeler, as MoorDyn
            horizontal = amplitude * omega * math.cosh(k * (zs + DEPTH)) / math.sinh(k * DEPTH) * math.sin(theta)
            np.testing.assert_allclose(sea.velocity(np.array([[x, y, z]]), t)[0],
                                       [horizontal * math.cos(beta), horizontal * math.sin(beta),
                                        amplitude * omega * math.sinh(k * (zs + DEPTH)) / math.sinh(k * DEPTH)
                                        * math.cos(theta)], atol=1e-9)


def test_one_component_is_the_regular_wave():
    """``type: components`` with one row is kanat's regular wave of the same height and period."""
    ours = component_sea([[2 * math.pi / 8.0, 2.0, 0.0, 30.0]], depth=DEPTH)
    regular = regular_wave(4.0, 8.0, 30.0, depth=DEPTH)
    points = np.array([[3.0, -4.0, -20.0], [50.0, 10.0, -1.0]])
    for t in (0.0, 2.5):
        np.testing.assert_allclose(ours.velocity(points, t), regular.velocity(points, t), atol=1e-12)
        np.testing.assert_allclose(ours.acceleration(points, t), regular.acceleration(points, t), atol=1e-12)


def test_the_continuum_model_runs_a_component_sea_as_the_regular_wave():
    """The continuum model takes ``type: components``: one row equal to the example's regular wave
    gives the same tensions (4 s of examples/surface_mooring_waves.yaml)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(EXAMPLE.parents[1] / "surface_mooring_waves.yaml").replace({"simulation.duration": 4.0})
    waves = case.environment.waves
    row = [2 * math.pi / waves.period, waves.height / 2, 0.0, waves.heading_deg]
    same = case.replace({"environment.waves": {"type": "components", "components": [row]}})
    assert case.model == "continuum"
    ours, regular = api.run(same).dataset, api.run(case).dataset
    assert ours.attrs["status"] == regular.attrs["status"] == "ok"
    np.testing.assert_allclose(ours.tension.values, regular.tension.values, rtol=1e-12, atol=1e-9)


def problems(path: Path) -> list:
    imported = read_moordyn(path.read_text(), str(path))
    return imported, imported.problems


def only_error(path: Path):
    imported, found = problems(path)
    errors = [p for p in found if p.severity == "error"]
    assert imported.data is None and len(errors) == 1, found
    return errors[0]


def test_wavekin_1_is_refused_with_what_to_do(tmp_path):
    path = write(tmp_path, "1 WaveKin\n", {})
    error = only_error(path)
    assert (error.file, error.line, error.key) == (str(path), 19, "OPTIONS.WaveKin")
    assert "ExternalWaveKinSet" in error.message and "environment.waves" in error.message


@pytest.mark.parametrize("mode", [4, 5, 6, 9])
def test_modes_moordyn_does_not_implement_are_refused(mode, tmp_path):
    error = only_error(write(tmp_path, f"{mode} WaveKin\n", {}))
    assert f"WaveKin = {mode}" in error.message and "does not implement" in error.message


@pytest.mark.parametrize("files, file, line, words", [
    ({}, "wave_frequencies.txt", None, "not found"),
    ({"wave_frequencies.txt": "0 0 0\n0.5 0.3\n"}, "wave_frequencies.txt", 2, "2 values"),
    ({"wave_frequencies.txt": "0 0 0\n0.5 0.3 x\n"}, "wave_frequencies.txt", 2, "not a row of numbers"),
    ({"wave_frequencies.txt": "0.1 0 0\n0.5 0.3 0\n"}, "wave_frequencies.txt", 1, "first row at 0 rad/s"),
    ({"wave_frequencies.txt": "0 0 0\n0.5 0.3 0 7\n"}, "wave_frequencies.txt", 2, "radians"),
])
def test_a_bad_wave_file_is_named_with_its_line(files, file, line, words, tmp_path):
    error = only_error(write(tmp_path, "7 WaveKin\n", files))
    assert (error.file, error.line, error.key) == (str(tmp_path / file), line, "OPTIONS.WaveKin")
    assert words in error.message


def test_grid_modes_need_their_grid_and_say_where_it_ends(tmp_path):
    error = only_error(write(tmp_path, "2 WaveKin\n", {"wave_frequencies.txt": frequencies_2()}))
    assert error.file == str(tmp_path / "water_grid.txt") and "not found" in error.message
    narrow = GRID.replace("-20 0 5 13", "0")
    imported, found = problems(write(tmp_path, "2 WaveKin\n", {"water_grid.txt": narrow}))
    assert imported.data is not None
    assert any("x axis 0 to 0 m" in p.message and p.severity == "warning" for p in found)


def test_elevation_series_times_must_increase(tmp_path):
    files = {"wave_elevation.txt": "0 0\n1 0.5\n1 0.2\n", "water_grid.txt": GRID}
    error = only_error(write(tmp_path, "3 WaveKin\n", files))
    assert (error.file, error.line) == (str(tmp_path / "wave_elevation.txt"), 3)


def test_a_mean_level_and_dtwave_are_reported_not_dropped_silently(tmp_path):
    files = {"wave_frequencies.txt": "0 0 0.3\n0.8 1 0\n"}
    imported, found = problems(write(tmp_path, "7 WaveKin\n0.5 dtWave\n", files))
    notes = " | ".join(p.message for p in found if p.severity == "warning")
    assert "still water level by 0.3 m" in notes and "dtWave acts only with WaveKin 3" in notes
    assert imported.data["environment"]["waves"] == {"type": "components", "stretching": "wheeler",
                                                     "components": [[0.8, 1.0, 90.0, 0.0]]}


def test_currents_1_is_the_current_profile(tmp_path):
    profile = "--- current ---\nz ux uy uz\n(m) (m/s)\n-10.0 1.25 0 0\n-5 0.6\n0.0 0.0 0.1 0\n"
    path = write(tmp_path, "1 Currents\n", {"current_profile.txt": profile})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        current = load_case(path).environment.current
    np.testing.assert_allclose(current.at(-5.5), [0.665, 0.0, 0.0])
    np.testing.assert_allclose(current.at(-2.0), [0.24, 0.06, 0.0])
    error = only_error(write(tmp_path, "2 Currents\n", {}))
    assert error.key == "OPTIONS.Currents" and "Currents = 2" in error.message


@pytest.mark.parametrize("rows, words", [([[0.0, 1.0, 0.0, 0.0]], "omega 0 rad/s"),
                                         ([[0.5, -1.0, 0.0, 0.0]], "amplitude -1 m"),
                                         ([[0.5, 0.0, 0.0, 0.0]], "still water"),
                                         ([[0.5, 1.0, 0.0]], "4 numbers")])
def test_component_waves_are_validated(rows, words):
    base = load_case(EXAMPLE.parents[1] / "mooring_buoy_waves.yaml")
    with pytest.raises(CaseError, match=words):
        base.replace({"environment.waves": {"type": "components", "components": rows}})


def test_kanat_run_takes_the_example_with_its_wave_file(tmp_path):
    for item in EXAMPLE.iterdir():
        shutil.copy(item, tmp_path / item.name)
    short = tmp_path / "taut_line_in_waves.dat"
    short.write_text(short.read_text().replace("72.0       TMax", "2.0        TMax"))
    out = tmp_path / "out.nc"
    result = CliRunner().invoke(app, ["run", str(short), "-o", str(out)])
    assert result.exit_code == 0, result.output
    ds = read_result(out)
    assert ds.attrs["status"] == "ok" and ds.attrs["model"] == "lumped"
    written = tmp_path / "case.yaml"
    result = CliRunner().invoke(app, ["import", str(short), "-o", str(written)])
    assert result.exit_code == 0, result.output
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        again = load_case(written).environment.waves
    assert again.type == "components" and len(again.components) == 2


# --- side by side with MoorDyn (slow) ---------------------------------------------------------

PERIOD, DURATION, WINDOW, COUPLING, SAMPLE = 8.0, 72.0, 48.0, 0.02, 5
TOLERANCE = dict(mean=5e-4, range=0.01, harmonic=0.01, harmonic_12=0.01, midpoint=0.01)


def harmonic(t, values, period):
    return abs(2.0 * np.mean((values - values.mean()) * np.exp(-2j * math.pi * t / period)))


def statistics(still, rows):
    t = np.round(rows[:, 0], 6)
    w = rows[(t >= WINDOW) & (t < DURATION)]
    tension = w[:, 1]
    return dict(mean=tension.mean(), wave_mean=tension.mean() - still, range=np.ptp(tension),
                harmonic=harmonic(w[:, 0], tension, PERIOD), harmonic_12=harmonic(w[:, 0], tension, 12.0),
                midpoint=np.ptp(w[:, 2]))


def run_moordyn(path: Path, sea=None):
    """MoorDyn on ``path`` (RK2, 1 ms); with ``sea`` the file's WaveKin is 1 and the sea's
    kinematics are set at its nodes every coupling step, mid-step."""
    moordyn = pytest.importorskip("moordyn")
    record = helpers_moordyn.fairlead_tension(moordyn, node=20)
    still, rows = helpers_moordyn.run_moordyn(moordyn, path, DURATION, COUPLING, record, SAMPLE, sea=sea,
                                              scheme="RK2", dt=0.001, at_start=lambda system: record(system)[0])
    return statistics(still, rows)


@pytest.fixture(scope="module")
def side_by_side(tmp_path_factory):
    """Statistics of kanat, MoorDyn on the file, and MoorDyn fed the same sea unstretched."""
    pytest.importorskip("moordyn")
    folder = tmp_path_factory.mktemp("moordyn_wave_files")  # MoorDyn writes its outputs beside its input
    for item in EXAMPLE.iterdir():
        shutil.copy(item, folder / item.name)
    path = folder / "taut_line_in_waves.dat"
    with warnings.catch_warnings():               # a taut line between two fixed points is the point
        warnings.simplefilter("ignore")
        case = load_case(path).replace({"simulation.scheme": "rk4", "simulation.dt": None})
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    top = int(np.flatnonzero(ds.segment_cable.values == "line1")[-1])
    node = int(np.argmin(np.linalg.norm(ds.position.values[0] - np.array([5.0, 0.0, -55.0]), axis=1)))
    tension = ds.segment_tension.values[:, top]
    ours = statistics(tension[0], np.column_stack([ds.time.values, tension, ds.position.values[:, node, :]]))
    external = folder / "external.dat"
    external.write_text(path.read_text().replace("7          WaveKin", "1          WaveKin"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plain = sea_from_model(case.replace({"environment.waves.stretching": "none"}).environment)
    return ours, run_moordyn(path), run_moordyn(external, plain)


@pytest.mark.slow
@pytest.mark.parametrize("quantity", list(TOLERANCE))
def test_the_example_in_its_waves_agrees_with_moordyn(side_by_side, quantity):
    ours, theirs, _ = side_by_side
    assert ours[quantity] == pytest.approx(theirs[quantity], rel=TOLERANCE[quantity])


@pytest.mark.slow
def test_the_wave_induced_mean_is_moordyns_with_stretching(side_by_side):
    """kanat, stretched as MoorDyn (the importer's ``stretching: wheeler``), gives MoorDyn's
    wave-induced mean; MoorDyn fed the sea unstretched gives a mean far from both."""
    ours, stretched, unstretched = side_by_side
    assert ours["wave_mean"] == pytest.approx(stretched["wave_mean"], rel=0.03)
    assert stretched["wave_mean"] < 0.8 * unstretched["wave_mean"]
