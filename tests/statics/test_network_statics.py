"""Network statics (kanat.statics.network*): 3-D networks of catenary lines on a seabed.

Oracles: the closed-form elastic catenary with seabed (kanat.statics.catenary); MoorPy 1.3's
answers stored in tests/data/moorpy/reference.json (how they were made: README.md there;
tests/peers/test_network_statics_moorpy.py runs MoorPy live); finite differences of the
equations and of the equilibrium; force balance with the friction drop of Jonkman's
grounded line; one system written two ways; the lumped model's equilibrium converging to
network statics at second order where nothing touches the seabed.
"""
from __future__ import annotations

import json
import math
import textwrap
import warnings

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

import kanat
from kanat.cli import app
from kanat.errors import CaseError, SolverError
from kanat.io.results import read_result
from kanat.model.support import unsupported
from kanat.statics import solve_statics
from kanat.statics.catenary import elastic_catenary
from kanat.statics.line_solve import solve_line
from kanat.statics.network import _caps, _continuation, _scales
from kanat.statics.network_result import first_guess
from kanat.statics.network_setup import fairlead_rotation, network_problem
from kanat.statics.piecewise import Ground, LiftedLoop, Pieces, end_position, sample

from helpers import DATA, ROOT, assert_network_jacobian_is_its_central_difference

REFERENCE = json.loads((DATA / "moorpy" / "reference.json").read_text())
CHAIN_W, CHAIN_EA = 981.0, 5.1e8


def load(source, **changes):
    """A case validated for the statics solver, with ``changes`` (``Case.replace`` paths)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(source, solver="statics")
        return case.replace(changes) if changes else case


# --- one line ---------------------------------------------------------------------------

@pytest.mark.parametrize("span, rise", [(600.0, 145.0), (650.0, 100.0), (690.0, 50.0), (300.0, 145.0),
                                        (100.0, 500.0), (20.0, 680.0)])
def test_a_grounded_chain_is_the_closed_form_catenary_with_seabed(span, rise):
    """Touchdown, anchor and fairlead tension of Irvine's elastic catenary, to round-off."""
    exact = elastic_catenary(span, rise, 700.0, CHAIN_W, CHAIN_EA, seabed=True)
    sol = solve_line(span, rise, Pieces.uniform(700.0, CHAIN_W, CHAIN_EA), Ground())
    assert sol.horizontal_tension == pytest.approx(exact.horizontal_tension, rel=1e-10, abs=1e-9 * CHAIN_W)
    assert sol.vertical_tension == pytest.approx(exact.vertical_tension_upper, rel=1e-10)
    assert sol.evaluation.touchdown == pytest.approx(exact.grounded_length, rel=1e-10, abs=1e-9)
    assert np.hypot(*sol.evaluation.anchor) == pytest.approx(exact.tension_lower, rel=1e-10, abs=1e-6)
    x, z, tension, _ = sample(exact.s, sol.horizontal_tension, sol.vertical_tension,
                              Pieces.uniform(700.0, CHAIN_W, CHAIN_EA), Ground())
    if sol.slack:                                  # lying slack: bunched up to the touchdown, as the closed form
        x = np.minimum(x, span)
    np.testing.assert_allclose(np.column_stack([x, z]), np.column_stack([exact.x, exact.z]), atol=1e-9 * 700)
    np.testing.assert_allclose(tension, exact.tension, rtol=1e-9, atol=1e-6)


def test_a_3d_grounded_chain_in_a_case_is_the_closed_form_catenary():
    """A chain from an anchor off the x-z plane to a vessel fairlead, solved as a network."""
    case = load(textwrap.dedent("""\
        model: statics
        environment: {depth: 150}
        line_types: {chain: {diameter: 0.137, mass: 115, weight_in_water: 981, axial_stiffness: 5.1e8}}
        cables:
          - {name: leg, line_type: chain, length: 700, segments: 70,
             from: "anchor:[-360, -480, -150]", to: {vessel: [0, 0, -5]}}
        """))
    result = solve_statics(case)
    exact = elastic_catenary(600.0, 145.0, 700.0, 981.0, 5.1e8, seabed=True, n_points=71)
    cable = result.cables["leg"]
    assert cable.grounded_length == pytest.approx(exact.grounded_length, rel=1e-10)
    assert cable.tension[-1] == pytest.approx(exact.tension_upper, rel=1e-10)
    direction = np.array([0.6, 0.8, 0.0])
    np.testing.assert_allclose(result.anchor_forces["leg.from"], exact.horizontal_tension * direction, rtol=1e-10,
                               atol=1e-6)
    np.testing.assert_allclose(cable.position[:, 0], -360 + 0.6 * exact.x, atol=1e-8)
    np.testing.assert_allclose(cable.position[:, 2], -150 + exact.z, atol=1e-8)


