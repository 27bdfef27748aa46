"""Several coupled bodies sharing a line (a shared-mooring array), as MoorPy 1.3 writes them.

Each layout is built with MoorPy's API (two coupled bodies, a line between them, one anchored
chain each), written with ``System.unload`` and read by kanat and by MoorPy. Oracles:

* geometry and tensions: MoorPy's equilibrium of the same file (ends to 1e-9 m, tensions 1e-6);
* the 12x12 coupled stiffness (eq. (1) of :mod:`kanat.statics.coupled`, each body about its
  reference point, small rotations about the global axes):

  - MoorPy's re-solved statics: each body moved by +-STEP m and turned by +-TURN rad about a
    global axis (its Euler angles recomputed from ``Rot(w) R0``), MoorPy's equilibrium solved
    again to 1e-10 and the lines' loads on both bodies differenced;
  - MoorPy's analytic ``getCoupledStiffnessA`` in every block but the rotation-rotation blocks
    between the two bodies, where MoorPy's analytic tangent differs from its own re-solved
    statics (and from kanat's) by up to 1.6 % of the largest term (measured: 1.6, 0.56 and 0.30 %
    on the aligned, turned and offset-heeled layouts);
  - MoorPy's own ``getCoupledStiffness`` call, which differences its Euler angles: kanat's matrix
    times the angle-rate Jacobian (to MoorPy's equilibrium tolerance);
  - central differences of kanat's own statics, each body's fairleads moved or turned alone.
"""
from __future__ import annotations

import contextlib
import io
import warnings
from dataclasses import replace

import numpy as np
import pytest

mp = pytest.importorskip("moorpy")
Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

from kanat.api import load_case, solve_statics  # noqa: E402
from kanat.io.moordyn_coupled import coupled_bodies  # noqa: E402
from kanat.statics.network import solve_network  # noqa: E402
from kanat.statics.network_result import first_guess, solve_network_case  # noqa: E402
from kanat.statics.network_setup import LineEnd, NetworkProblem, network_problem  # noqa: E402

STEP, TURN = 1e-3, 1e-5          # m, rad: central differences (error ~ K'' STEP^2)

# (r6 of body 1, r6 of body 2): reference point [m] and roll, pitch, yaw [deg]
LAYOUTS = {
    "turned": ([0, 0, 0, 0, 0, 30], [190, 20, 0, 0, 0, 200]),
    "aligned": ([0, 0, 0, 0, 0, 0], [200, 0, 0, 0, 0, 0]),
    "offset-heeled": ([-40, 25, -1, 2, -1.5, 75], [160, -15, 0.5, -1, 3, 250]),
}


def _quiet(function, *args, **kwargs):
    with contextlib.redirect_stdout(io.StringIO()):
        return function(*args, **kwargs)


def write_shared_array(layout: str, path, segments: int = 40) -> None:
    """Two coupled bodies, a 230 m chain between them, a 640 m chain from each to an anchor."""
    first, second = LAYOUTS[layout]
    ms = _quiet(mp.System, depth=150)
    ms.setLineType(dnommm=100, material="chain", name="chain")
    for x, y, z, *angles in (first, second):
        ms.addBody(-1, [x, y, z, *np.radians(angles)], m=0, v=0)
    ms.addPoint(1, [8, 2, -12], body=1)
    ms.addPoint(1, [6, -3, -12], body=2)
    ms.addLine(230, "chain", nSegs=segments, pointA=1, pointB=2)
    for body, anchor in ((1, [-600, 0, -150]), (2, [800, 0, -150])):
        ms.addPoint(1, [-8, 0, -12], body=body)
        ms.addPoint(1, anchor)
        ms.addLine(640, "chain", nSegs=segments, pointA=len(ms.pointList), pointB=len(ms.pointList) - 1)
    _quiet(ms.initialize)
    _quiet(ms.unload, str(path))


@pytest.fixture(scope="module", params=sorted(LAYOUTS))
def layout(request, tmp_path_factory):
    """``(case, MoorPy system read back from the same file at equilibrium, kanat's result)``."""
    path = tmp_path_factory.mktemp("shared") / f"{request.param}.dat"
    write_shared_array(request.param, path)
    ms = _quiet(mp.System, file=str(path))
    _quiet(ms.initialize)
    _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(path, solver="statics")
    return request.param, case, ms, solve_network_case(case)


