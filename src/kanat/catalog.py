"""Line catalogue: mooring chain, wire rope and fibre rope properties from a nominal diameter.

``line_type("studless_chain", 0.076, grade="R3")`` gives the keys of a case's line type
(``diameter``, ``mass``, ``axial_stiffness``, ``breaking_load``, drag and added-mass
coefficients); a case asks for them with ``line_types.X.catalog``, ``grade`` and
``nominal_diameter``, and any key written beside them overrides the catalogue.

Formulas and their sources (``d`` the nominal diameter: the bar diameter of a chain link,
the rope diameter otherwise)
------------------------------------------------------------------------------------------
Chain, minimum breaking load (DNV-OS-E302 *Offshore mooring chain*, the MBL of grades R3 to
R5, the same for studless and studlink chain)::

    MBL = c d^2 (44 - 0.08 d)   [kN, d in mm]
    c = 0.0223 (R3), 0.0249 (R3S), 0.0274 (R4), 0.0304 (R4S), 0.0320 (R5)  [kN/mm^2]

  Cross-checked against MoorPy's published R4 coefficients (``MoorProps_default.yaml``:
  ``MBL_d2 = 1.21e9``, ``MBL_d3 = -2.19e9`` N with d in m, i.e. 0.0274 x 44e9 and
  0.0274 x 80e9 rounded) and against the grade factors of the public script
  ddjokic/Mooring-Line-Properties (``moorchain.py``).

Chain, axial stiffness (DNV-OS-E301 *Position mooring*, Ch.2 Sec.2, effective elastic
modulus on the nominal area of the link's two bars, ``A = 2 pi d^2 / 4``)::

    studless: E = (5.40 - 0.0040 d) 1e10 Pa (R3, R3S), (5.45 - 0.0025 d) 1e10 Pa (R4, R4S),
              (6.00 - 0.0033 d) 1e10 Pa (R5)          [d in mm]
    studlink: E = 5.6e10 Pa, all grades
    EA = E pi d^2 / 2

  The standard gives R3, R4 and R5; R3S takes R3's modulus and R4S takes R4's. MoorPy's
  ``EA_d2 = 8.56e10`` (studless R4) and ``8.80e10`` N/m^2 (studlink) are ``pi / 2`` times
  5.45e10 and 5.6e10.

Chain, mass and volume (Vryhof *Anchor manual* and Orcina's OrcaFlex chain data, as in
the retired ``getLineProps`` kept in MoorPy's ``MoorProps.py``): ``m = 19.9e3 d^2`` kg/m (studless), ``21.9e3 d^2``
(studlink), d in m; volume-equivalent diameter (steel of 7850 kg/m^3) ``1.80 d`` and
``1.89 d`` (MoorPy ``dvol_dnom``).

Chain, hydrodynamics: DNV-OS-E301 drag coefficients on the nominal diameter, 2.4 normal and
1.15 tangential (studless), 2.6 and 1.4 (studlink), divided by ``d_vol / d`` to act on the
volume-equivalent diameter (as MoorPy's ``Cd``, ``Cd_ax``); added-mass coefficients 1.0
normal and 0.5 tangential (Bureau Veritas NR 493, as MoorPy's ``Ca``, ``Ca_ax``).

Six-strand wire rope with a steel core (IWRC) (Orcina's OrcaFlex wire data, as in the
retired ``getLineProps`` of MoorPy's ``MoorProps.py``, 'Orcaflex-original', and ddjokic/Mooring-Line-Properties
``moorwire.py``): ``m = 3989.7 d^2`` kg/m, ``EA = 4.04e10 d^2`` N, ``MBL = 633.358e6 d^2`` N,
``d_vol = 0.80 d``; drag 1.2 normal on ``d_vol``, 0 tangential; added mass 1.0 (DNV-RP-C205
circular cylinder), 0 tangential.

Spiral-strand wire rope, sheathed (MoorPy ``MoorProps_default.yaml`` 'wire', a fit to two
makers' catalogues): ``m = 5293 d^2`` kg/m, ``EA = 97.1e9 d^2`` N, ``MBL = 1022e6 d^2`` N,
``d_vol = 1.18 d``; drag 1.2 normal on the nominal (sheath) diameter, divided by 1.18 (MoorPy's
``Cd = 1.021``); added mass as above.

Fibre ropes (MoorPy ``MoorProps_default.yaml``, fits to makers' catalogues; stiffness per
MBL from the published quasi-static and dynamic stiffness ranges): ``m = k_m d^2``,
``MBL = c2 d^2 + c3 d^3``, static ``EA = K_rs MBL``, dynamic ``EA_d = K_rd,a MBL + K_rd,b
T_mean`` (the mean tension ``T_mean`` in N, i.e. ``K_rd = K_rd,a + K_rd,b L_m`` with ``L_m``
the mean load as a fraction of MBL); volume-equivalent diameter from the fibre density
``d_vol = d sqrt(4 k_m / (pi rho_f))``; drag 1.6 on the nominal diameter (DNV-OS-E301 fibre
rope) divided by ``d_vol / d``; added mass 1.1 normal, 0.15 tangential (Bureau Veritas
NR 493)::

    polyester: k_m = 679,  c2 = 308e6, c3 = 0,     K_rs = 14, K_rd = 11.6 + 40 L_m, rho_f = 1380
    nylon:     k_m = 585,  c2 = 207e6, c3 = 230e6, K_rs = 5,  K_rd = 2.08 + 39 L_m, rho_f = 1140
    hmpe:      k_m = 496,  c2 = 580e6, c3 = 651e6, K_rs = 56, K_rd = 59 + 54 L_m,   rho_f = 975

A line type takes the static stiffness as ``axial_stiffness``; :func:`properties` gives the
dynamic one (:meth:`LineProperties.dynamic_axial_stiffness`) for an analysis that wants it.
Every formula holds over the diameters of the catalogues it comes from
(:data:`DIAMETER_RANGE`); outside them :func:`line_type` raises.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from kanat.errors import KanatError

CHAIN_GRADES = ("R3", "R3S", "R4", "R4S", "R5")
"""Offshore mooring chain grades (DNV-OS-E302)."""

CHAIN_MBL_FACTOR = {"R3": 0.0223, "R3S": 0.0249, "R4": 0.0274, "R4S": 0.0304, "R5": 0.0320}
"""``c`` in ``MBL = c d^2 (44 - 0.08 d)`` [kN, d in mm] per grade (DNV-OS-E302)."""

ORQ_MBL_FACTOR = 0.0211
"""``c`` of ORQ (oil rig quality) chain [kN/mm^2] in the same formula: the reference breaking
strength of API RP 2SK's chain T-N curves (the factor in MoorPy's ``MoorProps.py``,
``ORQ=2.11e4`` with d in m, and of ddjokic/Mooring-Line-Properties)."""

STUDLESS_MODULUS = {"R3": (5.40e10, 0.0040e10), "R3S": (5.40e10, 0.0040e10),
                    "R4": (5.45e10, 0.0025e10), "R4S": (5.45e10, 0.0025e10),
                    "R5": (6.00e10, 0.0033e10)}
"""``(a, b)`` in the studless chain's effective modulus ``E = a - b d`` [Pa, d in mm]
(DNV-OS-E301 Ch.2 Sec.2; R3S as R3, R4S as R4)."""

STUDLINK_MODULUS = 5.6e10
"""Effective modulus of studlink chain, all grades [Pa] (DNV-OS-E301 Ch.2 Sec.2)."""

SEAWATER_DENSITY = 1025.0
"""Water density [kg/m^3] for the added mass when the case gives none."""


@dataclass(frozen=True)
class Construction:
    """Coefficients of one kind of line (module docstring gives the sources).

    Attributes
    ----------
    name : str
        Catalogue name (``line_types.X.catalog``).
    description : str
    mass_per_d2 : float
        Mass per length per nominal diameter squared [kg/m^3].
    volume_diameter_ratio : float
        Volume-equivalent diameter per nominal diameter [-].
    mbl_d2, mbl_d3 : float
        Breaking load ``mbl_d2 d^2 + mbl_d3 d^3`` [N/m^2, N/m^3] (ropes; chains use the
        grade formula).
    ea_d2 : float
        Axial stiffness per diameter squared [N/m^2] (steel ropes).
    static_stiffness_per_mbl : float
        ``K_rs``, static axial stiffness per MBL [-] (fibre ropes).
    dynamic_stiffness_per_mbl, dynamic_stiffness_per_mean : float
        ``K_rd,a`` and ``K_rd,b`` of the dynamic stiffness ``K_rd,a MBL + K_rd,b T_mean`` [-]
        (fibre ropes).
    drag_normal_nominal, drag_tangential_nominal : float
        Drag coefficients on the nominal diameter [-].
    added_mass_normal, added_mass_tangential : float
        Added-mass coefficients of the displaced volume [-].
    """

    name: str
    description: str
    mass_per_d2: float
    volume_diameter_ratio: float
    drag_normal_nominal: float
    drag_tangential_nominal: float
    added_mass_normal: float
    added_mass_tangential: float
    mbl_d2: float = 0.0
    mbl_d3: float = 0.0
    ea_d2: float = 0.0
    static_stiffness_per_mbl: float = 0.0
    dynamic_stiffness_per_mbl: float = 0.0
    dynamic_stiffness_per_mean: float = 0.0

    @property
    def is_chain(self) -> bool:
        """True for chains (their MBL and EA depend on the grade)."""
        return self.name.endswith("_chain")

    @property
    def is_fibre(self) -> bool:
        """True for fibre ropes (a static and a dynamic stiffness)."""
        return self.static_stiffness_per_mbl > 0.0


def _fibre_volume_ratio(mass_per_d2: float, fibre_density: float) -> float:
    """``d_vol / d = sqrt(4 k_m / (pi rho_f))`` from the mass and the fibre's density."""
    return math.sqrt(4.0 * mass_per_d2 / (math.pi * fibre_density))


