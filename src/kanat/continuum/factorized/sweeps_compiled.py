"""The factorized step compiled whole (numba): node forms, split, sweeps and characteristic ends.

The same algorithm as the readable NumPy path (:func:`kanat.continuum.factorized.sweeps.factorized_step`
with :mod:`.characteristics` and :class:`~kanat.continuum.factorized.system.CableSystem`), one
compiled call per step so that the "running count" costs what the paper says it costs; the
tests check the two agree to round-off. Nodal loads and their derivatives come from the full
model's kernels (:func:`kernels2d.node_load_jacobian`, :func:`kernels3d.node_load3_jacobian`);
the end conditions are solved by Newton with complex-step derivatives.

The cable's inputs are one named record, :class:`FactorizedLine` (:func:`line_data`). A planar
cable's ``vertical`` (``up`` in the kernels) is None: numba then compiles the planar branches only (a branch
on ``is None`` is pruned by type), so a planar run does not compile the spatial kernels.
Scalar loops throughout (no array expressions, ``@`` or ``np.linalg``; :mod:`kanat.jit`).

End parameters (``ENDPAR`` floats): ``[kind, V1, V2, V3, mass, net_buoyancy, half_rho_cds, F1, F2, F3]``
in the frame's coordinates (planar: the first two of each vector).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat import aot

from kanat.continuum import kernels2d as k2
from kanat.continuum import kernels3d as k3
from kanat.continuum.factorized.dense import lu_factor, lu_solve, sweep_into

STEP = 1e-30
ENDPAR = 10
FactorizedLine = aot.record(
    "FactorizedLine", "kanat.continuum.factorized.sweeps_compiled",
    current=aot.F2,                         # the water velocity at every node, frame coordinates (n, d_c) [m/s]
    vertical=aot.F1,                        # the frame components of the vertical z (3,); None for a planar cable
    parameters=aot.F1,                      # the cable's parameter row (kanat.continuum.layout2d)
    dimensions=aot.INT,                     # 2 or 3
    spacing=aot.FLOAT,                      # the node spacing ds [m]
    start=aot.F1, end=aot.F1,               # the end parameters at s = 0 and s = L (ENDPAR, end_parameters)
)
"""The cable as the factorized schemes' kernels read it (``line.spacing``): one field per input,
built by :func:`line_data` and nowhere else; ``vertical`` None prunes the spatial branches."""
END_ITERATIONS = 30
END_TOLERANCE = 1e-11
OK, COMPRESSION, SINGULAR, DIVERGED, NONFINITE = 0, 1, 2, 3, 4


@inner
def mass_stiffness(y, p, up, M, K):
    """``M(y)``, ``K(y)`` (d, d) of one node (theory/continuum.md §1–2); ``up`` None for a planar cable."""
    if up is not None:
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


@inner
def load(y, cur, up, p, out):
    """``F(y)`` (d,) of one node, complex-capable (zero on the compatibility rows)."""
    out[:] = 0.0
    if up is not None:
        f = k3.node_load3(y[0], y[1], y[2], y[3], y[4], y[5], cur, up, p)
        out[0], out[1], out[2] = f[0], f[1], f[2]
    else:
        ft, fn = k2.node_load(y[0], y[1], y[2], y[3], cur[0], cur[1], p)
        out[0], out[1] = ft, fn


@inner
def load_jacobian(y, cur, up, p, F, J):
    """``F(y)`` (d,) and ``J = dF/dy`` (d, d) of one node, real (zero on the compatibility rows)."""
    d = y.shape[0]
    for a in range(d):
        F[a] = 0.0
        for b in range(d):
            J[a, b] = 0.0
    if up is not None:
        f0, f1, f2 = k3.node_load3_jacobian(y, cur, up, p, J[:3])
        F[0], F[1], F[2] = f0, f1, f2
    else:
        F[0], F[1] = k2.node_load_jacobian(y[0], y[1], y[2], y[3], cur[0], cur[1], p, J[:2])


@inner
def axes(y, up):
    """Frame ``(t, n, b)`` rows (3, 3) of one node (planar: 2 x 2 used), complex-capable."""
    a = np.empty((3, 3), dtype=y.dtype)
    a[:, :] = 0.0
    if up is not None:
        t, n, b = k3.frame(y[4], y[5])
        for i in range(3):
            a[0, i], a[1, i], a[2, i] = t[i], n[i], b[i]
    else:
        c, s = np.cos(y[3]), np.sin(y[3])
        a[0, 0], a[0, 1], a[1, 0], a[1, 1] = c, s, -s, c
    return a


@inner
def node_forms(Y, cur, up, p, with_jacobian):
    """``B = M^-1 K``, ``D = M^-1 F``, ``J = M^-1 dF/dY`` (zeros unless asked) and ``M`` at every node."""
    n, d = Y.shape
    B, J, Ms = np.empty((n, d, d)), np.empty((n, d, d)), np.empty((n, d, d))
    J[:] = 0.0
    D = np.empty((n, d))
    M, K, F, LU, dF = np.empty((d, d)), np.empty((d, d)), np.empty(d), np.empty((d, d)), np.empty((d, d))
    piv = np.empty(d, dtype=np.int64)
    col, sol = np.empty(d), np.empty(d)
    for i in range(n):
        mass_stiffness(Y[i], p, up, M, K)
        load_jacobian(Y[i], cur[i], up, p, F, dF)
        lu_factor(M, LU, piv)
        for q in range(d):
            for r in range(d):
                col[r] = K[r, q]
                Ms[i, q, r] = M[q, r]
            lu_solve(LU, piv, col, sol)
            for r in range(d):
                B[i, r, q] = sol[r]
        lu_solve(LU, piv, F, D[i])
        if with_jacobian:
            for q in range(d):
                for r in range(d):
                    col[r] = dF[r, q]
                lu_solve(LU, piv, col, sol)
                for r in range(d):
                    J[i, r, q] = sol[r]
    return B, D, J, Ms


@inner
def split_node(B, c_l, c_t2, parts):
    """``parts[0..3] = B_1+, B_1-, B_2+, B_2-`` of one node (closed form, :mod:`.characteristics`).

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


