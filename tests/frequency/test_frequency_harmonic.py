"""The frequency domain under harmonic fairlead motion (kanat.frequency.solve_frequency) against a
closed form, kanat's own time domain and MoorDyn side by side.

* A taut weightless bar driven along its axis at one end: ``T(x) = EA a k cos(k x) / sin(k L)``
  (``k = omega sqrt(m / EA)``, the bar's axial wave; the lumped chain's dispersion is second
  order in ``k l``).
* A chain catenary (300 m of 76 mm chain in 60 m of water, 20 segments, drag, seabed) and a taut
  polyester line, the fairlead surging 0.1 m in 10 s: tension amplitude and phase at every node
  against a harmonic fit of the steady state of kanat's time domain, and of MoorDyn-C (PyPI
  ``moordyn``, RK2 at 1 ms) on the same MoorDyn input file.
"""
import math
import warnings

import numpy as np
import pytest

import kanat
import kanat.errors
from kanat.model import Case

from helpers import harmonic_fit, quiet
from helpers_moordyn import node_tensions, run_moordyn

CHAIN_FILE = """--------------------- MoorDyn Input File ------------------------------------
A 300 m chain from an anchor 270 m away in 60 m of water to a fairlead 5 m down, no friction
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.0766  113.35     7.536e8    -1.0        0          2.0    1.0    0.4     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -270.0  0.0     -60.0   0      0       0      0
2     Vessel    0.0     0.0     -5.0    0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         300       20      -
---------------------- OPTIONS -----------------------------------------
0.001         dtM                  time step to use in mooring integration (s)
3.0e6         kBot                 bottom stiffness (Pa/m)
3.0e5         cBot                 bottom damping (Pa-s/m)
1025.0        WtrDnsty             water density (kg/m^3)
60            WtrDpth              water depth (m)
1.0           dtIC                 time interval for analyzing convergence during IC gen (s)
200.0         TmaxIC               max time for ic gen (s)
4.0           CdScaleIC            factor by which to scale drag coefficients during dynamic relaxation (-)
1.0e-4        threshIC             threshold for IC convergence (-)
0.0           FrictionCoefficient  general bottom friction coefficient (-)
------------------------- need this line --------------------------------------
"""
AMPLITUDE, PERIOD = 0.1, 10.0
OMEGA = 2.0 * math.pi / PERIOD


def surge(period=PERIOD):
    """The fairlead's surge ``-a cos(omega t)``."""
    return [{"dof": "surge", "amplitude": AMPLITUDE, "period": period, "phase_deg": -90.0}]


def bar(segments=20, amplitude=1e-3, omega=3.0, ea=1e5, mass=1.0, length=100.0, method="frequency", phase_deg=90.0,
        z=-50.0, dof="surge", environment=None):
    """A weightless line from an anchor at ``(0, 0, z)`` to a vessel point 0.1 % further, along x."""
    return Case.model_validate({
        "name": "bar", "model": "lumped", "environment": environment or {},
        "line_types": {"bar": {"diameter": 0.01, "mass": mass, "weight_in_water": 0.0, "axial_stiffness": ea,
                               "added_mass": 0.0, "drag_normal": 0.0, "drag_tangential": 0.0}},
        "cables": [{"name": "bar", "line_type": "bar", "length": length, "segments": segments,
                    "from": {"anchor": [0.0, 0.0, z]}, "to": {"vessel": [1.001 * length, 0.0, z]}}],
        "vessel": {"motion": [{"dof": dof, "amplitude": amplitude, "period": 2 * math.pi / omega,
                               "phase_deg": phase_deg}]},                       # 90 deg: a cos(omega t)
        "simulation": {"duration": 100.0, "method": method}})


def test_taut_bar_axial_tension_against_the_closed_form():
    """Every node's tension amplitude within 0.5 % of the continuous bar's and in phase with the drive."""
    ea, mass, length, omega, a = 1e5, 1.0, 100.0, 3.0, 1e-3
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(bar(ea=ea, mass=mass, length=length, omega=omega, amplitude=a))
    assert ds.attrs["status"] == "ok"
    k = omega * math.sqrt(mass / ea)
    x = ds.s.values * 1.001
    exact = ea * a * k * np.cos(k * x) / math.sin(k * 1.001 * length) / 1.001
    np.testing.assert_allclose(ds.tension_amplitude.values[0], exact, rtol=5e-3)
    np.testing.assert_allclose(ds.tension_phase.values[0], 0.0, atol=1e-6)
    assert float(ds.tension_rao_amplitude[0, -1]) == pytest.approx(float(ds.tension_amplitude[0, -1]) / a)
    assert float(ds.tension_std[-1]) == pytest.approx(float(ds.tension_amplitude[0, -1]) / math.sqrt(2.0))


