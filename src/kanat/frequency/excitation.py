"""The excitation of a frequency-domain run: the sea and the vessel's motion as complex amplitudes.

Every excited quantity is written ``Re(X e^{i omega t})`` with a complex amplitude ``X``, so that
``|X|`` is its amplitude and ``arg X`` its phase: ``|X| cos(omega t + arg X)``. The sea's
components ``eta = a cos(k (x cos beta + y sin beta) - omega t + phi)``
(:mod:`kanat.physics.waves` eq. 2) have ``eta_hat = a e^{-i phi}`` at the origin; a vessel harmonic
``A sin(omega t + phase)`` (:mod:`kanat.physics.motion`) has ``A e^{i (phase - pi/2)}``; the RAOs'
motion (:mod:`kanat.physics.rao`) is that of the harmonics they give for a sea of unit amplitudes.

Two kinds of excitation (DNV-RP-C205 §3.5 for the spectral one):

* **harmonic**: a regular wave, a sea of listed components, or harmonic ``vessel.motion``: the
  actual amplitudes at their frequencies (``eta_hat`` as the sea has it);
* **spectral**: a JONSWAP sea, at the frequencies of the time domain's own components for the
  case's seed (:func:`kanat.physics.waves.jonswap_sea`: one per equal bin of width ``d omega``,
  drawn in its bin), with unit amplitudes (transfer functions) and the discrete spectrum
  ``S(omega_j) = a_j^2 / (2 d omega)``, each line standing for its bin, whose variance
  ``sum S(omega_j) d omega`` is exactly that of the time domain's sea. The lines are unequally
  spaced; their weight is the bin's width, never the gap between neighbours, so a response's
  variance ``sum |H(omega_j)|^2 S(omega_j) d omega`` is the time domain's for the same seed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import CaseError, Problem
from kanat.physics.motion import Harmonics, compile_motion
from kanat.physics.rao import rao_harmonics
from kanat.physics.waves import JONSWAP_BAND, LinearSea, jonswap_sea, sea_from_model, wavenumber

SAME_FREQUENCY = 1e-9   # relative: harmonics closer than this share one frequency


@dataclass(frozen=True, eq=False)
class Excitation:
    """What drives a frequency-domain run, frequency by frequency.

    Attributes
    ----------
    omega : ndarray, shape (nf,)
        Angular frequencies [rad/s], ascending.
    sea : LinearSea or None
        The waves at ``omega``: amplitudes 1 and phases 0 (spectral) or the sea's own; None: still water.
    wave : ndarray of complex, shape (nf,)
        ``eta_hat`` at the origin [m] (zero without waves).
    motion : ndarray of complex, shape (nf, 6)
        The vessel's surge, sway, heave [m] and roll, pitch, yaw [rad] (vessel axes).
    spectrum : ndarray, shape (nf,) or None
        The sea's spectral density [m^2 s/rad] (spectral excitation), None for a harmonic one.
    bandwidth : float
        The spectral lines' width ``d omega`` [rad/s]: that of the bin each stands for, the same
        for all, whatever the lines' spacing (0 for a harmonic excitation).
    reference : ndarray, shape (nf,)
        The amplitude a response is divided by for its RAO: ``|eta_hat|`` with waves, else the
        largest vessel harmonic at that frequency [m or rad].
    """

    omega: np.ndarray
    sea: LinearSea | None
    wave: np.ndarray
    motion: np.ndarray
    spectrum: np.ndarray | None
    bandwidth: float
    reference: np.ndarray

    @property
    def spectral(self) -> bool:
        return self.spectrum is not None


def excitation_of(case) -> Excitation:
    """The :class:`Excitation` of a case's ``environment.waves`` and ``vessel.motion``.

    Raises
    ------
    CaseError
        For what the frequency domain cannot take: a motion table (not harmonic), harmonic motion
        in an irregular sea, or nothing that moves.
    """
    env, motion = case.environment, case.vessel.motion
    waves = env.waves
    if motion.rows is not None:
        raise _refused("vessel.motion", "simulation.method: frequency takes harmonic vessel.motion or RAOs, "
                                        "not a motion table; give harmonics or run method: time")
    if waves is not None and waves.type == "jonswap":
        if motion.harmonics:
            raise _refused("vessel.motion", "simulation.method: frequency: harmonic vessel.motion in an irregular "
                                            "sea has no spectrum; drive the vessel by RAOs (vessel.motion: {rao: FILE}) "
                                            "or run method: time")
        return _spectral(case)
    if waves is None and not motion.harmonics:
        raise _refused("simulation.method", "the frequency domain needs an excitation: environment.waves or "
                                            "harmonic vessel.motion")
    return _harmonic(case)


def _refused(key: str, message: str) -> CaseError:
    return CaseError([Problem(key, message)])


def _spectral(case) -> Excitation:
    env, waves = case.environment, case.environment.waves
    sea = jonswap_sea(waves.hs, waves.tp, waves.gamma, waves.heading_deg, seed=waves.seed, depth=env.depth,
                      gravity=env.gravity)
    width = (JONSWAP_BAND[1] - JONSWAP_BAND[0]) * 2.0 * math.pi / waves.tp / len(sea.omega)   # a bin's
    spectrum = sea.amplitude**2 / (2.0 * width)
    unit = LinearSea(np.ones_like(sea.omega), sea.omega, sea.k, sea.direction, np.zeros_like(sea.omega), sea.depth)
    motion = _rao_motion(case, unit)
    return Excitation(sea.omega, unit, np.ones(len(sea.omega), complex), motion, spectrum, width,
                      np.ones(len(sea.omega)))


def _harmonic(case) -> Excitation:
    env = case.environment
    sea = sea_from_model(env)
    omegas = [] if sea is None else list(sea.omega)
    compiled = compile_motion(case.vessel.motion, env) if case.vessel.motion.harmonics else None
    if isinstance(compiled, Harmonics):
        omegas += list(compiled.omega)
    omega = _distinct(np.array(omegas, float))
    nf = len(omega)
    wave, motion = np.zeros(nf, complex), np.zeros((nf, 6), complex)
    unit = None
    if sea is not None:
        at = _slot(omega, sea.omega)
        np.add.at(wave, at, sea.amplitude * np.exp(-1j * sea.phase))
        direction = np.zeros(nf)
        direction[at] = sea.direction
        unit = LinearSea(np.ones(nf), omega, wavenumber(omega, env.gravity, env.depth), direction, np.zeros(nf),
                         sea.depth)
        if case.vessel.motion.rao_rows is not None:
            motion += _rao_motion(case, unit) * wave[:, None]
    if isinstance(compiled, Harmonics):
        at = _slot(omega, compiled.omega)
        np.add.at(motion, (at, compiled.dof), compiled.amplitude * np.exp(1j * (compiled.phase - 0.5 * math.pi)))
    reference = np.where(np.abs(wave) > 0.0, np.abs(wave), np.max(np.abs(motion), axis=1))
    return Excitation(omega, unit, wave, motion, None, 0.0, reference)


def _rao_motion(case, unit: LinearSea) -> np.ndarray:
    """The vessel's complex motion (nf, 6) per unit wave amplitude from its RAO table (zero without one)."""
    motion = np.zeros((len(unit.omega), 6), complex)
    rows = case.vessel.motion.rao_rows
    if rows is None:
        return motion
    dof, amplitude, omega, phase, _ = rao_harmonics(rows, unit)
    np.add.at(motion, (_slot(unit.omega, omega), dof), amplitude * np.exp(1j * (phase - 0.5 * math.pi)))
    return motion


