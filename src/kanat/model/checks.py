"""Physical sanity checks of a validated case, with numbers and units.

Each check looks at one kind of mistake that a schema cannot see (a line heavier in
water than in air, an anchor under the seabed, a cable too short for its ends, a
time step that does not divide the output interval, ...) and reports it as an error
(the case cannot be run as written) or a warning (it can, but probably not as meant).

:func:`physical_checks` runs them all; :data:`CHECKS` lists them in order.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping

from ..errors import Problem
from ._base import fmt
from .cable import Cable, CableEnd
from .case import Case
from .environment import JonswapWaves, RegularWaves
from . import limits
from .paths import Path, key_path, line_of
from .run_cost import check_node_steps, run_cost
from .setup_checks import check_continuum_cable, check_lumped_network, check_scheme, check_sea, check_track
from .support import check_support
from .vessel import Heading, Turn

MAX_STRETCH = 0.20          # strain beyond which fixed ends are an error, not a warning
MAX_STATIC_STRAIN = 0.10    # static strain of a hanging system considered unphysical
BREAKING_STEEPNESS = 1 / 7  # Miche's limit of H / wavelength for regular waves
BREAKING_DEPTH_RATIO = 0.78 # depth-limited breaking, H / depth (McCowan)
RESONANCE_GAIN = 10.0       # dynamic amplification of a pitch harmonic worth a warning
DEEP_WATER_KH = 20.0        # k h beyond which tanh(k h) = 1 to 1e-17: deep water
TIME_TOL = 1e-6             # relative tolerance on "multiple of dt"


class Findings:
    """Collects problems with their key paths and lines."""

    def __init__(self, file: str | None, lines: Mapping[Path, int] | None,
                 max_output_bytes: float | str | None = None):
        self.file = file
        self.lines = lines
        self.max_output_bytes = max_output_bytes
        self.problems: list[Problem] = []

    def add(self, path: Path, message: str, severity: str) -> None:
        """Record one problem at ``path``."""
        self.problems.append(Problem(key_path(path), message, self.file,
                                     line_of(self.lines, path), severity))

    def error(self, path: Path, message: str) -> None:
        """Record an error at ``path``."""
        self.add(path, message, "error")

    def warning(self, path: Path, message: str) -> None:
        """Record a warning at ``path``."""
        self.add(path, message, "warning")


def _kn(force: float) -> str:
    return f"{force / 1e3:.4g} kN"


def _end_position(case: Case, end: CableEnd) -> tuple[float, float, float] | None:
    """Initial global position of a fixed end: an anchor, or a vessel point (its own ``offset``, else
    the tow point) at t = 0, moved by the prescribed motion's translation there (rotations left out)."""
    if end.kind == "anchor":
        return tuple(end.position)
    if end.kind == "vessel":  # vessel at the origin, heading 0: vessel axes = global axes
        point = end.offset if end.offset is not None else case.vessel.tow_point
        return tuple(float(p + q) for p, q in zip(point, _motion_at_start(case)))
    return None


def _motion_at_start(case: Case) -> tuple[float, float, float]:
    """Surge, sway and heave of ``vessel.motion`` at t = 0 [m] (zeros without one)."""
    block = case.vessel.motion
    if not block.is_used:                                    # (no arrays, nor NumPy, for a case without one)
        return (0.0, 0.0, 0.0)
    from ..physics.motion import compile_motion, motion_at

    return tuple(float(q) for q in motion_at(compile_motion(block, case.environment), 0.0)[0][:3])


def _line_weight(case: Case, cable: Cable) -> float:
    """Weight in water of the whole cable [N], section by section."""
    env = case.environment
    return sum(case.line_types[s.line_type].weight_in_water_value(env.water_density, env.gravity) * s.length
               for s in cable.sections)


def check_line_types(case: Case, out: Findings) -> None:
    """A line cannot weigh more in water than in air."""
    g = case.environment.gravity
    for name, line in case.line_types.items():
        in_air = line.mass * g
        if line.weight_in_water is not None and line.weight_in_water > in_air:
            out.error(("line_types", name, "weight_in_water"),
                      f"weight in water {fmt(line.weight_in_water)} N/m exceeds the weight in "
                      f"air {in_air:.4g} N/m (mass {fmt(line.mass)} kg/m × g {fmt(g)} m/s^2); "
                      "buoyancy cannot be negative")