@inner
def physical(x, old, par, side, dt, gamma, cur, up, p, dim, out):
    """The ``dim`` physical end conditions (``CableSystem.end_residual``) for one candidate ``x``."""
    kind = int(par[0])
    a = axes(x, up)
    if kind == k2.VELOCITY:
        for i in range(dim):
            acc = x[1 + i]
            for c in range(dim):
                acc -= par[1 + c] * a[i, c]
            out[i] = acc
        return
    zold = np.empty(old.shape[0], dtype=np.complex128)
    for q in range(old.shape[0]):
        zold[q] = old[q]
    ao = axes(zold, up)
    V = np.empty(3, dtype=np.complex128)
    Vo = np.empty(3, dtype=np.complex128)
    V[:] = 0.0
    Vo[:] = 0.0
    for i in range(dim):
        for c in range(dim):
            V[c] += x[1 + i] * a[i, c]
            Vo[c] += old[1 + i] * ao[i, c]
    balance = np.empty(3, dtype=np.complex128)
    balance[:] = 0.0
    if kind == k2.FREE:
        d = 2 * dim
        f, fo = np.empty(d, dtype=np.complex128), np.empty(d, dtype=np.complex128)
        load(x, cur, up, p, f)
        load(zold, cur, up, p, fo)
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
    rel, relo = np.empty(3, dtype=np.complex128), np.empty(3, dtype=np.complex128)
    rel[:] = 0.0
    relo[:] = 0.0
    for c in range(dim):
        rel[c], relo[c] = cur[c] - V[c], cur[c] - Vo[c]
    speed = np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    speedo = np.sqrt(relo[0] * relo[0] + relo[1] * relo[1] + relo[2] * relo[2])
    for c in range(dim):
        lift = par[5] * (up[c] if up is not None else (1.0 if c == 1 else 0.0))
        g = -side * x[0] * a[0, c] + lift + par[6] * speed * rel[c] + par[7 + c]
        go = -side * old[0] * ao[0, c] + lift + par[6] * speedo * relo[c] + par[7 + c]
        balance[c] = par[4] * (V[c] - Vo[c]) / dt - gamma * g - (1.0 - gamma) * go
    for i in range(dim):
        acc = 0.0 * x[0]
        for c in range(dim):
            acc += balance[c] * a[i, c]
        out[i] = acc


@inner
def _end_residual(x, old, nbr, par, side, dt, cur, up, p, dim, ds, rows, B, Minv, M, K, free, out):
    """Physical conditions, outgoing compatibility rows (and, at a free end, the kinematic
    relations of its transverse components) for one complex candidate ``x`` (d,)."""
    d = 2 * dim
    phys = np.empty(dim, dtype=np.complex128)
    physical(x, old, par, side, dt, 1.0, cur, up, p, dim, phys)
    F = np.empty(d, dtype=np.complex128)
    load(x, cur, up, p, F)
    grad, res = np.empty(d, dtype=np.complex128), np.empty(d, dtype=np.complex128)
    for q in range(d):
        grad[q] = side * (x[q] - nbr[q]) / ds
    for a in range(d):
        acc = (x[a] - old[a]) / dt
        for b in range(d):
            acc += B[a, b] * grad[b] - Minv[a, b] * F[b]
        res[a] = acc
    for i in range(dim):
        out[i] = phys[i]
    m = rows.shape[0]
    for r in range(m):
        acc = 0.0 * x[0]
        for q in range(d):
            acc += rows[r, q] * res[q]
        out[dim + r] = acc
    if free:
        for r in range(dim - 1):
            a = dim + 1 + r
            acc = -F[a]
            for b in range(d):
                acc += M[a, b] * (x[b] - old[b]) / dt + K[a, b] * grad[b]
            out[dim + m + r] = acc


