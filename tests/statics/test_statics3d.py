"""The 3-D single-cable statics (shooting and collocation; theory/statics.md §1, theory/moorings.md): a current rotated about the
vertical rotates the solution, an x-z current gives the planar solution, the two solvers agree, and
the seabed's friction takes MoorPy's closed form."""
import re

import numpy as np
import pytest

import kanat
from kanat.statics import solve_cable
from kanat.statics.catenary import elastic_catenary
from kanat.statics.setup import cable_problems
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3
from kanat.statics.spatial import CableBVP3, Fixed3

from helpers import EXAMPLES

SUBSURFACE = (EXAMPLES / "subsurface_mooring.yaml").read_text()
MOORING = (EXAMPLES / "mooring_current.yaml").read_text()


def rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rotated(problem: CableBVP3, R) -> CableBVP3:
    turn = lambda end: Fixed3(tuple(R @ np.asarray(end.position))) if isinstance(end, Fixed3) else end  # noqa: E731
    return CableBVP3(problem.pieces, problem.joints, turn(problem.start), turn(problem.end),
                     problem.flow.rotated(R), problem.seabed)


@pytest.mark.parametrize("example, method", [("subsurface", "shooting"), ("grounded", "shooting"),
                                             ("grounded", "collocation"),
                                             pytest.param("subsurface", "collocation", marks=pytest.mark.slow)])
def test_a_current_rotated_about_the_vertical_rotates_the_solution(example, method):
    text = SUBSURFACE if example == "subsurface" else MOORING
    problem = cable_problem3(kanat.load_case(text))
    if example == "grounded":                      # a flat seabed is symmetric about z: turn everything
        problem = CableBVP3(problem.pieces, problem.joints, problem.start, problem.end, problem.flow,
                            problem.seabed)
    R = rotation(np.radians(40.0))
    a = solve_cable3(problem, method)
    b = solve_cable3(rotated(problem, R), method)
    np.testing.assert_allclose(b.tension, a.tension, rtol=1e-9)
    span = np.max(np.linalg.norm(a.position - a.position[0], axis=1))
    assert np.max(np.abs(b.position - a.position @ R.T)) < 1e-9 * span


@pytest.mark.parametrize("example", ["mooring_current", "subsurface_buoy", "towed_body", "speed_step_2d"])
def test_an_x_z_current_gives_the_planar_statics(example):
    case = kanat.load_case((EXAMPLES / f"{example}.yaml").read_text())
    cable = case.cables[0]
    s = np.linspace(0.0, cable.length, cable.segments + 1)
    planar = solve_cable(cable_problems(case)[cable.name], "auto", s)
    spatial = solve_cable3(cable_problem3(case), "auto", s)
    np.testing.assert_allclose(spatial.tension, planar.tension, rtol=1e-8)
    assert np.max(np.abs(spatial.position - planar.position)) < 1e-8 * cable.length
    assert np.all(spatial.y == 0.0) and spatial.grounded_length == pytest.approx(planar.grounded_length, abs=1e-6)


FRICTION = re.sub(r"  current:\n    profile:.*?\n(line_types)", r"\1", MOORING, flags=re.S).replace(
    "  depth: 150\n", "  depth: 150\n  seabed: {friction: 0.6, slope_deg: 0.0}\n").replace(
    "axial_stiffness: 5.1e8", "axial_stiffness: 5.1e13")     # nearly inextensible: friction leaves the shape


@pytest.mark.parametrize("method", ["shooting", "collocation"])
def test_seabed_friction_takes_moorpys_closed_form(method):
    """Friction mobilized towards the anchor: the grounded part's tension falls by mu w per metre from the
    touchdown, ``T_anchor = max(H - mu w L_B, 0)``; the suspended part is the frictionless catenary."""
    sol = solve_cable3(cable_problem3(kanat.load_case(FRICTION)), method)
    cat = elastic_catenary(600.0, 145.0, 700.0, 981.0, 5.1e13, seabed=True, n_points=2)
    assert sol.grounded_length == pytest.approx(cat.grounded_length, rel=1e-6)
    assert sol.tension[-1] == pytest.approx(cat.tension_upper, rel=1e-7)
    assert sol.tension[0] == pytest.approx(max(cat.horizontal_tension - 0.6 * 981.0 * cat.grounded_length, 0.0),
                                           abs=1e-6 * cat.tension_upper)


def test_shooting_and_collocation_agree_on_a_sloped_frictional_seabed_in_a_sheared_current():
    text = MOORING.replace("  depth: 150\n", "  depth: 150\n  seabed: {friction: 0.3, slope_deg: 2.0}\n").replace(
        "[0, 1.0, 0, 0]", "[0, 1.0, 0.4, 0]").replace('to: "anchor:[0, 0, -5]"', 'to: "anchor:[0, 0, -5]"')
    text = text.replace('from: "anchor:[-600, 0, -150]"', f'from: "anchor:[-600, 0, {-150 - 600 * np.tan(np.radians(2)):.12f}]"')
    problem = cable_problem3(kanat.load_case(text))
    a, b = solve_cable3(problem, "shooting"), solve_cable3(problem, "collocation")
    assert a.grounded_length > 100.0
    np.testing.assert_allclose(b.tension, a.tension, rtol=1e-6)
    assert np.max(np.abs(b.position - a.position)) < 1e-6 * 700.0
    assert np.max(np.abs(a.y)) > 0.05                                       # the y current leans it over


def test_kanat_statics_solves_a_single_cable_in_a_turning_current_in_3d():
    result = kanat.solve_statics(kanat.load_case(SUBSURFACE.replace("model: continuum", "model: statics")))
    assert result.attrs["method_mooring"] == "shooting"
    buoy = result.body_position.sel(body="top_buoy").values
    assert buoy[1] > 10.0 and buoy[0] > 25.0                               # downstream of the current, in x and y
    s = result.s.values
    assert np.count_nonzero(s == 300.0) == 2                                # the float: both sides of its jump
