"""Rainflow counting against ASTM E1049 and published cycles, and Miner's damage against
``n R^M / K``.

Reference cycles (rows range, mean, count), written here as published:

* ASTM E1049-85 (2017) §5.4.4, Fig. 6: the history -2, 1, -3, 5, -1, 3, -4, 4, -2; its cycles
  as tabulated in the tests of the ``rainflow`` package (iamlikeme/rainflow, TEST_CASE_1);
* a 23-point history from the same tests (TEST_CASE_2) with its published cycles.
"""
import math

import numpy as np
import pytest

from kanat import catalog
from kanat.analysis import fatigue
from kanat.errors import KanatError

ASTM_E1049 = ([-2, 1, -3, 5, -1, 3, -4, 4, -2],
              [(3, -0.5, 0.5), (4, -1.0, 0.5), (4, 1.0, 1.0), (8, 1.0, 0.5), (9, 0.5, 0.5),
               (8, 0.0, 0.5), (6, 1.0, 0.5)])
RAINFLOW_CASE_2 = ([-1.5, 1.0, -3.0, 10.0, -1.0, 3.0, -8.0, 4.0, -2.0, 6.0, -1.0, -4.0, -8.0, 2.0, 1.0,
                    -5.0, 0.0, 2.5, -4.0, 1.0, 0.0, 2.0, -0.5],
                   [(2.5, -0.25, 0.5), (4.0, -1.00, 0.5), (4.0, 1.00, 1.0), (13.0, 3.50, 0.5),
                    (6.0, 1.00, 1.0), (14.0, -1.00, 1.0), (7.0, -1.50, 1.0), (1.0, 0.50, 1.0),
                    (18.0, 1.00, 0.5), (10.5, -2.75, 0.5), (6.5, -0.75, 0.5), (6.0, -1.00, 0.5),
                    (2.5, 0.75, 0.5)])


@pytest.mark.parametrize("series, cycles", [ASTM_E1049, RAINFLOW_CASE_2], ids=["astm-e1049", "case-2"])
def test_rainflow_reproduces_published_cycles(series, cycles):
    np.testing.assert_allclose(fatigue.rainflow(series), np.array(cycles, dtype=float), rtol=0, atol=1e-12)
    # plateaus and intermediate points on a slope change nothing
    dense = np.repeat(series, 3)
    ramps = np.concatenate([np.linspace(a, b, 5)[:-1] for a, b in zip(series, series[1:])] + [[series[-1]]])
    for other in (dense, ramps):
        np.testing.assert_allclose(fatigue.rainflow(other), np.array(cycles, dtype=float), atol=1e-12)


def _four_point_count(series) -> dict[float, float]:
    """An independent count: the four-point rainflow method (Amzallag et al. 1994, Int. J.
    Fatigue 16(4)): inner ranges enclosed by their neighbours are full cycles; the residue
    counts, as in ASTM E1049, a half cycle per range."""
    points = list(fatigue.reversals(series))
    counts: dict[float, float] = {}
    stack: list[float] = []
    for p in points:
        stack.append(p)
        while len(stack) >= 4:
            a, b, c, d = stack[-4:]
            inner = abs(c - b)
            if inner <= abs(b - a) and inner <= abs(d - c):
                counts[inner] = counts.get(inner, 0.0) + 1.0
                del stack[-3:-1]
            else:
                break
    for a, b in zip(stack, stack[1:]):
        counts[abs(b - a)] = counts.get(abs(b - a), 0.0) + 0.5
    return counts


def _by_range(cycles: np.ndarray) -> dict[float, float]:
    counts: dict[float, float] = {}
    for rng, _, n in cycles:
        counts[rng] = counts.get(rng, 0.0) + n
    return counts


@pytest.mark.parametrize("seed", range(5))
def test_rainflow_matches_an_independent_count_on_random_records(seed):
    """The four-point method finds the same cycles by another rule: range by range, the same
    counts (and so the same Miner sums)."""
    x = np.random.default_rng(seed).normal(size=2000).round(3)
    ours, other = _by_range(fatigue.rainflow(x)), _four_point_count(x)
    assert ours.keys() == other.keys()
    for r in ours:
        assert ours[r] == pytest.approx(other[r], abs=1e-12), r
    for m in (3.0, 5.0):
        miner = sum(n * r**m for r, n in other.items())
        assert sum(n * r**m for r, n in ours.items()) == pytest.approx(miner, rel=1e-12)