def test_geometry_and_tensions_are_moorpys(layout):
    _, _, ms, result = layout
    for k, line in enumerate(ms.lineList):
        cable = result.cables[f"line{k + 1}"]
        np.testing.assert_allclose(cable.position[[0, -1]], [line.rA, line.rB], atol=1e-9)
        np.testing.assert_allclose([cable.tension[0], cable.tension[-1]], [line.TA, line.TB], rtol=1e-6)
    shared = np.linalg.norm(ms.lineList[0].rB - ms.lineList[0].rA)
    assert 150.0 < shared < 230.0                                  # the fairleads' true distance


def test_each_body_has_its_own_load_and_stiffness(layout):
    _, _, ms, result = layout
    assert list(result.coupled_bodies) == ["body1", "body2"]
    for b, body in enumerate(ms.bodyList):
        name = f"body{b + 1}"
        load = _quiet(body.getForces, lines_only=True)
        np.testing.assert_allclose(result.coupled_bodies[name], body.r6[:3], atol=1e-12)
        np.testing.assert_allclose(np.concatenate([result.body_forces[name], result.body_moments[name]]), load,
                                   atol=1e-8 * np.max(np.abs(load)))
        np.testing.assert_array_equal(result.stiffness[name], result.coupled_matrix[6 * b:6 * b + 6, 6 * b:6 * b + 6])