def check_bodies(case: Case, out: Findings) -> None:
    """Net buoyancy cannot be below minus the weight in air (negative displacement)."""
    g = case.environment.gravity
    for name, body in case.bodies.items():
        weight = body.mass * g
        if body.net_buoyancy < -weight:
            out.error(("bodies", name, "net_buoyancy"),
                      f"net buoyancy {fmt(body.net_buoyancy)} N is below -(mass × g) = "
                      f"{-weight:.6g} N (mass {fmt(body.mass)} kg): that needs a negative "
                      "buoyancy; net_buoyancy is buoyancy minus weight")


def check_anchors(case: Case, out: Findings) -> None:
    """Anchors lie between the seabed (a sloped one where ``seabed.slope_deg``) and the free surface."""
    if not any(end.kind == "anchor" for cable in case.cables for end in cable.ends):
        return                                  # (the seabed model, NumPy and all, loads for anchors only)
    from ..physics.seabed import seabed_of

    depth = case.environment.depth
    seabed = seabed_of(case.environment)
    for i, cable in enumerate(case.cables):
        for key, end in (("from", cable.from_), ("to", cable.to)):
            if end.kind != "anchor":
                continue
            z = end.position[2]
            floor = None if seabed is None else float(seabed.height(end.position[0], end.position[1]))
            if floor is not None and z < floor - 1e-9 * depth:
                out.error(("cables", i, key),
                          f"anchor at z = {fmt(z)} m is below the seabed at z = {fmt(floor)} m "
                          f"(depth {fmt(depth)} m at x = 0)")
            elif z > 0:
                out.warning(("cables", i, key),
                            f"anchor at z = {fmt(z)} m is above the free surface z = 0")


def check_positions_above_seabed(case: Case, out: Findings) -> None:
    """A body's or a point's given position lies above the seabed (the solvers would start it
    inside the ground and fail later as an element "stretched by 1510 %")."""
    placed = [(("bodies", name, "position"), f"body '{name}'", body.position)
              for name, body in case.bodies.items() if body.position is not None]
    placed += [(("points", name, "position"), f"point '{name}'", getattr(point, "position", None))
               for name, point in case.points.items() if getattr(point, "position", None) is not None]
    if not placed or case.environment.depth is None:
        return
    from ..physics.seabed import seabed_of

    depth = case.environment.depth
    seabed = seabed_of(case.environment)
    for path, what, position in placed:
        floor = float(seabed.height(position[0], position[1]))
        if position[2] < floor - 1e-9 * depth:
            out.error(path, f"{what} at z = {fmt(position[2])} m is {fmt(floor - position[2])} m below the "
                      f"seabed at z = {fmt(floor)} m (depth {fmt(depth)} m): place it in the water, "
                      f"above z = {fmt(floor)} m, or deepen environment.depth")


def check_fixed_span(case: Case, out: Findings) -> None:
    """A cable between two fixed ends must be long enough to reach both."""
    for i, cable in enumerate(case.cables):
        a, b = (_end_position(case, end) for end in cable.ends)
        if a is None or b is None:
            continue
        span = math.dist(a, b)
        if span <= cable.length:
            continue
        line = case.line_types[cable.line_type]
        strain = span / cable.length - 1.0
        tension = line.axial_stiffness * strain
        message = (f"its fixed ends ({cable.from_}, {cable.to}) are {span:.6g} m apart but it is "
                   f"{fmt(cable.length)} m long: it must stretch {100 * strain:.3g} %, a tension "
                   f"of {_kn(tension)} (EA {_kn(line.axial_stiffness)} × strain {strain:.4g})")
        too_far = strain > MAX_STRETCH
        broken = line.breaking_load is not None and tension > line.breaking_load
        if broken:
            message += f", above the breaking load {_kn(line.breaking_load)}"
        if too_far:
            message += f"; more than {MAX_STRETCH:.0%} stretch is not a cable"
        (out.error if too_far or broken else out.warning)(("cables", i, "length"), message)


def _hanging_load(case: Case, cable: Cable, body_name: str) -> tuple[float, float, float]:
    """Body pull, cable weight and largest static tension of a body hanging on a cable [N]."""
    pull = case.bodies[body_name].submerged_weight()
    weight = _line_weight(case, cable)
    return pull, weight, max(abs(pull), abs(pull + weight))


