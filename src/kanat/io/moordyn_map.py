"""MoorDyn rows as typed records and kanat keys (the conventions are in :mod:`kanat.io.moordyn`,
which assembles the case from the functions here)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path as FilePath

from ..errors import Problem
from ..model.paths import Path
from .moordyn_text import MoorDynText, Row

ANGLE_TOL = 1e-12

DEFAULTS = {"g": 9.80665, "rho": 1025.0, "kbot": 3.0e6, "cbot": 3.0e5}
"""MoorDyn-C v2's defaults of the options kanat maps."""
OPTION_KEYS = {
    "wtrdpth": "depth", "depth": "depth", "waterdepth": "depth",
    "rho": "rho", "rhow": "rho", "wtrdnsty": "rho", "wtrdens": "rho",
    "g": "g", "gravity": "g",
    "kbot": "kbot", "kb": "kbot", "cbot": "cbot", "cb": "cbot",
    "frictioncoefficient": "friction", "mu_ka": "friction_axial", "mu_kt": "friction_lateral",
    "dtm": "dt", "tmax": "duration", "dtout": "output_dt",
    "wavekin": "wave_kin", "dtwave": "dt_wave", "currents": "currents",
}
"""MoorDyn option names (lower case) -> what the importer maps them to."""
SETTINGS = frozenset({
    "writelog", "echo", "dtic", "tmaxic", "cdscaleic", "threshic", "icdfac", "icthresh",
    "ictmax", "icgendynamic", "disableoutput", "disableouttime", "writeunits", "tscheme", "cfl",
    "fricdamp", "statdynfricscale", "cv", "mc", "inertialf", "inertialf_rampt", "outswitch",
    "unifycurrentgrid", "wavekin_rampt", "numturbines"})
"""MoorDyn solver settings without a kanat counterpart: imported as warnings."""
REFUSED = {"waterkin": ("MoorDyn-F's water kinematics input file", "give waves and current in the kanat case instead"),
           "seafloorfile": ("a bathymetry file", "kanat's seabed is a plane: give environment.depth and "
                            "environment.seabed.slope_deg (rising towards +x) in the kanat case instead")}
"""MoorDyn options kanat cannot express when they are switched on, and what to give instead (``WaveKin``
and ``Currents``: :mod:`kanat.io.moordyn_waves`)."""
LINE_TYPE_COLUMNS = {1: ("Diam", "MassDen", "EA", "BA", "Can", "Cat", "Cdn", "Cdt"),
                     2: ("Diam", "MassDen", "EA", "BA", "EI", "Cd", "Ca", "CdAx", "CaAx")}


@dataclass
class Imported:
    """A MoorDyn file as case data.

    Attributes
    ----------
    data : dict
        The case in YAML keys (None when the file could not be mapped).
    lines : dict of Path to int
        MoorDyn line of each key path (for validation messages).
    problems : list of Problem
        Errors (the file cannot be imported) and warnings (settings not imported).
    version : int
        1 or 2.
    """

    data: dict | None
    lines: dict[Path, int] = field(default_factory=dict)
    problems: list[Problem] = field(default_factory=list)
    version: int = 2


@dataclass
class _Point:
    number: int
    kind: str                       # fixed | vessel | free | body
    xyz: tuple[float, float, float]
    line: int
    mass: float = 0.0
    volume: float = 0.0
    drag_area: float = 0.0
    ca: float = 0.0
    force: tuple[float, float, float] = (0.0, 0.0, 0.0)
    body: int | None = None


@dataclass
class _Body:
    number: int
    kind: str                       # free | coupled | fixed
    xyz: tuple[float, float, float]
    angles_deg: tuple[float, float, float]
    line: int
    data: dict = field(default_factory=dict)


