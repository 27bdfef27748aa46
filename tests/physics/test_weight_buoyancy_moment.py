"""The moment of a 6-DOF body's weight and buoyancy (kanat.physics.hydrostatics eq. 3), which network
statics and the lumped model share, against closed forms and finite differences:

* without tilt restoring in ``C`` it is the moment of the weight at the turning centre of gravity
  and the buoyancy at the turning centre of buoyancy, ``(R c) x (-W e_z) + (R b) x (B e_z)``;
* with it (a metacentric height), at the reference attitude, it is that same moment there, for a
  tilted and yawed reference too: the trim moment of centres off the body's axis;
* with it, added to the restoring of ``C44 = C55`` about a level reference (eq. 1), it is MoorPy's
  body with its buoyancy at the metacentre ``r_M = (b_x, b_y, (C44 + W c_z) / B)``, exactly, at any
  roll, pitch and yaw (the mapping of tests/moorpy_systems.py);
* the derivative that network statics' Newton iteration uses is its central difference.
"""
import math

import numpy as np
import pytest

from kanat.physics.hydrostatics import restoring_load, weight_buoyancy_load
from kanat.physics.motion import rotation_matrix
from kanat.statics.network_setup import fairlead_rotation

WEIGHT, BUOYANCY = 5.886e5, 1.1772e6          # N: the buoy of examples/mooring_3leg.yaml
COG, COB = np.array([0.6, -0.3, -2.0]), np.array([0.1, 0.25, -2.5])   # m, off the axis
C44 = BUOYANCY * 0.9                            # N m/rad: GM 0.9 m
UP = np.array([0.0, 0.0, 1.0])
ATTITUDES = [(0.0, 0.0, 0.0), (5.0, 0.0, 30.0), (0.0, -12.0, 90.0), (20.0, -15.0, 200.0), (-8.0, 25.0, -135.0)]


def moment(angles_deg, reference_deg, held):
    R, dR = fairlead_rotation(np.radians(angles_deg))
    k0 = rotation_matrix(*np.radians(reference_deg))[2]
    return weight_buoyancy_load(R, dR, k0, COG, COB, WEIGHT, BUOYANCY, held)


def levers(R):
    """The moment of the weight and buoyancy at their centres turned by ``R``."""
    return np.cross(R @ COG, -WEIGHT * UP) + np.cross(R @ COB, BUOYANCY * UP)


@pytest.mark.parametrize("angles", ATTITUDES)
def test_without_tilt_restoring_the_whole_levers_turn(angles):
    found, _ = moment(angles, (3.0, -4.0, 50.0), 0.0)
    np.testing.assert_allclose(found, levers(rotation_matrix(*np.radians(angles))), rtol=0, atol=1e-9 * WEIGHT)


@pytest.mark.parametrize("reference", [(0.0, 0.0, 0.0), (0.0, 0.0, 120.0), (7.0, -4.0, 35.0)])
def test_with_a_metacentric_height_the_moment_at_the_reference_is_its_levers_there(reference):
    found, _ = moment(reference, reference, 1.0)
    np.testing.assert_allclose(found, levers(rotation_matrix(*np.radians(reference))), rtol=0,
                               atol=1e-9 * WEIGHT)
    assert np.linalg.norm(found) > 0.1 * WEIGHT                 # a trim moment worth the name


@pytest.mark.parametrize("reference_yaw", [0.0, 90.0, -150.0])
@pytest.mark.parametrize("angles", ATTITUDES)
def test_with_the_restoring_it_is_moorpys_body_with_its_buoyancy_at_the_metacentre(angles, reference_yaw):
    stiffness = np.diag([0.0, 0.0, 2.0e5, C44, C44, 0.0])
    R, dR = fairlead_rotation(np.radians(angles))
    restoring, _ = restoring_load(stiffness, R, dR, rotation_matrix(0.0, 0.0, math.radians(reference_yaw)),
                                  np.zeros(3), math.radians(angles[2]), math.radians(reference_yaw))
    found, _ = moment(angles, (0.0, 0.0, reference_yaw), 1.0)
    metacentre = np.array([COB[0], COB[1], (C44 + WEIGHT * COG[2]) / BUOYANCY])
    moorpy = np.cross(R @ COG, -WEIGHT * UP) + np.cross(R @ metacentre, BUOYANCY * UP)
    np.testing.assert_allclose(found + restoring[3:], moorpy, rtol=0, atol=1e-9 * WEIGHT)


@pytest.mark.parametrize("held", [0.0, 1.0])
def test_the_derivative_is_the_central_difference(held):
    angles, reference = np.array([11.0, -7.0, 140.0]), (4.0, -6.0, 20.0)
    _, jacobian = moment(angles, reference, held)
    step = 1e-6
    for j in range(3):
        shift = np.zeros(3)
        shift[j] = math.degrees(step)
        fd = (moment(angles + shift, reference, held)[0] - moment(angles - shift, reference, held)[0]) / (2 * step)
        np.testing.assert_allclose(jacobian[:, j], fd, rtol=0, atol=1e-7 * WEIGHT)
