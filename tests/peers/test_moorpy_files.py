"""MoorDyn files as MoorPy 1.3 writes them (``System.unload``), read by kanat and solved side by
side with MoorPy reading the same file back.

* a free body with zero inertia (MoorPy writes I = 0): statics takes it; the dynamic models
  refuse it at its key;
* the same body with its CG 1 m below the reference point: imported with MoorDyn-C's
  ``buoyancy_at: cg`` (the importer says so); ``buoyancy_at: reference`` heels it as MoorPy does;
* two coupled bodies, turned, sharing a line (a shared-mooring array): the lines' geometry and
  tensions, and each body's stiffness against the diagonal blocks of MoorPy's coupled 12x12;
* a line touching the seabed between two suspended ends: the lumped model's equilibrium
  against MoorPy's catenary, which models the grounded middle.
"""
from __future__ import annotations

import contextlib
import io
import warnings

import numpy as np
import pytest

mp = pytest.importorskip("moorpy")

from kanat.api import load_case, solve_statics  # noqa: E402
from kanat.errors import CaseError  # noqa: E402
from kanat.model.support import require_supported  # noqa: E402
from kanat.statics.network_result import solve_network_case  # noqa: E402


def _quiet(function, *args, **kwargs):
    with contextlib.redirect_stdout(io.StringIO()):
        return function(*args, **kwargs)


def _load(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path, solver="statics")


def _reread(path):
    """MoorPy's system read back from the file it wrote, at equilibrium."""
    ms = _quiet(mp.System, file=str(path))
    _quiet(ms.initialize)
    _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
    return ms


@pytest.fixture(scope="module")
def free_body(tmp_path_factory):
    """A submerged buoy, CG 1 m below its reference point, on two chains (one off its axis: it heels)."""
    ms = _quiet(mp.System, depth=100)
    ms.setLineType(dnommm=80, material="chain", name="chain")
    ms.addBody(0, [0, 0, -20, 0, 0, 0], m=5e4, v=80.0, rCG=[0, 0, -1])
    ms.addPoint(1, [3, 0, -22], body=1)
    ms.addPoint(1, [300, 0, -100])
    ms.addLine(300, "chain", pointA=2, pointB=1)
    ms.addPoint(1, [0, 0, -24], body=1)
    ms.addPoint(1, [-200, 0, -100])
    ms.addLine(230, "chain", pointA=4, pointB=3)
    _quiet(ms.initialize)
    path = tmp_path_factory.mktemp("moorpy") / "free_body.dat"
    _quiet(ms.unload, str(path))
    return path


def test_zero_inertia_is_statics_only(free_body):
    assert "0.000e+00" in free_body.read_text()                      # MoorPy wrote I = 0
    case = _load(free_body)
    assert not case.bodies["body1"].has_inertia
    require_supported(case, "statics")
    with pytest.raises(CaseError, match="bodies.body1.inertia") as error:
        require_supported(case, "lumped")
    assert "moments of inertia" in str(error.value)


def test_buoyancy_at_the_reference_point_heels_as_moorpy(free_body):
    ms = _reread(free_body)
    assert np.allclose(ms.bodyList[0].rM, 0.0) and ms.bodyList[0].rCG[2] == -1.0
    case = _load(free_body)
    assert case.bodies["body1"].buoyancy_at == "cg"                 # MoorDyn-C's convention, imported
    moorpy_pitch = ms.bodyList[0].r6[4]
    as_moorpy = solve_network_case(case.replace({"bodies.body1.buoyancy_at": "reference"}))
    np.testing.assert_allclose(as_moorpy.bodies["body1"], ms.bodyList[0].r6[:3], atol=1e-6)
    assert as_moorpy.attitudes["body1"][1] == pytest.approx(moorpy_pitch, rel=1e-6)
    as_moordyn = solve_network_case(case)
    assert as_moordyn.attitudes["body1"][1] > 1.05 * moorpy_pitch    # the couple of weight and buoyancy is lost


def test_the_importer_says_where_the_buoyancy_acts(free_body):
    from kanat.io.moordyn import read_moordyn

    imported = read_moordyn(free_body.read_text(), str(free_body))
    said = [p.message for p in imported.problems if p.key == "BODIES 1.CG"]
    assert said and "buoyancy_at: cg" in said[0] and "buoyancy_at: reference" in said[0]


@pytest.fixture(scope="module")
def shared(tmp_path_factory):
    """Two coupled bodies, turned 30 and 200 deg, a shared line between them and one chain each."""
    ms = _quiet(mp.System, depth=150)
    ms.setLineType(dnommm=100, material="chain", name="chain")
    ms.addBody(-1, [0, 0, 0, 0, 0, np.radians(30)], m=0, v=0)
    ms.addBody(-1, [190, 20, 0, 0, 0, np.radians(200)], m=0, v=0)
    ms.addPoint(1, [8, 2, -12], body=1)
    ms.addPoint(1, [6, -3, -12], body=2)
    ms.addLine(230, "chain", pointA=1, pointB=2)
    ms.addPoint(1, [-8, 0, -12], body=1)
    ms.addPoint(1, [-600, 0, -150])
    ms.addLine(640, "chain", pointA=4, pointB=3)
    ms.addPoint(1, [-8, 0, -12], body=2)
    ms.addPoint(1, [800, 0, -150])
    ms.addLine(640, "chain", pointA=6, pointB=5)
    _quiet(ms.initialize)
    path = tmp_path_factory.mktemp("moorpy") / "shared.dat"
    _quiet(ms.unload, str(path))
    return path


