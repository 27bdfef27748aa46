"""Compiled kernels of the lumped model (numba), one loop over elements or nodes each.

Element ``k`` joins nodes ``i = el_i[k]`` and ``j = el_j[k]``; with ``d = x_j - x_i``,
``l = |d|``, ``t = d / l`` (SPEC §5; seed 004 eqs. 3-4)::

    (1)  e = l / L0 - 1,   e_dot = t . (v_j - v_i) / L0                    strain, rate
    (2)  T = max(0, f(e) + C_E2 e_dot) H(e)                                tension-only law
    (3)  F_i += T t,  F_j -= T t                                           internal forces Q*
    (4)  v_r = u_w - (v_i + v_j)/2,  v_t = (v_r . t) t,  v_n = v_r - v_t   relative flow
    (5)  f_d = s (c_n |v_n| v_n + c_t |v_r . t| v_t),  s = sqrt(1+e) or 1   drag per length
    (6)  f_i = (rho A + m_a) (a_w - (a_w . t) t)                            fluid inertia per length
    (7)  F_i, F_j += (f_d + f_i - w0 z) L0 / 2                              loads, lumped to the ends
    (8)  M_i, M_j += (L0 / 2) (m I + m_a (I - t t))                         lumped mass blocks
    (9)  B = (L0 / 6) (m I + m_a (I - t t)),  [[2B, B], [B, 2B]]            consistent mass

The added-mass matrix is taken at the current tangent (its ``dM/dq`` terms in Lagrange's
equations are neglected, as in MoorDyn). Each kernel has a plain NumPy twin in
:mod:`kanat.lumped.twins` that the tests compare it with.
"""
from __future__ import annotations

import numpy as np
from numba import njit

PCG_TOLERANCE = 1e-13      # relative residual of the consistent-mass solve (round-off level)
PCG_MAX_ITERATIONS = 200   # the preconditioned mass matrix has condition number < 4: ~20 suffice


@njit(cache=True, inline="always")
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


@njit(cache=True)
def elastic(kind, n, xs, ys, e):
    """Elastic tension ``f(e)`` and its slope ``df/de`` of one law given as its own arrays."""
    return elastic_row(np.array([kind]), np.array([n]), xs.reshape((1, -1)), ys.reshape((1, -1)), 0, e)


@njit(cache=True, inline="always")
def forces(x, v, uw, aw, node_force, node_mass, el_i, el_j, L0, m, ma, w, disp, cn, ct, stretch, c,
           law, law_kind, law_n, law_x, law_y, F, M, T, strain):
    """Nodal forces, lumped mass blocks and element tensions, eqs. (1)-(8).

    Parameters
    ----------
    x, v : ndarray, shape (n, 3)
        Node positions [m] and velocities [m/s].
    uw, aw : ndarray, shape (m, 3)
        Water velocity [m/s] and acceleration [m/s^2] at element midpoints.
    node_force : ndarray, shape (n, 3)
        Constant nodal loads [N].
    node_mass : ndarray, shape (n,)
        Nodal (body) mass including body added mass [kg].
    el_i ... law_y
        Element and law arrays of :class:`kanat.lumped.network.Network`.
    F, M, T, strain : ndarray, shapes (n, 3), (n, 3, 3), (m,), (m,)
        Outputs, overwritten.
    """
    n = x.shape[0]
    for a in range(n):
        for r in range(3):
            F[a, r] = node_force[a, r]
            for q in range(3):
                M[a, r, q] = node_mass[a] if r == q else 0.0
    t = np.empty(3)
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        length = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        t[0], t[1], t[2] = d0 / length, d1 / length, d2 / length
        e = length / L0[k] - 1.0
        edot = (t[0] * (v[j, 0] - v[i, 0]) + t[1] * (v[j, 1] - v[i, 1]) + t[2] * (v[j, 2] - v[i, 2])) / L0[k]
        tension = 0.0
        if e > 0.0:
            f, _ = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)
            tension = max(0.0, f + c[k] * edot)
        T[k] = tension
        strain[k] = e
        vr0 = uw[k, 0] - 0.5 * (v[i, 0] + v[j, 0])
        vr1 = uw[k, 1] - 0.5 * (v[i, 1] + v[j, 1])
        vr2 = uw[k, 2] - 0.5 * (v[i, 2] + v[j, 2])
        vts = vr0 * t[0] + vr1 * t[1] + vr2 * t[2]
        vn0, vn1, vn2 = vr0 - vts * t[0], vr1 - vts * t[1], vr2 - vts * t[2]
        s = np.sqrt(1.0 + e) if stretch[k] > 0.0 else 1.0
        cn_speed = s * cn[k] * np.sqrt(vn0 * vn0 + vn1 * vn1 + vn2 * vn2)
        ct_speed = s * ct[k] * abs(vts) * vts
        ats = aw[k, 0] * t[0] + aw[k, 1] * t[1] + aw[k, 2] * t[2]
        inertia = disp[k] + ma[k]
        half = 0.5 * L0[k]
        mass = m[k] + ma[k]
        for r in range(3):
            vn = vn0 if r == 0 else (vn1 if r == 1 else vn2)
            load = (cn_speed * vn + ct_speed * t[r] + inertia * (aw[k, r] - ats * t[r])) * half
            F[i, r] += tension * t[r] + load
            F[j, r] += -tension * t[r] + load
            for q in range(3):
                blk = half * (mass * (1.0 if r == q else 0.0) - ma[k] * t[r] * t[q])
                M[i, r, q] += blk
                M[j, r, q] += blk
        F[i, 2] -= w[k] * half
        F[j, 2] -= w[k] * half


