"""Initial equilibrium of the network (theory/moorings.md §1): the static state for the initial tow
speed, current and the mean (wave-free) surface.

In the frame moving with the vessel's initial velocity ``U`` every node moves at ``U``;
the free node positions ``q`` solve ``F(q) = 0`` (:class:`~kanat.lumped.system.LumpedSystem`
with ``steady_velocity = U``). Newton's method is first run on the taut residual, where slack
elements resist compression (:mod:`kanat.lumped.taut_newton`): from a start near the
equilibrium it converges in a few iterations where a stiff chain sits at strains of 1e-5 and
every iterate leaves some of its elements slack. If that does not meet the tolerance (a
start far off, or a line that is slack at the equilibrium), slack cables make the tangent
singular, so Newton's method is regularized as a pseudo-transient continuation (implicit dynamic relaxation; Kelley &
Keyes 1998, SIAM J. Numer. Anal. 35, 508)::

    (1)  (M / dtau^2 - dF/dq) dq = F(q),    dtau_k+1 = dtau_k ||F_k-1|| / ||F_k||   (SER)

and it becomes Newton's method as ``dtau`` grows. ``dF/dq`` is the exact finite-difference
Jacobian, built with a distance-2 colouring of the node graph (a node's force depends
only on its neighbours), so it costs ``3 x colours`` force evaluations; its linear systems are
solved by LAPACK's band LU after a reverse Cuthill–McKee order of the free nodes
(:class:`kanat.lumped.band_solve.NodeBandSolver`), which spares a run the import of SciPy's sparse
package.

Where all of that fails (lines held up by many small inline floats, whose sections go slack and
taut from one iterate to the next), :func:`_relaxed_equilibrium` settles the softened network by
dynamic relaxation (:mod:`kanat.lumped.relaxation`) and lets Newton's method finish; the info's
``fallback`` says so. It runs only after the other paths failed, so they give what they gave,
except in a network with spherical inline floats (``bodies.X.diameter``, whose buoyancy follows
their immersion): there it runs first (:func:`_floats_first`).
"""
from __future__ import annotations

import dataclasses
import functools

import numpy as np

from kanat.errors import SolverError
from kanat.statics import budget
from kanat.lumped.band_solve import NodeBandSolver
from kanat.lumped.relaxation import relax
from kanat.lumped.system import LumpedSystem
from kanat.lumped.taut_newton import SeabedGuard, compression_forces, onset_stiffness, taut_newton
from kanat.lumped.tow_guess import free_tail_guess

MAX_ITERATIONS = 400
DIRECT_ITERATIONS = 150        # before stiffness continuation takes over
CONTINUATION_START = 1e6       # N: stiffest elastic law coefficient of the first continuation stage
RESIDUAL_TOLERANCE = 1e-9      # of the largest nodal load scale
FD_STEP = 1e-7                 # relative finite-difference step (of element length)
INITIAL_PSEUDO_PERIOD = 0.05   # dtau0 as a fraction of the slowest pendulum period sqrt(L/g)
MAX_STEP_FRACTION = 0.25       # largest node move per iteration, in element lengths
STALL, STALL_GROWTH = 0.01, 1.5   # pseudo-time step growth when the residual moves by < 1 %
LINE_SEARCH_HALVINGS = 3       # a Newton step is shortened at most 2^-3 before the PTC step is tried
STARTING_DIFFERENCE = 0.01    # s, the time step of the starting velocities' central difference
ROUNDOFF_FACTOR = 64.0         # force round-off allowance: eps x stiffness x coordinate size x this
RELAXATION_STIFFNESS = 1e4     # N: stiffest elastic law coefficient of the dynamic relaxation (its axial
#                                modes, 1e3-1e4 times slower than a chain's, leave the fictitious motion a
#                                period of a few hundred steps; seatex: 62,000 steps to 43 N)
RELAXATION_TARGET = 5e-3       # of the nodal load scale: where the relaxation hands over to Newton's method
STAGE_ITERATIONS = 100        # Newton's first try at a relaxed stage: from a relaxed state it converges in a few
#                                or not at all (deep_s: 400 failed iterations at four stages, 43 s of 110 s)
RETRY_TARGET = 1e-2            # of RELAXATION_TARGET: a stage whose Newton iteration failed is relaxed this far
#                                (Newton's method finishes from there in 8-90 iterations; at 1e-3, in 2-5, but the
#                                relaxation's slowest modes took deep_s 232,000 steps instead of 127,000)


