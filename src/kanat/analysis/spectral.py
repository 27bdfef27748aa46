"""Spectral fatigue and extremes of a Gaussian response from its one-sided spectrum.

A stationary Gaussian response ``x(t)`` (a line's tension about its mean, say) with the
one-sided spectrum ``S(omega)`` [units^2 s/rad] has the spectral moments

    ``m_n = integral of omega^n S(omega) d omega``   (``m_0`` is the variance)

from which follow (Rice 1944; Cartwright & Longuet-Higgins 1956, *Proc. R. Soc. A* 237):

* the rate of mean up-crossings ``nu_0 = sqrt(m_2 / m_0) / (2 pi)`` [1/s] and of maxima
  (peaks) ``nu_p = sqrt(m_4 / m_2) / (2 pi)``;
* the irregularity factor ``alpha_2 = m_2 / sqrt(m_0 m_4) = nu_0 / nu_p`` and the spectral
  bandwidth ``epsilon = sqrt(1 - alpha_2^2)`` (0: narrow band, 1: white).

Fatigue damage per unit time on a curve ``N = K S^-m`` (``S`` the cycle's range):

``narrow-band`` (Bendat 1964; DNV-RP-C203 2016 App.D eq. D.2.6, DNV-RP-F204 2017 §4.3): the
ranges are twice Rayleigh-distributed amplitudes, one cycle per up-crossing::

    D / T = nu_0 / K (2 sqrt(2 m_0))^m Gamma(1 + m/2)

``dirlik`` (Dirlik 1985, *Application of computers in fatigue analysis*, PhD thesis, Univ.
of Warwick; as DNV-RP-F204 §4.3 and Bishop & Sherratt 1989 write it): one cycle per peak,
ranges distributed as an exponential and two Rayleigh parts in ``Z = S / (2 sqrt(m_0))``::

    x_m = m_1 / m_0 sqrt(m_2 / m_4)
    D_1 = 2 (x_m - alpha_2^2) / (1 + alpha_2^2)
    R   = (alpha_2 - x_m - D_1^2) / (1 - alpha_2 - D_1 + D_1^2)
    D_2 = (1 - alpha_2 - D_1 + D_1^2) / (1 - R)
    D_3 = 1 - D_1 - D_2
    Q   = 1.25 (alpha_2 - D_3 - D_2 R) / D_1
    p(S) = [D_1/Q e^(-Z/Q) + D_2 Z/R^2 e^(-Z^2/(2R^2)) + D_3 Z e^(-Z^2/2)] / (2 sqrt(m_0))
    D / T = nu_p / K (2 sqrt(m_0))^m [D_1 Q^m Gamma(1+m) + 2^(m/2) Gamma(1+m/2) (D_2 |R|^m + D_3)]

The T-N and S-N curves are those of :mod:`kanat.analysis.fatigue` (API RP 2SK in tension
range over the reference strength, DNV-OS-E301 in stress range in MPa).

Extremes over a duration ``T`` (:func:`most_probable_maximum`):

``rayleigh``
    ``mean + sigma sqrt(2 ln(nu_0 T))``: the narrow-band MPM with one peak per up-crossing
    (DNV-RP-C205 §3.3), as :func:`kanat.analysis.extremes.mpm` takes from a record.
``cartwright-longuet-higgins``
    The mode of the largest of ``N = nu_p T`` maxima drawn from Cartwright & Longuet-Higgins'
    distribution of the maxima of a Gaussian process of bandwidth ``epsilon``, found
    numerically (their eq. 3.7 for the peak distribution)::

        F(eta) = Phi(eta / epsilon) - sqrt(1 - epsilon^2) e^(-eta^2/2) Phi(sqrt(1 - epsilon^2) eta / epsilon)

    (``eta`` the maximum over ``sigma``); it tends to the Rayleigh MPM for a narrow band and
    long storms, and is lower for a broad band (more, smaller and partly negative maxima).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize, special, stats
from scipy.integrate import trapezoid

from kanat.analysis.fatigue import PASCAL_PER_MPA, SN_CURVES, TN_CURVES, SNCurve, TNCurve
from kanat.errors import KanatError

MPM_METHODS = ("rayleigh", "cartwright-longuet-higgins")
"""The estimators :func:`most_probable_maximum` knows."""

DAMAGE_METHODS = ("dirlik", "narrow-band")
"""The spectral damage models :func:`damage_rate` knows."""

SMALLEST_BANDWIDTH = 1e-6
"""Below this bandwidth the maxima are Rayleigh (the CLH distribution's limit), to avoid 0/0."""


@dataclass(frozen=True)
class SpectralMoments:
    """Moments ``m_0, m_1, m_2, m_4`` of a one-sided spectrum in angular frequency.

    Attributes
    ----------
    m0, m1, m2, m4 : float
        ``integral of omega^n S(omega) d omega`` [units^2 (rad/s)^n].
    """

    m0: float
    m1: float
    m2: float
    m4: float

    @property
    def std(self) -> float:
        """Standard deviation ``sqrt(m_0)``."""
        return math.sqrt(self.m0)

    @property
    def upcrossing_rate(self) -> float:
        """Mean up-crossings per second, ``sqrt(m_2/m_0) / (2 pi)`` [1/s]."""
        return math.sqrt(self.m2 / self.m0) / (2.0 * math.pi)

    @property
    def peak_rate(self) -> float:
        """Maxima per second, ``sqrt(m_4/m_2) / (2 pi)`` [1/s]."""
        return math.sqrt(self.m4 / self.m2) / (2.0 * math.pi)

    @property
    def irregularity(self) -> float:
        """``alpha_2 = m_2 / sqrt(m_0 m_4)`` (1: narrow band)."""
        return self.m2 / math.sqrt(self.m0 * self.m4)

    @property
    def bandwidth(self) -> float:
        """``epsilon = sqrt(1 - alpha_2^2)`` (Cartwright & Longuet-Higgins 1956)."""
        return math.sqrt(max(0.0, 1.0 - self.irregularity**2))

    def scaled(self, factor: float) -> SpectralMoments:
        """The moments of the response multiplied by ``factor`` (moments times ``factor^2``)."""
        f2 = factor * factor
        return SpectralMoments(self.m0 * f2, self.m1 * f2, self.m2 * f2, self.m4 * f2)


def spectral_moments(omega, spectrum, width=None) -> SpectralMoments:
    """The moments of a one-sided spectrum: a density sampled at ``omega`` (trapezoidal rule), or
    a line spectrum whose line ``j`` stands for a band of width ``width_j``.

    A line spectrum's moments are the sums ``m_n = sum_j omega_j^n S_j width_j``: those of the sum of
    components ``a_j cos(omega_j t + phi_j)`` with ``a_j^2 / 2 = S_j width_j`` the spectrum was made
    from (a JONSWAP sea's, :func:`kanat.physics.waves.jonswap_sea`, and the frequency domain's
    responses to it), whatever the spacing of the lines. The trapezoidal rule would weigh each line
    by half the gaps to its neighbours instead, which differs from ``width_j`` wherever the lines
    are unequally spaced (as the JONSWAP sea's, drawn in their bins, are).

    Parameters
    ----------
    omega : array_like, shape (n,)
        Angular frequencies [rad/s], increasing, >= 0.
    spectrum : array_like, shape (n,)
        One-sided spectral density ``S(omega)`` [units^2 s/rad], >= 0.
    width : float or array_like of shape (n,), optional
        The band each line stands for [rad/s], > 0; None: ``spectrum`` samples a continuous density.

    Returns
    -------
    SpectralMoments
    """
    w = np.asarray(omega, dtype=float)
    s = np.asarray(spectrum, dtype=float)
    if w.ndim != 1 or s.shape != w.shape or w.size < 2:
        raise KanatError(f"a spectrum needs matching 1-D frequencies and densities (at least 2); got "
                         f"shapes {w.shape} and {s.shape}")
    if not (np.all(np.isfinite(w)) and np.all(np.isfinite(s))):
        raise KanatError("the spectrum holds NaN or infinite values")
    if np.any(np.diff(w) <= 0) or w[0] < 0:
        raise KanatError("the spectrum's frequencies must be non-negative and increasing")
    if np.any(s < 0):
        raise KanatError("a spectral density cannot be negative")
    if width is None:
        m0, m1, m2, m4 = (float(trapezoid(w**n * s, w)) for n in (0, 1, 2, 4))
    else:
        band = np.broadcast_to(np.asarray(width, dtype=float), w.shape)
        if not np.all(band > 0):
            raise KanatError("a line spectrum's widths must be positive")
        m0, m1, m2, m4 = (float(np.sum(w**n * s * band)) for n in (0, 1, 2, 4))
    if not (m0 > 0 and m2 > 0 and m4 > 0):
        raise KanatError("the spectrum holds no energy away from zero frequency; its moments m0, m2, m4 "
                         "must be positive")
    return SpectralMoments(m0, m1, m2, m4)


def from_hertz(frequency, psd) -> tuple[np.ndarray, np.ndarray]:
    """A one-sided spectrum in hertz (``psd`` [units^2/Hz] at ``frequency`` [Hz], as
    :func:`kanat.analysis.tension_spectrum` gives it) in angular frequency:
    ``omega = 2 pi f``, ``S(omega) = S(f) / (2 pi)``, the same variance.

    Returns
    -------
    omega : ndarray
        [rad/s].
    spectrum : ndarray
        [units^2 s/rad].
    """
    f = np.asarray(frequency, dtype=float)
    return 2.0 * math.pi * f, np.asarray(psd, dtype=float) / (2.0 * math.pi)


def narrow_band_damage_rate(moments: SpectralMoments, exponent: float, intercept: float) -> float:
    """Narrow-band damage per second on ``N = K S^-m`` (module docstring, DNV-RP-C203 D.2.6).

    Parameters
    ----------
    moments : SpectralMoments
        Of the response whose ranges ``S`` the curve takes.
    exponent, intercept : float
        ``m`` and ``K`` of the curve.

    Returns
    -------
    float
        [1/s].
    """
    m = exponent
    return (moments.upcrossing_rate / intercept * (2.0 * math.sqrt(2.0 * moments.m0)) ** m
            * special.gamma(1.0 + m / 2.0))


@dataclass(frozen=True)
class DirlikCoefficients:
    """``D_1, D_2, D_3, Q, R`` of Dirlik's range distribution (module docstring)."""

    d1: float
    d2: float
    d3: float
    q: float
    r: float


def dirlik_coefficients(moments: SpectralMoments) -> DirlikCoefficients:
    """Dirlik's (1985) coefficients from the moments (module docstring)."""
    a2 = moments.irregularity
    xm = moments.m1 / moments.m0 * math.sqrt(moments.m2 / moments.m4)
    d1 = 2.0 * (xm - a2 * a2) / (1.0 + a2 * a2)
    r = (a2 - xm - d1 * d1) / (1.0 - a2 - d1 + d1 * d1)
    d2 = (1.0 - a2 - d1 + d1 * d1) / (1.0 - r)
    d3 = 1.0 - d1 - d2
    q = 1.25 * (a2 - d3 - d2 * r) / d1
    return DirlikCoefficients(d1, d2, d3, q, r)


def dirlik_range_density(ranges, moments: SpectralMoments) -> np.ndarray:
    """Dirlik's probability density of the rainflow ranges ``p(S)`` [1/units].

    Parameters
    ----------
    ranges : array_like
        Ranges ``S`` (peak to valley) [units].
    moments : SpectralMoments
    """
    c = dirlik_coefficients(moments)
    scale = 2.0 * moments.std
    z = np.asarray(ranges, dtype=float) / scale
    density = (c.d1 / c.q * np.exp(-z / c.q) + c.d2 * z / c.r**2 * np.exp(-z * z / (2.0 * c.r**2))
               + c.d3 * z * np.exp(-z * z / 2.0))
    return density / scale


def dirlik_damage_rate(moments: SpectralMoments, exponent: float, intercept: float) -> float:
    """Dirlik's damage per second on ``N = K S^-m``, in closed form (module docstring).

    Parameters
    ----------
    moments : SpectralMoments
    exponent, intercept : float
        ``m`` and ``K`` of the curve.

    Returns
    -------
    float
        [1/s].
    """
    c = dirlik_coefficients(moments)
    m = exponent
    expected = (c.d1 * c.q**m * special.gamma(1.0 + m)
                + 2.0 ** (m / 2.0) * special.gamma(1.0 + m / 2.0) * (c.d2 * abs(c.r) ** m + c.d3))
    return moments.peak_rate / intercept * (2.0 * moments.std) ** m * expected


_RATES = {"dirlik": dirlik_damage_rate, "narrow-band": narrow_band_damage_rate}


def damage_rate(moments: SpectralMoments, exponent: float, intercept: float, method: str = "dirlik") -> float:
    """Damage per second on ``N = K S^-m`` by ``method`` (``dirlik`` or ``narrow-band``)."""
    if method not in _RATES:
        raise KanatError(f"unknown spectral damage method '{method}'; known: {', '.join(DAMAGE_METHODS)}")
    return _RATES[method](moments, exponent, intercept)


def _curve(name, curves: dict):
    if isinstance(name, (TNCurve, SNCurve)):
        return name
    if name not in curves:
        raise KanatError(f"'{name}' is not a fatigue curve here; known: {', '.join(curves)}")
    return curves[name]


def tension_damage_rate(moments: SpectralMoments, mbl: float, curve: str | TNCurve = "api-chain-studless",
                        mean_tension: float = 0.0, method: str = "dirlik") -> float:
    """Damage per second of a tension process on an API RP 2SK T-N curve.

    The tension ranges over the reference strength ``R = S / mbl`` are a Gaussian process
    with the moments over ``mbl^2``; ``K`` is the curve's at ``L_m = mean_tension / mbl``
    (as :func:`kanat.analysis.fatigue.damage` takes it from a record).

    Parameters
    ----------
    moments : SpectralMoments
        Of the tension [N^2 ...].
    mbl : float
        Reference breaking strength [N].
    curve : str or TNCurve
        A name of :data:`kanat.analysis.fatigue.TN_CURVES`.
    mean_tension : float
        [N] (the wire curves' mean-load term).
    method : {"dirlik", "narrow-band"}

    Returns
    -------
    float
        [1/s].
    """
    if not mbl > 0:
        raise KanatError(f"the reference breaking strength must be positive (got {mbl!r} N)")
    t_n = _curve(curve, TN_CURVES)
    k = 10.0 ** (t_n.log10_k - t_n.log10_k_per_mean * mean_tension / mbl)
    return damage_rate(moments.scaled(1.0 / mbl), t_n.exponent, k, method)


def stress_damage_rate(moments: SpectralMoments, curve: str | SNCurve = "dnv-chain-studless",
                       method: str = "dirlik") -> float:
    """Damage per second of a nominal stress process [Pa] on a DNV-OS-E301 S-N curve (MPa)."""
    s_n = _curve(curve, SN_CURVES)
    return damage_rate(moments.scaled(1.0 / PASCAL_PER_MPA), s_n.exponent, s_n.intercept, method)


def maxima_cdf(eta, bandwidth: float) -> np.ndarray:
    """Cartwright & Longuet-Higgins' (1956) distribution of the maxima ``eta = x / sigma``."""
    eta = np.asarray(eta, dtype=float)
    if bandwidth < SMALLEST_BANDWIDTH:
        return np.where(eta > 0, -np.expm1(-0.5 * np.maximum(eta, 0.0) ** 2), 0.0)
    root = math.sqrt(1.0 - bandwidth**2)
    return (stats.norm.cdf(eta / bandwidth)
            - root * np.exp(-0.5 * eta * eta) * stats.norm.cdf(root * eta / bandwidth))


def maxima_density(eta, bandwidth: float) -> np.ndarray:
    """The density of :func:`maxima_cdf` (their eq. 3.7)."""
    eta = np.asarray(eta, dtype=float)
    if bandwidth < SMALLEST_BANDWIDTH:
        return np.where(eta > 0, eta * np.exp(-0.5 * eta * eta), 0.0)
    root = math.sqrt(1.0 - bandwidth**2)
    return (bandwidth / math.sqrt(2.0 * math.pi) * np.exp(-0.5 * (eta / bandwidth) ** 2)
            + root * eta * np.exp(-0.5 * eta * eta) * stats.norm.cdf(root * eta / bandwidth))


def largest_maximum_mode(bandwidth: float, n_maxima: float) -> float:
    """The mode of the largest of ``n_maxima`` independent CLH maxima, over ``sigma``.

    Maximises ``ln p(eta) + (N - 1) ln F(eta)`` (``F^N`` the distribution of the largest).
    """
    if n_maxima < 1:
        raise KanatError(f"fewer than one maximum ({n_maxima:g}) in the duration: lengthen it")
    top = 2.0 * math.sqrt(2.0 * math.log(max(n_maxima, 2.0))) + 4.0

    def minus_log_density(eta: float) -> float:
        p = float(maxima_density(eta, bandwidth))
        f = float(maxima_cdf(eta, bandwidth))
        if p <= 0.0 or f <= 0.0:
            return math.inf
        return -(math.log(p) + (n_maxima - 1.0) * math.log(f))

    found = optimize.minimize_scalar(minus_log_density, bounds=(1e-6, top), method="bounded",
                                     options={"xatol": 1e-9})
    return float(found.x)


def most_probable_maximum(moments: SpectralMoments, duration: float, mean: float = 0.0,
                          method: str = "cartwright-longuet-higgins") -> float:
    """Most probable maximum of the response over ``duration`` from its moments.

    Parameters
    ----------
    moments : SpectralMoments
    duration : float
        Exposure [s] (e.g. 10800 for a 3-hour storm).
    mean : float
        The response's mean, added [units].
    method : {"cartwright-longuet-higgins", "rayleigh"}
        Module docstring.

    Returns
    -------
    float
        [units].
    """
    if not duration > 0:
        raise KanatError(f"the storm duration must be positive (got {duration!r} s)")
    if method == "rayleigh":
        n = moments.upcrossing_rate * duration
        return mean + moments.std * math.sqrt(2.0 * math.log(max(n, 1.0)))
    if method == "cartwright-longuet-higgins":
        return mean + moments.std * largest_maximum_mode(moments.bandwidth, moments.peak_rate * duration)
    raise KanatError(f"unknown spectral MPM method '{method}'; known: {', '.join(MPM_METHODS)}")