@pytest.mark.parametrize("row", range(len(REFERENCE["catenaries"])))
def test_a_single_line_matches_moorpys_friction_and_slope_catenary(row):
    """MoorPy's catenary() with Coulomb friction (CB) or a sloped seabed, stored numbers."""
    ref = REFERENCE["catenaries"][row]
    ground = Ground(math.tan(math.radians(ref["slope_deg"])), ref["friction"])
    sol = solve_line(ref["span"], ref["rise"], Pieces.uniform(ref["length"], ref["weight"], ref["axial_stiffness"]),
                     ground)
    scale = ref["weight"] * ref["length"]
    assert sol.horizontal_tension == pytest.approx(ref["horizontal_tension"], rel=1e-9, abs=1e-10 * scale)
    assert sol.vertical_tension == pytest.approx(ref["vertical_tension"], rel=1e-9)
    np.testing.assert_allclose(sol.evaluation.anchor, ref["anchor_force"], rtol=1e-8, atol=1e-9 * scale)
    assert sol.evaluation.touchdown == pytest.approx(ref["grounded_length"], rel=1e-9)
    if ref["slope_deg"] == 0.0:                  # MoorPy's sloped stiffness leaves out the touchdown's motion
        np.testing.assert_allclose(sol.stiffness, ref["stiffness"], rtol=1e-7)


def test_the_jacobian_of_a_piecewise_line_is_its_finite_difference():
    """Pieces of three line types with a clump and a float, friction and slope: d(x, z)/d(H, V_B)
    and the anchor force's derivatives against central differences (away from the kinks)."""
    pieces = Pieces([200.0, 150.0, 300.0], [900.0, -200.0, 400.0], [5e8, 1e8, 3e8], [3e4, -1e4])
    cases = [(None, 2e5, 3e5), (None, 3e4, 2e4), (Ground(0.0, 0.5), 5e4, 1.5e5), (Ground(0.0, 0.5), 3e4, 2e4),
             (Ground(0.05, 0.3), 5e4, 1.5e5), (Ground(-0.03, 1.0), 3e4, 2e4)]
    for ground, H, VB in cases:
        ev = end_position(H, VB, pieces, ground)
        fd, fd_anchor = np.zeros((2, 2)), np.zeros((2, 2))
        for k, (dh, dv) in enumerate(((1e-5 * H, 0.0), (0.0, 1e-5 * VB))):
            a, b = end_position(H + dh, VB + dv, pieces, ground), end_position(H - dh, VB - dv, pieces, ground)
            fd[:, k] = [(a.x - b.x) / (2 * (dh + dv)), (a.z - b.z) / (2 * (dh + dv))]
            fd_anchor[:, k] = (a.anchor - b.anchor) / (2 * (dh + dv))
        np.testing.assert_allclose(ev.jacobian, fd, rtol=1e-6, atol=1e-9 * np.max(np.abs(fd)))
        np.testing.assert_allclose(ev.anchor_jacobian, fd_anchor, rtol=1e-6, atol=1e-7)


def test_a_buoyant_stretch_on_the_seabed_is_refused():
    pieces = Pieces([300.0, 100.0, 300.0], [900.0, -2000.0, 900.0], [5e8] * 3, [0.0, 0.0])
    with pytest.raises(LiftedLoop, match="lifted loop"):
        end_position(1e5, 2.0e5, pieces, Ground())


# --- systems against MoorPy --------------------------------------------------------------

def _system(name):
    ref = REFERENCE["systems"][name]
    return ref, solve_statics(load(ROOT / ref["case"]))


