"""examples/moordyn/shared_two_bodies.dat, as a MoorPy or MoorDyn user runs it: ``kanat statics`` for each
body's 6x6 and the coupled 12x12 stiffness, ``kanat offsets`` for each body's own offset curve.

The file (written by MoorPy 1.3) is symmetric: body 2 is body 1 turned 180 deg about the vertical
through (100, 0), the midpoint of the shared line. Oracles: that symmetry, which maps body 1's
surge, sway, roll, pitch to minus body 2's (``T = diag(-1, -1, 1, -1, -1, 1)``), so ``K_22 = T K_11 T``,
``K_21 = T K_12 T`` and body 2 moved along ``theta`` is body 1 moved along ``theta + 180 deg``;
MoorPy's analytic ``getCoupledStiffnessA`` of the same file. (The bodies share no line directly, the
buoy between them is a free point, so MoorPy's condensation holds in every block; where a line
joins two bodies directly its rotation-rotation blocks between the bodies are not MoorPy's own
re-solved statics: tests/peers/test_shared_bodies.py.)
"""
from __future__ import annotations

import contextlib
import io

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from helpers import EXAMPLES
from kanat.cli import app

FILE = EXAMPLES / "moordyn" / "shared_two_bodies.dat"
T = np.diag([-1.0, -1.0, 1.0, -1.0, -1.0, 1.0])
runner = CliRunner()


@pytest.fixture(scope="module")
def statics(tmp_path_factory):
    out = tmp_path_factory.mktemp("shared") / "statics.nc"
    done = runner.invoke(app, ["statics", str(FILE), "-o", str(out)])
    assert done.exit_code == 0, done.output
    assert "coupled body body2 (moments and stiffness about (" in done.output and "line force" in done.output
    with xr.open_dataset(out) as ds:
        return ds.load()


def test_statics_writes_each_bodys_stiffness_and_the_coupled_matrix(statics):
    assert statics.attrs["status"] == "ok"
    assert list(statics.body.values) == ["body1", "body2"]
    K = statics.coupled_stiffness.values
    assert K.shape == (12, 12) and list(statics.coupled_dof.values[[0, 6, 11]]) == ["body1.surge", "body2.surge",
                                                                                   "body2.yaw"]
    for b, name in enumerate(("body1", "body2")):
        np.testing.assert_array_equal(statics.body_stiffness.sel(body=name).values, K[6 * b:6 * b + 6, 6 * b:6 * b + 6])


def test_the_stiffness_has_the_layouts_symmetry(statics):
    """Measured: within 5e-17 of the largest term."""
    K = statics.coupled_stiffness.values
    scale = np.max(np.abs(K))
    np.testing.assert_allclose(K[6:, 6:], T @ K[:6, :6] @ T, atol=1e-9 * scale)
    np.testing.assert_allclose(K[6:, :6], T @ K[:6, 6:] @ T, atol=1e-9 * scale)
    force = statics.body_force.values
    np.testing.assert_allclose(force[1], T[:3, :3] @ force[0], atol=1e-9 * abs(force[0, 2]))
    assert np.max(np.abs(K[:3, 6:9])) > 1e3                         # N/m: the shared line couples them


def test_the_stiffness_is_moorpys_analytic_one(statics, moorpy):
    """Measured: within 6.4e-14 of the largest term."""
    with contextlib.redirect_stdout(io.StringIO()):
        ms = moorpy.System(file=str(FILE))
        ms.initialize()
        ms.solveEquilibrium(tol=1e-10, maxIter=5000)
        K = ms.getCoupledStiffnessA(lines_only=True)
    np.testing.assert_allclose(statics.coupled_stiffness.values, K, atol=1e-10 * np.max(np.abs(K)))


def _offsets(tmp_path, direction: float) -> xr.Dataset:
    out = tmp_path / f"offsets_{direction:g}.nc"
    done = runner.invoke(app, ["offsets", str(FILE), "--direction", str(direction), "--to", "20", "--steps", "4",
                               "-o", str(out)])
    assert done.exit_code == 0, done.output
    assert "body1 alone, the other bodies held" in done.output
    with xr.open_dataset(out) as ds:
        return ds.load()


def test_offsets_give_each_bodys_curve_with_the_layouts_symmetry(tmp_path):
    ahead, astern = _offsets(tmp_path, 0.0), _offsets(tmp_path, 180.0)
    assert list(ahead.body.values) == ["body1", "body2"]
    second = ahead.body_restoring_force.sel(body="body2").values
    first = astern.body_restoring_force.sel(body="body1").values
    np.testing.assert_allclose(second, first @ T[:3, :3], atol=1e-9 * np.max(np.abs(first)))
    moment = astern.body_restoring_moment.sel(body="body1").values
    np.testing.assert_allclose(ahead.body_restoring_moment.sel(body="body2").values, moment @ T[3:, 3:],
                               atol=1e-9 * np.max(np.abs(moment)))
    assert second[-1, 0] - second[0, 0] < -4e4                       # N: body 2 pushed into its shared line
