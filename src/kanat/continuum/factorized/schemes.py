"""Kaliukh & Vusatiuk's factorized and wave-factorized schemes as registered continuum schemes.

Five names, each a :class:`~kanat.continuum.schemes.ContinuumScheme` whose ``step`` takes
the planar or the spatial model:

| name | what one step does | order |
|---|---|---|
| ``factorized`` | two upwind sweeps, ``B+`` forward and ``B-`` backward (theory/time-schemes.md §2, eqs. 9–11) | 1 |
| ``factorized-4`` | four sweeps, one per wave and direction (eqs. 12–15) | 1 |
| ``wave-factorized`` | planar: longitudinal then transverse block, gamma-weighted box (theory/time-schemes.md §3) | 2 at gamma 1/2 |
| ``wave-factorized-2`` | spatial: longitudinal \\| both transverse waves (paper section 4.2) | 2 at gamma 1/2 |
| ``wave-factorized-3`` | spatial: longitudinal \\| normal \\| binormal | 2 at gamma 1/2 |

``wave-factorized`` on a spatial model uses the two-block split; on a planar model, which
has two wave types, every wave split is the two-block one. The registry
(:mod:`kanat.continuum.schemes`) imports this module; import the classes from there.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from kanat.continuum.factorized.sweeps import FOUR_SWEEPS, TWO_SWEEPS, factorized_step
from kanat.continuum.family import ContinuumScheme
from kanat.errors import KanatError

MAX_SIGMA_TR = {
    ("factorized", 2): 1.0, ("factorized", 3): 1.0,
    ("factorized-4", 2): 0.5, ("factorized-4", 3): 0.5,
    ("wave-factorized", 3): 4.5, ("wave-factorized-2", 3): 4.5, ("wave-factorized-3", 3): 4.5,
}
"""Largest transverse Courant number ``sigma_tr`` (at the initial state's largest tension) at
which each scheme stayed bounded on the examples, by scheme and dimensions (stability sweeps,
docs/factorization.md): the sweeps on the 1000 m speed step (bounded at 0.94 / 0.47, not at
1.42 / 0.94); the spatial wave blocks on the 360 deg turn (bounded at 4.7, not at 9.4). The
planar wave split stayed bounded on every example swept, so it has no entry."""


@dataclass(frozen=True)
class Factorized(ContinuumScheme):
    """Factorization by propagation direction: two implicit upwind sweeps per step (Kaliukh & Vusatiuk 2018, eq. 11).

    Parameters
    ----------
    implicit_source : bool
        Linearize the loads in the first sweep (default); False is the paper's explicit ``D^n``.
    compiled : bool
        Run the step compiled (numba); False runs its NumPy twin.
    delta : bool
        Sweep increments driven by the upwind residual (Beam–Warming delta form), whose
        steady state does not depend on the step; False (default) is the paper's eq. 8.
    check_stability : bool
        Refuse, before the run, a step beyond the transverse Courant number the scheme is
        known to take (:data:`MAX_SIGMA_TR`); False lets a stability study go past it.
    """

    name: ClassVar[str] = "factorized"
    order: ClassVar[int] = 1
    sweeps: ClassVar[tuple] = TWO_SWEEPS
    implicit_source: bool = True
    compiled: bool = True
    delta: bool = False
    check_stability: bool = True

    def max_sigma_tr(self, dimensions: int) -> float | None:
        """The largest ``sigma_tr`` this scheme is known to stay bounded at (:data:`MAX_SIGMA_TR`)."""
        return MAX_SIGMA_TR.get((self.name, dimensions)) if self.check_stability else None

    def step(self, model, state, dt: float):
        """One step: ``(new_state, 1)``; raises NewtonFailure when an end cannot be solved."""
        world, y, chart = model.world(state, dt)
        new = factorized_step(world, y, dt, self.sweeps, self.implicit_source, self.compiled, self.delta)
        return model.advanced(state, y, new, chart, dt), 1


@dataclass(frozen=True)
class Factorized4(Factorized):
    """Factorization by direction and wave type: four sweeps ``B_1+, B_1-, B_2+, B_2-`` (eqs. 14–15)."""

    name: ClassVar[str] = "factorized-4"
    sweeps: ClassVar[tuple] = FOUR_SWEEPS


@dataclass(frozen=True)
class WaveFactorized(ContinuumScheme):
    """Wave factorization: one gamma-weighted box sub-step per wave block (Kaliukh & Vusatiuk 2018, eqs. 23–24, 29).

    Parameters
    ----------
    gamma : float
        Weight of the new level in each sub-step, in [1/2, 1]. Default 0.6: at 1/2 (the paper's
        Crank–Nicolson) round-off grows without bound in a steady tow (docs/factorization.md);
        set ``gamma: 0.5`` in the case for the paper's scheme.
    iterations : int
        Passes over the blocks per step (1: the paper's quasi-linear scheme).
    compiled : bool
        Assemble the blocks compiled (numba); False uses the NumPy assembly.
    """

    name: ClassVar[str] = "wave-factorized"
    blocks: ClassVar[int] = 2
    gamma: float = 0.6
    iterations: int = 1
    compiled: bool = True
    check_stability: bool = True

    def max_sigma_tr(self, dimensions: int) -> float | None:
        """The largest ``sigma_tr`` this scheme is known to stay bounded at (:data:`MAX_SIGMA_TR`)."""
        return MAX_SIGMA_TR.get((self.name, dimensions)) if self.check_stability else None

    @property
    def order(self) -> int:
        """2 at ``gamma = 1/2`` (Crank–Nicolson blocks), else 1."""
        return 2 if self.gamma == 0.5 else 1

    def __post_init__(self):
        if not 0.5 <= self.gamma <= 1.0:
            raise KanatError(f"gamma = {self.gamma} is outside [1/2, 1] for the wave-factorized scheme "
                             "(1/2 is Crank–Nicolson)")
        if self.iterations < 1:
            raise KanatError(f"iterations = {self.iterations}; the wave-factorized scheme needs at least one pass")

    def step(self, model, state, dt: float):
        """One step: ``(new_state, iterations)``."""
        world, y, chart = model.world(state, dt)
        count = self.blocks if world.system.dim == 3 else 2
        from kanat.continuum.factorized.waves import wave_factorized_step    # compiled kernels: loaded when used

        new = wave_factorized_step(world, y, dt, count, self.gamma, self.iterations, self.compiled)
        return model.advanced(state, y, new, chart, dt), self.iterations


@dataclass(frozen=True)
class WaveFactorized2(WaveFactorized):
    """Spatial wave factorization in two blocks: longitudinal | both transverse waves."""

    name: ClassVar[str] = "wave-factorized-2"


@dataclass(frozen=True)
class WaveFactorized3(WaveFactorized):
    """Spatial wave factorization in three blocks: longitudinal | normal | binormal."""

    name: ClassVar[str] = "wave-factorized-3"
    blocks: ClassVar[int] = 3

