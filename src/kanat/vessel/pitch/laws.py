"""Stabilizer control laws of Gaisha (theory/vessel.md §2) and their Fourier series.

Every law keeps the stabilizer moment within ``0 <= f <= M0``: the reactive stabilizer
pushes one way only (bow up, a positive moment). Open-loop laws are functions of time
over one wave period ``T`` and have a Fourier series; the feedback law depends on the
pitch rate and has none.

=============  ============================================================  ===========
mode           moment over one period (t in [0, T))                          Fourier
=============  ============================================================  ===========
off            0                                                             trivial
sinusoidal     ``f_1 = M0 sin(omega t)`` for t < T/2, else 0 (eq. 5)           eq. 7
rectangular    ``f_2 = M0`` for t < T/2, else 0 (eq. 5)                        eq. 11
optimal        piecewise linear in [0, M0] over the first half (:class:`Shaped`)  exact
feedback       ``clip(-g phi', 0, M0)`` (:class:`Feedback`)                    none
=============  ============================================================  ===========
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

MomentFn = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]
"""``f(t, phi, phi')`` [N m] on one smooth piece of the period (arrays broadcast)."""


@dataclass(frozen=True)
class FourierSeries:
    """``g(t) = mean + sum_{n=1..N} (cos[n-1] cos(n omega t) + sin[n-1] sin(n omega t))``.

    Attributes
    ----------
    mean : float
        Constant term (the paper's ``a_0 / 2``).
    cos, sin : ndarray, shape (N,)
        Coefficients of harmonics ``n = 1..N``.
    frequency : float
        Fundamental ``omega`` [rad/s].
    """

    mean: float
    cos: np.ndarray
    sin: np.ndarray
    frequency: float

    @property
    def harmonics(self) -> int:
        """Number of harmonics ``N``."""
        return len(self.cos)

    def __call__(self, t) -> np.ndarray:
        """Evaluate at times ``t`` (any shape) [s]."""
        t = np.asarray(t, dtype=float)
        phase = np.multiply.outer(t, np.arange(1, self.harmonics + 1) * self.frequency)
        return self.mean + np.cos(phase) @ self.cos + np.sin(phase) @ self.sin

    def __add__(self, other: FourierSeries) -> FourierSeries:
        n = max(self.harmonics, other.harmonics)
        def pad(c):
            return np.pad(c, (0, n - len(c)))
        return FourierSeries(self.mean + other.mean, pad(self.cos) + pad(other.cos),
                             pad(self.sin) + pad(other.sin), self.frequency)

    def scaled(self, factor: float) -> FourierSeries:
        """``factor * g``."""
        return FourierSeries(factor * self.mean, factor * self.cos, factor * self.sin, self.frequency)


@dataclass(frozen=True)
class Piece:
    """One smooth stretch ``[start, end]`` of the period [s] and the moment on it."""

    start: float
    end: float
    moment: MomentFn


def _zero(t, phi=None, rate=None):
    return np.zeros_like(np.asarray(t, dtype=float))


class OpenLoopLaw:
    """A stabilizer moment that is a function of time over one period ``T = 2 pi / omega``.

    Subclasses implement :meth:`pieces` (the smooth stretches, used by the time
    integration, which restarts at every break) and :meth:`fourier` (the series, used by
    the Fourier steady state). :meth:`moment` evaluates the pieces.
    """

    name: ClassVar[str]
    closed_loop: ClassVar[bool] = False

    def pieces(self, max_moment: float, omega: float) -> list[Piece]:
        raise NotImplementedError

    def fourier(self, max_moment: float, omega: float, harmonics: int) -> FourierSeries:
        raise NotImplementedError

    def moment(self, t, max_moment: float, omega: float) -> np.ndarray:
        """Moment [N m] at times ``t`` [s] (taken modulo the period)."""
        period = 2.0 * math.pi / omega
        t = np.asarray(t, dtype=float)
        tau = np.mod(t, period)
        out = np.zeros_like(tau)
        for piece in self.pieces(max_moment, omega):
            inside = (tau >= piece.start) & (tau < piece.end)
            out[inside] = piece.moment(tau[inside], None, None)
        return out


@dataclass(frozen=True)
class Off(OpenLoopLaw):
    """No stabilizer: ``f = 0``."""

    name: ClassVar[str] = "off"

    def pieces(self, max_moment, omega):
        return [Piece(0.0, 2.0 * math.pi / omega, _zero)]

    def fourier(self, max_moment, omega, harmonics):
        return FourierSeries(0.0, np.zeros(harmonics), np.zeros(harmonics), omega)


@dataclass(frozen=True)
class Sinusoidal(OpenLoopLaw):
    """``f_1`` of paper eq. 5: ``M0 sin(omega t)`` in the first half period, 0 in the second."""

    name: ClassVar[str] = "sinusoidal"

    def pieces(self, max_moment, omega):
        half = math.pi / omega
        return [Piece(0.0, half, lambda t, phi, rate: max_moment * np.sin(omega * t)),
                Piece(half, 2.0 * half, _zero)]

    def fourier(self, max_moment, omega, harmonics):
        """Paper eq. 7 (theory/vessel.md §2): ``M0 (1/pi + sum_n (1 - (-1)^(1-n)) / (pi (1 - n^2))
        cos(n omega t) + sin(omega t) / 2)``; the ``n = 1`` cosine coefficient is 0."""
        n = np.arange(1, harmonics + 1)
        cos = np.zeros(harmonics)
        even = n % 2 == 0                       # 1 - (-1)^(1-n) = 2 for even n, 0 for odd
        cos[even] = 2.0 / (math.pi * (1.0 - n[even] ** 2))
        sin = np.zeros(harmonics)
        sin[0] = 0.5
        return FourierSeries(1.0 / math.pi, cos, sin, omega).scaled(max_moment)


@dataclass(frozen=True)
class Rectangular(OpenLoopLaw):
    """``f_2`` of paper eq. 5: ``M0`` in the first half period, 0 in the second."""

    name: ClassVar[str] = "rectangular"

    def pieces(self, max_moment, omega):
        half = math.pi / omega
        return [Piece(0.0, half, lambda t, phi, rate: np.full_like(np.asarray(t, float), max_moment)),
                Piece(half, 2.0 * half, _zero)]

    def fourier(self, max_moment, omega, harmonics):
        """Paper eq. 11: ``M0 (1/2 + sum_n (1 - (-1)^n) / (pi n) sin(n omega t))``."""
        n = np.arange(1, harmonics + 1)
        sin = (1.0 - (-1.0) ** n) / (math.pi * n)
        return FourierSeries(0.5, np.zeros(harmonics), sin, omega).scaled(max_moment)


@dataclass(frozen=True)
class Shaped(OpenLoopLaw):
    """A piecewise-linear moment ``M0 s(t)`` over ``[0, active T)``, 0 after it.

    Attributes
    ----------
    values : tuple of float
        ``s`` at ``K + 1`` equally spaced nodes of ``[0, active T]``, each in [0, 1], so
        that ``0 <= f <= M0`` holds everywhere (a linear interpolant stays between its
        node values). All ones is the rectangular law exactly.
    active : float
        Fraction of the period the stabilizer may act in (0.5: the paper's half period).
    name : str
        The mode it stands for (``"optimal"`` when found by :mod:`.pitch_optimal`).
    """

    values: tuple[float, ...]
    active: float = 0.5
    name: str = "optimal"

    def __post_init__(self):
        values = np.asarray(self.values, dtype=float)
        if len(values) < 2 or np.any(values < -1e-12) or np.any(values > 1 + 1e-12):
            raise ValueError("Shaped needs at least 2 node values, each within [0, 1]")
        if not 0.0 < self.active <= 1.0:
            raise ValueError(f"active fraction {self.active} is not in (0, 1]")

    def nodes(self, omega: float) -> np.ndarray:
        """Node times [s], shape (K + 1,)."""
        return np.linspace(0.0, self.active * 2.0 * math.pi / omega, len(self.values))

    def pieces(self, max_moment, omega):
        t, s = self.nodes(omega), np.clip(self.values, 0.0, 1.0) * max_moment
        out = [Piece(t[k], t[k + 1], _linear(t[k], t[k + 1], s[k], s[k + 1]))
               for k in range(len(t) - 1)]
        if self.active < 1.0:
            out.append(Piece(t[-1], 2.0 * math.pi / omega, _zero))
        return out

    def fourier(self, max_moment, omega, harmonics):
        """Exact coefficients of the piecewise-linear moment.

        On a piece ``f = y0 + q (t - t0)``, ``int f e^{-i lam t} dt = [e^{-i lam t}
        (i f(t) / lam + q / lam^2)]`` with ``lam = n omega``; ``c_n = (1/T) sum of these``,
        ``cos_n = 2 Re c_n``, ``sin_n = -2 Im c_n``.
        """
        period = 2.0 * math.pi / omega
        lam = np.arange(1, harmonics + 1) * omega
        c = np.zeros(harmonics, dtype=complex)
        mean = 0.0
        for p in self.pieces(max_moment, omega):
            y0, y1 = (float(p.moment(np.array(x), None, None)) for x in (p.start, p.end))
            mean += 0.5 * (y0 + y1) * (p.end - p.start)
            c += _linear_integral(lam, p.start, p.end, y0, y1)
        c /= period
        return FourierSeries(mean / period, 2.0 * c.real, -2.0 * c.imag, omega)


def _linear_integral(lam: np.ndarray, t0: float, t1: float, y0: float, y1: float) -> np.ndarray:
    """``int_t0^t1 f e^{-i lam t} dt`` of the linear ``f`` from ``y0`` to ``y1``, shape of ``lam``."""
    q = (y1 - y0) / (t1 - t0)

    def antiderivative(t, y):
        return np.exp(-1j * lam * t) * (1j * y / lam + q / lam**2)
    return antiderivative(t1, y1) - antiderivative(t0, y0)


def _linear(t0: float, t1: float, y0: float, y1: float) -> MomentFn:
    slope = (y1 - y0) / (t1 - t0)
    return lambda t, phi, rate: y0 + slope * (np.asarray(t, dtype=float) - t0)


@dataclass(frozen=True)
class Feedback:
    """Closed loop: a one-sided damper ``f = clip(-gain * phi', 0, M0)``.

    The stabilizer opposes the pitch rate when it can: it pushes the bow up (``f > 0``)
    while the bow falls (``phi' < 0``), in proportion to the rate, saturated at ``M0``,
    and rests while the bow rises (it cannot pull down). With ``gain = None`` the gain is
    ``2 I_y omega_0``, which adds a damping ratio of 1 while unsaturated.
    No Fourier form: the moment depends on the response, so this law is solved by
    periodic shooting on the time integration only.
    """

    gain: float | None = None
    name: ClassVar[str] = "feedback"
    closed_loop: ClassVar[bool] = True

    def gain_for(self, system) -> float:
        """The gain used with ``system`` [N m s/rad]."""
        return self.gain if self.gain is not None else 2.0 * system.inertia * system.natural_frequency

    def pieces(self, max_moment: float, omega: float, gain: float) -> list[Piece]:
        def law(t, phi, rate):
            return np.clip(-gain * np.asarray(rate, dtype=float), 0.0, max_moment)
        return [Piece(0.0, 2.0 * math.pi / omega, law)]


OPEN_LOOP: dict[str, type[OpenLoopLaw]] = {"off": Off, "sinusoidal": Sinusoidal, "rectangular": Rectangular}
"""Open-loop laws that need no data beyond ``M0``, by mode name."""