def node_graph(net) -> list[set]:
    """Each node's neighbours (itself included): the nodes its force depends on. Elements join
    their ends, bending the nodes either side of an interior node; a 6-DOF body's two pseudo-nodes join each other, its fairleads and the nodes
    next to them (the fairleads move with the body)."""
    neighbours = [{k} for k in range(net.n_nodes)]
    for i, j in zip(np.r_[net.el_i, net.bend[0]], np.r_[net.el_j, net.bend[2]]):   # bending: i-1 and i+1
        neighbours[i].add(j)
        neighbours[j].add(i)
    rigid = net.rigid
    for b in range(rigid.count):
        group = {int(rigid.ref_node[b]), int(rigid.rot_node[b])}
        for f in rigid.fairlead_node[rigid.fairlead_body == b]:
            group |= neighbours[int(f)]
        for node in group:
            neighbours[node] |= group
    return neighbours


def distance2_colouring(net) -> np.ndarray:
    """Colour of each free node so that nodes of one colour are > 2 edges apart."""
    n = net.n_nodes
    neighbours = node_graph(net)
    colour = -np.ones(n, dtype=np.int64)
    for node in np.flatnonzero(net.free):
        near = set(neighbours[node])
        for other in neighbours[node]:
            near |= neighbours[other]
        taken = {colour[k] for k in near if colour[k] >= 0}
        colour[node] = next(c for c in range(n + 1) if c not in taken)
    return colour


def _jacobian(force, free, xf, colour, step, neighbours_of):
    """Sparse ``dF/dq`` (3 n_free square, SciPy's CSC) of ``force(xf)`` by coloured central
    differences (:func:`_jacobian_entries`); ``free`` the free nodes' indices."""
    import scipy.sparse as sp                           # here only: the equilibrium's solves need no SciPy

    rows, cols, vals = _jacobian_entries(force, free, xf, colour, step, neighbours_of)
    size = 3 * len(free)
    return sp.csc_matrix((vals, (rows, cols)), shape=(size, size))


def _jacobian_entries(force, free, xf, colour, step, neighbours_of):
    """``dF/dq`` (3 n_free square) of ``force(xf)`` by coloured central differences as
    ``(rows, cols, values)``, no entry repeated; ``free`` the free nodes' indices.

    Each colour's group of nodes is moved in one direction ``r`` at a time; every node ``m`` whose force
    depends on a moved node ``k`` (its neighbour) gets the three entries ``dF_m / dq_k,r``, in the order
    of ``k`` and then of ``k``'s neighbours."""
    position = {node: k for k, node in enumerate(free)}
    rows, cols, vals = [], [], []
    zero = np.zeros_like(xf)
    block = np.arange(3)
    for c in range(colour[free].max() + 1):
        group = np.flatnonzero(colour[free] == c)
        pairs = np.array([(k, position[node]) for k in group for node in neighbours_of[free[k]] if node in position],
                         dtype=np.int64).reshape(-1, 2)
        moved, touched = pairs[:, 0], pairs[:, 1]
        pair_rows = (3 * touched[:, None] + block).ravel()
        for r in range(3):
            dx = zero.copy()
            dx[group, r] = step
            dF = (force(xf + dx) - force(xf - dx)) / (2 * step)
            rows.append(pair_rows)
            cols.append(np.repeat(3 * moved + r, 3))
            vals.append(dF[touched].ravel())
    if not rows:
        return np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0)
    return np.concatenate(rows), np.concatenate(cols), np.concatenate(vals).astype(float)


