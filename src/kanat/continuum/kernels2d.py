"""Compiled kernels of the planar continuum cable (SPEC §2.1, §2.3, §2.4): residual and Jacobian.

The unknowns of a step are the nodal states ``X = Y^{n+1}``, ``Y = (T, u, v, phi)``. The
residual rows are ordered ``[start end (2); interval 1 (4); ...; interval N (4); far end (2)]``
so the Jacobian is banded with 5 sub- and 5 super-diagonals, and one Newton iteration
costs O(N).

Interval ``j`` (nodes ``j-1, j``) carries the box-method equations at its midpoint.
``M`` and ``K`` are linear in ``Y``, so their two-node averages are ``M`` and ``K`` of the
averaged state; ``F`` is nonlinear and averaged as such. With ``Yb`` the two-node mean:

    R0 = c m (Ydot_u - Yb_v Ydot_phi)                - T_s        - Fb_t
    R1 = c (m + m_a)(Ydot_v + Yb_u Ydot_phi)         - Tb phi_s   - Fb_n
    R2 = c Ydot_T / EA    - u_s + Yb_v phi_s
    R3 = c (1 + Tb / EA) Ydot_phi   - v_s - Yb_u phi_s

where inertia terms use the ``[am]``-weighted states and all others the ``[ak]``-weighted
ones (:mod:`kanat.continuum.schemes`), and ``c = 0`` gives the discrete steady problem.

The Jacobian is exact and written out: the interval rows are polynomial in the weighted
states (:func:`_interval_rows`), the nodal loads and the end conditions have their
derivatives beside them (:func:`node_load_jacobian`, :func:`end_jacobian`). A run compiles
only these real-valued kernels. The residuals are also complex-capable (``|x| x`` is written
``x sqrt(x x)``, analytic away from 0 with the right derivative there): the test oracle
:func:`jacobian_complex_step` differentiates them by complex step (error ~1e-16 relative)
and is compiled only by the tests. A new load term goes into :func:`node_load` and its
derivative into :func:`node_load_jacobian`; the oracle checks the pair.

Kernels use scalar loops only — no array expressions, slice copies or ``@`` — which keeps
numba's compile of a run to about a second (docs/performance.md).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

# Parameter vector layout (see :func:`kanat.continuum.model2d.parameters`).
M, MA, W0, EA, DIAM, CN, CT, RHO, DS, AM, AK, GAMMA, DT, INERTIA = range(14)
NPAR = 14
# The elastic law follows the scalars: p[LAW] = n knots, then n tensions (ascending), then n strains.
LAW = NPAR
# End conditions: kind and parameters (BPAR: [kind, Vx, Vz, mass, net_buoyancy, half_rho_cds, Fx, Fz]).
VELOCITY, BODY, FREE = 0, 1, 2
NBPAR = 8
STEP = 1e-30           # complex-step size: derivative = imag(R(x + i h)) / h, exact to round-off
LOWER = UPPER = 5      # bandwidths of the Jacobian


@kernel
def _law_segment(T, p):
    """Knot ``(t0, e0)`` and slope of the law's segment holding ``T`` (the last knot below it)."""
    n = int(p[LAW])
    i = 0
    if n > 2:                                  # a linear law (two knots) needs no search
        low, high = 0, n - 2                   # bisection for the last knot < T, within [0, n - 2]
        while low < high:
            mid = (low + high + 1) // 2
            if p[LAW + 1 + mid] < T.real:
                low = mid
            else:
                high = mid - 1
        i = low
    t0, t1 = p[LAW + 1 + i], p[LAW + 2 + i]
    e0, e1 = p[LAW + 1 + n + i], p[LAW + 2 + n + i]
    return t0, e0, (e1 - e0) / (t1 - t0)


@kernel
def strain(T, p):
    """Strain ``e(T)`` of the elastic law: piecewise linear through its knots, extended linearly.

    A linear law ``e = T / EA`` is the two knots ``(0, 0), (EA, 1)``. Within a segment the law
    is linear in ``T``, so complex-step derivatives pass through it exactly.
    """
    t0, e0, slope = _law_segment(T, p)
    return e0 + slope * (T - t0)