class Reader:
    """Turns the rows of one file into case data, collecting problems."""

    def __init__(self, text: MoorDynText, file: str | None, base: FilePath):
        self.text, self.file, self.base = text, file, base
        self.problems: list[Problem] = []
        self.lines: dict[Path, int] = {(): 1}
        self.options: dict[str, float] = {}
        self.option_lines: dict[str, int] = {}
        self.version = 2
        self.refused: set[int] = set()     # point IDs already reported as errors

    # -- problems and numbers ---------------------------------------------------------------
    def error(self, line: int | None, where: str, message: str) -> None:
        self.problems.append(Problem(where, message, self.file, line, "error"))

    def warn(self, line: int | None, where: str, message: str) -> None:
        self.problems.append(Problem(where, message, self.file, line, "warning"))

    def number(self, row: Row, index: int, where: str, column: str) -> float:
        text = row.values[index]
        try:
            value = float(text)
        except ValueError:
            self.error(row.line, f"{where}.{column}", f"'{text}' is not a number"
                       + (" (kanat imports plain numbers: not a table file or a '|' list)"
                          if column in ("EA", "BA", "EI") else ""))
            return math.nan
        if not math.isfinite(value):
            self.error(row.line, f"{where}.{column}", f"'{text}' is not a finite number")
        return value

    def bar_list(self, row: Row, index: int, where: str, column: str) -> list[float]:
        values = []
        for part in row.values[index].split("|"):
            try:
                values.append(float(part))
            except ValueError:
                self.error(row.line, f"{where}.{column}", f"'{row.values[index]}' is not a number "
                           "or a list of numbers separated by '|'")
                return [math.nan]
        return values

    def rows(self, section: str, label: str, widths: tuple[int, ...]) -> list[Row]:
        """The section's rows that have one of the expected numbers of values."""
        good = []
        for row in self.text.sections.get(section, []):
            if len(row.values) in widths:
                good.append(row)
            else:
                expected = " or ".join(str(w) for w in widths)
                self.error(row.line, label, f"{len(row.values)} values on this row of {label}; "
                           f"MoorDyn v{self.version} has {expected} columns here")
        return good

    @property
    def rho(self) -> float:
        return self.options.get("rho", DEFAULTS["rho"])

    @property
    def g(self) -> float:
        return self.options.get("g", DEFAULTS["g"])


def _ids(reader: Reader, row: Row, label: str) -> int | None:
    try:
        number = int(row.values[0])
    except ValueError:
        reader.error(row.line, label, f"'{row.values[0]}' is not an ID number")
        return None
    return number


def file_version(reader: Reader) -> int:
    """1 when the line types have MoorDyn v1's 9 columns (Can Cat Cdn Cdt), else 2."""
    rows = reader.text.sections["line_types"]
    return 1 if rows and all(len(r.values) == 9 for r in rows) else 2


