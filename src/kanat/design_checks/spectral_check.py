"""The design check from tension spectra (``design.analysis: frequency``): the seam between
:func:`kanat.design_checks.design` and a frequency-domain analysis.

A *spectral analysis* is any function ``analysis(case) -> dict[str, LineSpectra]`` that takes the
case of one condition in one sea state (its waves the sea state's JONSWAP sea, as the dynamic
runs take it) and returns, per cable, the mean tension and the one-sided tension spectrum at
its nodes. From it, per line and sea state:

* the MPM of the fairlead tension (the end with the larger mean) over ``storm_duration`` from the
  spectrum's moments (:func:`kanat.analysis.spectral.most_probable_maximum`; ``extremes:
  rayleigh`` gives the Rayleigh MPM, the other estimators fit records and do not apply);
* at every node, Dirlik's fatigue damage per second on the design's T-N curve
  (:func:`kanat.analysis.spectral.tension_damage_rate`), times ``probability x YEAR``.

``kanat.design(case, spectral_analysis=...)`` takes one; by default (and in ``kanat design``) it
is :func:`frequency_domain`, kanat's frequency-domain solution of the lumped model
(:func:`kanat.frequency.solve_frequency`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from kanat.analysis.spectral import most_probable_maximum, spectral_moments, tension_damage_rate
from kanat.errors import KanatError
from kanat.model import Case

from . import records

SPECTRAL_EXTREMES = {"rayleigh": "rayleigh"}
"""``design.extremes`` -> the spectral MPM method it stands for."""


@dataclass(frozen=True)
class LineSpectra:
    """Tension spectra along one cable.

    Attributes
    ----------
    s : ndarray, shape (n_nodes,)
        Unstretched arclength of the nodes from the cable's ``from`` end [m].
    mean : ndarray, shape (n_nodes,)
        Mean tension [N].
    omega : ndarray, shape (n_freq,)
        Angular frequencies [rad/s], increasing.
    density : ndarray, shape (n_freq, n_nodes)
        One-sided spectral density of the tension [N^2 s/rad].
    width : ndarray, shape (n_freq,), or None
        The band each frequency stands for [rad/s] (a line spectrum, such as the frequency domain's
        at a JONSWAP sea's unequally spaced components); None: ``density`` samples a continuous
        spectrum (:func:`kanat.analysis.spectral.spectral_moments`).
    """

    s: np.ndarray
    mean: np.ndarray
    omega: np.ndarray
    density: np.ndarray
    width: np.ndarray | None = None

    def __post_init__(self):
        n = np.shape(self.s)[0]
        if np.shape(self.mean) != (n,) or np.shape(self.density) != (np.shape(self.omega)[0], n):
            raise KanatError(f"line spectra of {n} nodes need mean (n_nodes,) and density (n_freq, n_nodes); "
                             f"got {np.shape(self.mean)} and {np.shape(self.density)}")

    @property
    def fairlead(self) -> int:
        """Index of the end node with the larger mean tension."""
        return 0 if self.mean[0] >= self.mean[-1] else len(self.mean) - 1

    def moments(self, node: int):
        """:class:`kanat.analysis.spectral.SpectralMoments` at ``node``."""
        return spectral_moments(self.omega, self.density[:, node], self.width)


SpectralAnalysis = Callable[[Case], "dict[str, LineSpectra]"]
"""``analysis(case) -> {cable: LineSpectra}`` for the case of one condition in one sea state."""


def spectral_method(extremes: str) -> str:
    """The spectral MPM method of ``design.extremes``; raises for the record-fitting estimators."""
    if extremes not in SPECTRAL_EXTREMES:
        raise KanatError(f"design.extremes: {extremes}: a frequency-domain check takes the MPM from the "
                         f"tension spectrum; use extremes: {', '.join(SPECTRAL_EXTREMES)}")
    return SPECTRAL_EXTREMES[extremes]


def fairlead_extreme(spectra: LineSpectra, duration: float, extremes: str) -> tuple[float, float]:
    """Mean and most probable maximum [N] of the fairlead tension over ``duration``."""
    node = spectra.fairlead
    mean = float(spectra.mean[node])
    return mean, most_probable_maximum(spectra.moments(node), duration, mean, spectral_method(extremes))


def annual_damage(variant: Case, cable: str, spectra: LineSpectra, probability: float) -> np.ndarray:
    """Dirlik's damage per year at every node of ``cable`` in one sea state, shape (n_nodes,)."""
    curve = variant.design.fatigue.curve
    kinds = records.line_types_along(variant, cable, spectra.s)
    strength = [records.reference_strength(variant, kind, curve) for kind in kinds]
    rates = [tension_damage_rate(spectra.moments(k), ref, curve, float(spectra.mean[k]))
             for k, ref in enumerate(strength)]
    return np.array(rates) * probability * records.YEAR


def frequency_domain(case: Case) -> "dict[str, LineSpectra]":
    """The spectral analysis of ``design.analysis: frequency``: :func:`kanat.frequency.solve_frequency`
    of the case (the lumped model linearised about its equilibrium, drag by stochastic
    linearisation in the sea state's JONSWAP sea), per cable its nodes' mean tension and tension
    spectrum in the order of ``s``, a line spectrum whose lines weigh their bins' width
    (``frequency_width``), so that its ``m_0`` is the solution's ``tension_std`` squared.

    A solution that fails its own checks (a node whose expected largest peak exceeds its mean
    tension goes slack; the drag linearisation did not converge) is a failure of that sea state
    (:class:`kanat.errors.KanatError` with the solver's status), never a row of numbers. A node
    where cables meet (a body) counts for the cable the lumped network gives it; the fairlead
    of a cable is its end node with the larger mean tension (:attr:`LineSpectra.fairlead`).
    """
    from kanat.frequency import solve_frequency

    ds = solve_frequency(case)
    status = str(ds.attrs.get("status", ""))
    if status != "ok":
        raise KanatError(f"the frequency-domain solution failed its own checks: {status}")
    cables = ds["cable"].values.astype(str)
    spectra = {}
    for cable in case.cables:
        nodes = np.flatnonzero(cables == cable.name)
        nodes = nodes[np.argsort(ds["s"].values[nodes], kind="stable")]
        spectra[cable.name] = LineSpectra(s=ds["s"].values[nodes], mean=ds["mean_tension"].values[nodes],
                                          omega=ds["frequency"].values,
                                          density=ds["tension_spectrum"].values[:, nodes],
                                          width=ds["frequency_width"].values)
    return spectra