_POLYESTER_RATIO = _fibre_volume_ratio(679.0, 1380.0)
_NYLON_RATIO = _fibre_volume_ratio(585.0, 1140.0)
_HMPE_RATIO = _fibre_volume_ratio(496.0, 975.0)
FIBRE_DRAG = 1.6
"""Normal drag coefficient of fibre rope on its nominal diameter (DNV-OS-E301)."""

CATALOG: dict[str, Construction] = {c.name: c for c in (
    Construction("studless_chain", "studless mooring chain (grades R3-R5)", 19.9e3, 1.80,
                 2.4, 1.15, 1.0, 0.5),
    Construction("studlink_chain", "studlink mooring chain (grades R3-R5)", 21.9e3, 1.89,
                 2.6, 1.4, 1.0, 0.5),
    Construction("wire_six_strand", "six-strand wire rope, steel core (IWRC)", 3989.7, 0.80,
                 1.2 * 0.80, 0.0, 1.0, 0.0, mbl_d2=633.358e6, ea_d2=4.04e10),
    Construction("wire_spiral", "spiral-strand wire rope, sheathed", 5293.0, 1.18,
                 1.2, 0.0, 1.0, 0.0, mbl_d2=1022e6, ea_d2=97.1e9),
    Construction("polyester", "polyester fibre rope", 679.0, _POLYESTER_RATIO,
                 FIBRE_DRAG, 0.0, 1.1, 0.15, mbl_d2=308e6, static_stiffness_per_mbl=14.0,
                 dynamic_stiffness_per_mbl=11.6, dynamic_stiffness_per_mean=40.0),
    Construction("nylon", "nylon fibre rope", 585.0, _NYLON_RATIO,
                 FIBRE_DRAG, 0.0, 1.1, 0.15, mbl_d2=207e6, mbl_d3=230e6,
                 static_stiffness_per_mbl=5.0, dynamic_stiffness_per_mbl=2.08,
                 dynamic_stiffness_per_mean=39.0),
    Construction("hmpe", "high-modulus polyethylene (HMPE) fibre rope", 496.0, _HMPE_RATIO,
                 FIBRE_DRAG, 0.0, 1.1, 0.15, mbl_d2=580e6, mbl_d3=651e6,
                 static_stiffness_per_mbl=56.0, dynamic_stiffness_per_mbl=59.0,
                 dynamic_stiffness_per_mean=54.0),
)}
"""Every catalogue line by name, in the order ``kanat catalog`` lists them."""

