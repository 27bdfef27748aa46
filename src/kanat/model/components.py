"""Line types, bodies and junction points (case sections ``line_types``, ``bodies``,
``points``)."""
from __future__ import annotations

import math
from typing import Annotated, Any

from pydantic import BeforeValidator, Field, model_validator

from ._base import ZERO3, KanatModel, Vector3, fmt, quantity


def _as_pair(value: Any) -> Any:
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise ValueError(f"each table row must be 2 numbers [strain, tension] (got {value!r})")
    return tuple(value)


TableRow = Annotated[tuple[float, float], BeforeValidator(_as_pair)]


class ElasticLaw(KanatModel):
    """A nonlinear elastic part ``f(e)`` of the tension law ``T = (f(e) + C_E2 de/dt) H(e)``
    (SPEC §5; lumped model). Give exactly one form.

    Attributes
    ----------
    polynomial : tuple of float or None
        ``f(e) = c1 e + c2 e^2 + ...`` [N]: the coefficients ``(c1, c2, ...)``.
    table : tuple of (strain, tension) rows or None
        Piecewise-linear ``f(e)`` through ``(0, 0)`` and the rows (strain ascending,
        tension non-decreasing), extrapolated with the last slope.
    """

    polynomial: tuple[float, ...] | None = quantity(None, unit="N")
    table: tuple[TableRow, ...] | None = quantity(None, unit="-, N")

    @model_validator(mode="after")
    def _one_form(self) -> ElasticLaw:
        if (self.polynomial is None) == (self.table is None):
            raise ValueError("give exactly one of 'polynomial' [c1, c2, ...] (N) or "
                             "'table' [[strain, tension], ...]")
        if self.polynomial is not None and (not self.polynomial or self.polynomial[0] <= 0):
            raise ValueError("the polynomial's first coefficient c1 (the small-strain stiffness, N) "
                             "must be positive")
        if self.table is not None:
            strain = [r[0] for r in self.table]
            tension = [r[1] for r in self.table]
            if strain[0] <= 0 or any(b <= a for a, b in zip(strain, strain[1:])):
                raise ValueError("table strains must be positive and strictly ascending "
                                 f"(got {', '.join(fmt(e) for e in strain)})")
            if tension[0] <= 0 or any(b < a for a, b in zip(tension, tension[1:])):
                raise ValueError("table tensions must be positive and non-decreasing (a cable "
                                 "never pushes)")
        return self


class LineType(KanatModel):
    """Properties of a cable, rope or chain per unit length.

    Attributes
    ----------
    diameter : float
        Hydrodynamic diameter [m], also used for displacement when
        ``weight_in_water`` is not given.
    mass : float
        Mass per length in air [kg/m].
    weight_in_water : float or None
        Submerged weight per length [N/m] (negative: the line floats).
    axial_stiffness : float
        EA [N].
    axial_damping : float
        Kelvin–Voigt damping C_E2 [N s].
    added_mass : float
        Normal added mass per length [kg/m].
    drag_normal, drag_tangential : float
        Drag coefficients C_n (on d) and C_t (on pi d) [-].
    breaking_load : float or None
        Minimum breaking load [N].
    """

    diameter: float = quantity(unit="m", gt=0)
    mass: float = quantity(unit="kg/m", gt=0)
    weight_in_water: float | None = quantity(None, unit="N/m")
    axial_stiffness: float = quantity(unit="N", gt=0)
    axial_damping: float = quantity(0.0, unit="N s", ge=0)
    added_mass: float = quantity(0.0, unit="kg/m", ge=0)
    drag_normal: float = quantity(1.2, unit="-", ge=0)
    drag_tangential: float = quantity(0.0, unit="-", ge=0)
    breaking_load: float | None = quantity(None, unit="N", gt=0)
    drag_normal_coefficient: float | None = quantity(
        None, unit="kg/m^2", ge=0,
        description="seed 004 dimensional normal drag C_n: force per length C_n |v_n| v_n; "
                    "replaces drag_normal in the lumped model")
    drag_tangential_coefficient: float | None = quantity(
        None, unit="kg/m^2", ge=0,
        description="seed 004 dimensional tangential drag C_t: force per length C_t |v_t| v_t")
    elastic_law: ElasticLaw | None = Field(
        None, description="nonlinear elastic part of the tension (lumped model); "
                          "default: linear axial_stiffness * strain")

    @property
    def area(self) -> float:
        """Displaced cross-section pi d^2 / 4 [m^2]."""
        return math.pi * self.diameter**2 / 4.0

    def weight_in_water_value(self, water_density: float, gravity: float) -> float:
        """Submerged weight per length [N/m].

        The given ``weight_in_water``, else ``mass g - rho g pi d^2 / 4``.

        Parameters
        ----------
        water_density : float
            rho [kg/m^3].
        gravity : float
            g [m/s^2].
        """
        if self.weight_in_water is not None:
            return self.weight_in_water
        return self.mass * gravity - water_density * gravity * self.area


