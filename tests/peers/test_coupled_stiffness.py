"""Mooring stiffness at the coupled vessel and its fairleads (kanat.statics.coupled).

Oracles: MoorPy 1.3 run side by side (``getCoupledStiffness``'s central differences with the
free DOFs re-equilibrated, and ``getCoupledStiffnessA``, analytic), with the vessel a coupled
body at the origin or its fairleads coupled points; and central
differences of kanat's own statics, the vessel moved by +-STEP m and +-TURN rad and the
network solved again. Three systems: a spread mooring of three catenary chains (with
seabed contact), a taut mooring of polyester legs one of which carries a subsurface buoy
(a free point), and a shared line from the vessel to a second floating body held by its
own two chains (a free 6-DOF body).
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

moorpy = pytest.importorskip("moorpy")

from moorpy_systems import moorpy_system, solve  # noqa: E402

from kanat.api import load_case  # noqa: E402
from kanat.statics.coupled import VESSEL  # noqa: E402
from kanat.statics.network import solve_network  # noqa: E402
from kanat.statics.network_result import first_guess, solve_network_case  # noqa: E402
from kanat.statics.network_setup import network_problem  # noqa: E402
from kanat.statics.offsets import displaced, vessel_load  # noqa: E402

from helpers import ROOT

STEP, TURN = 1e-3, 1e-5          # m, rad: central differences of kanat's statics (error ~ K'' STEP^2)

TAUT = """
name: taut-with-buoy
model: statics
environment: {water_density: 1025, depth: 200}
line_types:
  polyester: {diameter: 0.16, mass: 27.0, axial_stiffness: 1.5e8}
points:
  buoy: {volume: 8.0, mass: 2000.0, position: [150, 0, -100]}
cables:
  - {name: leg1a, line_type: polyester, length: 150, segments: 20, from: "anchor:[300, 0, -200]", to: buoy}
  - {name: leg1b, line_type: polyester, length: 177, segments: 20, from: buoy, to: {vessel: [30, 0, -10]}}
  - {name: leg2, line_type: polyester, length: 324, segments: 20,
     from: "anchor:[-150, 259.81, -200]", to: {vessel: [-15, 25.98, -10]}}
  - {name: leg3, line_type: polyester, length: 324, segments: 20,
     from: "anchor:[-150, -259.81, -200]", to: {vessel: [-15, -25.98, -10]}}
"""

SHARED = """
name: shared-line
model: statics
environment: {water_density: 1025, depth: 150}
line_types:
  chain: {diameter: 0.12, mass: 90.0, axial_stiffness: 7.0e8}
  rope: {diameter: 0.1, mass: 10.0, axial_stiffness: 1.0e8}
bodies:
  float2:
    dof: 6
    mass: 2.0e5
    net_buoyancy: 1.2e6
    position: [420, 0, 0]
    inertia: [1e7, 1e7, 1e7]
    center_of_gravity: [0, 0, -8]
    center_of_buoyancy: [0, 0, -4]
    hydrostatic_stiffness: [0, 0, 2.0e6, 0, 0, 0]
cables:
  - {name: shared, line_type: rope, length: 400, segments: 20, from: {vessel: [20, 0, -10]},
     to: {body: float2, offset: [-5, 0, -10]}}
  - {name: a1, line_type: chain, length: 500, segments: 20, from: "anchor:[850, 200, -150]",
     to: {body: float2, offset: [3, 3, -10]}}
  - {name: a2, line_type: chain, length: 500, segments: 20, from: "anchor:[850, -200, -150]",
     to: {body: float2, offset: [3, -3, -10]}}
  - {name: v1, line_type: chain, length: 500, segments: 20, from: "anchor:[-440, 200, -150]",
     to: {vessel: [-10, 5, -10]}}
  - {name: v2, line_type: chain, length: 500, segments: 20, from: "anchor:[-440, -200, -150]",
     to: {vessel: [-10, -5, -10]}}
"""

PENDULUM = """
name: pendulum
model: statics
environment: {water_density: 1025, depth: 200}
line_types:
  wire: {diameter: 0.05, mass: 12.0, axial_stiffness: 2.0e8}
bodies:
  weight:
    dof: 6
    mass: 2.0e4
    net_buoyancy: -1.5e5
    inertia: [1e4, 1e4, 1e4]
    center_of_gravity: [0, 0, -1]
cables:
  - {name: hang, line_type: wire, length: 60, segments: 10, from: {vessel: [5, 0, -5]},
     to: {body: weight, offset: [0, 0, 1]}}
