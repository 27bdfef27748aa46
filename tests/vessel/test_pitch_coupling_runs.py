"""The stabilizer seen by the cable: coupled continuum runs (issue 6.5, theory/vessel.md §2).

Oracles and measured findings on the 6 kn example, shortened to 200 s (transient 60 s,
14 wave periods). Without a stabilizer, the top tension oscillates at the wave frequency.
A stabilizer that cuts the pitch amplitude also cuts the tow point's vertical velocity.
Kinematics fix the ratio: it equals the pitch-rate ratio, and for the fundamental it equals
the amplitude ratio. It cuts the top-tension range too (assert what we measure: see
docs/pitch.md). ``kanat run`` writes the solver's pitch as ``vessel_pitch``.
"""
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from kanat.cli import app
from kanat.errors import KanatError
from kanat.io import load_case
from kanat.io.results import read_result
from kanat.model import PitchModel
from kanat.report.coupled_plot import plot_coupled
from kanat.studies.pitch_tow import compare_modes, with_stabilizer_mode
from kanat.vessel.pitch import solve_pitch
from kanat.vessel.track import VesselTrack

from helpers import EXAMPLES

EXAMPLE_PATH = EXAMPLES / "pitch_tow_6kn.yaml"
EXAMPLE = load_case(EXAMPLE_PATH)
MODES = ("off", "sinusoidal", "rectangular")
TRANSIENT = 60.0


def shortened(duration):
    return EXAMPLE.model_copy(update={"simulation": EXAMPLE.simulation.model_copy(update={"duration": duration})})


@pytest.fixture(scope="module")
def coupled(tmp_path_factory):
    out = tmp_path_factory.mktemp("coupled")
    comparison, _ = compare_modes(shortened(200.0), out, MODES, transient=TRANSIENT)
    plot_coupled(read_result(out / "summary.nc"), out / "coupled.png")
    return comparison.table(), read_result(out / "summary.nc"), out


def of(summary, name, mode):
    return float(summary[name].sel(mode=mode))


@pytest.mark.slow
def test_compare_modes_writes_a_result_per_mode_a_summary_a_figure_and_a_table(coupled):
    table, summary, out = coupled
    assert [str(m) for m in summary["mode"].values] == list(MODES)
    assert all((out / f"{mode}.nc").exists() for mode in MODES)
    assert (out / "coupled.png").stat().st_size > 20_000
    assert (summary.attrs["window_start_s"], summary.attrs["window_end_s"]) == (60.0, 200.0)
    assert list(summary["status"].values) == ["ok"] * 3
    for mode in MODES:
        assert mode in table
    assert "below 5 % of its mean" in table


@pytest.mark.slow
def test_without_stabilizer_the_top_tension_oscillates_at_the_wave_period(coupled):
    _, summary, _ = coupled
    time = summary["time"].values
    inside = time >= TRANSIENT
    tension = summary["top_tension"].sel(mode="off").values[inside]
    spectrum = np.abs(np.fft.rfft(tension - tension.mean()))
    freq = np.fft.rfftfreq(len(tension), time[1] - time[0])
    resolution = 1.0 / (time[inside][-1] - time[inside][0])
    assert abs(freq[np.argmax(spectrum)] - 0.1) <= resolution


def fundamental(values):
    """Amplitude of the first harmonic of one period of samples (both ends included)."""
    return 2.0 * abs(np.fft.rfft(values[:-1])[1]) / (len(values) - 1)


@pytest.mark.parametrize("mode", ["sinusoidal", "rectangular", "feedback", "optimal"])
def test_the_tow_point_vertical_velocity_follows_the_pitch_kinematically(mode):
    def motion(m):
        track = VesselTrack.from_model(with_stabilizer_mode(EXAMPLE, m).vessel)
        t = np.linspace(0.0, 10.0, 801)
        return track.pitch.evaluate(t), np.array([track.state(s).velocity[2] for s in t])

    (off_angle, off_rate, _), off_w = motion("off")
    (angle, rate, _), w = motion(mode)
    amplitude_ratio = np.ptp(off_angle) / np.ptp(angle)
    # the fundamental of w is cut by the fundamental's ratio, to O(phi): w = (x cos phi - z sin phi) phi'
    assert fundamental(off_w) / fundamental(w) == pytest.approx(fundamental(off_angle) / fundamental(angle),
                                                                rel=5e-3)
    # the range of w follows the range of the pitch rate, not the pitch amplitude
    assert np.ptp(off_w) / np.ptp(w) == pytest.approx(np.ptp(off_rate) / np.ptp(rate), rel=1e-2)
    assert np.ptp(off_w) / np.ptp(w) <= amplitude_ratio * 1.01   # the harmonics keep w up


