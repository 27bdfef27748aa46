"""Line types and junction points (case sections ``line_types`` and ``points``); bodies
are in :mod:`kanat.model.body` (imported here too)."""
from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Field, ValidationInfo, field_validator, model_validator

from kanat import catalog as line_catalog

from ._base import ZERO3, KanatModel, Vector3, fmt, quantity
from .body import Body, SurfaceBuoy  # noqa: F401 - bodies lived here; kept importable


def _as_pair(value: Any) -> Any:
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise ValueError(f"each table row must be 2 numbers [strain, tension] (got {value!r})")
    return tuple(value)


TableRow = Annotated[tuple[float, float], BeforeValidator(_as_pair)]

DEFAULT_MAX_STRAIN = 0.1
"""Strain limit of a line without ``max_strain`` or a tabulated law [-] (10 %: beyond the
working range of synthetic ropes, five times the breaking strain of steel)."""


class ElasticLaw(KanatModel):
    """A nonlinear elastic part ``f(e)`` of the tension law ``T = (f(e) + C_E2 de/dt) H(e)``
    (theory/lumped.md), in the lumped and continuum models. Give exactly one form.

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
    bending_stiffness : float
        EI [N m^2]; 0: a perfectly flexible line.
    compression_stiffness : float
        The axial stiffness in compression [N] of a line with bending stiffness (lumped model);
        0: the line carries no compression.
    max_strain : float or None
        Strain limit of the line [-]; None: from the material (:meth:`strain_limit`).
    added_mass_tangential : float
        Tangential added mass per length [kg/m] (MoorDyn's CaAx rho pi d^2 / 4).
    catalog, grade, nominal_diameter : str, str, float or None
        A catalogue line (:mod:`kanat.catalog`) that gives every key not written: the
        volume-equivalent ``diameter``, ``mass``, static ``axial_stiffness``,
        ``breaking_load``, drag and added-mass coefficients (added masses at the case's
        water density when validated from a case file, else 1025 kg/m^3).
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
        description="Bezverkhyi 2006 dimensional normal drag C_n: force per length C_n |v_n| v_n; "
                    "replaces drag_normal in the lumped model")
    drag_tangential_coefficient: float | None = quantity(
        None, unit="kg/m^2", ge=0,
        description="Bezverkhyi 2006 dimensional tangential drag C_t: force per length C_t |v_t| v_t")
    elastic_law: ElasticLaw | None = Field(
        None, description="nonlinear elastic part of the tension (lumped and continuum models; "
                          "statics uses axial_stiffness); default: linear axial_stiffness * strain")
    bending_stiffness: float = quantity(
        0.0, unit="N m^2", ge=0,
        description="bending stiffness EI (continuum model, 2-D and 3-D runs, and lumped model: moments "
                    "from the turning angle at interior nodes; no torsion); 0: a perfectly flexible line. "
                    "The cable's ends and inline bodies are pinned (moment-free), a free end carries no "
                    "shear either; no case key clamps an end")
    compression_stiffness: float = quantity(
        0.0, unit="N", ge=0,
        description="axial stiffness in compression of a line with bending_stiffness (lumped model: its "
                    "elements are bars that push back in proportion to their shortening, and the bending "
                    "stiffness makes a compressed length buckle near Euler's load pi^2 EI / L^2); usually "
                    "the axial_stiffness; 0: the line carries no compression, its compressed parts go slack")
    max_strain: float | None = quantity(
        None, unit="-", gt=0, le=1,
        description="largest strain the line may take (a limit checked on results); None: "
                    "from the material: the last strain of an elastic_law table (beyond it "
                    "the law is extrapolated), else 0.1 (DEFAULT_MAX_STRAIN)")
    added_mass_tangential: float = quantity(
        0.0, unit="kg/m", ge=0,
        description="added mass per length for accelerations along the line (MoorDyn's "
                    "CaAx times rho pi d^2 / 4)")
    catalog: Literal[tuple(line_catalog.CATALOG)] | None = Field(  # type: ignore[valid-type]
        None, description="a line from the catalogue (docs/design.md) giving every key not "
                          "written here: diameter (volume-equivalent), mass, axial_stiffness "
                          "(static), breaking_load, drag and added-mass coefficients")
    grade: Literal[line_catalog.CHAIN_GRADES] | None = Field(  # type: ignore[valid-type]
        None, validate_default=True,
        description="chain grade (chains of the catalogue only), DNV-OS-E302")
    nominal_diameter: float | None = quantity(
        None, unit="m", gt=0, validate_default=True,
        description="bar diameter of a chain, rope diameter otherwise (with catalog)")

    @model_validator(mode="before")
    @classmethod
    def _from_catalog(cls, data: Any, info: ValidationInfo) -> Any:
        """Fill the keys not written from ``catalog`` (explicit keys override it)."""
        if not isinstance(data, dict) or data.get("catalog") is None:
            return data
        density = (info.context or {}).get("water_density", line_catalog.SEAWATER_DENSITY)
        try:
            if data.get("nominal_diameter") is None:
                raise line_catalog.CatalogError("nominal_diameter: missing")
            filled = line_catalog.line_type(data["catalog"], data["nominal_diameter"],
                                            data.get("grade"), water_density=density)
        except line_catalog.CatalogError:
            # the catalogue keys are wrong: their own validators say so at their keys; the
            # placeholders keep the keys the catalogue would give from being reported missing
            filled = dict.fromkeys(("diameter", "mass", "axial_stiffness"), 1.0)
        except TypeError:  # a diameter that is not a number: its own error, nothing filled
            return data
        return {**filled, **data}

    @field_validator("grade")
    @classmethod
    def _grade_for_chains(cls, grade: str | None, info: ValidationInfo) -> str | None:
        if "catalog" not in info.data:  # an unknown catalogue: said at its key
            return grade
        name = info.data["catalog"]
        if name is not None:
            try:
                line_catalog.check_grade(line_catalog.CATALOG[name], grade)
            except line_catalog.CatalogError as error:
                raise ValueError(str(error).removeprefix("grade: ")) from None
        elif grade is not None:
            raise ValueError("a grade goes with a chain of the catalogue: add catalog: "
                             "studless_chain or studlink_chain")
        return grade

    @field_validator("nominal_diameter")
    @classmethod
    def _diameter_in_range(cls, diameter: float | None, info: ValidationInfo) -> float | None:
        if "catalog" not in info.data:  # an unknown catalogue: said at its key
            return diameter
        name = info.data["catalog"]
        if name is None:
            if diameter is not None:
                raise ValueError("a nominal_diameter goes with a catalogue line: add catalog "
                                 f"({' | '.join(line_catalog.CATALOG)})")
            return diameter
        if diameter is None:
            raise ValueError(f"catalog '{name}' needs the nominal_diameter [m]")
        try:
            line_catalog.check_diameter(line_catalog.CATALOG[name], diameter)
        except line_catalog.CatalogError as error:
            raise ValueError(str(error).removeprefix("nominal_diameter: ")) from None
        return diameter

    @field_validator("compression_stiffness")
    @classmethod
    def _compression_needs_bending(cls, stiffness: float, info: ValidationInfo) -> float:
        if stiffness > 0.0 and info.data.get("bending_stiffness", 0.0) <= 0.0:
            raise ValueError("a line carries compression only with bending stiffness (without it a "
                             "compressed chain of elements folds at no load): add bending_stiffness [N m^2] "
                             "or set compression_stiffness to 0")
        return stiffness

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

    def strain_limit(self) -> float:
        """The effective strain limit [-].

        ``max_strain`` when given; else the last strain of an ``elastic_law`` table (the
        measured range; beyond it the law is extrapolated); else :data:`DEFAULT_MAX_STRAIN`
        (a linear ``axial_stiffness`` law or a polynomial: steel wire and chain break below
        2 %, synthetic ropes work below 10 %).
        """
        if self.max_strain is not None:
            return self.max_strain
        if self.elastic_law is not None and self.elastic_law.table is not None:
            return self.elastic_law.table[-1][0]
        return DEFAULT_MAX_STRAIN


class Point(KanatModel):
    """A named junction of cables in a network (lumped model), as MoorDyn's free point:
    a clump weight, a float, or a plain connection.

    Attributes
    ----------
    position : tuple of 3 float or None
        Initial position [m]; None: found by the statics.
    mass : float
        Lumped mass at the junction [kg]; its weight acts down.
    volume : float
        Displaced volume [m^3]; its buoyancy ``rho g volume`` acts up.
    drag_area : float
        C_D A [m^2], the same in every direction.
    added_mass : float
        [kg], the same in every direction (MoorDyn's Ca rho V).
    force : tuple of 3 float
        Constant external force in the global frame [N].
    """

    position: Vector3 | None = quantity(None, unit="m", description="initial position; None: "
                                        "found by the statics")
    mass: float = quantity(0.0, unit="kg", ge=0, description="lumped mass at the junction "
                           "(a clump weight); its weight acts down")
    volume: float = quantity(0.0, unit="m^3", ge=0, description="displaced volume (a float); "
                             "its buoyancy rho g volume acts up")
    drag_area: float = quantity(0.0, unit="m^2", ge=0, description="drag coefficient times "
                                "projected area C_D A, the same in every direction")
    added_mass: float = quantity(0.0, unit="kg", ge=0, description="added mass, the same in "
                                 "every direction (MoorDyn's Ca times rho volume)")
    force: Vector3 = quantity(ZERO3, unit="N", description="constant external force in the "
                              "global frame")

    def net_buoyancy(self, water_density: float, gravity: float) -> float:
        """Buoyancy minus weight, ``(rho volume - mass) g`` [N] (negative sinks)."""
        return (water_density * self.volume - self.mass) * gravity
