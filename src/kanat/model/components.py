"""Line types, bodies and junction points (case sections ``line_types``, ``bodies``,
``points``)."""
from __future__ import annotations

import math

from ._base import ZERO3, KanatModel, Vector3, quantity


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
    """

    mass: float = quantity(unit="kg", gt=0)
    net_buoyancy: float = quantity(unit="N")
    drag_area: float = quantity(0.0, unit="m^2", ge=0)
    added_mass: float = quantity(0.0, unit="kg", ge=0)
    force: Vector3 = quantity(ZERO3, unit="N")

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
