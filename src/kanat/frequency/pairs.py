"""Where each drag pair acts in the linear system: the maps between the pairs' 3-vectors and the
degrees of freedom (:mod:`kanat.frequency.response` eq. 1).

A pair ``k`` (:class:`kanat.frequency.drag.DragPairs`) has a 3-vector velocity ``v_k`` and force
``f_k``. Over all pairs, with ``X`` the degrees of freedom::

    (1)  v = P_v^T X_dot,   forces = P_f f,   so  f = D (u_w - v)  adds  P_f D P_v^T  to the damping

``P_f`` and ``P_v`` (n_dof, 3 p) sparse. A free line node's pair has the identity at the node's
degrees of freedom in both. A line node at a 6-DOF body's fairlead rides on the body
(:mod:`kanat.lumped.rigid` eq. 1): its displacement is ``u_f = u - S(p) E Theta`` (``p`` the
fairlead's arm at the equilibrium), and its force reaches the body as ``J_f^T`` of it, so both
maps hold ``L^T = G^T J_f^T``, ``L = [I, -S(p) E]``, at the body's six degrees of freedom, as the
time domain lumps the line's half elements on the body. The bodies' own drag and damping channels
bring their blocks (:mod:`kanat.frequency.bodies` eq. 2).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from kanat.frequency import bodies, drag
from kanat.frequency.rigid import euler_rates_matrix
from kanat.physics.motion import skew


@dataclass(frozen=True, eq=False)
class PairMaps:
    """``P_f``, ``P_v^T`` of eq. (1) and what each pair feels of the water's flow.

    Attributes
    ----------
    force : scipy.sparse.csr_matrix, shape (n_dof, 3 p)
    velocity_t : scipy.sparse.csr_matrix, shape (3 p, n_dof)
        ``P_v^T``.
    flow : ndarray, shape (p, 3, 3)
        The water's velocity at a pair is ``flow u_w``: the identity for the lines' and point
        bodies' pairs, the bodies' channels' own projections (:mod:`kanat.frequency.bodies`).
    """

    force: sp.csr_matrix
    velocity_t: sp.csr_matrix
    flow: np.ndarray

    def assemble(self, blocks: np.ndarray) -> sp.csr_matrix:
        """``P_f blockdiag(blocks) P_v^T`` (n_dof, n_dof) of the pairs' 3 x 3 ``blocks`` (p, 3, 3)."""
        p = len(blocks)
        indptr = 3 * np.arange(3 * p + 1)
        indices = (3 * np.repeat(np.arange(p), 9) + np.tile(np.arange(3), 3 * p))
        diagonal = sp.csr_matrix((np.asarray(blocks, float).ravel(), indices, indptr), shape=(3 * p, 3 * p))
        return (self.force @ diagonal @ self.velocity_t).tocsr()

    def forces(self, values: np.ndarray) -> np.ndarray:
        """The pairs' 3-vectors (nf, p, 3) as generalized forces (nf, n_dof)."""
        nf = values.shape[0]
        return np.asarray((self.force @ values.reshape(nf, -1).T).T)

    def velocities(self, X: np.ndarray) -> np.ndarray:
        """The pairs' 3-vectors (nf, p, 3) of the degrees of freedom's values ``X`` (nf, n_dof)."""
        nf = X.shape[0]
        return np.asarray((self.velocity_t @ X.T).T).reshape(nf, -1, 3)


def line_and_body_pairs(net, x: np.ndarray, free: np.ndarray, wet: np.ndarray, strain: np.ndarray, current,
                        frame_velocity: np.ndarray, rho: float) -> tuple[drag.DragPairs, PairMaps]:
    """Every drag pair of a network at positions ``x`` (n, 3) and their maps (eq. 1): the free
    nodes' (lines and point bodies, :func:`kanat.frequency.drag.drag_pairs`), the fairlead nodes'
    of the 6-DOF bodies, and the bodies' own channels (:func:`kanat.frequency.bodies.channels`)."""
    rigid, size = net.rigid, 3 * len(free)
    riding = np.asarray(rigid.fairlead_node, dtype=np.int64)
    pairs = drag.drag_pairs(net, x, np.r_[free, riding], wet, strain, current, frame_velocity, rho=rho)
    own = bodies.channels(rigid, free, x, current, frame_velocity, rho)

    def add(k: int, dofs: np.ndarray, block: np.ndarray, into: tuple) -> None:
        r, c = np.meshgrid(dofs, 3 * k + np.arange(3), indexing="ij")
        into[0].append(r.ravel())
        into[1].append(c.ravel())
        into[2].append(np.asarray(block, float).ravel())

    plain = np.flatnonzero(pairs.dof < size)
    force = ([np.repeat(pairs.dof[plain], 3) + np.tile(np.arange(3), len(plain))],
             [np.repeat(3 * plain, 3) + np.tile(np.arange(3), len(plain))], [np.ones(3 * len(plain))])
    dofs = bodies.body_dofs(rigid, free)
    for k in np.flatnonzero(pairs.dof >= size):
        f = int(np.flatnonzero(riding == pairs.node[k])[0])
        b = rigid.fairlead_body[f]
        arm = x[pairs.node[k]] - x[rigid.ref_node[b]]
        L = np.hstack([np.eye(3), -skew(arm) @ euler_rates_matrix(x[rigid.rot_node[b]])])
        add(k, dofs[b], L.T, force)
    velocity = tuple(list(part) for part in force)
    first = len(pairs.node)
    for j, ((fd, fb), (vd, vb)) in enumerate(zip(own.force, own.velocity)):
        add(first + j, fd, fb, force)
        add(first + j, vd, vb, velocity)
    total = first + len(own.flow)
    P_f, P_v = (sp.csr_matrix((np.concatenate(v), (np.concatenate(r), np.concatenate(c))), shape=(size, 3 * total))
                for r, c, v in (force, velocity))
    merged = drag.DragPairs(*(np.concatenate([getattr(pairs, name), getattr(own.pairs, name)])
                              for name in drag.DragPairs.__dataclass_fields__))
    flow = np.concatenate([np.broadcast_to(np.eye(3), (first, 3, 3)), own.flow])
    return merged, PairMaps(force=P_f, velocity_t=P_v.T.tocsr(), flow=flow)
