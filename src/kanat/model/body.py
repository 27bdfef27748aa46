"""Bodies (case section ``bodies``): point bodies (3 degrees of freedom) and rigid bodies
with 6 degrees of freedom (``dof: 6``).

A 3-DOF body is a point: towed vehicle, buoy, depressor, otter board, clump. A 6-DOF body
is a rigid body with a reference point (its ``position``), body axes turned by
``orientation_deg`` (roll, pitch, yaw about the global x, y, z axes, applied in the order
yaw, pitch, roll: ``R = Rz(yaw) Ry(pitch) Rx(roll)``), a centre of gravity and a centre of
buoyancy in body axes, an inertia, hydrostatics, damping, added mass and drag per degree
of freedom (surge, sway, heave, roll, pitch, yaw, about the reference point). Lines attach
to it at fairleads given in body axes (a cable end ``{body: NAME, offset: [x, y, z]}``).

The 6x6 matrices may be written as 6 numbers (the diagonal) or 6 rows of 6; they are
stored as 6 rows. Units of a 6x6 matrix follow its blocks: translation-translation
(N/m, N s/m, kg), translation-rotation (N/rad, N, kg m ...), rotation-rotation
(N m/rad, N m s/rad, kg m^2).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import Field, model_validator

from ._base import ZERO3, KanatModel, Matrix3, Matrix6, Vector3, Vector6, fmt, quantity

if TYPE_CHECKING:                   # NumPy loads for 6-DOF bodies and the models' matrices, not to read a case
    import numpy as np

SYMMETRY_RTOL = 1e-9
"""Relative asymmetry tolerated in matrices that must be symmetric (inertia, added mass)."""

SIX_DOF_ONLY = ("inertia", "center_of_gravity", "center_of_buoyancy", "orientation_deg",
                "waterplane_area", "metacentric_heights", "hydrostatic_stiffness",
                "linear_damping", "quadratic_damping", "added_mass_matrix", "drag_areas")
"""Keys that describe a rigid body and need ``dof: 6``."""


class SurfaceBuoy(KanatModel):
    """Hydrostatics of a surface-piercing buoy (vertical cylinder, theory/lumped.md §4) at cable ends: in the
    lumped model, and in the continuum model at the cable's far end (never inside a cable).

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


def _symmetric(matrix, name: str) -> None:
    import numpy as np

    a = np.asarray(matrix, dtype=float)
    scale = max(float(np.max(np.abs(a))), 1e-300)
    if np.max(np.abs(a - a.T)) > SYMMETRY_RTOL * scale:
        raise ValueError(f"{name} must be symmetric (row i, column j equal to row j, column i)")


