"""Each coupled body's own offset curve (kanat.offsets, kanat offsets) on two platforms sharing a line,
side by side with MoorPy 1.3 reading the same file.

The case is examples/moordyn/shared_two_bodies.dat (two coupled bodies 200 m apart, the second
turned 180 deg, a shared chain of two 125 m lines held up by a free buoy of 8 m^3 between them,
two 720 m chains from each to its anchors; MoorPy wrote it), so every offset re-balances the
buoy. Oracles:

* MoorPy's re-solved statics: body ``b`` set to its reference position plus the offset
  (``Body.setPosition``), the other body left where it is, ``solveEquilibrium`` to 1e-10, then
  ``Body.getForces(lines_only=True)`` (force and moment about the moved reference point) and every
  line's end tensions; the system curve with both bodies moved;
* the statics of the file rewritten with body ``b``'s ``X0, Y0`` moved, solved afresh (a new case,
  a new first guess);
* the slope of each body's curve at zero against that body's 6x6 ``body_stiffness``.
"""
from __future__ import annotations

import contextlib
import io
import math
import warnings

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat.api import load_case, offsets, solve_statics

FILE = EXAMPLES / "moordyn" / "shared_two_bodies.dat"
DIRECTION, TO, STEPS = 30.0, 20.0, 4
BODIES = ("body1", "body2")


def _quiet(function, *args, **kwargs):
    with contextlib.redirect_stdout(io.StringIO()):
        return function(*args, **kwargs)


def _load(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path, solver="statics")


def _unit(direction=DIRECTION) -> np.ndarray:
    return np.array([math.cos(math.radians(direction)), math.sin(math.radians(direction)), 0.0])


@pytest.fixture(scope="module")
def curves():
    return offsets(_load(FILE), direction=DIRECTION, to=TO, steps=STEPS)


@pytest.fixture(scope="module")
def system(moorpy):
    ms = _quiet(moorpy.System, file=str(FILE))
    _quiet(ms.initialize)
    _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
    return ms


def _moorpy_at(ms, moved: dict[int, float]) -> tuple[np.ndarray, np.ndarray]:
    """MoorPy's loads (2, 6) on both bodies and end tensions (lines, 2) with body ``b`` moved by
    ``moved[b]`` metres along DIRECTION, the others where they are; the bodies are put back after."""
    start = [body.r6.copy() for body in ms.bodyList]
    for b, d in moved.items():
        ms.bodyList[b].setPosition(start[b] + np.concatenate([d * _unit(), np.zeros(3)]))
    _quiet(ms.solveEquilibrium, tol=1e-10, maxIter=5000)
    loads = np.array([_quiet(body.getForces, lines_only=True) for body in ms.bodyList])
    tensions = np.array([[line.TA, line.TB] for line in ms.lineList])
    for body, r6 in zip(ms.bodyList, start):
        body.setPosition(r6)
    return loads, tensions


@pytest.mark.parametrize("b", range(len(BODIES)), ids=BODIES)
def test_each_bodys_curve_is_moorpys_resolved_statics(curves, system, b):
    """Measured: force within 2.8e-11 and 6.7e-10 of the body's vertical load (body1, body2), moment
    within 1.3e-10 and 3.3e-9 of it (per metre), tensions within 1.3e-10 and 3.2e-9: MoorPy's
    equilibrium tolerance on the buoy's position."""
    own = curves.sel(body=BODIES[b])
    for d in curves.offset.values:
        loads, tensions = _moorpy_at(system, {b: d})
        scale = abs(loads[b, 2])
        np.testing.assert_allclose(own.body_restoring_force.sel(offset=d).values, loads[b, :3], atol=1e-8 * scale)
        np.testing.assert_allclose(own.body_restoring_moment.sel(offset=d).values, loads[b, 3:], atol=2e-8 * scale)
        np.testing.assert_allclose(own.body_end_tension.sel(offset=d).values, tensions, rtol=2e-8)
    drop = own.body_restoring_force.values[-1, :2] - own.body_restoring_force.values[0, :2]
    assert np.linalg.norm(drop) > 5e4                                   # N: the body really moved


