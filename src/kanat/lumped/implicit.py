"""One step of the generalized-α scheme for the lumped model (Chung & Hulbert 1993).

With ``(x, v, a)`` at ``t_n`` and the unknown ``a_1`` at ``t_n+1 = t_n + h``::

    (1)  x_1 = x + h v + h^2 ((1/2 - beta) a + beta a_1),   v_1 = v + h ((1 - gamma) a + gamma a_1)
    (2)  R(a_1) = M(x_m) [(1 - alpha_m) a_1 + alpha_m a] - F(t_m, x_m, v_m) = 0
         x_m = (1 - alpha_f) x_1 + alpha_f x,  v_m likewise,  t_m = t_n + (1 - alpha_f) h
    (3)  J = (1 - alpha_m) M + (1 - alpha_f) (gamma h C + beta h^2 K)

``K = -dF/dx`` and ``C = -dF/dv`` from the element tangent blocks
(:func:`kanat.lumped.kernels.tangent_blocks`: axial, geometric, Kelvin–Voigt, drag), the
body drag and the seabed contact (:func:`kanat.physics.contact.contact_tangent`); the added-mass, buoy and wave terms are left out of ``J`` (Newton then
converges linearly rather than quadratically, to the same answer). ``J`` is sparse with
the network's node graph; it is factorized at every iteration by LAPACK's band LU after a
reverse Cuthill–McKee order of the nodes (:class:`kanat.lumped.band_solve.NodeBandSolver`). An increment that
raises the residual's 2-norm is halved (the line search of
:func:`kanat.lumped.fast_implicit.newton_step`). A step whose
Newton iteration fails is halved, up to ``MAX_HALVINGS`` times (:class:`kanat.step_control.Halving`),
then the run stops with a :class:`~kanat.errors.SolverError` naming time, cable and node.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np
from kanat.errors import SolverError
from kanat.lumped import kernels
from kanat.lumped.band_solve import NodeBandSolver
from kanat.lumped.bending import bending_blocks
from kanat.lumped.fast_implicit import LINE_SEARCH_HALVINGS
from kanat.physics.contact import contact_tangent
from kanat.step_control import Halving, StepRefused, StepsExhausted

MAX_HALVINGS = 4          # a step is cut to at most 1/16 before the run is stopped
HALVING = Halving(MAX_HALVINGS)
ACCELERATION_SCALE = 1.0  # m/s^2 floor of the convergence scale (1/10 g)


class TangentPattern:
    """Row/column indices of the sparse Jacobian over the free degrees of freedom."""

    def __init__(self, net):
        dof = -np.ones(net.n_nodes, dtype=np.int64)
        dof[net.free] = np.arange(np.count_nonzero(net.free))
        self.size = 3 * np.count_nonzero(net.free)
        r3, c3 = np.meshgrid(np.arange(3), np.arange(3), indexing="ij")
        rows, cols, keep = [], [], []
        pairs = ((net.el_i, net.el_i), (net.el_i, net.el_j), (net.el_j, net.el_i), (net.el_j, net.el_j))
        for a, b in pairs:
            ra, cb = dof[a], dof[b]
            rows.append(3 * ra[:, None, None] + r3)
            cols.append(3 * cb[:, None, None] + c3)
            keep.append(np.broadcast_to(((ra >= 0) & (cb >= 0))[:, None, None], (len(a), 3, 3)))
        free_nodes = np.flatnonzero(net.free)
        rows.append(3 * dof[free_nodes][:, None, None] + r3)
        cols.append(3 * dof[free_nodes][:, None, None] + c3)
        keep.append(np.ones((len(free_nodes), 3, 3), dtype=bool))
        self.keep = np.concatenate([k.ravel() for k in keep])
        self.rows = np.concatenate([r.ravel() for r in rows])[self.keep]
        self.cols = np.concatenate([c.ravel() for c in cols])[self.keep]
        self.free_nodes = free_nodes
        neighbours = [{k} for k in range(len(free_nodes))]
        for i, j in zip(np.r_[dof[net.el_i], dof[net.bend[0]], dof[net.bend[0]], dof[net.bend[1]]].tolist(),
                        np.r_[dof[net.el_j], dof[net.bend[1]], dof[net.bend[2]], dof[net.bend[2]]].tolist()):
            if i >= 0 and j >= 0:                       # elements and bending triples join their nodes
                neighbours[i].add(j)
                neighbours[j].add(i)
        self.solver = NodeBandSolver(neighbours)

    def entries(self, element_blocks, node_blocks):
        """``(rows, cols, values)`` of the matrix made of ``element_blocks`` (4, m, 3, 3) for
        (ii, ij, ji, jj) and ``node_blocks`` (n_free, 3, 3) on the diagonal."""
        data = np.concatenate([element_blocks.ravel(), node_blocks.ravel()])[self.keep]
        return self.rows, self.cols, data


def _pattern(system) -> TangentPattern:
    if getattr(system, "_pattern", None) is None:
        system._pattern = TangentPattern(system.net)
    return system._pattern


def jacobian(system, t, x, v, c_mass, c_damp, c_stiff, M_blocks):
    """``c_mass M + c_damp C + c_stiff K`` over the free DOFs (eq. 3), a SciPy sparse CSC matrix
    (:func:`jacobian_entries`'s; SciPy's sparse package is imported here only)."""
    import scipy.sparse as sp

    rows, cols, values = jacobian_entries(system, t, x, v, c_mass, c_damp, c_stiff, M_blocks)
    size = _pattern(system).size
    return sp.csc_matrix((values, (rows, cols)), shape=(size, size))


def jacobian_entries(system, t, x, v, c_mass, c_damp, c_stiff, M_blocks):
    """``c_mass M + c_damp C + c_stiff K`` over the free DOFs (eq. 3) as ``(rows, cols, values)``
    (repeated entries summed)."""
    net = system.net
    m = net.n_elements
    K, C, D = np.empty((m, 3, 3)), np.empty((m, 3, 3)), np.empty((m, 3, 3))
    uw = system.water(t, 0.5 * (x[net.el_i] + x[net.el_j]))[0]
    kernels.tangent_blocks(x, v, uw, system.el_args, K, C, D)
    diag = c_stiff * K + c_damp * (C + D)
    off = -c_stiff * K - c_damp * C                 # drag: each end's on its own velocity (D on ii, jj)
    pattern = _pattern(system)
    if system.consistent:
        B = np.empty((m, 3, 3))
        kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
        diag, off = diag + 2.0 * c_mass * B, off + c_mass * B
        node = c_mass * system.node_mass[pattern.free_nodes, None, None] * np.eye(3)
    else:
        node = c_mass * M_blocks[pattern.free_nodes]
    node = node + c_damp * _body_damping(system, t, x, v)[pattern.free_nodes]
    seabed = system.contact
    if seabed is not None:                         # seabed contact (kanat.physics.contact)
        Kc, Cc = np.zeros((net.n_nodes, 3, 3)), np.zeros((net.n_nodes, 3, 3))
        contact_tangent(x, v, seabed.area, seabed.seabed, seabed.law, system.normal_force, system._tangent, Kc, Cc)
        node = node + (c_stiff * Kc + c_damp * Cc)[pattern.free_nodes]
    rows, cols, values = pattern.entries(np.stack([diag, off, off, diag]), node)
    bend_rows, bend_cols, bend_values = _bending(system, x)
    return np.r_[rows, bend_rows], np.r_[cols, bend_cols], np.r_[values, c_stiff * bend_values]


def _bending(system, x):
    """The bending's Gauss-Newton tangent (:func:`kanat.lumped.bending.bending_blocks`, eq. 4) over
    the free DOFs as ``(rows, cols, values)``."""
    net = system.net
    before, node, after, k, _ = net.bend
    if not len(node):
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros(0)
    K = np.empty((len(node), 3, 3, 3, 3))
    bending_blocks(x, before, node, after, k, np.empty((3, 3, 3)), K)
    dof = -np.ones(net.n_nodes, dtype=np.int64)
    dof[system.free_index] = np.arange(len(system.free_index))
    nodes = dof[np.stack([before, node, after], -1)]                    # (triples, 3)
    r3 = np.arange(3)
    rows = 3 * nodes[:, :, None, None, None] + r3[None, None, None, :, None]
    cols = 3 * nodes[:, None, :, None, None] + r3[None, None, None, None, :]
    keep = np.broadcast_to((nodes[:, :, None] >= 0) & (nodes[:, None, :] >= 0), (len(node), 3, 3))
    keep = np.broadcast_to(keep[..., None, None], K.shape)
    rows, cols = np.broadcast_to(rows, K.shape), np.broadcast_to(cols, K.shape)
    return rows[keep], cols[keep], K[keep]


def _body_damping(system, t, x, v):
    """``-dF/dv`` of the body drag, per node (n, 3, 3)."""
    net = system.net
    out = np.zeros((net.n_nodes, 3, 3))
    if len(net.load_node):
        nodes = net.load_node
        ur = system.water(t, x[nodes])[0] - v[nodes]
        speed = np.linalg.norm(ur, axis=1)
        outer = np.einsum("kr,kq->krq", ur, ur) / np.maximum(speed, 1e-12)[:, None, None]
        k = 0.5 * system.rho * net.load_drag_area
        out[nodes] += k[:, None, None] * (speed[:, None, None] * np.eye(3) + outer)
    return out


def _residual(system, t, x, v, am_free, a_full):
    """``R = M a_m - F`` over the free nodes (eq. 2) and the lumped blocks."""
    heading = system.prescribed(t, x, v, a_full)
    F, M = system.loads(t, x, v, heading)
    net = system.net
    a_full[system.free_index] = am_free
    if system.consistent:
        B = np.empty((net.n_elements, 3, 3))
        kernels.consistent_blocks(x, net.el_i, net.el_j, net.el_length, net.el_mass, net.el_added_mass, B)
        y = np.empty_like(a_full)
        kernels.consistent_matvec(B, net.el_i, net.el_j, system.node_mass, a_full, y)
    else:
        y = np.einsum("nrq,nq->nr", M, a_full)
    return (y - F)[system.free_index], M


def _attempt(scheme, system, state, h):
    """One step of size ``h``; None when Newton fails. Returns (state, iterations)."""
    am, af, gamma, beta = scheme.coefficients
    t, x0, v0, a0 = state.t, state.x, state.v, state.a
    tm = t + (1.0 - af) * h
    n = system.net.n_nodes
    x, v, a_full = np.empty((n, 3)), np.empty((n, 3)), np.zeros((n, 3))
    a1 = a0.copy()
    last, norm_before, backtracks = np.zeros_like(a1), np.inf, 0
    for iteration in range(1, scheme.max_iterations + 1):
        x1 = x0 + h * v0 + h * h * ((0.5 - beta) * a0 + beta * a1)
        v1 = v0 + h * ((1.0 - gamma) * a0 + gamma * a1)
        x[system.free_index] = (1.0 - af) * x1 + af * x0
        v[system.free_index] = (1.0 - af) * v1 + af * v0
        R, M = _residual(system, tm, x, v, (1.0 - am) * a1 + am * a0, a_full)
        if not np.all(np.isfinite(R)):
            return None, iteration
        norm = float(np.sum(R * R))
        if norm > norm_before and backtracks < LINE_SEARCH_HALVINGS:    # the line search (fast_implicit)
            backtracks += 1
            last *= 0.5
            a1 = a1 - last
            continue
        norm_before, backtracks = norm, 0
        J = jacobian_entries(system, tm, x, v, 1.0 - am, (1.0 - af) * gamma * h, (1.0 - af) * beta * h * h, M)
        delta = _pattern(system).solver.solve(*J, -R.ravel())
        if delta is None:                                      # singular tangent
            return None, iteration
        delta = delta.reshape(-1, 3)
        a1, last = a1 + delta, delta
        scale = max(np.max(np.abs(a1)), ACCELERATION_SCALE)
        if np.max(np.abs(delta)) <= scheme.tolerance * scale:
            x1 = x0 + h * v0 + h * h * ((0.5 - beta) * a0 + beta * a1)
            v1 = v0 + h * ((1.0 - gamma) * a0 + gamma * a1)
            return replace(state, t=t + h, x=x1, v=v1, a=a1), iteration
    return None, scheme.max_iterations


def generalized_alpha_step(scheme, system, state, h):
    """Advance ``state`` by ``h`` (eqs. 1-3); a step whose Newton iteration fails is retaken in halves
    (:data:`HALVING`). The state's ``iterations`` and ``cuts`` count the work (:mod:`kanat.step_control`)."""
    def attempt(current, step):
        new, iterations = _attempt(scheme, system, current, step)
        if new is None:
            raise StepRefused(f"Newton did not converge in {scheme.max_iterations} iterations")
        return new, iterations

    try:
        new, work = HALVING.take(attempt, state, h)
    except StepsExhausted as exhausted:
        failed = exhausted.state
        worst = system.free_index[int(np.argmax(np.abs(failed.a).sum(axis=1)))]
        raise SolverError(
            f"{exhausted} at t = {failed.t:.6g} s even with the step cut to {exhausted.h:.3g} s, near "
            f"{system.net.where(worst)}; reduce dt, raise axial_damping, or try scheme rk4") from None
    return replace(new, iterations=state.iterations + work.iterations, cuts=state.cuts + work.cuts)
