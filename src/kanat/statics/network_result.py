"""Network statics of a case: the first guess, the solve, and the result (positions and
tensions at every node, forces on anchors and bodies, grounded lengths, stiffness).

The first guess needs no ``position`` hints for ordinary moorings: unknown nodes start
where springs of stiffness 1/length along the lines would hold them between the fixed ends
(100 Gauss-Seidel sweeps: nodes spaced along a chain of lines in proportion to their
lengths), a buoyant node half its shortest line higher and a sinking one a tenth lower
(kept between the seabed and the surface), and every line whose chord is longer than 95 %
of its length is then shortened to that. Given positions and attitudes are kept.

The mooring stiffness at a node is ``-dR_lines/dq`` of the lines on that node with every
other free node re-balanced (static condensation of the full tangent, analytic, module
eq. 3 of :mod:`kanat.statics.network`): 6x6 at a rigid body about its reference point, per
metre of translation and per radian of small rotation about the global axes (the roll,
pitch, yaw columns turned by the angular-rate matrix of the body's attitude); 3x3 at a
point and at a point body (MoorPy's ``getStiffnessA`` and ``getCoupledStiffnessA``). The
vessel's ends, held in statics, get theirs too (:mod:`kanat.statics.coupled`): the vessel,
named ``vessel``, as a coupled rigid body about its origin, and each coupled point.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import SolverError
from kanat.physics.seabed import seabed_of
from kanat.statics.coupled import VESSEL, coupled_body_stiffness, coupled_stiffness
from kanat.statics.network import NetworkSolution, cross, solve_network
from kanat.statics.network_setup import NeedsLumped, NetworkProblem, network_problem
from kanat.statics.piecewise import sample
from kanat.statics.steady_checks import check_result

__all__ = ["NetworkCable", "NetworkResult", "first_guess", "solve_network_case"]

SMOOTHING_SWEEPS = 100
LIFT_FRACTION, SINK_FRACTION = 0.5, 0.1     # of the shortest line at the node
CHORD_FRACTION = 0.95                        # longest first-guess chord, in line lengths
SHORTEN_SWEEPS = 1000                        # at most this many passes over the lines to shorten them
SHORTEN_TOLERANCE = 1e-3                     # of a line's length: a chord this close to the limit is kept
CLEARANCE = 0.02                             # of the depth: guesses stay this far off seabed and surface
SEABED_TOLERANCE = 1e-6                      # of the depth: deeper nodes are below the seabed
ON_SEABED = 0.01                             # m: a cable's end at most this far above the seabed rests on it


@dataclass(frozen=True, eq=False)
class NetworkCable:
    """One cable at equilibrium, at its output nodes.

    Attributes
    ----------
    s : ndarray, shape (n,)
        Unstretched arclength from the ``from`` end [m].
    position : ndarray, shape (n, 3)
    tension : ndarray, shape (n,)
    angle : ndarray, shape (n,)
        Tangent (towards ``to``) above the horizontal [rad].
    grounded_length : float
        Unstretched length resting on the seabed [m].
    method : str
    """

    s: np.ndarray
    position: np.ndarray
    tension: np.ndarray
    angle: np.ndarray
    grounded_length: float
    method: str = "catenary"

    @property
    def x(self) -> np.ndarray:
        return self.position[:, 0]

    @property
    def z(self) -> np.ndarray:
        return self.position[:, 2]


@dataclass(frozen=True, eq=False)
class NetworkResult:
    """The equilibrium of a case's network (the dataset of :func:`kanat.io.results.statics_dataset`).

    Attributes
    ----------
    case : kanat.model.Case
    method : str
    cables : dict of str to NetworkCable
    bodies : dict of str to ndarray, shape (3,)
        Body positions (a rigid body's reference point) [m].
    attitudes : dict of str to ndarray, shape (3,)
        Roll, pitch, yaw of every body [rad] (0 for point bodies).
    points : dict of str to ndarray, shape (3,)
    body_forces, body_moments : dict of str to ndarray, shape (3,)
        Resultant force of the lines on each body [N] and its moment about the body's
        reference point [N m].
    anchor_forces : dict of str to ndarray, shape (3,)
        Force of the line on each anchor, named by cable end (``line1.from``) [N].
    stiffness : dict of str to ndarray
        Mooring stiffness, 6x6 at a body (3x3 block for a point body, the rest 0), 3x3 at a point;
        the coupled ones included.
    iterations, stages : int
    residual : float
        Largest force residual at equilibrium [N].
    notes : tuple of str
    """

    case: object
    method: str
    cables: dict
    bodies: dict
    attitudes: dict
    points: dict
    body_forces: dict
    body_moments: dict
    anchor_forces: dict
    stiffness: dict
    iterations: int = 0
    stages: int = 0
    residual: float = 0.0
    notes: tuple = ()
    vessel_velocity: np.ndarray = field(default_factory=lambda: np.zeros(3))
    sphere: None = None
    coupled_bodies: dict = field(default_factory=dict)
    """Coupled bodies (the vessel, ``vessel``; a MoorDyn file's several ``bodyN``) by name: their
    reference point [m]; their line
    force and moment are in ``body_forces`` and ``body_moments``."""
    coupled_points: dict = field(default_factory=dict)
    """Coupled points (the vessel's fairleads, named by their first cable end) by name: position [m]."""
    coupled_matrix: np.ndarray | None = None
    """With several coupled bodies (a MoorDyn file's array), the (6 N, 6 N) stiffness of all of them
    together, in the order of ``coupled_bodies`` (:func:`kanat.statics.coupled.coupled_body_stiffness`)."""

    @property
    def verdict(self):
        """The checks of a steady state on this result (:func:`kanat.statics.steady_checks.check_result`):
        its ``status`` is ``ok`` or ``failed: <check>: ...``."""
        return check_result(self)

    def summary(self) -> str:
        """A few lines an engineer reads first: fairlead and anchor loads, offsets, uplift."""
        lines = [f"network statics ({self.method}): {len(self.cables)} cables, "
                 f"{self.iterations} Newton iterations" + (f" in {self.stages} load stages" if self.stages else "")]
        for name, cable in self.cables.items():
            lines.append(f"cable {name}: tension {cable.tension[0] / 1e3:.3f} kN at 'from', "
                         f"{cable.tension[-1] / 1e3:.3f} kN at 'to'"
                         + (f"; {cable.grounded_length:.2f} m on the seabed" if cable.grounded_length > 0 else ""))
        for name, force in self.anchor_forces.items():
            lines.append(f"anchor {name}: horizontal {math.hypot(force[0], force[1]) / 1e3:.3f} kN, "
                         f"uplift {force[2] / 1e3:.3f} kN")
        for name, r in {**self.bodies, **self.points}.items():
            lines.append(f"{'body' if name in self.bodies else 'point'} {name}: x = {r[0]:.3f}, y = {r[1]:.3f}, "
                         f"z = {r[2]:.3f} m")
        for name, about in self.coupled_bodies.items():
            K, F = np.diag(self.stiffness[name]), self.body_forces[name]
            point = ", ".join(f"{r:.6g}" for r in about)
            force = ", ".join(f"{f / 1e3:.3f}" for f in F)
            lines.append(f"coupled body {name} (moments and stiffness about ({point}) m): line force ({force}) kN; "
                         f"stiffness surge, sway, heave {', '.join(f'{k / 1e3:.4g}' for k in K[:3])} kN/m, "
                         f"roll, pitch, yaw {', '.join(f'{k / 1e3:.4g}' for k in K[3:])} kN m/rad")
        lines += [f"note: {note}" for note in self.notes]
        return "\n".join(lines)


# --------------------------------------------------------------------------- first guess

def _neighbours(problem: NetworkProblem):
    found = [[] for _ in problem.nodes]
    for line in problem.lines:
        a, b = line.ends
        for mine, other in ((a, b), (b, a)):
            if mine.node >= 0:
                found[mine.node].append((other, line.pieces.total_length))
    return found


def first_guess(problem: NetworkProblem) -> np.ndarray:
    """Unknowns to start Newton's method from (module docstring)."""
    nodes = problem.nodes
    fixed = [end.point for line in problem.lines for end in line.ends if end.node < 0]
    centre = np.mean(fixed, axis=0) if fixed else np.zeros(3)
    pos = [node.position.copy() if node.position is not None else centre.copy() for node in nodes]
    free = [n for n, node in enumerate(nodes) if node.position is None]
    near = _neighbours(problem)
    for _ in range(SMOOTHING_SWEEPS if free else 0):         # springs of stiffness 1/length
        moved = 0.0
        for n in free:
            weights = np.array([1.0 / length for _, length in near[n]])
            places = np.array([other.point if other.node < 0 else pos[other.node] for other, _ in near[n]])
            new = weights @ places / weights.sum()
            moved, pos[n] = max(moved, float(np.max(np.abs(new - pos[n])))), new
        if moved <= SHORTEN_TOLERANCE * min(length for n in free for _, length in near[n]):
            break
    depth = problem.seabed.depth if problem.seabed is not None else max(-c[2] for c in [centre, *fixed])
    for n in free:
        reach = min(length for _, length in near[n])
        lift = nodes[n].force[2] + nodes[n].buoyancy - nodes[n].weight
        z = pos[n][2] + (LIFT_FRACTION if lift > 0 else -SINK_FRACTION) * reach
        floor = (problem.seabed.height(pos[n][0], pos[n][1]) if problem.seabed is not None else -np.inf)
        pos[n][2] = min(max(z, floor + CLEARANCE * depth), -CLEARANCE * depth)
    for _ in range(SHORTEN_SWEEPS):
        if not any([_shorten(line, pos, free) for line in problem.lines]):
            break
    return np.concatenate([np.concatenate([pos[n], node.orientation]) if node.dof == 6 else pos[n]
                           for n, node in enumerate(nodes)]) if nodes else np.zeros(0)


def _shorten(line, pos, free) -> bool:
    """Pull the guessed ends of a line together until its chord is CHORD_FRACTION of its length
    (both by half the excess when both are guessed); True if it moved them."""
    a, b = line.ends
    moving = [end for end in (a, b) if end.node in free]
    if not moving:
        return False
    where = [end.point if end.node < 0 else pos[end.node] for end in (a, b)]
    chord = where[1] - where[0]
    length = np.linalg.norm(chord)
    excess = length - CHORD_FRACTION * line.pieces.total_length
    if excess <= SHORTEN_TOLERANCE * line.pieces.total_length:
        return False
    unit = chord / length
    share = excess / len(moving)
    if a.node in free:
        pos[a.node] = pos[a.node] + share * unit
    if b.node in free:
        pos[b.node] = pos[b.node] - share * unit
    return True


# --------------------------------------------------------------------------- the result

def solve_network_case(case, method: str = "catenary") -> NetworkResult:
    """Network statics of ``case`` (module docstring; :mod:`kanat.statics.network`).

    Raises
    ------
    kanat.statics.network_setup.NeedsDrag
        For a case with a current or a tow speed.
    CaseError
        For what the catenary network cannot take, at its key.
    NeedsLumped
        When it puts a line below the seabed, or finds no equilibrium of lines with inline bodies
        (floats clamped along a line split it into catenaries whose start the load continuation
        may not find: WHOI Cable's ``branch`` and ``horiz`` arrays).
    SolverError
        When no equilibrium is found.
    """
    _check_loaded(case)
    problem = network_problem(case)
    try:
        solution = solve_network(problem, first_guess(problem))
    except NeedsLumped:
        raise
    except SolverError as error:
        if not any(cable.attachments for cable in case.cables):
            raise
        raise NeedsLumped(f"network statics did not converge on lines with inline bodies ({error}); "
                          "the lumped model's equilibrium solves them") from None
    return _result(case, method, solution)


def _check_loaded(case) -> None:
    """Refuse a network that nothing loads: weightless lines, bodies of no net buoyancy, force or
    waterplane, and no current (network statics has none) leave every line slack and the free
    bodies and points anywhere: no equilibrium is the answer."""
    env = case.environment
    weights = [case.line_types[s.line_type].weight_in_water_value(env.water_density, env.gravity)
               for cable in case.cables for s in cable.sections]
    loaded_bodies = [name for name, body in case.bodies.items()
                     if body.net_buoyancy != 0 or any(body.force) or body.surface_buoy is not None
                     or getattr(body, "waterplane_area", None)]
    if any(w != 0 for w in weights) or loaded_bodies or not (case.bodies or case.points):
        return
    raise SolverError("nothing loads this network: its lines weigh nothing in water and its bodies have "
                      "no net buoyancy, force or waterplane, so every line is slack and the bodies and "
                      "points could be anywhere; give the lines weight_in_water or the bodies "
                      "net_buoyancy")


def _cable(problem: NetworkProblem, line, state) -> NetworkCable:
    sol = state.solution
    pieces = line.pieces.reversed() if state.reversed else line.pieces
    L = line.pieces.total_length
    s_A = L - line.stations if state.reversed else line.stations
    x, z, tension, vertical = sample(s_A, sol.horizontal_tension, sol.vertical_tension, pieces, state.ground)
    if sol.slack:                                     # lying slack: bunched up under end B, where it hangs
        grounded = s_A <= sol.evaluation.touchdown    # (laid out straight it would reach evaluation.x)
        x = np.minimum(x, state.span)
        slope = state.ground.slope if state.ground is not None else 0.0
        z = np.where(grounded, x * slope, z)
    position = state.origin + np.outer(x, state.direction) + np.outer(z, [0.0, 0.0, 1.0])
    horizontal = np.sqrt(np.maximum(tension**2 - vertical**2, 0.0))
    angle = np.arctan2(-vertical if state.reversed else vertical, horizontal)
    return NetworkCable(line.stations.copy(), position, tension, angle, float(sol.evaluation.touchdown))


def _check_seabed(problem: NetworkProblem, cables: dict) -> None:
    """No node may lie below the seabed: a line touching down between two suspended ends, which
    the catenary lines do not model, goes to the lumped model's equilibrium (:class:`NeedsLumped`)."""
    if problem.seabed is None:
        return
    for name, cable in cables.items():
        below = problem.seabed.height(cable.position[:, 0], cable.position[:, 1]) - cable.position[:, 2]
        worst = int(np.argmax(below))
        if below[worst] > SEABED_TOLERANCE * problem.seabed.depth:
            raise NeedsLumped(f"cable '{name}' passes {below[worst]:.4g} m below the seabed at s = "
                              f"{cable.s[worst]:.6g} m: it touches down between two suspended ends, which "
                              "the catenary lines do not model (the lumped model's equilibrium does)")


def condensed_stiffness(solution: NetworkSolution) -> dict:
    """Mooring stiffness at every node, the others re-balanced (module docstring)."""
    problem = solution.problem
    K_lines, K_all = -solution.line_jacobian, -solution.jacobian
    out = {}
    for n, node in enumerate(problem.nodes):
        i = np.arange(problem.offsets[n], problem.offsets[n + 1])
        o = np.setdiff1d(np.arange(problem.offsets[-1]), i)
        K = K_lines[np.ix_(i, i)]
        if len(o):
            K = K - K_all[np.ix_(i, o)] @ np.linalg.pinv(K_all[np.ix_(o, o)]) @ K_all[np.ix_(o, i)]
        if node.kind == "body" and node.dof == 3:
            padded = np.zeros((6, 6))
            padded[:3, :3] = K
            K = padded
        elif node.dof == 6:                      # per small rotation about the global axes
            turn = np.eye(6)
            turn[3:, 3:] = np.linalg.inv(_angular_rates(solution.q[i[3:]]))
            K = K @ turn
        out[node.name] = K
    return out


def _angular_rates(angles) -> np.ndarray:
    """``T`` with ``omega = T d(roll, pitch, yaw)`` for ``R = Rz(yaw) Ry(pitch) Rx(roll)``: the
    small global rotation made by small changes of the three angles (identity at zero)."""
    _, pitch, yaw = angles
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    return np.array([[cy * cp, -sy, 0.0], [sy * cp, cy, 0.0], [-sp, 0.0, 1.0]])


def _result(case, method: str, solution: NetworkSolution) -> NetworkResult:
    problem = solution.problem
    cables = {line.name: _cable(problem, line, state) for line, state in zip(problem.lines, solution.lines)}
    _check_seabed(problem, cables)
    bodies, attitudes, points = {}, {}, {}
    forces = {node.name: np.zeros(3) for node in problem.nodes}
    moments = {node.name: np.zeros(3) for node in problem.nodes}
    anchors = {}
    q = solution.q
    for line, state in zip(problem.lines, solution.lines):
        for i, (end, label) in enumerate(zip(line.ends, ("from", "to"))):
            f = state.forces[i]
            if end.node >= 0:
                node = problem.nodes[end.node]
                start = problem.offsets[end.node]
                lever = cables[line.name].position[0 if i == 0 else -1] - q[start:start + 3]
                forces[node.name] += f
                moments[node.name] += cross(lever, f)
            elif end.kind == "anchor":
                anchors[f"{line.name}.{label}"] = f + np.array([0.0, 0.0, -end.load])
    notes = []
    for n, node in enumerate(problem.nodes):
        start = problem.offsets[n]
        r = q[start:start + 3].copy()
        if node.kind == "body":
            bodies[node.name] = r
            attitudes[node.name] = q[start + 3:start + 6].copy() if node.dof == 6 else np.zeros(3)
        else:
            points[node.name] = r
        if r[2] > 0.0 and node.dof == 3:
            raise SolverError(f"{node.kind} '{node.name}' would float {r[2]:.4g} m above the water surface, "
                              "where its buoyancy is lost: its lines cannot hold it under water. Statics "
                              "takes submerged points and point bodies; give it more weight or shorter "
                              "lines, or make it a dof: 6 body with a waterplane")
    notes += friction_notes(case, cables, anchors, {line.name: float(state.solution.horizontal_tension)
                                                    for line, state in zip(problem.lines, solution.lines)})
    body_forces = {k: v for k, v in forces.items() if k in bodies}
    body_moments = {k: v for k, v in moments.items() if k in bodies}
    stiffness = condensed_stiffness(solution)
    coupled_bodies, coupled_points = {}, {}
    coupled = coupled_stiffness(solution)
    several = _several_coupled_bodies(case, solution, bodies)
    if several is not None and coupled is not None:
        coupled_bodies = several.positions
        body_forces.update(several.forces)
        body_moments.update(several.moments)
        stiffness.update(several.stiffness)
        coupled_points = coupled.points
        stiffness.update(coupled.point_stiffness)
    elif coupled is not None and VESSEL not in bodies and not set(coupled.points) & set(points):
        coupled_bodies[VESSEL] = np.zeros(3)
        body_forces[VESSEL], body_moments[VESSEL] = coupled.body_force, coupled.body_moment
        stiffness[VESSEL] = coupled.body_stiffness
        coupled_points = coupled.points
        stiffness.update(coupled.point_stiffness)
    return NetworkResult(case, method, cables, bodies, attitudes, points, body_forces, body_moments, anchors,
                         stiffness, solution.iterations, solution.stages,
                         float(np.max(np.abs(solution.residual), initial=0.0)), tuple(notes),
                         coupled_bodies=coupled_bodies, coupled_points=coupled_points,
                         coupled_matrix=None if several is None else several.matrix)


def _several_coupled_bodies(case, solution, bodies):
    """Each coupled body of a MoorDyn file with several (:func:`kanat.statics.coupled.coupled_body_stiffness`),
    or None (no such file, one coupled body, or a name taken by a free body)."""
    from kanat.io.moordyn_coupled import coupled_bodies

    coupled = coupled_bodies(case)
    if len(coupled) < 2 or {body.name for body in coupled} & set(bodies):
        return None
    return coupled_body_stiffness(solution, coupled)


# --------------------------------------------------------------------------- from node positions

def result_from_positions(case, cables: dict, bodies: dict, points: dict, method: str,
                          iterations: int = 0, notes=(), grounded=None, anchor_forces=None,
                          attitudes=None) -> NetworkResult:
    """A :class:`NetworkResult` from the node positions of a discretized equilibrium.

    For a network in a current, which the catenary lines cannot carry, the front door solves
    the lumped model's equilibrium and hands its node positions here. Each element of
    ``L_e = section length / segments`` between nodes ``k``, ``k + 1`` has the linear tension
    ``T_e = EA (|r_k+1 - r_k| / L_e - 1)`` (clipped at 0; statics takes linear lines only);
    node tensions are the mean of the adjacent elements', linearly extrapolated at an end that
    hangs, as the lumped model's outputs (:class:`kanat.lumped.output.NodeTension`; the end element's
    tension, half an element in, read ``w L_e / 2`` low there: 5.7 % at the anchor of MoorPy's
    W-shaped case6 at 20 segments, where the anchor force was right), the end element's at an end on
    the seabed (within :data:`ON_SEABED`), where the tension is level and the touchdown may be in the
    end elements. A
    fixed end carries its end element's pull ``T_e u_e`` and half the element's weight and
    drag, as a lumped node does; a body carries what balances its own loads (net buoyancy,
    constant force, drag in the relative flow). The stiffness is not computed (left empty).
    What only the discretized model knows — the length of each cable on the seabed, the
    anchors' forces with the seabed's share taken off, the 6-DOF bodies' attitudes — is given
    by the caller (``grounded``, ``anchor_forces``, ``attitudes``); without a seabed the
    lengths are zero and the anchors carry their end elements' pull.

    Parameters
    ----------
    case : kanat.model.Case
    cables : dict of str to ndarray, shape (segments + 1, 3)
        Node positions of every cable, from ``from`` to ``to``.
    bodies, points : dict of str to ndarray, shape (3,)
    method : str
    iterations : int
    notes : sequence of str
    grounded : dict of str to float, optional
        Unstretched length of each cable resting on the seabed [m].
    anchor_forces : dict of str to ndarray, shape (3,), optional
        Force of the line on each anchor, named by cable end (``line1.from``) [N].
    attitudes : dict of str to ndarray, shape (3,), optional
        Roll, pitch, yaw of each body [rad] (zeros for point bodies).
    """
    from kanat.physics.drag import body_drag

    if case.environment.seabed is not None and (grounded is None or anchor_forces is None):
        raise ValueError("a network on a seabed needs the model's grounded lengths and anchor forces")

    env = case.environment
    ship = np.array([case.vessel.initial_speed, 0.0, 0.0])         # every node moves with the vessel
    bed = seabed_of(env)
    out, anchors = {}, {}
    for cable in case.cables:
        r = np.asarray(cables[cable.name], dtype=float)
        s, T, unit, ends = _elements(case, cable, r, ship)
        node_T = np.concatenate([[T[0]], 0.5 * (T[:-1] + T[1:]), [T[-1]]])
        for end, (first, second) in ((0, (0, 1)), (-1, (-1, -2))):
            if len(T) > 1 and not (bed is not None and r[end, 2] <= bed.height(r[end, 0], r[end, 1]) + ON_SEABED):
                node_T[end] = max(1.5 * T[first] - 0.5 * T[second], 0.0)   # a hanging end: extrapolated
        for label, end, pull in zip(("from", "to"), cable.ends, ends):
            if end.kind == "anchor":
                anchors[f"{cable.name}.{label}"] = pull
        angle = np.arctan2(unit[:, 2], np.hypot(unit[:, 0], unit[:, 1]))
        node_angle = np.concatenate([[angle[0]], 0.5 * (angle[:-1] + angle[1:]), [angle[-1]]])
        out[cable.name] = NetworkCable(s, r, node_T, node_angle, (grounded or {}).get(cable.name, 0.0), method)
    forces = {}
    for name, r in bodies.items():
        body = case.bodies[name]
        own = np.asarray(body.force, dtype=float) + np.array([0.0, 0.0, body.net_buoyancy])
        forces[name] = -(own + body_drag(env.current.at(r[2]) - ship, body.drag_area, env.water_density))
    zeros = {name: np.zeros(3) for name in bodies}
    turned = {name: np.asarray((attitudes or {}).get(name, np.zeros(3)), float) for name in bodies}
    anchors = anchors if anchor_forces is None else {k: np.asarray(v, float) for k, v in anchor_forces.items()}
    notes = (*notes, *friction_notes(case, out, anchors))
    return NetworkResult(case, method, out, {k: np.asarray(v, float) for k, v in bodies.items()}, turned,
                         {k: np.asarray(v, float) for k, v in points.items()}, forces, dict(zeros), anchors, {},
                         iterations, 0, 0.0, notes)


def friction_notes(case, cables: dict, anchors: dict, touchdown: dict | None = None) -> list[str]:
    """A note for each anchor whose pull the seabed's friction lowers: statics takes it fully mobilized
    towards the anchor (MoorPy's convention, docs/statics.md), so the anchor gets the touchdown's
    horizontal tension less ``mu w`` times the length on the seabed, down to zero. A line laid
    otherwise, or moved since, pulls its anchor with up to the touchdown's tension: the note gives both
    (MoorDyn's WD0200 chain: 905.8 kN at the anchor, 1408.5 kN at the touchdown, which MoorDyn's
    dynamic start, without friction at rest, puts on its anchor). ``touchdown`` gives a cable's tension
    at its touchdown (a catenary line's horizontal tension) [N]; else it is read off the cable's nodes."""
    bed = case.environment.seabed
    if bed is None or bed.friction <= 0.0:
        return []
    notes = []
    for name, force in anchors.items():
        cable_name, end = name.rsplit(".", 1)
        cable = cables.get(cable_name)
        if cable is None or cable.grounded_length <= 0.0:
            continue
        s = cable.grounded_length if end == "from" else float(cable.s[-1]) - cable.grounded_length
        at = (touchdown or {}).get(cable_name, float(np.interp(s, cable.s, cable.tension)))
        pull = math.hypot(force[0], force[1])
        if at - pull > 1e-3 * at:
            notes.append(
                f"anchor {name}: seabed friction (coefficient {bed.friction:g}) on the {cable.grounded_length:.4g} m "
                f"of '{cable_name}' on the seabed takes {(at - pull) / 1e3:.4g} kN off the "
                f"{at / 1e3:.4g} kN at the touchdown, taken fully mobilized towards the anchor (MoorPy's "
                "convention: the line laid from its anchor, then pulled taut); a line laid otherwise, or moved "
                f"since, pulls its anchor with up to {at / 1e3:.4g} kN")
    return notes


def _elements(case, cable, r, ship):
    """Node arclengths, element tensions and directions, and the pull of the end elements
    (tension, half weight and half drag) on the two ends."""
    from kanat.physics.drag import cable_drag

    env = case.environment
    s, EA, L0, loads = [np.zeros(1)], [], [], []
    start = 0.0
    for section in cable.sections:
        line_type = case.line_types[section.line_type]
        n = section.segments
        s.append(start + np.linspace(0.0, section.length, n + 1)[1:])
        EA += [line_type.axial_stiffness] * n
        L0 += [section.length / n] * n
        loads += [(line_type.weight_in_water_value(env.water_density, env.gravity), line_type)] * n
        start += section.length
    EA, L0 = np.array(EA), np.array(L0)
    chord = np.diff(r, axis=0)
    length = np.linalg.norm(chord, axis=1)
    strain = length / L0 - 1.0
    T = np.maximum(EA * strain, 0.0)
    unit = chord / np.maximum(length, 1e-300)[:, None]
    ends = []
    for k, sign in ((0, 1.0), (-1, -1.0)):
        weight, line_type = loads[k]
        mid = 0.5 * (r[k] + r[k + 1] if k == 0 else r[-1] + r[-2])
        drag = cable_drag(unit[k], env.current.at(mid[2]) - ship, strain[k], line_type.diameter,
                          line_type.drag_normal, line_type.drag_tangential, env.water_density)
        ends.append(sign * T[k] * unit[k] + 0.5 * L0[k] * (drag - np.array([0.0, 0.0, weight])))
    return np.concatenate(s), T, unit, ends
