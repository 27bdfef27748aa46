"""Linear (Airy) wave kinematics: regular waves, JONSWAP seas and seas given component by
component (theory/lumped.md §5).

A sea is a sum of linear components ``j`` with amplitude ``a_j``, angular frequency
``omega_j``, wavenumber ``k_j`` (finite-depth dispersion), direction ``beta_j`` (the
direction the waves travel to, from ``+x``, counter-clockwise) and phase ``phi_j``.
With ``theta_j = k_j (x cos beta_j + y sin beta_j) - omega_j t + phi_j`` (Dean &
Dalrymple 1991, *Water Wave Mechanics*, ch. 3-4)::

    (1)  omega^2 = g k tanh(k h)                                   dispersion
    (2)  eta     = sum a cos(theta)                                 elevation
    (3)  u_h     = sum a omega C(z) cos(theta) (cos beta, sin beta) horizontal velocity
    (4)  u_z     = sum a omega S(z) sin(theta)                      vertical velocity
    (5)  C(z) = cosh(k (z + h)) / sinh(k h),  S(z) = sinh(k (z + h)) / sinh(k h)

(``C = S = exp(k z)`` in deep water), and accelerations are the time derivatives
of (3)-(4) at a fixed point. Kinematics above the mean surface are those at
``z = 0`` (constant extrapolation), below the seabed those at ``z = -h``.

Wheeler stretching (``stretching="wheeler"``; Wheeler 1970, J. Petrol. Technol. 22, 359)
maps the water column under the instantaneous surface ``eta`` onto the one under the mean
surface: a point at height ``z <= eta`` takes the kinematics (3)-(5) at::

    (7)  z_s = h (z + h) / (h + eta) - h        (deep water: z_s = z - eta)

and a point above the surface those at ``z_s = 0`` (the surface's own), as MoorDyn-C's summed
components (``WaveKin 7``) do. Without stretching (``"none"``, the default) a point takes
those at its own ``z``.

A ramp of ``T`` seconds (``ramp``) multiplies the elevation, velocity and acceleration by::

    (8)  r(t) = (1 - cos(pi t / T)) / 2  for 0 <= t < T,   r(t) = 1  for t >= T

(:mod:`kanat.physics.ramp`; a half cosine: ``r`` and ``dr/dt`` are continuous, 0 at the start
and 1 and 0 at ``T``); the acceleration is the sea's times ``r``, without the ``dr/dt`` term of
the ramped velocity's derivative. ``T = 0``: no ramp.

The JONSWAP spectrum (DNV-RP-C205 §3.5.5; Hasselmann et al. 1973)::

    (6)  S(w) = A 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w/wp)^-4) gamma^exp(-(w - wp)^2 / (2 s^2 wp^2))

with ``s = 0.07`` below the peak and ``0.09`` above; ``A`` is set so that the discrete
components give exactly ``4 sqrt(m0) = Hs`` (DNV's ``1 - 0.287 ln gamma`` is its
approximation). The band ``0.5 wp`` to ``4 wp`` is cut into equal bins of width ``dw``; component
``j`` takes a frequency ``w_j`` drawn uniformly in its bin, ``a_j = sqrt(2 S(w_j) dw)`` and a phase
uniform in ``[0, 2 pi)``, all from a seeded generator, so a seed always gives the same sea.
Frequencies at the bins' centres would repeat the sea every ``2 pi / dw`` (``200 Tp / 3.5``, 630 s
at Tp 11 s); drawn ones are incommensurate and it never repeats (Tucker, Challenor & Carter 1984,
Appl. Ocean Res. 6(2), 118; :func:`jonswap_sea`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from kanat.errors import KanatError
from kanat.physics.ramp import ramp_factor

STRETCHINGS = ("none", "wheeler")
"""Ways of taking the kinematics up to the instantaneous surface (module docstring, eq. 7)."""

JONSWAP_COMPONENTS = 200      # components of an irregular sea, one per equal bin at a frequency drawn in it
                              # (at the bins' centres the sea would repeat every 200 Tp / 3.5 s: jonswap_sea)
JONSWAP_BAND = (0.5, 4.0)     # frequency band in multiples of the peak frequency (holds > 99.5 % of m0)
SIGMA_LOW, SIGMA_HIGH = 0.07, 0.09   # JONSWAP peak widths below and above wp
DEEP_KH = 20.0                # k h beyond which tanh(k h) = 1 to 1e-17


def wavenumber(omega, gravity: float = 9.81, depth: float | None = None) -> np.ndarray:
    """Wavenumber ``k`` from the linear dispersion relation (1) by Newton's method.

    Parameters
    ----------
    omega : float or array_like
        Angular frequency [rad/s], > 0.
    gravity : float
        [m/s^2].
    depth : float or None
        Water depth ``h`` [m]; None: deep water (``k = omega^2 / g``).

    Returns
    -------
    ndarray
        ``k`` [rad/m], same shape as ``omega``.
    """
    omega = np.asarray(omega, dtype=float)
    if np.any(omega <= 0):
        raise KanatError("wave angular frequencies must be positive")
    k_deep = omega**2 / gravity
    if depth is None:
        return k_deep
    # Guo (2002) explicit approximation as the start, then Newton on f(k) = g k tanh(kh) - w^2
    x = omega * math.sqrt(depth / gravity)
    k = x**2 * (1.0 - np.exp(-x**2.5)) ** (-0.4) / depth
    for _ in range(50):
        th = np.tanh(k * depth)
        f = gravity * k * th - omega**2
        df = gravity * (th + k * depth * (1.0 - th**2))
        step = f / df
        k = k - step
        if np.all(np.abs(step) <= 1e-14 * k):
            break
    return k


@dataclass(frozen=True, eq=False)
class LinearSea:
    """A sum of linear wave components (eqs. 2-5).

    Attributes
    ----------
    amplitude, omega, k, direction, phase : ndarray, shape (n,)
        ``a`` [m], ``omega`` [rad/s], ``k`` [rad/m], ``beta`` [rad], ``phi`` [rad].
    depth : float or None
        Water depth [m]; None: deep water.
    stretching : str
        ``"none"`` or ``"wheeler"`` (eq. 7).
    ramp : float
        Duration ``T`` [s] of the start-up ramp (eq. 8); 0: none.
    """

    amplitude: np.ndarray
    omega: np.ndarray
    k: np.ndarray
    direction: np.ndarray
    phase: np.ndarray
    depth: float | None = None
    stretching: str = "none"
    ramp: float = 0.0

    def __post_init__(self):
        if self.stretching not in STRETCHINGS:
            raise KanatError(f"unknown wave stretching '{self.stretching}'; valid: {', '.join(STRETCHINGS)}")

    def _theta(self, x, y, t):
        cb, sb = np.cos(self.direction), np.sin(self.direction)
        return (np.multiply.outer(x, self.k * cb) + np.multiply.outer(y, self.k * sb)
                - self.omega * t + self.phase)

    def elevation(self, x, y, t: float) -> np.ndarray:
        """Surface elevation ``eta`` [m] at horizontal positions ``x, y`` (eq. 2, ramped by eq. 8)."""
        theta = self._theta(np.asarray(x, float), np.asarray(y, float), t)
        return ramp_factor(t, self.ramp) * (np.cos(theta) @ self.amplitude)

    def stretched(self, points, t: float) -> np.ndarray:
        """The heights (n,) [m] whose kinematics (3)-(5) ``points`` (n, 3) take: eq. (7) with
        Wheeler stretching, the points' own ``z`` without."""
        p = np.atleast_2d(np.asarray(points, dtype=float))
        if self.stretching == "none":
            return p[:, 2]
        eta = self.elevation(p[:, 0], p[:, 1], t)
        if self.depth is None:
            z = p[:, 2] - eta
        else:
            z = self.depth * (p[:, 2] + self.depth) / (self.depth + eta) - self.depth
        return np.where(p[:, 2] > eta, 0.0, np.minimum(z, 0.0))

    def _profiles(self, z: np.ndarray):
        """``C(z)``, ``S(z)`` of eq. (5), shape (n_points, n_components), overflow-free."""
        if self.depth is None:
            z = np.minimum(z, 0.0)
            e = np.exp(np.multiply.outer(z, self.k))
            return e, e
        h = self.depth
        z = np.clip(z, -h, 0.0)
        kz = np.multiply.outer(z, self.k)
        below = np.exp(-2.0 * np.multiply.outer(z + h, self.k))      # exp(-2 k (z + h))
        scale = np.exp(kz) / (1.0 - np.exp(-2.0 * self.k * h))
        return scale * (1.0 + below), scale * (1.0 - below)

    def _parts(self, points, t):
        p = np.atleast_2d(np.asarray(points, dtype=float))
        theta = self._theta(p[:, 0], p[:, 1], t)
        c, s = self._profiles(self.stretched(p, t))
        return theta, c, s

    def velocity(self, points, t: float) -> np.ndarray:
        """Water particle velocity [m/s] at ``points`` (shape (n, 3)) (eqs. 3-4, 7-8)."""
        theta, c, s = self._parts(points, t)
        aw = ramp_factor(t, self.ramp) * self.amplitude * self.omega
        horizontal = (c * np.cos(theta)) * aw
        out = np.empty((theta.shape[0], 3))
        out[:, 0] = horizontal @ np.cos(self.direction)
        out[:, 1] = horizontal @ np.sin(self.direction)
        out[:, 2] = (s * np.sin(theta)) @ aw
        return out

    def acceleration(self, points, t: float) -> np.ndarray:
        """Water particle acceleration ``du/dt`` at fixed points [m/s^2], shape (n, 3) (eqs. 7-8)."""
        theta, c, s = self._parts(points, t)
        aw2 = ramp_factor(t, self.ramp) * self.amplitude * self.omega**2
        horizontal = (c * np.sin(theta)) * aw2
        out = np.empty((theta.shape[0], 3))
        out[:, 0] = horizontal @ np.cos(self.direction)
        out[:, 1] = horizontal @ np.sin(self.direction)
        out[:, 2] = -(s * np.cos(theta)) @ aw2
        return out


