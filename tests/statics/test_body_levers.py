"""The weight and buoyancy of a 6-DOF body with its centres off its axis, in network statics, in MoorPy
1.3 run live and in the lumped model's equilibrium (kanat.physics.hydrostatics eq. 3, which both kanat
models share).

The buoy of examples/mooring_3leg.yaml (frictionless: MoorPy's ``System`` applies none) with its
centre of gravity moved off its axis, described two ways:

* ``metacentric``: on its waterplane with metacentric heights (``C44 = C55 = B GM``), centres of
  gravity and buoyancy off the axis: the metacentric height holds their vertical levers, their
  horizontal offsets trim the buoy by degrees. MoorPy: buoyancy at the metacentre above the centre
  of buoyancy (tests/moorpy_systems.py).
* ``heave_spring``: a waterplane without metacentric heights, ``hydrostatic_stiffness [0, 0,
  rho g A_w, 0, 0, 0]``, centre of buoyancy above the centre of gravity: weight and buoyancy turn
  the buoy at their centres, which restore and trim it. MoorPy: buoyancy at the centre of buoyancy.

Statics and MoorPy agree to round-off, also with the system turned about the vertical (the
offsets turn with the buoy's heading). The lumped model's equilibrium (64 segments per leg) lies
within its discretization error of statics (measured: 1.1 mm, 2.1e-5 rad on a trim of 3 to 4 deg;
before eq. 3 was shared the lumped model left both buoys level, 3.2 and 3.9 deg away).
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import kanat
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import build_network
from kanat.statics import solve_statics
from kanat.statics.network import assemble
from kanat.statics.network_setup import network_problem

from helpers import ROOT

WATERPLANE = 19.63                   # m^2, examples/mooring_3leg.yaml
DESCRIPTIONS = {
    "metacentric": {"bodies.buoy.center_of_gravity": [0.6, -0.3, -2.0],
                    "bodies.buoy.center_of_buoyancy": [0.1, 0.0, -2.5]},
    "heave_spring": {"bodies.buoy.center_of_gravity": [0.4, 0.2, -2.5],
                     "bodies.buoy.center_of_buoyancy": [0.0, 0.0, -1.0],
                     "bodies.buoy.waterplane_area": None, "bodies.buoy.metacentric_heights": None,
                     "bodies.buoy.hydrostatic_stiffness": [0.0, 0.0, 1025 * 9.81 * WATERPLANE, 0.0, 0.0, 0.0]},
}


def off_axis_buoy(description: str, degrees: float = 0.0):
    """The frictionless buoy of ``description``, with its anchors and heading turned by ``degrees``."""
    angle = math.radians(degrees)
    turn = np.array([[math.cos(angle), -math.sin(angle), 0.0], [math.sin(angle), math.cos(angle), 0.0],
                     [0.0, 0.0, 1.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(ROOT / "examples" / "mooring_3leg.yaml", solver="statics")
    changes = {"environment.seabed.friction": 0.0, "bodies.buoy.orientation_deg": [0.0, 0.0, degrees],
               **DESCRIPTIONS[description]}
    for k, cable in enumerate(case.cables):
        changes[f"cables[{k}].from"] = {"anchor": (turn @ np.asarray(cable.from_.position)).tolist()}
    return case.replace(changes), turn


@pytest.mark.parametrize("description", DESCRIPTIONS)
def test_the_network_jacobian_of_an_off_axis_body_is_its_central_difference(description):
    problem = network_problem(off_axis_buoy(description, 90.0)[0])
    q = np.array([6.0, -4.0, -0.3, *np.radians([7.0, -4.0, 115.0])])
    _, J, _, _ = assemble(problem, q)
    fd = np.zeros_like(J)
    for k in range(len(q)):
        step = np.zeros(len(q))
        step[k] = 1e-6 if k < 3 else 1e-8
        fd[:, k] = (assemble(problem, q + step)[0] - assemble(problem, q - step)[0]) / (2 * step[k])
    np.testing.assert_allclose(J, fd, rtol=0, atol=2e-5 * np.max(np.abs(fd)))


@pytest.mark.parametrize("degrees", [0.0, 45.0])
@pytest.mark.parametrize("description", DESCRIPTIONS)
def test_an_off_axis_body_is_moorpys(description, degrees):
    pytest.importorskip("moorpy")
    from moorpy_systems import line_end_tensions, moorpy_system, solve

    case, _ = off_axis_buoy(description, degrees)
    result = solve_statics(case)
    ms, names = moorpy_system(case)
    solve(ms, tol=1e-10, max_iterations=5000)
    r6 = ms.bodyList[names["bodies"]["buoy"] - 1].r6
    attitude = result.attitudes["buoy"]
    assert np.hypot(*attitude[:2]) > math.radians(3.0)            # the offsets trim it by degrees
    np.testing.assert_allclose(result.bodies["buoy"], r6[:3], rtol=0, atol=1e-8)
    np.testing.assert_allclose(attitude[:2], r6[3:5], rtol=0, atol=1e-9)
    assert (attitude[2] - r6[5] + math.pi) % (2 * math.pi) - math.pi == pytest.approx(0.0, abs=1e-9)
    for cable in case.cables:
        fairlead = line_end_tensions(ms, names["lines"][cable.name])[1]
        assert result.cables[cable.name].tension[-1] == pytest.approx(fairlead, rel=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("description", DESCRIPTIONS)
def test_the_lumped_equilibrium_of_an_off_axis_body_is_network_statics(description):
    case, _ = off_axis_buoy(description)
    exact = solve_statics(case)
    net = build_network(case)
    x, _ = equilibrium(net, case)
    position, angles = x[net.rigid.ref_node[0]], x[net.rigid.rot_node[0]]
    assert np.max(np.abs(position - exact.bodies["buoy"])) < 3e-3                # m, on 640 m legs
    assert np.max(np.abs(angles - exact.attitudes["buoy"])) < 5e-5               # rad, of a 3-4 deg trim