def read_options(reader: Reader) -> None:
    """The OPTIONS rows (``value key``): mapped options into ``reader.options``; warnings
    for settings kanat has no counterpart for; errors for inputs it cannot express."""
    for row in reader.text.sections.get("options", []):
        if len(row.values) < 2:
            reader.warn(row.line, "OPTIONS", f"'{row.values[0]}' has no option name after it; "
                        "not imported")
            continue
        value, key = row.values[0], row.values[1]
        low, where = key.lower(), f"OPTIONS.{key}"
        if low in OPTION_KEYS:
            mapped = OPTION_KEYS[low]
            if mapped == "depth" and not _is_number(value):
                reader.error(row.line, where, f"'{value}': a bathymetry file cannot be imported "
                             "(kanat's seabed is a plane: depth and slope_deg)")
                continue
            reader.options[mapped] = reader.number(row, 0, "OPTIONS", key)
            reader.option_lines[mapped] = row.line
        elif low in REFUSED:
            if value.strip("\"'").lower() not in ("", "0", "0.0", "none"):
                what, instead = REFUSED[low]
                reader.error(row.line, where, f"{key} = {value}: {what} cannot be imported; {instead}")
        elif low == "tmaxic" and _is_number(value) and float(value) < 1.0:
            reader.warn(row.line, where, f"{key} = {value}: MoorDyn starts from the file's layout, all but "
                        "unsettled; kanat starts from the equilibrium unless the case says "
                        "simulation.initial_state: as_given (the layout at rest); not imported")
        elif low in SETTINGS:
            reader.warn(row.line, where, f"{key} = {value} is a MoorDyn solver setting without "
                        "a kanat counterpart; not imported")
        else:
            reader.warn(row.line, where, f"unknown MoorDyn option '{key}'; not imported")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def read_line_types(reader: Reader) -> dict[str, tuple[dict, float | None, int]]:
    """Line types by name: (kanat keys, damping ratio when BA < 0, MoorDyn line)."""
    columns = LINE_TYPE_COLUMNS[reader.version]
    widths = (9,) if reader.version == 1 else (10, 11, 12, 13)
    rho, out = reader.rho, {}
    for row in reader.rows("line_types", "LINE TYPES", widths):
        name, where = row.values[0], f"LINE TYPES {row.values[0]}"
        row = _static_parts(reader, row, columns, where)
        v = {c: reader.number(row, i + 1, where, c) for i, c in enumerate(columns)}
        if reader.version == 1:
            v.update(Cd=v.pop("Cdn"), Ca=v.pop("Can"), CdAx=v.pop("Cdt"), CaAx=v.pop("Cat"), EI=0.0)
        lift = [reader.number(row, i, where, "Cl") for i in range(10, len(row.values))][:1]
        if lift and lift[0]:
            reader.error(row.line, f"{where}.Cl", f"Cl = {lift[0]:g}: vortex-induced vibration "
                         "is not modelled by kanat; set Cl to 0 to import the line type")
        if name in out:
            reader.error(row.line, where, f"line type '{name}' is defined twice")
        area = math.pi * v["Diam"] ** 2 / 4.0
        data = {"diameter": v["Diam"], "mass": v["MassDen"], "axial_stiffness": v["EA"],
                "drag_normal": v["Cd"], "drag_tangential": v["CdAx"], "added_mass": v["Ca"] * rho * area}
        if v["CaAx"]:
            data["added_mass_tangential"] = v["CaAx"] * rho * area
        if v["BA"] >= 0:
            data["axial_damping"] = v["BA"]
        if v["EI"]:
            data["bending_stiffness"] = v["EI"]
        out[name] = (data, -v["BA"] if v["BA"] < 0 else None, row.line)
    return out


def _static_parts(reader: Reader, row: Row, columns: tuple, where: str) -> Row:
    """``row`` with the static part of MoorDyn's viscoelastic ``EA`` and ``BA`` (``static|dynamic``) in a
    statics case (no ``TMax``), as MoorPy's statics takes it, and a warning of what it left out; a
    dynamic run, whose lines would want the dynamic stiffness kanat's linear line has not, keeps them
    and refuses them (:meth:`Reader.number`)."""
    if "duration" in reader.options:
        return row
    values = list(row.values)
    for index, column in enumerate(columns, 1):
        text = values[index] if index < len(values) else ""
        if column in ("EA", "BA") and text.count("|") == 1:
            static, dynamic = text.split("|")
            values[index] = static
            reader.warn(row.line, f"{where}.{column}", f"'{text}': MoorDyn's viscoelastic {column}; statics "
                        f"takes the static part {static} (as MoorPy does) and leaves out the dynamic {dynamic}, "
                        "which a dynamic run would need and kanat's linear line has not")
    return Row(row.line, tuple(values))


def _expand(values: list[float], sizes: dict[int, object], reader: Reader, row: Row,
            where: str) -> list[float] | None:
    rule = sizes.get(len(values))
    if rule is None:
        reader.error(row.line, where, f"{len(values)} values; MoorDyn takes "
                     f"{' or '.join(str(k) for k in sizes)} here (separated by '|')")
        return None
    return rule(values)