class Body(KanatModel):
    """A body: a point with 3 degrees of freedom (default) or a rigid body with 6.

    Attributes
    ----------
    mass : float
        [kg].
    net_buoyancy : float
        Buoyancy minus weight [N]; negative sinks.
    drag_area : float
        C_D S [m^2] (3-DOF bodies; 6-DOF bodies use ``drag_areas``).
    seabed_area : float
        Bearing area on the seabed [m^2] (3-DOF bodies): the contact pressure of
        :mod:`kanat.physics.contact` acts on it where the body's node is below the seabed.
    added_mass : float
        [kg] (3-DOF bodies; 6-DOF bodies use ``added_mass_matrix``).
    force : tuple of 3 float
        Constant external force in the global frame [N].
    spreading_force : float
        Otter-board force ``F0`` [N], horizontal, perpendicular to the vessel heading,
        positive to port (lumped model, theory/lumped.md §4).
    surface_buoy : SurfaceBuoy or None
        Waterplane hydrostatics of a surface buoy (lumped model, 3-DOF bodies).
    diameter : float or None
        Diameter of a spherical float [m] (3-DOF bodies): its buoyancy ``net_buoyancy + mass g``
        follows its immersion (:func:`kanat.physics.immersion.sphere_fraction`); None: constant.
    position : tuple of 3 float or None
        Initial position [m] (a guess for the equilibrium); the reference point of a
        6-DOF body.
    dof : {3, 6}
        Degrees of freedom.
    inertia, center_of_gravity, center_of_buoyancy, orientation_deg, waterplane_area,
    metacentric_heights, hydrostatic_stiffness, linear_damping, quadratic_damping,
    added_mass_matrix, drag_areas
        The rigid body (``dof: 6``); see the field descriptions and the module docstring.
    """

    mass: float = quantity(unit="kg", gt=0)
    net_buoyancy: float = quantity(unit="N")
    drag_area: float = quantity(0.0, unit="m^2", ge=0)
    added_mass: float = quantity(0.0, unit="kg", ge=0)
    force: Vector3 = quantity(ZERO3, unit="N")
    seabed_area: float = quantity(
        0.0, unit="m^2", ge=0,
        description="dof 3: the body's bearing area on the seabed, on which environment.seabed's contact "
                    "pressure (stiffness x penetration + damping) acts where the body reaches the seabed: a "
                    "sinker or an anchor dropped to the bottom (lumped model); 0: the body's node touches "
                    "the seabed only on its lines' contact area")
    spreading_force: float = quantity(
        0.0, unit="N", description="otter board force F0, horizontal and perpendicular to the "
                                   "vessel heading, positive to port (lumped model)")
    surface_buoy: SurfaceBuoy | None = Field(
        None, description="a buoy riding the wave surface on its waterplane, at cable ends, not as an "
                          "attachment (lumped model; continuum model: the cable's far end)")
    diameter: float | None = quantity(
        None, unit="m", gt=0,
        description="dof 3: diameter of a spherical float centred on its node, whose buoyancy (net_buoyancy + "
                    "mass * g) follows its immersion: the submerged cap's share of the sphere's volume, so a "
                    "float that reaches the surface floats there (continuum and lumped models, single-cable "
                    "statics); "
                    "none: the buoyancy is the same in and out of the water")
    position: Vector3 | None = quantity(
        None, unit="m", description="initial guess of the position for the network "
                                    "equilibrium (lumped model); None: guessed. For dof: 6, "
                                    "the reference point, about which the 6x6 matrices are given")
    dof: Literal[3, 6] = Field(
        3, description="degrees of freedom: 3, a point body; 6, a rigid body that also turns "
                       "(needs inertia)")
    inertia: Matrix3 | None = quantity(
        None, unit="kg m^2",
        description="dof 6: moments of inertia about the centre of gravity in body axes, "
                    "[Ixx, Iyy, Izz] or a symmetric 3x3 matrix; positive definite for a dynamic "
                    "run, zero allowed in statics")
    center_of_gravity: Vector3 = quantity(
        ZERO3, unit="m", description="dof 6: centre of gravity in body axes, from the "
                                     "reference point; the weight mass * g acts there")
    center_of_buoyancy: Vector3 = quantity(
        ZERO3, unit="m", description="dof 6: centre of buoyancy in body axes, from the "
                                     "reference point; the buoyancy net_buoyancy + mass * g "
                                     "acts there")
    buoyancy_at: Literal["cg", "reference"] | None = Field(
        None, description="dof 6: where the buoyancy acts, instead of center_of_buoyancy: cg, the centre "
                          "of gravity (MoorDyn-C's convention; the MoorDyn importer writes it), or "
                          "reference, the reference point (MoorPy's); none: at center_of_buoyancy")
    orientation_deg: Vector3 = quantity(
        ZERO3, unit="deg", description="dof 6: initial roll, pitch, yaw of the body axes "
                                       "about the global x, y, z axes (R = Rz(yaw) Ry(pitch) "
                                       "Rx(roll)); a guess for the equilibrium")
    waterplane_area: float | None = quantity(
        None, unit="m^2", gt=0,
        description="dof 6, surface-piercing: waterplane area A_w; heave stiffness rho g A_w "
                    "(give metacentric_heights with it)")
    metacentric_heights: tuple[float, float] | None = quantity(
        None, unit="m",
        description="dof 6, surface-piercing: [GM_roll, GM_pitch]; roll and pitch stiffness "
                    "(net_buoyancy + mass * g) * GM (give waterplane_area with it). GM holds the levers of "
                    "weight and buoyancy along the body's axis; their centres' offsets across it still "
                    "turn the body (a centre of gravity off the axis trims it)")
    hydrostatic_stiffness: Matrix6 | None = quantity(
        None, unit="N/m, N/rad, N m/rad",
        description="dof 6: hydrostatic restoring stiffness about the reference point, 6 "
                    "numbers (diagonal) or 6x6; instead of waterplane_area and "
                    "metacentric_heights. With roll and pitch restoring (C44 and C55: both or neither; "
                    "roll-pitch terms only with them) it holds the levers of weight and buoyancy along the "
                    "body's axis, as metacentric heights do; without (a heave spring, couplings), weight "
                    "and buoyancy turn the body at their centres. Every other term acts as given")
    linear_damping: Matrix6 | None = quantity(
        None, unit="N s/m, N m s/rad",
        description="dof 6: linear damping on the body velocity, force -B v, 6 numbers "
                    "(diagonal) or 6x6")
    quadratic_damping: Matrix6 | None = quantity(
        None, unit="N s^2/m^2, N m s^2/rad^2",
        description="dof 6: quadratic damping on the body velocity, force -B_q (|v| v) "
                    "per degree of freedom, 6 numbers (diagonal) or 6x6")
    added_mass_matrix: Matrix6 | None = quantity(
        None, unit="kg, kg m, kg m^2",
        description="dof 6: added mass and inertia about the reference point, 6 numbers "
                    "(diagonal) or a symmetric 6x6 (replaces added_mass)")
    drag_areas: Vector6 | None = quantity(
        None, unit="m^2, m^5",
        description="dof 6: drag per degree of freedom in the relative flow, force "
                    "0.5 rho C_D A |u| u: [C_D A] in surge, sway, heave [m^2] and roll, "
                    "pitch, yaw [m^5], in body axes (replaces drag_area)")

    @model_validator(mode="after")
    def _rigid_body(self) -> Body:
        if self.dof == 3:
            if self.diameter is not None and self.surface_buoy is not None:
                raise ValueError("give either diameter (a spherical float) or surface_buoy (a waterplane), not both")
            used = [k for k in (*SIX_DOF_ONLY, "buoyancy_at") if getattr(self, k) not in (None, ZERO3)]
            if used:
                verb = "is" if len(used) == 1 else "are"
                raise ValueError(f"{', '.join(used)} {verb} for rigid bodies: add dof: 6 "
                                 "(a 3-DOF body is a point)")
            return self
        if self.diameter is not None:
            raise ValueError("diameter (a spherical float) is for point bodies (dof: 3); a dof: 6 body takes "
                             "waterplane_area and metacentric_heights")
        if self.seabed_area > 0.0:
            raise ValueError("seabed_area is for point bodies (dof: 3); a dof: 6 body's seabed contact is not "
                             "modelled")
        self._check_rigid()
        if self.buoyancy_at is not None and tuple(self.center_of_buoyancy) != ZERO3:
            raise ValueError("give either buoyancy_at or center_of_buoyancy, not both")
        return self

    @property
    def buoyancy_point(self) -> tuple[float, float, float]:
        """Where the buoyancy acts, in body axes from the reference point [m]: the centre of gravity
        (``buoyancy_at: cg``), the reference point (``reference``), else ``center_of_buoyancy``."""
        if self.buoyancy_at == "cg":
            return tuple(self.center_of_gravity)
        if self.buoyancy_at == "reference":
            return ZERO3
        return tuple(self.center_of_buoyancy)

    @property
    def tilt_in_stiffness(self) -> bool:
        """True when the body's hydrostatics restore roll or pitch: ``metacentric_heights`` (a
        metacentric height, from the centre of gravity to the metacentre, holds the levers of weight
        and buoyancy along the body's vertical, whatever its value) or a ``hydrostatic_stiffness``
        with roll and pitch restoring ``C44``, ``C55`` (the one without the other, or roll-pitch terms
        without them, are refused: :meth:`_check_tilt_terms`). Both models then turn the body by the
        centres' offsets across its vertical only (:mod:`kanat.physics.hydrostatics` eq. 3); otherwise by the whole levers."""
        if self.metacentric_heights is not None:
            return True
        if self.hydrostatic_stiffness is None:
            return False
        C = self.hydrostatic_stiffness
        return C[3][3] != 0.0 or C[4][4] != 0.0       # both or neither (:meth:`_check_tilt_terms`)

    def _check_rigid(self) -> None:
        import numpy as np

        if self.inertia is None:
            raise ValueError("a dof: 6 body needs its inertia [Ixx, Iyy, Izz] (kg m^2) about "
                             "the centre of gravity")
        _symmetric(self.inertia, "inertia")
        low = float(np.min(np.linalg.eigvalsh(np.asarray(self.inertia))))
        if low < -SYMMETRY_RTOL * float(np.max(np.abs(self.inertia))):
            raise ValueError(f"inertia must not be negative (its smallest principal moment is "
                             f"{fmt(low)} kg m^2)")
        if self.drag_area or self.added_mass:
            raise ValueError("a dof: 6 body takes drag_areas (6 values) and added_mass_matrix "
                             "(6 or 6x6) instead of drag_area and added_mass")
        if self.surface_buoy is not None:
            raise ValueError("surface_buoy is for point bodies; a dof: 6 body takes "
                             "waterplane_area and metacentric_heights (or hydrostatic_stiffness)")
        pair = (self.waterplane_area is None, self.metacentric_heights is None)
        if pair[0] != pair[1]:
            raise ValueError("give waterplane_area (m^2) and metacentric_heights [GM_roll, "
                             "GM_pitch] (m) together")
        if not pair[0] and self.hydrostatic_stiffness is not None:
            raise ValueError("give either waterplane_area with metacentric_heights or "
                             "hydrostatic_stiffness, not both")
        if self.hydrostatic_stiffness is not None:
            self._check_tilt_terms()
        if self.added_mass_matrix is not None:
            _symmetric(self.added_mass_matrix, "added_mass_matrix")
        for key in ("linear_damping", "quadratic_damping"):
            matrix = getattr(self, key)
            if matrix is not None and min(np.diag(np.asarray(matrix))) < 0:
                raise ValueError(f"{key} must not be negative on its diagonal (it would feed "
                                 "energy into the body)")

    def _check_tilt_terms(self) -> None:
        """Refuse a ``hydrostatic_stiffness`` whose roll-pitch block kanat cannot read without guessing.

        Every term of ``C`` acts on the body (:mod:`kanat.physics.hydrostatics` eq. 1: heave-roll,
        sway-yaw, yaw couplings alike), but one switch reads the block ``C44, C45, C54, C55``: with tilt
        restoring there, ``C`` holds the levers of weight and buoyancy along the body's axis for roll and
        pitch together (eq. 3, as metacentric heights do); without, weight and buoyancy turn the body at
        their centres. A block restoring one axis only (``C44`` without ``C55`` or the reverse) would
        leave the other with neither the matrix's restoring nor the levers'; roll-pitch terms without
        ``C44`` and ``C55`` are no restoring of a tilt (a symmetric block with a zero diagonal has
        ``C45 = 0`` or is indefinite) and would drop the levers all the same.
        """
        C = self.hydrostatic_stiffness
        roll, pitch, cross = C[3][3], C[4][4], (C[3][4], C[4][3])
        if (roll != 0.0) != (pitch != 0.0):
            given, missing = ("C44 (roll)", "C55 (pitch)") if roll != 0.0 else ("C55 (pitch)", "C44 (roll)")
            value = fmt(roll if roll != 0.0 else pitch)
            raise ValueError(
                f"hydrostatic_stiffness gives {given} = {value} N m/rad but {missing} = 0: with roll or pitch "
                "restoring in the matrix kanat takes the levers of weight and buoyancy along the body's axis from "
                f"it for both axes, so {missing.split()[0]} would have no restoring at all; give {missing.split()[0]} "
                "too (B GM, the buoyancy times the metacentric height), or neither, and weight and buoyancy turn "
                "the body at their centres")
        if roll == 0.0 and any(cross):
            raise ValueError(
                f"hydrostatic_stiffness has roll-pitch terms (C45 = {fmt(cross[0])}, C54 = {fmt(cross[1])}) "
                "without roll and pitch restoring (C44 = C55 = 0): kanat cannot use them (they restore no tilt, "
                "and would take the levers of weight and buoyancy off the body); give C44 and C55 with them, "
                "or set them to 0")

    @property
    def has_inertia(self) -> bool:
        """True for a point body, and for a rigid body whose inertia is positive definite (Sylvester's
        leading minors): a dynamic run needs it to turn the body; statics does not (MoorPy writes
        ``I = 0`` in the MoorDyn files it makes)."""
        if self.dof == 3:
            return True
        a = self.inertia
        minors = (a[0][0], a[0][0] * a[1][1] - a[0][1] * a[1][0],
                  a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                  + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
        return all(m > 0 for m in minors)

    def submerged_weight(self) -> float:
        """Downward pull in still water, ``-net_buoyancy`` [N] (negative: it floats up)."""
        return -self.net_buoyancy

    def buoyancy(self, gravity: float) -> float:
        """Buoyancy force ``net_buoyancy + mass g`` [N] (the weight of the displaced water)."""
        return self.net_buoyancy + self.mass * gravity

    def rigid_body_mass_matrix(self) -> np.ndarray:
        """6x6 mass matrix about the reference point, in body axes [kg, kg m, kg m^2].

        ``M = [[m I, -m S(c)], [m S(c), I_c - m S(c) S(c)]]`` with ``c`` the centre of
        gravity and ``S(c) x = c x x`` (kinetic energy ``1/2 m |v + w x c|^2 + 1/2 w.I_c w``).
        A 3-DOF body: ``m`` on the translations, zeros elsewhere.
        """
        import numpy as np

        from kanat.physics.motion import skew

        m = self.mass
        out = np.zeros((6, 6))
        out[:3, :3] = m * np.eye(3)
        if self.dof == 3:
            return out
        s = skew(self.center_of_gravity)
        out[:3, 3:] = -m * s
        out[3:, :3] = m * s
        out[3:, 3:] = np.asarray(self.inertia, dtype=float) - m * s @ s
        return out

    def hydrostatic_stiffness_matrix(self, water_density: float, gravity: float) -> np.ndarray:
        """6x6 hydrostatic stiffness about the reference point [N/m, N m/rad].

        ``hydrostatic_stiffness`` as given; or, from the waterplane, ``C33 = rho g A_w``,
        ``C44 = B GM_roll``, ``C55 = B GM_pitch`` with ``B = net_buoyancy + mass g`` the
        buoyancy (small-angle hydrostatics of a wall-sided body); zero otherwise.
        """
        import numpy as np

        if self.hydrostatic_stiffness is not None:
            return np.asarray(self.hydrostatic_stiffness, dtype=float)
        out = np.zeros((6, 6))
        if self.waterplane_area is not None:
            buoyancy = self.buoyancy(gravity)
            out[2, 2] = water_density * gravity * self.waterplane_area
            out[3, 3] = buoyancy * self.metacentric_heights[0]
            out[4, 4] = buoyancy * self.metacentric_heights[1]
        return out