def band_solver(free, neighbours_of) -> NodeBandSolver:
    """The band solver of the matrices :func:`_jacobian_entries` builds over the free nodes ``free``
    with the node graph ``neighbours_of`` (:func:`node_graph`)."""
    position = {node: k for k, node in enumerate(free)}
    return NodeBandSolver([{position[node] for node in neighbours_of[f] if node in position} for f in free])


class _SteadyForces:
    """Free nodes' static forces ``F(q)`` in the steady frame, and their mass blocks."""

    def __init__(self, system: LumpedSystem):
        self.system = system

    def __call__(self, t, xf):
        s = self.system
        x, v, _, heading = s.full(t, xf, np.zeros_like(xf))
        F, M = s.loads(t, x, v, heading)
        return F[s.free_index].copy(), M[s.free_index].copy()

    def force(self, t, xf):
        """The forces alone (the coloured differences' evaluations): the mass blocks not unpacked."""
        s = self.system
        x, v, _, heading = s.full(t, xf, np.zeros_like(xf))
        return s.loads(t, x, v, heading, masses=False)[0][s.free_index]


def _newton(J, solver, F, xf, forces, length):
    """A Newton step ``-J dx = F`` (``J`` as ``(rows, cols, values)``, solved by ``solver``)
    shortened (halving, from at most MAX_STEP_FRACTION of an element per node) until the
    residual's 2-norm falls; None if it never does."""
    rows, cols, values = J
    direction = solver.solve(rows, cols, -values, F.ravel())
    if direction is None:                                        # singular: slack parts
        return None
    direction = direction.reshape(-1, 3)
    alpha = min(1.0, MAX_STEP_FRACTION * length / max(np.max(np.linalg.norm(direction, axis=1)), 1e-300))
    norm2 = np.linalg.norm(F)
    for _ in range(LINE_SEARCH_HALVINGS):
        F_new, M_new = forces(0.0, xf + alpha * direction)
        if np.isfinite(np.linalg.norm(F_new)) and np.linalg.norm(F_new) < (1.0 - 1e-4 * alpha) * norm2:
            return alpha * direction, F_new, M_new
        alpha *= 0.5
    return None


def _pseudo_transient(J, solver, M, F, xf, forces, length, dtau, norm):
    """One pseudo-transient step, eq. (1), clipped to MAX_STEP_FRACTION; None if it blows up.
    ``J`` as ``(rows, cols, values)``, the system solved by ``solver``."""
    rows, cols, values = J
    block = 3 * np.arange(len(M))[:, None, None]
    mass_rows = np.broadcast_to(block + np.arange(3)[:, None], M.shape).ravel()
    mass_cols = np.broadcast_to(block + np.arange(3), M.shape).ravel()
    dx = solver.solve(np.r_[mass_rows, rows], np.r_[mass_cols, cols], np.r_[(M / dtau**2).ravel(), -values],
                      F.ravel())
    if dx is None:                                               # singular: the caller shortens dtau
        return None
    dx = dx.reshape(-1, 3)
    biggest = np.max(np.linalg.norm(dx, axis=1))
    if biggest > MAX_STEP_FRACTION * length:
        dx *= MAX_STEP_FRACTION * length / biggest
    F_new, M_new = forces(0.0, xf + dx)
    norm_new = np.max(np.abs(F_new))
    return (dx, F_new, M_new) if np.isfinite(norm_new) and norm_new <= 10.0 * norm else None


def _tolerance(net, xf) -> float:
    """Force residual at which the equilibrium is converged [N]: RESIDUAL_TOLERANCE of the nodal
    load scale, but not below the round-off of the stiffest element's force."""
    scale = _load_scale(net)
    stiffness = np.max(net.law_y[:, 0]) / np.min(net.el_length) if net.law_y.size else 0.0
    noise = ROUNDOFF_FACTOR * np.finfo(float).eps * stiffness * max(np.max(np.abs(xf), initial=0.0), 1.0)
    return max(RESIDUAL_TOLERANCE * scale, noise)