def check_hanging_loads(case: Case, out: Findings) -> None:
    """A body on a cable from the vessel or an anchor must not break or overstretch it."""
    for i, cable in enumerate(case.cables):
        for body_end, other in ((cable.to, cable.from_), (cable.from_, cable.to)):
            if body_end.kind != "body" or not other.is_fixed:
                continue
            line = case.line_types[cable.line_type]
            pull, weight, tension = _hanging_load(case, cable, body_end.name)
            what = "submerged weight" if pull >= 0 else "net buoyancy"
            load = (f"body '{body_end.name}' ({what} {_kn(abs(pull))}) and the cable's weight "
                    f"in water {_kn(weight)} ({weight / cable.length:.4g} N/m × "
                    f"{fmt(cable.length)} m) give a static tension of up to {_kn(tension)}")
            if line.breaking_load is not None and tension > line.breaking_load:
                out.error(("cables", i), f"{load}, above the breaking load "
                          f"{_kn(line.breaking_load)} of line type '{cable.line_type}'")
            strain = tension / line.axial_stiffness
            if strain > MAX_STATIC_STRAIN:
                out.error(("cables", i), f"{load}: a static strain of {100 * strain:.3g} % "
                          f"(EA {_kn(line.axial_stiffness)}), more than "
                          f"{MAX_STATIC_STRAIN:.0%}; check axial_stiffness (N) and the loads")


def check_mooring_buoys(case: Case, out: Findings) -> None:
    """A buoy held only by anchored lines must lift their weight in water."""
    by_body: dict[str, list[Cable]] = {}
    for cable in case.cables:
        for name in dict.fromkeys(e.name for e in cable.ends if e.kind == "body"):
            by_body.setdefault(name, []).append(cable)
    for name, body in case.bodies.items():
        attached = by_body.get(name, [])
        if not attached or not all(any(e.kind == "anchor" for e in c.ends) for c in attached):
            continue
        weight = sum(_line_weight(case, c) for c in attached)
        if case.environment.seabed is not None:      # chain may rest on the seabed: only what must hang
            weight = sum(_hanging_at_least(case, c) for c in attached)
        lift = body.net_buoyancy
        buoy = body.surface_buoy
        if buoy is not None:                          # its hull, immersed to the deck, lifts this much more
            env = case.environment
            lift += env.water_density * env.gravity * buoy.waterplane_area * buoy.height
        if weight > 0 and lift < weight:
            names = ", ".join(f"'{c.name}'" for c in attached)
            hull = "" if buoy is None else f" and {lift - body.net_buoyancy:.6g} N more from its hull awash"
            out.warning(("bodies", name, "net_buoyancy"),
                        f"buoy '{name}' has net buoyancy {fmt(body.net_buoyancy)} N{hull}, less than "
                        f"the weight in water {weight:.6g} N of its mooring line(s) {names}: "
                        "it will sink")


def _hanging_at_least(case: Case, cable: Cable) -> float:
    """Weight in water of the least length of ``cable`` that must hang off the seabed [N]: the
    height of its body end above the anchor, in its lightest line type (the rest may rest on
    the seabed)."""
    env = case.environment
    anchors = [e.position[2] for e in cable.ends if e.kind == "anchor"]
    body = next((case.bodies[e.name] for e in cable.ends if e.kind == "body"), None)
    if not anchors or body is None or body.position is None:
        return 0.0
    lightest = min(case.line_types[s.line_type].weight_in_water_value(env.water_density, env.gravity)
                   for s in cable.sections)
    return max(lightest, 0.0) * min(max(body.position[2] - min(anchors), 0.0), cable.length)


def check_time_steps(case: Case, out: Findings) -> None:
    """dt fits in the duration and divides the output interval, which fits in the duration too."""
    sim = case.simulation
    if sim is None:
        return
    if sim.dt is None and case.model == "continuum":
        out.error(("simulation", "dt"), "the continuum model needs a time step dt [s] (e.g. 1.0 for a "
                  "1000 m tow; the lumped model is the one that can choose its own)")
        return
    if sim.dt is not None and sim.dt > sim.duration:
        out.error(("simulation", "dt"), f"dt {fmt(sim.dt)} s is longer than the duration "
                  f"{fmt(sim.duration)} s")
    elif sim.output_interval > sim.duration:
        given = "output_dt" if sim.output_dt is not None else "dt" if sim.dt is not None else None
        out.error(("simulation", given or "duration"),
                  f"the output interval ({fmt(sim.output_interval)} s"
                  f"{'' if given else ', the default when neither output_dt nor dt is given'}) is longer than "
                  f"the duration {fmt(sim.duration)} s: the run would take no step and store t = 0 alone; "
                  "give output_dt at most the duration")
    if sim.dt is None or sim.output_dt is None:
        return
    ratio = sim.output_dt / sim.dt
    steps = round(ratio)
    if steps < 1 or abs(ratio - steps) > TIME_TOL * max(1.0, ratio):
        low = max(1, math.floor(ratio))
        out.error(("simulation", "output_dt"),
                  f"output_dt {fmt(sim.output_dt)} s is not a multiple of dt {fmt(sim.dt)} s "
                  f"({ratio:.4g} steps); use e.g. {fmt(low * sim.dt)} s or "
                  f"{fmt((low + 1) * sim.dt)} s")