def regular_wave(height: float, period: float, heading_deg: float = 0.0, *,
                 depth: float | None = None, gravity: float = 9.81, phase: float = 0.0) -> LinearSea:
    """A regular Airy wave of crest-to-trough ``height`` [m] and ``period`` [s].

    ``heading_deg`` is the direction the wave travels to, from ``+x``, counter-clockwise.
    The crest passes ``x = y = 0`` at ``t = phase / omega``.
    """
    if height <= 0 or period <= 0:
        raise KanatError(f"a regular wave needs height > 0 and period > 0 (got {height} m, {period} s)")
    omega = 2.0 * math.pi / period
    return LinearSea(np.array([height / 2.0]), np.array([omega]), wavenumber([omega], gravity, depth),
                     np.array([math.radians(heading_deg)]), np.array([phase]), depth)


def jonswap_spectrum(omega, hs: float, tp: float, gamma: float = 3.3) -> np.ndarray:
    """JONSWAP spectral density ``S(omega)`` [m^2 s/rad] of eq. (6) with DNV's ``A``.

    Parameters
    ----------
    omega : array_like
        Angular frequency [rad/s].
    hs, tp, gamma : float
        Significant height [m], peak period [s], peak enhancement [-].
    """
    w = np.asarray(omega, dtype=float)
    wp = 2.0 * math.pi / tp
    sigma = np.where(w <= wp, SIGMA_LOW, SIGMA_HIGH)
    pm = 5.0 / 16.0 * hs**2 * wp**4 * w**-5 * np.exp(-1.25 * (w / wp) ** -4)
    return (1.0 - 0.287 * math.log(gamma)) * pm * gamma ** np.exp(-((w - wp) ** 2) / (2 * sigma**2 * wp**2))