@pytest.mark.parametrize("name", sorted(REFERENCE["systems"]))
def test_a_mooring_system_matches_moorpy(name):
    """Fairlead and anchor tensions, grounded lengths, anchor forces, body offset and attitude,
    and the mooring stiffness, against MoorPy's solveEquilibrium (stored)."""
    ref, result = _system(name)
    for cable, expected in ref["cables"].items():
        mine = result.cables[cable]
        assert mine.tension[0] == pytest.approx(expected["tension_from"], rel=1e-7)
        assert mine.tension[-1] == pytest.approx(expected["tension_to"], rel=1e-7)
        assert mine.grounded_length == pytest.approx(expected["grounded_length"], abs=1e-5)
    for anchor, force in ref["anchors"].items():
        np.testing.assert_allclose(result.anchor_forces[anchor], force, atol=1e-7 * np.linalg.norm(force))
    for node, r in ref["nodes"].items():
        position = result.bodies.get(node, result.points.get(node))
        np.testing.assert_allclose(position, r[:3], atol=1e-5)
        if len(r) == 6:
            np.testing.assert_allclose(result.attitudes[node], r[3:], atol=1e-7)
        K = np.asarray(ref["stiffness"][node])
        np.testing.assert_allclose(result.stiffness[node][:len(K), :len(K)], K, atol=1e-5 * np.max(np.abs(K)))


@pytest.mark.parametrize("name", ["buoy_spread_mooring", "three_leg_vessel_v1"])
def test_kanat_statics_of_a_moordyn_file_matches_moorpy(name, tmp_path):
    """The user's path: ``kanat statics FILE.dat -o OUT.nc``, against MoorPy on the same file."""
    ref = REFERENCE["systems"][name]
    out = tmp_path / "out.nc"
    result = CliRunner().invoke(app, ["statics", str(ROOT / ref["case"]), "-o", str(out)])
    assert result.exit_code == 0, result.output
    ds = read_result(out)
    assert ds.attrs["status"] == "ok"
    for cable, expected in ref["cables"].items():
        tension = ds.tension.values[ds.cable.values == cable]
        assert tension[[0, -1]] == pytest.approx([expected["tension_from"], expected["tension_to"]], rel=1e-7)
        assert float(ds.seabed_contact_length.values[list(ref["cables"]).index(cable)]) == pytest.approx(
            expected["grounded_length"], abs=1e-5)
    for anchor, force in ref["anchors"].items():
        np.testing.assert_allclose(ds.anchor_force.sel(anchor=anchor).values, force, atol=1e-7 * np.linalg.norm(force))
    for body, r in ref["nodes"].items():
        np.testing.assert_allclose(ds.body_position.sel(body=body).values, r[:3], atol=1e-5)


def test_a_float_that_would_surface_is_refused_with_the_reason(tmp_path):
    result = CliRunner().invoke(app, ["statics", str(DATA / "moordyn" / "float_surfaces.dat"), "-o",
                                      str(tmp_path / "out.nc")])
    assert result.exit_code != 0
    assert "point3" in result.output and "above the water surface" in " ".join(result.output.split())
    assert read_result(tmp_path / "out.nc").attrs["status"].startswith("failed")


# --- internal consistency ------------------------------------------------------------------

def test_the_network_jacobian_is_its_finite_difference():
    """dR/dq of the 6-DOF platform (fairlead offsets, weight and buoyancy levers, heave spring)
    away from equilibrium, against central differences."""
    problem = network_problem(load(DATA / "moorpy" / "platform_4leg.yaml"))
    assert_network_jacobian_is_its_central_difference(problem, np.array([12.0, -7.0, 1.5, 0.02, -0.03, 0.1]),
                                                      rtol=2e-5)


def test_the_stiffness_is_the_slope_of_the_equilibrium():
    """A small extra load on the buoy moves it by the inverse of the reported stiffness."""
    path = DATA / "moorpy" / "buoy_two_line_types_clumps.yaml"
    base = solve_statics(load(path))
    K = base.stiffness["buoy"][:3, :3]
    for k in range(3):
        push = np.array([20000.0, 10000.0, 0.0])
        push[k] += 100.0
        moved = solve_statics(load(path, **{"bodies.buoy.force": push.tolist()}))
        np.testing.assert_allclose(moved.bodies["buoy"] - base.bodies["buoy"], 100.0 * np.linalg.inv(K)[:, k],
                                   rtol=2e-3, atol=1e-6)