def check_element_length(case: Case, out: Findings) -> None:
    """Elements shorter than the cable diameter are pointless and stiff."""
    for i, cable in enumerate(case.cables):
        diameter = case.line_types[cable.line_type].diameter
        element = cable.length / cable.segments
        if element < diameter:
            out.warning(("cables", i, "segments"),
                        f"elements are {element:.3g} m long ({fmt(cable.length)} m / "
                        f"{cable.segments} segments), shorter than the diameter {fmt(diameter)} m "
                        f"of line type '{cable.line_type}'; use at most "
                        f"{max(1, math.floor(cable.length / diameter))} segments")


def wavelength(period: float, gravity: float, depth: float | None) -> float:
    """Linear-wave length [m] from ``omega^2 = g k tanh(k h)`` (deep water if no depth)."""
    omega = 2 * math.pi / period
    k = omega**2 / gravity
    if depth is not None and k * depth < DEEP_WATER_KH:
        k = k / math.sqrt(math.tanh(k * depth))  # good start in all depths
        for _ in range(50):
            f = gravity * k * math.tanh(k * depth) - omega**2
            df = gravity * (math.tanh(k * depth) + k * depth / math.cosh(k * depth) ** 2)
            step = f / df
            k -= step
            if abs(step) < 1e-12 * k:
                break
    return 2 * math.pi / k


def check_waves(case: Case, out: Findings) -> None:
    """Waves steeper than the breaking limit, or higher than the depth allows."""
    env = case.environment
    waves = env.waves
    if isinstance(waves, RegularWaves):
        height, period, keys = waves.height, waves.period, ("height", "period")
    elif isinstance(waves, JonswapWaves):
        height, period, keys = waves.hs, waves.tp, ("hs", "tp")
    elif waves is not None:        # components: the steepest one, as a regular wave of height 2a
        omega, amplitude = max(waves.components, key=lambda row: row[1] / wavelength(2 * math.pi / row[0],
                                                                                         env.gravity, env.depth))[:2]
        height, period, keys = 2 * amplitude, 2 * math.pi / omega, ("components", "period 2 pi/omega")
    else:
        return
    length = wavelength(period, env.gravity, env.depth)
    where = "deep water" if env.depth is None else f"depth {fmt(env.depth)} m"
    steepness = height / length
    if steepness > BREAKING_STEEPNESS:
        out.warning(("environment", "waves", keys[0]),
                    f"{keys[0]} {fmt(height)} m over the wavelength {length:.4g} m ({where}, "
                    f"{keys[1]} {fmt(period)} s) is a steepness of {steepness:.3g}, above the "
                    f"breaking limit 1/7 = {BREAKING_STEEPNESS:.3g}")
    if env.depth is not None and height > BREAKING_DEPTH_RATIO * env.depth:
        out.warning(("environment", "waves", keys[0]),
                    f"{keys[0]} {fmt(height)} m exceeds {BREAKING_DEPTH_RATIO} × depth = "
                    f"{BREAKING_DEPTH_RATIO * env.depth:.4g} m: such waves break in this depth")


def check_towing(case: Case, out: Findings) -> None:
    """A towed cable needs a vessel track (and a tow speed, for the statics)."""
    towed = [c.name for c in case.cables if any(e.kind == "vessel" and e.offset is None for e in c.ends)]
    if not towed:                  # none, or only fairleads of a moored vessel (they need no track)
        return
    if not case.vessel.track:
        moves = " but for its prescribed motion (vessel.motion)" if case.vessel.motion.is_used else ""
        out.warning(("vessel", "track"), f"cable '{towed[0]}' hangs from the vessel but the "
                    f"vessel has no track: the tow point stays at rest (speed 0 m/s){moves}")
    elif case.model == "statics" and case.vessel.initial_speed == 0:
        out.warning(("vessel", "track", 0), "the initial tow speed is 0 m/s: the statics will "
                    "hang the cable in still water; give the first segment a speed")


