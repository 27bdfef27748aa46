"""The hydrostatic restoring of a 6-DOF body on its waterplane (kanat.lumped.rigid, module eq. 4)
is that of its tilt, whatever its yaw, against closed forms:

* the righting moment of a floating vertical cylinder tilted by ``theta`` about any horizontal
  axis, at any yaw and about a reference orientation of any yaw:
  ``|M| = (rho g (I_wp + V z_B) - m g z_G) sin(theta)`` (``I_wp = pi a^4 / 4``, ``V = pi a^2 T``,
  ``z_B = -T / 2`` for radius ``a`` and draft ``T``; ``m = rho V``), about the tilt axis, restoring;
* a waterplane force straight down, ``-rho g A_w dz``, wherever the body is moved horizontally
  from its reference and however it is tilted (buoyancy stays vertical);
* its free roll decay at yaw 0, 90, 179 and 180 deg (from a reference yaw of 0: a body that has
  turned away from its reference heading; and from a reference of that yaw): period
  ``2 pi sqrt((I_xx + A_44) / C_44) / sqrt(1 - zeta^2)`` and logarithmic decrement
  ``2 pi zeta / sqrt(1 - zeta^2)``, ``zeta = B_44 / (2 sqrt(C_44 (I_xx + A_44)))`` (rotation about
  the centre of gravity, which no horizontal force moves), and the tilt's history the same at
  every yaw to round-off;
* the linearisation of the moored buoy of examples/mooring_buoy_waves.yaml: ``K`` of the body's
  degrees of freedom symmetric, and the same for a hydrostatic reference of yaw 0 or 90 deg.
"""
import math
from pathlib import Path

import numpy as np
import pytest

import kanat
from kanat.frequency.linearize import linearize
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem
from kanat.model import Case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RHO, G = 1025.0, 9.81
RADIUS, DRAFT, Z_G = 2.0, 4.0, -2.5                      # m: a vertical cylinder, G below the waterline
VOLUME = math.pi * RADIUS ** 2 * DRAFT
I_WP = math.pi * RADIUS ** 4 / 4.0
MASS = RHO * VOLUME                                      # floating at its draft: net buoyancy 0
GM = I_WP / VOLUME - DRAFT / 2.0 - Z_G
C44 = RHO * G * (I_WP + VOLUME * (-DRAFT / 2.0)) - MASS * G * Z_G     # closed form, N m/rad
I_XX, A44, ZETA = MASS * 1.5 ** 2, 5.0e4, 0.05
B44 = 2.0 * ZETA * math.sqrt(C44 * (I_XX + A44))
TETHER = dict(diameter=0.001, mass=1e-3, weight_in_water=0.0, axial_stiffness=1.0, drag_normal=0.0,
              drag_tangential=0.0, max_strain=1.0)


def cylinder_system(reference_yaw_deg: float) -> LumpedSystem:
    """The cylinder, its reference point on the waterline's centre, reference orientation level at
    ``reference_yaw_deg``; a slack, nearly massless tether to a free end gives it a fairlead."""
    body = dict(dof=6, mass=MASS, net_buoyancy=0.0, position=[0, 0, 0], orientation_deg=[0, 0, reference_yaw_deg],
                inertia=[I_XX, I_XX, MASS * 1.0], center_of_gravity=[0, 0, Z_G],
                waterplane_area=math.pi * RADIUS ** 2, metacentric_heights=[GM, GM],
                added_mass_matrix=[0, 0, 0, A44, A44, 0], linear_damping=[0, 0, 0, B44, B44, 0])
    case = Case.model_validate(dict(
        model="lumped", line_types={"tether": TETHER}, bodies={"b": body},
        cables=[dict(name="t", line_type="tether", length=5.0, segments=1,
                     **{"from": {"body": "b", "offset": [0, 0, 0]}}, to="free")],
        simulation={"duration": 1.0, "dt": 0.01, "scheme": "rk4", "initial_state": "as_given"}))
    return LumpedSystem(build_network(case), case, waves=False)


