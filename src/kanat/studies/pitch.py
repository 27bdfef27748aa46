"""Parameter studies of the stabilized pitch: ``omega_0`` scan and the band where the
paper's claim holds, the ``(t, M0)`` surfaces of paper figs. 3 and 4, and the Fourier
truncation error against ``N``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.vessel.pitch.fourier import steady_state, wave_series
from kanat.vessel.pitch.laws import OPEN_LOOP
from kanat.vessel.pitch.system import PitchSystem, ResonanceError
from kanat.vessel.pitch.periodic import periodic_orbit

CLAIM_FACTOR = 2.0    # "the amplitude falls more than 2 times" (paper, after fig. 2)
SCAN_SAMPLES = 721    # time samples per period of a scan (every 0.5 deg of phase)


@dataclass(frozen=True)
class FrequencyScan:
    """Steady amplitudes against ``omega_0``, open-loop modes by the Fourier path.

    Attributes
    ----------
    natural_frequency : ndarray, shape (m,)
        ``omega_0`` [rad/s]; NaN rows where the undamped guard refuses (resonance).
    amplitude, max_abs : dict of str to ndarray, shape (m,)
        Half peak-to-peak and largest ``|phi|`` per mode [rad].
    """

    natural_frequency: np.ndarray
    amplitude: dict[str, np.ndarray]
    max_abs: dict[str, np.ndarray]

    def ratio(self, mode: str, metric: str = "amplitude") -> np.ndarray:
        """``metric(off) / metric(mode)`` against ``omega_0``."""
        values = getattr(self, metric)
        return values["off"] / values[mode]


def natural_frequency_scan(system: PitchSystem, max_moment: float, omega0, harmonics: int = 50,
                           modes=("off", "sinusoidal", "rectangular")) -> FrequencyScan:
    """Amplitude and largest ``|phi|`` of open-loop ``modes`` for each ``omega_0`` [rad/s]."""
    omega0 = np.asarray(omega0, dtype=float)
    phase = np.multiply.outer(np.linspace(0.0, system.period, SCAN_SAMPLES),
                              np.arange(1, harmonics + 1) * system.wave_frequency)
    cos, sin = np.cos(phase), np.sin(phase)          # the series' basis, computed once
    forcing = {m: wave_series(system, harmonics) + OPEN_LOOP[m]().fourier(
        max_moment, system.wave_frequency, harmonics) for m in modes}
    amplitude = {m: np.full(omega0.shape, np.nan) for m in modes}
    max_abs = {m: np.full(omega0.shape, np.nan) for m in modes}
    for i, w0 in enumerate(omega0):
        s = system.with_natural_frequency(w0)
        for m in modes:
            try:
                series = steady_state(s, forcing[m])
            except ResonanceError:
                break
            phi = series.mean + cos @ series.cos + sin @ series.sin
            amplitude[m][i], max_abs[m][i] = 0.5 * np.ptp(phi), np.max(np.abs(phi))
    return FrequencyScan(omega0, amplitude, max_abs)


def claim_holds(scan: FrequencyScan, factor: float = CLAIM_FACTOR) -> np.ndarray:
    """Where the sinusoidal mode cuts the amplitude ``>= factor`` times and the rectangular
    mode cuts it more (paper, after fig. 2), shape (m,) of bool."""
    sin, rect = scan.ratio("sinusoidal"), scan.ratio("rectangular")
    sin, rect = np.nan_to_num(sin), np.nan_to_num(rect)
    return (sin >= factor) & (rect > sin)


def claim_band(scan: FrequencyScan, around: float, wave_frequency: float,
               factor: float = CLAIM_FACTOR):
    """The contiguous ``omega_0`` interval around ``around`` where :func:`claim_holds`,
    not crossing a resonance ``omega_0 = n omega`` (where every amplitude is unbounded).

    Returns
    -------
    (float, float) or None
        First and last scanned ``omega_0`` of the run [rad/s]; None if the claim fails
        at ``around``.
    """
    w = scan.natural_frequency
    holds = claim_holds(scan, factor)
    i = int(np.argmin(np.abs(w - around)))
    if not holds[i]:
        return None
    side = np.floor(w / wave_frequency)    # between the same two harmonics n omega
    lo, hi = i, i
    while lo > 0 and holds[lo - 1] and side[lo - 1] == side[i]:
        lo -= 1
    while hi < len(holds) - 1 and holds[hi + 1] and side[hi + 1] == side[i]:
        hi += 1
    return float(w[lo]), float(w[hi])


def moment_surface(system: PitchSystem, mode: str, max_moments, times, harmonics: int = 50) -> np.ndarray:
    """``phi(M0, t)`` of an open-loop mode (paper figs. 3, 4), shape (len(max_moments), len(times)).

    The pitch is affine in ``M0``: ``phi = phi_wave + M0 phi_1`` with ``phi_1`` the response
    to the law at ``M0 = 1`` (eqs. 10, 12).
    """
    times = np.asarray(times, dtype=float)
    wave = steady_state(system, wave_series(system, harmonics))(times)
    unit = steady_state(system, OPEN_LOOP[mode]().fourier(1.0, system.wave_frequency, harmonics))(times)
    return wave[None, :] + np.multiply.outer(np.asarray(max_moments, dtype=float), unit)


def truncation_errors(system: PitchSystem, law, max_moment: float, harmonics, times) -> np.ndarray:
    """``max_t |phi_N - phi_shooting| / amplitude`` for each ``N`` in ``harmonics``, shape (k,)."""
    from kanat.vessel.pitch.fourier import fourier_pitch

    times = np.asarray(times, dtype=float)
    reference = periodic_orbit(system, law.pieces(max_moment, system.wave_frequency), times).pitch
    amplitude = 0.5 * np.ptp(reference)
    return np.array([np.max(np.abs(fourier_pitch(system, law, max_moment, n)[0](times) - reference))
                     / amplitude for n in harmonics])


@dataclass(frozen=True)
class FigureData:
    """What the figures of a pitch case show beyond the solved modes.

    Attributes
    ----------
    max_moments : ndarray, shape (k,)
        ``M0`` axis of the surfaces [N m].
    times : ndarray, shape (n,)
        Time axis of the surfaces [s].
    surfaces : dict of str to ndarray, shape (k, n)
        ``phi(M0, t)`` for ``sinusoidal`` and ``rectangular`` [rad].
    scan : FrequencyScan
    band : (float, float) or None
        :func:`claim_band` around the case's ``omega_0``.
    """

    max_moments: np.ndarray
    times: np.ndarray
    surfaces: dict[str, np.ndarray]
    scan: FrequencyScan
    band: tuple[float, float] | None


def figure_data(result, surface_points: int = 61, scan_points: int = 701) -> FigureData:
    """Surfaces over ``M0`` in ``[0, 2 M0]`` and the ``omega_0`` scan over ``[0.5, 5] omega``."""
    system = result.system
    top = 2.0 * result.max_moment if result.max_moment > 0 else 2.0 * system.wave_moment_amplitude
    max_moments = np.linspace(0.0, top, surface_points)
    times = np.linspace(0.0, system.period, 241)
    surfaces = {m: moment_surface(system, m, max_moments, times, result.harmonics)
                for m in ("sinusoidal", "rectangular")}
    omega0 = np.linspace(0.5, 5.0, scan_points) * system.wave_frequency
    scan = natural_frequency_scan(system, result.max_moment, omega0, result.harmonics)
    return FigureData(max_moments, times, surfaces, scan,
                      claim_band(scan, system.natural_frequency, system.wave_frequency))