def _out_of_plane(case: Case) -> list[str]:
    """Features that leave the x-z plane."""
    found = [f"vessel.track[{i}] is a {s.kind}" for i, s in enumerate(case.vessel.track)
             if isinstance(s, (Turn, Heading))]
    found += [f"cables[{i}].{k} has y = {fmt(e.position[1])} m" for i, c in enumerate(case.cables)
              for k, e in (("from", c.from_), ("to", c.to))
              if e.kind == "anchor" and e.position[1] != 0]
    if case.vessel.tow_point[1] != 0:
        found.append(f"vessel.tow_point has y = {fmt(case.vessel.tow_point[1])} m")
    found += [f"bodies.{n}.force has y = {fmt(b.force[1])} N" for n, b in case.bodies.items()
              if b.force[1] != 0]
    current = case.environment.current
    rows = current.profile or ((0.0, *(current.velocity or (0.0, 0.0, 0.0))),)
    if any(r[2] != 0 for r in rows):
        found.append("the current has a y component")
    waves = case.environment.waves
    if waves is not None and abs(math.sin(math.radians(waves.heading_deg))) > 1e-9:
        found.append(f"the waves travel at heading {fmt(waves.heading_deg)} deg")
    return found


def check_dimensions(case: Case, out: Findings) -> None:
    """``dimensions: 2`` only when everything stays in the x-z plane."""
    if case.simulation is None or case.simulation.dimensions != 2:
        return
    found = _out_of_plane(case)
    if found:
        out.error(("simulation", "dimensions"), "dimensions: 2 models the x-z plane only, but "
                  + "; ".join(found) + "; use dimensions: 3 or auto")


def check_sphere(case: Case, out: Findings) -> None:
    """The sphere problem's groups must admit an equilibrium (the solver's own conditions).

    The line (``LoL`` cable lengths) and the cable (1) meet at the sphere, so the anchors
    must lie between ``|LoL - 1|`` and ``LoL + 1`` cable lengths apart; ``chi`` below 1;
    ``QkL`` and ``RkL`` not both zero.
    """
    sphere = case.sphere_two_cables
    if sphere is None:
        return
    if sphere.dimensionless is not None:
        groups = sphere.dimensionless
        where = ("sphere_two_cables", "dimensionless")
        _check_sphere_span(out, (*where, "x_C"), abs(groups.x_C), groups.LoL, 1.0,
                           f"|x_C| = {fmt(abs(groups.x_C))} cable lengths",
                           f"line (LoL = {fmt(groups.LoL)}) and the cable (1)", " cable lengths")
        if groups.chi >= 1:
            out.error((*where, "chi"), f"chi = C_0/C_90 = {fmt(groups.chi)} must be below 1 "
                      "(the tangential drag of a cable is a fraction of its normal drag)")
        if groups.QkL == 0 and groups.RkL == 0:
            out.error((*where, "QkL"), "QkL and RkL are both 0: the sphere has neither net "
                      "buoyancy nor drag, and its cable's tension no scale; give either")
    else:
        dims = sphere.dimensional
        _check_sphere_span(out, ("sphere_two_cables", "dimensional", "anchor_x"),
                           abs(dims.anchor_x), dims.line_length, dims.cable_length,
                           f"{fmt(abs(dims.anchor_x))} m", f"line ({fmt(dims.line_length)} m) "
                           f"and the cable ({fmt(dims.cable_length)} m)", " m")


def _check_sphere_span(out: Findings, path: Path, span: float, line: float, cable: float,
                       apart: str, lengths: str, unit: str) -> None:
    """The anchors ``span`` apart must be reached by ``line`` and ``cable`` meeting at A."""
    if span >= line + cable:
        out.error(path, f"the anchors are {apart} apart but the {lengths} reach only "
                  f"{fmt(line + cable)}{unit}: no equilibrium; bring the anchors closer than that")
    elif span <= abs(line - cable):
        out.error(path, f"the anchors are {apart} apart but the {lengths} differ by "
                  f"{fmt(abs(line - cable))}{unit}: they cannot meet at the sphere with both "
                  f"taut; set the anchors between {fmt(abs(line - cable))}{unit} and "
                  f"{fmt(line + cable)}{unit} apart")


