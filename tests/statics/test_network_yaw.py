"""Network statics of a yawed 6-DOF body (kanat.statics.network, eq. 2's hydrostatic restoring from
the body's actual tilt): the same physical system turned about the vertical has the same
equilibrium turned.

The buoy of examples/mooring_3leg.yaml, pushed sideways by a constant force so that its legs pitch
and roll it by a few degrees, is turned with its anchors, its force and its hydrostatic reference
by 0, 90, 180 and 270 deg: its reference point turns with them, its roll and pitch stay, its yaw
turns by the same angle, and every tension is the same (still water and a level seabed have no
horizontal preference). Raw Euler-angle differences, ``C (Theta - Theta_0)``, fail this: at 90 deg
they restore the roll about the wrong axis, at 180 deg with the wrong sign.

The other model: the lumped model's equilibrium (the rest state of its dynamics, kanat.lumped.rigid
with the same restoring) of the frictionless buoy turned by 0, 90 and 180 deg lies within its
discretization error of network statics (64 segments per leg: 2.8 mm, 6e-6 rad, measured), and
that error turns with the system.
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

PUSH = np.array([1.5e5, 0.6e5, 0.0])      # N: a constant force on the buoy, off the legs' axes


def turned_buoy(degrees: float, friction: float = 0.2):
    """examples/mooring_3leg.yaml pushed by PUSH, everything turned by ``degrees`` about the vertical,
    with the seabed's ``friction``."""
    return turned_mooring_buoy(degrees, {"environment.seabed.friction": friction, "bodies.buoy.force": PUSH})


@pytest.fixture(scope="module")
def level():
    case, _ = turned_buoy(0.0)
    return solve_statics(case)


def test_the_push_tilts_the_buoy(level):
    """The legs pull below the waterline: the pushed buoy rolls and pitches by degrees."""
    roll, pitch, _ = np.degrees(level.attitudes["buoy"])
    assert abs(roll) > 0.5 and abs(pitch) > 0.5


@pytest.mark.parametrize("degrees", [90.0, 180.0])
def test_the_network_jacobian_of_a_yawed_tilted_buoy_is_its_finite_difference(degrees):
    """dR/dq of the turned buoy (its restoring about a yawed reference included), rolled, pitched and
    yawed away from it, against central differences."""
    case, _ = turned_buoy(degrees)
    problem = network_problem(case)
    assert_network_jacobian_is_its_central_difference(
        problem, np.array([6.0, -4.0, -0.3, *np.radians([7.0, -4.0, degrees + 25.0])]))


@pytest.mark.parametrize("degrees", [90.0, 180.0, 270.0])
def test_the_turned_system_has_the_turned_equilibrium(level, degrees):
    case, turn = turned_buoy(degrees)
    result = solve_statics(case)
    np.testing.assert_allclose(result.bodies["buoy"], turn @ level.bodies["buoy"], rtol=0, atol=1e-8)
    attitude = result.attitudes["buoy"]
    np.testing.assert_allclose(attitude[:2], level.attitudes["buoy"][:2], rtol=0, atol=1e-10)
    yaw_change = (attitude[2] - level.attitudes["buoy"][2] - math.radians(degrees) + math.pi) % (2 * math.pi) - math.pi
    assert abs(yaw_change) < 1e-10
    for name, cable in level.cables.items():
        np.testing.assert_allclose(result.cables[name].tension, cable.tension, rtol=1e-8, atol=0)
        np.testing.assert_allclose(result.anchor_forces[f"{name}.from"], turn @ level.anchor_forces[f"{name}.from"],
                                   rtol=0, atol=1e-8 * np.max(cable.tension))
    np.testing.assert_allclose(result.body_moments["buoy"], turn @ level.body_moments["buoy"], rtol=0,
                               atol=1e-8 * np.linalg.norm(level.body_moments["buoy"]))


def lumped_and_statics(degrees: float):
    """Reference point [m] and roll, pitch, yaw [rad] of the frictionless buoy turned by ``degrees``:
    the lumped model's equilibrium, then network statics'."""
    case, turn = turned_buoy(degrees, friction=0.0)
    net = build_network(case)
    x, _ = equilibrium(net, case)
    rigid = net.rigid
    exact = solve_statics(case)
    return (x[rigid.ref_node[0]], x[rigid.rot_node[0]]), (exact.bodies["buoy"], exact.attitudes["buoy"]), turn


@pytest.mark.slow
def test_the_lumped_equilibrium_of_the_turned_buoy_is_network_statics():
    (lumped_r, lumped_angles), (r, angles), _ = lumped_and_statics(0.0)
    gap, angle_gap = lumped_r - r, lumped_angles - angles
    for degrees in (90.0, 180.0):
        (turned_lumped_r, turned_lumped_angles), (turned_r, turned_angles), turn = lumped_and_statics(degrees)
        assert np.max(np.abs(turned_lumped_r - turned_r)) < 5e-3                  # m, on 640 m legs
        assert np.max(np.abs(turned_lumped_angles[:2] - turned_angles[:2])) < 2e-5   # rad
        np.testing.assert_allclose(turned_lumped_r - turned_r, turn @ gap, rtol=0, atol=1e-8)
        np.testing.assert_allclose(turned_lumped_angles - turned_angles, angle_gap, rtol=0, atol=1e-9)
