"""Import MoorDyn input files (v1 and v2 text formats) as kanat cases.

:func:`read_moordyn` maps a MoorDyn file to case data (the YAML keys of
``docs/reference/case-format.md``) with the MoorDyn line of every item, so that validation reports
problems at the MoorDyn row. :func:`moordyn_document` is the hook
:mod:`kanat.io.case_file` uses (``kanat validate``, ``load_case`` and every verb accept a
MoorDyn file), :func:`kanat.io.case_file.import_moordyn` returns the validated :class:`~kanat.model.Case`,
and :func:`case_yaml` writes the data as a YAML case (``kanat import FILE -o case.yaml``).

Names follow MoorDyn's numbers: cables ``line1``, ``line2``, ...; free points ``point3``;
free bodies ``body1``; line types keep their names. MoorDyn's frame is kanat's (z up,
0 at the mean free surface, seabed at ``z = -WtrDpth``).

Conventions mapped (MoorDyn-C v2's Line, Point and Body; units SI):

* ``Diam`` is the volume-equivalent diameter, kanat's ``diameter`` (displacement and
  drag); ``MassDen`` [kg/m] is the mass in air, kanat's ``mass``. kanat's weight in water
  ``mass g - rho g pi d^2 / 4`` is MoorDyn's ``(MassDen - rho A) g`` with the file's
  ``rho`` and ``g`` (written to ``environment``), so ``weight_in_water`` is not set.
* ``EA`` [N] is ``axial_stiffness`` (a number; tables and viscoelastic forms are refused).
* ``BA`` [N s] is ``axial_damping`` (both Kelvin-Voigt: ``T = EA e + BA de/dt``). A
  negative ``BA`` is a damping ratio ``zeta = -BA`` of the segment's axial mode; MoorDyn
  converts it per line to ``BA = zeta (L / N) sqrt(EA MassDen)`` (segment length ``L / N``),
  and so does the importer. Lines of one type with different segment lengths then need
  different dampings: they get their own line type ``TYPE_lineK``.
* ``EI`` [N m^2] is ``bending_stiffness``.
* ``Cd``/``Cdn`` (normal drag on ``d``) is ``drag_normal``; ``CdAx``/``Cdt`` (tangential
  drag on ``pi d``: MoorDyn's ``0.5 rho Cdt pi d |v| v`` per length) is
  ``drag_tangential``, on the same area.
* ``Ca``/``Can`` and ``CaAx``/``Cat`` are coefficients of the displaced mass ``rho pi d^2
  / 4``: kanat's ``added_mass`` and ``added_mass_tangential`` [kg/m] are those products.
* Points: ``Fixed`` points are anchors (each line end its own ``anchor:[x, y, z]``),
  ``Vessel``/``Coupled`` points are vessel fairleads (``{vessel: [x, y, z]}``, the
  vessel at the origin at t = 0; all coupled points and bodies become fairleads of
  kanat's one vessel; statics and ``kanat.Coupling(..., rigid_vessel=True)`` read back which
  fairlead is on which ``Coupled`` body, :mod:`kanat.io.moordyn_coupled`, and treat each body as
  its own), free points (``Connect``/``Free``/``Point``)
  are kanat points: ``Mass`` -> ``mass``, ``Volume`` -> ``volume``, ``CdA`` -> ``drag_area``, ``Ca``
  -> ``added_mass = Ca rho V`` [kg]; v1's ``FX, FY, FZ`` [N, as MoorDyn documents them]
  -> ``force``. ``BodyN`` points are fairleads on body N.
* Bodies: a ``Free`` body is a kanat body with ``dof: 6``: ``net_buoyancy = (rho V -
  Mass) g``, buoyancy and weight at ``CG`` (as MoorDyn-C applies them: ``buoyancy_at: cg``,
  which the importer writes and states; MoorPy applies the buoyancy at the reference point,
  ``buoyancy_at: reference``), ``I`` (0 allowed in statics, as MoorPy writes it) ->
  ``inertia``, ``CdA`` -> ``drag_areas`` (1 value: all six; 2: translations, rotations;
  3: x, y, z for both; 6: as given -- as MoorDyn documents it; MoorDyn-C v2's reader
  (MoorDyn2.cpp) skips the first of 3 or 6 values), ``Ca`` -> ``added_mass_matrix = rho V diag(Ca)``
  (1 value: the three translations; 3 values: x, y, z). A ``Coupled`` body is the vessel
  (its points become vessel fairleads at ``position + R offset``, ``R = Rz(yaw) Ry(pitch)
  Rx(roll)`` of ``r0, p0, y0``, as MoorPy reads them; a run's vessel rotations turn about the
  vessel origin, while statics' stiffness and the coupling API take each body about its own
  reference point); a ``Fixed`` body's points become anchors there.
* Options: ``WtrDpth`` -> ``depth`` with a ``seabed`` block (``kBot`` -> ``stiffness``,
  ``cBot`` -> ``damping``, ``FrictionCoefficient`` -> both frictions, MoorDyn-F's
  ``MU_KA``/``MU_KT`` -> ``friction``/``lateral_friction``), ``rho``/``rhoW``/``WtrDnsty``
  -> ``water_density``, ``g``/``gravity`` -> ``gravity``, ``TMax`` ->
  ``duration`` (then ``model: lumped``, else ``model: statics``), ``dtOut`` -> ``output_dt``.
  ``dtM`` is MoorDyn's step for its own explicit scheme: reported, not imported, so a run of the
  file takes kanat's default scheme and step (an explicit-scale step given as ``simulation.dt``
  made the default scheme RK4 at 1 ms: 4 force evaluations a millisecond).
  Solver settings without a kanat counterpart (``dtIC``, ``TmaxIC``, ``tScheme``, ...) are
  reported as warnings, never dropped silently (a ``TmaxIC`` under 1 s, which leaves MoorDyn's
  start unsettled, with the key that starts kanat likewise: ``simulation.initial_state: as_given``);
  features kanat cannot express (rods, bathymetry files, failures) are errors, a ``SeafloorFile``
  with what a plane seabed takes instead (``depth``, ``seabed.slope_deg``). A viscoelastic line type's
  ``EA`` and ``BA`` (``static|dynamic``) give a statics case their static parts, as MoorPy's statics
  takes them, with a warning; a dynamic run refuses them (kanat's line is linear elastic).
* Water kinematics: ``WaveKin`` 2, 3 and 7 read MoorDyn's wave files beside the input file
  into ``environment.waves`` (``type: components``), ``Currents 1`` its current profile into
  ``environment.current.profile``; ``WaveKin 1`` (waves set through MoorDyn's API) and the
  other modes are errors (:mod:`kanat.io.moordyn_waves`).
"""
from __future__ import annotations