def check_pitch(case: Case, out: Findings) -> None:
    """No harmonic of the wave frequency should sit on the pitch natural frequency.

    Applies to the ``pitch`` block of a pitch case and to ``vessel.pitch`` of a tow.
    """
    for where, pitch in ((("pitch",), case.pitch), (("vessel", "pitch"), case.vessel.pitch)):
        if pitch is not None:
            _check_one_pitch(where, pitch, out)


def _check_one_pitch(where: tuple, pitch, out: Findings) -> None:
    from .problems import RESONANCE_RTOL      # the solver's own guard

    key = "natural_frequency" if pitch.natural_frequency is not None else "restoring"
    omega, omega0, zeta = pitch.wave_frequency, pitch.omega0, pitch.damping_ratio
    n = range(1, pitch.harmonics + 1)
    denominator = [math.hypot(1 - (k * omega / omega0) ** 2, 2 * zeta * k * omega / omega0) for k in n]
    worst = min(range(len(denominator)), key=denominator.__getitem__)
    nearest = max(1, round(omega0 / omega))  # every harmonic counts, also beyond the truncation
    text = (f"harmonic n = {n[worst]} of the wave frequency ({n[worst]} × {omega:.4g} = "
            f"{n[worst] * omega:.4g} rad/s) ")
    if zeta == 0 and abs(nearest * omega - omega0) / omega0 <= RESONANCE_RTOL:  # the solver's test
        beyond = f" (beyond the {pitch.harmonics} harmonics computed)" if nearest > pitch.harmonics else ""
        out.error((*where, key), f"harmonic n = {nearest} of the wave frequency ({nearest} × {omega:.4g} = "
                  f"{nearest * omega:.4g} rad/s){beyond} is within {100 * RESONANCE_RTOL:g} % of the natural "
                  f"frequency {omega0:.4g} rad/s and there is no damping: the steady state is unbounded; "
                  f"change {key} or give damping_ratio > 0")
    elif 1 / denominator[worst] > RESONANCE_GAIN:
        out.warning((*where, key), text + f"is close to the natural frequency {omega0:.4g} "
                    f"rad/s: its response is amplified {1 / denominator[worst]:.3g} times")
    stabilizer = pitch.stabilizer
    if stabilizer.mode != "off" and stabilizer.max_moment == 0:
        out.warning((*where, "stabilizer", "max_moment"), f"stabilizer mode "
                    f"'{stabilizer.mode}' with max_moment 0 N m has no effect")


def check_attachments(case: Case, out: Findings) -> None:
    """Bodies and points that no cable uses are ignored."""
    if not case.cables:
        return
    used = {(e.kind, e.name) for c in case.cables for e in c.ends}
    used |= {("body", a.body) for c in case.cables for a in c.attachments}
    for group, kind, items in (("bodies", "body", case.bodies), ("points", "point", case.points)):
        for name in items:
            if (kind, name) not in used:
                out.warning((group, name), f"{kind} '{name}' is not attached to any cable and "
                            "is ignored")


def check_clamps(case: Case, out: Findings) -> None:
    """A clamped end (``cables[].end_a/end_b``) needs something that holds a direction (an anchor, the
    vessel or a dof 6 body) and bending stiffness at that end, without which it holds nothing."""
    for i, cable in enumerate(case.cables):
        for key, end, section in (("end_a", cable.from_, cable.sections[0]), ("end_b", cable.to, cable.sections[-1])):
            if not getattr(cable, key).clamped:
                continue
            rigid = end.kind == "body" and end.name in case.bodies and case.bodies[end.name].dof == 6
            if end.kind not in ("anchor", "vessel") and not rigid:
                what = "a free end" if end.kind == "free" else f"{end.kind} '{end.name}'"
                out.error(("cables", i, key, "clamped"), f"a clamped end needs something that holds a direction: "
                          f"an anchor, the vessel or a dof 6 body, not {what}; drop clamped (a pinned end)")
            elif section.line_type in case.line_types and case.line_types[section.line_type].bending_stiffness <= 0:
                out.warning(("cables", i, key, "clamped"), f"line type '{section.line_type}' has no "
                            "bending_stiffness, so the clamp holds nothing: the end bends freely")