def test_shared_line_between_coupled_bodies_has_moorpys_geometry(shared):
    ms = _reread(shared)
    result = solve_network_case(_load(shared))
    for k, line in enumerate(ms.lineList):
        cable = result.cables[f"line{k + 1}"]
        np.testing.assert_allclose(cable.position[[0, -1]], [line.rA, line.rB], atol=1e-9)
        np.testing.assert_allclose([cable.tension[0], cable.tension[-1]], [line.TA, line.TB], rtol=1e-6)
    assert 170.0 < np.linalg.norm(ms.lineList[0].rB - ms.lineList[0].rA) < 230.0


def test_each_coupled_body_has_moorpys_stiffness(shared):
    """Each coupled body its own (no longer one vessel): its 6x6 about its reference point is the
    diagonal block of MoorPy's coupled 12x12 (the other body held); the whole matrix, and more
    layouts, in tests/peers/test_shared_bodies.py."""
    ms = _reread(shared)
    K12 = _quiet(ms.getCoupledStiffnessA, lines_only=True)
    result = solve_network_case(_load(shared))
    assert "vessel" not in result.stiffness
    for b in range(2):
        block = K12[6 * b:6 * b + 6, 6 * b:6 * b + 6]
        np.testing.assert_allclose(result.stiffness[f"body{b + 1}"], block, atol=1e-6 * np.max(np.abs(block)))


@pytest.mark.slow
def test_a_line_grounded_between_suspended_ends_goes_to_the_lumped_equilibrium():
    """A 400 m chain between two fairleads 200 m apart in 100 m of water rests on the seabed in its
    middle. MoorPy's catenary gives the end tension and the grounded length; the lumped model's
    equilibrium (50 segments, the seabed a stiff frictionless spring) approaches them as its
    segments shorten: 2.2 % and 2 % at 50."""
    text = """
name: u-line
model: statics
environment: {water_density: 1025, depth: 100, seabed: {friction: 0.0, lateral_friction: 0.0}}
line_types:
  chain: {diameter: 0.137, mass: 115.0, axial_stiffness: 4.93e8}
cables:
  - {name: shared, line_type: chain, length: 400, segments: 50, from: {vessel: [0, 0, -10]},
     to: {vessel: [200, 0, -10]}}
"""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = solve_statics(load_case(text))
    ms = _quiet(mp.System, depth=100)
    ms.lineTypes["chain"] = dict(name="chain", d_vol=0.137, m=115.0, EA=4.93e8, MBL=1e12, Cd=1.2, Ca=1.0,
                                 CdAx=0.2, CaAx=0.0, w=(115.0 - 1025.0 * np.pi / 4 * 0.137**2) * 9.81)
    ms.addPoint(1, [0, 0, -10])
    ms.addPoint(1, [200, 0, -10])
    ms.addLine(400, "chain", pointA=1, pointB=2, nSegs=40)
    _quiet(ms.initialize)
    _quiet(ms.solveEquilibrium)
    line = ms.lineList[0]
    assert ds.attrs["status"] == "ok" and ds.attrs["scheme"] == "lumped equilibrium"
    assert ds.tension.values[0] == pytest.approx(line.TA, rel=0.03)
    assert float(ds.seabed_contact_length.values[0]) == pytest.approx(line.LBot, rel=0.03)


@pytest.mark.parametrize("keys, words", [
    ({"buoyancy_at": "reference", "center_of_buoyancy": [0, 0, -1]}, "either buoyancy_at or center_of_buoyancy"),
    ({"dof": 3, "buoyancy_at": "cg"}, "buoyancy_at is for rigid bodies"),
])
def test_buoyancy_at_refuses_what_contradicts_it(keys, words):
    from kanat.model.body import Body

    base = {"dof": 6, "mass": 1.0, "net_buoyancy": 0.0, "inertia": [1, 1, 1]}
    if keys.get("dof") == 3:
        base = {"mass": 1.0, "net_buoyancy": 0.0}
    with pytest.raises(ValueError, match=words):
        Body(**{**base, **keys})


def test_buoyancy_at_places_the_buoyancy():
    from kanat.model.body import Body

    body = {"dof": 6, "mass": 1.0, "net_buoyancy": 0.0, "inertia": [1, 1, 1], "center_of_gravity": [0, 0, -1]}
    assert Body(**body, buoyancy_at="cg").buoyancy_point == (0, 0, -1)
    assert Body(**body, buoyancy_at="reference").buoyancy_point == (0, 0, 0)
    assert Body(**body, center_of_buoyancy=[0, 0, 2]).buoyancy_point == (0, 0, 2)
