"""Kaliukh & Vusatiuk's factorized schemes take the whole cable as submerged: a part above the water is
refused, not weighed as if wet.

Measured before this test: the planar example (``examples/factorization_planar80.yaml``) with its tow
point 5 m above the water ran ``ok`` with the scheme ``wave-factorized`` and a top tension of 12,400 N
at 4 s, against 11,445 N from ``generalized-alpha`` (which weighs the 9.1 m above the water in air,
without the water's drag), and a note saying that the part above the water "weighed its weight in
air". With the tow point at the surface both agree (12,413 and 12,412 N).
"""
from __future__ import annotations

import numpy as np
import pytest

from kanat.continuum.adapter import ContinuumModel
from kanat.errors import CaseError
from kanat.io import load_case

from helpers import EXAMPLES


def planar(**changes):
    return load_case(EXAMPLES / "factorization_planar80.yaml").replace(
        {"simulation.duration": 1.0, "simulation.output_dt": 0.5, **changes})


def test_a_tow_point_above_the_water_is_refused_by_the_factorized_schemes():
    with pytest.raises(CaseError, match=r"vessel\.tow_point.*above the water surface.*generalized-alpha"):
        ContinuumModel(planar(**{"vessel.tow_point": [0.0, 0.0, 5.0]}))


@pytest.mark.parametrize("scheme, refused", [("wave-factorized", True), ("generalized-alpha", False)])
def test_a_cable_risen_above_the_water_fails_a_factorized_run_only(scheme, refused):
    """The state at t = 0 lifted 2 m: its top 2 m and more stand above the water."""
    model = ContinuumModel(planar(**{"simulation.scheme": scheme}))
    state = model.initial()
    values = model.outputs(state)
    assert model.check(state, values) is None
    lifted = dict(values, position=np.asarray(values["position"]) + np.array([0.0, 0.0, 2.0]))
    found = model.check(state, lifted)
    if refused:
        assert found is not None and "above the water surface" in found and "factorized" in found
        length = float(found.split(" m of cable")[0])
        assert length > 2.0                      # the cable leaves the tow point downwards, not plumb
    else:
        assert found is None                     # a heavy part above the water hangs in air
