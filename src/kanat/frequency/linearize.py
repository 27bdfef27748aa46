"""The lumped system linearised about its equilibrium (docs/frequency.md).

With ``q`` the free node positions and ``q_e`` the lumped model's equilibrium
(:func:`kanat.lumped.equilibrium.equilibrium`, without seabed friction) about the vessel's mean
place (:func:`about_mean`), small motions ``u = q - q_e`` obey::

    (1)  M u_ddot + C u_dot + K u = f(t)
    (2)  M = the time domain's mass at q_e,   K = -dF/dq (q_e, q_dot_e),   C = -dF/dq_dot (q_e, q_dot_e)

``F`` the free nodes' forces of :class:`kanat.lumped.system.LumpedSystem` (eqs. 1-2 there:
elastic, geometric, bending, weight and buoyancy, seabed contact, point bodies' loads and
waterplane buoyancy; 6-DOF bodies' forces and moments, :mod:`kanat.frequency.rigid`); ``M`` the lumped blocks (structural + added mass turned with each
element, :mod:`kanat.lumped.kernels` eq. 8) or the consistent matrix (eq. 9) as
``simulation.mass_matrix`` says. ``K`` and ``C`` are sparse Jacobians by central differences
over a distance-2 colouring of the node graph (``3 x colours`` pairs of force evaluations,
:func:`kanat.lumped.equilibrium._jacobian`), of steps :data:`POSITION_STEP` and
:data:`VELOCITY_STEP`: ``K`` thus holds the tangent of every static load, exactly as the
equilibrium's Newton iteration sees it. ``C`` is the axial (Kelvin–Voigt) damping and the tangent
of drag about the mean relative flow: zero in still water, where drag is quadratic
(``|u| u`` has no slope at ``u = 0``); drag's equivalent linearisation is not in ``C``.

The equilibrium is the one the motion oscillates about (:func:`about_mean`): a current with a
start-up ``ramp`` at its full speed, not at its ramp's zero at t = 0, and the vessel at the mean
place of its harmonic or RAO motion, not at the motion's t = 0 place where a time-domain run
starts (a 1 m surge starting at -1 m would otherwise be linearised at one end of its stroke).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from kanat.frequency.rigid import rigid_rows
from kanat.lumped import kernels
from kanat.lumped.equilibrium import _jacobian, distance2_colouring, equilibrium, node_graph
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem

POSITION_STEP = 1e-7   # of the shortest element: the equilibrium's own finite-difference step
VELOCITY_STEP = 1e-6   # m/s: F is linear in velocity but for drag, whose central difference at rest
                       # is 1/2 rho C_D d l x VELOCITY_STEP (~1e-6 of the axial damping) instead of 0


@dataclass(frozen=True, eq=False)
class Linearization:
    """Eq. (1) over the free degrees of freedom of a lumped network.

    Attributes
    ----------
    mass, damping, stiffness : scipy.sparse.csr_matrix, shape (n_dof, n_dof)
        ``M`` [kg], ``C`` [N s/m], ``K`` [N/m] of eq. (2).
    node : ndarray of int, shape (n_dof,)
        The network node of each degree of freedom (``net`` numbering).
    xyz : ndarray of int, shape (n_dof,)
        Its direction: 0, 1, 2 for x, y, z (global axes, z up).
    position : ndarray, shape (n_nodes, 3)
        The equilibrium's node positions [m].
    net : kanat.lumped.network.Network
        The network (cable and node names: ``net.where(node)``).
    """

    mass: sp.csr_matrix
    damping: sp.csr_matrix
    stiffness: sp.csr_matrix
    node: np.ndarray
    xyz: np.ndarray
    position: np.ndarray
    net: object

    @property
    def asymmetry(self) -> float:
        """``||K - K^T|| / ||K||`` (Frobenius): non-zero where loads follow the line (drag in a
        current, a tow's flow), zero for conservative loads up to finite-difference round-off."""
        K = self.stiffness
        return float(sp.linalg.norm(K - K.T) / max(sp.linalg.norm(K), 1e-300))


def linearize(case) -> Linearization:
    """Mass, damping and stiffness of a lumped case about its equilibrium, eqs. (1)-(2).

    Parameters
    ----------
    case : kanat.model.Case
        Any case the lumped model runs (its ``model`` need not be ``lumped``); waves are left
        out (the linearisation is about the mean surface).

    Returns
    -------
    Linearization

    Raises
    ------
    SolverError
        If the equilibrium does not converge (:func:`kanat.lumped.equilibrium.equilibrium`).
    """
    case = about_mean(case)
    net = build_network(case)
    x, _ = equilibrium(net, case, friction=False)
    base = LumpedSystem(net, case, waves=False, friction=False)
    velocity = base.frame_velocity()
    steady = LumpedSystem(net, case, waves=False, steady_velocity=velocity, friction=False)
    free = steady.free_index
    xf = x[free]
    colour, neighbours = distance2_colouring(net), node_graph(net)

    def static_forces(q):
        full, v, _, heading = steady.full(0.0, q, np.zeros_like(q))
        return steady.loads(0.0, full, v, heading)[0][free].copy()

    def moving_forces(vf):
        full, v, _, heading = base.full(0.0, xf, vf)
        return base.loads(0.0, full, v, heading)[0][free].copy()

    step = POSITION_STEP * float(np.min(net.el_length))
    stiffness = -_jacobian(static_forces, free, xf, colour, step, neighbours)
    v0 = np.broadcast_to(velocity, xf.shape).copy()
    v0[np.searchsorted(free, net.rigid.rot_node)] = 0.0                 # Euler angle rates
    damping = -_jacobian(moving_forces, free, v0, colour, VELOCITY_STEP, neighbours)
    consistent = case.simulation is not None and case.simulation.mass_matrix == "consistent"
    mass = mass_matrix(steady, x, consistent)
    if net.rigid.count:
        full, v, _, heading = steady.full(0.0, xf, np.zeros_like(xf))
        blocks = steady.loads(0.0, full, v, heading)[1].copy()
        mass, damping, stiffness = rigid_rows(net.rigid, free, x, blocks, mass, damping, stiffness)
    return Linearization(mass=mass.tocsr(), damping=damping.tocsr(), stiffness=stiffness.tocsr(),
                         node=np.repeat(free, 3), xyz=np.tile(np.arange(3), len(free)), position=x, net=net)


def about_mean(case):
    """The case whose equilibrium the system is linearised about (module docstring): its current at
    full speed from t = 0 (``environment.current.ramp`` 0) and its vessel on its track without the
    prescribed motion (whose harmonics and RAO motion oscillate about that place), on the seabed the
    lumped model applies (:meth:`kanat.model.Case.with_seabed_contact`)."""
    case = case.with_seabed_contact()
    current = case.environment.current
    if current.ramp != 0.0:
        environment = case.environment.model_copy(update={"current": current.model_copy(update={"ramp": 0.0})})
        case = case.model_copy(update={"environment": environment})
    motion = case.vessel.motion
    if motion.harmonics or motion.rao_rows is not None:
        still = motion.model_copy(update={"harmonics": (), "rao": None, "rao_rows": None})
        case = case.model_copy(update={"vessel": case.vessel.model_copy(update={"motion": still})})
    return case


def after_ramps(case):
    """The case with its current at full speed from t = 0 (``environment.current.ramp`` 0): the
    steady state the excitation acts in, the current's ramp ended."""
    current = case.environment.current
    if current.ramp == 0.0:
        return case
    environment = case.environment.model_copy(update={"current": current.model_copy(update={"ramp": 0.0})})
    return case.model_copy(update={"environment": environment})


def mass_matrix(system: LumpedSystem, x: np.ndarray, consistent: bool) -> sp.csr_matrix:
    """The time domain's mass matrix over the free nodes at positions ``x`` (n, 3), shape
    (3 n_free, 3 n_free): lumped blocks of :meth:`LumpedSystem.loads` (kernels eq. 8), or the
    consistent matrix (kernels eq. 9: element blocks ``B`` as ``[[2B, B], [B, 2B]]`` plus the
    point masses)."""
    net, free = system.net, system.free_index
    if not consistent:
        _, v, _, heading = system.full(0.0, x[free], np.zeros_like(x[free]))
        blocks = system.loads(0.0, x, v, heading)[1][free]
        return sp.block_diag(list(blocks), format="csr")
    B = np.empty((net.n_elements, 3, 3))
    kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free] = np.arange(len(free))
    rows, cols, vals = [], [], []

    def add(a, b, block):
        if position[a] >= 0 and position[b] >= 0:
            r, c = np.meshgrid(3 * position[a] + np.arange(3), 3 * position[b] + np.arange(3), indexing="ij")
            rows.extend(r.ravel())
            cols.extend(c.ravel())
            vals.extend(block.ravel())

    for k, (i, j) in enumerate(zip(net.el_i, net.el_j)):
        add(i, i, 2.0 * B[k])
        add(j, j, 2.0 * B[k])
        add(i, j, B[k])
        add(j, i, B[k])
    for node in free:
        add(node, node, system.node_mass[node] * np.eye(3))
    size = 3 * len(free)
    return sp.csr_matrix((vals, (rows, cols)), shape=(size, size))