DIAMETER_RANGE: dict[str, tuple[float, float]] = {
    "studless_chain": (0.019, 0.220), "studlink_chain": (0.019, 0.220),
    "wire_six_strand": (0.010, 0.160), "wire_spiral": (0.020, 0.180),
    "polyester": (0.040, 0.300), "nylon": (0.040, 0.300), "hmpe": (0.020, 0.300)}
"""Nominal diameters [m] each formula is used for: the sizes of the makers' catalogues and
standards' tables it comes from (chain 19-220 mm as DNV-OS-E302 and the chain makers'
catalogues; larger or smaller lines are extrapolations, e.g. the chain MBL falls past
366 mm)."""


class CatalogError(KanatError, ValueError):
    """A catalogue line that does not exist (name, grade or diameter)."""


def check(catalog: str, nominal_diameter: float | None = None, grade: str | None = None) -> Construction:
    """The construction of a catalogue line, after checking the name, grade and diameter.

    Parameters
    ----------
    catalog : str
        A name of :data:`CATALOG`.
    nominal_diameter : float or None
        [m]; None: not checked.
    grade : str or None
        Chain grade (:data:`CHAIN_GRADES`); required for chains, refused for ropes.

    Raises
    ------
    CatalogError
        Naming the key at fault (``catalog``, ``grade`` or ``nominal_diameter``).
    """
    construction = CATALOG.get(catalog)
    if construction is None:
        raise CatalogError(f"catalog: '{catalog}' is not in the catalogue; known: {', '.join(CATALOG)}")
    check_grade(construction, grade)
    if nominal_diameter is not None:
        check_diameter(construction, nominal_diameter)
    return construction