def equilibrium(net, case, x0=None, velocity=None, friction=True, time=0.0):
    """Static equilibrium of the network, eq. (1), with continuation in axial stiffness.

    Tried directly first; if that fails, the elastic laws are softened so that the stiffest
    tangent is CONTINUATION_START [N] and stiffened tenfold per stage back to the true laws,
    each stage starting from the last: a softer line's equilibrium is stretched more, so every
    element stays taut when it stiffens and Newton's method sees no slack kinks.

    Parameters and returns as :func:`_solve`. The search has the time budget of a steady solve
    (:mod:`kanat.statics.budget`). Where it fails on a network with inline bodies (floats clamped
    along a line: the systems it is built for), the fallback (:func:`_relaxed_equilibrium`) is
    tried under a budget of its own; elsewhere the failure stands as it did (a case with no
    equilibrium fails as fast as before).
    """
    if x0 is None and len(net.float_body):
        return _floats_first(net, case, velocity, friction, time)
    with budget.budget("the equilibrium of the lumped network"):
        try:
            return _equilibrium(net, case, x0, velocity, friction, time)
        except SolverError as error:
            if not any(cable.attachments for cable in case.cables):
                raise
            failure = error
    with budget.budget("the equilibrium of the lumped network by dynamic relaxation"):
        try:
            return _relaxed_equilibrium(net, case, velocity, friction, time)
        except SolverError:
            raise failure from None


def _floats_first(net, case, velocity, friction, time):
    """:func:`equilibrium` of a network with spherical floats whose buoyancy follows their immersion
    (``bodies.X.diameter``): dynamic relaxation first. Which floats reach the surface, and how deep
    each floats there, is what the equilibrium decides; Newton's method from a guess that has them
    all under water (or all above it) meets a residual that changes its law as they cross the
    surface and stalls (shallow_s: 58 s of failed iterations before the fallback's 12 s). The
    other paths are tried after it, as :func:`equilibrium` tries them."""
    with budget.budget("the equilibrium of the lumped network by dynamic relaxation"):
        try:
            x, info = _relaxed_equilibrium(net, case, velocity, friction, time)
            return x, {**info, "relaxation_reason": "floats at the surface"}
        except SolverError as error:
            failure = error
    with budget.budget("the equilibrium of the lumped network"):
        try:
            return _equilibrium(net, case, None, velocity, friction, time)
        except SolverError:
            raise failure from None


def _equilibrium(net, case, x0, velocity, friction, time):
    """:func:`equilibrium` under its budget; from the statics solver's shape first where it gives one,
    and from the still-water catenaries where that start does not converge (a line with bending
    stiffness, whose statics guess is the flexible line's: a tether of EI 100 N m^2 in a current)."""
    solve = functools.partial(_solve, friction=friction, time=time)
    start = "given" if x0 is not None else "network"
    if x0 is None and velocity is None:
        x0, start = first_guess(net, case)
        if start == "statics":
            try:
                return _equilibrium_from(net, case, x0, velocity, solve, start)
            except SolverError:
                from kanat.lumped.catenary_guess import catenary_guess

                x0 = catenary_guess(net, case)
                start = "catenary" if x0 is not None else "network"
    return _equilibrium_from(net, case, x0, velocity, solve, start)


def _equilibrium_from(net, case, x0, velocity, solve, start):
    """The equilibrium from ``x0`` (None: the network's guess), directly, else by continuation."""
    stiffest = float(np.max(np.abs(net.law_y))) if net.law_y.size else 0.0
    if stiffest <= CONTINUATION_START:
        x, info = solve(net, case, x0, velocity, MAX_ITERATIONS)
        return x, {**info, "first_guess": start}
    try:
        x, info = solve(net, case, x0, velocity, DIRECT_ITERATIONS)
        return x, {**info, "first_guess": start}
    except SolverError:
        pass
    factors = CONTINUATION_START / stiffest * 10.0 ** np.arange(int(np.ceil(np.log10(stiffest / CONTINUATION_START))))
    x = x0
    for factor in [*factors, 1.0]:                   # the taut phase was tried (and failed) directly
        soft = dataclasses.replace(net, law_y=net.law_y * factor)
        x, info = solve(soft, case, x, velocity, MAX_ITERATIONS, taut=False)
    info["continuation_stages"] = len(factors) + 1
    info["first_guess"] = start
    return x, info


