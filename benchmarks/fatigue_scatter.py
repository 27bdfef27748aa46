"""A wave scatter diagram written from the DNV-RP-C205 joint model of Hs and Tp.

The joint distribution is the Weibull-lognormal model of DNV-RP-C205 (2010) section 3.6.3:

* Hs follows a 3-parameter Weibull, ``F(h) = 1 - exp(-((h - gamma) / alpha)**beta)``;
* ln Tp given Hs = h is normal with mean ``mu(h) = a0 + a1 h**a2`` and standard deviation
  ``sigma(h) = b0 + b1 exp(b2 h)``.

The default parameters are the Northern North Sea set commonly quoted with this model (after
Haver and Nyhus, 1986); they were not checked against a copy of the standard here, and any site's
fit can be passed as a :class:`WeibullLognormal`. The heading is uniform over ``headings`` directions ``90 k / headings`` deg (0, 22.5, 45, 67.5
for 4), inside the span of the RAO table of ``examples/design/raos.csv`` (0 and 90 deg; the time
domain's RAO interpolation refuses a heading of exactly 90 deg there).

The grid: ``n_hs`` Hs classes of equal width from ``gamma`` to the Hs exceeded with probability
``HS_TOP_EXCEEDANCE`` (the last class open above), each represented by the Hs at its middle
probability; in each class ``n_tp`` Tp classes of equal conditional probability, represented by
the conditional lognormal quantile at their middle probability; so a cell's probability is
``P(Hs class) / (n_tp * headings)`` and the cells sum to 1.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.stats import norm

HS_TOP_EXCEEDANCE = 1.0e-3   # the last Hs class starts where Hs is exceeded 0.1 % of the time


@dataclass(frozen=True)
class WeibullLognormal:
    """Parameters of the DNV-RP-C205 section 3.6.3 joint model (Northern North Sea by default)."""

    alpha: float = 2.776      # m: Weibull scale
    beta: float = 1.471       # Weibull shape
    gamma: float = 0.8888     # m: Weibull location
    a0: float = 0.1000
    a1: float = 1.489
    a2: float = 0.1901
    b0: float = 0.0400
    b1: float = 0.1748
    b2: float = -0.2243

    def hs_cdf(self, hs: np.ndarray) -> np.ndarray:
        """Marginal CDF of Hs [m]: ``1 - exp(-((h - gamma) / alpha)**beta)``, 0 below ``gamma``."""
        x = np.clip((np.asarray(hs, dtype=float) - self.gamma) / self.alpha, 0.0, None)
        return 1.0 - np.exp(-x ** self.beta)

    def hs_quantile(self, p: np.ndarray) -> np.ndarray:
        """Inverse of :meth:`hs_cdf`."""
        return self.gamma + self.alpha * (-np.log1p(-np.asarray(p, dtype=float))) ** (1.0 / self.beta)

    def ln_tp(self, hs: float) -> tuple[float, float]:
        """Mean and standard deviation of ln Tp given Hs [m]."""
        return self.a0 + self.a1 * hs ** self.a2, self.b0 + self.b1 * math.exp(self.b2 * hs)


@dataclass(frozen=True)
class SeaStateCell:
    """One cell of the scatter diagram."""

    hs: float            # m
    tp: float            # s
    heading_deg: float
    probability: float   # fraction of the time


def grid_shape(sea_states: int) -> tuple[int, int, int]:
    """Classes ``(n_hs, n_tp, headings)`` whose product is ``sea_states``: 4, 2 or 1 headings
    (the most that leave at least 4 Hs x Tp cells), the rest split as evenly as it divides."""
    for headings in (4, 2, 1):
        rest, remainder = divmod(sea_states, headings)
        if remainder == 0 and rest >= 4 or headings == 1:
            break
    n_tp = max(d for d in range(1, int(math.isqrt(rest)) + 1) if rest % d == 0)
    return rest // n_tp, n_tp, headings


def scatter_diagram(sea_states: int = 100, model: WeibullLognormal = WeibullLognormal()) -> list[SeaStateCell]:
    """The ``sea_states`` cells of the grid described in the module docstring."""
    n_hs, n_tp, headings = grid_shape(sea_states)
    edges = hs_class_edges(n_hs, model)
    p_edges = np.append(model.hs_cdf(edges[:-1]), 1.0)
    cells = []
    for k in range(n_hs):
        hs = float(model.hs_quantile(0.5 * (p_edges[k] + p_edges[k + 1])))
        mu, sigma = model.ln_tp(hs)
        for j in range(n_tp):
            tp = math.exp(mu + sigma * norm.ppf((j + 0.5) / n_tp))
            for h in range(headings):
                cells.append(SeaStateCell(hs, tp, 90.0 * h / headings,
                                          float(p_edges[k + 1] - p_edges[k]) / (n_tp * headings)))
    return cells


def hs_class_edges(n_hs: int, model: WeibullLognormal = WeibullLognormal()) -> np.ndarray:
    """Edges of the Hs classes [m], ``n_hs + 1`` of them, the last ``inf``."""
    top = float(model.hs_quantile(1.0 - HS_TOP_EXCEEDANCE))
    return np.append(np.linspace(model.gamma, top, n_hs), np.inf)


def sea_state_table(cells: list[SeaStateCell], duration: float, gamma: float = 3.3) -> str:
    """The cells as a ``design.sea_states`` CSV table (docs/design.md)."""
    rows = ["name,hs,tp,gamma,heading_deg,probability,duration"]
    rows += [f"ss{k:03d},{c.hs:.4f},{c.tp:.4f},{gamma:g},{c.heading_deg:g},{c.probability:.12g},{duration:g}"
             for k, c in enumerate(cells)]
    return "\n".join(rows) + "\n"