def check_grade(construction: Construction, grade: str | None) -> None:
    """Raise :class:`CatalogError` for a missing chain grade or a grade on a rope."""
    if construction.is_chain and grade is None:
        raise CatalogError(f"grade: a {construction.name} needs a grade: {' | '.join(CHAIN_GRADES)}")
    if construction.is_chain and grade not in CHAIN_MBL_FACTOR:
        raise CatalogError(f"grade: '{grade}' is not a chain grade; known: {', '.join(CHAIN_GRADES)}")
    if not construction.is_chain and grade is not None:
        raise CatalogError(f"grade: only chains have a grade ({construction.name} is a rope); "
                           f"remove 'grade'")


def check_diameter(construction: Construction, nominal_diameter: float) -> None:
    """Raise :class:`CatalogError` for a nominal diameter outside :data:`DIAMETER_RANGE`."""
    low, high = DIAMETER_RANGE[construction.name]
    if not low <= nominal_diameter <= high:
        raise CatalogError(f"nominal_diameter: {nominal_diameter:g} m is outside the range of the "
                           f"{construction.name} formulas, {low:g} to {high:g} m (the diameter is "
                           f"in metres: 76 mm is 0.076)")


def chain_breaking_load(nominal_diameter: float, grade: str) -> float:
    """Minimum breaking load of offshore mooring chain [N] (DNV-OS-E302).

    ``MBL = c d^2 (44 - 0.08 d)`` kN with ``d`` in mm and ``c`` from :data:`CHAIN_MBL_FACTOR`.

    Parameters
    ----------
    nominal_diameter : float
        Bar diameter [m].
    grade : str
        One of :data:`CHAIN_GRADES`.
    """
    return _chain_formula(nominal_diameter, CHAIN_MBL_FACTOR[grade])


def chain_reference_breaking_load(nominal_diameter: float) -> float:
    """Reference breaking strength of chain in API RP 2SK's T-N curves [N]: the MBL of ORQ
    chain of the same diameter, ``0.0211 d^2 (44 - 0.08 d)`` kN (d in mm), whatever the grade.

    Parameters
    ----------
    nominal_diameter : float
        Bar diameter [m].
    """
    return _chain_formula(nominal_diameter, ORQ_MBL_FACTOR)