def _scaled(net, factor):
    """``net`` with every elastic law's force, its stiffness in compression and its seabed contact's
    stiffness scaled by ``factor`` (the relaxation's softer line, :func:`_relaxed_equilibrium`): the
    contact area ``A_n`` of :mod:`kanat.physics.contact` eq. (1) is scaled, so that the contact's normal
    force ``k_b delta A_n`` keeps its ratio to the line's axial forces. The compression stiffness
    (``compression_stiffness``, a line with bending stiffness) is scaled with the laws: left at its true
    value, an element that the bent line compresses is ~3,400 times stiffer than the softened line, its
    nodes take fictitious masses as large, and the relaxation does not settle (WHOI's ``mpl``, EI 2000
    N m^2 and 3.4e7 N in compression: 120 s of CPU without an equilibrium; scaled: 4,379 steps, 3.7 s)."""
    if factor == 1.0:
        return net
    return dataclasses.replace(net, law_y=net.law_y * factor, node_contact_area=net.node_contact_area * factor,
                               el_compression=net.el_compression * factor)


def _load_scale(net) -> float:
    """The nodal load scale [N]: the largest applied nodal force or element weight."""
    return max(np.max(np.abs(net.node_force)), np.max(net.el_weight * net.el_length), 1.0)


def _relaxed_equilibrium(net, case, velocity, friction, time):
    """The fallback where :func:`_equilibrium` fails: dynamic relaxation (:mod:`kanat.lumped.relaxation`)
    of the line softened to RELAXATION_STIFFNESS, its seabed contact with it (:func:`_scaled`), from
    the still-water catenaries (or the network's guess) down to RELAXATION_TARGET of the load scale,
    then the stiffness continuation of :func:`_equilibrium_from` from there, each stage by Newton's
    method (:func:`_solve`), relaxed again at its own stiffness first where Newton's method does not
    converge from the last.

    Returns as :func:`_solve`, with ``fallback = "dynamic relaxation"`` and the relaxation's
    ``relaxation_steps`` in the info."""
    from kanat.lumped.catenary_guess import catenary_guess

    x0 = catenary_guess(net, case)
    x = np.array(net.x_guess if x0 is None else x0, dtype=float)
    if velocity is None:
        velocity = LumpedSystem(net, case, waves=False).frame_velocity()
    stiffest = float(np.max(np.abs(net.law_y))) if net.law_y.size else 0.0
    factor = min(1.0, RELAXATION_STIFFNESS / stiffest) if stiffest > 0.0 else 1.0
    target = RELAXATION_TARGET * _load_scale(net)
    x, steps = _relaxed(_scaled(net, factor), case, x, velocity, friction, time, target)
    stages = [factor * 10.0**k for k in range(int(np.ceil(np.log10(1.0 / factor))))] + [1.0]
    for k, stage in enumerate(stages):
        stage_net = _scaled(net, stage)
        try:
            x, info = _solve(stage_net, case, x, velocity, STAGE_ITERATIONS, taut=(k == 0), friction=friction,
                             time=time)
        except SolverError:
            x, more = _relaxed(stage_net, case, x, velocity, friction, time, RETRY_TARGET * target)
            steps += more
            x, info = _solve(stage_net, case, x, velocity, MAX_ITERATIONS, friction=friction, time=time)
    return x, {**info, "first_guess": "catenary" if x0 is not None else "network",
               "fallback": "dynamic relaxation", "relaxation_steps": steps, "continuation_stages": len(stages)}