def test_a_swing_beyond_the_mean_tension_fails_the_result_as_slack():
    """100 N of pretension (the line's 0.1 % stretch at its mean place), a drive of 0.12 m that swings
    it by 120 N (``EA a / L``, slowly): the result says slack."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(bar(segments=5, amplitude=0.12, phase_deg=-90.0, omega=0.3))
    assert ds.attrs["status"].startswith("failed: slack")
    assert float(ds.mean_tension.min()) == pytest.approx(100.0, rel=1e-3)
    assert float(ds.tension_amplitude.max()) == pytest.approx(120.0, rel=0.01)


def test_kanat_run_writes_the_frequency_dataset(tmp_path):
    """``kanat.run`` of a case with ``simulation.method: frequency`` gives (and writes) the same
    Dataset as ``kanat.solve_frequency``."""
    case = bar(segments=5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        outcome = kanat.run(case, output=tmp_path / "bar.nc")
        direct = kanat.solve_frequency(case)
    back = kanat.read_result(tmp_path / "bar.nc")
    assert outcome.status == "ok" and back.attrs["model"] == "frequency"
    np.testing.assert_allclose(back.tension_amplitude.values, direct.tension_amplitude.values, rtol=1e-9)
    np.testing.assert_allclose(back.frequency.values, [3.0])


def chain(tmp_path, method, period=PERIOD):
    path = tmp_path / "chain.dat"
    path.write_text(CHAIN_FILE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(path)
    return case.replace({"model": "lumped", "vessel.motion": surge(period), "simulation.duration": 12 * period,
                         "simulation.output_dt": 0.1, "simulation.method": method})


def time_domain_tension(case):
    """Mean and complex amplitude of every node's tension over the time domain's last three periods."""
    with quiet(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.run(case.replace({"simulation.method": "time"})).dataset
    assert ds.attrs["status"] == "ok"
    t = ds.time.values
    keep = t >= t[-1] - 3 * PERIOD
    return harmonic_fit(t[keep], ds.tension.values[keep], OMEGA)


def assert_agrees(ds, reference, rtol, atol_phase, nodes=slice(None)):
    amplitude = ds.tension_amplitude.values[0][nodes]
    phase = ds.tension_phase.values[0][nodes]
    np.testing.assert_allclose(amplitude, np.abs(reference), rtol=rtol)
    np.testing.assert_allclose(np.angle(np.exp(1j * (phase - np.angle(reference)))), 0.0, atol=atol_phase)


@pytest.mark.slow
def test_chain_catenary_against_the_time_domain(tmp_path):
    """Every node's tension amplitude within 5 % (measured 1.1 %) and phase within 0.05 rad of the
    time domain's steady state."""
    case = chain(tmp_path, "frequency")
    ds = kanat.solve_frequency(case)
    assert ds.attrs["status"] == "ok"
    _, reference = time_domain_tension(case)
    assert_agrees(ds, reference, rtol=0.05, atol_phase=0.05)


def polyester(method="frequency"):
    """A taut polyester line: 137.24 m from an anchor in 100 m of water to a fairlead 5 m down,
    137.93 m away (0.5 % stretch, 0.5 MN)."""
    return Case.model_validate({
        "name": "polyester", "model": "lumped",
        "environment": {"depth": 100.0, "seabed": {"stiffness": 3e6, "damping": 3e5}},
        "line_types": {"polyester": {"diameter": 0.16, "mass": 20.0, "weight_in_water": 45.0, "axial_stiffness": 1e8,
                                     "drag_normal": 1.2, "drag_tangential": 0.01}},
        "cables": [{"name": "leg", "line_type": "polyester", "length": 137.24, "segments": 20,
                    "from": {"anchor": [-100.0, 0.0, -100.0]}, "to": {"vessel": [0.0, 0.0, -5.0]}}],
        "vessel": {"motion": surge()},
        "simulation": {"duration": 12 * PERIOD, "output_dt": 0.1, "method": method}})


@pytest.mark.slow
def test_taut_polyester_against_the_time_domain():
    """Every node within 5 % in amplitude and 0.05 rad in phase of the time domain's steady state
    (about 4 minutes on a loaded two-core machine: the stiff line's time domain)."""
    case = polyester()
    ds = kanat.solve_frequency(case)
    assert ds.attrs["status"] == "ok"
    _, reference = time_domain_tension(case)
    assert_agrees(ds, reference, rtol=0.05, atol_phase=0.05)