import math
from pathlib import Path as FilePath

import yaml

from .moordyn_map import (
    DEFAULTS,
    Imported,
    Reader,
    attach_token,
    read_bodies,
    line_end,
    line_rows,
    read_line_types,
    read_options,
    read_points,
    file_version,
)
from .moordyn_text import looks_like_moordyn, split
from .moordyn_waves import import_water
from .yaml_loader import YamlDocument

__all__ = ["Imported", "case_yaml", "looks_like_moordyn", "moordyn_document", "read_moordyn"]


def read_moordyn(text: str, file: str | None = None) -> Imported:
    """Map a MoorDyn input file to case data (module docstring); never raises for content.

    Parameters
    ----------
    text : str
        The file's text.
    file : str or None
        Its path: names problems, and is where relative names would be resolved.
    """
    base = FilePath(file).parent if file else FilePath(".")
    reader = Reader(split(text), file, base)
    data = map_moordyn(reader, FilePath(file).stem if file else "moordyn")
    if any(p.severity == "error" for p in reader.problems):
        data = None
    return Imported(data, reader.lines, reader.problems, reader.version)


def moordyn_document(text: str, file: str | None = None) -> YamlDocument:
    """A MoorDyn file as the :class:`YamlDocument` the case reader validates."""
    imported = read_moordyn(text, file)
    return YamlDocument(imported.data, imported.lines, imported.problems)


def case_yaml(imported: Imported, source: str) -> str:
    """The imported case as YAML text, headed by a comment naming its source and notes."""
    notes = [f"#   {p.key}: {p.message}" for p in imported.problems if p.severity == "warning"]
    head = [f"# Imported from {source} (MoorDyn v{imported.version}) by kanat import.",
            "# Names follow MoorDyn's numbers: cables lineN, points pointN, bodies bodyN.",
            "# Conventions: see kanat.io.moordyn."]
    if notes:
        head += ["# Not imported (MoorDyn settings without a kanat counterpart):", *notes]
    body = yaml.safe_dump(imported.data, sort_keys=False, default_flow_style=None, width=100,
                          allow_unicode=True)
    return "\n".join(head) + "\n" + body


UNSUPPORTED_SECTIONS = {"rods": "rods", "rod_types": "rod types", "failure": "line failures",
                        "control": "line control channels", "external_loads": "external loads",
                        "syrope": "Syrope initial conditions"}
"""MoorDyn sections kanat has no counterpart for: an error when they have rows."""
BA_RTOL = 1e-12
"""Relative difference of two lines' converted dampings that still share one line type."""