@kernel
def compliance(T, p):
    """``de/dT`` of the elastic law at ``T`` [1/N] (piecewise constant)."""
    return _law_segment(T, p)[2]


@kernel
def node_load(T, u, v, phi, ucx, ucz, p):
    """``(f_t, f_n)``: weight in water and drag per unit unstretched length (SPEC §2.1)."""
    c, s = np.cos(phi), np.sin(phi)
    root = np.sqrt(1.0 + strain(T, p))
    ur = u - (ucx * c + ucz * s)
    vr = v - (-ucx * s + ucz * c)
    ft = -p[W0] * s - 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT] * ur * np.sqrt(ur * ur) * root
    fn = -p[W0] * c - 0.5 * p[RHO] * p[DIAM] * p[CN] * vr * np.sqrt(vr * vr) * root
    return ft, fn


@kernel
def node_load_jacobian(T, u, v, phi, ucx, ucz, p, jac):
    """:func:`node_load` (real) and its derivatives ``jac[i, q] = d f_i / d (T, u, v, phi)_q`` (2, 4).

    With ``a = rho pi d C_t / 2``, ``b = rho d C_n / 2``, ``r = sqrt(1 + e(T))``:
    ``d(x|x|)/dx = 2|x|``, ``dr/dT = e'(T) / (2 r)``, ``du_r/dphi = -v_c``, ``dv_r/dphi = u_c``
    (``u_c, v_c`` the current's tangential and normal components).
    """
    c, s = np.cos(phi), np.sin(phi)
    t0, e0, slope = _law_segment(T, p)
    root = np.sqrt(1.0 + e0 + slope * (T - t0))
    droot = 0.5 * slope / root
    uc, vc = ucx * c + ucz * s, -ucx * s + ucz * c
    ur, vr = u - uc, v - vc
    a = 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT]
    b = 0.5 * p[RHO] * p[DIAM] * p[CN]
    jac[0, 0] = -a * ur * abs(ur) * droot
    jac[0, 1] = -2.0 * a * abs(ur) * root
    jac[0, 2] = 0.0
    jac[0, 3] = -p[W0] * c + 2.0 * a * abs(ur) * root * vc
    jac[1, 0] = -b * vr * abs(vr) * droot
    jac[1, 1] = 0.0
    jac[1, 2] = -2.0 * b * abs(vr) * root
    jac[1, 3] = p[W0] * s - 2.0 * b * abs(vr) * root * uc
    return -p[W0] * s - a * ur * abs(ur) * root, -p[W0] * c - b * vr * abs(vr) * root