def test_sections_and_attachments_are_cables_joined_at_points():
    """Legs written with sections and a clump attachment, and the same as two cables joined
    at a network point that carries the clump, give one equilibrium."""
    path = DATA / "moorpy" / "buoy_two_line_types_clumps.yaml"
    sections = solve_statics(load(path))
    data = yaml.safe_load(path.read_text())
    data["points"] = {}
    cables = []
    for cable in data["cables"]:
        n = cable["name"][-1]
        data["points"][f"clump{n}"] = {"mass": 6000.0, "force": [0.0, 0.0, -50000.0 + 6000.0 * 9.81]}
        data["bodies"].pop(f"clump{n}")
        cables += [{"name": f"a{n}", "line_type": "chain", "length": 449, "segments": 1, "from": cable["from"],
                    "to": {"point": f"clump{n}"}},
                   {"name": f"b{n}", "from": {"point": f"clump{n}"}, "to": "buoy",
                    "sections": [{"line_type": "chain", "length": 1, "segments": 1},
                                 {"line_type": "wire", "length": 300, "segments": 1}]}]
    data["cables"] = cables
    points = solve_statics(load(data))
    np.testing.assert_allclose(points.bodies["buoy"], sections.bodies["buoy"], atol=1e-7)
    for n in "123":
        assert points.cables[f"a{n}"].tension[0] == pytest.approx(sections.cables[f"leg{n}"].tension[0], rel=1e-9)
        assert points.cables[f"b{n}"].tension[-1] == pytest.approx(sections.cables[f"leg{n}"].tension[-1], rel=1e-9)
        assert points.cables[f"a{n}"].grounded_length == pytest.approx(sections.cables[f"leg{n}"].grounded_length)


def test_the_example_buoy_balances_and_its_anchors_feel_the_friction_drop():
    """examples/mooring_3leg.yaml: heave balance with the waterplane, equal legs, and each
    anchor's pull is the touchdown tension less the friction of the grounded chain
    (Jonkman 2007 eq. 2-7: H_A = H - CB w L_B, H the fairlead's horizontal tension)."""
    case = load(ROOT / "examples" / "mooring_3leg.yaml")
    result = solve_statics(case)
    body = case.bodies["buoy"]
    z = result.bodies["buoy"][2]
    heave = body.net_buoyancy - 1025 * 9.81 * body.waterplane_area * z + result.body_forces["buoy"][2]
    assert abs(heave) < 1e-6 * body.net_buoyancy
    C = body.hydrostatic_stiffness_matrix(1025, 9.81)            # the levers are on the axis: no moment
    z_body = fairlead_rotation(result.attitudes["buoy"])[0][:, 2]   # the righting moment of the tilt, C44 = C55
    np.testing.assert_allclose(result.body_moments["buoy"], C[3, 3] * np.cross([0.0, 0.0, 1.0], z_body), atol=1e-6)
    w = (115.0 - 1025 * math.pi / 4 * 0.137**2) * 9.81
    tensions = [c.tension[-1] for c in result.cables.values()]
    assert max(tensions) - min(tensions) < 1e-6 * max(tensions)
    for name, cable in result.cables.items():
        H = cable.tension[-1] * math.cos(cable.angle[-1])
        anchor = np.linalg.norm(result.anchor_forces[f"{name}.from"])
        assert anchor == pytest.approx(H - 0.2 * w * cable.grounded_length, rel=1e-9)
        assert 0.0 < anchor < 0.5 * H


def test_an_anchor_relieved_by_friction_says_what_it_could_feel_without(tmp_path):
    """The friction drop above is a convention (friction fully mobilized towards the anchor): each
    anchor's note gives the drop ``CB w L_B`` and the touchdown's ``H``, which a line laid otherwise
    puts on its anchor (MoorDyn's dynamic start on its WD0200 chain: 1408 kN against statics' 906 kN);
    written in the result's ``notes``. Without friction, no note."""
    case = load(ROOT / "examples" / "mooring_3leg.yaml")
    result = solve_statics(case)
    w = (115.0 - 1025 * math.pi / 4 * 0.137**2) * 9.81
    assert len(result.notes) == len(result.cables) == 3
    for (name, cable), note in zip(result.cables.items(), result.notes):
        H = cable.tension[-1] * math.cos(cable.angle[-1])
        assert note.startswith(f"anchor {name}.from: seabed friction (coefficient 0.2) on the "
                               f"{cable.grounded_length:.4g} m of '{name}'")
        assert f"takes {0.2 * w * cable.grounded_length / 1e3:.4g} kN off the {H / 1e3:.4g} kN" in note
        assert note.endswith(f"pulls its anchor with up to {H / 1e3:.4g} kN")
    out = CliRunner().invoke(app, ["statics", str(ROOT / "examples" / "mooring_3leg.yaml"), "-o",
                                   str(tmp_path / "s.nc")])
    assert out.exit_code == 0 and out.output.count("note: anchor") == 3
    assert read_result(tmp_path / "s.nc").attrs["notes"] == "; ".join(result.notes)
    frictionless = solve_statics(case.replace({"environment.seabed.friction": 0.0}))
    assert frictionless.notes == ()


