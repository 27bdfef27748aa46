"""Cables of several sections with inline bodies in the continuum model (theory/moorings.md §4), against oracles:
force balance at every junction, the piecewise closed-form catenary of a two-section line, the 3-D
statics and the lumped model on a subsurface mooring, and the continuum and lumped models
converging together with the grid on a tow with an inline float."""
import warnings

import numpy as np
import pytest
from scipy.optimize import fsolve

import kanat
from kanat.continuum import kernels2d as k
from kanat.continuum.chart import frames
from kanat.continuum.models import model_for
from kanat.physics.drag import body_drag
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

from helpers import EXAMPLES

SUBSURFACE = (EXAMPLES / "subsurface_mooring.yaml").read_text()


def quiet_simulate(text):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.simulate(kanat.load_case(text))


def test_grid_puts_the_attachment_on_a_junction_between_the_sections():
    model = model_for(kanat.load_case(SUBSURFACE))
    grid = model.cable.grid
    junction = grid.junctions[0][0]
    assert grid.junctions == ((60, "glass_balls"),)
    assert grid.s[junction] == grid.s[junction + 1] == 300.0 and len(grid.s) == 92
    assert grid.rows[junction, k.KIND] == k.JUNCTION and grid.rows[junction, k.DS] == 0.0
    wire, nylon = grid.rows[junction - 1], grid.rows[junction + 1]
    assert (wire[k.EA], wire[k.W0], nylon[k.EA], nylon[k.W0]) == (1.0e7, 3.5, 1.5e6, 0.3)   # no averaging


def test_an_attachment_off_the_nodes_splits_its_section_and_says_so():
    text = SUBSURFACE.replace("{body: glass_balls, s: 300}", "{body: glass_balls, s: 123}")
    model = model_for(kanat.load_case(text))
    grid = model.cable.grid
    junction = grid.junctions[0][0]
    assert grid.s[junction] == pytest.approx(123.0) and np.all(np.diff(grid.s) >= 0)
    assert grid.notes and "split at its attachments" in grid.notes[0]


def test_force_balance_at_every_junction_to_round_off():
    """Steady state: T_b t_b - T_a t_a + B z + drag + F = 0 at the float (3-D, sheared current)."""
    case = kanat.load_case(SUBSURFACE)
    model = model_for(case)
    state = model.initial()
    t = frames(state.y, state.chart)[0]
    T = state.y[:, 0]
    body = case.bodies["glass_balls"]
    for a, name in model.cable.grid.junctions:
        water = case.environment.current.at(state.xyz[a, 2])
        load = body.net_buoyancy * np.array([0.0, 0.0, 1.0]) + body_drag(water, body.drag_area, 1025.0)
        balance = T[a + 1] * t[a + 1] - T[a] * t[a] + load
        assert np.linalg.norm(balance) < 1e-9 * np.linalg.norm(load)
        assert np.linalg.norm(state.xyz[a] - state.xyz[a + 1]) < 1e-12           # one point, two sides
        assert abs(T[a + 1] - T[a]) > 0.5 * body.net_buoyancy                   # the jump is the float's


def piecewise_catenary(span, rise, pieces):
    """Closed form of a line of sections ``(length, w, EA)`` hanging between the origin and
    ``(span, rise)``: H constant, V(s) = V0 + integral of w; per section ``x = H/w (asinh(V1/H) -
    asinh(V0/H)) + H l/EA``, ``z = (T1 - T0)/w + (V0 l + w l^2/2)/EA``. Returns H, V0, tensions at joints."""
    def ends(q):
        H, V0 = q
        x = z = 0.0
        V = V0
        for length, w, ea in pieces:
            V1 = V + w * length
            T0, T1 = np.hypot(H, V), np.hypot(H, V1)
            x += H / w * (np.arcsinh(V1 / H) - np.arcsinh(V / H)) + H * length / ea
            z += (T1 - T0) / w + (V * length + 0.5 * w * length**2) / ea
            V = V1
        return [x - span, z - rise]
    H, V0 = fsolve(ends, [1e4, -1e3], xtol=1e-12)
    tensions, V = [np.hypot(H, V0)], V0
    for length, w, _ in pieces:
        V += w * length
        tensions.append(np.hypot(H, V))
    return H, V0, np.array(tensions)


TWO_SECTIONS = """
name: two-section-hanging-line
model: continuum
line_types:
  chain: {diameter: 0.05, mass: 20.0, weight_in_water: 170.0, axial_stiffness: 2.0e8}
  wire: {diameter: 0.03, mass: 4.0, weight_in_water: 34.0, axial_stiffness: 5.0e7}
cables:
  - name: line
    from: "anchor:[0, 0, -200]"
    to: "anchor:[400, 0, -60]"
    sections:
      - {line_type: chain, length: 200, segments: SEG}
      - {line_type: wire, length: 300, segments: SEG}
simulation: {duration: 1, dt: 0.5, output_dt: 0.5}
"""


