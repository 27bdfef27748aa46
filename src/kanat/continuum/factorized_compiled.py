"""The factorized step compiled whole (numba): node forms, split, sweeps and characteristic ends.

The same algorithm as the readable NumPy path (:func:`kanat.continuum.factorized.factorized_step`
with :mod:`characteristics` and :class:`~kanat.continuum.factorized_system.CableSystem`), one
compiled call per step so that the "running count" costs what the paper says it costs; the
tests check the two agree to round-off. Nodal loads come from the full model's kernels
(:func:`kernels2d.node_load`, :func:`kernels3d.node_load3`).

End parameters (``ENDPAR`` floats): ``[kind, V1, V2, V3, mass, net_buoyancy, half_rho_cds, F1, F2, F3]``
in the frame's coordinates (planar: the first two of each vector).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from kanat.continuum import kernels2d as k2
from kanat.continuum import kernels3d as k3
from kanat.continuum.factorized_kernels import lu_factor, lu_solve, sweep

STEP = 1e-30
ENDPAR = 10
END_ITERATIONS = 30
END_TOLERANCE = 1e-11
OK, COMPRESSION, SINGULAR, DIVERGED, NONFINITE = 0, 1, 2, 3, 4


@njit(cache=True)
def mass_stiffness(y, p, dim, M, K):
    """``M(y)``, ``K(y)`` (d, d) of one node (SPEC §2.1, §2.2)."""
    if dim == 3:
        k3.mass_matrix(y, p, M)
        k3.stiffness_matrix(y, K)
        return
    m, mn, ea = p[k2.M], p[k2.M] + p[k2.MA], p[k2.EA]
    M[:, :] = 0.0
    K[:, :] = 0.0
    M[0, 1], M[0, 3] = m, -m * y[2]
    M[1, 2], M[1, 3] = mn, mn * y[1]
    M[2, 0] = 1.0 / ea
    M[3, 3] = 1.0 + y[0] / ea
    K[0, 0] = -1.0
    K[1, 3] = -y[0]
    K[2, 1], K[2, 3] = -1.0, y[2]
    K[3, 2], K[3, 3] = -1.0, -y[1]


@njit(cache=True)
def load(y, cur, up, p, dim, out):
    """``F(y)`` (d,) of one node, complex-capable (zero on the compatibility rows)."""
    out[:] = 0.0
    if dim == 3:
        f = k3.node_load3(y[0], y[1], y[2], y[3], y[4], y[5], cur, up, p)
        out[0], out[1], out[2] = f[0], f[1], f[2]
    else:
        ft, fn = k2.node_load(y[0], y[1], y[2], y[3], cur[0], cur[1], p)
        out[0], out[1] = ft, fn


@njit(cache=True)
def axes(y, dim):
    """Frame ``(t, n, b)`` rows (3, 3) of one node (planar: 2 x 2 used), complex-capable."""
    a = np.zeros((3, 3), dtype=y.dtype)
    if dim == 3:
        t, n, b = k3.frame(y[4], y[5])
        for i in range(3):
            a[0, i], a[1, i], a[2, i] = t[i], n[i], b[i]
    else:
        c, s = np.cos(y[3]), np.sin(y[3])
        a[0, 0], a[0, 1], a[1, 0], a[1, 1] = c, s, -s, c
    return a


@njit(cache=True)
def node_forms(Y, cur, up, p, dim, with_jacobian):
    """``B = M^-1 K``, ``D = M^-1 F``, ``J = M^-1 dF/dY`` (zeros unless asked) and ``M`` at every node."""
    n, d = Y.shape
    B, J, Ms = np.empty((n, d, d)), np.zeros((n, d, d)), np.empty((n, d, d))
    D = np.empty((n, d))
    M, K, F, LU = np.empty((d, d)), np.empty((d, d)), np.empty(d), np.empty((d, d))
    piv = np.empty(d, dtype=np.int64)
    col, sol = np.empty(d), np.empty(d)
    z, fz = np.empty(d, dtype=np.complex128), np.empty(d, dtype=np.complex128)
    for i in range(n):
        mass_stiffness(Y[i], p, dim, M, K)
        load(Y[i], cur[i], up, p, dim, F)
        lu_factor(M, LU, piv)
        for q in range(d):
            for r in range(d):
                col[r] = K[r, q]
            lu_solve(LU, piv, col, sol)
            for r in range(d):
                B[i, r, q] = sol[r]
        lu_solve(LU, piv, F, D[i])
        Ms[i] = M
        if with_jacobian:
            for q in range(d):
                for r in range(d):
                    z[r] = Y[i, r]
                z[q] += 1j * STEP
                load(z, cur[i], up, p, dim, fz)
                for r in range(d):
                    col[r] = fz[r].imag / STEP
                lu_solve(LU, piv, col, sol)
                for r in range(d):
                    J[i, r, q] = sol[r]
    return B, D, J, Ms


@njit(cache=True)
def split_node(B, c_l, c_t2, parts):
    """``parts[0..3] = B_1+, B_1-, B_2+, B_2-`` of one node (closed form, :mod:`characteristics`).

    ``R = (B^2 - c_t^2)/(c_l^2 - c_t^2)``, ``B_1+- = (R B +- c_l R)/2``, ``B_2+- = (Q B +- c_t Q)/2``
    with ``Q = I - R``; plain loops (no allocation).
    """
    d = B.shape[0]
    c_t = np.sqrt(c_t2)
    inv = 1.0 / (c_l * c_l - c_t2)
    R = np.empty((d, d))
    for i in range(d):
        for j in range(d):
            acc = 0.0
            for m in range(d):
                acc += B[i, m] * B[m, j]
            R[i, j] = (acc - (c_t2 if i == j else 0.0)) * inv
    for i in range(d):
        for j in range(d):
            rb = 0.0
            for m in range(d):
                rb += R[i, m] * B[m, j]
            q = (1.0 if i == j else 0.0) - R[i, j]
            qb = B[i, j] - rb
            parts[0, i, j] = 0.5 * (rb + c_l * R[i, j])
            parts[1, i, j] = 0.5 * (rb - c_l * R[i, j])
            parts[2, i, j] = 0.5 * (qb + c_t * q)
            parts[3, i, j] = 0.5 * (qb - c_t * q)


@njit(cache=True)
def physical(x, old, par, side, dt, gamma, cur, up, p, dim, out):
    """The ``dim`` physical end conditions (``CableSystem.end_residual``) for one candidate ``x``."""
    kind = int(par[0])
    a = axes(x, dim)
    if kind == k2.VELOCITY:
        for i in range(dim):
            acc = x[1 + i]
            for c in range(dim):
                acc -= par[1 + c] * a[i, c]
            out[i] = acc
        return
    ao = axes(old.astype(np.complex128), dim)
    V = np.zeros(3, dtype=np.complex128)
    Vo = np.zeros(3, dtype=np.complex128)
    for i in range(dim):
        for c in range(dim):
            V[c] += x[1 + i] * a[i, c]
            Vo[c] += old[1 + i] * ao[i, c]
    balance = np.zeros(3, dtype=np.complex128)
    if kind == k2.FREE:
        d = 2 * dim
        f, fo = np.empty(d, dtype=np.complex128), np.empty(d, dtype=np.complex128)
        load(x, cur, up, p, dim, f)
        load(old.astype(np.complex128), cur, up, p, dim, fo)
        mn = p[k2.M] + p[k2.MA]
        for c in range(dim):
            balance[c] = mn * (V[c] - Vo[c]) / dt
            for i in range(dim):
                balance[c] -= gamma * f[i] * a[i, c] + (1.0 - gamma) * fo[i] * ao[i, c]
        out[0] = x[0] / p[k2.EA]
        for i in range(1, dim):
            acc = 0.0 * x[0]
            for c in range(dim):
                acc += balance[c] * a[i, c]
            out[i] = acc
        return
    rel, relo = np.zeros(3, dtype=np.complex128), np.zeros(3, dtype=np.complex128)
    for c in range(dim):
        rel[c], relo[c] = cur[c] - V[c], cur[c] - Vo[c]
    speed = np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    speedo = np.sqrt(relo[0] * relo[0] + relo[1] * relo[1] + relo[2] * relo[2])
    for c in range(dim):
        g = -side * x[0] * a[0, c] + par[5] * up[c] + par[6] * speed * rel[c] + par[7 + c]
        go = -side * old[0] * ao[0, c] + par[5] * up[c] + par[6] * speedo * relo[c] + par[7 + c]
        balance[c] = par[4] * (V[c] - Vo[c]) / dt - gamma * g - (1.0 - gamma) * go
    for i in range(dim):
        acc = 0.0 * x[0]
        for c in range(dim):
            acc += balance[c] * a[i, c]
        out[i] = acc


@njit(cache=True)
def _end_residual(x, old, nbr, par, side, dt, cur, up, p, dim, ds, rows, B, Minv, M, K, free, out):
    d = 2 * dim
    phys = np.empty(dim, dtype=np.complex128)
    physical(x, old, par, side, dt, 1.0, cur, up, p, dim, phys)
    F = np.empty(d, dtype=np.complex128)
    load(x, cur, up, p, dim, F)
    grad = side * (x - nbr) / ds
    res = (x - old) / dt + B.astype(np.complex128) @ grad - Minv.astype(np.complex128) @ F
    out[:dim] = phys
    m = rows.shape[0]
    for r in range(m):
        acc = 0.0 * x[0]
        for q in range(d):
            acc += rows[r, q] * res[q]
        out[dim + r] = acc
    if free:
        kin = M.astype(np.complex128) @ (x - old) / dt + K.astype(np.complex128) @ grad - F
        for r in range(dim - 1):
            out[dim + m + r] = kin[dim + 1 + r]


@njit(cache=True)
def end_solve(Y, e, side, nbr, par, dt, cur, up, p, dim, ds):
    """One end node from its physical conditions and outgoing characteristics (:func:`characteristics.end_state`).

    Returns ``(x, status)``.
    """
    d = 2 * dim
    old = Y[e].copy()
    M, K = np.empty((d, d)), np.empty((d, d))
    mass_stiffness(old, p, dim, M, K)
    Minv = np.linalg.inv(M)
    B = Minv @ K
    c_l = np.sqrt(p[k2.EA] / p[k2.M])
    c_t2 = max(old[0] / ((p[k2.M] + p[k2.MA]) * (1.0 + old[0] / p[k2.EA])), 0.0)
    parts = np.empty((4, d, d))
    split_node(B, c_l, c_t2, parts)
    free = int(par[0]) == k2.FREE
    if side > 0:
        projector = parts[0] / c_l
        if not free:
            projector = projector + parts[2] / np.sqrt(c_t2)
    else:
        projector = -parts[1] / c_l
        if not free:
            projector = projector - parts[3] / np.sqrt(c_t2)
    count = 1 if free else dim
    _, _, vt = np.linalg.svd(projector)
    rows = vt[:count].copy()
    tension = max(np.max(np.abs(Y[:, 0])), 1.0)
    speed = max(np.max(np.abs(Y[:, 1:1 + dim])), 1.0)
    x = old.copy()
    z = np.empty(d, dtype=np.complex128)
    out = np.empty(d, dtype=np.complex128)
    res, jac = np.empty(d), np.empty((d, d))
    for _ in range(END_ITERATIONS):
        for q in range(-1, d):
            for r in range(d):
                z[r] = x[r]
            if q >= 0:
                z[q] += 1j * STEP
            _end_residual(z, old, nbr, par, side, dt, cur, up, p, dim, ds, rows, B, Minv, M, K, free, out)
            if q < 0:
                for r in range(d):
                    res[r] = out[r].real
            else:
                for r in range(d):
                    jac[r, q] = out[r].imag / STEP
        if np.abs(np.linalg.det(jac)) == 0.0:
            return x, SINGULAR
        dx = np.linalg.solve(jac, -res)
        x += dx
        if not np.all(np.isfinite(x)):
            return x, NONFINITE
        worst = np.abs(dx[0]) / tension
        for r in range(1, d):
            worst = max(worst, np.abs(dx[r]) / (speed if r <= dim else 1.0))
        if worst < END_TOLERANCE:
            return x, OK
    return x, DIVERGED


@njit(cache=True)
def factorized_step_compiled(Y, cur, up, p, dim, ds, dt, four, implicit, par0, par1, slack, delta):
    """One factorized step (two or four sweeps, states or increments); returns ``(X, status, node)``."""
    n, d = Y.shape
    B, D, J, _Ms = node_forms(Y, cur, up, p, dim, implicit)
    c_l = np.sqrt(p[k2.EA] / p[k2.M])
    parts = np.empty((n, 4, d, d))
    for i in range(n):
        c_t2 = Y[i, 0] / ((p[k2.M] + p[k2.MA]) * (1.0 + Y[i, 0] / p[k2.EA]))
        if c_t2 < 0.0:
            if c_t2 > -slack:
                c_t2 = 0.0
            else:
                return Y.copy(), COMPRESSION, i
        split_node(B[i], c_l, c_t2, parts[i])
    sigma = dt / ds
    eye = np.eye(d)
    offset = Y.copy() if delta else np.zeros((n, d))
    X = Y - offset
    residual = np.zeros((n, d))
    if delta:
        for i in range(1, n - 1):
            for a in range(d):
                acc = -D[i, a]
                for b in range(d):
                    acc += ((parts[i, 0, a, b] + parts[i, 2, a, b]) * (Y[i, b] - Y[i - 1, b])
                            + (parts[i, 1, a, b] + parts[i, 3, a, b]) * (Y[i + 1, b] - Y[i, b])) / ds
                residual[i, a] = acc
    count = 4 if four else 2
    A, C = np.empty((n, d, d)), np.empty((n, d, d))
    r = np.empty((n, d))
    for index in range(count):
        forward = index % 2 == 0
        sign = 1.0 if forward else -1.0
        first, second = (index, -1) if four else ((0, 2) if forward else (1, 3))
        for i in range(n):
            for a in range(d):
                r[i, a] = X[i, a]
                for b in range(d):
                    P = parts[i, first, a, b] + (parts[i, second, a, b] if second >= 0 else 0.0)
                    C[i, a, b] = sign * sigma * P
                    A[i, a, b] = eye[a, b] + sign * sigma * P
                if index == 0:
                    r[i, a] = -dt * residual[i, a] if delta else r[i, a] + dt * D[i, a]
                    if implicit:
                        for b in range(d):
                            A[i, a, b] -= dt * J[i, a, b]
                            if not delta:
                                r[i, a] -= dt * J[i, a, b] * Y[i, b]
        if forward:
            X[0], status = end_solve(Y, 0, -1.0, X[1] + offset[1], par0, dt, cur[0], up, p, dim, ds)
            X[0] -= offset[0]
            node = 0
        else:
            X[n - 1], status = end_solve(Y, n - 1, 1.0, X[n - 2] + offset[n - 2], par1, dt, cur[n - 1], up, p,
                                         dim, ds)
            X[n - 1] -= offset[n - 1]
            node = n - 1
        if status != OK:
            return X + offset, status, node
        X = sweep(A, C, r, X, forward)
    X = X + offset
    X[n - 1], status = end_solve(Y, n - 1, 1.0, X[n - 2], par1, dt, cur[n - 1], up, p, dim, ds)
    if status != OK:
        return X, status, n - 1
    X[0], status = end_solve(Y, 0, -1.0, X[1], par0, dt, cur[0], up, p, dim, ds)
    if status != OK:
        return X, status, 0
    for i in range(n):
        for q in range(d):
            if not np.isfinite(X[i, q]):
                return X, NONFINITE, i
    return X, OK, 0


def end_parameters(end) -> np.ndarray:
    """The ``ENDPAR`` vector of an :class:`~kanat.continuum.factorized_system.EndData`."""
    par = np.zeros(ENDPAR)
    par[0] = end.kind
    dim = len(end.velocity)
    par[1:1 + dim] = end.velocity
    par[4:7] = end.mass, end.net_buoyancy, end.half_rho_cds
    if end.force is not None:
        par[7:7 + dim] = end.force
    return par


MESSAGES = {COMPRESSION: "the cable is in compression, where the transverse characteristics are complex and the "
                         "split by direction does not exist",
            SINGULAR: "the end conditions are singular",
            DIVERGED: f"the end conditions did not converge in {END_ITERATIONS} iterations",
            NONFINITE: "the factorized step is not finite (NaN)"}
