"""The tow vessel's pitch as a smooth periodic motion of time (theory/vessel.md §2, coupled to the tow).

:func:`pitch_motion` turns a ``vessel.pitch`` block into ``t -> (angle, rate, acceleration)``,
the callable :class:`kanat.vessel.track.VesselTrack` takes: the steady periodic pitch of
the block's stabilizer mode, as solved by :func:`kanat.vessel.solve_pitch`, written as a
Fourier series

``phi(t) = mean + sum_{n=1..N} (a_n cos(n omega tau) + b_n sin(n omega tau))``,
``tau = t + phase_deg / 360 * T``,

whose rate and acceleration are the series' exact derivatives. The series is

* for the open-loop modes (``off``, ``sinusoidal``, ``rectangular``, ``optimal``): the
  solver's own Fourier steady state, ``N = harmonics`` (paper eqs. 10, 12; the exact
  harmonics, no resampling);
* for ``feedback`` (solved by periodic shooting only): the trigonometric interpolant of the
  ``time_points`` samples of the solved period, truncated at ``N`` (its coefficients fall
  like ``n^-4``: the moment is continuous).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .solve import PitchResponse, solve_pitch
from .fourier import fourier_pitch
from .laws import FourierSeries


@dataclass(frozen=True)
class PitchMotion:
    """Steady periodic pitch ``t -> (phi, phi', phi'')`` [rad, rad/s, rad/s^2], bow up positive.

    Attributes
    ----------
    series : FourierSeries
        ``phi`` over the solver's period time ``tau`` [rad].
    time_offset : float
        ``tau - t`` [s]: the run's ``t = 0`` sits at this time of the solved period.
    response : PitchResponse
        The solver's steady period this series represents.
    method : {"fourier", "samples"}
        Exact harmonics of the Fourier steady state, or the interpolant of the shooting samples.
    """

    series: FourierSeries
    time_offset: float
    response: PitchResponse
    method: str

    @property
    def mode(self) -> str:
        """The stabilizer mode."""
        return self.response.mode

    @property
    def period(self) -> float:
        """Wave period ``T`` [s]."""
        return 2.0 * math.pi / self.series.frequency

    @property
    def amplitude(self) -> float:
        """Half the peak-to-peak of the solver's period [rad] (``PitchResponse.amplitude``)."""
        return self.response.amplitude

    def evaluate(self, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Angle, rate and acceleration at times ``t`` (any shape) [s]; arrays of ``t``'s shape."""
        s = self.series
        t = np.asarray(t, dtype=float)
        n_omega = np.arange(1, s.harmonics + 1) * s.frequency
        phase = np.multiply.outer(t + self.time_offset, n_omega)
        cos, sin = np.cos(phase), np.sin(phase)
        angle = s.mean + cos @ s.cos + sin @ s.sin
        rate = cos @ (n_omega * s.sin) - sin @ (n_omega * s.cos)
        accel = -(cos @ (n_omega**2 * s.cos) + sin @ (n_omega**2 * s.sin))
        return angle, rate, accel

    def __call__(self, t: float) -> tuple[float, float, float]:
        """``(angle, rate, acceleration)`` at time ``t`` [s] (the :class:`VesselTrack` hook)."""
        angle, rate, accel = self.evaluate(t)
        return float(angle), float(rate), float(accel)


def series_from_samples(values, frequency: float, harmonics: int) -> FourierSeries:
    """Fourier series through equally spaced samples of one period.

    Parameters
    ----------
    values : array_like, shape (M + 1,)
        Samples at ``t_j = j T / M``, ``j = 0..M``, both ends included (the last repeats the first).
    frequency : float
        ``omega = 2 pi / T`` [rad/s].
    harmonics : int
        Largest harmonic kept; capped at ``(M - 1) // 2``, below the Nyquist harmonic.

    Returns
    -------
    FourierSeries
        With all harmonics below Nyquist it interpolates the samples (exactly, for odd ``M``).
    """
    samples = np.asarray(values, dtype=float)[:-1]
    m = len(samples)
    keep = min(harmonics, (m - 1) // 2)
    c = np.fft.rfft(samples) / m
    return FourierSeries(float(c[0].real), 2.0 * c[1:keep + 1].real, -2.0 * c[1:keep + 1].imag, frequency)


def pitch_motion(block) -> PitchMotion:
    """The steady pitch of a ``vessel.pitch`` block's stabilizer mode, as a function of time.

    Parameters
    ----------
    block : kanat.model.vessel.VesselPitch
        (or any :class:`kanat.model.PitchModel`; ``phase_deg`` defaults to 0).

    Returns
    -------
    PitchMotion
        Callable ``t -> (angle, rate, acceleration)`` [rad, rad/s, rad/s^2].

    Raises
    ------
    kanat.vessel.ResonanceError
        Undamped, with a wave harmonic on the natural frequency.
    """
    mode = block.stabilizer.mode
    result = solve_pitch(block, modes=(mode,), cross_check=False)
    response, system = result.responses[mode], result.system
    if response.method == "fourier":
        series, _ = fourier_pitch(system, result.laws[mode], result.max_moment, result.harmonics)
        method = "fourier"
    else:
        series = series_from_samples(response.pitch, system.wave_frequency, result.harmonics)
        method = "samples"
    offset = getattr(block, "phase_deg", 0.0) / 360.0 * system.period
    return PitchMotion(series, offset, response, method)
