"""The hydrostatic restoring of a 6-DOF body (kanat.physics.hydrostatics, eq. 1), as network statics
takes it, against closed forms and finite differences:

* a floating vertical cylinder tilted by ``theta`` about any horizontal axis, at any yaw and about a
  reference of any yaw, feels ``M = C44 (z_b x e_z)``: ``|M| = C44 sin(theta)`` about the tilt axis,
  restoring (``C44 = C55``);
* its waterplane force is ``-C33 dz`` straight down wherever it is moved horizontally and however
  it is tilted (buoyancy stays vertical);
* the Jacobian that network statics' Newton iteration uses is the central difference of the load,
  for a full symmetric ``C`` at a tilted, yawed attitude about a tilted, yawed reference.
"""
import math

import numpy as np
import pytest

from kanat.physics.hydrostatics import restoring_load
from kanat.physics.motion import rotation_matrix
from kanat.statics.network_setup import fairlead_rotation

C33, C44 = 2.0e5, 3.0e6                  # N/m, N m/rad
LEVEL_CYLINDER = np.diag([0.0, 0.0, C33, C44, C44, 0.0])


def load(stiffness, position, angles, reference_position, reference_angles):
    R, dR = fairlead_rotation(angles)
    return restoring_load(stiffness, R, dR, rotation_matrix(*reference_angles),
                          np.asarray(position) - reference_position, angles[2], reference_angles[2])


@pytest.mark.parametrize("reference_yaw", [0.0, 90.0, 180.0, 270.0])
@pytest.mark.parametrize("yaw", [0.0, 90.0, 179.0, 180.0, -135.0])
@pytest.mark.parametrize("roll, pitch", [(5.0, 0.0), (0.0, 10.0), (20.0, -15.0)])
def test_the_righting_moment_is_that_of_the_tilt_at_any_yaw(reference_yaw, yaw, roll, pitch):
    angles = np.radians([roll, pitch, yaw])
    force, moment = np.split(load(LEVEL_CYLINDER, np.zeros(3), angles, np.zeros(3),
                                  np.radians([0.0, 0.0, reference_yaw]))[0], 2)
    z_body, e_z = rotation_matrix(*angles)[:, 2], np.array([0.0, 0.0, 1.0])
    assert np.linalg.norm(moment) == pytest.approx(C44 * math.sin(math.acos(z_body[2])), rel=1e-12)
    np.testing.assert_allclose(moment, C44 * np.cross(z_body, e_z), rtol=0, atol=1e-9 * C44)
    np.testing.assert_allclose(force, 0.0, atol=1e-9 * C33)


@pytest.mark.parametrize("yaw", [0.0, 90.0, 180.0])
def test_the_waterplane_force_stays_vertical_and_blind_to_the_horizontal_offset(yaw):
    angles = np.radians([0.0, 4.0, yaw])
    force = load(LEVEL_CYLINDER, [10.0, 5.0, 0.2], angles, np.zeros(3), np.zeros(3))[0][:3]
    np.testing.assert_allclose(force, [0.0, 0.0, -C33 * 0.2], rtol=1e-12, atol=1e-9 * C33)


def test_the_jacobian_is_the_central_difference_of_the_load():
    rng = np.random.default_rng(3)
    C = rng.normal(size=(6, 6)) * np.array([1e5, 1e5, 1e5, 1e6, 1e6, 1e6])
    C = C + C.T
    reference, reference_angles = np.array([1.0, -2.0, 0.5]), np.radians([3.0, -2.0, 75.0])
    q = np.array([4.0, 1.0, -0.7, *np.radians([8.0, -12.0, 140.0])])
    _, J = load(C, q[:3], q[3:], reference, reference_angles)
    fd = np.zeros((6, 6))
    for k in range(6):
        step = np.zeros(6)
        step[k] = 1e-6
        fd[:, k] = (load(C, (q + step)[:3], (q + step)[3:], reference, reference_angles)[0]
                    - load(C, (q - step)[:3], (q - step)[3:], reference, reference_angles)[0]) / 2e-6
    np.testing.assert_allclose(J, fd, rtol=0, atol=1e-7 * np.max(np.abs(fd)))
