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

import numpy as np
import pytest

from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import build_network
from kanat.statics import solve_statics
from kanat.statics.network_setup import network_problem

from helpers import assert_network_jacobian_is_its_central_difference, turned_mooring_buoy

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
    return turned_mooring_buoy(degrees, {"environment.seabed.friction": 0.0, **DESCRIPTIONS[description]})


@pytest.mark.parametrize("description", DESCRIPTIONS)
def test_the_network_jacobian_of_an_off_axis_body_is_its_central_difference(description):
    problem = network_problem(off_axis_buoy(description, 90.0)[0])
    assert_network_jacobian_is_its_central_difference(
        problem, np.array([6.0, -4.0, -0.3, *np.radians([7.0, -4.0, 115.0])]))


@pytest.mark.parametrize("degrees", [0.0, 45.0])
@pytest.mark.parametrize("description", DESCRIPTIONS)
def test_an_off_axis_body_is_moorpys(description, degrees):
    pytest.importorskip("moorpy")
    from moorpy_systems import assert_body_is_moorpys

    case, _ = off_axis_buoy(description, degrees)
    result = solve_statics(case)
    attitude = result.attitudes["buoy"]
    assert np.hypot(*attitude[:2]) > math.radians(3.0)            # the offsets trim it by degrees
    assert_body_is_moorpys(case, result)


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