def map_moordyn(reader: Reader, name: str) -> dict | None:
    """Case data of a MoorDyn file (module docstring), or None when it has no lines."""
    sections = reader.text.sections
    for key, what in UNSUPPORTED_SECTIONS.items():     # first: a file of rods alone says so
        if sections.get(key):
            reader.error(sections[key][0].line, key.upper(), f"{what} cannot be imported (kanat "
                         "has no counterpart); remove the rows or model them otherwise")
    for needed, header in (("line_types", "LINE TYPES"), ("lines", "LINES")):
        if needed not in sections:
            reader.error(None, header, f"no '--- {header} ---' section: not a complete MoorDyn "
                         "input file")
    if any(problem.severity == "error" for problem in reader.problems):
        return None
    reader.version = file_version(reader)
    read_options(reader)
    if sections.get("outputs"):
        reader.warn(reader.text.headers["outputs"], "OUTPUTS", f"{len(sections['outputs'])} output "
                    "channel(s) not imported: kanat writes every node's position and tension")
    types = read_line_types(reader)
    bodies = read_bodies(reader)
    points = read_points(reader, bodies)
    cables = _cables(reader, types, points, bodies)
    data: dict = {"name": name, "model": "lumped" if "duration" in reader.options else "statics",
                  "environment": _environment(reader, _positions(points, bodies))}
    data["line_types"] = {k: v[0] for k, v in types.items()}
    for type_name, (_, _, line) in types.items():
        reader.lines[("line_types", type_name)] = line
    _split_dampings(reader, data, types, cables)
    used = {_key_of(e) for c in cables for e in (c["from"], c["to"])}
    _bodies_and_points(reader, data, bodies, points, used)
    data["cables"] = cables
    simulation = _simulation(reader)
    if simulation:
        data["simulation"] = simulation
    return data


def _positions(points, bodies) -> list[tuple[float, float, float]]:
    """Initial positions of the points and bodies (a body's points at the body: for extents)."""
    out = [p.xyz for p in points.values() if p.kind != "body"]
    return out + [b.xyz for b in bodies.values()]


def _environment(reader: Reader, positions) -> dict:
    opts, lines = reader.options, reader.option_lines
    env = {"water_density": reader.rho, "gravity": reader.g}
    env.update(import_water(reader, positions))
    for key, option in (("water_density", "rho"), ("gravity", "g"), ("depth", "depth")):
        if option in lines:
            reader.lines[("environment", key)] = lines[option]
    header = reader.text.headers.get("options")
    if header:
        reader.lines[("environment",)] = header
    if not opts.get("depth"):
        if any(k in opts for k in ("kbot", "cbot", "friction")):
            reader.warn(header, "OPTIONS", "no WtrDpth: imported without a seabed (kBot, cBot "
                        "and friction need one)")
        return env
    env["depth"] = opts["depth"]
    seabed = {"stiffness": opts.get("kbot", DEFAULTS["kbot"]),
              "damping": opts.get("cbot", DEFAULTS["cbot"])}
    friction = {"friction": opts.get("friction_axial", opts.get("friction")),
                "lateral_friction": opts.get("friction_lateral", opts.get("friction"))}
    seabed.update({k: v for k, v in friction.items() if v})
    env["seabed"] = seabed
    for key, option in (("stiffness", "kbot"), ("damping", "cbot"), ("friction", "friction_axial"),
                        ("lateral_friction", "friction_lateral")):
        line = lines.get(option, lines.get("friction") if "friction" in key else None)
        if line:
            reader.lines[("environment", "seabed", key)] = line
    return env


def _simulation(reader: Reader) -> dict:
    opts, lines = reader.options, reader.option_lines
    if "duration" not in opts:
        for key, option in (("dt", "dtM"), ("output_dt", "dtOut")):
            if key in opts:
                reader.warn(lines[key], f"OPTIONS.{option}", f"{option} without TMax: a statics "
                            "case (give TMax for a dynamic run); not imported")
        return {}
    sim = {"duration": opts["duration"]}
    if "dt" in opts:
        reader.warn(lines["dt"], "OPTIONS.dtM", f"MoorDyn's step for its own scheme ({opts['dt']:g} s) is "
                    "not imported: kanat chooses the scheme and step of a case that names none (docs/lumped.md, "
                    "'Default step of the implicit scheme'); give simulation.scheme and simulation.dt in a case "
                    "file to fix them")
    if opts.get("output_dt"):
        sim["output_dt"] = opts["output_dt"]
    for key in sim:
        reader.lines[("simulation", key)] = lines[key]
    reader.lines[("simulation",)] = reader.text.headers.get("options", 1)
    reader.lines[("model",)] = lines["duration"]
    return sim