def jonswap_sea(hs: float, tp: float, gamma: float = 3.3, heading_deg: float = 0.0, *, seed: int = 0,
                depth: float | None = None, gravity: float = 9.81,
                components: int = JONSWAP_COMPONENTS) -> LinearSea:
    """An irregular long-crested sea from the JONSWAP spectrum (6) with seeded phases and frequencies.

    The band ``JONSWAP_BAND`` (in multiples of ``wp = 2 pi / tp``) is cut into ``components``
    equal bins of width ``dw``. Component ``j`` takes a frequency ``omega_j`` drawn uniformly in
    its bin, the amplitude ``a_j = sqrt(2 S(omega_j) dw)`` of the bin it stands for, and a phase
    uniform in ``[0, 2 pi)``; the generator is seeded by ``seed``, the phases drawn first (so they
    are those the same seed gave when the components sat at the bins' centres), then the
    positions in the bins. The amplitudes are then scaled so that ``4 sqrt(sum a^2 / 2) = hs``
    exactly.

    Why drawn frequencies: components at the bins' centres are ``omega_0 + j dw``, so after
    ``2 pi / dw = components tp / 3.5`` seconds (630 s at Tp 11 s) every one has turned a whole
    number of times plus one common angle and the wave groups come back: a 3-hour storm would be
    one 10-minute sea 17 times over, and the maxima of a long record those of 10 minutes.
    Frequencies drawn in their bins are incommensurate and the sea never repeats (Tucker,
    Challenor & Carter 1984, "Numerical simulation of a random sea: a common error and its effect
    upon wave group statistics", Appl. Ocean Res. 6(2), 118-122). Every
    component still stands for a bin of width ``dw``: a spectrum built from the components is
    ``a_j^2 / (2 dw)`` at ``omega_j`` (what :mod:`kanat.frequency` does), whatever their spacing.

    Parameters
    ----------
    hs, tp, gamma : float
        Significant height [m], peak period [s], peak enhancement [-] of eq. (6).
    heading_deg : float
        The direction the waves travel to [deg], from ``+x``, counter-clockwise.
    seed : int
        Seed of the phases and frequencies: the same seed, the same sea, bit for bit.
    depth, gravity : float
        Water depth [m] (None: deep water) and gravity [m/s^2] of the dispersion relation (1).
    components : int
        Number of components (and bins).

    Returns
    -------
    LinearSea
        ``components`` components in increasing frequency.
    """
    if hs <= 0 or tp <= 0 or gamma < 1:
        raise KanatError(f"JONSWAP needs hs > 0, tp > 0, gamma >= 1 (got {hs}, {tp}, {gamma})")
    wp = 2.0 * math.pi / tp
    edges = np.linspace(JONSWAP_BAND[0] * wp, JONSWAP_BAND[1] * wp, components + 1)
    rng = np.random.default_rng(seed)
    phase = rng.uniform(0.0, 2.0 * math.pi, components)
    omega = edges[:-1] + rng.uniform(0.0, 1.0, components) * np.diff(edges)
    amplitude = np.sqrt(2.0 * jonswap_spectrum(omega, hs, tp, gamma) * np.diff(edges))
    amplitude *= hs / (4.0 * math.sqrt(0.5 * np.sum(amplitude**2)))
    return LinearSea(amplitude, omega, wavenumber(omega, gravity, depth),
                     np.full(components, math.radians(heading_deg)), phase, depth)