def check_ignored_sections(case: Case, out: Findings) -> None:
    """Sections that the chosen model does not use."""
    if case.sphere_two_cables is not None and case.model != "statics":
        out.warning(("sphere_two_cables",), f"ignored by model '{case.model}' (it is solved "
                    "by model: statics)")
    if case.pitch is not None and case.model != "pitch":
        out.warning(("pitch",), f"ignored by model '{case.model}' (it is solved by model: "
                    "pitch; a vessel's own pitch goes in vessel.pitch)")
    if case.cables and case.model == "pitch":
        out.warning(("cables",), "ignored by model 'pitch'")


# --- limits: run first; the sanity checks below assume numbers in range -----------------

def check_magnitudes(case: Case, out: Findings) -> None:
    """Every number within the sane range of its unit (:data:`limits.UNIT_RANGES`)."""
    for q in limits.iter_quantities(case):
        sane = limits.unit_range(q.unit)
        unit = f" {q.unit}" if q.unit and q.unit != "-" else ""
        if abs(q.value) > sane.high:
            out.error(q.path, f"must be at most {sane.high:g}{unit} in magnitude (got "
                      f"{fmt(q.value)}{unit}; {sane.what})")
        elif q.positive and q.value < sane.low:
            out.error(q.path, f"must be at least {sane.low:g}{unit} (got {fmt(q.value)}{unit}, "
                      f"too small to compute with; {sane.what})")


def check_discretization(case: Case, out: Findings) -> None:
    """Segments per cable and in all (:data:`limits.MAX_SEGMENTS_PER_CABLE`, ``_TOTAL``)."""
    counts = [cable.segments for cable in case.cables]
    for i, n in enumerate(counts):
        if n > limits.MAX_SEGMENTS_PER_CABLE:
            out.error(("cables", i, "segments"), f"{n:,} segments is more than the limit of "
                      f"{limits.MAX_SEGMENTS_PER_CABLE:,} a cable (10 cm elements over 10 km; "
                      "the continuum model converges by 1000); use fewer segments")
    if sum(counts) > limits.MAX_SEGMENTS_TOTAL and max(counts) <= limits.MAX_SEGMENTS_PER_CABLE:
        out.error(("cables",), f"{sum(counts):,} segments in all cables is more than the limit "
                  f"of {limits.MAX_SEGMENTS_TOTAL:,} (about 1 kB of solver memory a node); "
                  "use fewer segments")
    sphere = case.sphere_two_cables
    if sphere is not None and sphere.n_nodes > limits.MAX_SEGMENTS_PER_CABLE + 1:
        out.error(("sphere_two_cables", "n_nodes"), f"{sphere.n_nodes:,} nodes is more than "
                  f"the limit of {limits.MAX_SEGMENTS_PER_CABLE + 1:,}; 101 (the default) "
                  "resolves the published profiles")


def _size(n_bytes: float) -> str:
    for unit, scale in (("TiB", 1024**4), ("GiB", 1024**3), ("MiB", 1024**2), ("kiB", 1024)):
        if n_bytes >= scale:
            return f"{n_bytes / scale:.3g} {unit}"
    return f"{n_bytes:.0f} bytes"


def check_run_size(case: Case, out: Findings) -> None:
    """Time steps, node-steps and the estimated result size of a dynamic run."""
    sim = case.simulation
    if sim is None or case.model not in ("continuum", "lumped"):
        return
    cost = run_cost(case)
    nodes = cost.nodes
    where = ("simulation", "dt") if sim.dt is not None else ("simulation", "duration")
    try:
        refused = check_node_steps(cost.steps, cost.nodes, cost.step, cost.why)
    except ValueError as exc:
        out.error(("simulation",), str(exc))
        return
    if refused:
        out.error(where, f"duration {fmt(sim.duration)} s is {refused}")
    try:
        limit = limits.max_output_bytes(out.max_output_bytes)
    except ValueError as exc:
        out.error(("simulation",), str(exc))
        return
    outputs = math.floor(sim.duration / sim.output_interval * (1 + TIME_TOL)) + 1
    per_output = (limits.OUTPUT_VALUES_PER_NODE * nodes + limits.OUTPUT_VALUES_PER_STEP
                  + limits.OUTPUT_VALUES_PER_BODY * len(case.bodies))
    size = 8.0 * outputs * per_output
    if size > limit:
        key = "output_dt" if sim.output_dt is not None else "duration"
        out.error(("simulation", key), f"the result would hold about {_size(size)} ({outputs:,} "
                  f"outputs x {nodes:,} nodes x {limits.OUTPUT_VALUES_PER_NODE} values x 8 bytes), "
                  f"more than the limit of {_size(limit)}; store less often (output_dt), shorten "
                  f"the duration or use fewer segments, or raise the limit "
                  f"(kanat --max-output 8G, {limits.OUTPUT_BYTES_ENV}=8G, or max_output_bytes=\"8G\" in Python)")


