"""Wave loading of a steep taut line: kanat's lumped model beside MoorDyn-C (PyPI ``moordyn``),
both fed the same Airy kinematics — kanat's own (:func:`kanat.physics.waves.sea_from_model`).

The line (one set of numbers, :data:`LINE`, written as one MoorDyn file that kanat imports): 40
segments, diameter 0.25 m, 120 kg/m, EA 2e7 N, BA 2e4 N s, Cd 1.2, Ca 1.0, CdAx 0.01, CaAx 0,
from an anchor at 100 m depth to a fixed point 10 m under the still surface (8 m under the
troughs, so partial submergence never enters) — straight above the anchor (``vertical``, 89.45
m unstretched) or 10 m off (``inclined``, 6.3 deg from vertical, 90 m); 153-156 kN of tension; a
regular wave of H 4 m, T 8 s in 100 m of water, along +x; 72 s from still water.

MoorDyn runs with ``WaveKin = 1`` (externally driven waves): every 0.02 s coupling step the test
evaluates the kanat case's sea at MoorDyn's kinematics points (its nodes, where they are) at the
middle of the step and passes the velocities and accelerations with ``ExternalWaveKinSet``
(MoorDyn holds them over the step; its time argument is not used). Both codes then load the line
with Morison's equation: drag on the relative velocity, added mass ``Ca rho A`` on the normal
acceleration, fluid inertia ``(1 + Ca) rho A a_n + (1 + CaAx) rho A a_t`` — with CaAx = 0 the
axial part is the Froude–Krylov (pressure-gradient) term ``rho A (a_w . t) t`` alone.

Compared over 48-72 s (three periods after the start-up transient), sampled every 0.1 s: the top
segment's tension (MoorDyn's ``FairTen``, kanat's ``segment_tension`` of the last element) —
mean, mean less the still-water tension (the wave-induced mean), range (max - min), first
harmonic — and the horizontal range of the midpoint node. Measured on 2026-11-28 (MoorDyn 2.7.2
RK2 at 1 ms, kanat RK4 at its safe step, 3.6 ms, each element end's drag on its own velocity;
MoorDyn's RK4 at 0.5 ms gave the same figures):

==========================  =====================  =====================
kanat vs MoorDyn            vertical               inclined
==========================  =====================  =====================
mean top tension            152.939 kN, +0.001 %   155.591 kN, +0.001 %
wave-induced mean           155.4 N, -0.42 %       105.0 N, +0.79 %
range                       950.5 N, +0.37 %       3573 N, +0.42 %
first harmonic              396.3 N, +0.25 %       1781 N, +0.42 %
midpoint horizontal range   0.439 m, +0.35 %       0.380 m, +0.36 %
==========================  =====================  =====================

Tolerances: 0.01 % on the mean, 3 % on the wave-induced mean, 1.5 % on the rest.
The differences fall with the segment count (range: +1.5 %, +0.42 %, +0.16 % at 20, 40 and 80
segments, inclined): they are the two discretizations' (kanat loads elements with their mean
relative flow and tangent, MoorDyn nodes with theirs), not their physics.

The Froude–Krylov term matters: on the vertical line it *is* the first-order tension. Each
interior node ``i`` of a fixed-fixed stiff line carries ``F_i = rho A (L0/N) a_z(z_i)`` (both codes
lump loads per unstretched length ``L0``), of which the top segment takes ``-F_i i / N``
(quasi-static: the axial period is 0.4 s), so the first harmonic of its tension is
``rho A (L0/N) |sum a_z(z_i) i/N|`` = 394.8 N: kanat 396.3 N (+0.4 %), MoorDyn 395.3 N (+0.1 %).
kanat has no switch for the term; zeroing the elements' displaced mass in memory (``rho A a_w``
gone, normal and axial) gives a first harmonic of 14.7 N and a range of 143 N on the vertical
line (-96 %, -85 %), a range of 1.84 kN on the inclined one (-48 %), and midpoint ranges 37-38 %
smaller — against tolerances of 1.5 %.
"""
import math
import warnings

