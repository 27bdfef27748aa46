"""Water, current and waves (case section ``environment``)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal, Union

from pydantic import BeforeValidator, Field, ValidationInfo, field_validator, model_validator

from ._base import ZERO3, KanatModel, Vector3, fmt, quantity

if TYPE_CHECKING:                   # NumPy loads when a model asks for arrays, not to read a case
    import numpy as np


def _as_row(value: Any) -> Any:
    if not isinstance(value, (list, tuple)) or len(value) != 4:
        got = f"{len(value)} values" if isinstance(value, (list, tuple)) else repr(value)
        raise ValueError(f"each profile row must be 4 numbers [z, ux, uy, uz] (got {got})")
    return tuple(value)


ProfileRow = Annotated[tuple[float, float, float, float], BeforeValidator(_as_row)]

RAMP_DESCRIPTION = ("start-up ramp [s]: the half cosine r(t) = (1 - cos(pi t / ramp)) / 2 for t < ramp, "
                    "1 after, multiplies {what}; 0: none (full strength from t = 0)")
"""The description every ``ramp`` key shares (:mod:`kanat.physics.ramp`)."""


class Current(KanatModel):
    """Steady current: uniform ``velocity`` or a depth ``profile`` (not both).

    Attributes
    ----------
    velocity : tuple of 3 float or None
        Uniform current [m/s] in the global frame.
    profile : tuple of rows (z, ux, uy, uz) or None
        Piecewise-linear profile [m, m/s]; stored sorted by ``z`` from the surface down.
        Beyond the first and last rows the velocity is held constant.
    """

    velocity: Vector3 | None = quantity(None, unit="m/s")
    profile: tuple[ProfileRow, ...] | None = quantity(None, unit="m, m/s")
    ramp: float = quantity(0.0, unit="s", ge=0, description=RAMP_DESCRIPTION.format(what="the velocity"))

    @field_validator("profile")
    @classmethod
    def _sort_profile(cls, rows: tuple[ProfileRow, ...] | None) -> tuple[ProfileRow, ...] | None:
        if rows is None:
            return None
        if not rows:
            raise ValueError("needs at least one row [z, ux, uy, uz]")
        ordered = tuple(sorted(rows, key=lambda r: -r[0]))
        z = [r[0] for r in ordered]
        repeated = sorted({a for a, b in zip(z, z[1:]) if a == b})  # sorted: O(n), not O(n^2)
        if repeated:
            raise ValueError(f"depth z = {fmt(repeated[0])} m appears in two rows; "
                             "each z may appear once")
        return ordered

    @model_validator(mode="after")
    def _one_form(self) -> Current:
        if self.velocity is not None and self.profile is not None:
            raise ValueError("give either 'velocity' (uniform) or 'profile' (rows z, ux, uy, uz), "
                             "not both")
        return self

    def table(self) -> tuple[np.ndarray, np.ndarray]:
        """The current as ascending heights ``(k,)`` [m] and velocities ``(k, 3)`` [m/s] (one row
        when uniform): the form the kernels interpolate in, linear between rows and constant
        beyond the ends."""
        import numpy as np

        if self.profile is None:
            return np.zeros(1), np.asarray(self.at(0.0), dtype=float).reshape(1, 3)
        rows = np.asarray(self.profile, dtype=float)[::-1]
        return np.ascontiguousarray(rows[:, 0]), np.ascontiguousarray(rows[:, 1:4])

    def at(self, z: float | np.ndarray) -> np.ndarray:
        """Current velocity at height ``z``.

        Parameters
        ----------
        z : float or array_like, shape (n,)
            Height [m], ``z = 0`` at the free surface, negative below.

        Returns
        -------
        numpy.ndarray, shape (3,) or (n, 3)
            Velocity [m/s]; linear between profile rows, constant beyond the ends.
        """
        import numpy as np

        z_arr = np.asarray(z, dtype=float)
        if self.profile is None:
            u = np.asarray(self.velocity if self.velocity is not None else ZERO3, dtype=float)
            return np.broadcast_to(u, z_arr.shape + (3,)).copy()
        table = np.asarray(self.profile, dtype=float)[::-1]  # ascending z for np.interp
        out = np.stack([np.interp(z_arr, table[:, 0], table[:, k]) for k in (1, 2, 3)], axis=-1)
        return out


class SeaOptions(KanatModel):
    """What every kind of sea shares: how its kinematics reach the surface, and its ramp."""

    stretching: Literal["none", "wheeler"] = Field(
        "none", description="none: each point takes the linear kinematics at its own depth (those at "
                            "z = 0 above the mean surface); wheeler: those at z_s = h (z + h) / (h + eta) - h, "
                            "the column under the instantaneous surface eta stretched onto the one under "
                            "the mean surface (the surface's own above it), as MoorDyn's WaveKin 7")
    ramp: float = quantity(0.0, unit="s", ge=0,
                           description=RAMP_DESCRIPTION.format(what="the elevation, velocity and acceleration"))


class RegularWaves(SeaOptions):
    """Linear (Airy) regular waves."""

    type: Literal["regular"] = "regular"
    height: float = quantity(unit="m", gt=0, description="crest-to-trough height H")
    period: float = quantity(unit="s", gt=0)
    heading_deg: float = quantity(0.0, unit="deg",
                                  description="direction the waves travel to, from +x, "
                                              "counter-clockwise seen from above")


class JonswapWaves(SeaOptions):
    """Irregular waves from a JONSWAP spectrum with seeded random phases and frequencies (one drawn in
    each of 200 equal bins, so the sea never repeats: :func:`kanat.physics.waves.jonswap_sea`)."""

    type: Literal["jonswap"] = "jonswap"
    hs: float = quantity(unit="m", gt=0, description="significant wave height")
    tp: float = quantity(unit="s", gt=0, description="peak period")
    gamma: float = quantity(3.3, unit="-", ge=1, description="peak enhancement factor")
    heading_deg: float = quantity(0.0, unit="deg")
    seed: int = Field(0, ge=0, description="random seed of the phases and of the frequencies drawn in their bins "
                      "(numpy takes no negative seed)")


def _as_component(value: Any) -> Any:
    if not isinstance(value, (list, tuple)) or len(value) != 4:
        got = f"{len(value)} values" if isinstance(value, (list, tuple)) else repr(value)
        raise ValueError("each component must be 4 numbers [omega, amplitude, phase_deg, heading_deg] "
                         f"(got {got})")
    return tuple(value)


ComponentRow = Annotated[tuple[float, float, float, float], BeforeValidator(_as_component)]


class ComponentWaves(SeaOptions):
    """A sea given component by component: a sum of linear (Airy) waves.

    The elevation is ``eta = sum a cos(k (x cos b + y sin b) - omega t + phase)`` with ``k``
    from the finite-depth dispersion relation (:mod:`kanat.physics.waves`, eqs. 1-5); each
    row ``[omega, amplitude, phase_deg, heading_deg]`` is one component. ``kanat import``
    writes a MoorDyn file's wave files (``WaveKin`` 2, 3 and 7) in this form.

    Attributes
    ----------
    components : tuple of rows (omega, amplitude, phase_deg, heading_deg)
        Angular frequency [rad/s] (> 0), amplitude [m] (>= 0), phase [deg] and the direction
        the component travels to [deg], from +x, counter-clockwise seen from above.
    """

    type: Literal["components"] = Field(
        "components", description="components: a sum of linear waves given one by one (as kanat "
                                  "import writes a MoorDyn file's wave files)")
    components: tuple[ComponentRow, ...] = quantity(
        unit="rad/s, m, deg, deg",
        description="one row [omega, amplitude, phase_deg, heading_deg] per component: angular "
                    "frequency (> 0), amplitude (>= 0), phase and the direction it travels to (from +x, "
                    "counter-clockwise); eta = sum a cos(k (x cos b + y sin b) - omega t + phase)")

    @field_validator("components")
    @classmethod
    def _check_components(cls, rows: tuple[ComponentRow, ...]) -> tuple[ComponentRow, ...]:
        if not rows:
            raise ValueError("needs at least one row [omega, amplitude, phase_deg, heading_deg]")
        for index, (omega, amplitude, _, _) in enumerate(rows):
            if omega <= 0:
                raise ValueError(f"row {index}: omega {fmt(omega)} rad/s; each component's angular "
                                 "frequency must be > 0")
            if amplitude < 0:
                raise ValueError(f"row {index}: amplitude {fmt(amplitude)} m; amplitudes are >= 0 "
                                 "(a phase of 180 deg turns a component over)")
        if not any(row[1] > 0 for row in rows):
            raise ValueError("every amplitude is 0 (still water): remove environment.waves instead")
        return rows

    @property
    def heading_deg(self) -> float:
        """The heading [deg] of the component farthest from the x axis (the one the x-z plane
        checks look at); the common heading when all components share one."""
        return max((row[3] for row in self.components),
                   key=lambda h: abs(math.sin(math.radians(h))))


Waves = Annotated[Union[RegularWaves, JonswapWaves, ComponentWaves], Field(discriminator="type")]


MAX_SLOPE_DEG = 45.0
"""Steepest seabed slope accepted [deg]: beyond it a line does not rest on the seabed."""


class Seabed(KanatModel):
    """Contact of the lines with the seabed (``environment.seabed``; needs ``depth``).

    The seabed is the plane ``z = -depth + x tan(slope_deg)`` (:mod:`kanat.physics.seabed`
    holds its geometry). A line node below it feels a normal pressure ``stiffness *
    penetration + damping * penetration rate`` on its contact area ``diameter x length``,
    as MoorDyn's ``kbot`` and ``cbot``, and Coulomb friction along and across the line.
    """

    stiffness: float = quantity(
        3.0e6, unit="Pa/m", gt=0,
        description="normal pressure per metre of penetration on the contact area "
                    "(diameter x length), as MoorDyn's kbot")
    damping: float = quantity(
        3.0e5, unit="Pa s/m", ge=0,
        description="normal pressure per m/s of penetration rate on the contact area, "
                    "as MoorDyn's cbot")
    friction: float = quantity(
        0.0, unit="-", ge=0,
        description="Coulomb friction coefficient along the line (MoorPy's CB): friction "
                    "force per unit normal contact force")
    lateral_friction: float = quantity(
        0.0, unit="-", ge=0,
        description="Coulomb friction coefficient across the line")
    slope_deg: float = quantity(
        0.0, unit="deg", ge=-MAX_SLOPE_DEG, le=MAX_SLOPE_DEG,
        description="slope of the seabed plane, rising towards +x: z = -depth + x tan(slope)")


class Environment(KanatModel):
    """Water properties, seabed, current and waves."""

    water_density: float = quantity(1025.0, unit="kg/m^3", gt=0)
    gravity: float = quantity(9.81, unit="m/s^2", gt=0)
    depth: float | None = quantity(None, unit="m", gt=0,
                                   description="seabed at z = -depth; None: no seabed")
    seabed: Seabed | None = Field(
        None, description="contact of the lines with the seabed (stiffness, damping, friction, "
                          "slope); needs depth. None: the models' own treatment of the "
                          "seabed at z = -depth (see kanat.model.support)")
    current: Current = Field(default_factory=Current)
    waves: Waves | None = Field(
        None, description="regular (Airy) waves, irregular (JONSWAP) waves, or a sea given component "
                          "by component; none: still water")

    def at_start(self) -> Environment:
        """The environment at t = 0, where initial states are found: without the current when it is
        ramped up (its ramp is 0 at the start), else this one."""
        if self.current.ramp == 0.0:
            return self
        return self.model_copy(update={"current": Current(ramp=self.current.ramp)})

    def with_seabed_contact(self) -> Environment:
        """The environment with the seabed contact every model applies: ``seabed`` as given, or a
        :class:`Seabed` of its documented defaults (stiffness 3e6 Pa/m, damping 3e5 Pa s/m, no
        friction, flat) when only ``depth`` is given, as the continuum model takes it
        (:func:`kanat.continuum.grid.seabed_contact`); this one without ``depth``. (Statics keeps a rigid
        seabed at ``-depth`` without the block: its exact contact.)"""
        if self.depth is None or self.seabed is not None:
            return self
        return self.model_copy(update={"seabed": Seabed()})

    @field_validator("seabed")
    @classmethod
    def _seabed_needs_depth(cls, seabed: Seabed | None, info: ValidationInfo) -> Seabed | None:
        if seabed is not None and info.data.get("depth", 0) is None:
            raise ValueError("a seabed needs environment.depth [m] (the seabed is at "
                             "z = -depth at x = 0)")
        return seabed
