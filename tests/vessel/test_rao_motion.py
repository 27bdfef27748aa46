"""Vessel motion from displacement RAOs (``vessel.motion: {rao: FILE}``), checked by hand:

* one regular wave between two tabulated headings: every degree of freedom is the RAO
  (interpolated as a complex number) times the wave amplitude with the RAO's phase, and a
  fairlead off the centreline follows with its lever arm (pitch turns it by hand-written
  rotation matrices here, not the code's);
* a WAMIT ``.4`` and a Capytaine dataset give the motion their own conventions define
  (``Re(xi A e^{i omega t})``, ``Re(X A e^{-i omega t})``), rotations scaled by ULEN;
* a lumped run driven by RAOs is the run driven by the same motion written as harmonics;
* bad files and a moving vessel are refused, naming file, line and key.
"""
import math

import numpy as np
import pytest
import xarray as xr

from helpers import run
from kanat.errors import CaseError
from kanat.io.case_file import load_case
from kanat.io.results import read_result
from kanat.physics.motion import compile_motion, motion_at, rigid_point_motion

HEIGHT, PERIOD, HEADING = 3.0, 10.0, 30.0
OMEGA = 2 * math.pi / PERIOD
TABLE = """omega,heading_deg,dof,amplitude,phase_deg
0.3,0,surge,0.9,10
{w},0,surge,0.5,40
1.5,0,surge,0.1,80
0.3,90,surge,0.1,20
{w},90,surge,0.2,-30
1.5,90,surge,0.0,0
0.3,0,heave,1.0,0
{w},0,heave,0.8,-20
1.5,0,heave,0.1,-90
0.3,90,heave,1.0,0
{w},90,heave,1.1,15
1.5,90,heave,0.2,-90
0.3,0,pitch,0.5,90
{w},0,pitch,1.5,100
1.5,0,pitch,0.1,120
0.3,90,pitch,0.1,90
{w},90,pitch,0.3,60
1.5,90,pitch,0.0,0
""".format(w=OMEGA)


def case_yaml(motion, model="lumped", track="", waves=None):
    waves = waves or f"{{type: regular, height: {HEIGHT}, period: {PERIOD}, heading_deg: {HEADING}}}"
    return f"""
name: rao
model: {model}
environment: {{depth: 100, seabed: {{}}, waves: {waves}}}
line_types:
  chain: {{diameter: 0.1, mass: 60, axial_stiffness: 5.0e8}}
vessel:
  motion: {motion}
{track}
cables:
  - {{name: leg, line_type: chain, length: 300, segments: 20,
     from: "anchor:[280, 0, -100]", to: {{vessel: [10, 5, -2]}}}}
simulation: {{duration: 4.0, dt: 0.01, output_dt: 0.5}}
"""


