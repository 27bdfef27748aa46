"""What the dynamic models refuse when a run is set up, checked with the case.

The continuum and the lumped models build their grids, networks and tracks from a case
that passed validation; whatever they would refuse there is checked here first, so that
``kanat validate`` and the run accept the same cases and every refusal comes with its file,
line and key:

* the scheme: a name of the case's model's registry (:data:`~kanat.schemes.SCHEME_NAMES`),
  and what that scheme can step (Kaliukh & Vusatiuk's factorized schemes a uniform flexible cable, the
  lumped model's implicit scheme no 6-DOF body);
* the sea: a JONSWAP spectrum that is positive, a seabed that holds the lines;
* the track: a turn of given radius needs a speed to turn at;
* the continuum model's cable: no attachment at a cable end, an elastic law it can invert;
* the lumped model's network (also built by the statics of a network in a current): 6-DOF
  bodies placed, fairleads on rigid bodies only, each attached body on a node of its own inside
  a cable, every part of it held by the vessel, an anchor or a given position.

Each function is a check of :data:`kanat.model.checks.CHECKS`: ``check(case, out)`` records
its problems with ``out.error(path, message)``.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..schemes import DYNAMIC_MODELS, SCHEME_NAMES, schemes_of
from ._base import fmt, listing, suggest
from .environment import JonswapWaves
from .paths import key_path
from .support import has_drag, needs_network, single_cable
from .vessel import Turn, start_speeds

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

ATTACHMENT_SNAP = 1e-6
"""The lumped model puts an attachment on the node within this fraction of the cable's length
(:data:`kanat.lumped.grid.SNAP_RTOL`; a test holds them equal)."""
END_RTOL = 1e-12
"""The continuum model takes an attachment this close (relative) to the cable's far end for
the end itself."""
LAW_STRAIN = 0.5
"""The continuum model inverts an elastic law up to this strain (sampled at :data:`LAW_SAMPLES`
intervals): its tension must increase there (:func:`kanat.continuum.grid.elastic_law_knots`)."""
LAW_SAMPLES = 400


def builds_lumped_network(case: Case) -> bool:
    """True when a run builds the lumped network: the lumped model, and the statics of a network
    in a current or under tow (handed to the lumped model's equilibrium)."""
    return case.model == "lumped" or (case.model == "statics" and has_drag(case) and needs_network(case)
                                      and not single_cable(case))


def check_scheme(case: Case, out) -> None:
    """``simulation.scheme`` names a scheme of the case's model, which can step this case."""
    sim = case.simulation
    if sim is None or sim.scheme is None or case.model not in DYNAMIC_MODELS:
        return
    valid = schemes_of(case.model)
    known = SCHEME_NAMES.get(sim.scheme)
    if known is None or known.model != case.model:
        other = f" ('{sim.scheme}' is a {known.model} scheme)" if known is not None else ""
        hint = other + suggest(sim.scheme, valid)
        out.error(("simulation", "scheme"), f"unknown {case.model} scheme '{sim.scheme}'; valid: "
                  f"{', '.join(valid)}{hint}")
    elif known.uniform_cable_only:
        _uniform_cable(case, sim.scheme, out)
    elif case.model == "lumped" and not known.explicit:
        rigid = sorted({e.name for c in case.cables for e in c.ends
                        if e.kind == "body" and e.name in case.bodies and case.bodies[e.name].dof == 6})
        if rigid:
            explicit = [n for n in valid if SCHEME_NAMES[n].explicit]
            out.error(("simulation", "scheme"), f"scheme {sim.scheme} does not take bodies with dof: 6 yet "
                      f"(body '{rigid[0]}'); use simulation.scheme: {' or '.join(explicit)}")


def _uniform_cable(case: Case, scheme: str, out) -> None:
    """Kaliukh & Vusatiuk's factorized schemes step a uniform, perfectly flexible cable without waves, winch
    or surface buoy (what :class:`kanat.continuum.adapter.ContinuumModel` refuses for them)."""
    if not case.cables:
        return
    cable = case.cables[0]
    used = []
    if len(cable.sections) > 1:
        used.append((("cables", 0, "sections"), "a cable of several sections"))
    if cable.attachments:
        used.append((("cables", 0, "attachments"), "inline bodies"))
    used += [(("line_types", name, "bending_stiffness"), "bending stiffness")
             for name in dict.fromkeys(cable.line_types)
             if name in case.line_types and case.line_types[name].bending_stiffness > 0]
    if case.environment.waves is not None:
        used.append((("environment", "waves"), "waves"))
    if case.winch:
        used.append((("winch",), "a winch"))
    used += [(("bodies", e.name, "surface_buoy"), "a surface buoy") for e in cable.ends
             if e.kind == "body" and e.name in case.bodies and case.bodies[e.name].surface_buoy is not None]
    for path, what in used:
        out.error(path, f"{what}: scheme '{scheme}' (Kaliukh & Vusatiuk's factorized schemes) steps a uniform "
                  "flexible cable only; use scheme: generalized-alpha")


def check_track(case: Case, out) -> None:
    """A turn of given radius needs a speed > 0: its turn rate is speed / radius (a speed so small
    that the rate is 0 in floating point counts as none). For the models that sail the track: the
    dynamic ones, and the lumped equilibrium of network statics (the other statics take the initial
    speed only)."""
    if case.model not in DYNAMIC_MODELS and not builds_lumped_network(case):
        return
    track = case.vessel.track
    for i, (segment, speed) in enumerate(zip(track, start_speeds(track))):
        if not isinstance(segment, Turn) or segment.radius is None or speed / segment.radius > 0.0:
            continue
        if speed > 0.0:
            why = f"at {fmt(speed)} m/s on a radius of {fmt(segment.radius)} m it turns at 0 rad/s"
        elif segment.speed_ms is not None:
            why = "its own speed is 0"
        else:
            why = "the track starts with it, at rest" if i == 0 else f"vessel.track[{i - 1}] ends at 0 m/s"
        out.error(("vessel", "track", i), f"a turn of given radius needs a speed > 0 ({why}); give the turn "
                  "a speed or a rate_deg_s")


def check_continuum_cable(case: Case, out) -> None:
    """The continuum model's cable: attachments inside it, elastic laws it can invert."""
    if case.model != "continuum" or not case.cables:
        return
    cable = case.cables[0]
    for i, item in enumerate(cable.attachments):
        if item.s <= 0.0 or item.s >= cable.length * (1 - END_RTOL):
            out.error(("cables", 0, "attachments", i, "s"), f"an attachment at a cable end (s = {fmt(item.s)} "
                      "m) is that end's body: write it as the end ('from' or 'to') instead")
    strains = [LAW_STRAIN * k / LAW_SAMPLES for k in range(LAW_SAMPLES + 1)]
    for name in dict.fromkeys(cable.line_types):
        law = case.line_types[name].elastic_law if name in case.line_types else None
        if law is None:
            continue
        if law.table is not None:
            tensions = [0.0, *(row[1] for row in law.table)]
        else:
            tensions = [sum(c * e ** (i + 1) for i, c in enumerate(law.polynomial)) for e in strains]
        if any(after <= before for before, after in zip(tensions, tensions[1:])):
            out.error(("line_types", name, "elastic_law"), "the tension of the elastic law must increase "
                      f"with strain up to {LAW_STRAIN:g} for the continuum model (it inverts the law); "
                      "a table must not repeat a tension")


def check_sea(case: Case, out) -> None:
    """The dynamic models' sea and seabed: a JONSWAP spectrum that is positive (DNV's normalization
    ``1 - 0.287 ln(gamma)`` is not, beyond gamma = 32.6), and a seabed stiff enough to hold the
    lines (their static penetration ``w / (k d)`` within the depth)."""
    if case.model not in DYNAMIC_MODELS:
        return
    env = case.environment
    waves = env.waves
    if isinstance(waves, JonswapWaves) and not _jonswap_positive(waves):
        out.error(("environment", "waves", "gamma"), f"gamma {fmt(waves.gamma)} makes the JONSWAP spectrum "
                  f"negative (DNV's normalization 1 - 0.287 ln(gamma) = {1 - 0.287 * math.log(waves.gamma):.3g}); "
                  "DNV gives it for 1 <= gamma <= 7 (3.3 is the mean North Sea value)")
    seabed = env.seabed
    if seabed is None or env.depth is None:
        return
    used = dict.fromkeys(name for cable in case.cables for name in cable.line_types if name in case.line_types)
    for name in used:
        line = case.line_types[name]
        weight = line.weight_in_water_value(env.water_density, env.gravity)
        sink = weight / seabed.stiffness / line.diameter      # no product to underflow
        if sink > env.depth:
            out.error(("environment", "seabed", "stiffness"), f"a stiffness of {fmt(seabed.stiffness)} Pa/m "
                      f"lets line type '{name}' ({weight:.4g} N/m in water, diameter {fmt(line.diameter)} m) "
                      f"sink w / (k d) = {sink:.3g} m into the seabed, more than the depth {fmt(env.depth)} m; "
                      "MoorDyn's kbot is typically 3e6 Pa/m")
            return


def _jonswap_positive(waves: JonswapWaves) -> bool:
    """Whether the JONSWAP spectrum of ``waves`` is positive at its peak (the wave model, NumPy and
    all, loads only for a JONSWAP case)."""
    from ..physics.waves import jonswap_spectrum

    return bool(jonswap_spectrum(2 * math.pi / waves.tp, waves.hs, waves.tp, waves.gamma) > 0)


# --- the lumped model's network ------------------------------------------------------------

def check_lumped_network(case: Case, out) -> None:
    """What :func:`kanat.lumped.network.build_network` needs: 6-DOF bodies with a position,
    fairlead offsets on rigid bodies, each attached body on its own node inside a cable, and
    every part of the network held by the vessel, an anchor or a given position."""
    if not builds_lumped_network(case):
        return
    network = _Network(case, out)
    for i, cable in enumerate(case.cables):
        first = network.end(cable.from_, ("cables", i, "from"))
        last = network.end(cable.to, ("cables", i, "to"))
        network.attach(i, cable, first, last)
        network.join(first, last)
    network.report_loose()


class _Network:
    """The lumped network's nodes as :func:`~kanat.lumped.network.build_network` makes them, in its
    order (the first use of a body or point makes its node), each cable joining its two ends."""

    def __init__(self, case: Case, out):
        self.case, self.out = case, out
        self.named: dict[str, tuple] = {}          # body or point -> its node
        self.kind: dict[tuple, str] = {}           # node -> vessel, anchor, free, fairlead, body, point
        self.parent: dict[tuple, tuple] = {}       # union-find of the nodes joined by cables
        self.placed: set[tuple] = set()            # nodes whose position is known from the start
        self.cables: list[tuple] = []              # each cable's first node
        self.unplaced: set[str] = set()            # 6-DOF bodies without a position, reported

    def _node(self, node: tuple, kind: str, placed: bool) -> tuple:
        if node not in self.parent:
            self.parent[node], self.kind[node] = node, kind
            if placed:
                self.placed.add(node)
        return node

    def end(self, end, where: tuple) -> tuple:
        """The node of a cable end (and the problems of placing it)."""
        if end.kind == "vessel":
            return self._node(("vessel", end.offset), "vessel", True)
        if end.kind in ("anchor", "free"):
            return self._node((end.kind, where), end.kind, end.kind == "anchor")
        body = self.case.bodies.get(end.name) if end.kind == "body" else None
        if body is not None and body.dof == 6:
            if body.position is None and end.name not in self.unplaced:
                self.unplaced.add(end.name)
                self.out.error(("bodies", end.name, "position"), f"body '{end.name}' has dof: 6 and ends "
                               f"{key_path(where)}: the lumped model needs its position (the reference "
                               "point its fairleads and 6x6 matrices are given about)")
            return self._node(("fairlead", end.name, end.offset), "fairlead", True)
        if body is not None and end.offset is not None:
            self.out.error(where, f"a fairlead offset needs a rigid body: body '{end.name}' is a point "
                           "(dof 3); add dof: 6 and its inertia, or drop the offset")
        if end.name not in self.named:
            item = body if end.kind == "body" else self.case.points.get(end.name)
            placed = item is not None and item.position is not None
            self.named[end.name] = self._node(("named", end.name), end.kind, placed)
        return self.named[end.name]

    def attach(self, index: int, cable, first: tuple, last: tuple) -> None:
        """Each attached body on a node of its own: not placed before, a point body, inside the cable
        (or at a free end), apart from the attachment before it."""
        far = cable.section_bounds()[-1][1]
        tolerance = ATTACHMENT_SNAP * cable.length
        previous = None
        for k, item in enumerate(cable.attachments):
            where = ("cables", index, "attachments", k, "body")
            body = self.case.bodies.get(item.body)
            target = min(max(item.s, 0.0), cable.length)
            node = (first if target <= tolerance else last if abs(far - target) <= tolerance
                    else ("inner", index, k))
            kind = self.kind.get(node, "cable")
            if item.body in self.named:
                self.out.error(where, f"body '{item.body}' is already placed (a cable end or another "
                               "attachment); each attached body needs its own body entry")
            elif body is not None and body.dof == 6:
                self.out.error(where, f"body '{item.body}' has dof: 6; an inline attachment is a point (dof 3)")
            elif kind not in ("cable", "free"):
                article = "an" if kind[0] in "aeiou" else "a"
                self.out.error(where, f"body '{item.body}' is attached at a cable end that is {article} {kind}; "
                               "attach it inside the cable or end the cable at the body")
            elif previous is not None and item.s - previous <= 2 * tolerance:
                self.out.error(where, f"attachments[{k - 1}] and [{k}] are {fmt(item.s - previous)} m apart: "
                               f"the lumped model puts bodies closer than {2 * ATTACHMENT_SNAP:g} of the "
                               "cable's length on one node; attach one body there, or move them apart")
            else:
                self._node(node, "body", False)
                self.kind[node] = "body"
                self.named[item.body] = node
            previous = item.s

    def _root(self, node: tuple) -> tuple:
        while self.parent[node] != node:
            node = self.parent[node]
        return node

    def join(self, a: tuple, b: tuple) -> None:
        """A cable between nodes ``a`` and ``b``."""
        self.parent[self._root(b)] = self._root(a)
        self.cables.append(a)

    def report_loose(self) -> None:
        """One error per part of the network that nothing holds or places (at its first cable)."""
        held = {self._root(node) for node in self.placed}
        reported = set()
        for i, node in enumerate(self.cables):
            root = self._root(node)
            if root in held or root in reported:
                continue
            reported.add(root)
            names = [name for name, n in self.named.items() if self._root(n) == root]
            which = f" ({listing(names)})" if names else ""
            self.out.error(("cables", i), f"part of the network is joined to neither the vessel nor an anchor"
                           f"{which}: give its bodies or points a 'position'")