def _relaxed(net, case, x, velocity, friction, time, target):
    """``(x, steps)``: all nodes' positions (n, 3) after dynamic relaxation of ``net`` from ``x``
    down to a largest force of ``target`` [N] (or its step limit), and the steps it took."""
    system = LumpedSystem(net, case, waves=False, steady_velocity=velocity, steady_time=time, friction=friction)
    forces, free = _SteadyForces(system), system.free_index
    colour, neighbours = distance2_colouring(net), node_graph(net)
    step = FD_STEP * np.min(net.el_length)

    def force(q):
        return forces.force(0.0, q)

    relaxed = relax(force, lambda q: _jacobian_entries(force, free, q, colour, step, neighbours), x[free], target)
    x = x.copy()
    x[free] = relaxed.position
    return x, relaxed.steps


def relaxation_note(info: dict) -> str:
    """The run's note that its initial equilibrium came from the dynamic-relaxation fallback."""
    return (f"initial equilibrium by dynamic relaxation ({info['relaxation_steps']} steps of the line softened "
            f"to {RELAXATION_STIFFNESS:g} N, then Newton's method over {info['continuation_stages']} stiffness "
            f"stages; residual {info['residual']:.3g} N): "
            + ("tried first, as for every network with spherical inline floats" if info.get("relaxation_reason")
               else "Newton's method alone did not converge"))


def first_guess(net, case):
    """The start of the equilibrium without positions given: ``(x, source)``, the first of
    :func:`statics_guess` (``"statics"``), the still-water catenaries of network statics
    (:func:`kanat.lumped.catenary_guess.catenary_guess`, ``"catenary"``), the network's own guess
    with its free tails trailing at the critical angle of the relative flow
    (:func:`kanat.lumped.tow_guess.free_tail_guess`, ``"free tail"``: a towed array, whose tail the
    network's guess hangs at 45 degrees; plumb in still water; on the seabed from where a heavy tail reaches
    it; afloat where a buoyant tail reaches the surface, a SolverError where it would float on still water), or None for the network's own guess ``net.x_guess``
    (``"network"``).

    A case that the statics front door would solve as a network
    (:func:`kanat.model.support.needs_network`, other than one cable in a current) goes to the
    catenaries straight away: the front door's answer there is network statics of the same
    still-water catenaries (or a refusal of the current, whose drag the catenary guess
    carries), and asking it first costs its solvers' imports (SciPy's ``integrate`` and
    ``optimize``: 0.2-0.3 s of CPU per process)."""
    from kanat.lumped.catenary_guess import catenary_guess
    from kanat.model.support import has_drag, needs_network, single_cable

    network = needs_network(case) and not (has_drag(case) and single_cable(case))
    x = None if network else statics_guess(net, case)
    if x is not None:
        return x, "statics"
    x = catenary_guess(net, case)
    if x is not None:
        return x, "catenary"
    x = free_tail_guess(net, case, net.x_guess, LumpedSystem(net, case, waves=False).frame_velocity())
    return (x, "free tail") if x is not None else (None, "network")


def statics_guess(net, case):
    """Node positions from the 2-D statics solver (:func:`kanat.statics.solve_statics`) when the
    case is one it takes (planar single cables ending at the vessel, anchors or bodies), else
    None: a far better start than the network's straight guess for a long towed cable."""
    from kanat.statics import solve_statics
    flexible = {name: line.model_copy(update={"bending_stiffness": 0.0}) for name, line in case.line_types.items()}
    try:                         # the flexible line's shape (statics of a line with EI is this equilibrium)
        result = solve_statics(case.model_copy(update={"line_types": flexible}))
    except Exception:                                        # networks, free ends, 3-D loads: no guess
        return None
    x = net.x_guess.copy()
    for name, solution in result.cables.items():
        nodes = net.node_index[net.node_cable == name]
        if len(nodes) != len(solution.s):
            return None
        x[nodes] = solution.position
    return x if np.all(np.isfinite(x)) else None