def test_lines_on_a_sloped_seabed_lie_on_it_and_hold_the_platform():
    """A 6-DOF platform on four chains over a seabed rising 2 deg towards +x: every grounded node
    lies on the sloped plane, the suspended ones above it; the platform's forces and moments
    balance; the anchor up the slope carries its grounded chain's weight along the slope too
    (the tension grows by w sin(alpha) per metre towards it), and pulls along the slope."""
    case = load(DATA / "network" / "platform_4leg_slope.yaml")
    result = solve_statics(case)
    seabed = 2.0 * math.pi / 180.0
    for cable in result.cables.values():
        floor = -180.0 + cable.position[:, 0] * math.tan(seabed)
        grounded = cable.s <= cable.grounded_length
        np.testing.assert_allclose(cable.position[grounded, 2], floor[grounded], atol=1e-8)
        assert np.all(cable.position[~grounded, 2] > floor[~grounded] - 1e-8)
    body = case.bodies["platform"]
    r, angles = result.bodies["platform"], result.attitudes["platform"]
    weight, up = body.mass * 9.81, np.array([0.0, 0.0, 1.0])
    R = fairlead_rotation(angles)[0]
    force = result.body_forces["platform"] + body.force + (body.buoyancy(9.81) - weight) * up \
        - body.hydrostatic_stiffness_matrix(1025, 9.81)[:3, :3] @ r
    moment = result.body_moments["platform"] + np.cross(R @ body.center_of_gravity, -weight * up) \
        + np.cross(R @ body.center_of_buoyancy, body.buoyancy(9.81) * up)
    assert np.max(np.abs(force)) < 1e-6 * body.buoyancy(9.81)
    assert np.max(np.abs(moment)) < 1e-6 * body.buoyancy(9.81)
    up, down = result.anchor_forces["leg1.from"], result.anchor_forces["leg3.from"]
    assert np.linalg.norm(up) > np.linalg.norm(down)         # the anchor up the slope holds its chain from sliding
    assert up[2] / np.hypot(*up[:2]) == pytest.approx(-math.tan(seabed), rel=1e-9)     # along the slope, down it
    assert down[2] / np.hypot(*down[:2]) == pytest.approx(math.tan(seabed), rel=1e-9)


def test_load_continuation_finds_the_equilibrium_from_a_far_guess():
    """From a guess 200 m off, where Newton's method alone is not trusted, the load
    continuation (R = (1 - lambda) R0, lambda 0 -> 1) ends at Newton's equilibrium."""
    case = load(DATA / "moorpy" / "buoy_two_line_types_clumps.yaml")
    problem = network_problem(case)
    scale, tolerance = _scales(problem)
    q, _, stages, _ = _continuation(problem, first_guess(problem) + np.array([150.0, -100.0, 0.0]), scale,
                                    tolerance, _caps(problem))
    assert stages >= 2
    np.testing.assert_allclose(q, solve_statics(case).bodies["buoy"], atol=1e-7)


# --- the lumped model, where nothing touches the seabed -------------------------------------

def test_the_lumped_equilibrium_converges_to_network_statics_at_second_order():
    """A buoy on a riser from a junction of three legs, no seabed: the lumped network's
    equilibrium at 10, 20 and 40 segments per cable approaches the catenary network's
    positions and riser tension, the error falling fourfold per halving."""
    from kanat.lumped.equilibrium import equilibrium
    from kanat.lumped.network import build_network

    text = (DATA / "network" / "subsurface_bridle.yaml").read_text()
    exact = solve_statics(load(text))
    errors = []
    for segments in (10, 20, 40):
        case = load(text.replace("segments: 40", f"segments: {segments}"))
        net = build_network(case)
        x, _ = equilibrium(net, case)
        errors.append(max(np.linalg.norm(x[net.body_node[0]] - exact.bodies["buoy"]),
                          np.linalg.norm(x[net.names["junction"]] - exact.points["junction"])))
    assert errors[-1] < 0.02                                  # m, on 450 m of lines
    for coarse, fine in zip(errors, errors[1:]):
        assert 3.5 < coarse / fine < 4.5