def component_sea(rows, *, depth: float | None = None, gravity: float = 9.81) -> LinearSea:
    """A sea of components given one by one (eq. 2 with each component as written).

    Parameters
    ----------
    rows : array_like, shape (n, 4)
        ``[omega, amplitude, phase_deg, heading_deg]`` per component: angular frequency
        [rad/s] (> 0), amplitude ``a`` [m], phase ``phi`` [deg] and direction ``beta`` [deg]
        of eq. (2).
    depth, gravity : float
        Water depth [m] (None: deep water) and gravity [m/s^2] of the dispersion relation (1).
    """
    table = np.asarray(rows, dtype=float).reshape(-1, 4)
    omega = table[:, 0]
    return LinearSea(table[:, 1].copy(), omega.copy(), wavenumber(omega, gravity, depth),
                     np.radians(table[:, 3]), np.radians(table[:, 2]), depth)


def sea_from_model(environment) -> LinearSea | None:
    """The sea of a case's ``environment`` (:class:`kanat.model.Environment`), or None."""
    waves = environment.waves
    if waves is None:
        return None
    common = {"depth": environment.depth, "gravity": environment.gravity}
    if waves.type == "regular":
        sea = regular_wave(waves.height, waves.period, waves.heading_deg, **common)
    elif waves.type == "components":
        sea = component_sea(waves.components, **common)
    else:
        sea = jonswap_sea(waves.hs, waves.tp, waves.gamma, waves.heading_deg, seed=waves.seed, **common)
    return replace(sea, stretching=waves.stretching, ramp=waves.ramp)
