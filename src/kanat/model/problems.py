"""Self-contained problem blocks: the sphere on two cables (Naumov & Agievich, theory/statics.md §3) and
ship pitch with a reactive stabilizer (Gaisha, theory/vessel.md §2)."""
from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import BeforeValidator, Field, model_validator

from ._base import KanatModel, quantity


class SphereDimensionless(KanatModel):
    """The Naumov & Agievich groups (theory/statics.md §3): ``Psi = q/k1``, ``LoL = L0/L``, ``x_C = X_C/L``,
    ``QkL = Q/(k1 L)``, ``RkL = R0/(k1 L)``, ``chi = C_0/C_90``."""

    Psi: float = quantity(unit="-", ge=0)
    LoL: float = quantity(unit="-", gt=0)
    x_C: float = quantity(unit="-")
    QkL: float = quantity(unit="-")
    RkL: float = quantity(unit="-", ge=0)
    chi: float = quantity(0.0333, unit="-", ge=0, le=1)


class SphereDimensional(KanatModel):
    """Dimensional input of the Naumov & Agievich problem, mapped to the groups by the solver."""

    flow_speed: float = quantity(unit="m/s", gt=0)
    sphere_diameter: float = quantity(unit="m", gt=0)
    net_buoyancy: float = quantity(unit="N")
    cable_diameter: float = quantity(unit="m", gt=0)
    cable_length: float = quantity(unit="m", gt=0)
    cable_weight: float = quantity(unit="N/m", ge=0, description="weight in water per length")
    line_length: float = quantity(unit="m", gt=0)
    anchor_x: float = quantity(unit="m", description="X_C of the line's anchor")
    water_density: float | None = quantity(None, unit="kg/m^3", gt=0)


class SphereTwoCables(KanatModel):
    """Sphere held by a weightless line and a heavy cable in a uniform flow.

    Exactly one of ``dimensionless`` and ``dimensional``.
    """

    convention: Literal["published", "physical"] = "published"
    dimensionless: SphereDimensionless | None = None
    dimensional: SphereDimensional | None = None
    n_nodes: int = Field(101, ge=3)

    @model_validator(mode="after")
    def _one_input(self) -> SphereTwoCables:
        if (self.dimensionless is None) == (self.dimensional is None):
            raise ValueError("give exactly one of 'dimensionless' {Psi, LoL, x_C, QkL, RkL} "
                             "or 'dimensional' {flow_speed, sphere_diameter, ...}")
        return self


STABILIZER_MODES = ("off", "sinusoidal", "rectangular", "feedback", "optimal")
"""Control modes of the reactive stabilizer (theory/vessel.md §2, :mod:`kanat.vessel.pitch.laws`)."""
RESONANCE_RTOL = 1e-3
"""Relative detuning ``|n omega - omega_0| / omega_0`` below which an undamped pitch case is
refused (the case checks and the pitch solver share it). Within 0.1 % of resonance the undamped
amplification ``1/|1 - (n omega/omega_0)^2|`` exceeds ~500, and any real damping ratio above
0.001 would change the answer by more than half: the undamped steady state says nothing there."""


def _off_not_false(value):
    """YAML 1.1 reads a bare ``off`` as False: take it as the mode ``off``."""
    return "off" if value is False else value


StabilizerMode = Annotated[Literal["off", "sinusoidal", "rectangular", "feedback", "optimal"],
                           BeforeValidator(_off_not_false)]


class Stabilizer(KanatModel):
    """Reactive stabilizer: control ``mode`` and the largest moment ``max_moment`` M0 [N m].

    Modes: ``off``; ``sinusoidal`` and ``rectangular`` (paper eq. 5: M0 sin(omega t) or M0
    over the first half period, 0 in the second); ``feedback`` (``clip(-feedback_gain
    phi', 0, M0)``; ``feedback_gain`` defaults to ``2 I_y omega_0``); ``optimal`` (the
    piecewise-linear half-period shape of ``shape_nodes`` pieces in [0, M0] minimising
    ``objective``: the amplitude or the largest |pitch|).
    """

    mode: StabilizerMode = "off"
    max_moment: float = quantity(0.0, unit="N m", ge=0)
    feedback_gain: float | None = quantity(None, unit="N m s/rad", gt=0)
    shape_nodes: int = Field(16, ge=1, le=200)
    objective: Literal["amplitude", "max_abs"] = "amplitude"


class PitchModel(KanatModel):
    """Linear pitch oscillator ``I phi'' + c phi' + k phi = M_m sin(omega t + pi) + f(t)``.

    Exactly one of ``natural_frequency`` (omega_0) and ``restoring`` (k); the damping is
    ``c = 2 damping_ratio I omega_0``. ``modes`` lists the stabilizer modes to compare
    (all with ``stabilizer.max_moment``), ``time_points`` the samples of the steady period.
    """

    inertia: float = quantity(unit="kg m^2", gt=0)
    natural_frequency: float | None = quantity(None, unit="rad/s", gt=0)
    restoring: float | None = quantity(None, unit="N m/rad", gt=0)
    wave_moment_amplitude: float = quantity(unit="N m", ge=0)
    wave_period: float = quantity(unit="s", gt=0)
    damping_ratio: float = quantity(0.0, unit="-", ge=0)
    stabilizer: Stabilizer = Field(default_factory=Stabilizer)
    harmonics: int = Field(50, ge=1)
    modes: tuple[StabilizerMode, ...] | None = Field(
        None, description="modes to compute and compare; default off, sinusoidal, rectangular "
                          "and the stabilizer's own mode")
    time_points: int = Field(401, ge=3, description="samples over one period, both ends included")

    @model_validator(mode="after")
    def _one_stiffness(self) -> PitchModel:
        if (self.natural_frequency is None) == (self.restoring is None):
            raise ValueError("give exactly one of 'natural_frequency' (rad/s) or "
                             "'restoring' (N m/rad)")
        return self

    @property
    def omega0(self) -> float:
        """Undamped natural frequency [rad/s]."""
        if self.natural_frequency is not None:
            return self.natural_frequency
        return math.sqrt(self.restoring / self.inertia)

    @property
    def restoring_value(self) -> float:
        """Restoring stiffness k = I omega_0^2 [N m/rad]."""
        return self.restoring if self.restoring is not None else self.inertia * self.omega0**2

    @property
    def wave_frequency(self) -> float:
        """omega = 2 pi / wave_period [rad/s]."""
        return 2.0 * math.pi / self.wave_period
