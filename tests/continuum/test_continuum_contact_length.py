"""The continuum model's ``seabed_contact_length`` (theory/moorings.md eq. (M8a)) against the closed-form
elastic catenary resting on a frictionless seabed: the grounded chain of examples/mooring_current.yaml in
still water, within half an interval plus the elastic sink at three grids."""
import re
import warnings

import numpy as np
import pytest

import kanat

from helpers import EXAMPLES, grounded_catenary

SPAN, RISE, LENGTH, WEIGHT, STIFFNESS = 600.0, 145.0, 700.0, 981.0, 5.1e8      # the example's chain


def grounded_length() -> float:
    """The unstretched length on the seabed of the elastic catenary with a grounded part (no friction),
    :func:`helpers.grounded_catenary`."""
    return LENGTH - grounded_catenary(SPAN, RISE, LENGTH, WEIGHT, STIFFNESS)[1]


def grounded_chain(segments: int) -> str:
    """The chain mooring of examples/mooring_current.yaml in still water, as a short continuum run."""
    text = (EXAMPLES / "mooring_current.yaml").read_text()
    text = re.sub(r"  current:\n    profile:.*?\n(line_types)", r"\1", text, flags=re.S)
    text = text.replace("model: statics", "model: continuum").replace("segments: 70", f"segments: {segments}")
    return text + "simulation: {duration: 1, dt: 0.5, output_dt: 0.5}\n"


@pytest.mark.slow
@pytest.mark.parametrize("segments", [35, 70, 140])
def test_the_grounded_length_is_the_elastic_catenarys(segments):
    expected = grounded_length()                                         # about 529 m of 700 m
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(grounded_chain(segments)))
    assert ds.attrs["status"] == "ok"
    contact = ds.seabed_contact_length
    assert contact.dims == ("time", "cable") and list(ds.cable_name.values) == ["mooring"]
    assert contact.attrs["units"] == "m"
    spacing = LENGTH / segments
    assert np.all(np.abs(contact.values - expected) <= 0.5 * spacing + 0.5)   # half an interval, the sink's shift
    assert np.ptp(contact.values) == 0.0                                 # steady in still water


def test_a_towed_cable_far_above_the_seabed_rests_none_of_its_length_on_it():
    case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace({"simulation.duration": 2})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(case)
    assert ds.position.sel(xyz="z").min() > -case.environment.depth + 100.0      # 2000 m of water
    assert np.all(ds.seabed_contact_length.values == 0.0)