def rotation(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def state(system, angles, shift=(0.0, 0.0, 0.0)):
    """Free coordinates and velocities (at rest) with the body (and its tether) ``shift`` from its
    reference point, turned by ``angles``."""
    x = system.net.x_guess + shift
    x[system.net.rigid.rot_node[0]] = angles
    xf = x[system.free_index]
    return xf, np.zeros_like(xf)


def loads(system, angles, shift=(0.0, 0.0, 0.0)):
    """The force and the moment about the reference point (global axes) on the body at rest,
    ``shift`` from its reference point and turned by ``angles``."""
    xf, vf = state(system, angles, shift)
    x, v, _, heading = system.full(0.0, xf, vf)
    F, _ = system.loads(0.0, x, v, heading)
    return F[system.net.rigid.ref_node[0]].copy(), F[system.net.rigid.rot_node[0]].copy()


def moment(system, angles):
    return loads(system, angles)[1]


@pytest.mark.parametrize("reference_yaw", [0.0, 90.0, 180.0])
@pytest.mark.parametrize("yaw", [0.0, 90.0, 179.0, 180.0, -135.0])
@pytest.mark.parametrize("roll, pitch", [(5.0, 0.0), (0.0, 10.0), (20.0, -15.0)])
def test_righting_moment_is_that_of_the_tilt_at_any_yaw(reference_yaw, yaw, roll, pitch):
    system = cylinder_system(reference_yaw)
    R = rotation(*np.radians([roll, pitch, yaw]))
    M = moment(system, np.radians([roll, pitch, yaw]))
    z_body, e_z = R[:, 2], np.array([0.0, 0.0, 1.0])
    tilt = math.acos(z_body[2])
    assert np.linalg.norm(M) == pytest.approx(C44 * math.sin(tilt), rel=1e-12)
    # about the tilt axis, restoring: M = C44 (z_b x e_z)
    np.testing.assert_allclose(M, C44 * np.cross(z_body, e_z), rtol=0, atol=1e-9 * C44)


@pytest.mark.parametrize("yaw", [0.0, 90.0, 180.0])
def test_buoyancy_stays_vertical_and_blind_to_the_horizontal_offset(yaw):
    """Moved 10 m in surge and 5 m in sway from its reference, pitched 4 deg and lifted 0.2 m, the
    cylinder feels the waterplane's ``-rho g A_w dz`` straight down and the righting moment of its
    tilt: still water has no horizontal preference."""
    system = cylinder_system(0.0)
    angles = np.radians([0.0, 4.0, yaw])
    force, M = loads(system, angles, shift=(10.0, 5.0, 0.2))
    heave = RHO * G * math.pi * RADIUS ** 2 * 0.2
    np.testing.assert_allclose(force, [0.0, 0.0, -heave], rtol=0, atol=1e-2)      # N: the slack tether's pull
    z_body = rotation(*angles)[:, 2]
    np.testing.assert_allclose(M, C44 * np.cross(z_body, [0.0, 0.0, 1.0]), rtol=0, atol=1e-9 * C44)


YAWS = [0.0, 90.0, 179.0, 180.0]


def roll_decay(reference_yaw, yaw, roll=3.0, duration=20.0, dt=0.01):
    """Tilt [rad] every step of a fixed-step RK4 free roll decay from ``roll`` about the body's x axis."""
    system = cylinder_system(reference_yaw)
    xf, vf = state(system, np.radians([roll, 0.0, yaw]))
    y = np.concatenate([xf.ravel(), vf.ravel()])
    rot = int(np.searchsorted(system.free_index, system.net.rigid.rot_node[0]))
    tilts = []
    for k in range(int(round(duration / dt))):
        t = k * dt
        k1 = system.rhs(t, y)
        k2 = system.rhs(t + dt / 2, y + dt / 2 * k1)
        k3 = system.rhs(t + dt / 2, y + dt / 2 * k2)
        k4 = system.rhs(t + dt, y + dt * k3)
        y = y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        R = rotation(*y[3 * rot: 3 * rot + 3])
        tilts.append(math.atan2(R[2, 1], R[2, 2]))       # the roll about the body's own x axis
    return dt * np.arange(1, len(tilts) + 1), np.array(tilts)


def peaks(t, s):
    i = np.flatnonzero((s[1:-1] > s[:-2]) & (s[1:-1] >= s[2:])) + 1
    # parabola through each peak and its neighbours
    a, b, c = s[i - 1], s[i], s[i + 1]
    shift = 0.5 * (a - c) / (a - 2 * b + c)
    return t[i] + shift * (t[1] - t[0]), b - 0.25 * (a - c) * shift


@pytest.mark.slow
@pytest.mark.parametrize("reference", ["yaw 0", "the body's yaw"])
def test_roll_decay_is_the_same_at_any_yaw(reference):
    natural = 2 * math.pi * math.sqrt((I_XX + A44) / C44)
    damped = natural / math.sqrt(1 - ZETA ** 2)
    decrement = 2 * math.pi * ZETA / math.sqrt(1 - ZETA ** 2)
    runs = {yaw: roll_decay(0.0 if reference == "yaw 0" else yaw, yaw) for yaw in YAWS}
    for yaw, (t, tilt) in runs.items():
        tp, peak = peaks(t, tilt)
        assert np.mean(np.diff(tp)) == pytest.approx(damped, rel=2e-3), f"yaw {yaw}"
        assert np.mean(np.log(peak[:-1] / peak[1:])) == pytest.approx(decrement, rel=1e-2), f"yaw {yaw}"
        np.testing.assert_allclose(tilt, runs[0.0][1], rtol=0, atol=1e-12, err_msg=f"yaw {yaw}")


def body_stiffness(reference_yaw):
    """``K`` (6, 6) of the mooring buoy's degrees of freedom (examples/mooring_buoy_waves.yaml),
    its hydrostatic reference turned to ``reference_yaw``, and its equilibrium angles [deg]."""
    case = kanat.load_case(EXAMPLES / "mooring_buoy_waves.yaml").replace(
        {"bodies.buoy.orientation_deg": [0.0, 0.0, reference_yaw]})
    lin = linearize(case)
    rigid = lin.net.rigid
    dofs = np.flatnonzero(np.isin(lin.node, [rigid.ref_node[0], rigid.rot_node[0]]))
    return lin.stiffness.toarray()[np.ix_(dofs, dofs)], np.degrees(lin.position[rigid.rot_node[0]])


@pytest.mark.slow
def test_the_linearised_stiffness_is_symmetric_and_blind_to_the_reference_heading():
    """The three legs turn the buoy back to yaw 0 from a hydrostatic reference at 90 deg: with no
    yaw stiffness of its own, the reference's heading changes nothing (the restoring acts on the
    tilt), and ``K`` is symmetric (a potential's Hessian at the equilibrium)."""
    level, angles_level = body_stiffness(0.0)
    turned, angles_turned = body_stiffness(90.0)
    np.testing.assert_allclose(angles_turned, angles_level, atol=1e-6)
    for K in (level, turned):
        assert np.linalg.norm(K - K.T) < 1e-8 * np.linalg.norm(K)
    np.testing.assert_allclose(turned, level, rtol=0, atol=1e-8 * np.linalg.norm(level))
