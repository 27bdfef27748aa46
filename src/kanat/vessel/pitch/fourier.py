"""Fourier steady state of the pitch oscillator (paper eqs. 8–12, theory/vessel.md §2).

By superposition each term of the forcing's series is answered on its own:

* a constant ``A``: ``phi = A / (I_y omega_0^2)`` (eq. 9a);
* ``A sin(n omega t)`` / ``A cos(n omega t)``, undamped: the same function times
  ``1 / (I_y (omega_0^2 - (n omega)^2))`` (eqs. 9b, 9c), computed literally so;
* damped: the complex transfer function ``H_n = 1 / (I_y (omega_0^2 - (n omega)^2
  + 2 i zeta omega_0 n omega))`` applied to ``A - i B`` for ``A cos + B sin``.

The wave moment ``M_m sin(omega t + pi) = -M_m sin(omega t)`` is the first term of eqs. 10
and 12; adding a stabilizer law's series (eqs. 7, 11) gives eqs. 10 and 12.
"""
from __future__ import annotations

import numpy as np

from .laws import FourierSeries, OpenLoopLaw
from .system import PitchSystem


def harmonic_response(system: PitchSystem, n, cos_amp, sin_amp) -> tuple[np.ndarray, np.ndarray]:
    """Steady response to ``cos_amp cos(n omega t) + sin_amp sin(n omega t)`` [N m].

    Parameters
    ----------
    system : PitchSystem
    n : int or ndarray of int, shape (N,)
        Harmonic numbers, ``n >= 1``.
    cos_amp, sin_amp : float or ndarray, shape (N,)
        Moment amplitudes [N m].

    Returns
    -------
    (ndarray, ndarray)
        Cosine and sine amplitudes of the pitch [rad]. Undamped: exactly
        ``A / (I_y (omega_0^2 - (n omega)^2))`` (eqs. 9b, 9c).

    The caller guards resonance (:meth:`PitchSystem.check_resonance`); an undamped
    harmonic exactly on ``omega_0`` would divide by zero here.
    """
    n = np.asarray(n, dtype=float)
    omega, omega0, inertia = system.wave_frequency, system.natural_frequency, system.inertia
    cos_amp, sin_amp = np.asarray(cos_amp, dtype=float), np.asarray(sin_amp, dtype=float)
    if system.damping_ratio == 0.0:
        denominator = inertia * (omega0**2 - (n * omega) ** 2)
        return cos_amp / denominator, sin_amp / denominator
    transfer = 1.0 / (inertia * (omega0**2 - (n * omega) ** 2
                                 + 2j * system.damping_ratio * omega0 * n * omega))
    z = transfer * (cos_amp - 1j * sin_amp)
    return z.real, -z.imag


def steady_state(system: PitchSystem, forcing: FourierSeries) -> FourierSeries:
    """Series of the periodic pitch [rad] under a moment series [N m] (eqs. 9a–9c).

    Raises
    ------
    ResonanceError
        Undamped with a harmonic within :data:`~kanat.model.problems.RESONANCE_RTOL` of ``omega_0``.
    """
    system.check_resonance()
    n = np.arange(1, forcing.harmonics + 1)
    cos, sin = harmonic_response(system, n, forcing.cos, forcing.sin)
    return FourierSeries(forcing.mean / system.restoring, cos, sin, forcing.frequency)


def wave_series(system: PitchSystem, harmonics: int) -> FourierSeries:
    """``M_m sin(omega t + pi) = -M_m sin(omega t)`` as a series of ``harmonics`` terms [N m]."""
    sin = np.zeros(harmonics)
    sin[0] = -system.wave_moment_amplitude
    return FourierSeries(0.0, np.zeros(harmonics), sin, system.wave_frequency)


def fourier_pitch(system: PitchSystem, law: OpenLoopLaw, max_moment: float,
                  harmonics: int) -> tuple[FourierSeries, FourierSeries]:
    """Steady pitch under the waves and an open-loop law, truncated at ``N`` harmonics.

    With :class:`~.pitch_laws.Sinusoidal` this is paper eq. 10, with
    :class:`~.pitch_laws.Rectangular` eq. 12 (both as corrected in theory/vessel.md §2), with
    :class:`~.pitch_laws.Off` the wave term alone (eq. 3).

    Parameters
    ----------
    system : PitchSystem
    law : OpenLoopLaw
    max_moment : float
        ``M0`` [N m].
    harmonics : int
        ``N``.

    Returns
    -------
    (FourierSeries, FourierSeries)
        The pitch [rad] and the stabilizer moment [N m].
    """
    moment = law.fourier(max_moment, system.wave_frequency, harmonics)
    pitch = steady_state(system, wave_series(system, harmonics) + moment)
    return pitch, moment