def _cables(reader: Reader, types, points, bodies) -> list[dict]:
    cables = []
    for row, number, kind, token_a, token_b, length, segments in line_rows(reader):
        where = f"LINES {number}"
        if kind not in types:
            reader.error(row.line, f"{where}.LineType", f"'{kind}' is not in LINE TYPES; known: "
                         f"{', '.join(types) or 'none'}")
            continue
        ends = []
        for token, column in ((token_a, "AttachA"), (token_b, "AttachB")):
            point = attach_token(token)
            if point is None:
                reader.error(row.line, f"{where}.{column}", f"'{token}': rod ends cannot be imported"
                             if token[:1] in "Rr" else f"'{token}' is not a point number")
            elif point in reader.refused:
                pass                                   # the point's own row says why
            elif point not in points:
                reader.error(row.line, f"{where}.{column}", f"there is no point {point} in POINTS")
            else:
                ends.append(line_end(reader, points[point], bodies))
        if len(ends) != 2:
            continue
        if length < 0:
            chord = math.dist(ends[0][1], ends[1][1])
            reader.warn(row.line, f"{where}.UnstrLen", f"UnstrLen {length:g} is a multiple of the "
                        f"distance between the ends ({chord:.6g} m): imported as {-length * chord:.6g} m")
            length = -length * chord
        reader.lines[("cables", len(cables))] = row.line
        cables.append({"name": f"line{number}", "line_type": kind, "length": length,
                       "segments": segments, "from": ends[0][0], "to": ends[1][0]})
    return cables


def _split_dampings(reader: Reader, data: dict, types, cables: list[dict]) -> None:
    """Convert negative BA (a damping ratio) per line: ``BA = zeta (L/N) sqrt(EA MassDen)``."""
    for name, (keys, zeta, line) in types.items():
        if zeta is None:
            continue
        users = [c for c in cables if c["line_type"] == name]
        values = [zeta * c["length"] / c["segments"] * math.sqrt(keys["axial_stiffness"] * keys["mass"])
                  for c in users]
        if not values:
            reader.warn(line, f"LINE TYPES {name}.BA", "a damping ratio (negative BA) of a line type "
                        "no line uses: imported without damping")
            continue
        if max(values) - min(values) <= BA_RTOL * max(values):
            data["line_types"][name]["axial_damping"] = values[0]
            continue
        reader.warn(line, f"LINE TYPES {name}.BA", f"the damping ratio {zeta:g} gives each line its "
                    f"own BA (segments of different lengths): line types {name}_lineN")
        for cable, value in zip(users, values):
            own = f"{name}_{cable['name']}"
            data["line_types"][own] = {**data["line_types"][name], "axial_damping": value}
            reader.lines[("line_types", own)] = line
            cable["line_type"] = own


def _key_of(end) -> tuple[str, str] | None:
    if isinstance(end, str):
        return ("points", end)
    if isinstance(end, dict) and "offset" in end:
        return ("bodies", end["body"])
    return None


def _bodies_and_points(reader: Reader, data: dict, bodies, points, names) -> None:
    rho = reader.rho
    free_bodies = {f"body{n}": b for n, b in bodies.items() if b.kind == "free"}
    for name, body in free_bodies.items():
        if ("bodies", name) not in names:
            reader.warn(body.line, f"BODIES {body.number}", "no line is attached to this body; not "
                        "imported")
            continue
        data.setdefault("bodies", {})[name] = body.data
        reader.lines[("bodies", name)] = body.line
    for number, point in points.items():
        extras = (point.mass, point.volume, point.drag_area, point.ca, *point.force)
        where = f"POINTS {number}"
        if point.kind == "free":
            if ("points", f"point{number}") not in names:
                reader.warn(point.line, where, "no line is attached to this point; not imported")
                continue
            keys = {"position": list(point.xyz), "mass": point.mass, "volume": point.volume,
                    "drag_area": point.drag_area, "added_mass": point.ca * rho * point.volume,
                    "force": list(point.force)}
            data.setdefault("points", {})[f"point{number}"] = {
                k: v for k, v in keys.items() if k == "position" or (v and v != [0.0, 0.0, 0.0])}
            reader.lines[("points", f"point{number}")] = point.line
        elif point.kind == "body" and any(extras):
            reader.error(point.line, where, "a point on a body with mass, volume, drag or force "
                         "cannot be imported; add them to the body")
        elif any(extras):
            reader.warn(point.line, where, f"a {point.kind} point's mass, volume, drag and force "
                        "have no effect (its motion is prescribed, as in MoorDyn); not imported")