def test_rainflow_agrees_with_the_rainflow_package():
    rainflow = pytest.importorskip("rainflow")
    x = np.random.default_rng(7).normal(size=3000)
    theirs = np.array([(r, m, n) for r, m, n, _, _ in rainflow.extract_cycles(x)])
    np.testing.assert_allclose(fatigue.rainflow(x), theirs, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("curve", list(fatigue.TN_CURVES))
def test_constant_amplitude_damage_is_n_r_m_over_k(curve):
    mbl = catalog.chain_reference_breaking_load(0.076)
    mean, amplitude, cycles = 0.2 * mbl, 0.05 * mbl, 500
    t = np.linspace(0.0, cycles, 40 * cycles + 1)
    tension = mean - amplitude * np.cos(2.0 * np.pi * t)  # starts and ends at a valley
    c = fatigue.TN_CURVES[curve]
    k = 10.0 ** (c.log10_k - c.log10_k_per_mean * tension.mean() / mbl)  # the record's own L_m
    expected = cycles * (2.0 * amplitude / mbl) ** c.exponent / k
    assert fatigue.damage(tension, mbl, curve=curve) == pytest.approx(expected, rel=1e-9)


def test_api_curves_as_published():
    """API RP 2SK: studlink K = 1000, studless K = 316, M = 3.36; six-strand log K = 3.20 - 2.79 Lm,
    M = 4.09; spiral log K = 3.25 - 3.43 Lm, M = 5.05. At R = 0.1: N = K / 0.1^M."""
    r = 0.1
    assert fatigue.TN_CURVES["api-chain-studlink"].cycles_to_failure(r) == pytest.approx(1000 * 10**3.36)
    assert fatigue.TN_CURVES["api-chain-studless"].cycles_to_failure(r) == pytest.approx(316 * 10**3.36)
    assert fatigue.TN_CURVES["api-wire-six-strand"].cycles_to_failure(r, 0.3) == \
        pytest.approx(10 ** (3.20 - 2.79 * 0.3) * 10**4.09)
    assert fatigue.TN_CURVES["api-wire-spiral"].cycles_to_failure(r, 0.3) == \
        pytest.approx(10 ** (3.25 - 3.43 * 0.3) * 10**5.05)


@pytest.mark.parametrize("curve", list(fatigue.SN_CURVES))
def test_stress_damage_is_n_s_m_over_a(curve):
    """DNV-OS-E301: N = a_D s^-m, s in MPa; 300 cycles of 60 MPa."""
    c = fatigue.SN_CURVES[curve]
    t = np.linspace(0.0, 300.0, 300 * 40 + 1)
    stress = 100e6 - 30e6 * np.cos(2.0 * np.pi * t)
    assert fatigue.stress_damage(stress, curve) == pytest.approx(300 * 60.0**c.exponent / c.intercept, rel=1e-9)
    published = {"dnv-chain-studlink": (1.2e11, 3.0), "dnv-chain-studless": (6.0e10, 3.0),
                 "dnv-wire-six-strand": (3.4e14, 4.0), "dnv-wire-spiral": (1.7e17, 4.8)}
    assert (c.intercept, c.exponent) == published[curve]


def test_miner_sum_adds_blocks():
    """30 cycles of range 1e6 N, then 100 of range 4e5 N (valleys 5e5 and 8e5 N): by hand, the
    rainflow count is 30 cycles of 1e6, 99.5 of 4e5 and, left on the stack, the rise from the
    last large valley to the first small peak, 1.2e6 - 5e5: half a cycle of 7e5.
    D = sum n R^M / K (chain: no mean-load term)."""
    mbl = 5.0e6
    block = lambda amp, n: 1e6 - amp * np.cos(2 * np.pi * np.linspace(0, n, 20 * n + 1))
    tension = np.concatenate([block(5e5, 30), block(2e5, 100)])
    c = fatigue.TN_CURVES["api-chain-studlink"]
    counted = {(1e6, 30.0), (4e5, 99.5), (7e5, 0.5)}
    expected = sum(n * (r / mbl) ** c.exponent for r, n in counted) / 1000.0
    assert fatigue.damage(tension, mbl, "api-chain-studlink") == pytest.approx(expected, rel=1e-9)


def test_bad_inputs_say_what_is_wrong():
    with pytest.raises(KanatError, match="known: api-chain-studlink"):
        fatigue.damage([1.0, 2.0, 1.0], 1e6, curve="api-chain")
    with pytest.raises(KanatError, match="positive"):
        fatigue.damage([1.0, 2.0, 1.0], 0.0)
    with pytest.raises(KanatError, match="NaN"):
        fatigue.rainflow([1.0, math.nan, 2.0])
    assert fatigue.damage(np.full(10, 3.0e5), 1e6) == 0.0
