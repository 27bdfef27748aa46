"""The linear model a frequency-domain run solves, assembled about the lumped equilibrium.

On top of the linearisation ``M u'' + C u' + K u = f`` of the free nodes
(:mod:`kanat.frequency.linearize` eq. 1), the prescribed (vessel) nodes' displacements ``u_p``
force the free ones through the time domain's own forces (:mod:`kanat.lumped.system` eq. 1,
``M q'' = F(q, q', q_p, q_p') - M_qp a_p``)::

    (1)  f = (G + i omega G_v + omega^2 M_qp) u_p,   G = dF/dq_p,  G_v = dF/dq_p'

``G`` and ``G_v`` by central differences of ``F`` (steps of the linearisation), ``M_qp`` the
consistent mass's blocks between free and prescribed nodes (zero for the lumped mass). An element's
tension (kernels eqs. 1-2, ``T = f(e) + C_E2 e_dot``) varies with its length ``l`` and its rate as::

    (2)  T_hat = (dT/dl + i omega dT/dl_dot) t . (u_j - u_i)

the slopes by central differences of the time domain's tension under a uniform stretch of all
positions (``x (1 +- eps)``: every element's length changes by ``+- eps l``) and a uniform
stretching velocity (``v +- eps x``).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from kanat.frequency import drag
from kanat.frequency.bodies import BodyWaves, body_waves
from kanat.frequency.linearize import POSITION_STEP, VELOCITY_STEP, Linearization, linearize
from kanat.frequency.pairs import PairMaps, line_and_body_pairs
from kanat.frequency.rigid import euler_rates_matrix
from kanat.lumped import kernels
from kanat.lumped.output import NodeTension
from kanat.lumped.system import LumpedSystem

STRETCH_STEP = 1e-7     # relative change of every element's length for dT/dl (eq. 2)


@dataclass(frozen=True, eq=False)
class LinearModel:
    """Everything a frequency-domain solve needs (module docstring).

    Attributes
    ----------
    lin : Linearization
    prescribed : ndarray of int, shape (p,)
        The vessel nodes; ``arms`` (p, 3) their lever arms in vessel axes [m].
    heading : float
        The vessel's heading at t = 0 [rad].
    coupling, coupling_rate, coupling_mass : scipy.sparse.csr_matrix, shape (n_dof, 3 p)
        ``G`` [N/m], ``G_v`` [N s/m] and ``M_qp`` [kg] of eq. (1).
    pairs : kanat.frequency.drag.DragPairs
        The lines', point bodies' and 6-DOF bodies' drag (:mod:`kanat.frequency.pairs`).
    maps : kanat.frequency.pairs.PairMaps
        Where each pair acts in the linear system.
    drag_at_mean : scipy.sparse.csr_matrix, shape (n_dof, n_dof)
        The drag's slope about the mean flow, assembled (part of ``lin.damping``).
    stiffness_slope, rate_slope : ndarray, shape (m,)
        ``dT/dl`` [N/m] and ``dT/dl_dot`` [N s/m] of eq. (2).
    tangent : ndarray, shape (m, 3)
    mean_tension : ndarray, shape (m,)
        The elements' tension at the equilibrium [N].
    node_tension : kanat.lumped.output.NodeTension
        Element to output-node tensions (the result files' ``tension``).
    contact_force : ndarray, shape (n,)
        The seabed's normal force on each node at the equilibrium [N].
    waterplane_dof, waterplane_stiffness : ndarray, shape (b,)
        The surface buoys' vertical degree of freedom and ``rho g A_w`` [N/m] (zero for a buoy
        whose immersion is at 0 or its height at the equilibrium: its waterplane force is clipped);
        ``waterplane_place`` (b, 2) their keels' x, y [m]. A wave of elevation ``eta`` at the keel
        lifts the buoy by ``rho g A_w eta`` (:meth:`kanat.lumped.system.LumpedSystem.loads`).
    bodies : kanat.frequency.bodies.BodyWaves
        The 6-DOF bodies' wave excitation (Froude-Krylov, added mass, a surface-piercing body's
        waterplane).
    """

    lin: Linearization
    prescribed: np.ndarray
    arms: np.ndarray
    heading: float
    coupling: sp.csr_matrix
    coupling_rate: sp.csr_matrix
    coupling_mass: sp.csr_matrix
    pairs: drag.DragPairs
    maps: PairMaps
    drag_at_mean: sp.csr_matrix
    stiffness_slope: np.ndarray
    rate_slope: np.ndarray
    tangent: np.ndarray
    mean_tension: np.ndarray
    node_tension: NodeTension
    contact_force: np.ndarray
    waterplane_dof: np.ndarray
    waterplane_stiffness: np.ndarray
    waterplane_place: np.ndarray
    bodies: BodyWaves

    @property
    def size(self) -> int:
        return self.lin.mass.shape[0]


def linear_model(case) -> LinearModel:
    """The :class:`LinearModel` of a case (its lumped network about the equilibrium)."""
    lin = linearize(case)
    net, x = lin.net, lin.position
    steady = LumpedSystem(net, case, waves=False, friction=False)
    frame = steady.frame_velocity()
    steady = LumpedSystem(net, case, waves=False, steady_velocity=frame, friction=False)
    moving = LumpedSystem(net, case, waves=False, friction=False)
    free = steady.free_index
    xs, vs, _, heading = steady.full(0.0, x[free], np.zeros_like(x[free]))
    steady.loads(0.0, xs, vs, heading)
    wet, strain, tension = steady.wet.copy(), steady.strain.copy(), steady.tension.copy()
    contact_force = steady.normal_force.copy()
    v0 = np.broadcast_to(frame, x[free].shape).copy()
    v0[np.searchsorted(free, net.rigid.rot_node)] = 0.0
    xm, vm, _, heading_m = moving.full(0.0, x[free], v0)
    prescribed = np.asarray(net.vessel_nodes, dtype=np.int64)
    step = POSITION_STEP * float(np.min(net.el_length))
    G = _coupling(lambda xx: steady.loads(0.0, xx, vs, heading)[0][free], xs, prescribed, step)
    Gv = _coupling(lambda vv: moving.loads(0.0, xm, vv, heading_m)[0][free], vm, prescribed, VELOCITY_STEP)
    pairs, maps = line_and_body_pairs(net, x, free, wet, strain, lambda p: case.environment.current.at(p[:, 2]),
                                      frame, rho=case.environment.water_density)
    slope = _slope(lambda xx: steady.loads(0.0, xx, vs, heading), lambda: steady.tension, xs, STRETCH_STEP)
    rate = _slope(lambda vv: moving.loads(0.0, xm, vv, heading_m), lambda: moving.tension, vm, VELOCITY_STEP,
                  about=xm)
    d = x[net.el_j] - x[net.el_i]
    length = np.linalg.norm(d, axis=1)
    consistent = case.simulation is not None and case.simulation.mass_matrix == "consistent"
    return LinearModel(
        lin=lin, prescribed=prescribed, arms=np.asarray(net.vessel_offset, float).reshape(-1, 3),
        heading=float(heading), coupling=G, coupling_rate=Gv,
        coupling_mass=_coupling_mass(net, x, free, prescribed, consistent),
        pairs=pairs, maps=maps, drag_at_mean=maps.assemble(drag.tangent_at_mean(pairs)),
        stiffness_slope=slope / length, rate_slope=rate / length, tangent=d / length[:, None],
        mean_tension=tension, node_tension=NodeTension(net), contact_force=contact_force,
        bodies=body_waves(net.rigid, free, x), **_waterplanes(net, x, free, case.environment))


def _waterplanes(net, x: np.ndarray, free: np.ndarray, environment) -> dict:
    """The surface buoys' fields of :class:`LinearModel` at positions ``x`` (n, 3), the mean
    surface at z = 0."""
    node = np.asarray(net.body_node, dtype=np.int64)[np.asarray(net.buoy_body, dtype=np.int64)]
    immersion = -x[node, 2]
    inside = (immersion > 0.0) & (immersion < net.buoy_height)
    stiffness = environment.water_density * environment.gravity * np.asarray(net.buoy_area, float) * inside
    return dict(waterplane_dof=3 * np.searchsorted(free, node) + 2, waterplane_stiffness=stiffness,
                waterplane_place=x[node, :2].copy())


def _coupling(forces, base: np.ndarray, prescribed: np.ndarray, step: float) -> sp.csr_matrix:
    """``dF_free/d(base[prescribed])`` by central differences, shape (n_dof, 3 p)."""
    columns = []
    for node in prescribed:
        for r in range(3):
            up, down = base.copy(), base.copy()
            up[node, r] += step
            down[node, r] -= step
            columns.append((forces(up).ravel() - forces(down).ravel()) / (2.0 * step))
    size = forces(base).size
    return sp.csr_matrix(np.array(columns).T if columns else np.zeros((size, 0)))


def _slope(loads, tension, base: np.ndarray, eps: float, about: np.ndarray | None = None) -> np.ndarray:
    """``dT/d(eps)`` (m,) under ``base (1 + eps)`` (positions) or ``base + eps about`` (velocities)."""
    about = base if about is None else about
    loads(base + eps * about)
    up = tension().copy()
    loads(base - eps * about)
    down = tension().copy()
    return (up - down) / (2.0 * eps)


def _coupling_mass(net, x, free, prescribed, consistent: bool) -> sp.csr_matrix:
    """``M_qp`` of eq. (1): the consistent mass's element blocks joining a free and a prescribed node."""
    size, columns = 3 * len(free), 3 * len(prescribed)
    if not consistent or not len(prescribed):
        return sp.csr_matrix((size, columns))
    B = np.empty((net.n_elements, 3, 3))
    kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
    row = -np.ones(net.n_nodes, dtype=np.int64)
    row[free] = np.arange(len(free))
    col = -np.ones(net.n_nodes, dtype=np.int64)
    col[prescribed] = np.arange(len(prescribed))
    dense = np.zeros((size, columns))
    for k, (i, j) in enumerate(zip(net.el_i, net.el_j)):
        for a, b in ((i, j), (j, i)):
            if row[a] >= 0 and col[b] >= 0:
                dense[3 * row[a]:3 * row[a] + 3, 3 * col[b]:3 * col[b] + 3] += B[k]
    return sp.csr_matrix(dense)


