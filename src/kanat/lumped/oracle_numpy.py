"""Plain NumPy twins of the compiled kernels (:mod:`kanat.lumped.kernels`), written
independently (vectorized over elements, ``np.add.at`` for the scatter) so that the
tests can check each kernel against them. Same equations and numbering as there. The consistent
mass twins use SciPy's sparse matrices, imported where they are used (a run that loads these twins
for their element forces does not load SciPy).
"""
from __future__ import annotations

import numpy as np


def elastic_numpy(kind, n, xs, ys, e):
    """Elastic tension and slope of one law for an array of strains ``e``."""
    e = np.asarray(e, dtype=float)
    if kind == 0:
        c = ys[:n]
        powers = np.arange(1, n + 1)
        f = np.sum(c * e[..., None] ** powers, axis=-1)
        df = np.sum(c * powers * e[..., None] ** (powers - 1), axis=-1)
        return f, df
    x, y = xs[:n], ys[:n]
    k = np.clip(np.searchsorted(x, e, side="left"), 1, n - 1)
    slope = (y[k] - y[k - 1]) / (x[k] - x[k - 1])
    return y[k - 1] + slope * (e - x[k - 1]), slope


def forces_numpy(el, x, v, uw, aw, node_force, node_mass, wet=None):
    """Twin of :func:`kernels.forces`: returns ``F (n,3), M (n,3,3), T (m,), strain (m,)``.

    ``el`` a :class:`kanat.lumped.entries.Elements`, ``wet`` (default all 1) the wetted fractions.
    """
    i, j, L0 = el.first_node, el.second_node, el.length
    wet = np.ones(len(i)) if wet is None else np.asarray(wet)
    d = x[j] - x[i]
    length = np.linalg.norm(d, axis=1)
    t = d / length[:, None]
    e = length / L0 - 1.0
    edot = np.einsum("kr,kr->k", t, v[j] - v[i]) / L0
    f = np.zeros_like(e)
    for row in range(len(el.law_kind)):
        sel = el.law == row
        f[sel] = elastic_numpy(el.law_kind[row], el.law_size[row], el.law_strains[row], el.law_values[row],
                               np.maximum(e[sel], 0.0))[0]
    rope = np.where(e > 0.0, np.maximum(0.0, f + el.damping * edot), 0.0)               # eq. (2)
    bar = np.where(e > 0.0, f, el.compression_stiffness * e) + el.damping * edot        # eq. (2a)
    T = np.where(el.compression_stiffness > 0.0, bar, rope)
    s = wet * np.where(el.stretch_drag > 0, np.sqrt(1.0 + e), 1.0)

    def drag(v_end):                                  # eqs. (4)-(5) on one end's own velocity
        vr = uw - v_end
        vts = np.einsum("kr,kr->k", vr, t)
        vn = vr - vts[:, None] * t
        return s[:, None] * (el.drag_normal[:, None] * np.linalg.norm(vn, axis=1)[:, None] * vn
                             + (el.drag_tangential * np.abs(vts) * vts)[:, None] * t)
    at = np.einsum("kr,kr->k", aw, t)[:, None] * t
    fi = wet[:, None] * ((el.displaced + el.added_mass)[:, None] * (aw - at)
                         + (el.displaced + el.added_mass_tangential)[:, None] * at)
    load = fi * (0.5 * L0)[:, None]
    load[:, 2] -= (el.weight + (1.0 - wet) * el.buoyancy) * 0.5 * L0
    F = np.array(node_force, dtype=float)
    np.add.at(F, i, T[:, None] * t + load + drag(v[i]) * (0.5 * L0)[:, None])
    np.add.at(F, j, -T[:, None] * t + load + drag(v[j]) * (0.5 * L0)[:, None])
    eye = np.eye(3)
    tt = np.einsum("kr,kq->krq", t, t)
    blocks = (0.5 * L0)[:, None, None] * ((el.mass + wet * el.added_mass)[:, None, None] * eye
                                           + (wet * (el.added_mass_tangential - el.added_mass))[:, None, None] * tt)
    M = node_mass[:, None, None] * eye
    np.add.at(M, i, blocks)
    np.add.at(M, j, blocks)
    return F, M, T, e


PACKED_ROWS, PACKED_COLUMNS = [0, 1, 2, 0, 0, 1], [0, 1, 2, 1, 2, 2]   # xx, yy, zz, xy, xz, yz