def _distinct(omega: np.ndarray) -> np.ndarray:
    """The distinct frequencies of ``omega``, ascending (equal within :data:`SAME_FREQUENCY`)."""
    omega = np.sort(omega)
    keep = np.r_[True, np.diff(omega) > SAME_FREQUENCY * omega[1:]]
    return omega[keep]


def _slot(grid: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Index into ``grid`` of each of ``omega`` (each within :data:`SAME_FREQUENCY` of a grid value)."""
    at = np.clip(np.searchsorted(grid, np.asarray(omega) * (1 - SAME_FREQUENCY)), 0, len(grid) - 1)
    return at.astype(np.int64)


def vessel_displacement(motion: np.ndarray, arms: np.ndarray, heading: float) -> np.ndarray:
    """Complex displacements (nf, p, 3) of vessel points at lever arms ``arms`` (p, 3) [m] for the
    motion (nf, 6): ``Rz(heading) (q + theta x r)`` (small rotations of
    :mod:`kanat.physics.motion`'s ``R r``), global axes."""
    translation, rotation = motion[:, None, :3], motion[:, None, 3:]
    local = translation + np.cross(rotation, np.asarray(arms, float)[None, :, :])
    c, s = math.cos(heading), math.sin(heading)
    return np.stack([c * local[..., 0] - s * local[..., 1], s * local[..., 0] + c * local[..., 1], local[..., 2]], -1)
