"""The scatter diagram of ``benchmarks/bench_fatigue_frequency.py``.

Oracles: the cells' probabilities sum to 1; the Hs marginal they add up to is the DNV-RP-C205
3-parameter Weibull, checked against scipy's ``weibull_min`` at every class edge (1e-12) and by
its mean (the classes' representative Hs weighted by probability against ``gamma + alpha
Gamma(1 + 1/beta)``, within 3 %: the discretisation of 5 classes); within each Hs class the Tp
classes are equiprobable and their median is the lognormal's ``exp(mu(Hs))``.
"""
from __future__ import annotations

import math
import sys

import numpy as np
import pytest
from scipy.stats import weibull_min

from helpers import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
from fatigue_scatter import (WeibullLognormal, grid_shape, hs_class_edges,  # noqa: E402
                             scatter_diagram, sea_state_table)

MODEL = WeibullLognormal()


@pytest.mark.parametrize("sea_states", [100, 10, 12, 7])
def test_the_probabilities_sum_to_one(sea_states):
    cells = scatter_diagram(sea_states)
    assert len(cells) == sea_states == math.prod(grid_shape(sea_states))
    assert sum(c.probability for c in cells) == pytest.approx(1.0, abs=1e-12)
    assert all(c.probability > 0 for c in cells)


@pytest.mark.parametrize("sea_states", [100, 10])
def test_the_hs_marginal_is_the_weibull_it_claims(sea_states):
    cells = scatter_diagram(sea_states)
    n_hs = grid_shape(sea_states)[0]
    edges = hs_class_edges(n_hs)
    hs = np.array([c.hs for c in cells])
    p = np.array([c.probability for c in cells])
    oracle = weibull_min(MODEL.beta, loc=MODEL.gamma, scale=MODEL.alpha)
    for edge in edges[1:-1]:
        assert p[hs < edge].sum() == pytest.approx(oracle.cdf(edge), abs=1e-12)
    assert np.sum(p * hs) == pytest.approx(oracle.mean(), rel=0.03)


def test_the_tp_classes_are_equiprobable_about_the_lognormal_median():
    cells = scatter_diagram(100)                    # 5 Hs x 5 Tp x 4 headings
    for hs in sorted({c.hs for c in cells}):
        row = [c for c in cells if c.hs == hs and c.heading_deg == 0.0]
        assert len({round(c.probability, 15) for c in row}) == 1
        assert np.median([c.tp for c in row]) == pytest.approx(math.exp(MODEL.ln_tp(hs)[0]), rel=1e-12)


def test_the_table_is_a_design_sea_state_table():
    text = sea_state_table(scatter_diagram(10), duration=1800)
    lines = text.splitlines()
    assert lines[0] == "name,hs,tp,gamma,heading_deg,probability,duration"
    assert len(lines) == 11
    assert sum(float(line.split(",")[5]) for line in lines[1:]) == pytest.approx(1.0, abs=1e-9)