class SurfaceBuoy(KanatModel):
    """Hydrostatics of a surface-piercing buoy (vertical cylinder; SPEC §5, lumped model).

    The body's node is the buoy's keel. Its immersion ``d = clip(eta(x, y, t) - z, 0,
    height)`` adds the buoyancy ``rho g waterplane_area d`` to the body's constant
    ``net_buoyancy`` (which then holds minus its weight): restoring from the waterplane,
    lost when the buoy leaves the water.

    Attributes
    ----------
    waterplane_area : float
        [m^2].
    height : float
        Keel to deck [m]; immersion beyond it adds no buoyancy.
    """

    waterplane_area: float = quantity(unit="m^2", gt=0)
    height: float = quantity(2.0, unit="m", gt=0)


class Body(KanatModel):
    """A rigid body treated as a point: towed vehicle, buoy, depressor, otter board.

    Attributes
    ----------
    mass : float
        [kg].
    net_buoyancy : float
        Buoyancy minus weight [N]; negative sinks.
    drag_area : float
        C_D S [m^2].
    added_mass : float
        [kg].
    force : tuple of 3 float
        Constant external force in the global frame [N].
    spreading_force : float
        Otter-board force ``F0`` [N], horizontal, perpendicular to the vessel heading,
        positive to port (lumped model, SPEC §5).
    surface_buoy : SurfaceBuoy or None
        Waterplane hydrostatics of a surface buoy (lumped model).
    position : tuple of 3 float or None
        Initial guess for the network equilibrium [m] (lumped model).
    """

    mass: float = quantity(unit="kg", gt=0)
    net_buoyancy: float = quantity(unit="N")
    drag_area: float = quantity(0.0, unit="m^2", ge=0)
    added_mass: float = quantity(0.0, unit="kg", ge=0)
    force: Vector3 = quantity(ZERO3, unit="N")
    spreading_force: float = quantity(
        0.0, unit="N", description="otter board force F0, horizontal and perpendicular to the "
                                   "vessel heading, positive to port (lumped model)")
    surface_buoy: SurfaceBuoy | None = Field(
        None, description="a buoy riding the wave surface (lumped model)")
    position: Vector3 | None = quantity(
        None, unit="m", description="initial guess of the position for the network "
                                    "equilibrium (lumped model); None: guessed")

    def submerged_weight(self) -> float:
        """Downward pull in still water, ``-net_buoyancy`` [N] (negative: it floats up)."""
        return -self.net_buoyancy


class Point(KanatModel):
    """A named junction of cables in a network (lumped model).

    Attributes
    ----------
    position : tuple of 3 float or None
        Initial position [m]; None: found by the statics.
    mass : float
        Lumped mass at the junction [kg].
    """

    position: Vector3 | None = quantity(None, unit="m")
    mass: float = quantity(0.0, unit="kg", ge=0)