def test_the_lumped_equilibrium_on_the_seabed_converges_to_network_statics():
    """Three chain legs lying 448 m on the seabed: the lumped equilibrium with seabed contact
    at 20, 40 and 80 segments per leg approaches network statics' buoy height and fairlead
    tension at second order."""
    from kanat.lumped.equilibrium import equilibrium
    from kanat.lumped.network import build_network

    text = (DATA / "network" / "buoy_3leg_seabed.yaml").read_text()
    exact = solve_statics(load(text))
    errors = []
    for segments in (20, 40, 80):
        case = load(text.replace("segments: 40", f"segments: {segments}"))
        net = build_network(case)
        x, _ = equilibrium(net, case)
        errors.append(abs(x[net.body_node[0]][2] - exact.bodies["buoy"][2]))
    assert errors[-1] < 0.03                                   # m, of a 104 m rise
    for coarse, fine in zip(errors, errors[1:]):
        assert 3.5 < coarse / fine < 4.5


@pytest.mark.slow
def test_a_network_in_a_current_goes_to_the_lumped_equilibrium():
    """The catenary carries no drag: for a network in a current the front door solves the
    lumped model's equilibrium. A buoy written as a network point on a riser in a current
    (a network case) converges, at second order in the segments, to the same buoy written as
    a body, which the shooting solver takes as one continuous cable."""
    case = textwrap.dedent("""\
        model: statics
        environment: {current: {velocity: [0.6, 0.0, 0.0]}}
        line_types: {wire: {diameter: 0.016, mass: 1.0, axial_stiffness: 1.3e7, drag_normal: 1.2,
                            drag_tangential: 0.01}}
        bodies: {buoy: {mass: 900, net_buoyancy: 8500, drag_area: 0.88}}
        cables:
          - {name: riser, line_type: wire, length: 400, segments: 80, from: "anchor:[0, 0, -500]", to: buoy}
        """)
    exact = kanat.solve_statics(load(case)).body_position.sel(body="buoy").values
    volume = (8500 + 900 * 9.81) / (1025 * 9.81)
    point = case.replace("bodies: {buoy: {mass: 900, net_buoyancy: 8500, drag_area: 0.88}}",
                         f"points: {{buoy: {{mass: 900, volume: {volume!r}, drag_area: 0.88}}}}")
    errors = []
    for segments in (10, 20):
        ds = kanat.solve_statics(load(point.replace("segments: 80", f"segments: {segments}")))
        assert ds.attrs["status"] == "ok" and ds.attrs["scheme"] == "lumped equilibrium"
        errors.append(np.linalg.norm(ds.point_position.sel(point="buoy").values - exact))
    assert exact[0] > 50.0                                      # carried 53 m downstream
    assert errors[-1] < 0.02 and 3.5 < errors[0] / errors[1] < 4.5


def test_a_network_on_the_seabed_in_a_current_reports_its_grounded_length_and_anchor_pull():
    """The three-leg buoy on the seabed in a faint current (1 mm/s) goes to the lumped model's
    equilibrium; its seabed contact length (half an element per touching node: first order)
    and anchor forces (second order) converge to network statics' catenary without current,
    and the seabed, not the anchor, carries the resting chain's weight (no uplift)."""
    text = (DATA / "network" / "buoy_3leg_seabed.yaml").read_text()
    exact = kanat.solve_statics(load(text))
    grounded, pull = [], []
    for segments in (20, 40, 80):
        data = yaml.safe_load(text.replace("segments: 40", f"segments: {segments}"))
        data["environment"]["current"] = {"velocity": [1.0e-3, 0.0, 0.0]}
        ds = kanat.solve_statics(load(data))
        assert ds.attrs["status"] == "ok" and ds.attrs["scheme"] == "lumped equilibrium"
        grounded.append(np.max(np.abs(ds.seabed_contact_length.values - exact.seabed_contact_length.values)))
        assert grounded[-1] < 640.0 / segments                         # within an element
        force = ds.anchor_force.values
        pull.append(np.max(np.abs(force[:, :2] - exact.anchor_force.values[:, :2])))
        assert np.all(np.abs(force[:, 2]) < 1e-4 * np.abs(force[:, 0]))
    assert all(1.7 < a / b < 2.3 for a, b in zip(grounded, grounded[1:]))
    assert all(3.5 < a / b < 4.5 for a, b in zip(pull, pull[1:]))