@inner
def row_basis(A, count, rows):
    """An orthonormal basis of the row space of ``A`` (d, d) of rank ``count`` into ``rows``
    (count, d): Gram–Schmidt with pivoting on the largest remaining row (twice, for round-off)."""
    d = A.shape[0]
    W = np.empty((d, d))
    for i in range(d):
        for j in range(d):
            W[i, j] = A[i, j]
    for k in range(count):
        best, norm = 0, -1.0
        for i in range(d):
            s = 0.0
            for j in range(d):
                s += W[i, j] * W[i, j]
            if s > norm:
                best, norm = i, s
        norm = np.sqrt(norm)
        for j in range(d):
            rows[k, j] = W[best, j] / norm
        for _ in range(2):
            for i in range(d):
                dot = 0.0
                for j in range(d):
                    dot += W[i, j] * rows[k, j]
                for j in range(d):
                    W[i, j] -= dot * rows[k, j]


@inner
def end_solve(Y, e, side, nbr, par, dt, cur, up, p, dim, ds, x):
    """One end node from its physical conditions and outgoing characteristics (:func:`characteristics.end_state`)
    into ``x`` (d,); returns the status."""
    d = 2 * dim
    old = np.empty(d)
    for q in range(d):
        old[q] = Y[e, q]
    M, K, Minv, B, LU = np.empty((d, d)), np.empty((d, d)), np.empty((d, d)), np.empty((d, d)), np.empty((d, d))
    piv = np.empty(d, dtype=np.int64)
    col, sol = np.empty(d), np.empty(d)
    mass_stiffness(old, p, up, M, K)
    lu_factor(M, LU, piv)
    for q in range(d):
        for r in range(d):
            col[r] = 1.0 if r == q else 0.0
        lu_solve(LU, piv, col, sol)
        for r in range(d):
            Minv[r, q] = sol[r]
    for a in range(d):
        for b in range(d):
            acc = 0.0
            for m in range(d):
                acc += Minv[a, m] * K[m, b]
            B[a, b] = acc
    c_l = np.sqrt(p[k2.EA] / p[k2.M])
    c_t2 = max(old[0] / ((p[k2.M] + p[k2.MA]) * (1.0 + old[0] / p[k2.EA])), 0.0)
    parts = np.empty((4, d, d))
    split_node(B, c_l, c_t2, parts)
    free = int(par[0]) == k2.FREE
    projector = np.empty((d, d))
    for a in range(d):
        for b in range(d):
            if side > 0:
                projector[a, b] = parts[0, a, b] / c_l + (0.0 if free else parts[2, a, b] / np.sqrt(c_t2))
            else:
                projector[a, b] = -parts[1, a, b] / c_l - (0.0 if free else parts[3, a, b] / np.sqrt(c_t2))
    count = 1 if free else dim
    rows = np.empty((count, d))
    row_basis(projector, count, rows)
    tension, speed = 1.0, 1.0
    for i in range(Y.shape[0]):
        tension = max(tension, abs(Y[i, 0]))
        for c in range(1, 1 + dim):
            speed = max(speed, abs(Y[i, c]))
    for q in range(d):
        x[q] = old[q]
    z = np.empty(d, dtype=np.complex128)
    out = np.empty(d, dtype=np.complex128)
    res, jac, dx = np.empty(d), np.empty((d, d)), np.empty(d)
    for _ in range(END_ITERATIONS):
        for q in range(-1, d):
            for r in range(d):
                z[r] = x[r]
            if q >= 0:
                z[q] += 1j * STEP
            _end_residual(z, old, nbr, par, side, dt, cur, up, p, dim, ds, rows, B, Minv, M, K, free, out)
            for r in range(d):
                if q < 0:
                    res[r] = -out[r].real
                else:
                    jac[r, q] = out[r].imag / STEP
        lu_factor(jac, LU, piv)
        for r in range(d):
            if LU[r, r] == 0.0:
                return SINGULAR
        lu_solve(LU, piv, res, dx)
        worst = 0.0
        for r in range(d):
            x[r] += dx[r]
            if not np.isfinite(x[r]):
                return NONFINITE
            worst = max(worst, abs(dx[r]) / (tension if r == 0 else (speed if r <= dim else 1.0)))
        if worst < END_TOLERANCE:
            return OK
    return DIVERGED