def _chain_formula(nominal_diameter: float, factor: float) -> float:
    """``1000 c d^2 (44 - 0.08 d)`` N with d in mm."""
    d_mm = 1000.0 * nominal_diameter
    return 1000.0 * factor * d_mm**2 * (44.0 - 0.08 * d_mm)


def chain_axial_stiffness(nominal_diameter: float, grade: str, studlink: bool) -> float:
    """Axial stiffness of mooring chain ``EA = E pi d^2 / 2`` [N] (DNV-OS-E301 Ch.2 Sec.2).

    Parameters
    ----------
    nominal_diameter : float
        Bar diameter [m].
    grade : str
        One of :data:`CHAIN_GRADES`.
    studlink : bool
        Studlink (``E = 5.6e10`` Pa) or studless (``E = a - b d``, :data:`STUDLESS_MODULUS`).
    """
    if studlink:
        modulus = STUDLINK_MODULUS
    else:
        a, b = STUDLESS_MODULUS[grade]
        modulus = a - b * 1000.0 * nominal_diameter
    return modulus * math.pi * nominal_diameter**2 / 2.0


@dataclass(frozen=True)
class LineProperties:
    """Everything the catalogue knows of one line.

    Attributes
    ----------
    catalog, grade : str, str or None
    nominal_diameter : float
        [m].
    diameter : float
        Volume-equivalent (hydrodynamic) diameter [m].
    mass : float
        [kg/m] in air.
    breaking_load : float
        Minimum breaking load [N].
    axial_stiffness : float
        Static (quasi-static) axial stiffness EA [N].
    drag_normal, drag_tangential : float
        Drag coefficients on ``diameter`` (tangential on ``pi diameter``) [-].
    added_mass_coefficient, added_mass_tangential_coefficient : float
        Of the displaced mass ``rho pi diameter^2 / 4`` [-].
    dynamic_stiffness_per_mbl, dynamic_stiffness_per_mean : float
        ``K_rd,a``, ``K_rd,b`` (fibre ropes; 0 for steel).
    """

    catalog: str
    grade: str | None
    nominal_diameter: float
    diameter: float
    mass: float
    breaking_load: float
    axial_stiffness: float
    drag_normal: float
    drag_tangential: float
    added_mass_coefficient: float
    added_mass_tangential_coefficient: float
    dynamic_stiffness_per_mbl: float = 0.0
    dynamic_stiffness_per_mean: float = 0.0

    def dynamic_axial_stiffness(self, mean_tension: float = 0.0) -> float:
        """Dynamic axial stiffness ``K_rd,a MBL + K_rd,b T_mean`` [N] of a fibre rope
        (MoorPy's ``EAd`` and ``EAd_Lm``); a steel line's static stiffness.

        Parameters
        ----------
        mean_tension : float
            Mean tension of the rope [N].
        """
        if self.dynamic_stiffness_per_mbl == 0.0:
            return self.axial_stiffness
        return self.dynamic_stiffness_per_mbl * self.breaking_load + self.dynamic_stiffness_per_mean * mean_tension


def properties(catalog: str, nominal_diameter: float, grade: str | None = None) -> LineProperties:
    """All catalogue properties of a line (formulas and sources: module docstring).

    Parameters
    ----------
    catalog : str
        A name of :data:`CATALOG`.
    nominal_diameter : float
        Bar diameter of a chain, rope diameter otherwise [m].
    grade : str or None
        Chain grade; None for ropes.

    Raises
    ------
    CatalogError
        Unknown catalogue name, a grade missing (chain) or given (rope), a diameter out of
        :data:`DIAMETER_RANGE`.
    """
    c = check(catalog, nominal_diameter, grade)
    d = nominal_diameter
    if c.is_chain:
        breaking_load = chain_breaking_load(d, grade)
        stiffness = chain_axial_stiffness(d, grade, studlink=catalog == "studlink_chain")
    else:
        breaking_load = c.mbl_d2 * d**2 + c.mbl_d3 * d**3
        stiffness = c.ea_d2 * d**2 if not c.is_fibre else c.static_stiffness_per_mbl * breaking_load
    ratio = c.volume_diameter_ratio
    return LineProperties(
        catalog=catalog, grade=grade, nominal_diameter=d, diameter=ratio * d,
        mass=c.mass_per_d2 * d**2, breaking_load=breaking_load, axial_stiffness=stiffness,
        drag_normal=c.drag_normal_nominal / ratio, drag_tangential=c.drag_tangential_nominal / ratio,
        added_mass_coefficient=c.added_mass_normal,
        added_mass_tangential_coefficient=c.added_mass_tangential,
        dynamic_stiffness_per_mbl=c.dynamic_stiffness_per_mbl,
        dynamic_stiffness_per_mean=c.dynamic_stiffness_per_mean)