@pytest.mark.parametrize("length", [40.0, 80.0])
def test_a_network_in_a_current_never_leaves_a_float_above_the_water(length):
    """A float on two taut ropes from anchors 50 m down and 40 m apart, in a faint current (the
    lumped equilibrium): it stands at z = -50 + sqrt(L^2 - 20^2). On 40 m ropes that is 15.36 m
    under water (ok); on 80 m ropes it would be 27.46 m above it, still buoyed by the model: an
    error saying so, not a result."""
    data = {"name": "float-network", "model": "statics",
            "environment": {"current": {"velocity": [0.1, 0.0, 0.0]}},
            "line_types": {"rope": {"diameter": 0.02, "mass": 0.3, "axial_stiffness": 1.0e8, "drag_normal": 1.2}},
            "bodies": {"float": {"mass": 100.0, "net_buoyancy": 5000.0, "drag_area": 0.5}},
            "cables": [{"name": name, "line_type": "rope", "length": length, "segments": 8,
                        "from": f"anchor:[{x}, 0, -50]", "to": "float"} for name, x in (("a", -20), ("b", 20))]}
    height = -50.0 + math.sqrt(length ** 2 - 20.0 ** 2)
    if height < 0:
        ds = kanat.solve_statics(load(data))
        assert ds.attrs["scheme"] == "lumped equilibrium"
        assert ds.body_position.values[0, 2] == pytest.approx(height, abs=0.01)
    else:
        with pytest.raises(SolverError, match=f"body 'float' is {height:.4g} m above the water surface"):
            kanat.solve_statics(load(data))


def test_statics_refuses_what_the_table_says():
    """A network in a current over a seabed, which the lumped equilibrium cannot take yet, and
    a nonlinear elastic law: errors at their keys, from the support table and the solver alike."""
    from kanat.model import Case

    data = yaml.safe_load((DATA / "moorpy" / "buoy_two_line_types_clumps.yaml").read_text())
    data["environment"]["current"] = {"velocity": [0.5, 0.0, 0.0]}
    case = Case.model_validate(data)
    keys = {p.key for p in unsupported(case, "statics") if p.severity == "error"}
    assert "environment.depth" in keys                 # rigid in statics, the default compliant one in the lumped model
    with pytest.raises(CaseError, match="lumped model's equilibrium"):
        solve_statics(case)
    del data["environment"]["current"]
    data["line_types"]["wire"]["elastic_law"] = {"polynomial": [4.0e8, 1.0e9]}
    nonlinear = Case.model_validate(data)
    assert [p.key for p in unsupported(nonlinear, "statics") if p.severity == "error"] == \
        ["line_types.wire.elastic_law"]
    with pytest.raises(CaseError, match="nonlinear elastic law"):
        solve_statics(nonlinear)


def test_a_line_touching_down_between_suspended_ends_is_refused():
    case = load(textwrap.dedent("""\
        model: statics
        environment: {depth: 100}
        line_types: {chain: {diameter: 0.1, mass: 60, axial_stiffness: 5e8}}
        cables:
          - {name: sag, line_type: chain, length: 400, segments: 40,
             from: "anchor:[0, 0, -90]", to: "anchor:[160, 120, -90]"}
        """))
    with pytest.raises(SolverError, match="below the seabed"):
        solve_statics(case)


def test_a_network_takes_no_single_cable_method():
    with pytest.raises(SolverError, match="use auto or catenary"):
        solve_statics(load(ROOT / "examples" / "mooring_3leg.yaml"), "shooting")


SLACK_LINE = """MoorDyn Input File
a chain longer than the way down and across: it lies slack on the seabed
----------------------- LINE TYPES ------------------------------------------
Name  Diam  MassDen  EA       BA/-zeta   EI    Cd    Ca   CdAx   CaAx
(-)   (m)   (kg/m)   (N)      (N-s/-)   (-)   (-)   (-)   (-)   (-)
main  0.2  500.00  2.0E+09  -1        0     1    0.27  1      0.20
---------------------- POINTS --------------------------------
Node Type      X     Y      Z     M    V   CdA   CA
(-)  (-)      (m)   (m)    (m)   (kg) (m^3)  (m^2) (-)
1   Fixed  -400.0   0.0  -300.0    0    0    0    0
2   Coupled   0.0   0.0     0.0    0    0    0    0
---------------------- LINES --------------------------------------
Line  LineType NodeAnch  NodeFair UnstrLen  NumSegs    Flags/Outputs
(-)   (-)      (-)       (-)      (m)       (-)        (-)
1     main      1         2       890.00    40          -
---------------------- SOLVER OPTIONS ---------------------------------------
300      WtrDpth
3.0e6    kbot
3.0e5    cbot
------------------------- need this line --------------------------------------
"""


