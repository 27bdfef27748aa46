"""Extremes of a response over a storm: the most probable maximum (MPM) from one or several
seeds, by three estimators.

``rayleigh``
    Narrow-band Gaussian response (DNV-RP-C205 §3.3; Ochi, *Ocean Waves*, 1998): the peaks
    above the mean are Rayleigh distributed and the most probable largest of ``N`` of them is
    ``MPM = mean + sigma sqrt(2 ln N)``, ``N = duration / T_z`` with ``T_z`` the mean
    zero-upcrossing period of the record (``x - mean``). Per seed, then averaged.
``weibull``
    A two-parameter Weibull fitted (maximum likelihood, :func:`scipy.stats.weibull_min.fit`
    with the location at 0) to the peaks above the mean, the largest value between two
    successive up-crossings, pooled over the seeds; with the exceedance probability
    ``exp(-(x / s)^c)`` of one peak, the most probable largest of ``N`` peaks is
    ``x = s (ln N)^(1/c)`` (``1 - F(x) = 1 / N``), added to the mean (API RP 2SK 3rd ed.
    Appendix; Rayleigh is ``c = 2``, ``s = sqrt(2) sigma``).
``gumbel``
    A Gumbel distribution (:func:`scipy.stats.gumbel_r.fit`) fitted to the maxima of the
    seeds (DNV-OS-E301 Ch.2 Sec.2 [2.4]): its mode ``mu`` is the MPM of one record; a storm
    ``k`` times longer than the records has its MPM at ``mu + beta ln k`` (the maximum of
    ``k`` independent Gumbel maxima is Gumbel with the same ``beta``). Needs at least 3
    seeds.

The spread reported with each estimate is the standard deviation of the per-seed estimates
(rayleigh, weibull; NaN with one seed) or of the fitted distribution of the storm maximum,
``pi beta / sqrt(6)`` (gumbel).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import stats

from kanat.errors import KanatError

METHODS = ("rayleigh", "weibull", "gumbel")
"""The estimators :func:`mpm` knows."""

MIN_GUMBEL_SEEDS = 3
"""Fewest seeds a Gumbel fit takes (two parameters from two maxima fit them exactly)."""

MIN_PEAKS = 10
"""Fewest peaks a Weibull fit takes."""


@dataclass(frozen=True)
class Extreme:
    """A most probable maximum and how it was found.

    Attributes
    ----------
    value : float
        The MPM over ``duration``, in the units of the series.
    method : str
        ``rayleigh``, ``weibull`` or ``gumbel``.
    spread : float
        Standard deviation of the estimate (module docstring).
    duration : float
        Exposure [s] the MPM is for.
    per_seed : ndarray, shape (n_seeds,)
        Per-seed MPMs (rayleigh, weibull) or per-seed maxima (gumbel).
    parameters : dict
        The fitted distribution: ``sigma`` (rayleigh, per-seed mean), ``shape`` and
        ``scale`` (weibull), ``location`` and ``scale`` (gumbel); and ``cycles``, ``N``.
    """

    value: float
    method: str
    spread: float
    duration: float
    per_seed: np.ndarray
    parameters: dict

    def __float__(self) -> float:
        return self.value


def _seeds(series, time) -> tuple[np.ndarray, np.ndarray, float]:
    """Series as (n_seeds, n_time), time as (n_time,) and the record length [s]."""
    x = np.atleast_2d(np.asarray(series, dtype=float))
    t = np.asarray(time, dtype=float)
    if x.ndim != 2 or t.ndim != 1 or x.shape[1] != t.size:
        raise KanatError(f"series must be (n_time,) or (n_seeds, n_time) along time ({t.size} "
                         f"instants); got shape {np.shape(series)}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(t))):
        raise KanatError("the series or the time holds NaN or infinite values")
    length = float(t[-1] - t[0]) if t.size else 0.0
    if length <= 0:
        raise KanatError("the record lasts no time; an MPM needs a record over time")
    return x, t, length


def upcrossing_indices(values: np.ndarray) -> np.ndarray:
    """Indices ``i`` where ``values`` crosses zero upwards between samples ``i-1`` and ``i``."""
    return np.flatnonzero((values[:-1] < 0.0) & (values[1:] >= 0.0)) + 1


def peaks_above_mean(record: np.ndarray) -> np.ndarray:
    """Largest excess over the mean between each two successive zero up-crossings.

    Parameters
    ----------
    record : ndarray, shape (n_time,)

    Returns
    -------
    ndarray, shape (n_cycles,)
        One peak per complete cycle (``n_cycles`` = up-crossings - 1), each > 0.
    """
    centred = record - record.mean()
    up = upcrossing_indices(centred)
    return np.array([centred[a:b].max() for a, b in zip(up, up[1:])])


def rayleigh_mpm(record: np.ndarray, length: float, duration: float) -> tuple[float, float, float]:
    """``mean + sigma sqrt(2 ln N)``, ``N = duration x upcrossings / length``.

    Returns
    -------
    mpm, sigma, n : float
    """
    sigma = float(record.std())
    upcrossings = upcrossing_indices(record - record.mean()).size
    if sigma == 0.0:
        return float(record.mean()), 0.0, 0.0
    if upcrossings < 2:
        raise KanatError(f"the record crosses its mean upwards {upcrossings} time(s); a Rayleigh "
                         f"MPM needs many cycles: lengthen the record")
    n = duration * upcrossings / length
    return float(record.mean()) + sigma * math.sqrt(2.0 * math.log(max(n, 1.0))), sigma, n


def weibull_fit(peaks: np.ndarray) -> tuple[float, float]:
    """Shape ``c`` and scale ``s`` of a two-parameter Weibull fitted to positive peaks
    (maximum likelihood, :func:`scipy.stats.weibull_min.fit`, location 0)."""
    peaks = np.asarray(peaks, dtype=float)
    if peaks.size < MIN_PEAKS:
        raise KanatError(f"{peaks.size} peaks are too few for a Weibull fit (at least {MIN_PEAKS}): "
                         f"lengthen the record or use method='rayleigh'")
    shape, _, scale = stats.weibull_min.fit(peaks, floc=0.0)
    return float(shape), float(scale)


def weibull_mpm(shape: float, scale: float, n: float) -> float:
    """Most probable largest of ``n`` Weibull peaks, ``scale (ln n)^(1 / shape)``."""
    return scale * math.log(max(n, 1.0)) ** (1.0 / shape)


def gumbel_fit(maxima: np.ndarray) -> tuple[float, float]:
    """Location ``mu`` and scale ``beta`` of a Gumbel fitted to maxima
    (maximum likelihood, :func:`scipy.stats.gumbel_r.fit`)."""
    maxima = np.asarray(maxima, dtype=float)
    if maxima.size < MIN_GUMBEL_SEEDS:
        raise KanatError(f"a Gumbel fit needs the maxima of at least {MIN_GUMBEL_SEEDS} seeds "
                         f"(got {maxima.size}); run more seeds or use method='rayleigh'")
    location, scale = stats.gumbel_r.fit(maxima)
    return float(location), float(scale)


def _spread(values: np.ndarray) -> float:
    return float(np.std(values, ddof=1)) if values.size > 1 else math.nan


def _rayleigh(x: np.ndarray, length: float, duration: float) -> Extreme:
    estimates = [rayleigh_mpm(record, length, duration) for record in x]
    per_seed = np.array([e[0] for e in estimates])
    return Extreme(float(per_seed.mean()), "rayleigh", _spread(per_seed), duration, per_seed,
                   {"sigma": float(np.mean([e[1] for e in estimates])),
                    "N": float(np.mean([e[2] for e in estimates]))})


def _weibull(x: np.ndarray, length: float, duration: float) -> Extreme:
    peaks = [peaks_above_mean(record) for record in x]
    # N peaks in the storm: one per zero up-crossing, counted over all seeds
    n = duration * sum(p.size for p in peaks) / (length * len(peaks))
    shape, scale = weibull_fit(np.concatenate(peaks))
    mean = float(x.mean())
    per_seed = np.array([record.mean() + weibull_mpm(*weibull_fit(p), n) for record, p in zip(x, peaks)]) \
        if len(peaks) > 1 else np.array([mean + weibull_mpm(shape, scale, n)])
    return Extreme(mean + weibull_mpm(shape, scale, n), "weibull", _spread(per_seed), duration,
                   per_seed, {"shape": shape, "scale": scale, "N": n})


def _gumbel(x: np.ndarray, length: float, duration: float) -> Extreme:
    maxima = x.max(axis=1)
    location, scale = gumbel_fit(maxima)
    value = location + scale * math.log(duration / length)
    return Extreme(value, "gumbel", math.pi * scale / math.sqrt(6.0), duration, maxima,
                   {"location": location, "scale": scale})


_ESTIMATORS = {"rayleigh": _rayleigh, "weibull": _weibull, "gumbel": _gumbel}


def mpm(series, time, duration: float, method: str = "rayleigh") -> Extreme:
    """Most probable maximum of a response over a storm (module docstring).

    Parameters
    ----------
    series : array_like, shape (n_time,) or (n_seeds, n_time)
        One record, or one per seed (the same instants), e.g. the tension at a node [N].
        Cut off the start-up transient first.
    time : array_like, shape (n_time,)
        [s].
    duration : float
        The storm's duration [s] (e.g. 10800 for 3 hours); may exceed the records.
    method : {"rayleigh", "weibull", "gumbel"}

    Returns
    -------
    Extreme
        ``value`` (the MPM), ``method``, ``spread``, per-seed values and fitted parameters.
    """
    if method not in _ESTIMATORS:
        raise KanatError(f"unknown extreme-value method '{method}'; known: {', '.join(METHODS)}")
    if not duration > 0:
        raise KanatError(f"the storm duration must be positive (got {duration!r} s)")
    x, _, length = _seeds(series, time)
    return _ESTIMATORS[method](x, length, duration)