def check_run_length(case: Case, out: Findings) -> None:
    """A warning when a run's node-steps exceed :data:`limits.WARN_NODE_STEPS` (minutes to hours)."""
    cost = run_cost(case)
    if cost is None or cost.node_steps <= limits.WARN_NODE_STEPS:
        return
    where = ("simulation", "dt") if case.simulation.dt is not None else ("simulation", "duration")
    out.warning(where, f"a long run: {cost.steps:.3g} time steps of {cost.step:.3g} s ({cost.why}) x "
                f"{cost.nodes:,} nodes = {cost.node_steps:.3g} node-steps, at least "
                f"{cost.node_steps * limits.FASTEST_NODE_STEP_S / 60:.0f} minutes of computing "
                f"(the warning starts at {limits.WARN_NODE_STEPS:.3g}); a larger dt, an implicit "
                "scheme or fewer segments would shorten it")


def check_pitch_size(case: Case, out: Findings) -> None:
    """Harmonics and samples of the pitch problem's Fourier series."""
    for where, pitch in ((("pitch",), case.pitch), (("vessel", "pitch"), case.vessel.pitch)):
        if pitch is None:
            continue
        if pitch.harmonics > limits.MAX_HARMONICS:
            out.error((*where, "harmonics"), f"{pitch.harmonics:,} harmonics is more than the "
                      f"limit of {limits.MAX_HARMONICS:,}; 50 (the default) give the pitch to 1e-3")
        elif pitch.time_points > limits.MAX_TIME_POINTS:
            out.error((*where, "time_points"), f"{pitch.time_points:,} samples of the period is "
                      f"more than the limit of {limits.MAX_TIME_POINTS:,}")
        elif pitch.harmonics * pitch.time_points > limits.MAX_PITCH_SAMPLES:
            out.error((*where, "time_points"), f"harmonics x time_points = {pitch.harmonics:,} x "
                      f"{pitch.time_points:,} is more than the limit of "
                      f"{limits.MAX_PITCH_SAMPLES:,} values; use fewer of either")


LIMIT_CHECKS: tuple[Callable[[Case, Findings], None], ...] = (
    check_magnitudes, check_discretization, check_run_size, check_pitch_size,
)
"""Bounds on numbers and work (:mod:`kanat.model.limits`), in order: each assumes the
bounds of the ones before it, so the first that finds an error is the last to run, and the
sanity checks of :data:`CHECKS` (which assume numbers in range) are skipped."""


CHECKS: tuple[Callable[[Case, Findings], None], ...] = (
    check_line_types, check_bodies, check_anchors, check_positions_above_seabed, check_fixed_span, check_hanging_loads,
    check_mooring_buoys, check_time_steps, check_element_length, check_waves, check_towing,
    check_dimensions, check_sphere, check_pitch, check_attachments, check_clamps, check_ignored_sections,
    check_support, check_scheme, check_track, check_sea, check_continuum_cable, check_lumped_network,
    check_run_length,
)


def physical_checks(case: Case, file: str | None = None,
                    lines: Mapping[Path, int] | None = None,
                    max_output_bytes: float | str | None = None) -> list[Problem]:
    """Run every limit and sanity check on a validated case.

    Parameters
    ----------
    case : Case
        A case that passed validation.
    file : str or None
        Case file name for the problems.
    lines : mapping of key path to int, optional
        Lines of the case file's keys (:func:`kanat.io.yaml_loader.load_yaml`).
    max_output_bytes : float, str or None
        Largest estimated result of a dynamic run [bytes] (``"8G"`` works too); None:
        the environment variable ``KANAT_MAX_OUTPUT_BYTES``, else 2 GiB
        (:func:`kanat.model.limits.max_output_bytes`).

    Returns
    -------
    list of Problem
        Errors and warnings, in the order of :data:`LIMIT_CHECKS` then :data:`CHECKS`;
        only the first failing limit check's errors when one fails.
    """
    out = Findings(file, lines, max_output_bytes)
    for check in LIMIT_CHECKS:
        check(case, out)
        if out.problems:  # the limit checks report errors only; later ones assume them met
            return out.problems
    for check in CHECKS:
        check(case, out)
    return out.problems
