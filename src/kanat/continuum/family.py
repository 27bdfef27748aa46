"""The generalized-α family of time schemes for the box-discretized cable (theory/time-schemes.md §1).

With ``(.)^[a] = (1 - a)(.)^{n+1} + a (.)^n`` (the α weights sit on the *old* level),
every scheme of the family solves at each step

    avg(M)^[am] avg(Ydot)^[am] + avg(K)^[ak] ((Y_j - Y_{j-1}) / ds)^[ak] = avg(F)^[ak]
    Ydot^{n+1} = (Y^{n+1} - Y^n) / (gamma dt) - (1 - gamma) / gamma * Ydot^n

and differs only in ``(am, ak, gamma)``. For the generalized-α scheme (Chung & Hulbert,
as adapted by Gobat & Grosenbaugh 2001 and Zhang, Zhang & Liu 2012) ``lam = lambda_inf`` in [-1, 0] is
the double eigenvalue of the amplification matrix at infinite frequency:

    ak = lam / (lam - 1),   am = (3 lam + 1) / (2 (lam - 1)),   gamma = 1/2 - am + ak.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from kanat.errors import KanatError
from kanat.schemes import Scheme


@dataclass(frozen=True)
class ContinuumScheme(Scheme):
    """Base of every continuum scheme: ``step(model, state, dt) -> (state, iterations)``.

    ``model`` is a planar or spatial adapter (:mod:`kanat.continuum.models`) holding the
    cable, its ends and the vessel track; a step that cannot be taken raises
    :class:`kanat.continuum.stepper.NewtonFailure` (the run loop then cuts the step).
    """

    model: ClassVar[str] = "continuum"

    def step(self, model, state, dt: float):
        raise NotImplementedError

    def max_sigma_tr(self, dimensions: int) -> float | None:
        """The largest transverse Courant number the scheme is known to take, or None when it
        takes any step (the generalized-α family is unconditionally stable)."""
        return None


@dataclass(frozen=True)
class FamilyScheme(ContinuumScheme):
    """A member of the generalized-α family; subclasses give ``coefficients()``."""

    def coefficients(self) -> tuple[float, float, float]:
        """``(am, ak, gamma)``."""
        raise NotImplementedError

    def step(self, model, state, dt: float):
        """Newton on the box equations with this member's weights (:mod:`stepper`, :mod:`spatial`)."""
        return model.step(state, dt, self.coefficients())


@dataclass(frozen=True)
class GeneralizedAlpha(FamilyScheme):
    """Generalized-α, second order, numerical damping set by ``lambda_inf`` (Zhang, Zhang & Liu 2012)."""

    name: ClassVar[str] = "generalized-alpha"
    order: ClassVar[int] = 2
    lambda_inf: float = -0.5

    def __post_init__(self):
        if not -1.0 <= self.lambda_inf <= 0.0:
            raise KanatError(f"lambda_inf = {self.lambda_inf} is outside [-1, 0]; the papers recommend "
                             "[-0.7, -0.3] (default -0.5)")

    def coefficients(self):
        lam = self.lambda_inf
        ak = lam / (lam - 1.0)
        am = (3.0 * lam + 1.0) / (2.0 * (lam - 1.0))
        return am, ak, 0.5 - am + ak


@dataclass(frozen=True)
class Box(FamilyScheme):
    """The box method of Ablow & Schechter: centred in time, second order, no dissipation."""

    name: ClassVar[str] = "box"
    order: ClassVar[int] = 2

    def coefficients(self):
        return 0.5, 0.5, 0.5


@dataclass(frozen=True)
class BackwardEuler(FamilyScheme):
    """Backward Euler (Koh et al.): first order, strongly dissipative."""

    name: ClassVar[str] = "backward-euler"
    order: ClassVar[int] = 1

    def coefficients(self):
        return 0.0, 0.0, 1.0


@dataclass(frozen=True)
class GeneralizedTrapezoidal(FamilyScheme):
    """Generalized trapezoidal (Sun et al.): ``am = ak = 0``, ``gamma`` in [1/2, 1]; order 1 (2 at 1/2)."""

    name: ClassVar[str] = "generalized-trapezoidal"
    gamma: float = 0.6

    @property
    def order(self) -> int:
        """2 at ``gamma = 1/2`` (the trapezoidal rule), else 1."""
        return 2 if self.gamma == 0.5 else 1

    def __post_init__(self):
        if not 0.5 <= self.gamma <= 1.0:
            raise KanatError(f"gamma = {self.gamma} is outside [1/2, 1] for the generalized trapezoidal scheme")

    def coefficients(self):
        return 0.0, 0.0, self.gamma