def line_type(catalog: str, nominal_diameter: float, grade: str | None = None,
              water_density: float = SEAWATER_DENSITY) -> dict[str, float]:
    """Line-type keys of a catalogue line, as a case's ``line_types`` entry takes them.

    Parameters
    ----------
    catalog : str
        ``studless_chain``, ``studlink_chain``, ``wire_six_strand``, ``wire_spiral``,
        ``polyester``, ``nylon`` or ``hmpe``.
    nominal_diameter : float
        Bar diameter of a chain, rope diameter otherwise [m].
    grade : str or None
        Chain grade ``R3``, ``R3S``, ``R4``, ``R4S`` or ``R5``; None for ropes.
    water_density : float
        [kg/m^3], for the added masses ``C_a rho pi d_vol^2 / 4``.

    Returns
    -------
    dict
        ``diameter`` (volume-equivalent) [m], ``mass`` [kg/m], ``axial_stiffness`` (static)
        [N], ``breaking_load`` [N], ``drag_normal``, ``drag_tangential`` [-],
        ``added_mass``, ``added_mass_tangential`` [kg/m].

    Examples
    --------
    >>> round(line_type("studless_chain", 0.076, grade="R3")["breaking_load"] / 1e6, 3)
    4.884
    """
    p = properties(catalog, nominal_diameter, grade)
    displaced = water_density * math.pi * p.diameter**2 / 4.0
    return {"diameter": p.diameter, "mass": p.mass, "axial_stiffness": p.axial_stiffness,
            "breaking_load": p.breaking_load, "drag_normal": p.drag_normal,
            "drag_tangential": p.drag_tangential,
            "added_mass": p.added_mass_coefficient * displaced,
            "added_mass_tangential": p.added_mass_tangential_coefficient * displaced}


def catalog_table() -> str:
    """The catalogue as text: one line per entry with its grades and diameter range."""
    rows = []
    for name, c in CATALOG.items():
        low, high = DIAMETER_RANGE[name]
        grades = " | ".join(CHAIN_GRADES) if c.is_chain else "-"
        stiffness = "static and dynamic EA" if c.is_fibre else "EA"
        rows.append(f"{name:<16} {c.description}; grade: {grades}; nominal_diameter "
                    f"{low:g} to {high:g} m; {stiffness}")
    return "\n".join(rows)


def line_type_text(catalog: str, nominal_diameter: float, grade: str | None = None,
                   water_density: float = SEAWATER_DENSITY) -> str:
    """A catalogue line as the lines of a case's ``line_types`` entry (YAML, with units)."""
    units = {"diameter": "m, volume-equivalent", "mass": "kg/m", "axial_stiffness": "N, static",
             "breaking_load": "N", "drag_normal": "-, on diameter",
             "drag_tangential": "-, on pi diameter", "added_mass": "kg/m",
             "added_mass_tangential": "kg/m"}
    keys = line_type(catalog, nominal_diameter, grade, water_density)
    lines = [f"catalog: {catalog}", *([f"grade: {grade}"] if grade else []),
             f"nominal_diameter: {nominal_diameter:g}  # m"]
    lines += [f"{key}: {value:.6g}  # {units[key]}" for key, value in keys.items()]
    p = properties(catalog, nominal_diameter, grade)
    if p.dynamic_stiffness_per_mbl:
        lines.append(f"# dynamic axial stiffness: {p.dynamic_axial_stiffness():.6g} N + "
                     f"{p.dynamic_stiffness_per_mean:g} x mean tension")
    return "\n".join(lines)