"""

SYSTEMS = {"spread": ROOT / "examples" / "moordyn" / "three_leg_vessel_v1.dat", "taut": TAUT, "shared": SHARED}


def _case(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(SYSTEMS[name], solver="statics")


def _moorpy(case, vessel: str):
    ms, _ = moorpy_system(case, vessel=vessel)
    return solve(ms, tol=1e-10, max_iterations=20000)


def _moorpy_differences(case) -> np.ndarray:
    """MoorPy's ``getCoupledStiffness``: central differences of the lines' load on the coupled
    body with the free DOFs re-equilibrated, here with tight equilibria (1e-10) and the steps
    STEP, TURN (MoorPy's own default, 0.1 m and 0.1 rad with tolerances of 0.005, is coarse)."""
    ms = _moorpy(case, "body")
    body = ms.bodyList[0]
    K = np.zeros((6, 6))
    for j in range(6):
        loads = []
        for sign in (1.0, -1.0):
            move = np.zeros(6)
            move[j] = sign * (STEP if j < 3 else TURN)
            body.setPosition(move)
            solve(ms, tol=1e-10, max_iterations=20000)
            loads.append(body.getForces(lines_only=True))
        K[:, j] = -(loads[0] - loads[1]) / (2.0 * (STEP if j < 3 else TURN))
    return K


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_vessel_stiffness_matches_moorpys_resolved_statics(name):
    case = _case(name)
    K = solve_network_case(case).stiffness[VESSEL]
    K_mp = _moorpy_differences(case)
    np.testing.assert_allclose(K, K_mp, atol=1e-6 * np.max(np.abs(K_mp)))
    assert np.max(np.abs(K[:3, :3])) > 1e3                            # N/m: a real stiffness was compared


@pytest.mark.parametrize("name", ["spread", "taut"])
def test_vessel_stiffness_matches_moorpys_analytic_one(name):
    """MoorPy's ``getCoupledStiffnessA``. On the shared line it differs by 0.5 % in the sway-roll-yaw
    terms from MoorPy's own re-solved statics (above), which kanat matches to 3e-7: its analytic
    tangent of a pitched free body is not exact, so that system is compared above only."""
    case = _case(name)
    K = solve_network_case(case).stiffness[VESSEL]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        K_mp = _moorpy(case, "body").getCoupledStiffnessA(lines_only=False)
    np.testing.assert_allclose(K, K_mp, atol=1e-6 * np.max(np.abs(K_mp)))


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_coupled_point_stiffness_matches_moorpy(name):
    case = _case(name)
    result = solve_network_case(case)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        K_mp = _moorpy(case, "points").getCoupledStiffnessA(lines_only=False)
    for g, point in enumerate(result.coupled_points):                 # MoorPy's points in the same order
        block = K_mp[3 * g:3 * g + 3, 3 * g:3 * g + 3]
        np.testing.assert_allclose(result.stiffness[point], block, atol=1e-6 * np.max(np.abs(block)))


def _kanat_differences(case) -> np.ndarray:
    """-dQ/dc of kanat's re-solved statics, Q the lines' force and moment on the vessel."""
    problem = network_problem(case)
    base = solve_network(problem, first_guess(problem))
    K = np.zeros((6, 6))
    for j in range(6):
        loads = []
        for sign in (1.0, -1.0):
            move = np.zeros(6)
            move[j] = sign * (STEP if j < 3 else TURN)
            moved = solve_network(displaced(problem, move[:3], move[3:]), base.q)
            loads.append(np.concatenate(vessel_load(moved, move[:3])))
        K[:, j] = -(loads[0] - loads[1]) / (2.0 * (STEP if j < 3 else TURN))
    return K


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_vessel_stiffness_is_the_slope_of_kanats_statics(name):
    """Small rotations about the global axes: roll, pitch, yaw of R = Rz Ry Rx agree with them
    to first order at zero attitude, so the columns are comparable."""
    case = _case(name)
    K = solve_network_case(case).stiffness[VESSEL]
    K_fd = _kanat_differences(case)
    np.testing.assert_allclose(K, K_fd, atol=1e-5 * np.max(np.abs(K)))


def test_statics_file_holds_the_coupled_stiffness(tmp_path):
    """kanat statics writes the vessel among the bodies and its fairleads among the points."""
    from kanat.api import solve_statics

    case = _case("taut")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = solve_statics(case)
    result = solve_network_case(case)
    assert list(ds.body.values) == [VESSEL]
    assert list(ds.point.values) == ["buoy", "leg1b.to", "leg2.to", "leg3.to"]
    np.testing.assert_allclose(ds.body_stiffness.sel(body=VESSEL).values, result.stiffness[VESSEL])
    np.testing.assert_allclose(ds.point_stiffness.sel(point="leg2.to").values, result.stiffness["leg2.to"])
    np.testing.assert_allclose(ds.body_force.sel(body=VESSEL).values, result.body_forces[VESSEL])
    np.testing.assert_allclose(ds.body_position.sel(body=VESSEL).values, 0.0)


def test_a_free_body_whose_yaw_nothing_restores():
    """A weight hanging from the vessel on one wire: its yaw is free (the free tangent is
    singular). Re-balanced, it follows the fairlead wherever it moves, so the line's force on the
    vessel stays its weight: the translation stiffness is zero (the pendulum's T/L holds only with
    the weight held), and so is the re-solved statics' slope."""
    SYSTEMS["pendulum"] = PENDULUM
    try:
        case = _case("pendulum")
    finally:
        del SYSTEMS["pendulum"]
    result = solve_network_case(case)
    K = result.stiffness[VESSEL]
    pendulum = result.cables["hang"].tension[0] / 62.0                    # N/m: wire 60 m, lever 2 m
    assert np.all(np.isfinite(K))
    np.testing.assert_allclose(K[:3, :3], 0.0, atol=1e-9 * pendulum)
    np.testing.assert_allclose(_kanat_differences(case)[:3, :3], 0.0, atol=1e-4 * pendulum)