@kernel
def weighted(x, y, d, p):
    """States at ``[am]`` and ``[ak]`` and the rate at ``[am]`` for one node (shapes (4,))."""
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    m, k, r = np.empty(4, x.dtype), np.empty(4, x.dtype), np.empty(4, x.dtype)
    for i in range(4):
        xdot = (x[i] - y[i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[i]
        m[i] = (1.0 - am) * x[i] + am * y[i]
        k[i] = (1.0 - ak) * x[i] + ak * y[i]
        r[i] = (1.0 - am) * xdot + am * d[i]
    return m, k, r


@kernel
def interval_residual(xl, xr, yl, yr, dl, dr, cl, cr, p, out):
    """The four box equations of one interval (module docstring); writes ``out`` (4,)."""
    ml, kl, rl = weighted(xl, yl, dl, p)
    mr, kr, rr = weighted(xr, yr, dr, p)
    mb = 0.5 * (ml + mr)
    kb = 0.5 * (kl + kr)
    rate = 0.5 * (rl + rr)
    grad = (kr - kl) / p[DS]
    ftl, fnl = node_load(kl[0], kl[1], kl[2], kl[3], cl[0], cl[1], p)
    ftr, fnr = node_load(kr[0], kr[1], kr[2], kr[3], cr[0], cr[1], p)
    c = p[INERTIA]
    mass, normal_mass = p[M], p[M] + p[MA]
    out[0] = c * mass * (rate[1] - mb[2] * rate[3]) - grad[0] - 0.5 * (ftl + ftr)
    out[1] = c * normal_mass * (rate[2] + mb[1] * rate[3]) - kb[0] * grad[3] - 0.5 * (fnl + fnr)
    out[2] = c * compliance(mb[0], p) * rate[0] - grad[1] + kb[2] * grad[3]
    out[3] = c * (1.0 + strain(mb[0], p)) * rate[3] - grad[2] - kb[1] * grad[3]


@kernel
def end_residual(x, y, d, cur, p, b, side, out):
    """The two conditions of one end (SPEC §2.3); ``side`` = -1 at ``s = 0``, +1 at ``s = L``.

    Prescribed velocity (tow point, anchor): ``u = V.t``, ``v = V.n`` at the new level.
    Body: ``(M_b + M_a) dV/dt = -side T t + B z + D + F`` in (t, n) components, inertia at
    ``[am]``, forces at ``[ak]``, ``D = 0.5 rho C_D S |U_r| U_r`` with ``U_r`` the water
    velocity relative to the body. Free end: ``T = 0`` and the normal momentum equation of
    the end node without its (vanishing) tension term.
    """
    kind = int(b[0].real)
    if kind == VELOCITY:
        c, s = np.cos(x[3]), np.sin(x[3])
        out[0] = x[1] - (b[1] * c + b[2] * s)
        out[1] = x[2] - (-b[1] * s + b[2] * c)
        return
    m, k, r = weighted(x, y, d, p)
    c, s = np.cos(k[3]), np.sin(k[3])
    if kind == FREE:
        ft, fn = node_load(k[0], k[1], k[2], k[3], cur[0], cur[1], p)
        out[0] = x[0] / p[EA]
        out[1] = p[INERTIA] * (p[M] + p[MA]) * (r[2] + m[1] * r[3]) - fn
        return
    wt = cur[0] * c + cur[1] * s - k[1]                      # water relative to body, along t
    wn = -cur[0] * s + cur[1] * c - k[2]
    speed = np.sqrt(wt * wt + wn * wn)
    buoy, drag = b[4], b[5] * speed
    mass = p[INERTIA] * b[3]
    out[0] = mass * (r[1] - m[2] * r[3]) - (-side * k[0] + buoy * s + drag * wt + b[6] * c + b[7] * s)
    out[1] = mass * (r[2] + m[1] * r[3]) - (buoy * c + drag * wn - b[6] * s + b[7] * c)


@kernel
def end_jacobian(x, y, d, cur, p, b, side, out, jac):
    """:func:`end_residual` into ``out`` (2,) and its derivatives by ``x`` into ``jac`` (2, 4), real.

    The same equations written out for a real ``x`` (the tests compare the two): the
    weighted states depend on ``x`` as ``dm/dx = 1 - a_m``, ``dk/dx = 1 - a_k``,
    ``dr/dx = (1 - a_m) / (gamma dt)``; the body's drag ``b5 |w| w`` of the relative water
    velocity ``w`` has the derivative ``b5 (|w| I + w w^T / |w|)`` (zero at rest).
    """
    for i in range(2):
        for q in range(4):
            jac[i, q] = 0.0
    kind = int(b[0])
    if kind == VELOCITY:
        c, s = np.cos(x[3]), np.sin(x[3])
        out[0] = x[1] - (b[1] * c + b[2] * s)
        out[1] = x[2] - (-b[1] * s + b[2] * c)
        jac[0, 1], jac[0, 3] = 1.0, b[1] * s - b[2] * c
        jac[1, 2], jac[1, 3] = 1.0, b[1] * c + b[2] * s
        return
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    m1, m2 = cm * x[1] + am * y[1], cm * x[2] + am * y[2]
    k0, k1, k2, k3 = (ck * x[0] + ak * y[0], ck * x[1] + ak * y[1], ck * x[2] + ak * y[2],
                      ck * x[3] + ak * y[3])
    r1, r2, r3 = (cr * (x[1] - y[1]) - cm * (1.0 - gamma) / gamma * d[1] + am * d[1],
                  cr * (x[2] - y[2]) - cm * (1.0 - gamma) / gamma * d[2] + am * d[2],
                  cr * (x[3] - y[3]) - cm * (1.0 - gamma) / gamma * d[3] + am * d[3])
    if kind == FREE:
        load = np.empty((2, 4))
        fn = node_load_jacobian(k0, k1, k2, k3, cur[0], cur[1], p, load)[1]
        mn = p[INERTIA] * (p[M] + p[MA])
        out[0] = x[0] / p[EA]
        out[1] = mn * (r2 + m1 * r3) - fn
        jac[0, 0] = 1.0 / p[EA]
        jac[1, 0] = -load[1, 0] * ck
        jac[1, 1] = mn * r3 * cm - load[1, 1] * ck
        jac[1, 2] = mn * cr - load[1, 2] * ck
        jac[1, 3] = mn * m1 * cr - load[1, 3] * ck
        return
    c, s = np.cos(k3), np.sin(k3)
    wt = cur[0] * c + cur[1] * s - k1                     # water relative to the body, along t and n
    wn = -cur[0] * s + cur[1] * c - k2
    speed = np.sqrt(wt * wt + wn * wn)
    mass = p[INERTIA] * b[3]
    out[0] = mass * (r1 - m2 * r3) - (-side * k0 + b[4] * s + b[5] * speed * wt + b[6] * c + b[7] * s)
    out[1] = mass * (r2 + m1 * r3) - (b[4] * c + b[5] * speed * wn - b[6] * s + b[7] * c)
    g00 = g01 = g11 = 0.0
    if speed > 0.0:
        g00, g01, g11 = b[5] * (speed + wt * wt / speed), b[5] * wt * wn / speed, b[5] * (speed + wn * wn / speed)
    dwt3, dwn3 = wn + k2, -(wt + k1)            # d(wt)/d(phi), d(wn)/d(phi); d(wt)/du = d(wn)/dv = -1
    jac[0, 0] = side * ck
    jac[0, 1] = mass * cr + g00 * ck
    jac[0, 2] = -mass * r3 * cm + g01 * ck
    jac[0, 3] = -mass * m2 * cr - (b[4] * c - b[6] * s + b[7] * c + g00 * dwt3 + g01 * dwn3) * ck
    jac[1, 1] = mass * r3 * cm + g01 * ck
    jac[1, 2] = mass * cr + g11 * ck
    jac[1, 3] = mass * m1 * cr - (-b[4] * s - b[6] * c - b[7] * s + g01 * dwt3 + g11 * dwn3) * ck


@kernel
def assemble(x, y, d, cur, p, b0, b1, res, band):
    """Residual ``res`` (4(N+1),) and banded Jacobian ``band`` (11, 4(N+1)) at unknowns ``x``.

    ``x, y, d`` are (N+1, 4): new state, old state, old rate; ``cur`` (N+1, 2) the current
    (x, z) at the nodes; ``b0``, ``b1`` the end conditions at ``s = 0`` and ``s = L``.
    ``band[UPPER + row - col, col]`` holds ``dR[row]/dx[col]`` (LAPACK banded storage).

    The interval rows are polynomial in the weighted nodal states, so their derivatives
    are written out (:func:`_interval_rows`); the nodal loads are differentiated once per
    node (:func:`_node_loads`), the ends by :func:`end_jacobian`. The all-complex-step
    :func:`jacobian_complex_step` is the oracle the tests compare this with.
    """
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    wm = np.empty((n_nodes, 4))
    wk = np.empty((n_nodes, 4))
    wr = np.empty((n_nodes, 4))
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    for j in range(n_nodes):
        for i in range(4):
            rate = (x[j, i] - y[j, i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[j, i]
            wm[j, i] = (1.0 - am) * x[j, i] + am * y[j, i]
            wk[j, i] = (1.0 - ak) * x[j, i] + ak * y[j, i]
            wr[j, i] = (1.0 - am) * rate + am * d[j, i]
    load, dload = _node_loads(wk, cur, p)
    chain = np.empty(3)
    chain[0], chain[1], chain[2] = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    for j in range(1, n_nodes):
        _interval_rows(j, wm, wk, wr, load, dload, p, chain, res, band)
    _end_rows(x, y, d, cur, p, b0, b1, res, band)


@inner
def _node_loads(wk, cur, p):
    """Loads ``(f_t, f_n)`` at every node and their derivatives by the node's 4 states."""
    n_nodes = wk.shape[0]
    load = np.empty((n_nodes, 2))
    dload = np.empty((n_nodes, 2, 4))
    jac = np.empty((2, 4))
    for j in range(n_nodes):
        ft, fn = node_load_jacobian(wk[j, 0], wk[j, 1], wk[j, 2], wk[j, 3], cur[j, 0], cur[j, 1], p, jac)
        load[j, 0], load[j, 1] = ft, fn
        for i in range(2):
            for q in range(4):
                dload[j, i, q] = jac[i, q]
    return load, dload


@inner
def _interval_rows(j, wm, wk, wr, load, dload, p, chain, res, band):
    """Rows of interval ``j`` (module docstring) and their exact derivatives."""
    l, r = j - 1, j
    c, ds = p[INERTIA], p[DS]
    mass, normal_mass = p[M], p[M] + p[MA]
    mb1, mb2, mb0 = 0.5 * (wm[l, 1] + wm[r, 1]), 0.5 * (wm[l, 2] + wm[r, 2]), 0.5 * (wm[l, 0] + wm[r, 0])
    kb0, kb1, kb2 = 0.5 * (wk[l, 0] + wk[r, 0]), 0.5 * (wk[l, 1] + wk[r, 1]), 0.5 * (wk[l, 2] + wk[r, 2])
    r0, r1, r2, r3 = (0.5 * (wr[l, 0] + wr[r, 0]), 0.5 * (wr[l, 1] + wr[r, 1]),
                      0.5 * (wr[l, 2] + wr[r, 2]), 0.5 * (wr[l, 3] + wr[r, 3]))
    g0, g1, g2, g3 = ((wk[r, 0] - wk[l, 0]) / ds, (wk[r, 1] - wk[l, 1]) / ds,
                      (wk[r, 2] - wk[l, 2]) / ds, (wk[r, 3] - wk[l, 3]) / ds)
    row = 2 + 4 * (j - 1)
    res[row] = c * mass * (r1 - mb2 * r3) - g0 - 0.5 * (load[l, 0] + load[r, 0])
    res[row + 1] = c * normal_mass * (r2 + mb1 * r3) - kb0 * g3 - 0.5 * (load[l, 1] + load[r, 1])
    t0, e0, flex = _law_segment(mb0, p)
    stretch = 1.0 + e0 + flex * (mb0 - t0)
    res[row + 2] = c * flex * r0 - g1 + kb2 * g3
    res[row + 3] = c * stretch * r3 - g2 - kb1 * g3
    dm = np.zeros((4, 4))          # dR[row i] / d(weighted state of one node)[q], for m, k, r
    dk = np.zeros((4, 4))
    dr = np.zeros((4, 4))
    for side in range(2):
        node = l if side == 0 else r
        sign = -1.0 if side == 0 else 1.0
        dm[:, :] = 0.0
        dr[:, :] = 0.0
        dk[:, :] = 0.0
        dm[0, 2] = -0.5 * c * mass * r3
        dr[0, 1] = 0.5 * c * mass
        dr[0, 3] = -0.5 * c * mass * mb2
        dk[0, 0] = -sign / ds
        dm[1, 1] = 0.5 * c * normal_mass * r3
        dr[1, 2] = 0.5 * c * normal_mass
        dr[1, 3] = 0.5 * c * normal_mass * mb1
        dk[1, 0] = -0.5 * g3
        dk[1, 3] = -kb0 * sign / ds
        dr[2, 0] = 0.5 * c * flex
        dk[2, 1] = -sign / ds
        dk[2, 2] = 0.5 * g3
        dk[2, 3] = kb2 * sign / ds
        dm[3, 0] = 0.5 * c * r3 * flex
        dr[3, 3] = 0.5 * c * stretch
        dk[3, 1] = -0.5 * g3
        dk[3, 2] = -sign / ds
        dk[3, 3] = -kb1 * sign / ds
        for q in range(4):
            dk[0, q] -= 0.5 * dload[node, 0, q]
            dk[1, q] -= 0.5 * dload[node, 1, q]
        for q in range(4):
            col = 4 * node + q
            for i in range(4):
                band[UPPER + row + i - col, col] = dm[i, q] * chain[0] + dk[i, q] * chain[1] + dr[i, q] * chain[2]


@kernel
def jacobian_complex_step(x, y, d, cur, p, b0, b1, res, band):
    """The same residual and Jacobian as :func:`assemble`, every entry by complex step.

    Slower (each interval evaluated 9 times); the tests' oracle for :func:`assemble`.
    """
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    out = np.empty(4)
    zout = np.empty(4, dtype=np.complex128)
    zl = np.empty(4, dtype=np.complex128)
    zr = np.empty(4, dtype=np.complex128)
    for j in range(1, n_nodes):
        row = 2 + 4 * (j - 1)
        interval_residual(x[j - 1], x[j], y[j - 1], y[j], d[j - 1], d[j], cur[j - 1], cur[j], p, out)
        res[row:row + 4] = out
        for side in range(2):
            for k in range(4):
                zl[:] = x[j - 1]
                zr[:] = x[j]
                if side == 0:
                    zl[k] += 1j * STEP
                else:
                    zr[k] += 1j * STEP
                interval_residual(zl, zr, y[j - 1], y[j], d[j - 1], d[j], cur[j - 1], cur[j], p, zout)
                col = 4 * (j - 1 + side) + k
                for i in range(4):
                    band[UPPER + row + i - col, col] = zout[i].imag / STEP
    _end_rows_complex_step(x[0], y[0], d[0], cur[0], p, b0, -1.0, 0, 0, res, band)
    _end_rows_complex_step(x[-1], y[-1], d[-1], cur[-1], p, b1, 1.0, 4 * n_nodes - 2, 4 * (n_nodes - 1), res, band)


@inner
def _end_rows(x, y, d, cur, p, b0, b1, res, band):
    """The two rows of each end and their derivatives (:func:`end_jacobian`) into ``res``, ``band``."""
    out = np.empty(2)
    jac = np.empty((2, 4))
    last = x.shape[0] - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, 4 * last + 2)
        end_jacobian(x[node], y[node], d[node], cur[node], p, b0 if end == 0 else b1, side, out, jac)
        for i in range(2):
            res[row + i] = out[i]
            for k in range(4):
                band[UPPER + row + i - (4 * node + k), 4 * node + k] = jac[i, k]


@kernel
def _end_rows_complex_step(x, y, d, cur, p, b, side, row, col0, res, band):
    """:func:`_end_rows` by complex step (the tests' oracle)."""
    out = np.empty(2)
    zout = np.empty(2, dtype=np.complex128)
    z = np.empty(4, dtype=np.complex128)
    end_residual(x, y, d, cur, p, b, side, out)
    res[row:row + 2] = out
    for k in range(4):
        z[:] = x
        z[k] += 1j * STEP
        end_residual(z, y, d, cur, p, b, side, zout)
        for i in range(2):
            band[UPPER + row + i - (col0 + k), col0 + k] = zout[i].imag / STEP
