"""Network statics: the equilibrium of free points and bodies held by catenary lines.

The unknowns ``q`` are the free nodes' positions (and a rigid body's roll, pitch, yaw);
each line is solved exactly in its own vertical plane (:mod:`kanat.statics.line_solve`)
between its two ends, which gives the forces it puts on them and their derivatives. The
residual is every free node's force (and a rigid body's moment about its reference point)::

    (1)  R(q) = sum_lines f_end(q) + F_node(q) + F_C(q) = 0
    (2)  M(q) = sum_lines (R o) x f_end + M_WB(q) + M_C(q) = 0

with ``o`` a fairlead in body axes, ``M_WB`` the moment of the weight ``m g`` at the centre of
gravity and the buoyancy at the centre of buoyancy (:mod:`kanat.physics.hydrostatics` eq. 3, as
the lumped model) and ``(F_C, M_C)`` the restoring of the hydrostatic
stiffness ``C`` (body axes) about the body's given position ``r_0`` and attitude ``R_0``, from
its actual tilt (:mod:`kanat.physics.hydrostatics`, as the lumped model)::

    [F_C; M_C] = -[H (C dxi)_t; R (C dxi)_r],   H = Rz(yaw),
    dxi = (H^T (r - r_0), k x k_0 + (yaw - yaw_0) k_0),   k = R^T e_z,   k_0 = R_0^T e_z

so a body tilted by ``theta`` about any horizontal axis, at any yaw, feels ``C44 sin(theta)``
about that axis (``C44 = C55``, level reference), and heave and surge act in the heading
frame. When ``C`` has a roll or pitch restoring (a metacentric height), it holds the levers of
weight and buoyancy along the body's vertical at the reference, and only their offsets across it
turn with the body in ``M_WB``; otherwise the whole levers turn.

A 3-D line of in-plane tensions ``(H, V_B)`` with unit horizontal direction ``e_h`` from A
to B pulls B by ``f_B = -(H e_h + V_B e_z)`` and A by ``f_A = H_A e_h + V_A e_z``; with
``K = d(H, V_B)/d(span, rise)`` (the inverse of the line's flexibility) and ``P`` the
horizontal projection across the line, the end stiffness is (MoorPy's ``getStiffnessA``)::

    (3)  -df_B/dr_B = K_hh e_h e_h^T + K_hv e_h e_z^T + K_vh e_z e_h^T + K_vv e_z e_z^T + H/span P

Newton's method on (1)-(2) with this exact Jacobian runs in a trust region (at most a
quarter of the longest line at a node and 0.2 rad per step, shrunk fourfold until the
scaled residual falls), its step bent from Newton's towards the nodes' own forces
(Levenberg-Marquardt) where the region is small or slack lines leave the Jacobian singular.
If that fails from the first guess, a pseudo-transient continuation (:func:`_relax`) tries
from the same guess, and then the loads are continued (a Newton homotopy): with ``R_0`` the
residual at the guess, ``R(q) = (1 - lambda) R_0`` is solved for ``lambda`` rising from 0
(the guess itself) to 1 in adaptive steps, each from the previous solution.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.errors import SolverError
from kanat.physics.hydrostatics import restoring_load, weight_buoyancy_load
from kanat.physics.motion import skew
from kanat.statics import budget
from kanat.statics.line_solve import LineSolution, solve_line
from kanat.statics.network_setup import NetworkProblem, fairlead_rotation
from kanat.statics.piecewise import Ground

__all__ = ["LineState", "NetworkSolution", "solve_network"]

MAX_ITERATIONS = 60           # Newton iterations from the first guess
STAGE_ITERATIONS = 20         # per continuation stage
RELAX_ITERATIONS = 150        # pseudo-transient continuation, where Newton's method stalls
MAX_SHRINKS = 20              # trust-region reductions (by 4) before a Newton iteration gives up
MAX_REGULARIZATIONS = 30      # tenfold increases of the Levenberg-Marquardt parameter
STEP_FRACTION = 0.25          # largest node move per iteration, in lengths of its longest line
MAX_TURN = 0.2                # largest body rotation per iteration [rad]
FORCE_TOLERANCE = 1e-9        # of the network's load scale
ROUNDOFF = 1e-12              # force round-off allowance, per newton of the stiffest EA
FIRST_STAGE, MIN_STAGE = 0.25, 1e-4
VERTICAL = 1e-9               # spans below this many line lengths: the line is vertical
MAX_CONDITION = 1e12          # a Jacobian worse conditioned than this gets a regularized step
REGULARIZATION = 1e-8         # Levenberg-Marquardt diagonal, relative to the Jacobian's own


def cross(a, b) -> np.ndarray:
    """``a x b`` of two 3-vectors (numpy's cross is slow on small arrays)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


@dataclass(frozen=True, eq=False)
class LineState:
    """A line solved between its two ends.

    Attributes
    ----------
    solution : LineSolution
        In the line's plane, from end A.
    reversed : bool
        True when end A is the cable's ``to`` end.
    origin : ndarray, shape (3,)
        End A's position [m].
    direction : ndarray, shape (3,)
        ``e_h``, horizontal unit vector from A towards B.
    ground : Ground or None
    forces : ndarray, shape (2, 3)
        Force of the line on its ``from`` and ``to`` ends [N].
    blocks : ndarray, shape (2, 2, 3, 3)
        ``blocks[i, j] = d forces[i] / d r_j`` (ends ``from``, ``to``) [N/m].
    span : float
        Horizontal distance from end A to end B [m] (a line slack on the seabed lays out longer:
        its ``solution.evaluation.x``).
    """

    solution: LineSolution
    reversed: bool
    origin: np.ndarray
    direction: np.ndarray
    ground: Ground | None
    forces: np.ndarray
    blocks: np.ndarray
    span: float


def _spread(K, force_h, e_h, span, transverse) -> np.ndarray:
    """The 3x3 derivative of an in-plane force ``(F_h, F_v)`` with ``d(F_h, F_v)/d(span, rise) = K``
    with respect to end B's position, eq. (3)."""
    ez = np.array([0.0, 0.0, 1.0])
    across = np.diag([1.0, 1.0, 0.0]) - np.outer(e_h, e_h)
    return (np.outer(e_h, K[0, 0] * e_h + K[0, 1] * ez) + np.outer(ez, K[1, 0] * e_h + K[1, 1] * ez)
            + (force_h / span if span > 0.0 else transverse) * across)


def evaluate_line(line, r_from, r_to, seabed, friction, start=None) -> LineState:
    """Solve ``line`` between its ends at ``r_from``, ``r_to`` and return its end forces and
    their derivatives (module eq. 3)."""
    reverse = line.grounded_end == 1
    r_A, r_B = (r_to, r_from) if reverse else (r_from, r_to)
    pieces = line.pieces.reversed() if reverse else line.pieces
    d = r_B - r_A
    span, rise = math.hypot(d[0], d[1]), float(d[2])
    e_h = np.array([d[0] / span, d[1] / span, 0.0]) if span > VERTICAL * pieces.total_length else np.array([1.0, 0.0, 0.0])
    ground = None
    if line.grounded_end is not None:
        slope = seabed.gradient * e_h[0] if seabed is not None else 0.0
        ground = Ground(slope, friction)
    sol = solve_line(span, rise, pieces, ground, start)
    H, VB = sol.horizontal_tension, sol.vertical_tension
    H_A, V_A = sol.evaluation.anchor
    f_B = -(H * e_h + np.array([0.0, 0.0, VB]))
    f_A = H_A * e_h + np.array([0.0, 0.0, V_A])
    K, G = sol.stiffness, sol.anchor_stiffness
    span_ = span if span > VERTICAL * pieces.total_length else 0.0
    dB = -_spread(K, H, e_h, span_, K[0, 0])                         # d f_B / d r_B
    dA = _spread(G, H_A, e_h, span_, G[0, 0])                        # d f_A / d r_B
    blocks = np.array([[-dA, dA], [-dB, dB]])                        # rows A, B; columns r_A, r_B
    forces = np.array([f_A, f_B])
    if reverse:
        forces, blocks = forces[::-1], blocks[::-1, ::-1]
    return LineState(sol, reverse, r_A, e_h, ground, forces, blocks, span)


@dataclass(frozen=True, eq=False)
class NetworkSolution:
    """The equilibrium of a network.

    Attributes
    ----------
    problem : NetworkProblem
    q : ndarray
        Unknowns at equilibrium (positions; roll, pitch, yaw of rigid bodies).
    lines : list of LineState
    residual : ndarray
        ``R(q)`` (forces [N], moments [N m]).
    jacobian : ndarray
        ``dR/dq`` of lines and node loads.
    line_jacobian : ndarray
        ``dR/dq`` of the lines only (the mooring).
    iterations : int
        Newton iterations, over all continuation stages.
    stages : int
        Continuation stages (0: Newton converged from the first guess).
    """

    problem: NetworkProblem
    q: np.ndarray
    lines: list
    residual: np.ndarray
    jacobian: np.ndarray
    line_jacobian: np.ndarray
    iterations: int
    stages: int


# --------------------------------------------------------------------------- kinematics

def fairlead(problem: NetworkProblem, q, end):
    """Global position of a line end and its derivative with respect to its node's unknowns."""
    if end.node < 0:
        return end.point, None
    node = problem.nodes[end.node]
    start = problem.offsets[end.node]
    r = q[start:start + 3]
    if node.dof == 3:
        return r + end.point, np.eye(3)
    R, dR = fairlead_rotation(q[start + 3:start + 6])
    lever = R @ end.point
    return r + lever, np.hstack([np.eye(3), np.column_stack([m @ end.point for m in dR])])


def _restoring(node, q6) -> tuple[np.ndarray, np.ndarray]:
    """Hydrostatic restoring of a 6-DOF node at ``q6`` (position, roll, pitch, yaw) about its
    given position and attitude, eq. (2)'s ``F_C``, and its derivative (6, 6)."""
    reference = np.zeros(3) if node.position is None else node.position
    rot, d_rot = fairlead_rotation(q6[3:])
    return restoring_load(node.hydrostatic, rot, d_rot, fairlead_rotation(node.orientation)[0], q6[:3] - reference,
                          float(q6[5]), float(node.orientation[2]))


def _own_loads(problem: NetworkProblem, q, R, J) -> None:
    """Add the nodes' own loads (weight, buoyancy, hydrostatics, constant forces) to R, J."""
    for n, node in enumerate(problem.nodes):
        i = problem.offsets[n]
        R[i:i + 3] += node.force
        if node.dof == 3:
            continue
        if np.any(node.hydrostatic):
            load, d_load = _restoring(node, q[i:i + 6])
            R[i:i + 6] += load
            J[i:i + 6, i:i + 6] += d_load
        R[i + 2] += node.buoyancy - node.weight
        rot, d_rot = fairlead_rotation(q[i + 3:i + 6])
        moment, d_moment = weight_buoyancy_load(rot, d_rot, fairlead_rotation(node.orientation)[0][2], node.cog,
                                                node.cob, node.weight, node.buoyancy, float(node.tilt_in_stiffness))
        R[i + 3:i + 6] += moment
        J[i + 3:i + 6, i + 3:i + 6] += d_moment


def assemble(problem: NetworkProblem, q, starts=None):
    """Residual eqs. (1)-(2) and its Jacobian at ``q``.

    Returns
    -------
    R : ndarray, shape (n,)
    J : ndarray, shape (n, n)
        ``dR/dq`` (lines and node loads).
    J_lines : ndarray, shape (n, n)
        The lines' part of ``J``.
    states : list of LineState
    """
    n = problem.offsets[-1]
    R, J = np.zeros(n), np.zeros((n, n))
    states = []
    for k, line in enumerate(problem.lines):
        kin = [fairlead(problem, q, end) for end in line.ends]
        state = evaluate_line(line, kin[0][0], kin[1][0], problem.seabed, problem.friction,
                              None if starts is None else starts[k])
        states.append(state)
        for i, end in enumerate(line.ends):
            if end.node < 0:
                continue
            node, row = problem.nodes[end.node], problem.offsets[end.node]
            f = state.forces[i] - np.array([0.0, 0.0, end.load])    # with an attachment at the end
            R[row:row + 3] += f
            lever = kin[i][0] - q[row:row + 3]
            if node.dof == 6:
                R[row + 3:row + 6] += cross(lever, f)
            for j, other in enumerate(line.ends):
                if other.node < 0:
                    continue
                col = problem.offsets[other.node]
                block = state.blocks[i, j] @ kin[j][1]
                J[row:row + 3, col:col + block.shape[1]] += block
                if node.dof == 6:
                    J[row + 3:row + 6, col:col + block.shape[1]] += skew(lever) @ block
            if node.dof == 6:                                      # the fairlead turns with the body
                J[row + 3:row + 6, row + 3:row + 6] -= skew(f) @ kin[i][1][:, 3:]
    J_lines = J.copy()
    _own_loads(problem, q, R, J)
    return R, J, J_lines, states


# --------------------------------------------------------------------------- Newton and continuation

def _scales(problem: NetworkProblem):
    """Residual scale per unknown (forces [N], moments [N m]) and the tolerance factor."""
    loads = [1.0] + [abs(line.pieces.total_weight) for line in problem.lines]
    loads += [float(np.max(np.abs(node.force))) for node in problem.nodes]
    loads += [max(node.weight, node.buoyancy) for node in problem.nodes]
    force = max(loads)
    lever = max([1.0] + [float(np.linalg.norm(end.point)) for line in problem.lines for end in line.ends
                         if end.node >= 0] + [float(np.linalg.norm(node.cog)) for node in problem.nodes])
    scale = np.array([value for node in problem.nodes for value in [force] * 3 + [force * lever] * (node.dof - 3)])
    stiffest = max(float(np.max(line.pieces.stiffness)) for line in problem.lines)
    tolerance = max(FORCE_TOLERANCE, ROUNDOFF * stiffest / force)
    return scale, tolerance


def _caps(problem: NetworkProblem) -> np.ndarray:
    """Largest change of each unknown per Newton step: a quarter of the longest line at the
    node (a short link does not hold back the lines beyond it), MAX_TURN for a rotation."""
    longest = np.zeros(len(problem.nodes))
    for line in problem.lines:
        for end in line.ends:
            if end.node >= 0:
                longest[end.node] = max(longest[end.node], line.pieces.total_length)
    return np.array([value for n, node in enumerate(problem.nodes)
                     for value in [STEP_FRACTION * longest[n]] * 3 + [MAX_TURN] * (node.dof - 3)])


def _step(J, R, limit):
    """The Newton step ``J dq = -R`` where it is within ``limit`` (per unknown), else the
    Levenberg-Marquardt step ``(J - mu D) dq = -R``, ``D`` the diagonal of ``|J|``, with ``mu``
    raised tenfold from REGULARIZATION until it is: from Newton's direction towards each
    node's own force, as the trust region shrinks (and where slack lines leave ``J``
    singular)."""
    try:
        if np.linalg.cond(J) < MAX_CONDITION:
            dq = np.linalg.solve(J, -R)
            if np.all(np.abs(dq) <= limit):
                return dq
    except np.linalg.LinAlgError:
        pass
    diagonal = np.abs(np.diag(J))
    diagonal = np.maximum(diagonal, np.max(diagonal, initial=0.0) * 1e-12 + 1e-300)
    mu = REGULARIZATION
    for _ in range(MAX_REGULARIZATIONS):
        dq = np.linalg.solve(J - mu * np.diag(diagonal), -R)
        if np.all(np.abs(dq) <= limit):
            return dq
        mu *= 10.0
    return dq * float(np.min(limit / np.maximum(np.abs(dq), 1e-300)))


def _try(problem, q, starts):
    try:
        return assemble(problem, q, starts)
    except SolverError:
        return None


def _newton(problem, q, shift, scale, tolerance, caps, max_iterations, starts=None):
    """Newton's method on ``R(q) = shift`` in a trust region; returns ``(q, iterations,
    converged, assembled)``.

    The region starts at the caps; a step that does not lower the scaled residual is
    retried in a region four times smaller (:func:`_step` bends it from Newton's direction
    towards the nodes' forces), and the region grows back twofold after a step accepted at
    once.
    """
    def merit(values):
        return float(np.sum(((values[0] - shift) / scale) ** 2))
    current = _try(problem, q, starts)
    if current is None:
        return q, 0, False, None
    radius = 1.0
    for iteration in range(1, max_iterations + 1):
        R = current[0] - shift
        if np.max(np.abs(R) / scale, initial=0.0) <= tolerance:
            return q, iteration - 1, True, current
        budget.check_time()
        base = merit(current)
        for attempt in range(MAX_SHRINKS):
            trial_q = q + _step(current[1], R, radius * caps)
            trial = _try(problem, trial_q, warm_starts(current[3]))
            if trial is not None and merit(trial) < base:
                radius = min(1.0, 2.0 * radius) if attempt == 0 else radius
                break
            radius *= 0.25
        else:
            return q, iteration, False, current
        q, current = trial_q, trial
    R = current[0] - shift
    return q, max_iterations, bool(np.max(np.abs(R) / scale, initial=0.0) <= tolerance), current


def _relax(problem, q, shift, scale, tolerance, caps, max_iterations):
    """Pseudo-transient continuation of ``R(q) = shift`` (Kelley & Keyes 1998, SIAM J. Numer.
    Anal. 35, 508; the lumped model's equilibrium): ``(J - D/dtau) dq = -R`` with ``D`` a
    pseudo-mass of the network's load scale per node (so that nodes joined by a stiff link
    move together), ``dtau`` growing as the residual falls (switched evolution relaxation)
    until the step is Newton's. A step may raise the residual up to tenfold, so it passes
    where a line snaps taut; returns ``(q, iterations, converged, assembled)``."""
    current = _try(problem, q, None)
    if current is None:
        return q, 0, False, None
    mass = np.diag(scale**2 / scale[0])         # F per m of pseudo-time; F lever^2 for a turn (scale F lever)
    dtau = 1.0                                               # m: a node moves about dtau R/F at first
    for iteration in range(1, max_iterations + 1):
        R = current[0] - shift
        size = np.max(np.abs(R) / scale, initial=0.0)
        if size <= tolerance:
            return q, iteration - 1, True, current
        budget.check_time()
        dq = np.linalg.solve(current[1] - mass / dtau, -R)
        dq *= min(1.0, float(np.min(caps / np.maximum(np.abs(dq), 1e-300))))
        trial = _try(problem, q + dq, warm_starts(current[3]))
        new = np.max(np.abs(trial[0] - shift) / scale, initial=0.0) if trial is not None else np.inf
        if not new <= 10.0 * size:
            dtau *= 0.25
            continue
        dtau *= min(max(size / max(new, 1e-300), 0.5), 10.0)
        q, current = q + dq, trial
    R = current[0] - shift
    return q, max_iterations, bool(np.max(np.abs(R) / scale, initial=0.0) <= tolerance), current


def _solve_stage(problem, q, shift, scale, tolerance, caps, max_iterations):
    """Newton's method in its trust region, else pseudo-transient continuation from ``q``."""
    found = _newton(problem, q, shift, scale, tolerance, caps, max_iterations)
    if found[2]:
        return found
    relaxed = _relax(problem, q, shift, scale, tolerance, caps, RELAX_ITERATIONS)
    return relaxed[0], found[1] + relaxed[1], relaxed[2], relaxed[3]


def warm_starts(states) -> list[tuple[float, float]]:
    """``(H, V_B)`` of every line, to start the next solve of the same lines from."""
    return [(s.solution.horizontal_tension, s.solution.vertical_tension) for s in states]


def solve_network(problem: NetworkProblem, q0: np.ndarray) -> NetworkSolution:
    """The equilibrium of ``problem`` from the first guess ``q0`` (module docstring).

    Raises
    ------
    SolverError
        When neither Newton's method nor the load continuation converges.
    """
    scale, tolerance = _scales(problem)
    caps = _caps(problem)
    q, iterations, ok, done = _solve_stage(problem, q0, 0.0, scale, tolerance, caps, MAX_ITERATIONS)
    stages = 0
    if not ok:
        q, iterations, stages, done = _continuation(problem, q0, scale, tolerance, caps)
    R, J, J_lines, states = done
    return NetworkSolution(problem, q, states, R, J, J_lines, iterations, stages)


def _continuation(problem, q0, scale, tolerance, caps):
    """Load continuation from the guess, where ``R = R_0`` holds by construction."""
    R0 = assemble(problem, q0)[0]
    q, lam, step, total, stages = q0, 0.0, FIRST_STAGE, 0, 0
    done = None
    while lam < 1.0:
        target = min(1.0, lam + step)
        q_new, used, ok, assembled = _newton(problem, q, (1.0 - target) * R0, scale, tolerance, caps,
                                             STAGE_ITERATIONS)
        total += used
        stages += 1
        if ok:
            q, lam, done = q_new, target, assembled
            step *= 2.0
        else:
            step *= 0.25
            if step < MIN_STAGE:
                worst = int(np.argmax(np.abs(assemble(problem, q)[0]) / scale))
                node = problem.nodes[int(np.searchsorted(problem.offsets, worst, side="right")) - 1]
                raise SolverError(f"network statics did not converge: the load continuation stalled at "
                                  f"{100 * lam:.3g} % of the loads (largest residual at {node.kind} "
                                  f"'{node.name}'); give that {node.kind} a 'position' near its "
                                  "equilibrium, or check that its lines can hold it")
    return q, total, stages, done
