"""The lumped model applies the default seabed when a case gives ``environment.depth`` alone, as the
continuum model does (stiffness 3e6 Pa/m, damping 3e5 Pa s/m, no friction): examples/mooring_current.yaml,
a chain with 527 m of its 700 m on the seabed in a sheared current, side by side with the continuum model.

The two discretize the same line (lumped nodes and elements against the box scheme's): their
touchdown moves by whole elements, so the tensions agree to the grid's error and converge together
as the grid is refined (the continuum model's top tension moves by 0.8 % from 35 to 70 segments,
0.15 % from 70 to 140; at 280 the models are 1e-4 apart).
"""
import warnings

import numpy as np
import pytest

from helpers import EXAMPLES
from kanat import api, load_case
from kanat.model import Seabed
from kanat.model.support import unsupported


def mooring(model, segments=70):
    return load_case(EXAMPLES / "mooring_current.yaml").replace({
        "model": model, "cables[0].segments": segments, "simulation.duration": 2.0, "simulation.dt": 0.05})


def steady(case):
    """Top and anchor tension [N], seabed contact length [m] and positions (n, 3) of a run's initial state."""
    model = api.dynamic_model(case)
    out = model.outputs(model.initial())
    return out["tension"][-1], out["tension"][0], float(out["seabed_contact_length"][0]), out["position"]


def test_the_default_seabed_is_the_documented_one_and_the_written_case_is_kept():
    case = mooring("lumped")
    assert case.environment.seabed is None
    applied = case.with_seabed_contact().environment.seabed
    assert applied == Seabed() and (applied.stiffness, applied.damping, applied.friction) == (3.0e6, 3.0e5, 0.0)
    assert mooring("statics").model_copy(update={"environment": case.environment.model_copy(
        update={"depth": None})}).with_seabed_contact().environment.seabed is None
    model = api.dynamic_model(case)
    assert model.case.environment.seabed == Seabed()
    assert model.layout().attrs["case_sha256"] == api.dynamic_model(case).layout().attrs["case_sha256"]
    assert "seabed:" not in model.layout().attrs["case_yaml"]


def test_the_lumped_model_validates_without_a_seabed_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        case = mooring("lumped")
    assert not [p for p in unsupported(case, "lumped") if "seabed" in p.message or p.key == "environment.depth"]


def test_lumped_and_continuum_statics_of_the_mooring_in_current_agree():
    top_c, anchor_c, contact_c, x_c = steady(mooring("continuum"))
    top_l, anchor_l, contact_l, x_l = steady(mooring("lumped"))
    assert top_l == pytest.approx(top_c, rel=3e-3)
    assert anchor_l == pytest.approx(anchor_c, rel=5e-3)
    assert abs(contact_l - contact_c) <= 700 / 70 + 1e-9           # one element
    assert np.max(np.abs(x_l - x_c)) < 1.0                        # m, of a 600 m span
    assert np.min(x_l[:, 2]) > -150.0 - 0.01                      # on the seabed, not through it


@pytest.mark.slow
def test_lumped_and_continuum_converge_together():
    gaps = []
    for n in (70, 280):
        top_c, anchor_c, _, _ = steady(mooring("continuum", n))
        top_l, anchor_l, _, _ = steady(mooring("lumped", n))
        gaps.append((abs(top_l / top_c - 1.0), abs(anchor_l / anchor_c - 1.0)))
    assert gaps[1][0] < 0.2 * gaps[0][0] and gaps[1][0] < 2e-4
    assert gaps[1][1] < 1e-3


@pytest.mark.slow
def test_a_short_lumped_run_of_the_example_is_ok():
    outcome = api.run(mooring("lumped").replace({"simulation.duration": 1.0}))
    assert outcome.ok, outcome.status