def _solve(net, case, x0, velocity, max_iterations, taut=True, friction=True, time=0.0):
    """Static equilibrium of the network, eq. (1), from ``x0`` (or the network's guess), by the
    taut phase first (when ``taut``), then pseudo-transient Newton.

    Parameters
    ----------
    net : kanat.lumped.network.Network
    case : kanat.model.Case
    x0 : ndarray, shape (n, 3), optional
        Starting positions (default: the network's guess).
    velocity : ndarray, shape (3,), optional
        Steady velocity of every node (default: the track's at t = 0,
        :meth:`~kanat.lumped.system.LumpedSystem.frame_velocity`, or zero).
    max_iterations : int
    taut : bool
        Try :func:`_taut_phase` first (the continuation's stages do not: it failed directly).
    friction : bool
        False: without the seabed's friction (:func:`starting_state`).
    time : float
        The prescribed motion's time whose place the vessel's points take (the track's stays at 0).

    Returns
    -------
    x : ndarray, shape (n, 3)
        Equilibrium positions (prescribed nodes at their t = 0 places).
    info : dict
        ``iterations``, ``residual`` [N], ``taut_iterations`` (those of the taut phase that
        solved it, or 0); ``loads`` (n, 3), the nodal forces at the solution
        (eq. (1) without inertia: the prescribed nodes' are the pull they must resist), and
        ``normal_force`` (n,), the seabed's push on each node [N].

    Raises
    ------
    SolverError
        If the iteration does not converge, naming the node with the largest residual.
    """
    if velocity is None:
        velocity = LumpedSystem(net, case, waves=False).frame_velocity()
    system = LumpedSystem(net, case, waves=False, steady_velocity=velocity, steady_time=time, friction=friction)
    forces = _SteadyForces(system)
    free = system.free_index
    colour = distance2_colouring(net)
    neighbours = node_graph(net)
    xf = np.array((net.x_guess if x0 is None else x0)[free], dtype=float)
    if not len(free):                                   # every node prescribed: nothing to balance
        return _finish(net, system, xf, 0, {"taut_iterations": 0})
    tolerance = _tolerance(net, xf)
    length = np.min(net.el_length)
    step = FD_STEP * length
    solver = band_solver(free, neighbours)
    solved = _taut_phase(net, case, system, forces, xf, tolerance, colour, neighbours, solver) if taut else None
    if solved is not None:
        return _finish(net, system, *solved)
    dtau = INITIAL_PSEUDO_PERIOD * np.sqrt(np.max(net.el_length) * len(net.el_length) / case.environment.gravity)
    F, M = forces(0.0, xf)
    norm = np.max(np.abs(F))
    for iteration in range(1, max_iterations + 1):
        if norm <= tolerance:
            break
        budget.check_time()
        J = _jacobian_entries(lambda q: forces.force(0.0, q), free, xf, colour, step, neighbours)
        trials = [t for t in (_pseudo_transient(J, solver, M, F, xf, forces, length, dtau, norm),
                              _newton(J, solver, F, xf, forces, length)) if t is not None]
        trial = min(trials, key=lambda t: np.max(np.abs(t[1]))) if trials else None   # the better of the two
        if trial is None:
            dtau *= 0.25
            continue
        dx, F_new, M_new = trial
        norm_new = np.max(np.abs(F_new))
        xf, F, M = xf + dx, F_new, M_new
        growth = norm / max(norm_new, 1e-300)
        if abs(growth - 1.0) < STALL:             # a stalled pseudo-time (slack parts merely sinking): longer steps
            growth = STALL_GROWTH
        dtau *= min(max(growth, 0.5), 10.0)
        norm = norm_new
    else:
        worst = system.free_index[int(np.argmax(np.abs(F).sum(axis=1)))]
        raise SolverError(f"the initial equilibrium did not converge in {max_iterations} iterations "
                          f"(largest force residual {norm:.3g} N near {net.where(worst)}); give bodies "
                          "and points a 'position' near their expected place, or use "
                          "simulation.initial_state: as_given")
    return _finish(net, system, xf, iteration, {"taut_iterations": 0})