CG_FORMS = {1: lambda v: [0.0, 0.0, v[0]], 3: list}
INERTIA_FORMS = {1: lambda v: v * 3, 3: list}
CDA_FORMS = {1: lambda v: v * 6, 2: lambda v: [v[0]] * 3 + [v[1]] * 3, 3: lambda v: v + v, 6: list}
CA_FORMS = {1: lambda v: v * 3 + [0.0] * 3, 3: lambda v: v + [0.0] * 3}
BODY_KINDS = {"free": "free", "fixed": "fixed", "fix": "fixed", "anchor": "fixed",
              "coupled": "coupled", "vessel": "coupled", "ves": "coupled", "cpld": "coupled"}


def read_bodies(reader: Reader) -> dict[int, _Body]:
    """The BODIES rows by ID; a free body's kanat keys in ``data`` (module conventions)."""
    out: dict[int, _Body] = {}
    rho, g = reader.rho, reader.g
    for row in reader.rows("bodies", "BODIES", (14,)):
        number = _ids(reader, row, "BODIES")
        kind = BODY_KINDS.get(row.values[1].lower())
        where = f"BODIES {row.values[0]}"
        if number is None:
            continue
        if kind is None:
            reader.error(row.line, f"{where}.Attachment", f"'{row.values[1]}' bodies cannot be "
                         "imported; kanat takes Free, Fixed and Coupled bodies")
            continue
        nums = [reader.number(row, i, where, c) for i, c in
                zip(range(2, 9), ("X0", "Y0", "Z0", "r0", "p0", "y0", "Mass"))]
        volume = reader.number(row, 11, where, "Volume")
        body = _Body(number, kind, tuple(nums[:3]), tuple(nums[3:6]), row.line)
        forms = [_expand(reader.bar_list(row, i, where, c), f, reader, row, f"{where}.{c}")
                 for i, c, f in ((9, "CG", CG_FORMS), (10, "I", INERTIA_FORMS),
                                 (12, "CdA", CDA_FORMS), (13, "Ca", CA_FORMS))]
        if kind == "free" and all(f is not None for f in forms):
            cg, inertia, cda, ca = forms
            mass = nums[6]
            body.data = {"dof": 6, "mass": mass, "net_buoyancy": (rho * volume - mass) * g,
                         "position": list(body.xyz), "orientation_deg": list(body.angles_deg),
                         "center_of_gravity": cg, "buoyancy_at": "cg", "inertia": inertia,
                         "drag_areas": cda, "added_mass_matrix": [rho * volume * c for c in ca]}
            if any(cg) and volume:
                reader.warn(row.line, f"{where}.CG", "the buoyancy acts at the CG, as MoorDyn-C applies it "
                            "(buoyancy_at: cg); MoorPy applies it at the reference point: for its "
                            "convention import the file to YAML and write buoyancy_at: reference")
        elif kind != "free" and (nums[6] or volume):
            reader.warn(row.line, where, f"a {kind} body's mass and volume have no effect (its "
                        "motion is prescribed, as in MoorDyn); not imported")
        if number in out:
            reader.error(row.line, where, f"body {number} is defined twice")
        out[number] = body
    return out


POINT_KINDS = {"fixed": "fixed", "fix": "fixed", "anchor": "fixed",
               "coupled": "vessel", "vessel": "vessel", "ves": "vessel", "cpld": "vessel",
               "free": "free", "connect": "free", "con": "free", "point": "free"}


def _point_kind(text: str) -> tuple[str | None, int | None]:
    low = text.lower()
    if low in POINT_KINDS:
        return POINT_KINDS[low], None
    if low.startswith("body") and low[4:].isdigit():
        return "body", int(low[4:])
    return None, None


