"""DNV-OS-E301 partial factors against hand calculations, and the design check from tension
spectra (the seam a frequency-domain solver plugs into: ``kanat.design(case, spectral_analysis=f)``).

The spectral analysis here is a stand-in with a known answer: the statics of the case it is given
(its mean tensions) and, at every node, a JONSWAP-shaped tension spectrum with a standard deviation
of 8 % of the node's mean tension at the sea state's Hs and Tp. The tables are checked against the
MPM and Dirlik damage worked out here from those spectra's moments.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import yaml

import kanat
from kanat.analysis import spectral
from kanat.catalog import chain_reference_breaking_load
from kanat.design_checks import design
from kanat.design_checks.factors import DNV_CAPACITY_FACTOR, required_safety_factor
from kanat.design_checks.spectral_check import LineSpectra
from kanat.errors import KanatError
from kanat.physics.waves import jonswap_spectrum

from helpers import EXAMPLES

EXAMPLE = EXAMPLES / "design" / "mooring_design.yaml"
YEAR = 365.25 * 86400.0
OMEGA = np.linspace(0.2, 3.0, 800)
RELATIVE_STD = 0.08
SEA_STATES = """name,hs,tp,gamma,heading_deg,probability,duration
calm,1.5,6.0,3.3,0,0.6,40
rough,4.0,8.0,2.0,30,0.05,40
"""


@pytest.mark.parametrize("condition, cls, mean, mpm, gammas", [
    ("intact", 1, 2.0e6, 3.0e6, (1.10, 1.50)), ("intact", 2, 2.0e6, 3.0e6, (1.40, 2.10)),
    ("damaged:leg1", 1, 2.5e6, 3.1e6, (1.00, 1.10)), ("damaged", 2, 2.5e6, 3.1e6, (1.00, 1.25))])
def test_dnv_os_e301_design_tension_against_0_95_mbs(condition, cls, mean, mpm, gammas):
    """T_d = gamma_mean T_mean + gamma_dyn (T_MPM - T_mean) <= 0.95 MBS, written as MBL / T_MPM >= required."""
    required = required_safety_factor("dnv-os-e301", "dynamic", condition, mean, mpm, cls)
    design_tension = gammas[0] * mean + gammas[1] * (mpm - mean)
    assert required == pytest.approx(design_tension / (0.95 * mpm), rel=1e-14)
    # intact class 1 by hand: 1.10 x 2.0 + 1.50 x 1.0 = 3.7 MN, needs an MBL of 3.7 / 0.95 = 3.8947 MN
    if (condition, cls) == ("intact", 1):
        assert design_tension / DNV_CAPACITY_FACTOR == pytest.approx(3.7e6 / 0.95)
    for mbl in (0.999 * design_tension / 0.95, 1.001 * design_tension / 0.95):
        assert (mbl / mpm >= required) == (design_tension <= 0.95 * mbl)


def test_dnv_without_consequence_class_or_in_quasi_static_is_refused():
    with pytest.raises(KanatError, match="consequence_class: missing"):
        required_safety_factor("dnv-os-e301", "dynamic", "intact", 1.0, 2.0)
    with pytest.raises(KanatError, match="not verified"):
        required_safety_factor("dnv-os-e301", "quasi-static", "intact", 1.0, 2.0, 1)


def shape(hs, tp, gamma):
    """The tension spectrum's shape: JONSWAP, scaled to unit variance."""
    s = jonswap_spectrum(OMEGA, hs, tp, gamma)
    return s / np.trapezoid(s, OMEGA)


def stand_in_analysis(case):
    """Mean tensions from the statics; spectra of std 8 % of the mean, JONSWAP-shaped."""
    ds = kanat.solve_statics(case)
    waves = case.environment.waves
    unit = shape(waves.hs, waves.tp, waves.gamma)
    found = {}
    for cable in case.cables:
        nodes = ds.cable.values == cable.name
        mean = ds.tension.values[nodes]
        found[cable.name] = LineSpectra(ds.s.values[nodes], mean, OMEGA,
                                        np.outer(unit, (RELATIVE_STD * mean) ** 2))
    return found