def test_two_section_hanging_line_against_the_piecewise_catenary():
    H, V0, tensions = piecewise_catenary(400.0, 140.0, [(200.0, 170.0, 2.0e8), (300.0, 34.0, 5.0e7)])
    errors = []
    for segments in (25, 50, 100):
        case = kanat.load_case(TWO_SECTIONS.replace("SEG", str(segments)))
        T = model_for(case).initial().y[:, 0]
        got = T[[0, segments, -1]]
        errors.append(np.max(np.abs(got / tensions - 1)))
    assert errors[-1] < 1e-4                                 # continuum at 100 + 100 segments
    assert errors[0] / errors[-1] > 10                       # second order: ~16 for two halvings
    statics = solve_cable3(cable_problem3(case), "auto", [0.0, 200.0, 500.0])
    np.testing.assert_allclose(statics.tension, tensions, rtol=1e-8)
    assert statics.force3[0, 0] == pytest.approx(H, rel=1e-8)


def test_continuum_lumped_and_statics_agree_on_the_subsurface_mooring():
    """Steady state in the sheared, turning current: within 0.1 % (tension) and 0.1 % of the offset."""
    continuum = quiet_simulate(SUBSURFACE.replace("duration: 120", "duration: 5"))
    lumped = quiet_simulate(SUBSURFACE.replace("duration: 120", "duration: 0.5").replace("output_dt: 5", "output_dt: 0.5")
                            .replace("model: continuum", "model: lumped")
                            .replace("scheme: generalized-alpha", "scheme: generalized-alpha-lumped"))
    statics = kanat.solve_statics(kanat.load_case(SUBSURFACE.replace("model: continuum", "model: statics")))
    assert continuum.attrs["status"] == lumped.attrs["status"] == "ok"
    c = continuum.isel(time=0)
    for name in ("top_buoy", "glass_balls"):
        where = statics.body_position.sel(body=name).values
        offset = np.hypot(where[0], where[1])
        for ds in (c, lumped.isel(time=0)):
            assert np.linalg.norm(ds.body_position.sel(body=name).values - where) < 1e-3 * offset
    for end in (0, -1):
        expected = float(statics.tension.values[end])
        assert float(c.tension.values[end]) == pytest.approx(expected, rel=1e-3)
        assert float(lumped.isel(time=0).tension.values[end]) == pytest.approx(expected, rel=1e-3)


INLINE_TOW = """
name: tow-with-inline-float
model: MODEL
line_types:
  towcable: {diameter: 0.0173, mass: 1.12, weight_in_water: 8.89, axial_stiffness: 1.2717e7, added_mass: 0.24,
             drag_normal: 1.5, drag_tangential: 0.01}
bodies:
  float: {mass: 100, net_buoyancy: 600, drag_area: 0.2, added_mass: 100, position: [-150, 0, -60]}
  sled: {mass: 1135, net_buoyancy: -6686, drag_area: 0.3276, position: [-300, 0, -150]}
vessel:
  tow_point: [0, 0, 0]
  track:
    - {straight: {speed_kn: 4, duration: 5}}
    - {accelerate: {to_speed_kn: 6, acceleration: 0.1}}
    - {straight: {duration: 200}}
cables:
  - name: tow
    from: vessel
    to: sled
    sections:
      - {line_type: towcable, length: 200, segments: SEG}
      - {line_type: towcable, length: 200, segments: SEG}
    attachments:
      - {body: float, s: 200}
simulation: {scheme: SCHEME, duration: 60, dt: DT, output_dt: 5, dimensions: 2}
"""


@pytest.mark.slow
def test_continuum_and_lumped_converge_together_on_a_tow_with_an_inline_float():
    """A speed step: the two models' body depths approach each other as both grids are refined."""
    gaps = []
    for segments in (5, 10, 20):
        text = INLINE_TOW.replace("SEG", str(segments))
        c = quiet_simulate(text.replace("MODEL", "continuum").replace("SCHEME", "generalized-alpha").replace(
            "DT", "0.25"))
        lump = quiet_simulate(text.replace("MODEL", "lumped").replace("SCHEME", "generalized-alpha-lumped").replace(
            "DT", "0.05"))
        assert c.attrs["status"] == lump.attrs["status"] == "ok"
        depth = lambda ds, name: ds.body_position.sel(body=name, xyz="z").values       # noqa: E731
        gaps.append(max(np.max(np.abs(depth(c, n) - depth(lump, n))) for n in ("sled", "float")))
    assert gaps[2] < gaps[1] < gaps[0]
    assert gaps[2] < 0.5                                       # m, over a 40 m rise of the sled