def test_a_line_slack_on_the_seabed_ends_at_its_fairlead(tmp_path):
    """MoorPy's case5 (890 m of chain from an anchor 400 m away and 300 m down): it hangs straight down
    from the fairlead and lies on the seabed, the 190 m it has more than the way along the seabed piled
    under the fairlead, as MoorPy lays it. The profile ran 190 m past the fairlead (laid out straight
    along the seabed), status ok; its tensions were right."""
    path = tmp_path / "slack.dat"
    path.write_text(SLACK_LINE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = solve_statics(load(path))
    cable = result.cables["line1"]
    np.testing.assert_allclose(cable.position[0], [-400.0, 0.0, -300.0], atol=1e-9)
    np.testing.assert_allclose(cable.position[-1], [0.0, 0.0, 0.0], atol=1e-9)
    assert np.all((cable.x >= -400.0 - 1e-9) & (cable.x <= 1e-9))
    grounded = cable.s <= cable.grounded_length
    np.testing.assert_allclose(cable.z[grounded], -300.0, atol=1e-9)
    np.testing.assert_allclose(cable.x[~grounded], 0.0, atol=1e-9)        # hanging plumb under the fairlead
    w = (500.0 - 1025.0 * math.pi / 4 * 0.2**2) * 9.80665
    assert cable.tension[-1] == pytest.approx(w * 300.0, rel=1e-3)          # the plumb 300 m (stretch 7e-4)


W_SHAPE = SLACK_LINE.replace("""1   Fixed  -400.0   0.0  -300.0    0    0    0    0
2   Coupled   0.0   0.0     0.0    0    0    0    0""", """1   Fixed  -400.0   0.0     0.0    0    0    0    0
2   Free      0.0   0.0  -100.0    0   200   0    0
3   Free      0.0 200.0  -200.0    0    0    0    0
4   Fixed     0.0 400.0     0.0    0    0    0    0""").replace(
    """1     main      1         2       890.00    40          -""",
    """1     main      1         2       660.00    20          -
2     main      2         3       330.00    10          -
3     main      3         4       330.00    10          -""")


def test_a_line_touching_down_between_suspended_ends_reports_its_end_tensions(tmp_path):
    """MoorPy's W-shaped case6 (two lines from surface anchors 400 m apart touch down on the way to a float
    of 200 m^3 between them), solved by the lumped model's equilibrium at the file's segments: the anchor's
    end tension is the line's tension there (linearly extrapolated, within 0.1 % of the anchor's force;
    the end element's tension read 5 % low), within 1 % of the continuous elastic catenary worked out by
    symmetry (each half from its anchor to the float, which carries half the float's buoyancy)."""
    from scipy.optimize import brentq

    path = tmp_path / "w.dat"
    path.write_text(W_SHAPE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.api.solve_statics(load(path))
    rho, g, EA = 1025.0, 9.80665, 2.0e9
    w = (500.0 - rho * math.pi / 4 * 0.2**2) * g

    def rise(H, V):                 # elastic catenary from a horizontal touchdown to tension (H, V)
        return H / w * (math.hypot(1.0, V / H) - 1.0) + V**2 / (2 * w * EA)

    def run(H, V):
        return H / w * math.asinh(V / H) + H * V / (w * EA)

    def gap(H):                     # the half's horizontal reach against its span, sqrt(2) 200 m
        V1 = brentq(lambda V: rise(H, V) - 300.0, 1.0, 1e9)
        V2 = rho * g * 200.0 / 2
        grounded = 660.0 - V1 / w - V2 / w
        return run(H, V1) + grounded * (1 + H / EA) + run(H, V2) - math.hypot(200.0, 200.0)

    H = brentq(gap, 1e3, 5e6)
    exact = math.hypot(H, brentq(lambda V: rise(H, V) - 300.0, 1.0, 1e9))
    end = ds.tension.values[ds.cable.values == "line1"][0]
    assert end == pytest.approx(np.linalg.norm(ds.anchor_force.sel(anchor="line1.from").values), rel=1e-3)
    assert end == pytest.approx(exact, rel=0.01)                   # -0.7 % at 20 segments
    assert "tensions converge as the segments are refined" in ds.attrs["notes"]
