"""The pitch oscillator of Gaisha (theory/vessel.md §2) as typed data, and its resonance guard.

``I_y phi'' + c phi' + k phi = M_m sin(omega t + pi) + f(t)`` with ``k = I_y omega_0^2``
and ``c = 2 zeta I_y omega_0`` (paper eq. 1/1a, with the optional linear damping of
theory/vessel.md §2). ``phi > 0`` is bow up; a positive moment raises the bow.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from kanat.errors import SolverError
from kanat.model.problems import RESONANCE_RTOL


class ResonanceError(SolverError):
    """An undamped pitch model with a wave harmonic on its natural frequency."""


@dataclass(frozen=True)
class PitchSystem:
    """Linear pitch oscillator driven by a regular wave moment (paper eq. 1, theory/vessel.md §2).

    Attributes
    ----------
    inertia : float
        ``I_y`` [kg m^2].
    natural_frequency : float
        ``omega_0 = sqrt(k / I_y)`` [rad/s].
    wave_moment_amplitude : float
        ``M_m`` [N m].
    wave_frequency : float
        ``omega = 2 pi / T`` [rad/s].
    damping_ratio : float
        ``zeta``; the damping is ``c = 2 zeta I_y omega_0`` [N m s/rad].
    """

    inertia: float
    natural_frequency: float
    wave_moment_amplitude: float
    wave_frequency: float
    damping_ratio: float = 0.0

    @classmethod
    def from_model(cls, model) -> PitchSystem:
        """From a validated :class:`kanat.model.PitchModel`."""
        return cls(inertia=model.inertia, natural_frequency=model.omega0,
                   wave_moment_amplitude=model.wave_moment_amplitude,
                   wave_frequency=model.wave_frequency, damping_ratio=model.damping_ratio)

    @property
    def period(self) -> float:
        """Wave (and stabilizer) period ``T = 2 pi / omega`` [s]."""
        return 2.0 * math.pi / self.wave_frequency

    @property
    def restoring(self) -> float:
        """``k = I_y omega_0^2`` [N m/rad]."""
        return self.inertia * self.natural_frequency**2

    @property
    def damping(self) -> float:
        """``c = 2 zeta I_y omega_0`` [N m s/rad]."""
        return 2.0 * self.damping_ratio * self.inertia * self.natural_frequency

    @property
    def angle_scale(self) -> float:
        """Static pitch under the wave moment, ``M_m / k`` [rad] (1 rad if ``M_m = 0``)."""
        return self.wave_moment_amplitude / self.restoring or 1.0

    def wave_moment(self, t):
        """``M_m sin(omega t + pi)`` [N m] at times ``t`` [s] (paper eq. 1)."""
        return self.wave_moment_amplitude * np.sin(self.wave_frequency * np.asarray(t) + math.pi)

    def with_natural_frequency(self, omega0: float) -> PitchSystem:
        """The same ship and sea with another ``omega_0`` [rad/s]."""
        return replace(self, natural_frequency=float(omega0))

    def nearest_harmonic(self) -> int:
        """The harmonic ``n >= 1`` of the wave frequency closest to ``omega_0``."""
        return max(1, round(self.natural_frequency / self.wave_frequency))

    def check_resonance(self) -> None:
        """Refuse an undamped model with ``|n omega - omega_0| <= RESONANCE_RTOL omega_0``.

        Every harmonic ``n >= 1`` counts, also those above the Fourier truncation and
        those the stabilizer law happens not to contain: an undamped oscillator with
        ``omega_0 = n omega`` has no unique periodic steady state (its free oscillation
        is itself T-periodic), and the shooting map ``x(0) -> x(T)`` is singular.

        Raises
        ------
        ResonanceError
            With the harmonic, the frequencies and what to change.
        """
        if self.damping_ratio > 0.0:
            return
        n, omega, omega0 = self.nearest_harmonic(), self.wave_frequency, self.natural_frequency
        detuning = abs(n * omega - omega0) / omega0
        if detuning > RESONANCE_RTOL:
            return
        away = [omega0 * (1 - 0.05), omega0 * (1 + 0.05)]
        raise ResonanceError(
            f"harmonic n = {n} of the wave frequency ({n} × {omega:.6g} = {n * omega:.6g} rad/s) is "
            f"within {100 * detuning:.3g} % of the natural frequency omega_0 = {omega0:.6g} rad/s and "
            f"there is no damping (the guard refuses |n omega - omega_0| <= {100 * RESONANCE_RTOL:g} % "
            "of omega_0): the undamped steady state is unbounded or meaningless there. Give "
            "damping_ratio > 0 (ship pitch: about 0.05 to 0.3), or move natural_frequency away "
            f"from {n * omega:.4g} rad/s (e.g. {away[0]:.4g} or {away[1]:.4g} rad/s).")
