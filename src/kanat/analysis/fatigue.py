"""Fatigue of mooring lines: rainflow counting, T-N and S-N curves, Miner's sum.

Rainflow counting
-----------------
:func:`rainflow` is the three-point rainflow count of ASTM E1049-85 (reapproved 2017),
§5.4.4: the series is reduced to its reversals (turning points); each reversal is pushed on
a stack and, while the last range ``X`` is at least the one before it ``Y``, ``Y`` is
counted: as one cycle, or as half a cycle when ``Y`` holds the starting point (which is then
dropped); what remains on the stack at the end counts as half cycles. kanat counts with its
own forty lines rather than a dependency; the tests check them against the standard's
worked example, the published cycles of the ``rainflow`` package's tests and, on random
records, an independent four-point count (and the ``rainflow`` package itself when it is
installed: ``kanat[test]``).

Tension-range curves (T-N, API RP 2SK 3rd ed. 2005, §7.5)
-------------------------------------------------------
``N R^M = K``: ``N`` cycles to failure at the tension range ``R`` given as a fraction of the
reference breaking strength (``range / mbl``)::

    api-chain-studlink   M = 3.36  K = 1000
    api-chain-studless   M = 3.36  K = 316
    api-wire-six-strand  M = 4.09  log10 K = 3.20 - 2.79 L_m
    api-wire-spiral      M = 5.05  log10 K = 3.25 - 3.43 L_m

``L_m`` is the mean tension over the reference breaking strength (the record's own mean).
API RP 2SK takes as the reference breaking strength of chain, whatever its grade, the MBL
of ORQ chain of the same diameter (:func:`kanat.catalog.chain_reference_breaking_load`),
and the rope's own MBL for wire.

Stress-range curves (S-N, DNV-OS-E301 Ch.2 Sec.2 [6])
---------------------------------------------------
``N = a_D s^-m`` with ``s`` the stress range [MPa] on the nominal area (chain: the two bars
of a link, ``pi d^2 / 2``)::

    dnv-chain-studlink   a_D = 1.2e11  m = 3.0
    dnv-chain-studless   a_D = 6.0e10  m = 3.0
    dnv-wire-six-strand  a_D = 3.4e14  m = 4.0
    dnv-wire-spiral      a_D = 1.7e17  m = 4.8

Miner's rule: the damage of a record is ``D = sum_i n_i / N(range_i)`` over its rainflow
cycles (``n_i`` = 0.5 or 1); a constant-amplitude record of ``n`` cycles of range ``R`` on a
T-N curve has ``D = n R^M / K``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import KanatError

PASCAL_PER_MPA = 1.0e6


def reversals(series) -> np.ndarray:
    """The turning points of a series: its first and last values and every local extremum.

    Repeated values (a plateau) count once.

    Parameters
    ----------
    series : array_like, shape (n,)

    Returns
    -------
    ndarray, shape (n_reversals,)
    """
    x = np.asarray(series, dtype=float)
    if x.ndim != 1:
        raise KanatError(f"a rainflow count takes one series (a 1-D array); got shape {x.shape}")
    if not np.all(np.isfinite(x)):
        raise KanatError("the series holds NaN or infinite values; a rainflow count needs finite numbers")
    if x.size == 0:
        return x
    x = x[np.r_[True, np.diff(x) != 0.0]]
    if x.size < 3:
        return x
    slope = np.sign(np.diff(x))
    turning = np.flatnonzero(slope[1:] != slope[:-1]) + 1
    return x[np.r_[0, turning, x.size - 1]]


def rainflow(series) -> np.ndarray:
    """Rainflow cycles of a series (ASTM E1049-85 §5.4.4, module docstring).

    Parameters
    ----------
    series : array_like, shape (n,)
        A load history, e.g. the tension at one node [N].

    Returns
    -------
    ndarray, shape (n_cycles, 3)
        Rows ``(range, mean, count)``: the cycle's range (peak to valley), its mean, and
        ``count`` 1 for a full cycle or 0.5 for a half cycle, in the order they close.

    Examples
    --------
    >>> rainflow([-2, 1, -3, 5, -1, 3, -4, 4, -2])[:, [0, 2]].tolist()[:3]
    [[3.0, 0.5], [4.0, 0.5], [4.0, 1.0]]
    """
    cycles: list[tuple[float, float, float]] = []
    stack: list[float] = []
    for point in reversals(series):
        stack.append(point)
        while len(stack) >= 3:
            last, middle, first = stack[-1], stack[-2], stack[-3]
            if abs(last - middle) < abs(middle - first):
                break
            if len(stack) == 3:  # Y holds the starting point: half a cycle, drop the start
                cycles.append((abs(middle - first), 0.5 * (middle + first), 0.5))
                stack.pop(0)
            else:
                cycles.append((abs(middle - first), 0.5 * (middle + first), 1.0))
                del stack[-3:-1]
    cycles += [(abs(b - a), 0.5 * (a + b), 0.5) for a, b in zip(stack, stack[1:])]
    return np.array(cycles, dtype=float).reshape(-1, 3)


@dataclass(frozen=True)
class TNCurve:
    """A tension-range curve ``N R^M = K`` with ``log10 K = log10_k - log10_k_per_mean L_m``.

    Attributes
    ----------
    name : str
    exponent : float
        ``M`` [-].
    log10_k : float
        ``log10 K`` at zero mean load [-].
    log10_k_per_mean : float
        Decrease of ``log10 K`` per unit mean load ratio ``L_m`` (wire ropes; 0 for chain).
    source : str
    """

    name: str
    exponent: float
    log10_k: float
    log10_k_per_mean: float = 0.0
    source: str = "API RP 2SK 3rd ed. (2005) §7.5"

    def cycles_to_failure(self, range_ratio: np.ndarray, mean_ratio: float = 0.0) -> np.ndarray:
        """``N = K / R^M`` for tension ranges ``R`` as fractions of the reference strength.

        Parameters
        ----------
        range_ratio : ndarray
            ``R`` [-].
        mean_ratio : float
            ``L_m``, mean tension over the reference breaking strength [-].
        """
        k = 10.0 ** (self.log10_k - self.log10_k_per_mean * mean_ratio)
        with np.errstate(divide="ignore"):
            return k / np.asarray(range_ratio, dtype=float) ** self.exponent


@dataclass(frozen=True)
class SNCurve:
    """A stress-range curve ``N = a_D s^-m`` with ``s`` in MPa.

    Attributes
    ----------
    name : str
    exponent : float
        ``m`` [-].
    intercept : float
        ``a_D`` [MPa^m].
    source : str
    """

    name: str
    exponent: float
    intercept: float
    source: str = "DNV-OS-E301 Ch.2 Sec.2 [6]"

    def cycles_to_failure(self, stress_range: np.ndarray) -> np.ndarray:
        """``N = a_D s^-m`` for stress ranges ``s`` [Pa]."""
        s = np.asarray(stress_range, dtype=float) / PASCAL_PER_MPA
        with np.errstate(divide="ignore"):
            return self.intercept / s**self.exponent


TN_CURVES: dict[str, TNCurve] = {c.name: c for c in (
    TNCurve("api-chain-studlink", 3.36, math.log10(1000.0)),
    TNCurve("api-chain-studless", 3.36, math.log10(316.0)),
    TNCurve("api-wire-six-strand", 4.09, 3.20, 2.79),
    TNCurve("api-wire-spiral", 5.05, 3.25, 3.43),
)}
"""API RP 2SK tension-range curves by name."""

SN_CURVES: dict[str, SNCurve] = {c.name: c for c in (
    SNCurve("dnv-chain-studlink", 3.0, 1.2e11),
    SNCurve("dnv-chain-studless", 3.0, 6.0e10),
    SNCurve("dnv-wire-six-strand", 4.0, 3.4e14),
    SNCurve("dnv-wire-spiral", 4.8, 1.7e17),
)}
"""DNV-OS-E301 stress-range curves by name."""


def _curve(name: str, curves: dict):
    if isinstance(name, (TNCurve, SNCurve)):
        return name
    if name not in curves:
        raise KanatError(f"'{name}' is not a fatigue curve here; known: {', '.join(curves)}")
    return curves[name]


def damage(tension, mbl: float, curve: str | TNCurve = "api-chain-studless") -> float:
    """Miner's damage of a tension record on a T-N curve (module docstring).

    ``D = sum_i n_i R_i^M / K`` over the rainflow cycles of ``tension``, ``R_i`` = cycle
    range / ``mbl``, ``K`` at the record's mean load ratio ``L_m = mean(tension) / mbl``.

    Parameters
    ----------
    tension : array_like, shape (n,)
        Tension history [N].
    mbl : float
        Reference breaking strength [N] (for API's chain curves, ORQ chain's MBL of the
        same diameter: :func:`kanat.catalog.chain_reference_breaking_load`).
    curve : str or TNCurve
        A name of :data:`TN_CURVES` or a curve of one's own.

    Returns
    -------
    float
        Damage of the record [-] (1 is failure).
    """
    if not mbl > 0:
        raise KanatError(f"the reference breaking strength must be positive (got {mbl!r} N)")
    t_n = _curve(curve, TN_CURVES)
    tension = np.asarray(tension, dtype=float)
    cycles = rainflow(tension)
    if cycles.size == 0:
        return 0.0
    n = t_n.cycles_to_failure(cycles[:, 0] / mbl, mean_ratio=float(tension.mean()) / mbl)
    return float(np.sum(cycles[:, 2] / n))


def stress_damage(stress, curve: str | SNCurve = "dnv-chain-studless") -> float:
    """Miner's damage of a stress record on an S-N curve, ``sum_i n_i s_i^m / a_D``.

    Parameters
    ----------
    stress : array_like, shape (n,)
        Nominal stress history [Pa] (tension over the nominal area: ``pi d^2 / 2`` for chain).
    curve : str or SNCurve
        A name of :data:`SN_CURVES` or a curve of one's own.

    Returns
    -------
    float
        Damage of the record [-].
    """
    s_n = _curve(curve, SN_CURVES)
    cycles = rainflow(stress)
    if cycles.size == 0:
        return 0.0
    return float(np.sum(cycles[:, 2] / s_n.cycles_to_failure(cycles[:, 0])))