import numpy as np
import pytest

from kanat import api
from kanat.errors import CaseWarning
from kanat.io import load_case
from kanat.physics.waves import sea_from_model

import helpers_moordyn

pytestmark = pytest.mark.slow

LINE = dict(diameter=0.25, mass=120.0, ea=2e7, ba=2e4, cd=1.2, ca=1.0, cdax=0.01, caax=0.0, segments=40)
GEOMETRY = {"vertical": dict(top_x=0.0, length=89.45), "inclined": dict(top_x=10.0, length=90.0)}
ANCHOR_Z, TOP_Z, DEPTH = -100.0, -10.0, 100.0
WAVE = {"type": "regular", "height": 4.0, "period": 8.0, "heading_deg": 0.0}
DURATION, WINDOW = 72.0, 48.0          # s: run, start of the compared window (three periods)
COUPLING, SAMPLE = 0.02, 5             # s; MoorDyn sampled every SAMPLE coupling steps (0.1 s)
OUTPUT_DT = COUPLING * SAMPLE
MIDDLE = LINE["segments"] // 2         # MoorDyn's midpoint node (nodes 0..N from the anchor)

TOLERANCE = dict(mean=1e-4, wave_mean=0.03, range=0.015, harmonic=0.015, midpoint=0.015)

MOORDYN_FILE = """--------------------- MoorDyn Input File ------------------------------------------------
A steep taut line in regular waves, from an anchor to a fixed point below the troughs.
---------------------- LINE TYPES -------------------------------------------------------
TypeName   Diam    Mass/m   EA        BA/-zeta   EI      Cd     Ca     CdAx   CaAx
(name)     (m)     (kg/m)   (N)       (N-s/-)    (N-m^2) (-)    (-)    (-)    (-)
taut       {diameter} {mass} {ea} {ba} 0 {cd} {ca} {cdax} {caax}
---------------------- POINTS -----------------------------------------------------------
ID   Attachment  X        Y         Z        Mass   Volume  CdA   Ca
(#)  (word)      (m)      (m)       (m)      (kg)   (m^3)   (m^2) (-)
1    Fixed       0.0      0.0       {anchor_z} 0    0       0     0
2    Fixed       {top_x}  0.0       {top_z}  0      0       0     0
---------------------- LINES ------------------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)     (#)      (#)      (m)       (-)      (-)
1    taut       1        2        {length}  {segments} -
---------------------- OPTIONS ----------------------------------------------------------
0.001      dtM          time step of the integration (s)
9.81       g            gravity (m/s^2)
1025.0     rho          water density (kg/m^3)
{depth}    WtrDpth      water depth (m)
{duration} TMax         simulated time (s)
0.5        dtOut        output interval (s)
{moordyn_only}---------------------- need this line ---------------------------------------------------
"""
MOORDYN_ONLY = "1          WaveKin\n1          disableOutput\n1          disableOutTime\n"
"""Options kanat's importer refuses or warns about: externally driven waves, no output files."""


def moordyn_text(geometry: str, moordyn_only: str = "") -> str:
    return MOORDYN_FILE.format(**LINE, **GEOMETRY[geometry], anchor_z=ANCHOR_Z, top_z=TOP_Z, depth=DEPTH,
                               duration=DURATION, moordyn_only=moordyn_only)


def kanat_case(geometry: str, folder):
    """The MoorDyn file (without MoorDyn's own options) imported, with the wave and RK4."""
    path = folder / f"{geometry}.dat"
    path.write_text(moordyn_text(geometry))
    with warnings.catch_warnings():              # a taut line between two fixed points is the point
        warnings.filterwarnings("ignore", ".*must stretch", CaseWarning)
        return load_case(path).replace({"environment.waves": WAVE, "simulation.output_dt": OUTPUT_DT,
                                        "simulation.scheme": "rk4", "simulation.dt": None})