def write_case(tmp_path, text, name="case.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def by_hand(t):
    """Surge, heave, pitch [m, m, rad] at ``t``: RAOs at omega, 1/3 of the way from 0 to 90 deg."""
    def z(at0, at90):
        return (2 / 3) * at0[0] * np.exp(1j * math.radians(at0[1])) + (1 / 3) * at90[0] * np.exp(1j * math.radians(at90[1]))
    a = HEIGHT / 2
    surge, heave, pitch = z((0.5, 40), (0.2, -30)), z((0.8, -20), (1.1, 15)), math.radians(1) * z((1.5, 100), (0.3, 60))
    return [abs(r) * a * math.cos(OMEGA * t - np.angle(r)) for r in (surge, heave, pitch)]


def test_a_regular_wave_moves_every_dof_and_fairlead_by_the_interpolated_rao(tmp_path):
    (tmp_path / "raos.csv").write_text(TABLE)
    case = load_case(write_case(tmp_path, case_yaml("{rao: raos.csv}")))
    motion = compile_motion(case.vessel.motion, case.environment)
    arm = np.array([10.0, 5.0, -2.0])
    for t in np.linspace(0.0, PERIOD, 7):
        q, v = motion_at(motion, t)
        surge, heave, pitch = by_hand(t)
        np.testing.assert_allclose(q, [surge, 0, heave, 0, pitch, 0], atol=1e-12)
        c, s = math.cos(pitch), math.sin(pitch)
        turned = np.array([c * arm[0] + s * arm[2], arm[1], -s * arm[0] + c * arm[2]])    # Ry(pitch) arm
        displacement, _ = rigid_point_motion(arm, q, v)
        np.testing.assert_allclose(displacement, [surge, 0, heave] + turned - arm, atol=1e-12)
        dt = 1e-6                                                    # velocity: the displacement's slope
        ahead = np.array(by_hand(t + dt)) - np.array(by_hand(t - dt))
        np.testing.assert_allclose(v[[0, 2, 4]], ahead / (2 * dt), rtol=1e-6, atol=1e-9)


def test_wamit_and_capytaine_files_follow_their_own_conventions(tmp_path):
    a, ulen = HEIGHT / 2, 2.0
    xi = {1: 0.4 * np.exp(0.3j), 3: 0.9 * np.exp(-0.7j), 5: 0.05 * np.exp(1.1j)}   # per metre (rotation: xi L / A)
    lines = [f"{PERIOD:.6f} {h:.1f} {mode} {abs(x):.9e} {math.degrees(np.angle(x)):.9e} {x.real:.9e} {x.imag:.9e}"
             for h in (0.0, 90.0) for mode, x in xi.items()]
    lines += [f"{p:.6f} {h:.1f} {mode} {abs(x):.9e} {math.degrees(np.angle(x)):.9e} 0 0"
              for p in (5.0, 20.0) for h in (0.0, 90.0) for mode, x in xi.items()]
    (tmp_path / "ship.4").write_text("\n".join(["-1.0 0.0 1 0 0 0 0", *lines]) + "\n")
    case = load_case(write_case(tmp_path, case_yaml(f"{{rao: ship.4, ulen: {ulen}}}")))
    q, _ = motion_at(compile_motion(case.vessel.motion, case.environment), 1.7)
    wamit = {mode: (x * a * np.exp(1j * OMEGA * 1.7)).real for mode, x in xi.items()}
    np.testing.assert_allclose(q[[0, 2, 4]], [wamit[1], wamit[3], wamit[5] / ulen], rtol=1e-8)

    X = np.array([0.4 * np.exp(0.3j), 0.9 * np.exp(-0.7j), 0.05 * np.exp(1.1j)])       # rad/m for pitch
    rao = np.broadcast_to(X, (3, 2, 3))
    ds = xr.Dataset({"RAO": (("omega", "wave_direction", "radiating_dof", "complex"),
                             np.stack([rao.real, rao.imag], axis=-1))},
                    coords={"omega": [0.2, OMEGA, 2.0], "wave_direction": [0.0, math.pi / 2],
                            "radiating_dof": ["Surge", "Heave", "Pitch"], "complex": ["re", "im"]})
    ds.to_netcdf(tmp_path / "ship.nc")
    case = load_case(write_case(tmp_path, case_yaml("{rao: ship.nc}")))
    q, _ = motion_at(compile_motion(case.vessel.motion, case.environment), 1.7)
    np.testing.assert_allclose(q[[0, 2, 4]], (X * a * np.exp(-1j * OMEGA * 1.7)).real, rtol=1e-8)


@pytest.mark.slow
def test_a_run_driven_by_raos_is_the_run_driven_by_the_same_harmonics(tmp_path):
    (tmp_path / "raos.csv").write_text(TABLE)
    a = HEIGHT / 2
    harmonics = []
    for name, (at0, at90) in {"surge": ((0.5, 40), (0.2, -30)), "heave": ((0.8, -20), (1.1, 15)),
                              "pitch": ((1.5, 100), (0.3, 60))}.items():
        z = (2 / 3) * at0[0] * np.exp(1j * math.radians(at0[1])) + (1 / 3) * at90[0] * np.exp(1j * math.radians(at90[1]))
        # A cos(w t - arg z) = A sin(w t + 90 deg - arg z)
        harmonics.append(f"{{dof: {name}, amplitude: {float(abs(z) * a)!r}, period: {PERIOD}, "
                         f"phase_deg: {float(90 - math.degrees(np.angle(z)))!r}}}")
    results = {}
    for label, motion in (("rao", "{rao: raos.csv, ramp: 2.0}"), ("harmonics", f"{{harmonics: [{', '.join(harmonics)}], ramp: 2.0}}")):
        run(load_case(write_case(tmp_path, case_yaml(motion), f"{label}.yaml")), tmp_path / f"{label}.nc")
        results[label] = read_result(tmp_path / f"{label}.nc")
    assert results["rao"].attrs["status"] == "ok"
    np.testing.assert_allclose(results["rao"]["tension"].values, results["harmonics"]["tension"].values,
                               rtol=1e-9)


def test_a_jonswap_sea_beyond_the_table_warns_of_the_share_it_leaves_out(tmp_path):
    (tmp_path / "raos.csv").write_text(TABLE)
    waves = "{type: jonswap, hs: 2.0, tp: 8.0, heading_deg: 0.0, seed: 3}"
    case = load_case(write_case(tmp_path, case_yaml("{rao: raos.csv}", waves=waves)))
    with pytest.warns(UserWarning, match="% of the sea's variance lies at frequencies outside"):
        compile_motion(case.vessel.motion, case.environment)


@pytest.mark.parametrize("table, message", [
    ("omega,heading_deg,dof,amplitude\n0.5,0,surge,1\n", "lacks the column(s) phase_deg"),
    ("omega,heading_deg,dof,amplitude,phase_deg\n0.5,0,surge,1,0\n0.6,0,bob,1,0\n",
     "raos.csv, line 3, column dof: 'bob' is not one of surge"),
    ("omega,heading_deg,dof,amplitude,phase_deg\n0.5,0,surge,x1,0\n", "line 2, column amplitude: 'x1' is not a number"),
])
def test_a_bad_rao_file_is_refused_naming_its_line_and_column(tmp_path, table, message):
    (tmp_path / "raos.csv").write_text(table)
    with pytest.raises(CaseError, match="vessel.motion.rao") as error:
        load_case(write_case(tmp_path, case_yaml("{rao: raos.csv}")))
    assert message in str(error.value)
    assert "case.yaml:8: error: vessel.motion.rao: " in str(error.value)


def test_raos_on_a_moving_vessel_are_refused(tmp_path):
    (tmp_path / "raos.csv").write_text(TABLE)
    track = "  track: [{straight: {speed: 2.0, duration: 10.0}}]"
    with pytest.raises(CaseError, match="zero forward speed"):
        load_case(write_case(tmp_path, case_yaml("{rao: raos.csv}", track=track)))


def test_a_sea_along_a_table_heading_takes_that_headings_raos_whatever_the_gaps():
    """RAOs given at 0 and 90 deg only (a 270 deg gap beyond 90): a sea travelling at exactly
    90 deg takes the 90 deg column (it was refused: the gap past the last heading was chosen);
    one at 45 deg interpolates halfway; one at 180 deg, inside the gap, is still refused."""
    from kanat.errors import KanatError
    from kanat.physics.rao import _along_heading

    values = np.array([[1.0, 3.0], [2.0, 6.0]])                # (frequencies, headings)
    headings = np.array([0.0, 90.0])
    np.testing.assert_array_equal(_along_heading(headings, values, 90.0, "surge"), [3.0, 6.0])
    np.testing.assert_array_equal(_along_heading(headings, values, 360.0, "surge"), [1.0, 2.0])
    np.testing.assert_allclose(_along_heading(headings, values, 45.0, "surge"), [2.0, 4.0], rtol=1e-15)
    with pytest.raises(KanatError, match="270 deg gap"):
        _along_heading(headings, values, 180.0, "surge")
