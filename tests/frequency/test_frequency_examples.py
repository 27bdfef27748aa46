"""``simulation.method: frequency`` on the examples that have an excitation, and on a tow.

* ``examples/moordyn/waves/taut_line_in_waves.dat`` (waves along a taut line) and
  ``examples/lazy_wave.yaml`` (harmonic vessel motion) run and pass their own checks.
* ``examples/towed_body.yaml``, linearised about its steady tow (a line in the uniform relative
  flow), its tow point heaving 0.5 m slowly (600 s): the whole tow follows as a rigid translation
  in a uniform flow, so the body heaves 0.5 m and the tension hardly changes (quasi-static limit).
* The examples without waves or vessel motion are refused with the reason.
"""
import warnings

import numpy as np
import pytest

import kanat
from kanat.errors import CaseError

from helpers import EXAMPLES


def frequency(path, **changes):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(path)
        simulation = {} if case.simulation is not None else {"simulation.duration": 600.0}
        return case.replace({"simulation.method": "frequency", **simulation, **changes})


@pytest.mark.slow
@pytest.mark.parametrize("name", ["moordyn/waves/taut_line_in_waves.dat", "lazy_wave.yaml"])
def test_the_examples_with_an_excitation_run(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(frequency(EXAMPLES / name))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    assert float(ds.tension_std.max()) > 0.0


@pytest.mark.slow
def test_a_tow_heaved_slowly_follows_rigidly():
    """The body's heave amplitude within 1 % of the tow point's 0.5 m; the tension's swing below
    1 % of its mean."""
    case = frequency(EXAMPLES / "towed_body.yaml", model="lumped",
                     **{"vessel.motion": [{"dof": "heave", "amplitude": 0.5, "period": 600.0}]})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.solve_frequency(case)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    body = list(ds.body.values).index(next(iter(case.bodies)))
    assert float(ds.body_motion_rao_amplitude[0, body, 2]) * 0.5 == pytest.approx(0.5, rel=0.01)
    assert float(ds.tension_amplitude.max()) < 0.01 * float(ds.mean_tension.min())


@pytest.mark.parametrize("name", ["mooring_buoy_decay.yaml", "moordyn/three_leg_chain_50.dat"])
def test_an_example_without_an_excitation_is_refused_with_the_reason(name):
    with pytest.raises(CaseError, match="needs an excitation"):
        kanat.solve_frequency(frequency(EXAMPLES / name))