MEASURED_RANGE_REDUCTION = {"sinusoidal": (1.5, 1.9), "rectangular": (2.1, 2.7)}   # 6 kn: 1.69, 2.39


@pytest.mark.slow
@pytest.mark.parametrize("mode", ["sinusoidal", "rectangular"])
def test_a_stabilizer_that_cuts_the_pitch_cuts_the_top_tension_range(coupled, mode):
    _, summary, _ = coupled
    low, high = MEASURED_RANGE_REDUCTION[mode]
    tension_ratio = of(summary, "top_tension_range", "off") / of(summary, "top_tension_range", mode)
    velocity_ratio = (of(summary, "tow_point_vertical_velocity_range", "off")
                      / of(summary, "tow_point_vertical_velocity_range", mode))
    assert of(summary, "pitch_amplitude", "off") / of(summary, "pitch_amplitude", mode) > 3.0
    assert low < tension_ratio < high
    assert tension_ratio < velocity_ratio              # cut less than the tow point's w range
    assert of(summary, "top_tension_std", mode) < 0.6 * of(summary, "top_tension_std", "off")
    assert of(summary, "top_tension_mean", mode) == pytest.approx(of(summary, "top_tension_mean", "off"),
                                                                  rel=0.03)
    assert of(summary, "snap_events", mode) == of(summary, "snap_events", "off") == 0   # the heavy sled


def test_kanat_run_writes_the_pitch_solvers_response_as_vessel_pitch(tmp_path):
    out = tmp_path / "tow.nc"
    result = CliRunner().invoke(app, ["run", str(EXAMPLE_PATH), "-o", str(out)])
    assert result.exit_code == 0, result.output
    ds = read_result(out)
    pitch = EXAMPLE.vessel.pitch
    mode = pitch.stabilizer.mode
    response = solve_pitch(PitchModel(**pitch.model_dump(exclude={"phase_deg", "modes"})), modes=(mode,),
                           cross_check=False).responses[mode]
    period, step = pitch.wave_period, response.time[1]
    tau = (ds["time"].values + pitch.phase_deg / 360.0 * period) % period
    index = np.rint(tau / step).astype(int)
    assert np.allclose(index * step, tau, atol=1e-9)          # the outputs fall on the solver's samples
    assert np.max(np.abs(ds["vessel_pitch"].values - response.pitch[index])) < 1e-6 * response.amplitude
    assert ds["vessel_position"].values[0, 2] == pytest.approx(
        -60 * math.sin(response.pitch[index[0]]) + 5 * math.cos(response.pitch[index[0]]))


@pytest.mark.slow
def test_the_study_runs_as_a_command(tmp_path):
    result = CliRunner().invoke(app, ["study", "pitch-tow", str(EXAMPLE_PATH), "-o", str(tmp_path), "--mode", "off",
                                      "--transient", "0"])
    assert result.exit_code == 0, result.output
    assert "off" in result.output and (tmp_path / "summary.nc").exists() and (tmp_path / "coupled.png").exists()


def test_compare_modes_refuses_a_case_without_vessel_pitch(tmp_path):
    case = EXAMPLE.model_copy(update={"vessel": EXAMPLE.vessel.model_copy(update={"pitch": None})})
    with pytest.raises(KanatError, match="no vessel.pitch block"):
        compare_modes(case, tmp_path)


def test_lumped_tow_sees_the_vessel_pitch(tmp_path):
    """The lumped model's tow point rises and falls with the pitch (x sin(pitch) at the stern)."""
    import numpy as np

    from kanat.io import parse_case

    from helpers import run
    from kanat.io.results import read_result
    from kanat.vessel.pitch.motion import pitch_motion

    text = EXAMPLE_PATH.read_text().replace("model: continuum", "model: lumped")
    text = text.replace("segments: 100", "segments: 20")
    lines = [line for line in text.splitlines() if not line.strip().startswith(("scheme:", "duration:"))]
    text = "\n".join(lines).replace("simulation:", "simulation:\n  scheme: generalized-alpha-lumped\n  duration: 20")
    case = parse_case(text)
    summary = run(case, tmp_path / "r.nc")
    assert summary.status == "ok", summary.status
    ds = read_result(tmp_path / "r.nc")
    motion = pitch_motion(case.vessel.pitch)
    angle = np.array([motion(t)[0] for t in ds.time.values])
    arm = np.asarray(case.vessel.tow_point)
    expected = arm[0] * np.sin(angle) + arm[2] * np.cos(angle)
    np.testing.assert_allclose(ds.vessel_position.values[:, 2], expected, atol=1e-9)
    assert np.ptp(expected) > 0.5          # rectangular stabilizer: about 1 m of heave at the stern