def read_points(reader: Reader, bodies: dict[int, _Body]) -> dict[int, _Point]:
    """The POINTS rows by ID (v1: 12 columns with forces; v2: 9)."""
    v1 = reader.version == 1
    columns = (("X", "Y", "Z", "M", "V", "FX", "FY", "FZ", "CdA", "CA") if v1 else
               ("X", "Y", "Z", "Mass", "Volume", "CdA", "Ca"))
    out: dict[int, _Point] = {}
    widths = (12,) if v1 else (9,)
    for row in reader.text.sections.get("points", []):
        if len(row.values) not in widths and row.values[0].isdigit():
            reader.refused.add(int(row.values[0]))
    for row in reader.rows("points", "POINTS", widths):
        number = _ids(reader, row, "POINTS")
        where = f"POINTS {row.values[0]}"
        kind, body = _point_kind(row.values[1])
        if number is None:
            continue
        if kind is None or (kind == "body" and body not in bodies):
            reader.refused.add(number)
            reader.error(row.line, f"{where}.Attachment", f"there is no body {body} in BODIES"
                         if kind else f"'{row.values[1]}' points cannot be imported; kanat takes "
                         "Fixed, Vessel/Coupled, Free/Connect and BodyN")
            continue
        v = [reader.number(row, i + 2, where, c) for i, c in enumerate(columns)]
        force = tuple(v[5:8]) if v1 else (0.0, 0.0, 0.0)
        cda, ca = (v[8], v[9]) if v1 else (v[5], v[6])
        point = _Point(number, kind, tuple(v[:3]), row.line, v[3], v[4], cda, ca, force, body)
        if number in out:
            reader.error(row.line, where, f"point {number} is defined twice")
        out[number] = point
    return out


def rotation(angles_deg) -> list[list[float]]:
    """``Rz(yaw) Ry(pitch) Rx(roll)`` of angles in degrees (MoorDyn's body orientation)."""
    r, p, y = (math.radians(a) for a in angles_deg)
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def _placed(body: _Body, offset) -> list[float]:
    """Global position of a point at ``offset`` in a body's axes."""
    rot = rotation(body.angles_deg)
    return [body.xyz[i] + sum(rot[i][j] * offset[j] for j in range(3)) for i in range(3)]


def line_end(reader: Reader, point: _Point, bodies: dict[int, _Body]) -> tuple[object, list[float]]:
    """A line end at ``point``: the kanat end and its initial global position."""
    xyz = [float(c) for c in point.xyz]
    if point.kind == "fixed":
        return {"anchor": xyz}, xyz
    if point.kind == "vessel":
        return {"vessel": xyz}, xyz
    if point.kind == "free":
        return f"point{point.number}", xyz
    body = bodies[point.body]
    where = _placed(body, xyz)
    if body.kind == "free":
        return {"body": f"body{body.number}", "offset": xyz}, where
    return ({"vessel": where} if body.kind == "coupled" else {"anchor": where}), where


def attach_token(text: str) -> int | None:
    """The point number of a line's ``AttachA``/``AttachB`` (``3``, ``C3``, ``P3``, ...)."""
    low = text.lower()
    for prefix in ("point", "con", "p", "c", ""):
        if low.startswith(prefix) and low[len(prefix):].isdigit():
            return int(low[len(prefix):])
    return None


def line_rows(reader: Reader) -> list[tuple[Row, int, str, str, str, float, int]]:
    """``(row, id, type, attach A, attach B, length, segments)`` of every line."""
    out = []
    for row in reader.rows("lines", "LINES", (6, 7)):
        number = _ids(reader, row, "LINES")
        where = f"LINES {row.values[0]}"
        if number is None:
            continue
        if reader.version == 1:
            kind, length, segs, a, b = row.values[1], row.values[2], row.values[3], row.values[4], row.values[5]
        else:
            kind, a, b, length, segs = row.values[1], row.values[2], row.values[3], row.values[4], row.values[5]
        try:
            n = int(segs)
        except ValueError:
            reader.error(row.line, f"{where}.NumSegs", f"'{segs}' is not a whole number")
            continue
        index = 2 if reader.version == 1 else 4
        out.append((row, number, kind, a, b, reader.number(row, index, where, "UnstrLen"), n))
    return out
