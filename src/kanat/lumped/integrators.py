"""Time schemes of the lumped model, registered in :mod:`kanat.schemes` (theory/lumped.md §6).

Every scheme is a frozen dataclass (its fields are its parameters) with the contract:

1. ``start(system, t, xf, vf, h) -> state``: the scheme's state at ``t`` (its ``state_type``, a
   frozen dataclass: :class:`ExplicitState`, :class:`MultistepState` or :class:`ImplicitState`:
   free nodes' positions and velocities, plus the scheme's own history) — everything a
   checkpoint needs to continue exactly (:meth:`SchemeState.arrays`);
2. ``step(system, state, h) -> state``: a new state ``h`` later; the old one is not touched;
3. class attributes ``name``, ``order`` and, for explicit schemes, ``stability_limit``: the
   largest ``omega h`` on the imaginary axis (undamped oscillation) for which the scheme is
   stable; ``model`` and ``explicit`` come from the list of names (:data:`kanat.schemes.SCHEME_NAMES`).

Schemes:

* ``rk4`` — classical Runge–Kutta, 4 evaluations per step;
* ``abm4`` — Adams–Bashforth–Moulton 4 in PECE mode, started by three RK4 steps (the
  Bezverkhyi's multistep predictor–corrector, Bezverkhyi 2006, refs. [1, 4]), 2 evaluations per step;
* ``generalized-alpha-lumped`` — Chung & Hulbert's (1993, J. Appl. Mech. 60, 371)
  generalized-α family for ``M a = F(x, v)`` in its WBZ-α member (``alpha_f = 0``: the force
  balance at the step's end), unconditionally stable, second order, its
  amplification at infinite frequency ``lambda_inf = -rho_inf`` (as the continuum's
  ``lambda_inf``); each step a Newton solve with the sparse tangent (:mod:`.implicit`).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from kanat.lumped.implicit import generalized_alpha_step
from kanat.model.limits import EXPLICIT_STABILITY
from kanat.schemes import Scheme, registry


def pack(xf, vf):
    return np.concatenate([np.ravel(xf), np.ravel(vf)])


def unpack(y):
    half = y.size // 2
    return y[:half].reshape(-1, 3), y[half:].reshape(-1, 3)


@dataclass(frozen=True)
class SchemeState:
    """A lumped scheme's state at time ``t`` [s]; subclasses add its arrays."""

    t: float

    def positions(self) -> tuple[np.ndarray, np.ndarray]:
        """Free nodes' ``(x, v)``, shape (n_free, 3) each."""
        raise NotImplementedError

    def arrays(self) -> dict:
        """Every field by name, as a checkpoint stores it (:meth:`from_arrays` reads it back)."""
        return {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}

    @classmethod
    def from_arrays(cls, arrays: dict):
        """The state of :meth:`arrays` (numbers stored as 0-d arrays come back as numbers; a field
        a checkpoint lacks takes its default)."""
        values = {}
        for f in dataclasses.fields(cls):
            if f.name in arrays:
                value = arrays[f.name]
                values[f.name] = value.item() if f.type in ("float", "int") and np.ndim(value) == 0 else value
        return cls(**values)

    def copy(self):
        """The same state with its arrays copied."""
        return dataclasses.replace(self, **{name: np.array(value) for name, value in self.arrays().items()
                                            if isinstance(value, np.ndarray)})


@dataclass(frozen=True)
class ExplicitState(SchemeState):
    """``rk4``'s state: ``y = (x, v)`` of the free nodes packed (:func:`pack`), shape (6 n_free,)."""

    y: np.ndarray = None

    def positions(self):
        return unpack(self.y)


@dataclass(frozen=True)
class MultistepState(ExplicitState):
    """``abm4``'s state: ``y`` and ``history``, the rates ``f_n .. f_n-k`` (k + 1, 6 n_free), k < 4."""

    history: np.ndarray = None


@dataclass(frozen=True)
class ImplicitState(SchemeState):
    """The generalized-α state and its work so far.

    Attributes
    ----------
    x, v, a : ndarray, shape (n_free, 3)
        Free nodes' positions [m], velocities [m/s] and accelerations [m/s^2].
    iterations : int
        Newton iterations so far.
    cuts : int
        Refused step attempts so far (:mod:`kanat.step_control`).
    explicit : int
        Steps ``rk4`` took where the implicit iteration failed even on the step's halves.
    """

    x: np.ndarray = None
    v: np.ndarray = None
    a: np.ndarray = None
    iterations: int = 0
    cuts: int = 0
    explicit: int = 0

    def positions(self):
        return self.x, self.v


def _rk4(system, t, y, h):
    f = system.rhs
    k1 = f(t, y)
    k2 = f(t + 0.5 * h, y + 0.5 * h * k1)
    k3 = f(t + 0.5 * h, y + 0.5 * h * k2)
    k4 = f(t + h, y + h * k3)
    return y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)


@dataclass(frozen=True)
class RK4(Scheme):
    """Classical 4th-order Runge–Kutta on ``y = (q, q_dot)``."""

    name: ClassVar[str] = "rk4"
    order: ClassVar[int] = 4
    stability_limit: ClassVar[float] = EXPLICIT_STABILITY["rk4"]    # imaginary-axis bound 2 sqrt(2) = 2.83, real 2.79
    evaluations_per_step: ClassVar[int] = 4
    state_type: ClassVar[type] = ExplicitState

    def start(self, system, t, xf, vf, h):
        return ExplicitState(float(t), pack(xf, vf))

    def step(self, system, state, h):
        return ExplicitState(state.t + h, _rk4(system, state.t, state.y, h))