def element_forces_numpy(x, v, uw, aw, wet, node_force, node_mass, el, F, M, T, strain):
    """Twin of :func:`kernels.element_forces`, with its arguments: ``F, M, T, strain`` overwritten,
    ``M`` (n, 6) the symmetric mass blocks packed (xx, yy, zz, xy, xz, yz)."""
    F[:], full, T[:], strain[:] = forces_numpy(el, x, v, uw, aw, node_force, node_mass, wet)
    M[:] = full[:, PACKED_ROWS, PACKED_COLUMNS]


def lumped_solve_numpy(M, F, free, a):
    """Twin of :func:`kernels.lumped_solve`."""
    out = np.array(a, dtype=float)
    out[free] = np.linalg.solve(M[free], F[free][..., None])[..., 0]
    return out


def lumped_solve_into(M, F, free, a):
    """Twin of :func:`kernels.lumped_solve`, with its arguments (``a`` of free nodes overwritten)."""
    a[:] = lumped_solve_numpy(M, F, free, a)


def consistent_matrix(net, x, node_mass):
    """The consistent mass matrix (kernels eq. 9) as a sparse (3n, 3n) matrix."""
    import scipy.sparse as sp

    n = len(x)
    d = x[net.el_j] - x[net.el_i]
    t = d / np.linalg.norm(d, axis=1)[:, None]
    B = (net.el_length / 6.0)[:, None, None] * (
        (net.el_mass + net.el_added_mass)[:, None, None] * np.eye(3)
        - net.el_added_mass[:, None, None] * np.einsum("kr,kq->krq", t, t))
    rows, cols, vals = [], [], []
    r3, c3 = np.meshgrid(np.arange(3), np.arange(3), indexing="ij")
    for (a, b, w) in ((net.el_i, net.el_i, 2.0), (net.el_i, net.el_j, 1.0),
                      (net.el_j, net.el_i, 1.0), (net.el_j, net.el_j, 2.0)):
        rows.append((3 * a[:, None, None] + r3).ravel())
        cols.append((3 * b[:, None, None] + c3).ravel())
        vals.append((w * B).ravel())
    rows.append(np.arange(3 * n))
    cols.append(np.arange(3 * n))
    vals.append(np.repeat(node_mass, 3))
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(3 * n, 3 * n))


def consistent_solve_numpy(net, x, node_mass, F, free, a):
    """Twin of :func:`kernels.consistent_solve` by a sparse direct solve."""
    import scipy.sparse.linalg as spla

    M = consistent_matrix(net, x, node_mass)
    dof = np.repeat(free, 3)
    a = np.array(a, dtype=float).ravel()
    rhs = F.ravel()[dof] - M[dof][:, ~dof] @ a[~dof]
    a[dof] = spla.spsolve(M[dof][:, dof].tocsc(), rhs)
    return a.reshape(-1, 3)


def tensions_numpy(el, x, v):
    """Twin of :func:`kernels.tensions`: the element tensions (m,), kernels eqs. (1)-(2a)."""
    return forces_numpy(el, x, v, np.zeros((len(el.first_node), 3)), np.zeros((len(el.first_node), 3)),
                        np.zeros_like(x), np.zeros(len(x)))[2]


def calm_wetted_numpy(el, x):
    """Twin of :func:`kanat.lumped.output_loads.calm_wetted`: the wetted fraction (m,) of each element
    under the still surface ``z = 0``."""
    zi, zj, half = x[el.first_node, 2], x[el.second_node, 2], 0.5 * el.diameter
    top, low = np.maximum(zi, zj) + half, np.minimum(zi, zj) - half
    return np.where(top < 0.0, 1.0, np.clip(-low / np.maximum(top - low, 1e-300), 0.0, 1.0))


def output_loads_numpy(x, v, el, contact, out):
    """Twin of :func:`kanat.lumped.output_loads.output_loads`, with its arguments: its steps 1-5 from
    this module's twins (:func:`tensions_numpy`, :func:`calm_wetted_numpy`, :func:`forces_numpy`)
    and the bending and seabed contact kernels as the lookup runs them (plain Python with
    ``KANAT_KERNELS=python``; they are tested against their own oracles)."""
    from kanat.lumped.bending import bending_forces
    from kanat.physics.contact import contact_forces

    out.line_tension[:] = tensions_numpy(el, x, v)
    if out.calm:
        out.wet[:] = calm_wetted_numpy(el, x)
    element_forces_numpy(x, v, out.water_velocity, out.water_acceleration, out.wet, out.node_force, out.node_mass,
                         el, out.force, out.mass, out.tension, out.strain)
    bending_forces(x, el.bend_before, el.bend_node, el.bend_after, el.bend_stiffness, out.force)
    if contact is not None:
        contact_forces(x, v, el.first_node, el.second_node, contact.area, contact.seabed, contact.law,
                       contact.laid, out.tangent, out.force, out.normal_force)
