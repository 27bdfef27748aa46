"""``design.analysis: frequency``: the design check from kanat's own frequency-domain solution.

Oracles: every utilisation row is the Rayleigh MPM of the fairlead node's tension spectrum that
:func:`kanat.solve_frequency` gives for that sea state's case (the spectral moments and MPM of
:mod:`kanat.analysis.spectral`, computed here from the solver's dataset), and the fatigue table
the Dirlik damage of the same spectra weighted by each sea state's probability; a case with a
6-DOF body in waves is solved, and a sea state whose
linear solution fails its own checks (slack) is a failed row, never numbers.

The system: a spread mooring of three catenary chains to RAO-driven fairleads (the vessel of
``examples/design/quasi_static.yaml``), JONSWAP sea states.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

import kanat
from kanat.analysis.spectral import most_probable_maximum, spectral_moments
from kanat.design_checks import design
from kanat.design_checks.conditions import sea_state_case, wave_seed

from helpers import EXAMPLES

EXAMPLE = EXAMPLES / "design" / "quasi_static.yaml"
SEA_STATES = """name,hs,tp,gamma,heading_deg,probability,duration
moderate,2.0,8.0,3.3,0,0.7,10800
rough,4.0,10.0,3.3,30,0.3,10800
"""


def _case(tmp_path: Path, **design_keys):
    data = yaml.safe_load(EXAMPLE.read_text())
    data["design"] = {k: v for k, v in data["design"].items() if k != "mean_offset"}
    data["design"].update({"analysis": "frequency", "sea_states": "sea_states.csv", "conditions": ["intact"],
                           "extremes": "rayleigh", "fatigue": {"curve": "api-chain-studless", "design_life": 25}},
                          **design_keys)
    data["model"] = "lumped"
    (tmp_path / "sea_states.csv").write_text(SEA_STATES)
    for name in ("raos.csv",):
        source = EXAMPLE.parent / name
        if source.exists():
            (tmp_path / name).write_text(source.read_text())
    path = tmp_path / "case.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return kanat.load_case(path)


@pytest.mark.slow
def test_frequency_design_rows_are_the_spectra_of_the_frequency_domain(tmp_path):
    case = _case(tmp_path)
    result = design(case)
    assert not result.failures
    table = result.utilisation
    assert len(table) == 2 * len(case.cables)
    for sea_state in case.design.sea_state_rows:
        ds = kanat.solve_frequency(sea_state_case(case, sea_state, wave_seed(case, 0)))
        assert ds.attrs["status"] == "ok"
        cables = ds["cable"].values.astype(str)
        for cable in case.cables:
            nodes = np.flatnonzero(cables == cable.name)
            ends = nodes[[np.argmin(ds["s"].values[nodes]), np.argmax(ds["s"].values[nodes])]]
            fairlead = ends[int(np.argmax(ds["mean_tension"].values[ends]))]   # the end holding more
            moments = spectral_moments(ds["frequency"].values, ds["tension_spectrum"].values[:, fairlead],
                                       ds["frequency_width"].values)
            assert moments.std == pytest.approx(float(ds["tension_std"].values[fairlead]), rel=1e-12)
            expected = most_probable_maximum(moments, case.design.storm_duration,
                                             ds["mean_tension"].values[fairlead], "rayleigh")
            row = table[(table.sea_state == sea_state.name) & (table.line == cable.name)]
            assert float(row.mpm_tension.iloc[0]) == pytest.approx(expected, rel=1e-9)
    assert (result.fatigue.damage_per_year > 0).all()


@pytest.mark.slow
def test_a_body_in_waves_is_solved_by_the_frequency_domain():
    """The 6-DOF buoy of mooring_design.yaml moves in the waves (its wave loads:
    tests/frequency/test_frequency_rigid_waves.py checks them against the time domain)."""
    data = yaml.safe_load((EXAMPLE.parent / "mooring_design.yaml").read_text())
    del data["design"]
    data["simulation"] = {"method": "frequency", "duration": 600}
    ds = kanat.solve_frequency(kanat.load_case(data))
    assert ds.attrs["status"] == "ok"
    assert float(ds.body_motion_std.sel(body="buoy", dof="z")) > 0.1