def _taut_phase(net, case, system, forces, xf, tolerance, colour, neighbours, solver):
    """:func:`kanat.lumped.taut_newton.taut_newton` from ``xf``: ``(xf, iterations, info)`` or None."""
    free = system.free_index
    stiffness = onset_stiffness(net)
    zero = np.zeros_like(xf)

    def taut_forces(q):
        F = forces.force(0.0, q)
        return F + compression_forces(net, system.full(0.0, q, zero)[0], stiffness)[free]

    def jacobian(q):
        rows, cols, values = _jacobian_entries(taut_forces, free, q, colour, FD_STEP * np.min(net.el_length),
                                               neighbours)
        return rows, cols, -values

    def newton_step(q, F):                                   # -J step = F_taut
        step = solver.solve(*jacobian(q), F.ravel())
        return None if step is None else step.reshape(-1, 3)

    solved = taut_newton(lambda q: forces.force(0.0, q), newton_step, xf, tolerance,
                         MAX_STEP_FRACTION * np.min(net.el_length), SeabedGuard(net, case, free), taut_forces)
    if solved is None:
        return None
    return solved[0], solved[1], {"taut_iterations": solved[1]}


def _finish(net, system, xf, iterations, extra):
    """The equilibrium's positions (n, 3) and info (:func:`_solve`)."""
    x = net.x_guess.copy()
    x[system.free_index] = xf
    system.prescribed(0.0, x, np.zeros_like(x))
    full, v, _, heading = system.full(0.0, xf, np.zeros_like(xf))
    loads, _ = system.loads(0.0, full, v, heading)
    residual = float(np.max(np.abs(loads[system.free_index]), initial=0.0))
    return x, {"iterations": iterations, "residual": residual, "loads": loads,
               "normal_force": system.normal_force.copy(), **extra}


def starting_state(net, case, system) -> tuple[np.ndarray, np.ndarray]:
    """A dynamic run's first state: positions and velocities (n, 3) of every node, at rest in the
    equations of motion the run integrates (theory/moorings.md, the consistent start).

    * The positions are the equilibrium at the prescribed motion's place at ``t = 0``, in the frame
      moving with the track (:meth:`LumpedSystem.frame_velocity`), **without seabed friction**: the
      run's friction is regularized in velocity (:mod:`kanat.physics.contact`, eqs. 3-4) and
      vanishes at rest, so a state held by friction (the MoorPy equilibrium of ``kanat statics``)
      would start with unbalanced forces where the line lies on the seabed (4.3 m/s^2 on MoorDyn's
      WD0050 chain, friction 0.5), as MoorDyn's own start, relaxed with its velocity friction, has
      none either.
    * The velocities are the frame's, plus, under a prescribed motion, the quasi-static response to
      the motion's velocity at ``t = 0``: the central difference of the equilibria at the motion's
      places ``STARTING_DIFFERENCE`` before and after ``t = 0``. A line whose fairlead starts moving
      then starts moving with it (anchor at rest, the fairlead's neighbours nearly at its speed)
      rather than every node at the fairlead's velocity, or none.

    Raises
    ------
    SolverError
        As :func:`equilibrium`.
    """
    return starting_state_info(net, case, system)[:2]


def starting_state_info(net, case, system) -> tuple[np.ndarray, np.ndarray, dict]:
    """:func:`starting_state` and the info of its equilibrium (:func:`_solve`'s; ``fallback`` says
    whether dynamic relaxation found it)."""
    x, info = equilibrium(net, case, friction=False)          # in the track's frame (_solve's default)
    v = np.zeros_like(x)
    v[:] = system.frame_velocity()
    if system.motion is not None:
        delta = STARTING_DIFFERENCE
        ahead = equilibrium(net, case, x0=x, friction=False, time=delta)[0]
        behind = equilibrium(net, case, x0=x, friction=False, time=-delta)[0]
        v = (ahead - behind) / (2.0 * delta)
    return x, v, info
