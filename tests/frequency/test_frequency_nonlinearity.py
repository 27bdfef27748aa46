"""The frequency domain's offset nonlinearity check (kanat.frequency.nonlinearity, docs/frequency.md).

* Its measure ``r = |T(+d) + T(-d) - 2 T(0)| / |T(+d) - T(-d)|`` of a finely discretized chain
  against the elastic catenary with a frictionless seabed in closed form (Jonkman 2007, eqs. 2-2
  and 2-3 with ``C_B = 0``: ``X = L - V/w + H/w asinh(V/H) + H L / EA``,
  ``Z = H/w (sqrt(1 + (V/H)^2) - 1) + V^2 / (2 EA w)``, fairlead tension ``sqrt(H^2 + V^2)``).
* Its verdict on the time-domain comparisons of docs/frequency.md: the 300 m chain surging 0.1 m
  and in a JONSWAP sea at Hs 3 m stay ``ok``; surging 1 m (peaks 7-11 % off) and at Hs 8 m it is
  warned of; surging 2 m (std 10 %, peaks 34-53 % off) it fails, with the measured departure.
"""
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import fsolve

import kanat
from kanat.frequency import nonlinearity
from kanat.frequency.assembly import linear_model
from kanat.frequency.linearize import about_mean

from test_frequency_harmonic import CHAIN_FILE, surge
from test_frequency_irregular import irregular

SPAN, HEIGHT, LENGTH, AXIAL_STIFFNESS = 270.0, 55.0, 300.0, 7.536e8     # the MoorDyn file's chain


def catenary_top_tension(span: float, weight: float) -> float:
    """The fairlead tension [N] of the elastic catenary on a frictionless seabed (module docstring)."""
    def residual(p):
        H, V = np.exp(p)
        return [LENGTH - V / weight + H / weight * np.arcsinh(V / H) + H * LENGTH / AXIAL_STIFFNESS - span,
                H / weight * (np.sqrt(1 + (V / H) ** 2) - 1) + V ** 2 / (2 * AXIAL_STIFFNESS * weight) - HEIGHT]
    H, V = np.exp(fsolve(residual, np.log([2e4, 1e5]), xtol=1e-13))
    return float(np.hypot(H, V))


def chain(tmp_path, amplitude, segments=20):
    path = tmp_path / f"chain_{segments}.dat"
    path.write_text(CHAIN_FILE.replace("300       20 ", f"300       {segments} "))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(path)
    motion = [{**surge()[0], "amplitude": amplitude}]
    return case.replace({"model": "lumped", "vessel.motion": motion, "simulation.duration": 120.0,
                         "simulation.method": "frequency"})


@pytest.mark.slow
def test_the_measure_of_a_fine_chain_is_the_catenarys(tmp_path):
    """160 segments, the fairlead at its mean place and +-1 m about it: ``r`` at the fairlead within
    5 % of the closed form's (the 20-segment chain's is 0.146, its touchdown moving node by node)."""
    case = about_mean(chain(tmp_path, 1.0, segments=160))
    model = linear_model(case)
    check = nonlinearity.offset_check(model, case, np.array([[1.0, 0.0, 0.0]]), np.zeros(161))
    line = case.line_types["chain"]
    weight = (line.mass - case.environment.water_density * math.pi / 4 * line.diameter ** 2) * case.environment.gravity
    mean, up, down = (catenary_top_tension(SPAN + d, weight) for d in (0.0, 1.0, -1.0))
    assert abs(up + down - 2 * mean) / abs(up - down) == pytest.approx(check.ratio[-1], rel=0.05)
    assert check.mean[-1] == pytest.approx(mean, rel=0.01)


@pytest.mark.parametrize("amplitude, verdict, measured", [(0.1, "ok", 1.38), (1.0, "warning", 14.6),
                                                         (2.0, "failed", 29.1)])
def test_a_chain_surge_outside_the_linear_range_is_flagged(tmp_path, amplitude, verdict, measured):
    """The 300 m chain surging in 10 s, against the time domain (docs/frequency.md): 0.1 m ok (its
    tension within 1.4 %), 1 m warned of (std within 3.1 %, peaks 7-11 % off: the quadratic term),
    2 m failed (std 10 %, peaks 34-53 % off)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = kanat.solve_frequency(chain(tmp_path, amplitude))
    status, notes = ds.attrs["status"], ds.attrs["notes"]
    assert (status == "ok") is (verdict != "failed")
    assert ("warning: outside the linear range" in notes) is (verdict == "warning")
    assert any("outside the linear range" in str(w.message) for w in caught) is (verdict == "warning")
    if verdict == "failed":
        assert status.startswith("failed: outside the linear range")
    text = notes if verdict != "failed" else status
    departure = float(text.split("departs from the linear model's by ")[1].split(" %")[0])
    assert departure == pytest.approx(measured, rel=0.05)


@pytest.mark.slow
@pytest.mark.parametrize("hs, ok", [(3.0, True), (8.0, False)])
def test_a_sea_state_outside_the_linear_range_is_warned_of(tmp_path, hs, ok):
    """The chain driven by RAOs in a JONSWAP sea: Hs 3 m ok (3.3 %), Hs 8 m warned of (6.4 %); the
    excursion is 2 sigma of the fairlead's motion along its principal axis, at most the 2 sigma of
    its total motion (equal when surge and heave are in phase)."""
    case = irregular(tmp_path, "chain", hs, "frequency")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = kanat.solve_frequency(case)
    assert ds.attrs["status"] == "ok"
    warned = [str(w.message) for w in caught if "outside the linear range" in str(w.message)]
    assert bool(warned) is not ok
    assert ("warning: outside the linear range" in ds.attrs["notes"]) is not ok
    fairlead = int(np.argmax(ds.s.values))
    sigma = float(np.linalg.norm(ds.motion_std.values[fairlead]))
    text = ds.attrs["notes"]
    excursion = float(text.split("mean place +- ")[1].split(" m (2 sigma)")[0])
    assert 0.9 * 2 * sigma <= excursion <= 2 * sigma * 1.001
    assert float(text.split("departs from the linear model's by ")[1].split(" %")[0]) == pytest.approx(
        3.28 if ok else 6.41, rel=0.05)