def run_moordyn(geometry: str, sea, folder):
    """MoorDyn with the sea's kinematics at its points, mid-step, every coupling step.

    Returns the still-water tension and rows ``(t, top tension, midpoint x, y, z)``."""
    moordyn = pytest.importorskip("moordyn")
    path = folder / f"moordyn_{geometry}.dat"          # MoorDyn writes its log beside its input
    path.write_text(moordyn_text(geometry, MOORDYN_ONLY))
    record = helpers_moordyn.fairlead_tension(moordyn, node=MIDDLE)
    return helpers_moordyn.run_moordyn(moordyn, path, DURATION, COUPLING, record, SAMPLE, sea=sea,
                                       at_start=lambda system: record(system)[0])


def run_kanat(geometry: str, case):
    """kanat's run as MoorDyn's rows: the still-water tension and ``(t, top tension, midpoint)``."""
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    top = int(np.flatnonzero(ds.segment_cable.values == "line1")[-1])
    middle = np.array([GEOMETRY[geometry]["top_x"] / 2, 0.0, (ANCHOR_Z + TOP_Z) / 2])
    node = int(np.argmin(np.linalg.norm(ds.position.values[0] - middle, axis=1)))
    tension = ds.segment_tension.values[:, top]
    return tension[0], np.column_stack([ds.time.values, tension, ds.position.values[:, node, :]])


def window(rows):
    t = np.round(rows[:, 0], 6)
    return rows[(t >= WINDOW) & (t < DURATION)]


def first_harmonic(t, values, period):
    """Amplitude of the component at ``2 pi / period`` of a series over whole periods."""
    return abs(2.0 * np.mean((values - values.mean()) * np.exp(-2j * math.pi * t / period)))


def statistics(still, rows):
    w = window(rows)
    tension = w[:, 1]
    return dict(mean=tension.mean(), wave_mean=tension.mean() - still, range=np.ptp(tension),
                harmonic=first_harmonic(w[:, 0], tension, WAVE["period"]), midpoint=np.ptp(w[:, 2]))


@pytest.fixture(scope="module")
def side_by_side(tmp_path_factory):
    """``side_by_side(geometry)``: statistics of (kanat, MoorDyn), each geometry run once."""
    pytest.importorskip("moordyn")
    folder = tmp_path_factory.mktemp("moordyn_waves")
    done = {}

    def get(geometry):
        if geometry not in done:
            case = kanat_case(geometry, folder)
            sea = sea_from_model(case.environment)
            ours = statistics(*run_kanat(geometry, case))
            done[geometry] = ours, statistics(*run_moordyn(geometry, sea, folder))
        return done[geometry]
    return get


@pytest.mark.parametrize("geometry", list(GEOMETRY))
@pytest.mark.parametrize("quantity", list(TOLERANCE))
def test_wave_induced_tension_and_motion_agree_with_moordyn(side_by_side, geometry, quantity):
    ours, theirs = side_by_side(geometry)
    assert ours[quantity] == pytest.approx(theirs[quantity], rel=TOLERANCE[quantity])


def test_froude_krylov_is_the_first_order_tension_of_a_vertical_line(side_by_side, tmp_path):
    """The quasi-static axial Froude–Krylov load on the vertical line (module docstring) is its top
    tension's first harmonic in both codes: the term is the whole of it, not a correction."""
    n, span, length = LINE["segments"], TOP_Z - ANCHOR_Z, GEOMETRY["vertical"]["length"]
    environment = kanat_case("vertical", tmp_path).environment
    sea = sea_from_model(environment)
    i = np.arange(1, n)
    nodes = np.column_stack([0.0 * i, 0.0 * i, ANCHOR_Z + i * span / n])     # evenly stretched
    load = environment.water_density * math.pi * LINE["diameter"] ** 2 / 4 * length / n   # rho A L0/N
    times = np.arange(0.0, WAVE["period"], 0.01)
    top = [-load * np.sum(sea.acceleration(nodes, t)[:, 2] * i / n) for t in times]
    froude_krylov = first_harmonic(times, np.array(top), WAVE["period"])
    for stats in side_by_side("vertical"):
        assert stats["harmonic"] == pytest.approx(froude_krylov, rel=TOLERANCE["harmonic"])
