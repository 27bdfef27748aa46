"""Compiled kernels of the lumped model (numba), one loop over elements or nodes each.

Element ``k`` joins nodes ``i = el_i[k]`` and ``j = el_j[k]``; with ``d = x_j - x_i``,
``l = |d|``, ``t = d / l`` (theory/lumped.md §2-3, eq. (2a) is eq. (L6a); Bezverkhyi 2006, eqs. 3-4)::

    (1)  e = l / L0 - 1,   e_dot = t . (v_j - v_i) / L0                    strain, rate
    (2)  T = max(0, f(e) + C_E2 e_dot) H(e)                                tension-only law
    (2a) T = f~(e) + C_E2 e_dot,  f~ = f(e) (e > 0), C_c e (e <= 0)         a bar (C_c > 0): also pushes
    (3)  F_i += T t,  F_j -= T t                                           internal forces Q*
    (4)  v_r = u_w - v_a,  v_t = (v_r . t) t,  v_n = v_r - v_t   relative flow at end a = i, j
    (5)  f_d = phi s (c_n |v_n| v_n + c_t |v_r . t| v_t),  s = sqrt(1+e) or 1   drag per length
    (6)  f_i = phi [(rho A + m_a) (a_w - (a_w . t) t) + (rho A + m_at) (a_w . t) t]
                                                                           fluid inertia per length:
                                                                           Froude-Krylov rho A a_w on the
                                                                           whole wave acceleration, added
                                                                           mass normal and tangential
    (7)  F_a += (f_d(v_a) + f_i - (w0 + (1 - phi) rho g A) z) L0 / 2      loads, lumped to each end a
    (8)  M_i, M_j += (L0 / 2) (m I + phi m_a (I - t t) + phi m_at t t)     lumped mass blocks
    (9)  B = (L0 / 6) (m I + m_a (I - t t)),  [[2B, B], [B, 2B]]            consistent mass

``phi`` is the wetted fraction of the element (:func:`wetted_fraction`): an element crossing
the surface keeps its buoyancy, drag and fluid inertia only for its part below it (as
MoorDyn's VOF); ``phi = 1`` once its top is half a diameter below the surface. ``rho A a_w`` is the pressure-gradient force
of the undisturbed wave on the displaced volume (MoorDyn, OrcaFlex).
Each end's half of the drag takes that end's own velocity (4), as MoorDyn's nodal drag does:
drag on the element's mean velocity ``(v_i + v_j) / 2`` leaves the mode in which neighbouring
nodes move opposite ways (the mesh's highest transverse mode) without hydrodynamic damping, and
waves excite it. A jumper in regular waves (tests/peers/test_moordyn_jumper.py, 20 segments) then rang
at 0.6 Hz and its top tension's range came out 26 % above MoorDyn's; with each end's own
velocity it is within 3 %, and the two discretizations converge to each other with the segments.
The added-mass matrix is taken at the current tangent (its ``dM/dq`` terms in Lagrange's
equations are neglected, as in MoorDyn). Each kernel has a plain NumPy twin in
:mod:`kanat.lumped.oracle_numpy` that the tests compare it with.

One element loop, :func:`element_forces`, serves both the step-by-step Python path
(:func:`forces`) and the fused compiled paths (:mod:`kanat.lumped.fast`), so a run compiles it
once. Kernels use scalar loops only, and none is inlined at the numba level (LLVM still
inlines what pays), which keeps a run's compile short (docs/performance.md).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import kernel

from kanat.lumped import entries

PCG_TOLERANCE = 1e-13      # relative residual of the consistent-mass solve (round-off level)
PCG_MAX_ITERATIONS = 200   # the preconditioned mass matrix has condition number < 4: ~20 suffice


@kernel
def elastic_row(kinds, ns, xs, ys, row, e):
    """Elastic tension ``f(e)`` and its slope ``df/de`` of law ``row`` of the law arrays
    (network.law_arrays): a polynomial ``sum y_k e^k`` or a table through ``(0, 0)``."""
    n = ns[row]
    if kinds[row] == 0:
        f, df, p = 0.0, 0.0, 1.0
        for k in range(n):
            df += (k + 1) * ys[row, k] * p
            p *= e
            f += ys[row, k] * p
        return f, df
    for k in range(1, n):
        if e <= xs[row, k] or k == n - 1:
            slope = (ys[row, k] - ys[row, k - 1]) / (xs[row, k] - xs[row, k - 1])
            return ys[row, k - 1] + slope * (e - xs[row, k - 1]), slope
    return 0.0, 0.0


@kernel
def elastic(kind, n, xs, ys, e):
    """Elastic tension ``f(e)`` and its slope ``df/de`` of one law given as its own arrays."""
    return elastic_row(np.array([kind]), np.array([n]), xs.reshape((1, -1)), ys.reshape((1, -1)), 0, e)


PACKED = ((0, 3, 4), (3, 1, 5), (4, 5, 2))   # packed symmetric 3 x 3: xx, yy, zz, xy, xz, yz


@kernel
def wetted_fraction(z_i, z_j, d, eta):
    """Wetted fraction of an element of diameter ``d`` between centreline heights ``z_i, z_j``
    under the surface ``eta``: the part of its vertical extent ``[low - d/2, high + d/2]`` below
    ``eta`` — continuous, 1/2 for a horizontal element at the surface, ``(eta - low)/(high - low)``
    for a steep one."""
    low, high = min(z_i, z_j) - 0.5 * d, max(z_i, z_j) + 0.5 * d
    if high <= eta:
        return 1.0
    if low >= eta:
        return 0.0
    return (eta - low) / (high - low)


@kernel
def axial_force(f, compression, damping, e, edot):
    """The element's axial force ``T`` at strain ``e`` and rate ``edot``, eqs. (2) and (2a), from its
    elastic tension ``f = f(e)`` (:func:`elastic_row`; any value where ``e <= 0``, which is not read).

    A rope (``compression == 0``) is tension-only: ``T = max(0, f(e) + C_E2 e_dot)`` for ``e > 0``
    and 0 otherwise (the caller passes only ``e > 0``). A bar (``compression > 0``, a line type
    with bending stiffness and a ``compression_stiffness``) also pushes:
    ``T = f~(e) + C_E2 e_dot`` with ``f~(e) = f(e)`` for ``e > 0`` and ``compression * e`` for
    ``e <= 0``, continuous at ``e = 0`` and without the clamp at zero.

    Scalars only, the law looked up by the caller: a compiled call that passes arrays costs more
    than the whole law here (the element loops ran 7x slower with the arrays passed down;
    docs/performance.md, "Calls in the element loops").
    """
    if compression > 0.0:
        return (f if e > 0.0 else compression * e) + damping * edot
    return max(0.0, f + damping * edot)


@kernel
def element_forces(x, v, uw, aw, wet, node_force, node_mass, el, F, M, T, strain):
    """Nodal forces, packed lumped mass blocks and element tensions and strains, eqs. (1)-(8).

    Parameters
    ----------
    x, v : ndarray, shape (n, 3)
        Node positions [m] and velocities [m/s].
    uw, aw : ndarray, shape (m, 3)
        Water velocity [m/s] and acceleration [m/s^2] at element midpoints.
    wet : ndarray, shape (m,)
        Wetted fraction ``phi`` of each element.
    node_force : ndarray, shape (n, 3)
        Constant nodal loads [N].
    node_mass : ndarray, shape (n,)
        Nodal (body) mass including body added mass [kg].
    el : kanat.lumped.entries.Elements
        The elements' properties and laws, read by name (``el.length`` is ``L0``, ``el.mass``
        ``m``, ``el.added_mass_tangential`` ``m_at``, ``el.buoyancy`` ``rho g A``, ...).
    F, M, T, strain : ndarray, shapes (n, 3), (n, 6), (m,), (m,)
        Outputs, overwritten; ``M`` holds each node's symmetric mass block packed as
        :data:`PACKED` (xx, yy, zz, xy, xz, yz).
    """
    el_i, el_j, L0, m, ma, mat = el.first_node, el.second_node, el.length, el.mass, el.added_mass, \
        el.added_mass_tangential
    w, disp, buoy, cn, ct, stretch = el.weight, el.displaced, el.buoyancy, el.drag_normal, el.drag_tangential, \
        el.stretch_drag
    c, law, law_kind, law_n, law_x, law_y = el.damping, el.law, el.law_kind, el.law_size, el.law_strains, \
        el.law_values
    compression = el.compression_stiffness
    for a in range(x.shape[0]):
        for r in range(3):
            F[a, r] = node_force[a, r]
            M[a, r] = node_mass[a]
            M[a, r + 3] = 0.0
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        length = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        inv = 1.0 / length
        t0, t1, t2 = d0 * inv, d1 * inv, d2 * inv
        e = length / L0[k] - 1.0
        tension = 0.0
        if e > 0.0 or compression[k] > 0.0:
            edot = (t0 * (v[j, 0] - v[i, 0]) + t1 * (v[j, 1] - v[i, 1]) + t2 * (v[j, 2] - v[i, 2])) / L0[k]
            f = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)[0] if e > 0.0 else 0.0
            tension = axial_force(f, compression[k], c[k], e, edot)
        T[k] = tension
        strain[k] = e
        phi = wet[k]
        half = 0.5 * L0[k]
        s = phi * half * (np.sqrt(1.0 + e) if stretch[k] > 0.0 else 1.0)
        ats = aw[k, 0] * t0 + aw[k, 1] * t1 + aw[k, 2] * t2
        fn = phi * half * (disp[k] + ma[k])
        ft = phi * half * (disp[k] + mat[k]) * ats
        l0 = fn * (aw[k, 0] - ats * t0) + ft * t0
        l1 = fn * (aw[k, 1] - ats * t1) + ft * t1
        l2 = fn * (aw[k, 2] - ats * t2) + ft * t2 - (w[k] + (1.0 - phi) * buoy[k]) * half
        for node, sign in ((i, 1.0), (j, -1.0)):
            vr0 = uw[k, 0] - v[node, 0]
            vr1 = uw[k, 1] - v[node, 1]
            vr2 = uw[k, 2] - v[node, 2]
            vts = vr0 * t0 + vr1 * t1 + vr2 * t2
            vn0, vn1, vn2 = vr0 - vts * t0, vr1 - vts * t1, vr2 - vts * t2
            normal = s * cn[k] * np.sqrt(vn0 * vn0 + vn1 * vn1 + vn2 * vn2)
            axial = s * ct[k] * abs(vts) * vts
            F[node, 0] += l0 + normal * vn0 + axial * t0 + sign * tension * t0
            F[node, 1] += l1 + normal * vn1 + axial * t1 + sign * tension * t1
            F[node, 2] += l2 + normal * vn2 + axial * t2 + sign * tension * t2
        mass, added = half * (m[k] + phi * ma[k]), half * phi * (ma[k] - mat[k])
        for node in (i, j):
            M[node, 0] += mass - added * t0 * t0
            M[node, 1] += mass - added * t1 * t1
            M[node, 2] += mass - added * t2 * t2
            M[node, 3] -= added * t0 * t1
            M[node, 4] -= added * t0 * t2
            M[node, 5] -= added * t1 * t2


def forces(x, v, uw, aw, node_force, node_mass, el, F, M, T, strain, wet=None):
    """:func:`element_forces` with the mass blocks unpacked to ``M`` (n, 3, 3) (the Python path).

    The arguments are those of :func:`element_forces` (``el`` an
    :class:`~kanat.lumped.entries.Elements`); ``F, M, T, strain`` (shapes (n, 3), (n, 3, 3),
    (m,), (m,)) are overwritten. ``wet`` (default all 1): the wetted fraction of each element.
    """
    wet = np.ones(len(el.first_node)) if wet is None else wet
    packed = np.empty((x.shape[0], 6))
    entries.element_forces(x, v, _writable(uw), _writable(aw), _writable(wet), node_force, node_mass, el, F,
                           packed, T, strain)
    M[:] = packed[:, np.array(PACKED)]


@kernel
def solve3(A, b):
    """Solution of one 3 x 3 system by cofactors (A symmetric positive definite)."""
    c00 = A[1, 1] * A[2, 2] - A[1, 2] * A[2, 1]
    c01 = A[1, 2] * A[2, 0] - A[1, 0] * A[2, 2]
    c02 = A[1, 0] * A[2, 1] - A[1, 1] * A[2, 0]
    det = A[0, 0] * c00 + A[0, 1] * c01 + A[0, 2] * c02
    c10 = A[0, 2] * A[2, 1] - A[0, 1] * A[2, 2]
    c11 = A[0, 0] * A[2, 2] - A[0, 2] * A[2, 0]
    c12 = A[0, 1] * A[2, 0] - A[0, 0] * A[2, 1]
    c20 = A[0, 1] * A[1, 2] - A[0, 2] * A[1, 1]
    c21 = A[0, 2] * A[1, 0] - A[0, 0] * A[1, 2]
    c22 = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
    out = np.empty(3)
    out[0] = (c00 * b[0] + c10 * b[1] + c20 * b[2]) / det
    out[1] = (c01 * b[0] + c11 * b[1] + c21 * b[2]) / det
    out[2] = (c02 * b[0] + c12 * b[1] + c22 * b[2]) / det
    return out


@kernel
def lumped_solve(M, F, free, a):
    """``a_n = M_n^-1 F_n`` on free nodes (lumped mass, eq. 8) by cofactors of each symmetric
    3 x 3 block; ``a`` of the other nodes untouched."""
    for n in range(M.shape[0]):
        if not free[n]:
            continue
        c00 = M[n, 1, 1] * M[n, 2, 2] - M[n, 1, 2] * M[n, 2, 1]
        c01 = M[n, 1, 2] * M[n, 2, 0] - M[n, 1, 0] * M[n, 2, 2]
        c02 = M[n, 1, 0] * M[n, 2, 1] - M[n, 1, 1] * M[n, 2, 0]
        inv = 1.0 / (M[n, 0, 0] * c00 + M[n, 0, 1] * c01 + M[n, 0, 2] * c02)
        c10 = M[n, 0, 2] * M[n, 2, 1] - M[n, 0, 1] * M[n, 2, 2]
        c11 = M[n, 0, 0] * M[n, 2, 2] - M[n, 0, 2] * M[n, 2, 0]
        c12 = M[n, 0, 1] * M[n, 2, 0] - M[n, 0, 0] * M[n, 2, 1]
        c20 = M[n, 0, 1] * M[n, 1, 2] - M[n, 0, 2] * M[n, 1, 1]
        c21 = M[n, 0, 2] * M[n, 1, 0] - M[n, 0, 0] * M[n, 1, 2]
        c22 = M[n, 0, 0] * M[n, 1, 1] - M[n, 0, 1] * M[n, 1, 0]
        b0, b1, b2 = F[n, 0], F[n, 1], F[n, 2]
        a[n, 0] = (c00 * b0 + c10 * b1 + c20 * b2) * inv
        a[n, 1] = (c01 * b0 + c11 * b1 + c21 * b2) * inv
        a[n, 2] = (c02 * b0 + c12 * b1 + c22 * b2) * inv


@kernel
def consistent_blocks(x, el_i, el_j, L0, m, ma, B):
    """Element blocks ``B`` of the consistent mass matrix, eq. (9); shape (m, 3, 3)."""
    for k in range(el_i.shape[0]):
        d = x[el_j[k]] - x[el_i[k]]
        t = d / np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        for r in range(3):
            for q in range(3):
                B[k, r, q] = L0[k] / 6.0 * ((m[k] + ma[k]) * (1.0 if r == q else 0.0) - ma[k] * t[r] * t[q])


@kernel
def consistent_matvec(B, el_i, el_j, node_mass, a, y):
    """``y = M a`` for the consistent mass matrix (eq. 9) plus nodal masses."""
    for node in range(a.shape[0]):
        y[node] = node_mass[node] * a[node]
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        y[i] += B[k] @ (2.0 * a[i] + a[j])
        y[j] += B[k] @ (a[i] + 2.0 * a[j])


@kernel
def consistent_solve(B, el_i, el_j, node_mass, F, free, a):
    """Solve ``(M a)_free = F_free`` with ``a`` given on prescribed nodes (eq. 9).

    Preconditioned conjugate gradients with the matrix's 3 x 3 diagonal blocks; ``a``
    holds the prescribed accelerations on entry and the solution on exit. Returns the
    number of iterations.
    """
    n = a.shape[0]
    P = np.zeros((n, 3, 3))
    for node in range(n):
        for r in range(3):
            P[node, r, r] = node_mass[node]
    for k in range(el_i.shape[0]):
        P[el_i[k]] += 2.0 * B[k]
        P[el_j[k]] += 2.0 * B[k]
    for node in range(n):
        if free[node]:
            a[node] = solve3(P[node], F[node])
    y = np.empty_like(a)
    consistent_matvec(B, el_i, el_j, node_mass, a, y)
    r = np.zeros_like(a)
    z = np.zeros_like(a)
    norm_f = 0.0
    for node in range(n):
        if free[node]:
            r[node] = F[node] - y[node]
            z[node] = solve3(P[node], r[node])
            norm_f += F[node] @ F[node]
    p = z.copy()
    rz = np.sum(r * z)
    tol2 = PCG_TOLERANCE**2 * max(norm_f, 1e-300)
    for it in range(PCG_MAX_ITERATIONS):
        if np.sum(r * r) <= tol2:
            return it
        consistent_matvec(B, el_i, el_j, node_mass, p, y)
        for node in range(n):
            if not free[node]:
                y[node] = 0.0
        alpha = rz / np.sum(p * y)
        a += alpha * p
        r -= alpha * y
        for node in range(n):
            if free[node]:
                z[node] = solve3(P[node], r[node])
        rz_new = np.sum(r * z)
        p = z + (rz_new / rz) * p
        rz = rz_new
    return PCG_MAX_ITERATIONS


@kernel
def tangent_blocks(x, v, uw, el, K, C, D):
    """Element Jacobian blocks for the implicit scheme.

    ``K = d(T t)/dd`` (axial and geometric stiffness), ``C = d(T t)/d(v_j - v_i)`` (Kelvin–
    Voigt), ``D = d f_d / d v_r`` times ``L0/2`` (drag: each end's half on that end's own
    velocity, eq. 5, so ``-dF_a/dv_a`` with ``D`` taken at the element's mean relative flow
    ``u_w - (v_i + v_j)/2`` for both ends — exact where they move together), each shape
    (m, 3, 3). Assembly: ``-dF/dx`` has ``+K`` on the diagonal blocks ``ii, jj`` and ``-K`` off
    it; the same pattern for ``C``; ``+D`` on the diagonal blocks ``ii, jj`` of ``-dF/dv``. A bar
    (eq. 2a) has them in compression too (its geometric stiffness then negative: buckling).
    """
    el_i, el_j, L0, cn, ct, stretch, c = el.first_node, el.second_node, el.length, el.drag_normal, \
        el.drag_tangential, el.stretch_drag, el.damping
    law, law_kind, law_n, law_x, law_y = el.law, el.law_kind, el.law_size, el.law_strains, el.law_values
    compression = el.compression_stiffness
    t, dv, vn = np.empty(3), np.empty(3), np.empty(3)
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        length = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        t[0], t[1], t[2] = d0 / length, d1 / length, d2 / length
        e = length / L0[k] - 1.0
        for r in range(3):
            dv[r] = v[j, r] - v[i, r]
        tdv = t[0] * dv[0] + t[1] * dv[1] + t[2] * dv[2]
        tension, slope, bar = 0.0, 0.0, compression[k] > 0.0
        if e > 0.0:
            f, df = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)
            tension = f + c[k] * tdv / L0[k]
            slope = df
        elif bar:
            tension = compression[k] * e + c[k] * tdv / L0[k]
            slope = compression[k]
        vts = 0.0
        for r in range(3):
            vts += (uw[k, r] - 0.5 * (v[i, r] + v[j, r])) * t[r]
        for r in range(3):
            vn[r] = uw[k, r] - 0.5 * (v[i, r] + v[j, r]) - vts * t[r]
        speed_n = np.sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2])
        s = np.sqrt(1.0 + e) if stretch[k] > 0.0 else 1.0
        for r in range(3):
            for q in range(3):
                nrq = (1.0 if r == q else 0.0) - t[r] * t[q]
                if tension > 0.0 or bar:
                    dTdd = slope / L0[k] * t[q] + c[k] / L0[k] * (dv[q] - tdv * t[q]) / length
                    K[k, r, q] = t[r] * dTdd + tension / length * nrq
                    C[k, r, q] = c[k] / L0[k] * t[r] * t[q]
                else:
                    K[k, r, q] = 0.0
                    C[k, r, q] = 0.0
                dn = cn[k] * (speed_n * nrq + (vn[r] * vn[q] / speed_n if speed_n > 0 else 0.0))
                D[k, r, q] = 0.5 * L0[k] * s * (dn + 2.0 * ct[k] * abs(vts) * t[r] * t[q])


@kernel
def tensions(x, v, el, T):
    """Element tensions only, eqs. (1)-(2a) (for outputs and snap detection); ``el`` an
    :class:`~kanat.lumped.entries.Elements` (its fields read once, outside the loop)."""
    el_i, el_j, L0, compression, c = el.first_node, el.second_node, el.length, el.compression_stiffness, el.damping
    law, law_kind, law_n, law_x, law_y = el.law, el.law_kind, el.law_size, el.law_strains, el.law_values
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        length = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        e = length / L0[k] - 1.0
        T[k] = 0.0
        if e > 0.0 or compression[k] > 0.0:
            edot = (d0 * (v[j, 0] - v[i, 0]) + d1 * (v[j, 1] - v[i, 1]) + d2 * (v[j, 2] - v[i, 2])) / (length * L0[k])
            f = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)[0] if e > 0.0 else 0.0
            T[k] = axial_force(f, compression[k], c[k], e, edot)


def body_loads(x, v, uw, aw, body_node, drag_area, spreading, fluid_inertia, rho, heading, F):
    """:func:`add_body_loads` from Python: the water kinematics as writable C arrays, whatever
    array the environment gave (one compiled version for every run)."""
    entries.add_body_loads(x, v, _writable(uw), _writable(aw), body_node, drag_area, spreading, fluid_inertia,
                           float(rho), float(heading), F)


def _writable(a) -> np.ndarray:
    return np.require(a, np.float64, ("C", "W"))


@kernel
def add_body_loads(x, v, uw, aw, body_node, drag_area, spreading, fluid_inertia, rho, heading, F):
    """Body drag, spreading force and fluid inertia added to ``F`` (system eq. 2).

    ``uw, aw`` (n_body, 3) water velocity and acceleration at the bodies; ``fluid_inertia`` (n,)
    the Morison inertia ``rho V + m_a`` [kg] at nodes, so the water's acceleration pulls a body
    with its Froude–Krylov part ``rho V a_w`` and its added-mass part ``m_a a_w`` (the body's
    ``m_a`` is also on the left-hand side, in the node's mass).
    """
    sn, cs = np.sin(heading), np.cos(heading)
    for b in range(body_node.shape[0]):
        node = body_node[b]
        ur0, ur1, ur2 = uw[b, 0] - v[node, 0], uw[b, 1] - v[node, 1], uw[b, 2] - v[node, 2]
        drag = 0.5 * rho * drag_area[b] * np.sqrt(ur0 * ur0 + ur1 * ur1 + ur2 * ur2)
        F[node, 0] += drag * ur0 + fluid_inertia[node] * aw[b, 0]
        F[node, 1] += drag * ur1 + fluid_inertia[node] * aw[b, 1]
        F[node, 2] += drag * ur2 + fluid_inertia[node] * aw[b, 2]
        F[node, 0] -= spreading[b] * sn
        F[node, 1] += spreading[b] * cs
