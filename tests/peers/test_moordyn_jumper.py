"""Waves on steep and slack lines near the surface: kanat's lumped model (its default scheme)
beside MoorDyn-C (PyPI ``moordyn``), both fed the same Airy kinematics — kanat's own
(:func:`kanat.physics.waves.sea_from_model`), passed to MoorDyn with ``ExternalWaveKinSet`` at its
nodes every 0.02 s coupling step (as tests/peers/test_moordyn_waves.py does).

The cases, each one MoorDyn file that kanat imports:

* **jumper**: 170 m, diameter 0.396 m, 165 kg/m, EA 5e8 N, damping ratio 1 (BA = -1), Cd 1, Ca 1,
  40 segments, from an anchor at 55 m depth to a point fixed 5 m under the still surface, 100 m
  away horizontally along the wave heading (0, 45 or 90 deg) in 100 m of water; regular waves of
  H 10 m, T 10 s: the troughs reach the top end. About 42 kN at the top.
* **taut** (tests/peers/test_moordyn_waves.py's line): 0.25 m, 120 kg/m, EA 2e7 N, BA 2e4 N s, Cd 1.2,
  from 100 m depth to a point 10 m off, its length set for a strain of 0.75 % (about 150 kN).
* **catenary**: a 90 m line of 0.1 m, 60 kg/m, EA 1e8 N, damping ratio 1, Cd 1.2, Ca 1, 20
  segments, from a point 60 m deep (40 m above the seabed) to a point 60 m off, hanging in a
  catenary (32-45 kN at the top).

The taut line and the catenary run over top depths 2, 10 and 30 m and wave heights 2, 6 and 10 m
(T 8 s), where the top stays under the troughs by at least a metre (the others are partial
submergence, a different question); 30 m depth is the lowest.

Compared over the last three wave periods of each run, sampled every 0.1 s: the top segment's
tension (MoorDyn's ``FairTen``, kanat's ``segment_tension`` of the last element) — mean within
1 %, range (max - min) and maximum within 3 %. A range under 1 % of the mean (the catenary 30 m
down: 15-73 N of 32 kN; kanat 15 N, MoorDyn 17 N at H 2 m) is also accepted within 0.05 % of
the mean (16 N): differences of that size come from the two codes' different starts (a
catenary 30 m down with 8 periods: 95 N and 163 N, with 16 periods 117 N and 126 N).

What this caught (2026-11-28, jumper at 0 deg; MoorDyn 2.7.2 RK2 at 1 ms): kanat's default scheme
(generalized-α at 0.1 s) read a mean top tension 8 % above MoorDyn's and a range 1.9x it, at every
heading. Two causes. (1) The scheme's force balance was at ``x_m = (1 - alpha_f) x_n+1 + alpha_f
x_n``, and its end positions extrapolated from there: the chord of a swinging element grows by
``O((w h)^2)``, which EA 5e8 N turns into tension (RK4, and the scheme with ``lambda_inf = 0``,
agreed with each other). The lumped scheme is now the WBZ-α member (``alpha_f = 0``). (2) Drag on
the element's mean velocity left the mesh's zig-zag mode undamped: waves rang it (0.6 Hz at 20
segments, 1 Hz at 40) and the range was 26 % (20 segments) and 9 % (40) above MoorDyn's, converging
to it only at 80. Each end's half of the drag now takes that end's velocity: RK4 +2.9 % at 20
segments, -0.1 % at 40; the default scheme at 40 segments: mean -0.03 %, range +0.7 %, maximum
+0.3 %, the same at the three headings.
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

COUPLING, SAMPLE = 0.02, 5                  # s; MoorDyn sampled every SAMPLE coupling steps (0.1 s)
TOLERANCE = dict(mean=0.01, range=0.03, max=0.03)
RANGE_FLOOR = 5e-4        # of the mean tension: ranges agree to this much whatever their size (docstring)

LINE_FILE = """--------------------- MoorDyn Input File ------------------------------------------------
{title}
---------------------- LINE TYPES -------------------------------------------------------
TypeName   Diam    Mass/m   EA        BA/-zeta   EI      Cd     Ca     CdAx   CaAx
(name)     (m)     (kg/m)   (N)       (N-s/-)    (N-m^2) (-)    (-)    (-)    (-)
line       {diameter} {mass} {ea} {ba} 0 {cd} {ca} 0.0 0.0
---------------------- POINTS -----------------------------------------------------------
ID   Attachment  X        Y         Z        Mass   Volume  CdA   Ca
(#)  (word)      (m)      (m)       (m)      (kg)   (m^3)   (m^2) (-)
1    Fixed       0.0      0.0       {anchor_z} 0    0       0     0
2    Fixed       {top_x:.6f}  {top_y:.6f}  {top_z}  0      0       0     0
---------------------- LINES ------------------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)     (#)      (#)      (m)       (-)      (-)
1    line       1        2        {length:.6f} {segments} -
---------------------- OPTIONS ----------------------------------------------------------
0.001      dtM          time step of the integration (s)
9.81       g            gravity (m/s^2)
1025.0     rho          water density (kg/m^3)
100.0      WtrDpth      water depth (m)
{duration} TMax         simulated time (s)
0.5        dtOut        output interval (s)
{moordyn_only}---------------------- need this line ---------------------------------------------------
"""
MOORDYN_ONLY = "1          WaveKin\n1          disableOutput\n1          disableOutTime\n"
"""Options kanat's importer refuses or warns about: externally driven waves, no output files."""

JUMPER = dict(title="A flexible jumper in waves, its top end 5 m under the still surface.", diameter=0.396,
              mass=165.0, ea=5e8, ba=-1.0, cd=1.0, ca=1.0, anchor_z=-55.0, top_z=-5.0, span=100.0, length=170.0,
              segments=40)
TAUT = dict(title="A steep taut line in waves.", diameter=0.25, mass=120.0, ea=2e7, ba=2e4, cd=1.2, ca=1.0,
            anchor_z=-100.0, span=10.0, strain=0.0075, segments=40)
CATENARY = dict(title="A hanging catenary in waves.", diameter=0.1, mass=60.0, ea=1e8, ba=-1.0, cd=1.2, ca=1.0,
                anchor_z=-60.0, span=60.0, length=90.0, segments=20)
PERIOD = {"jumper": 10.0, "taut": 8.0, "catenary": 8.0}
TOP_DEPTHS, HEIGHTS = (2.0, 10.0, 30.0), (2.0, 6.0, 10.0)
MATRIX = [(depth, height) for depth in TOP_DEPTHS for height in HEIGHTS if depth >= height / 2 + 1.0]
FAST = {("taut", 10.0, 6.0), ("catenary", 10.0, 6.0)}
"""The matrix's representative runs that are not marked slow."""


def line_text(line: dict, heading_deg: float, top_z: float, duration: float, moordyn_only: str = "") -> str:
    """One MoorDyn file of ``line``, its top end ``line['span']`` m away along ``heading_deg``."""
    values = dict(line, top_z=top_z)
    if "strain" in line:                                  # taut: the length for the strain asked
        values["length"] = math.hypot(line["span"], top_z - line["anchor_z"]) / (1.0 + line["strain"])
    heading = math.radians(heading_deg)
    return LINE_FILE.format(**values, top_x=line["span"] * math.cos(heading), top_y=line["span"] * math.sin(heading),
                            duration=duration, moordyn_only=moordyn_only)


def kanat_case(text: str, path, wave: dict, duration: float):
    """The MoorDyn file imported, with the wave, its default scheme and outputs every 0.1 s."""
    path.write_text(text)
    with warnings.catch_warnings():              # a taut line between two fixed points is the point
        warnings.filterwarnings("ignore", ".*must stretch", CaseWarning)
        return load_case(path).replace({"environment.waves": wave, "simulation.output_dt": COUPLING * SAMPLE,
                                        "simulation.dt": None, "simulation.duration": duration})


def run_moordyn(text: str, path, sea, duration: float) -> np.ndarray:
    """MoorDyn with ``sea``'s kinematics at its points, mid-step, every coupling step: rows
    ``(t, top tension)`` every 0.1 s."""
    moordyn = pytest.importorskip("moordyn")
    path.write_text(text)
    return helpers_moordyn.run_moordyn(moordyn, path, duration, COUPLING, helpers_moordyn.fairlead_tension(moordyn),
                                       SAMPLE, sea=sea)[1]


def run_kanat(case) -> np.ndarray:
    """kanat's run as MoorDyn's rows ``(t, top tension)``."""
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    top = int(np.flatnonzero(ds.segment_cable.values == "line1")[-1])
    return np.column_stack([ds.time.values, ds.segment_tension.values[:, top]])


def statistics(rows: np.ndarray, start: float, end: float) -> dict:
    t = np.round(rows[:, 0], 6)
    tension = rows[(t >= start) & (t < end), 1]
    return dict(mean=tension.mean(), range=np.ptp(tension), max=tension.max())


def side_by_side(folder, name: str, line: dict, heading_deg: float, top_z: float, height: float,
                 periods: int = 8) -> tuple[dict, dict]:
    """Statistics of kanat's and MoorDyn's top tension over the last three of ``periods`` periods."""
    period = PERIOD[name]
    duration = periods * period
    wave = {"type": "regular", "height": height, "period": period, "heading_deg": heading_deg}
    stem = f"{name}_{heading_deg:g}_{-top_z:g}_{height:g}"
    case = kanat_case(line_text(line, heading_deg, top_z, duration), folder / f"{stem}.dat", wave, duration)
    theirs = run_moordyn(line_text(line, heading_deg, top_z, duration, MOORDYN_ONLY),
                         folder / f"moordyn_{stem}.dat", sea_from_model(case.environment), duration)
    start = duration - 3 * period
    return statistics(run_kanat(case), start, duration), statistics(theirs, start, duration)


def assert_agree(ours: dict, theirs: dict) -> None:
    for quantity, tolerance in TOLERANCE.items():
        floor = RANGE_FLOOR * theirs["mean"] if quantity == "range" else 0.0
        assert ours[quantity] == pytest.approx(theirs[quantity], rel=tolerance, abs=floor), quantity


@pytest.mark.parametrize("heading_deg", [0.0, pytest.param(45.0, marks=pytest.mark.slow),
                                         pytest.param(90.0, marks=pytest.mark.slow)])
def test_jumper_in_waves_agrees_with_moordyn(tmp_path, heading_deg):
    ours, theirs = side_by_side(tmp_path, "jumper", JUMPER, heading_deg, JUMPER["top_z"], 10.0)
    assert_agree(ours, theirs)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["taut", "catenary"])
@pytest.mark.parametrize("top_depth, height", MATRIX)
def test_lines_over_depths_and_heights_agree_with_moordyn(tmp_path, name, top_depth, height, request):
    if (name, top_depth, height) not in FAST:
        request.applymarker(pytest.mark.slow)
    line = TAUT if name == "taut" else CATENARY
    ours, theirs = side_by_side(tmp_path, name, line, 0.0, -top_depth, height)
    assert_agree(ours, theirs)