AB4 = np.array([55.0, -59.0, 37.0, -9.0]) / 24.0     # on f_n, f_n-1, f_n-2, f_n-3
AM4 = np.array([9.0, 19.0, -5.0, 1.0]) / 24.0        # on f_n+1, f_n, f_n-1, f_n-2


@dataclass(frozen=True)
class ABM4(Scheme):
    """Adams–Bashforth–Moulton 4 (PECE), started by RK4; ``history`` holds ``f_n .. f_n-3``."""

    name: ClassVar[str] = "abm4"
    order: ClassVar[int] = 4
    stability_limit: ClassVar[float] = EXPLICIT_STABILITY["abm4"]    # 0.3: PECE is weakly unstable on the imaginary axis (growth
                                              # 1e-4 per step at 0.3, 1.5e-3 at 0.5; real-axis bound 1.28):
                                              # it relies on some physical damping (tests measure it)
    evaluations_per_step: ClassVar[int] = 2
    state_type: ClassVar[type] = MultistepState

    def start(self, system, t, xf, vf, h):
        y = pack(xf, vf)
        return MultistepState(float(t), y, system.rhs(t, y)[None, :])

    def step(self, system, state, h):
        t, y, hist = state.t, state.y, state.history
        if len(hist) < 4:                                   # RK4 start-up
            y1 = _rk4(system, t, y, h)
            return MultistepState(t + h, y1, np.vstack([system.rhs(t + h, y1)[None, :], hist]))
        yp = y + h * (AB4 @ hist)
        fp = system.rhs(t + h, yp)
        yc = y + h * (AM4[0] * fp + AM4[1:] @ hist[:3])
        fc = system.rhs(t + h, yc)
        return MultistepState(t + h, yc, np.vstack([fc[None, :], hist[:3]]))


@dataclass(frozen=True)
class GeneralizedAlphaLumped(Scheme):
    """Generalized-α (WBZ-α, ``alpha_f = 0``) with Newton on the sparse tangent (:mod:`.implicit`).

    Attributes
    ----------
    lambda_inf : float
        Amplification at infinite frequency, ``-rho_inf``, in [-1, 0]; -1 is the
        trapezoidal rule (no dissipation), 0 annihilates the highest modes (their position at
        once, their velocity and acceleration within two steps).
    max_iterations : int
        Newton iterations per step before the step is halved.
    tolerance : float
        Convergence: the acceleration's increment (full Newton) or its estimated remaining error
        (the compiled modified Newton, :func:`kanat.lumped.fast_implicit.newton_step`) below
        ``tolerance * max(1 m/s^2, max |a|)``: the force balance of every node is then met to about
        ``tolerance`` times the largest inertial force of the step. 1e-5 (1e-6 before 2026-11-27) takes
        9 % less CPU on the three-leg mooring of ``benchmarks/bench_mooring_moordyn.py`` with the
        fairlead tension's mean and range unchanged to four digits; tensions move by at most 5e-6
        of their largest value on ``examples/lazy_wave.yaml`` (docs/lumped.md).
    """

    name: ClassVar[str] = "generalized-alpha-lumped"
    order: ClassVar[int] = 2
    lambda_inf: float = -0.5
    max_iterations: int = 12
    tolerance: float = 1e-5
    state_type: ClassVar[type] = ImplicitState

    def __post_init__(self):
        if not -1.0 <= self.lambda_inf <= 0.0:
            raise ValueError(f"lambda_inf must be in [-1, 0] (got {self.lambda_inf})")

    @property
    def coefficients(self) -> tuple[float, float, float, float]:
        """``(alpha_m, alpha_f, gamma, beta)``: the WBZ-α member of Chung & Hulbert's family
        (1993, section 3: ``alpha_f = 0``, ``alpha_m = (rho_inf - 1) / (rho_inf + 1)``, eqs. 17
        and 20 for ``gamma`` and ``beta``), second order and unconditionally stable.

        ``alpha_f = 0`` puts the force balance at ``t_n+1`` itself, where the run reports its
        tensions. With ``alpha_f > 0`` it holds at ``x_m``, and ``x_n+1`` is extrapolated from
        ``x_m``: on a line that swings, each element's chord is lengthened by ``O((w h)^2)``, and
        an axial stiffness of ``EA = 5e8 N`` turned that into a top tension 8 % high on average
        with twice the range (a jumper in waves, h = 0.1 s; docs/lumped.md).
        """
        r = -self.lambda_inf
        am, af = (r - 1.0) / (r + 1.0), 0.0
        gamma = 0.5 - am + af
        return am, af, gamma, 0.25 * (1.0 - am + af) ** 2

    def start(self, system, t, xf, vf, h):
        xf, vf = np.array(xf, float), np.array(vf, float)
        return ImplicitState(float(t), xf, vf, system.acceleration(t, xf, vf))

    def step(self, system, state, h):
        return generalized_alpha_step(self, system, state, h)


SCHEMES = registry(RK4, ABM4, GeneralizedAlphaLumped)
"""Every lumped scheme by name."""


def state_positions(state: SchemeState) -> tuple[np.ndarray, np.ndarray]:
    """Free nodes' ``(x, v)``, shape (n_free, 3) each, of any scheme's state."""
    return state.positions()
