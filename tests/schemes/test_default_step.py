"""A case that names no scheme and no dt (issue: lumped model) runs with the fastest safe scheme
and a documented default step; the continuum model asks for its dt by key."""

import pytest

from kanat.errors import CaseError
from kanat.io import parse_case
from kanat.io.results import read_result
from kanat.model.simulation import DEFAULT_IMPLICIT_DT

from helpers import EXAMPLES, run



def test_lumped_case_without_scheme_or_dt_chooses_both(tmp_path):
    text = (EXAMPLES / "trawl_head_8s_1to2.yaml").read_text()
    lines = [line for line in text.splitlines() if not line.strip().startswith(("scheme:", "dt:"))]
    text = "\n".join(lines).replace("duration: 600", "duration: 20")
    case = parse_case(text)
    assert case.simulation.dt is None and case.simulation.scheme is None
    summary = run(case, tmp_path / "r.nc")
    assert summary.status == "ok"
    notes = " ".join(summary.notes)
    assert "no scheme named" in notes and "no dt given" in notes
    ds = read_result(tmp_path / "r.nc")
    assert ds.attrs["scheme"] in ("rk4", "generalized-alpha-lumped")
    assert 0 < ds.attrs["dt"] <= max(ds.attrs["axial_period"], DEFAULT_IMPLICIT_DT)
    assert ds.sizes["time"] == 41                               # every 0.5 s over 20 s


def test_continuum_case_without_dt_is_refused_by_key():
    text = (EXAMPLES / "speed_step_2d.yaml").read_text().replace("  dt: 1.0\n", "")
    with pytest.raises(CaseError, match="simulation.dt: the continuum model needs a time step"):
        parse_case(text)