def moordyn_node_tensions(moordyn, path, duration, omega, coupling=0.05, dt=0.001, every=0.1):
    """MoorDyn-C on ``path`` with its vessel point surging ``-a cos(omega t)``: times (k,) and the
    line's node tensions (k, nodes) every ``every`` seconds."""
    start = np.array([0.0, 0.0, -5.0])

    def point(t):
        return start + np.array([-AMPLITUDE * math.cos(omega * t), 0.0, 0.0])

    _, rows = run_moordyn(moordyn, path, duration, coupling, node_tensions(moordyn), int(round(every / coupling)),
                          point=point, scheme="RK2", dt=dt)
    return rows[:, 0], rows[:, 1:]


@pytest.mark.slow
def test_chain_catenary_against_moordyn_side_by_side(tmp_path, moordyn, moordyn_folder):
    """The same MoorDyn file in kanat's frequency domain and in MoorDyn-C's time domain, the fairlead
    surging 0.1 m in 60 s: every interior node's tension amplitude within 5 % (measured: 0.0 % on the
    seabed, 0.1-0.3 % in the suspended span, 4.2 % just before touchdown) but the touchdown node's,
    within 6 % (measured 2.7 %: where the seabed contact is linearised), and phase within 0.05 rad.
    (At 10 s MoorDyn agrees only when called every few ms: tests/frequency/test_moordyn_chain_dynamic.py,
    docs/frequency.md.)"""
    period = 60.0
    case = chain(tmp_path, "frequency", period)
    ds = kanat.solve_frequency(case)
    t, tension = moordyn_node_tensions(moordyn, tmp_path / "chain.dat", 5 * period, 2 * math.pi / period)
    keep = t >= t[-1] - 2 * period
    _, reference = harmonic_fit(t[keep], tension[keep], 2 * math.pi / period)
    touchdown = int(np.argmax(ds.tension_amplitude.values[0]))
    assert_agrees(ds, reference[touchdown], rtol=0.06, atol_phase=0.05, nodes=touchdown)
    for part in (slice(1, touchdown), slice(touchdown + 1, -1)):
        assert_agrees(ds, reference[part], rtol=0.05, atol_phase=0.05, nodes=part)


def test_a_motion_table_is_refused_at_its_key():
    """The frequency domain needs harmonics: a motion table is a case error naming vessel.motion."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = bar(segments=2).replace({"vessel.motion": {"rows": [[0.0, 0, 0, 0, 0, 0, 0], [1.0, 0.1, 0, 0, 0, 0, 0]]}})
        with pytest.raises(kanat.errors.CaseError, match="vessel.motion.*motion table"):
            kanat.solve_frequency(case)


def test_a_node_moving_down_to_the_seabed_is_noted():
    """A taut weightless line 0.4 m above the seabed, its vessel end heaving 1 m slowly: its nodes move
    0, 0.25, 0.5, 0.75 and 1 m (the string's quasi-static shape), the last three beyond their
    clearance, and the result's notes say they land (a note). The string's tension is quadratic in
    its transverse motion, which the linear model drops: the offset check fails the result."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(bar(segments=4, amplitude=1.0, omega=0.03, z=-49.6, dof="heave", phase_deg=0.0,
                                       environment={"depth": 50.0, "seabed": {"stiffness": 3e6}}))
    assert float(ds.motion_amplitude[0, 2, 2]) == pytest.approx(0.5, rel=0.02)       # quasi-static: (omega/omega_1)^2 = 1 %
    assert "3 suspended node(s) move down to the seabed" in ds.attrs["notes"]     # 0.5, 0.75, 1 m > 0.4 m
    assert ds.attrs["status"].startswith("failed: outside the linear range")


@pytest.mark.parametrize("environment", [{"depth": 50.0}, {"depth": 50.0, "seabed": {"stiffness": 3e6}}],
                         ids=["depth-alone", "seabed-block"])
def test_a_buoyant_line_moving_down_to_the_seabed_is_noted_with_depth_alone(environment):
    """The line of the test above made slightly buoyant (-0.01 N/m: it cannot reach the seabed at rest,
    so a case giving ``depth`` alone has no contact model): its vessel end moves 1 m down from 0.4 m
    above the seabed, and the note says so whether the case gives a seabed block or only
    ``environment.depth`` (the seabed every model applies, 50 m down); the middle node, lifted by
    the buoyancy, clears it."""
    case = bar(segments=4, amplitude=1.0, omega=0.03, z=-49.6, dof="heave", phase_deg=0.0, environment=environment)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(case.replace({"line_types.bar.weight_in_water": -0.01}))
    assert float(ds.motion_amplitude[0, 2, 2]) == pytest.approx(0.5, rel=0.02)
    assert float(ds.position[4, 2]) == pytest.approx(-49.6, abs=1e-3)           # 0.4 m above z = -50
    assert "2 suspended node(s) move down to the seabed (node 4: 1 m of motion, 0.4 m above it)" in ds.attrs["notes"]
