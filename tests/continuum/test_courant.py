"""Kaliukh & Vusatiuk's schemes are refused, before a run, at a step beyond the transverse Courant number
they are known to take, with the largest step to use; the generalized-α family never is."""
import dataclasses

import numpy as np
import pytest

from kanat.continuum.courant import check_step, courant_numbers
from kanat.continuum.factorized.schemes import MAX_SIGMA_TR
from kanat.continuum.models import PlanarModel
from kanat.continuum.schemes import SCHEMES, GeneralizedAlpha
from kanat.errors import KanatError
from kanat.validation.checks_dynamics import straight_cable

from helpers import StepDrive


def model_and_state(tension=1000.0):
    cable, state = straight_cable(100.0, 20, tension, 1e6, 1.0, 0.5)
    return PlanarModel(cable, StepDrive((0.0, 0.0))), state


def test_courant_numbers_are_the_wave_speeds_times_dt_over_ds():
    model, state = model_and_state()
    sigma_long, sigma_tr = courant_numbers(model, state, 0.1)
    c_t = np.sqrt(1000.0 / (1.5 * (1 + 1e-3)))
    assert sigma_long == pytest.approx(np.sqrt(1e6) * 0.1 / 5.0)
    assert sigma_tr == pytest.approx(c_t * 0.1 / 5.0)


@pytest.mark.parametrize("name", ["factorized", "factorized-4"])
def test_a_step_beyond_the_known_range_is_refused_with_the_largest_safe_step(name):
    model, state = model_and_state()
    scheme = SCHEMES[name]()
    limit = MAX_SIGMA_TR[(name, 2)]
    c_t_dt = courant_numbers(model, state, 1.0)[1]               # sigma_tr per second of step
    safe = limit / c_t_dt
    check_step(scheme, model, state, 0.99 * safe)                # within: accepted
    with pytest.raises(KanatError, match=f"use dt <= {safe:.3g} s|Use dt <= {safe:.3g} s"):
        check_step(scheme, model, state, 2 * safe)
    check_step(dataclasses.replace(scheme, check_stability=False), model, state, 2 * safe)   # on request


def test_the_generalized_alpha_family_takes_any_step():
    model, state = model_and_state()
    check_step(GeneralizedAlpha(), model, state, 1e3)
    assert all(SCHEMES[n]().max_sigma_tr(2) is None for n in ("generalized-alpha", "box", "backward-euler"))


@pytest.mark.parametrize("example, scheme", [("speed_step_2d.yaml", "factorized"),
                                             ("speed_step_2d.yaml", "factorized-4"),
                                             ("turn_360_3d.yaml", "wave-factorized-2")])
def test_kanat_run_refuses_a_factorized_scheme_beyond_its_range_before_any_step(example, scheme, tmp_path):
    """The main examples at dt = 1 s lie far beyond these schemes' known range (sigma_tr 9.4):
    ``kanat run`` refuses before the first step, writes nothing and names the safe step."""
    from typer.testing import CliRunner

    from kanat.cli import app
    from helpers import EXAMPLES

    out = tmp_path / "out.nc"
    result = CliRunner().invoke(app, ["run", str(EXAMPLES / example), "--scheme", scheme, "-o", str(out)])
    assert result.exit_code == 1
    assert f"the {scheme} scheme is known to stay bounded only up to" in result.output
    safe = float(result.output.split("Use dt <= ")[1].split(" s")[0])
    assert 0.01 < safe < 1.0 and not out.exists()