@pytest.fixture(scope="module")
def checked(tmp_path_factory):
    folder = tmp_path_factory.mktemp("spectral")
    data = yaml.safe_load(EXAMPLE.read_text())
    data["design"].update(analysis="frequency", standard="dnv-os-e301", consequence_class=2,
                          conditions=["intact", "leg2"])
    (folder / "sea_states.csv").write_text(SEA_STATES)
    (folder / "case.yaml").write_text(yaml.safe_dump(data, sort_keys=False))
    case = kanat.load_case(folder / "case.yaml")
    return case, design(case, spectral_analysis=stand_in_analysis)


def test_utilisation_from_spectra_is_the_hand_mpm_and_dnv_check(checked):
    case, result = checked
    assert not result.failures and len(result.utilisation) == 2 * (3 + 2)
    statics = {"intact": kanat.solve_statics(case)}
    for row in result.utilisation.itertuples():
        sea = next(s for s in case.design.sea_state_rows if s.name == row.sea_state)
        if row.condition not in statics:
            statics[row.condition] = result.statics[row.condition]
        ds = statics[row.condition]
        tension = ds.tension.values[ds.cable.values == row.line]
        mean = max(tension[0], tension[-1])
        unit = shape(sea.hs, sea.tp, sea.gamma)
        m0, m2 = [np.trapezoid(OMEGA**n * unit, OMEGA) * (RELATIVE_STD * mean) ** 2 for n in (0, 2)]
        n = math.sqrt(m2 / m0) / (2 * math.pi) * case.design.storm_duration
        mpm = mean + math.sqrt(m0) * math.sqrt(2 * math.log(n))
        assert row.mpm_tension == pytest.approx(mpm, rel=1e-6)
        gamma_mean, gamma_dyn = (1.40, 2.10) if row.condition == "intact" else (1.00, 1.25)
        design_tension = gamma_mean * mean + gamma_dyn * (mpm - mean)
        assert row.required_safety_factor == pytest.approx(design_tension / (0.95 * mpm), rel=1e-6)
        assert row.ok == (design_tension <= 0.95 * row.mbl)


def test_fatigue_from_spectra_is_the_dirlik_sum_over_the_sea_states(checked):
    case, result = checked
    ds = kanat.solve_statics(case)
    reference = chain_reference_breaking_load(0.076)
    for cable in ("leg1", "leg3"):
        mean = ds.tension.values[ds.cable.values == cable]
        expected = np.zeros_like(mean)
        for sea in case.design.sea_state_rows:
            unit = shape(sea.hs, sea.tp, sea.gamma)
            for k, t in enumerate(mean):
                moments = spectral.spectral_moments(OMEGA, unit * (RELATIVE_STD * t) ** 2)
                expected[k] += spectral.dirlik_damage_rate(moments.scaled(1 / reference), 3.36, 316.0) \
                    * sea.probability * YEAR
        rows = result.fatigue[result.fatigue.line == cable]
        np.testing.assert_allclose(rows.damage_per_year.values, expected, rtol=1e-6)
        np.testing.assert_allclose(rows.life_years.values, 1 / expected, rtol=1e-6)


def test_frequency_analysis_needs_the_rayleigh_estimator(checked):
    case, _ = checked
    with pytest.raises(KanatError, match="extremes: rayleigh"):
        design(case.replace({"design.extremes": "gumbel"}), spectral_analysis=stand_in_analysis)


def test_a_spectral_analysis_missing_a_cable_is_a_clear_error(checked):
    case, _ = checked

    def partial(variant):
        found = stand_in_analysis(variant)
        found.pop("leg1", None)
        return found

    with pytest.raises(KanatError, match="no tension spectra for cable 'leg1'"):
        design(case.replace({"design.conditions": ["intact"]}), spectral_analysis=partial)
