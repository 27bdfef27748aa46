"""Network statics side by side with MoorPy 1.3 (PyPI, the ``peers`` extra), run live.

Skipped when ``moorpy`` cannot be imported; tests/statics/test_network_statics.py checks the same
numbers, stored in tests/data/moorpy/reference.json, in every run. Here MoorPy solves the
systems again (so the stored numbers are MoorPy's), and its friction catenary is compared
with kanat's line over a grid of configurations.
"""
from __future__ import annotations

import importlib.util
import json
import math
import sys
import warnings

import numpy as np
import pytest

from helpers import ROOT

moorpy = pytest.importorskip("moorpy")

DATA = ROOT / "tests" / "data" / "moorpy"
REFERENCE = json.loads((DATA / "reference.json").read_text())


def _make_reference():
    """tests/data/moorpy/make_reference.py as a module (it makes the stored numbers)."""
    spec = importlib.util.spec_from_file_location("make_reference", DATA / "make_reference.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("make_reference", module)
    spec.loader.exec_module(module)
    return module


SLOW = {"buoy_two_line_types_clumps"}          # MoorPy takes about 4 s on its nine free points


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n
                                  for n in sorted(REFERENCE["systems"])])
def test_moorpy_still_gives_the_stored_answer(name):
    maker = _make_reference()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        live = maker.system_reference(name, maker.SYSTEMS[name])
    stored = REFERENCE["systems"][name]
    for cable, values in stored["cables"].items():
        for key, value in values.items():
            assert live["cables"][cable][key] == pytest.approx(value, rel=1e-8, abs=1e-8)
    for node, r in stored["nodes"].items():
        np.testing.assert_allclose(live["nodes"][node], r, atol=1e-7)
        K = np.asarray(r and stored["stiffness"][node])
        np.testing.assert_allclose(live["stiffness"][node], K, atol=1e-7 * np.max(np.abs(K)))


def test_moorpy_catenaries_are_the_stored_ones():
    maker = _make_reference()
    for row, stored in zip(maker.CATENARIES, REFERENCE["catenaries"]):
        live = maker.catenary_reference(*row)
        assert live["horizontal_tension"] == pytest.approx(stored["horizontal_tension"], rel=1e-10)
        assert live["vertical_tension"] == pytest.approx(stored["vertical_tension"], rel=1e-10)


@pytest.mark.parametrize("friction", [0.0, 0.3, 1.0])
def test_the_friction_catenary_matches_moorpy_over_a_grid(friction):
    """MoorPy's catenary() (end A on the seabed, Coulomb friction CB) and kanat's line, over
    spans and rises from nearly slack to taut, wherever MoorPy converges."""
    from moorpy.Catenary import catenary

    from kanat.statics.line_solve import solve_line
    from kanat.statics.piecewise import Ground, Pieces

    L, w, EA = 700.0, 981.0, 5.1e8
    compared = 0
    for span in np.linspace(450.0, 695.0, 12):
        for rise in np.linspace(10.0, 200.0, 8):
            if math.hypot(span, rise) > L:
                continue
            try:
                fAH, fAV, fBH, fBV, info = catenary(span, rise, L, EA, w, CB=friction, Tol=1e-12, MaxIter=500)
            except Exception:                       # noqa: BLE001 - MoorPy's own failures are not compared
                continue
            if info.get("ProfileType") not in (1, 2, 3):
                continue
            sol = solve_line(span, rise, Pieces.uniform(L, w, EA), Ground(0.0, friction))
            assert sol.horizontal_tension == pytest.approx(-fBH, rel=1e-8, abs=1e-9 * w * L)
            assert sol.vertical_tension == pytest.approx(-fBV, rel=1e-8)
            np.testing.assert_allclose(sol.evaluation.anchor, [fAH, fAV], rtol=1e-7, atol=1e-8 * w * L)
            assert sol.evaluation.touchdown == pytest.approx(info["LBot"], rel=1e-8, abs=1e-8 * L)
            compared += 1
    assert compared >= 20
