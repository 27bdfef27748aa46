"""The vessel's first-order motion in a sea from its displacement RAOs (``vessel.motion: {rao: FILE}``).

Each wave component ``eta_i = a_i cos(omega_i t - phi_i)`` at the vessel origin (the sea of
:mod:`kanat.physics.waves`, eq. 2 at x = y = 0) moves degree of freedom ``d`` by

    q_d(t) = sum_i |Z_d(omega_i, beta_i)| a_i cos(omega_i t - phi_i - arg Z_d(omega_i, beta_i)),

``Z_d = amplitude e^{i phase}`` the RAO (:mod:`kanat.io.raos`), interpolated linearly in
frequency and in heading (``beta_i`` relative to the vessel, whose heading is 0 at t = 0) as a
complex number, so that phases never wrap. That is a sum of harmonics
(``A sin(omega t + pi/2 - phi - arg Z)``, :class:`kanat.physics.motion.Harmonics`), so every
vessel point follows with its lever arm as for written harmonics. The motion is the one at zero
forward speed (no encounter frequency) and about the heading at t = 0.

Components outside the table's frequencies move nothing; the share of the sea's variance they
hold is returned, for the caller's warning.
"""
from __future__ import annotations

import math

import numpy as np

from kanat.errors import KanatError

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
"""Order of the degrees of freedom (that of :data:`kanat.physics.motion.DOFS`)."""


def _grid(rows, dof):
    """Frequencies (k,), headings [deg] (h,) and complex RAOs (k, h) of one degree of freedom."""
    picked = [r for r in rows if r[2] == dof]
    if not picked:
        return None
    omegas = np.unique([r[0] for r in picked])
    headings = np.unique([r[1] % 360.0 for r in picked])
    values = np.full((len(omegas), len(headings)), np.nan, dtype=complex)
    scale = math.pi / 180.0 if DOFS.index(dof) >= 3 else 1.0     # deg/m -> rad/m
    for omega, heading, _, amplitude, phase in picked:
        values[np.searchsorted(omegas, omega), np.searchsorted(headings, heading % 360.0)] = \
            scale * amplitude * np.exp(1j * math.radians(phase))
    if np.isnan(values.real).any():
        raise KanatError(f"the {dof} RAOs are not a full table: every frequency needs a value at every "
                         f"heading ({len(omegas)} frequencies x {len(headings)} headings, "
                         f"{int(np.isnan(values.real).sum())} missing)")
    return omegas, headings, values


def _along_heading(headings, values, beta_deg, dof):
    """RAOs (k,) at heading ``beta_deg``: linear between the table's headings, periodic in 360 deg."""
    beta = beta_deg % 360.0
    if len(headings) == 1:
        if min(abs(beta - headings[0]), 360.0 - abs(beta - headings[0])) > 0.5:
            raise KanatError(f"the {dof} RAOs are given for one heading ({headings[0]:g} deg) and the "
                             f"waves travel at {beta_deg:g} deg: give the RAOs at that heading")
        return values[:, 0]
    on = np.flatnonzero(np.abs((headings - beta + 180.0) % 360.0 - 180.0) <= 1e-9)
    if len(on):                                  # a heading of the table: its own column, whatever the gaps
        return values[:, on[0]]
    ring = np.concatenate([headings, [headings[0] + 360.0]])
    cols = np.concatenate([values, values[:, :1]], axis=1)
    if beta < ring[0]:
        beta += 360.0
    j = min(int(np.searchsorted(ring, beta, side="right")) - 1, len(ring) - 2)
    gap = ring[j + 1] - ring[j]
    if gap > 180.0:
        raise KanatError(f"the {dof} RAOs' headings leave a {gap:g} deg gap around {beta_deg:g} deg "
                         "(the waves' heading): give RAOs on both sides of it")
    w = (beta - ring[j]) / gap
    return (1.0 - w) * cols[:, j] + w * cols[:, j + 1]


def rao_harmonics(rows, sea):
    """The harmonics of the vessel's motion in ``sea`` (module docstring).

    Parameters
    ----------
    rows : sequence of (omega, heading_deg, dof, amplitude, phase_deg)
        ``vessel.motion.rao_rows``.
    sea : kanat.physics.waves.LinearSea

    Returns
    -------
    dof, amplitude, omega, phase : ndarray, shape (n,)
        The harmonics ``amplitude sin(omega t + phase)`` of degree of freedom ``dof``
        (index into :data:`DOFS`) [m or rad, rad/s, rad].
    outside : float
        Share of the sea's variance ``sum a_i^2 / 2`` at frequencies outside the RAO table.
    """
    dof, amplitude, omega, phase = [], [], [], []
    outside = np.zeros(len(sea.omega), dtype=bool)
    for d, name in enumerate(DOFS):
        grid = _grid(rows, name)
        if grid is None:
            continue
        omegas, headings, values = grid
        for i in range(len(sea.omega)):
            w = sea.omega[i]
            if w < omegas[0] or w > omegas[-1]:
                outside[i] = True
                continue
            column = _along_heading(headings, values, math.degrees(sea.direction[i]), name)
            z = np.interp(w, omegas, column.real) + 1j * np.interp(w, omegas, column.imag)
            dof.append(d)
            amplitude.append(abs(z) * sea.amplitude[i])
            omega.append(w)
            phase.append(0.5 * math.pi - sea.phase[i] - np.angle(z))
    variance = float(np.sum(sea.amplitude**2))
    share = float(np.sum(sea.amplitude[outside] ** 2)) / variance if variance > 0 else 0.0
    return (np.array(dof, dtype=np.int64), np.array(amplitude, float), np.array(omega, float),
            np.array(phase, float), share)