def node_displacements(model: LinearModel, free_motion: np.ndarray, prescribed_motion: np.ndarray) -> np.ndarray:
    """All nodes' complex displacements (nf, n, 3) from the free DOFs' (nf, n_dof) and the vessel
    nodes' (nf, p, 3): anchors at rest, 6-DOF bodies' fairleads moved with their bodies
    (``u_ref + (E(Theta) u_Theta) x arm``, :mod:`kanat.frequency.rigid`)."""
    lin = model.lin
    net, x = lin.net, lin.position
    nf = free_motion.shape[0]
    U = np.zeros((nf, net.n_nodes, 3), complex)
    U[:, lin.node, lin.xyz] = free_motion
    U[:, model.prescribed] = prescribed_motion
    rigid = net.rigid
    for f, node in enumerate(rigid.fairlead_node):
        b = rigid.fairlead_body[f]
        ref, rot = rigid.ref_node[b], rigid.rot_node[b]
        turn = U[:, rot] @ euler_rates_matrix(x[rot]).T
        U[:, node] = U[:, ref] + np.cross(turn, x[node] - x[ref])
    return U


def element_tension(model: LinearModel, U: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Complex element tensions (nf, m) of eq. (2) from the nodes' displacements (nf, n, 3)."""
    net = model.lin.net
    stretch = np.einsum("fmr,mr->fm", U[:, net.el_j] - U[:, net.el_i], model.tangent)
    return (model.stiffness_slope[None, :] + 1j * omega[:, None] * model.rate_slope[None, :]) * stretch


def node_tension(model: LinearModel, elements: np.ndarray) -> np.ndarray:
    """The output nodes' values (..., node) of element values (..., m): the result files' weights
    (:class:`kanat.lumped.output.NodeTension`, without its clip at zero)."""
    weights = model.node_tension
    return weights.wa * elements[..., weights.ia] + weights.wb * elements[..., weights.ib]