def test_the_system_curve_is_moorpys_with_both_bodies_moved(curves, system):
    """Measured: force within 5.6e-13 of the vertical load, tensions within 1.2e-12."""
    for d in curves.offset.values:
        loads, tensions = _moorpy_at(system, {0: d, 1: d})
        np.testing.assert_allclose(curves.restoring_force.sel(offset=d).values, loads[:, :3].sum(axis=0),
                                   atol=1e-8 * abs(loads[0, 2]))
        np.testing.assert_allclose(curves.end_tension.sel(offset=d).values, tensions, rtol=1e-8)


def _moved_file(tmp_path, b: int, d: float):
    """The example with body ``b``'s reference point moved by ``d`` along DIRECTION."""
    lines = FILE.read_text().splitlines()
    row = next(k for k, line in enumerate(lines) if line.split()[:2] == [str(b + 1), "coupled"])
    fields = lines[row].split()
    x, y = (float(fields[2 + i]) + float(d * _unit()[i]) for i in (0, 1))
    lines[row] = " ".join([*fields[:2], repr(x), repr(y), *fields[4:]])
    path = tmp_path / f"moved_{b}_{d:g}.dat"
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("b", range(len(BODIES)), ids=BODIES)
def test_each_bodys_curve_is_the_statics_of_the_moved_file(curves, tmp_path, b):
    """Measured: force within 9.4e-12 and 3.5e-10, moment within 3.3e-11 and 7.8e-10 (relative)."""
    d = curves.offset.values[-1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = solve_statics(_load(_moved_file(tmp_path, b, d)))
    own = curves.sel(body=BODIES[b], offset=d)
    np.testing.assert_allclose(own.body_restoring_force.values, ds.body_force.sel(body=BODIES[b]).values,
                               rtol=1e-8, atol=1e-3)
    np.testing.assert_allclose(own.body_restoring_moment.values, ds.body_moment.sel(body=BODIES[b]).values,
                               rtol=1e-8, atol=1e-2)


def test_the_slope_at_zero_is_each_bodys_stiffness():
    """Central difference of offsets of +-1 mm along x and y against the body's 6x6 (the difference's
    error is K'' h^2 / 6; measured within 1.1e-9 of K_xx in force, 6.4e-9 in moment)."""
    step = 1e-3
    case = _load(FILE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        stiffness = solve_statics(case).body_stiffness
    for direction, column in ((0.0, 0), (90.0, 1)):
        plus = offsets(case, direction=direction, to=step, steps=1)
        minus = offsets(case, direction=direction + 180.0, to=step, steps=1)
        for name in BODIES:
            K = stiffness.sel(body=name).values
            slope = -(plus.body_restoring_force.sel(body=name).values[-1]
                      - minus.body_restoring_force.sel(body=name).values[-1]) / (2 * step)
            turn = -(plus.body_restoring_moment.sel(body=name).values[-1]
                     - minus.body_restoring_moment.sel(body=name).values[-1]) / (2 * step)
            np.testing.assert_allclose(slope, K[:3, column], atol=1e-7 * K[0, 0])
            np.testing.assert_allclose(turn, K[3:, column], atol=1e-7 * K[0, 0])


def test_the_command_writes_each_body_or_the_system_only(tmp_path, curves):
    from typer.testing import CliRunner

    from kanat.cli import app

    runner = CliRunner()
    args = ["offsets", str(FILE), "--direction", str(DIRECTION), "--to", str(TO), "--steps", str(STEPS)]
    done = runner.invoke(app, [*args, "-o", str(tmp_path / "curve.csv"), "--plot", str(tmp_path / "curve.png")])
    assert done.exit_code == 0, done.output
    assert "body2 alone, the other bodies held" in done.output
    assert (tmp_path / "curve.png").stat().st_size > 20_000
    rows = np.genfromtxt(tmp_path / "curve.csv", delimiter=",", names=True)
    np.testing.assert_allclose(rows["body2_restoring_force_x"],
                               curves.body_restoring_force.sel(body="body2", xyz="x").values)
    np.testing.assert_allclose(rows["body1_restoring_moment_z"],
                               curves.body_restoring_moment.sel(body="body1", xyz="z").values)
    done = runner.invoke(app, [*args, "--system-only", "-o", str(tmp_path / "system.csv")])
    assert done.exit_code == 0, done.output
    head = (tmp_path / "system.csv").read_text().splitlines()[0].split(",")
    assert not any(name.startswith("body") for name in head)
    np.testing.assert_allclose(np.genfromtxt(tmp_path / "system.csv", delimiter=",", names=True)["restoring_force_y"],
                               curves.restoring_force.sel(xyz="y").values)


def test_the_picture_draws_the_system_and_each_body(curves, tmp_path):
    """What was drawn, read back from the figure: each curve's force along the direction and its largest
    tension, against the dataset's vectors projected by hand."""
    from kanat.report.run_plot import plot_run

    fig = plot_run(curves, tmp_path / "curve.png")
    assert (tmp_path / "curve.png").stat().st_size > 20_000
    force_ax, tension_ax = fig.axes
    drawn = {line.get_gid(): line for ax in fig.axes for line in ax.get_lines() if line.get_gid()}
    assert set(drawn) == {f"{what}/{name}" for what in ("force", "tension") for name in ("system", *BODIES)}
    unit = _unit()[:2]
    expected = {"system": (curves.restoring_force.values[:, :2] @ unit, curves.end_tension.values)}
    for name in BODIES:
        own = curves.sel(body=name)
        expected[name] = (own.body_restoring_force.values[:, :2] @ unit, own.body_end_tension.values)
    for name, (force, tension) in expected.items():
        np.testing.assert_allclose(drawn[f"force/{name}"].get_xdata(), curves.offset.values)
        np.testing.assert_allclose(drawn[f"force/{name}"].get_ydata(), force / 1e3, rtol=1e-12)
        np.testing.assert_allclose(drawn[f"tension/{name}"].get_ydata(), tension.max(axis=(1, 2)) / 1e3, rtol=1e-12)
    legend = [t.get_text() for t in force_ax.get_legend().get_texts()]
    assert legend == ["all moved together", "body1 alone, the others held", "body2 alone, the others held"]
    assert force_ax.get_xlabel() == f"offset along {DIRECTION:g} deg [m]"
    assert tension_ax.get_ylabel() == "largest end tension [kN]"


def test_the_report_draws_the_system_and_each_body(curves, tmp_path):
    """The HTML report of the offsets file: one trace per curve, its force along the direction read back."""
    import base64
    import json
    import re

    from kanat.report.html_report import write_report

    path = tmp_path / "curve.nc"
    curves.to_netcdf(path)
    html = write_report(path, tmp_path / "curve.html").read_text()
    figures = json.loads(re.search(r'<script type="application/json" id="kanat-figures">(.*?)</script>', html,
                                   re.S).group(1))
    traces = figures["plot-offsets"]["data"]
    assert [t["name"] for t in traces] == ["all moved together", "body1 alone, the others held",
                                          "body2 alone, the others held"]

    def values(array):
        return np.frombuffer(base64.b64decode(array["bdata"]), array["dtype"]) if isinstance(array, dict) else array

    unit = _unit()[:2]
    np.testing.assert_allclose(values(traces[0]["y"]), curves.restoring_force.values[:, :2] @ unit / 1e3, rtol=1e-12)
    np.testing.assert_allclose(values(traces[2]["y"]),
                               curves.body_restoring_force.sel(body="body2").values[:, :2] @ unit / 1e3, rtol=1e-12)