def _moorpy_global_turns(ms) -> np.ndarray:
    """-dQ/dX of MoorPy's re-solved statics, each body moved by STEP or turned by TURN about a global
    axis (module docstring); Q the lines' force and moment on both bodies about their reference points."""
    K = np.zeros((12, 12))
    for c in range(12):
        body, j = ms.bodyList[c // 6], c % 6
        r6 = body.r6.copy()
        loads = []
        for sign in (1.0, -1.0):
            moved = r6.copy()
            if j < 3:
                moved[j] += sign * STEP
            else:
                start = Rotation.from_euler("ZYX", r6[[5, 4, 3]])
                turned = Rotation.from_rotvec(sign * TURN * np.eye(3)[j - 3]) * start
                moved[[5, 4, 3]] = turned.as_euler("ZYX")
            body.setPosition(moved)
            _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
            loads.append(np.concatenate([_quiet(b.getForces, lines_only=True) for b in ms.bodyList]))
        body.setPosition(r6)
        K[:, c] = -(loads[0] - loads[1]) / (2.0 * (STEP if j < 3 else TURN))
    _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
    return K


def test_the_coupled_matrix_is_moorpys_resolved_statics(layout):
    """Measured: within 5e-10, 1.2e-10 and 8.5e-9 of the largest term (aligned, turned, offset-heeled);
    kanat's own central differences within 1.1e-10, 1.1e-10, 7.7e-10."""
    _, _, ms, result = layout
    K = _moorpy_global_turns(ms)
    np.testing.assert_allclose(result.coupled_matrix, K, atol=1e-6 * np.max(np.abs(K)))
    assert np.max(np.abs(K[:3, 6:9])) > 1e3                        # the shared line couples the bodies


def test_the_coupled_matrix_is_moorpys_analytic_one_but_its_cross_turns(layout):
    _, _, ms, result = layout
    K = _quiet(ms.getCoupledStiffnessA, lines_only=True)
    cross_turns = np.zeros((12, 12), bool)
    cross_turns[3:6, 9:12] = cross_turns[9:12, 3:6] = True
    scale = np.max(np.abs(K))
    np.testing.assert_allclose(np.where(cross_turns, 0.0, result.coupled_matrix), np.where(cross_turns, 0.0, K),
                               atol=1e-6 * scale)
    assert np.max(np.abs(result.coupled_matrix - K)[cross_turns]) < 2e-2 * scale


def _euler_rates(angles) -> np.ndarray:
    """``E`` (3, 3): the angular velocity about the global axes of unit rates of roll, pitch, yaw of
    ``R = Rz(yaw) Ry(pitch) Rx(roll)`` at ``angles`` [rad]."""
    _, pitch, yaw = angles
    cp, sp, cy, sy = np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    return np.array([[cp * cy, -sy, 0.0], [cp * sy, cy, 0.0], [-sp, 0.0, 1.0]])


def test_moorpys_own_coupled_stiffness_is_the_matrix_in_its_euler_angles(layout):
    """MoorPy's ``getCoupledStiffness`` (its own call, steps STEP and TURN) differences its Euler angles:
    its rotation columns are kanat's times the angle-rate Jacobian, ``K E``. Within 1e-5 of the largest
    term, MoorPy's equilibrium tolerance being 0.05 STEP (measured: 5.9e-6, 1.5e-6, 2.1e-6 on the
    aligned, turned and offset-heeled layouts)."""
    _, _, ms, result = layout
    J = np.eye(12)
    for b, body in enumerate(ms.bodyList):
        J[6 * b + 3:6 * b + 6, 6 * b + 3:6 * b + 6] = _euler_rates(body.r6[3:])
    K = _quiet(ms.getCoupledStiffness, dx=STEP, dth=TURN, lines_only=True)
    np.testing.assert_allclose(result.coupled_matrix @ J, K, atol=1e-5 * np.max(np.abs(K)))


def _kanat_differences(case) -> np.ndarray:
    """-dQ/dX of kanat's re-solved statics, each body's fairleads moved by STEP or turned by TURN about
    a global axis through its reference point, the other body's held."""
    bodies = coupled_bodies(case)
    problem = network_problem(case)
    base = solve_network(problem, first_guess(problem))
    owner = {}
    for line in problem.lines:
        for i, end in enumerate(line.ends):
            if end.node < 0 and end.kind == "vessel":
                owner[(line.name, i)] = next(b for b, body in enumerate(bodies)
                                             if np.min(np.max(np.abs(body.points - end.point), axis=1)) < 1e-6)

    def moved(b, j, h):
        X = bodies[b].position
        R = Rotation.from_rotvec(h * np.eye(3)[j - 3]).as_matrix() if j >= 3 else np.eye(3)
        t = h * np.eye(3)[j] if j < 3 else np.zeros(3)
        lines = [replace(line, ends=tuple(
            LineEnd(end.node, X + t + R @ (end.point - X), end.kind, end.on_seabed, end.load)
            if owner.get((line.name, i)) == b else end for i, end in enumerate(line.ends)))
            for line in problem.lines]
        return NetworkProblem(list(problem.nodes), lines, problem.seabed, problem.friction, problem.gravity), t

    def loads(solution, b, t):
        out = np.zeros((len(bodies), 6))
        for line, state in zip(solution.problem.lines, solution.lines):
            for i, end in enumerate(line.ends):
                if (line.name, i) in owner:
                    k = owner[(line.name, i)]
                    f = state.forces[i] - np.array([0.0, 0.0, end.load])
                    out[k, :3] += f
                    out[k, 3:] += np.cross(end.point - bodies[k].position - (t if k == b else 0.0), f)
        return out.ravel()

    K = np.zeros((12, 12))
    for c in range(12):
        b, j = divmod(c, 6)
        h = STEP if j < 3 else TURN
        columns = []
        for sign in (1.0, -1.0):
            moved_problem, t = moved(b, j, sign * h)
            columns.append(loads(solve_network(moved_problem, base.q), b, t))
        K[:, c] = -(columns[0] - columns[1]) / (2.0 * h)
    return K


def test_the_coupled_matrix_is_the_slope_of_kanats_statics(layout):
    _, case, _, result = layout
    K = _kanat_differences(case)
    np.testing.assert_allclose(result.coupled_matrix, K, atol=1e-6 * np.max(np.abs(K)))


def test_statics_file_holds_each_body_and_the_coupled_matrix(layout):
    _, case, _, result = layout
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = solve_statics(case)
    assert ds.attrs["status"] == "ok"
    assert [b for b in ds.body.values] == ["body1", "body2"]
    assert list(ds.coupled_dof.values[:2]) == ["body1.surge", "body1.sway"]
    np.testing.assert_allclose(ds.coupled_stiffness.values, result.coupled_matrix)
    np.testing.assert_allclose(ds.body_stiffness.sel(body="body2").values, result.coupled_matrix[6:, 6:])
    np.testing.assert_allclose(ds.body_position.sel(body="body2").values, result.coupled_bodies["body2"])