@njit(cache=True)
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


@njit(cache=True, inline="always")
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


@njit(cache=True)
def consistent_blocks(x, el_i, el_j, L0, m, ma, B):
    """Element blocks ``B`` of the consistent mass matrix, eq. (9); shape (m, 3, 3)."""
    for k in range(el_i.shape[0]):
        d = x[el_j[k]] - x[el_i[k]]
        t = d / np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        for r in range(3):
            for q in range(3):
                B[k, r, q] = L0[k] / 6.0 * ((m[k] + ma[k]) * (1.0 if r == q else 0.0) - ma[k] * t[r] * t[q])


@njit(cache=True)
def consistent_matvec(B, el_i, el_j, node_mass, a, y):
    """``y = M a`` for the consistent mass matrix (eq. 9) plus nodal masses."""
    for node in range(a.shape[0]):
        y[node] = node_mass[node] * a[node]
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        y[i] += B[k] @ (2.0 * a[i] + a[j])
        y[j] += B[k] @ (a[i] + 2.0 * a[j])


@njit(cache=True)
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


@njit(cache=True)
def tangent_blocks(x, v, uw, el_i, el_j, L0, cn, ct, stretch, c, law, law_kind, law_n, law_x, law_y,
                   K, C, D):
    """Element Jacobian blocks for the implicit scheme.

    ``K = d(T t)/dd`` (axial and geometric stiffness), ``C = d(T t)/d(v_j - v_i)`` (Kelvin–
    Voigt), ``D = d f_d / d v_r`` times ``L0/4`` (drag, per end node and per end velocity),
    each shape (m, 3, 3). Assembly: ``-dF/dx`` has ``+K`` on the diagonal blocks ``ii, jj``
    and ``-K`` off it; the same pattern for ``C``; ``+D`` on all four blocks of ``-dF/dv``.
    """
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d = x[j] - x[i]
        length = np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        t = d / length
        e = length / L0[k] - 1.0
        dv = v[j] - v[i]
        tdv = t[0] * dv[0] + t[1] * dv[1] + t[2] * dv[2]
        tension, slope = 0.0, 0.0
        if e > 0.0:
            f, df = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)
            tension = f + c[k] * tdv / L0[k]
            slope = df
        vr = uw[k] - 0.5 * (v[i] + v[j])
        vts = vr[0] * t[0] + vr[1] * t[1] + vr[2] * t[2]
        vn = vr - vts * t
        speed_n = np.sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2])
        s = np.sqrt(1.0 + e) if stretch[k] > 0.0 else 1.0
        for r in range(3):
            for q in range(3):
                nrq = (1.0 if r == q else 0.0) - t[r] * t[q]
                if tension > 0.0:
                    dTdd = slope / L0[k] * t[q] + c[k] / L0[k] * (dv[q] - tdv * t[q]) / length
                    K[k, r, q] = t[r] * dTdd + tension / length * nrq
                    C[k, r, q] = c[k] / L0[k] * t[r] * t[q]
                else:
                    K[k, r, q] = 0.0
                    C[k, r, q] = 0.0
                dn = cn[k] * (speed_n * nrq + (vn[r] * vn[q] / speed_n if speed_n > 0 else 0.0))
                D[k, r, q] = 0.25 * L0[k] * s * (dn + 2.0 * ct[k] * abs(vts) * t[r] * t[q])


@njit(cache=True)
def tensions(x, v, el_i, el_j, L0, c, law, law_kind, law_n, law_x, law_y, T):
    """Element tensions only, eqs. (1)-(2) (for outputs and snap detection)."""
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
        length = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        e = length / L0[k] - 1.0
        T[k] = 0.0
        if e > 0.0:
            edot = (d0 * (v[j, 0] - v[i, 0]) + d1 * (v[j, 1] - v[i, 1]) + d2 * (v[j, 2] - v[i, 2])) / (length * L0[k])
            f, _ = elastic_row(law_kind, law_n, law_x, law_y, law[k], e)
            T[k] = max(0.0, f + c[k] * edot)


@njit(cache=True)
def body_loads(x, v, uw, aw, body_node, drag_area, spreading, added_mass, rho, heading, F):
    """Body drag, spreading force and fluid inertia added to ``F`` (system eq. 2).

    ``uw, aw`` (n_body, 3) water velocity and acceleration at the bodies.
    """
    sn, cs = np.sin(heading), np.cos(heading)
    for b in range(body_node.shape[0]):
        node = body_node[b]
        ur = uw[b] - v[node]
        speed = np.sqrt(ur[0] * ur[0] + ur[1] * ur[1] + ur[2] * ur[2])
        for r in range(3):
            F[node, r] += 0.5 * rho * drag_area[b] * speed * ur[r] + added_mass[node] * aw[b, r]
        F[node, 0] -= spreading[b] * sn
        F[node, 1] += spreading[b] * cs