def line_data(world) -> FactorizedLine:
    """The :class:`FactorizedLine` of ``world`` (a :class:`~kanat.continuum.factorized.system.World`),
    its one builder: a planar cable's ``vertical`` is None, so the kernels compile their planar
    branches only."""
    system = world.system
    return FactorizedLine(current=np.ascontiguousarray(world.current, dtype=float),
                          vertical=np.asarray(world.up, dtype=float) if system.dim == 3 else None,
                          parameters=system.p, dimensions=system.dim, spacing=world.ds,
                          start=end_parameters(world.start), end=end_parameters(world.end))


def factorized_step_compiled(Y, line, dt, four, implicit, slack, delta):
    """One factorized step (two or four sweeps, states or increments) of the cable ``line``
    (:func:`line_data`); returns ``(X, status, node)``."""
    X = np.empty_like(Y)
    step = aot.kernel("factorized_step")
    status, node = step(Y, line, dt, four, implicit, slack, delta, X)
    return X, status, node


aot.register("factorized_step", __name__, *((aot.F2, line, aot.FLOAT, aot.BOOL, aot.BOOL, aot.FLOAT, aot.BOOL, aot.F2)
                                             for line in (FactorizedLine.narrowed(vertical=None), FactorizedLine)),
             returns=(aot.INT, aot.INT), function="_factorized_step")      # planar (vertical None) and spatial


@inner
def _split_all(Y, B, p, slack, parts):
    """The split of every node into ``parts`` (n, 4, d, d); returns the first node in compression
    beyond ``slack`` (or -1)."""
    c_l = np.sqrt(p[k2.EA] / p[k2.M])
    for i in range(Y.shape[0]):
        c_t2 = Y[i, 0] / ((p[k2.M] + p[k2.MA]) * (1.0 + Y[i, 0] / p[k2.EA]))
        if c_t2 < 0.0:
            if c_t2 > -slack:
                c_t2 = 0.0
            else:
                return i
        split_node(B[i], c_l, c_t2, parts[i])
    return -1


@kernel
def _factorized_step(Y, line, dt, four, implicit, slack, delta, X):
    """:func:`factorized_step_compiled` into ``X`` (n, d); returns ``(status, node)``."""
    cur, up, p, dim, ds = line.current, line.vertical, line.parameters, line.dimensions, line.spacing
    par0, par1 = line.start, line.end
    n, d = Y.shape
    B, D, J, _Ms = node_forms(Y, cur, up, p, implicit)
    parts = np.empty((n, 4, d, d))
    bad = _split_all(Y, B, p, slack, parts)
    if bad >= 0:
        for i in range(n):
            for a in range(d):
                X[i, a] = Y[i, a]
        return COMPRESSION, bad
    sigma = dt / ds
    offset, residual = np.empty((n, d)), np.empty((n, d))
    offset[:, :] = 0.0
    residual[:, :] = 0.0
    for i in range(n):
        for a in range(d):
            if delta:
                offset[i, a] = Y[i, a]
            X[i, a] = Y[i, a] - offset[i, a]
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
    end, nbr = np.empty(d), np.empty(d)
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
                    A[i, a, b] = (1.0 if a == b else 0.0) + sign * sigma * P
                if index == 0:
                    r[i, a] = -dt * residual[i, a] if delta else r[i, a] + dt * D[i, a]
                    if implicit:
                        for b in range(d):
                            A[i, a, b] -= dt * J[i, a, b]
                            if not delta:
                                r[i, a] -= dt * J[i, a, b] * Y[i, b]
        e, e_nbr = (0, 1) if forward else (n - 1, n - 2)
        for a in range(d):
            nbr[a] = X[e_nbr, a] + offset[e_nbr, a]
        status = end_solve(Y, e, -sign, nbr, par0 if forward else par1, dt, cur[e], up, p, dim, ds, end)
        for a in range(d):
            X[e, a] = end[a] - offset[e, a]
        if status != OK:
            _add(X, offset)
            return status, e
        sweep_into(A, C, r, X, forward)
    _add(X, offset)
    for e, e_nbr, par in ((n - 1, n - 2, par1), (0, 1, par0)):
        status = end_solve(Y, e, 1.0 if e > 0 else -1.0, X[e_nbr], par, dt, cur[e], up, p, dim, ds, end)
        for a in range(d):
            X[e, a] = end[a]
        if status != OK:
            return status, e
    for i in range(n):
        for q in range(d):
            if not np.isfinite(X[i, q]):
                return NONFINITE, i
    return OK, 0


@inner
def _add(X, offset):
    for i in range(X.shape[0]):
        for a in range(X.shape[1]):
            X[i, a] += offset[i, a]


def end_parameters(end) -> np.ndarray:
    """The ``ENDPAR`` vector of an :class:`~kanat.continuum.factorized.system.EndData`."""
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
