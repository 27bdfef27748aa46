"""Quasi-static analysis (``design.analysis: quasi-static``): line tensions from the statics with
the vessel held at its design offset.

API RP 2SK (3rd ed. 2005, §6.3-6.4) and DNV-OS-E301 (Ch.2 Sec.2) define the quasi-static line
tension as the static tension with the vessel displaced to its maximum offset, the mean offset
(from the mean wind, current and wave-drift loads) plus the maximum low-frequency and
wave-frequency motions, whose dynamics in the lines is ignored. kanat takes, per sea state,

    S_design = S_mean + S_wf,max,    S_wf,max = sigma_wf sqrt(2 ln N),   N = T_storm / T_z

* ``S_mean`` is ``design.mean_offset`` [m], along the sea state's heading, for the condition's
  kind (``{intact: S, damaged: S}``, or one value for both): kanat models no mean environmental
  load on a vessel nor its slow drift, so the mean offset, and the low-frequency part one wants
  added to it, come from the engineer's own analysis of the vessel;
* ``sigma_wf`` and ``T_z = 2 pi sqrt(m_0 / m_2)`` come from the spectrum of the vessel origin's
  horizontal motion along the waves' heading ``beta``, ``S_x(omega) = |Z_surge(omega) cos beta
  + Z_sway(omega) sin beta|^2 S_J(omega)``, ``Z`` the displacement RAOs of
  ``vessel.motion: {rao: FILE}`` at the heading (interpolated as :mod:`kanat.physics.rao` does),
  ``S_J`` the sea state's JONSWAP spectrum: the Rayleigh most probable maximum of a narrow-band
  motion over ``design.storm_duration`` (:func:`kanat.analysis.spectral.most_probable_maximum`).

The vessel is translated rigidly to ``S_design`` along ``beta`` (no rotation) and the network
statics re-solved there (:func:`kanat.api.offsets`); each line's tension is the larger of its
two end tensions. The RAO table must cover the sea: a table that leaves more than
:data:`UNCOVERED_SHARE` of the sea's variance outside its frequencies is refused.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import trapezoid

from kanat import api
from kanat.analysis.spectral import most_probable_maximum, spectral_moments
from kanat.errors import KanatError
from kanat.model import Case
from kanat.physics.rao import rao_harmonics
from kanat.physics.waves import LinearSea, jonswap_spectrum, wavenumber

FREQUENCIES = 400
"""Frequencies of the motion spectrum over the RAO table's range."""

UNCOVERED_SHARE = 0.01
"""Largest share of the sea's variance the RAO table may leave outside its frequencies."""

OFFSET_STEPS = 8
"""Steps of the offset curve from the neutral position to the design offset (each re-solved
from the last, which keeps the statics on its branch)."""

SURGE, SWAY = 0, 1


@dataclass(frozen=True)
class DesignOffset:
    """The vessel's design offset in one sea state.

    Attributes
    ----------
    heading_deg : float
        Direction of the offset (the waves') [deg].
    mean : float
        ``S_mean`` [m].
    wave_frequency_std, zero_crossing_period, wave_frequency_max : float
        ``sigma_wf`` [m], ``T_z`` [s], ``S_wf,max`` [m].
    """

    heading_deg: float
    mean: float
    wave_frequency_std: float
    zero_crossing_period: float
    wave_frequency_max: float

    @property
    def total(self) -> float:
        """``S_mean + S_wf,max`` [m]."""
        return self.mean + self.wave_frequency_max


def horizontal_rao(rao_rows, omega: np.ndarray, heading_deg: float) -> np.ndarray:
    """``Z_surge cos beta + Z_sway sin beta`` at ``omega`` [m/m], complex, shape (n,).

    The RAOs are read through :func:`kanat.physics.rao.rao_harmonics` on a sea of unit
    components at ``omega`` with zero phase, whose harmonics are ``|Z| sin(omega t + pi/2 - arg Z)``.
    """
    beta = math.radians(heading_deg)
    unit = LinearSea(np.ones_like(omega), omega, wavenumber(omega), np.full(omega.size, beta), np.zeros(omega.size))
    dof, amplitude, omega_h, phase, _ = rao_harmonics(rao_rows, unit)
    total = np.zeros(omega.size, dtype=complex)
    for d, weight in ((SURGE, math.cos(beta)), (SWAY, math.sin(beta))):
        picked = dof == d
        z = amplitude[picked] * np.exp(1j * (0.5 * math.pi - phase[picked]))
        total[np.searchsorted(omega, omega_h[picked])] += weight * z
    return total


def mean_offset(case: Case, kind: str) -> float:
    """``S_mean`` [m] of a condition kind (``intact`` or ``damaged``) from ``design.mean_offset``."""
    written = case.design.mean_offset
    if written is None:
        raise KanatError("design.mean_offset: missing; a quasi-static analysis displaces the vessel to its mean "
                         "offset (m, along the waves) plus its wave-frequency motion: write one value, or "
                         "{intact: S, damaged: S}")
    if isinstance(written, dict):
        if kind not in written:
            raise KanatError(f"design.mean_offset.{kind}: missing; the {kind} condition needs the vessel's mean "
                             "offset (a broken line lets the vessel drift further)")
        return float(written[kind])
    return float(written)


def design_offset(case: Case, sea_state, kind: str = "intact") -> DesignOffset:
    """``S_mean + S_wf,max`` of ``case``'s vessel in ``sea_state`` for a condition kind (module docstring)."""
    motion = case.vessel.motion if case.vessel is not None else None
    rows = motion.rao_rows if motion is not None else None
    if rows is None:
        raise KanatError("design.analysis: quasi-static: the wave-frequency offset comes from the vessel's "
                         "RAOs; give vessel.motion: {rao: FILE}")
    omegas = np.unique([row[0] for row in rows])
    omega = np.linspace(omegas[0], omegas[-1], FREQUENCIES)
    sea = jonswap_spectrum(omega, sea_state.hs, sea_state.tp, sea_state.gamma)
    uncovered = 1.0 - float(trapezoid(sea, omega)) / (sea_state.hs**2 / 16.0)
    if uncovered > UNCOVERED_SHARE:
        raise KanatError(f"sea state '{sea_state.name}': the RAO table covers {omegas[0]:g} to {omegas[-1]:g} "
                         f"rad/s, which leaves {100 * uncovered:.1f} % of its variance outside; extend the "
                         "table's frequencies")
    motion_spectrum = np.abs(horizontal_rao(rows, omega, sea_state.heading_deg)) ** 2 * sea
    duration = case.design.storm_duration
    if not np.any(motion_spectrum > 0):
        return DesignOffset(sea_state.heading_deg, mean_offset(case, kind), 0.0, math.inf, 0.0)
    moments = spectral_moments(omega, motion_spectrum)
    largest = most_probable_maximum(moments, duration, method="rayleigh")
    return DesignOffset(sea_state.heading_deg, mean_offset(case, kind), moments.std,
                        1.0 / moments.upcrossing_rate, largest)


def line_tensions(variant: Case, offset: DesignOffset) -> dict[str, float]:
    """Each cable's larger end tension [N] with the vessel at ``offset.total`` along its heading."""
    curve = api.offsets(variant, direction=offset.heading_deg, to=offset.total, steps=OFFSET_STEPS,
                         each_body=False)                 # the tensions only: no per-body curves
    last = curve["end_tension"].isel(offset=-1)
    return {str(cable): float(last.sel(cable=cable).max()) for cable in curve["cable"].values}
