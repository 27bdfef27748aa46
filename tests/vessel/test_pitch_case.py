"""The pitch case end to end: case file -> kanat.api.run -> result file and figures
(case-format.md: ``pitch(mode, time)``, ``stabilizer_moment(mode, time)``,
``amplitude(mode)``, ``max_abs(mode)``)."""
import math
from pathlib import Path

import numpy as np
import pytest

import yaml

from kanat.errors import CaseError, KanatError
from kanat.model import Case
from kanat.io import check_case, load_case, parse_case
from kanat.io.results import read_result
from kanat.report.pitch_plot import FILES
from kanat.vessel.pitch import ResonanceError

from helpers import EXAMPLES


def run_pitch_case(case, output, plot_dir=None):
    """What ``kanat pitch CASE -o OUTPUT --plot DIR`` does: the result, the table, the figures."""
    from kanat import api
    from kanat.report.pitch_plot import plot_pitch_case
    from kanat.studies.pitch import figure_data

    outcome = api.run(case, output=output, model="pitch")
    if plot_dir is not None:
        plot_pitch_case(outcome.solution, figure_data(outcome.solution), Path(plot_dir))
    return outcome.dataset, outcome.text

EXAMPLE = EXAMPLES / "pitch_stabilizer.yaml"


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    out = tmp_path_factory.mktemp("pitch")
    ds, table = run_pitch_case(load_case(EXAMPLE), out / "pitch.nc", out / "figs")
    return out, ds, table


def test_example_is_valid_without_warnings():
    assert check_case(EXAMPLE) == []


@pytest.mark.slow
def test_result_file_has_the_case_format_names(ran):
    out, _, _ = ran
    back = read_result(out / "pitch.nc")
    modes = ["off", "sinusoidal", "rectangular", "feedback", "optimal"]
    assert list(back["mode"].values) == modes
    assert back["pitch"].dims == ("mode", "time") and back["stabilizer_moment"].dims == ("mode", "time")
    assert back["amplitude"].dims == ("mode",) and back["max_abs"].dims == ("mode",)
    assert back["pitch"].attrs["units"] == "rad" and back["stabilizer_moment"].attrs["units"] == "N m"
    assert back["time"].attrs["units"] == "s"
    assert back["time"].values[0] == 0.0 and back["time"].values[-1] == pytest.approx(10.0)
    assert back.attrs["status"] == "ok" and back.attrs["model"] == "pitch"
    assert back.attrs["case_name"] == "pitch-stabilizer" and back.attrs["harmonics"] == 50
    pitch = back["pitch"].values
    np.testing.assert_allclose(back["amplitude"].values, 0.5 * np.ptp(pitch, axis=1))
    np.testing.assert_allclose(back["max_abs"].values, np.abs(pitch).max(axis=1))
    np.testing.assert_allclose(pitch[:, 0], pitch[:, -1], atol=1e-9)        # one steady period
    agreement = back["fourier_vs_shooting"].sel(mode=["off", "sinusoidal", "rectangular", "optimal"])
    assert (agreement.values < 1e-3).all() and np.isnan(back["fourier_vs_shooting"].sel(mode="feedback"))
    assert back.attrs["method_feedback"] == "shooting"


@pytest.mark.slow
def test_nan_for_not_applicable_says_so_in_the_attributes(ran, tmp_path):
    out, _, _ = ran
    back = read_result(out / "pitch.nc")
    check = back["fourier_vs_shooting"].attrs
    assert check["not_applicable_modes"] == "feedback" and check["comment"].startswith("NaN means not applicable")
    assert "comment" not in back["amplitude_reduction"].attrs           # every mode has its reduction
    text = EXAMPLE.read_text().replace("modes: [off, sinusoidal, rectangular, feedback, optimal]",
                                       "modes: [sinusoidal, feedback]")
    ds, _ = run_pitch_case(parse_case(text), tmp_path / "no_off.nc")
    for name in ("amplitude_reduction", "max_abs_reduction"):
        assert np.isnan(ds[name].values).all()
        assert ds[name].attrs["not_applicable_modes"] == "sinusoidal, feedback"
        assert "'off', which was not among the modes solved" in ds[name].attrs["comment"]


@pytest.mark.slow
def test_figures_and_table(ran):
    out, _, table = ran
    for name in FILES.values():
        assert (out / "figs" / name).stat().st_size > 30_000
    for mode in ("off", "sinusoidal", "rectangular", "feedback", "optimal"):
        assert f"\n{mode} " in table
    assert "3.17" in table and "11.2" in table


def test_resonance_is_refused_by_the_loader_and_the_solver_alike(tmp_path):
    near = 2 * math.pi / 10 * (1 + 5e-4)       # within the solver's 0.1 % guard, no damping
    text = EXAMPLE.read_text().replace("natural_frequency: 0.876", f"natural_frequency: {near!r}")
    with pytest.raises(CaseError, match="within 0.1 % of the natural frequency"):
        parse_case(text)
    case = Case.model_validate(yaml.safe_load(text), context={})    # skips the loader's checks
    with pytest.raises(ResonanceError, match="harmonic n = 1"):
        run_pitch_case(case, tmp_path / "bad.nc")
    assert read_result(tmp_path / "bad.nc").attrs["status"].startswith("failed: harmonic n = 1")


def test_a_case_without_pitch_block_is_refused(tmp_path):
    case = load_case(EXAMPLE.parent / "sphere_two_cables.yaml")
    with pytest.raises(KanatError, match="has no 'pitch' block; the pitch model solves model: pitch"):
        run_pitch_case(case, tmp_path / "none.nc")


def test_yaml_off_is_the_mode_off():
    text = EXAMPLE.read_text().replace("mode: rectangular", "mode: off")
    assert parse_case(text).pitch.stabilizer.mode == "off"
    assert parse_case(text).pitch.modes[0] == "off"


def test_plot_to_a_png_file_puts_fig2_there_and_the_rest_beside(tmp_path):
    from kanat.report.pitch_plot import figure_paths

    paths = figure_paths(tmp_path / "out.png")
    assert paths["period"] == tmp_path / "out.png"
    assert paths["sinusoidal"] == tmp_path / "out_fig3_sinusoidal.png"
    assert figure_paths(tmp_path)["band"] == tmp_path / "pitch_omega0_band.png"


@pytest.mark.slow
def test_kanat_study_pitch_writes_the_scan_that_passes_through_the_solved_modes(ran, tmp_path):
    """``kanat study pitch``: the omega_0 scan, read back from scan.csv and interpolated at the
    case's omega_0 = 0.876 rad/s, gives the amplitudes of the modes solved on their own (the
    result file's), within the scan's grid error; the five figures are written beside it."""
    from typer.testing import CliRunner

    from kanat.cli import app

    result = CliRunner().invoke(app, ["study", "pitch", str(EXAMPLE), "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    table = np.genfromtxt(tmp_path / "scan.csv", delimiter=",", names=True)
    assert len(table) == 701
    _, ds, _ = ran
    for mode in ("off", "sinusoidal", "rectangular"):
        scanned = np.interp(0.876, table["omega0_rad_s"], table[f"amplitude_{mode}_rad"])
        solved = float(ds.amplitude.sel(mode=mode))
        assert scanned == pytest.approx(solved, rel=2e-3), mode
    assert sorted(p.name for p in tmp_path.glob("*.png")) == sorted(FILES.values())
    assert "more than halves the amplitude" in result.output
