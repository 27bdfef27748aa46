"""Compiled kernels of the spatial continuum cable (SPEC §2.2–2.4): residual and Jacobian.

Unknowns per node ``Y = (T, u, v, w, phi, theta)``; ``V = u t + v n + w b`` with the frame of
SPEC §2.2 about the pole ``p`` of the current chart, and every vector (weight direction,
current, prescribed velocities) given in chart coordinates ``(e1, e2, p)``. Projecting
momentum and compatibility on ``(t, n, b)`` gives ``M(Y) Y_t + K(Y) Y_s = F(Y)`` with

    row 0  m (u_t - v phi_t + w cos(phi) theta_t)            - T_s                 = f_t
    row 1  mn (v_t + u phi_t - w sin(phi) theta_t)           - T phi_s             = f_n
    row 2  mn (w_t - u cos(phi) theta_t + v sin(phi) theta_t) + T cos(phi) theta_s  = f_b
    row 3  T_t / EA       - u_s + v phi_s - w cos(phi) theta_s                     = 0
    row 4  (1 + e) phi_t  - v_s - u phi_s + w sin(phi) theta_s                     = 0
    row 5  -(1 + e) cos(phi) theta_t - w_s + u cos(phi) theta_s - v sin(phi) theta_s = 0

(``mn = m + m_a``; frame identities ``t_phi = n``, ``t_theta = -cos(phi) b``, ``n_phi = -t``,
``n_theta = sin(phi) b``, ``b_theta = cos(phi) t - sin(phi) n``). For ``w = 0`` and constant
``theta`` rows 0, 1, 3, 4 are the planar equations of SPEC §2.1; :mod:`derivation3d` derives
the same system symbolically and the tests compare. ``M`` is singular where ``cos(phi) = 0``
(the tangent along the pole): the driver re-charts the pole before that happens.

Box method and generalized-α exactly as the planar kernels (:mod:`kernels2d`), with the
two-node averages of ``M``, ``K`` and ``F``; rows are ``[start (3); interval 1 (6); ...;
far end (3)]``, a band of 8 sub- and super-diagonals. All derivatives are written out —
``M(m) r`` and ``K(k) g`` (:func:`d_mass_times`, :func:`d_stiffness_times`), the nodal loads
(:func:`node_load3_jacobian`) and the ends (:func:`end_jacobian3`) — so a run compiles real
kernels only; the complex-step oracle :func:`jacobian_complex_step3` is compiled by the tests.
As in :mod:`kernels2d`, scalar loops only (no array expressions, slice copies or ``@``).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.continuum.kernels2d import (AK, AM, CN, CT, DIAM, DS, DT, EA, FREE, GAMMA, INERTIA, MA, RHO,
                                       STEP, VELOCITY, W0, M, _law_segment, compliance, strain)

LOWER = UPPER = 8
# End parameters: [kind, Vt1, Vt2, Vp (velocity, chart), mass, net_buoyancy, half_rho_cds, F1, F2, Fp]
NBPAR3 = 10


@kernel
def frame(phi, theta):
    """Chart components of ``(t, n, b)`` (each a 3-tuple) at angles ``phi, theta``."""
    cp, sp, ct, st = np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta)
    return (cp * ct, cp * st, sp), (-sp * ct, -sp * st, cp), (st, -ct, 0.0 * st)


@kernel
def node_load3(T, u, v, w, phi, theta, cur, up, p):
    """``(f_t, f_n, f_b)``: weight in water and drag of the relative flow per unstretched length."""
    t, n, b = frame(phi, theta)
    root = np.sqrt(1.0 + strain(T, p))
    ur = u - (cur[0] * t[0] + cur[1] * t[1] + cur[2] * t[2])
    vr = v - (cur[0] * n[0] + cur[1] * n[1] + cur[2] * n[2])
    wr = w - (cur[0] * b[0] + cur[1] * b[1] + cur[2] * b[2])
    g = -p[W0]
    normal = 0.5 * p[RHO] * p[DIAM] * p[CN] * np.sqrt(vr * vr + wr * wr) * root
    ft = g * (up[0] * t[0] + up[1] * t[1] + up[2] * t[2]) - 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT] * ur * np.sqrt(
        ur * ur) * root
    fn = g * (up[0] * n[0] + up[1] * n[1] + up[2] * n[2]) - normal * vr
    fb = g * (up[0] * b[0] + up[1] * b[1] + up[2] * b[2]) - normal * wr
    return ft, fn, fb


@kernel
def node_load3_jacobian(y, cur, up, p, jac):
    """:func:`node_load3` (real) at the state ``y`` (6,) and ``jac[i, q] = d f_i / d y_q`` (3, 6).

    Frame derivatives ``t_phi = n``, ``n_phi = -t``, ``b_phi = 0``, ``t_theta = -cos(phi) b``,
    ``n_theta = sin(phi) b``, ``b_theta = cos(phi) t - sin(phi) n`` (module docstring);
    ``d(x|x|)/dx = 2|x|``; the normal drag ``c |w| w`` of ``w = (v_r, w_r)`` has the
    derivative ``c (|w| I + w w^T / |w|)``; ``d sqrt(1 + e)/dT = e'(T) / (2 sqrt(1 + e))``.
    """
    T, phi, theta = y[0], y[4], y[5]
    cp, sp, ct, st = np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta)
    t0, t1, t2 = cp * ct, cp * st, sp
    n0, n1, n2 = -sp * ct, -sp * st, cp
    b0, b1 = st, -ct
    ct_, cn_, cb_ = cur[0] * t0 + cur[1] * t1 + cur[2] * t2, cur[0] * n0 + cur[1] * n1 + cur[2] * n2, \
        cur[0] * b0 + cur[1] * b1
    ut, un, ub = up[0] * t0 + up[1] * t1 + up[2] * t2, up[0] * n0 + up[1] * n1 + up[2] * n2, up[0] * b0 + up[1] * b1
    knot, e0, slope = _law_segment(T, p)
    root = np.sqrt(1.0 + e0 + slope * (T - knot))
    droot = 0.5 * slope / root
    ur, vr, wr = y[1] - ct_, y[2] - cn_, y[3] - cb_
    g = -p[W0]
    a = 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT]
    c = 0.5 * p[RHO] * p[DIAM] * p[CN]
    q = np.sqrt(vr * vr + wr * wr)
    j00, j01, j11 = 0.0, 0.0, 0.0                  # d(q w)/dw, symmetric 2 x 2
    if q > 0.0:
        j00, j01, j11 = q + vr * vr / q, vr * wr / q, q + wr * wr / q
    # d(ur, vr, wr)/d(phi) and /d(theta); d(ut, un, ub) likewise
    dur_p, dvr_p, dwr_p = -cn_, ct_, 0.0
    dur_t, dvr_t, dwr_t = cp * cb_, -sp * cb_, -(cp * ct_ - sp * cn_)
    dut_p, dun_p, dub_p = un, -ut, 0.0
    dut_t, dun_t, dub_t = -cp * ub, sp * ub, cp * ut - sp * un
    for i in range(3):
        for k in range(6):
            jac[i, k] = 0.0
    tangential = a * ur * abs(ur)
    jac[0, 0] = -tangential * droot
    jac[0, 1] = -2.0 * a * abs(ur) * root
    jac[0, 4] = g * dut_p - 2.0 * a * abs(ur) * root * dur_p
    jac[0, 5] = g * dut_t - 2.0 * a * abs(ur) * root * dur_t
    jac[1, 0] = -c * q * vr * droot
    jac[2, 0] = -c * q * wr * droot
    jac[1, 2], jac[1, 3] = -c * root * j00, -c * root * j01
    jac[2, 2], jac[2, 3] = -c * root * j01, -c * root * j11
    jac[1, 4] = g * dun_p - c * root * (j00 * dvr_p + j01 * dwr_p)
    jac[1, 5] = g * dun_t - c * root * (j00 * dvr_t + j01 * dwr_t)
    jac[2, 4] = g * dub_p - c * root * (j01 * dvr_p + j11 * dwr_p)
    jac[2, 5] = g * dub_t - c * root * (j01 * dvr_t + j11 * dwr_t)
    normal = c * q * root
    return g * ut - tangential * root, g * un - normal * vr, g * ub - normal * wr


@kernel
def mass_times(y, r, p, out):
    """``out = M(y) r`` (rows of the module docstring)."""
    m, mn = p[M], p[M] + p[MA]
    cp, sp = np.cos(y[4]), np.sin(y[4])
    stretch = 1.0 + strain(y[0], p)
    out[0] = m * (r[1] - y[2] * r[4] + y[3] * cp * r[5])
    out[1] = mn * (r[2] + y[1] * r[4] - y[3] * sp * r[5])
    out[2] = mn * (r[3] + (-y[1] * cp + y[2] * sp) * r[5])
    out[3] = compliance(y[0], p) * r[0]
    out[4] = stretch * r[4]
    out[5] = -stretch * cp * r[5]


@kernel
def stiffness_times(y, g, out):
    """``out = K(y) g``."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    out[0] = -g[0]
    out[1] = -y[0] * g[4]
    out[2] = y[0] * cp * g[5]
    out[3] = -g[1] + y[2] * g[4] - y[3] * cp * g[5]
    out[4] = -g[2] - y[1] * g[4] + y[3] * sp * g[5]
    out[5] = -g[3] + (y[1] * cp - y[2] * sp) * g[5]


@kernel
def mass_matrix(y, p, out):
    """``out = M(y)`` (6, 6), the rows of :func:`mass_times` written out (one law lookup)."""
    m, mn = p[M], p[M] + p[MA]
    cp, sp = np.cos(y[4]), np.sin(y[4])
    knot, e0, flex = _law_segment(y[0], p)
    stretch = 1.0 + e0 + flex * (y[0] - knot)
    out[:, :] = 0.0
    out[0, 1], out[0, 4], out[0, 5] = m, -m * y[2], m * y[3] * cp
    out[1, 2], out[1, 4], out[1, 5] = mn, mn * y[1], -mn * y[3] * sp
    out[2, 3], out[2, 5] = mn, mn * (-y[1] * cp + y[2] * sp)
    out[3, 0] = flex
    out[4, 4] = stretch
    out[5, 5] = -stretch * cp


@kernel
def stiffness_matrix(y, out):
    """``out = K(y)`` (6, 6), the rows of :func:`stiffness_times` written out."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    out[:, :] = 0.0
    out[0, 0] = -1.0
    out[1, 4] = -y[0]
    out[2, 5] = y[0] * cp
    out[3, 1], out[3, 4], out[3, 5] = -1.0, y[2], -y[3] * cp
    out[4, 2], out[4, 4], out[4, 5] = -1.0, -y[1], y[3] * sp
    out[5, 3], out[5, 5] = -1.0, y[1] * cp - y[2] * sp


@kernel
def d_mass_times(y, r, p, out):
    """``out[i, q] = d(M(y) r)_i / d y_q`` for fixed ``r``."""
    m, mn = p[M], p[M] + p[MA]
    cp, sp = np.cos(y[4]), np.sin(y[4])
    knot, e0, flex = _law_segment(y[0], p)
    stretch = 1.0 + e0 + flex * (y[0] - knot)
    out[:, :] = 0.0
    out[0, 2], out[0, 3], out[0, 4] = -m * r[4], m * cp * r[5], -m * y[3] * sp * r[5]
    out[1, 1], out[1, 3], out[1, 4] = mn * r[4], -mn * sp * r[5], -mn * y[3] * cp * r[5]
    out[2, 1], out[2, 2], out[2, 4] = -mn * cp * r[5], mn * sp * r[5], mn * (y[1] * sp + y[2] * cp) * r[5]
    out[4, 0] = r[4] * flex
    out[5, 0], out[5, 4] = -cp * r[5] * flex, stretch * sp * r[5]


@kernel
def d_stiffness_times(y, g, out):
    """``out[i, q] = d(K(y) g)_i / d y_q`` for fixed ``g``."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    out[:, :] = 0.0
    out[1, 0] = -g[4]
    out[2, 0], out[2, 4] = cp * g[5], -y[0] * sp * g[5]
    out[3, 2], out[3, 3], out[3, 4] = g[4], -cp * g[5], y[3] * sp * g[5]
    out[4, 1], out[4, 3], out[4, 4] = -g[4], sp * g[5], y[3] * cp * g[5]
    out[5, 1], out[5, 2], out[5, 4] = cp * g[5], -sp * g[5], (-y[1] * sp - y[2] * cp) * g[5]


@inner
def _node_loads(wk, cur, up, p):
    """Loads (n, 3) at the ``[ak]`` states and their derivatives (n, 3, 6) (:func:`node_load3_jacobian`)."""
    n_nodes = wk.shape[0]
    load = np.empty((n_nodes, 3))
    dload = np.empty((n_nodes, 3, 6))
    jac = np.empty((3, 6))
    for j in range(n_nodes):
        f0, f1, f2 = node_load3_jacobian(wk[j], cur[j], up, p, jac)
        load[j, 0], load[j, 1], load[j, 2] = f0, f1, f2
        for i in range(3):
            for q in range(6):
                dload[j, i, q] = jac[i, q]
    return load, dload


@kernel
def assemble3(x, y, d, cur, up, p, b0, b1, res, band):
    """Residual (6(N+1),) and banded Jacobian (17, 6(N+1)) of one step at unknowns ``x`` (N+1, 6).

    ``y, d``: old state and rate; ``cur`` (N+1, 3) current in chart coordinates; ``up`` (3,)
    the chart components of the vertical ``z``; ``b0, b1`` end conditions (NBPAR3).
    """
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    wm, wk, wr = np.empty((n_nodes, 6)), np.empty((n_nodes, 6)), np.empty((n_nodes, 6))
    for j in range(n_nodes):
        for i in range(6):
            wm[j, i] = (1.0 - am) * x[j, i] + am * y[j, i]
            wk[j, i] = (1.0 - ak) * x[j, i] + ak * y[j, i]
            wr[j, i] = (1.0 - am) * ((x[j, i] - y[j, i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[j, i]) \
                + am * d[j, i]
    load, dload = _node_loads(wk, cur, up, p)
    scratch, vectors = np.empty((6, 6, 6)), np.empty((2, 6))
    for j in range(1, n_nodes):
        _interval_rows3(j, wm, wk, wr, load, dload, p, scratch, vectors, res, band)
    _end_rows3(x, y, d, cur, up, p, b0, b1, res, band)


@inner
def _interval_rows3(j, wm, wk, wr, load, dload, p, scratch, vectors, res, band):
    """The six rows of interval ``j`` and their derivatives by the states of its two nodes
    (``scratch`` (6, 6, 6) and ``vectors`` (2, 6) are work space)."""
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    c, ds = p[INERTIA], p[DS]
    l, r = j - 1, j
    ml, mr, kl, kr, dm, dk = scratch[0], scratch[1], scratch[2], scratch[3], scratch[4], scratch[5]
    rate, grad = vectors[0], vectors[1]
    for i in range(6):
        rate[i] = 0.5 * (wr[l, i] + wr[r, i])
        grad[i] = (wk[r, i] - wk[l, i]) / ds
    mass_matrix(wm[l], p, ml)
    mass_matrix(wm[r], p, mr)
    stiffness_matrix(wk[l], kl)
    stiffness_matrix(wk[r], kr)
    row = 3 + 6 * (j - 1)
    for i in range(6):
        acc = 0.0
        for q in range(6):
            acc += c * 0.5 * (ml[i, q] + mr[i, q]) * rate[q] + 0.5 * (kl[i, q] + kr[i, q]) * grad[q]
        if i < 3:
            acc -= 0.5 * (load[l, i] + load[r, i])
        res[row + i] = acc
    for side in range(2):
        node = l if side == 0 else r
        sign = -1.0 if side == 0 else 1.0
        d_mass_times(wm[node], rate, p, dm)
        d_stiffness_times(wk[node], grad, dk)
        for q in range(6):
            col = 6 * node + q
            for i in range(6):
                value = (c * (0.5 * dm[i, q] * cm + 0.25 * (ml[i, q] + mr[i, q]) * cr)
                         + 0.5 * dk[i, q] * ck + 0.5 * (kl[i, q] + kr[i, q]) * sign / ds * ck)
                if i < 3:
                    value -= 0.5 * dload[node, i, q] * ck
                band[UPPER + row + i - col, col] = value


@kernel
def end_residual3(x, y, d, cur, up, p, b, side, out):
    """The three conditions of one end (SPEC §2.3), as :func:`kernels2d.end_residual` in 3-D."""
    kind = int(b[0].real)
    if kind == VELOCITY:
        t, n, bb = frame(x[4], x[5])
        out[0] = x[1] - (b[1] * t[0] + b[2] * t[1] + b[3] * t[2])
        out[1] = x[2] - (b[1] * n[0] + b[2] * n[1] + b[3] * n[2])
        out[2] = x[3] - (b[1] * bb[0] + b[2] * bb[1] + b[3] * bb[2])
        return
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    m = (1.0 - am) * x + am * y
    k = (1.0 - ak) * x + ak * y
    r = (1.0 - am) * ((x - y) / (gamma * dt) - (1.0 - gamma) / gamma * d) + am * d
    cp, sp = np.cos(m[4]), np.sin(m[4])
    at = r[1] - m[2] * r[4] + m[3] * cp * r[5]                     # acceleration in (t, n, b)
    an = r[2] + m[1] * r[4] - m[3] * sp * r[5]
    ab = r[3] + (-m[1] * cp + m[2] * sp) * r[5]
    if kind == FREE:
        f = node_load3(k[0], k[1], k[2], k[3], k[4], k[5], cur, up, p)
        mn = p[INERTIA] * (p[M] + p[MA])
        out[0] = x[0] / p[EA]
        out[1] = mn * an - f[1]
        out[2] = mn * ab - f[2]
        return
    t, n, bb = frame(k[4], k[5])
    rel_t = cur[0] * t[0] + cur[1] * t[1] + cur[2] * t[2] - k[1]    # water relative to the body
    rel_n = cur[0] * n[0] + cur[1] * n[1] + cur[2] * n[2] - k[2]
    rel_b = cur[0] * bb[0] + cur[1] * bb[1] + cur[2] * bb[2] - k[3]
    drag = b[6] * np.sqrt(rel_t * rel_t + rel_n * rel_n + rel_b * rel_b)
    lift = (b[5] * up[0] + b[7], b[5] * up[1] + b[8], b[5] * up[2] + b[9])   # buoyancy + force
    mass = p[INERTIA] * b[4]
    out[0] = mass * at - (-side * k[0] + drag * rel_t + lift[0] * t[0] + lift[1] * t[1] + lift[2] * t[2])
    out[1] = mass * an - (drag * rel_n + lift[0] * n[0] + lift[1] * n[1] + lift[2] * n[2])
    out[2] = mass * ab - (drag * rel_b + lift[0] * bb[0] + lift[1] * bb[1] + lift[2] * bb[2])


@kernel
def end_jacobian3(x, y, d, cur, up, p, b, side, out, jac):
    """:func:`end_residual3` (real) into ``out`` (3,) and its derivatives by ``x`` into ``jac`` (3, 6).

    The same equations written out (the tests compare): weighted states as in
    :func:`kernels2d.end_jacobian`, frame derivatives as in :func:`node_load3_jacobian`, the
    body's drag ``b6 |w| w`` with derivative ``b6 (|w| I + w w^T / |w|)``.
    """
    for i in range(3):
        for q in range(6):
            jac[i, q] = 0.0
    kind = int(b[0])
    if kind == VELOCITY:
        cp, sp, ct, st = np.cos(x[4]), np.sin(x[4]), np.cos(x[5]), np.sin(x[5])
        vt = b[1] * cp * ct + b[2] * cp * st + b[3] * sp
        vn = -b[1] * sp * ct - b[2] * sp * st + b[3] * cp
        vb = b[1] * st - b[2] * ct
        out[0], out[1], out[2] = x[1] - vt, x[2] - vn, x[3] - vb
        jac[0, 1], jac[1, 2], jac[2, 3] = 1.0, 1.0, 1.0
        jac[0, 4], jac[0, 5] = -vn, cp * vb
        jac[1, 4], jac[1, 5] = vt, -sp * vb
        jac[2, 5] = -(cp * vt - sp * vn)
        return
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    m, k, r = np.empty(6), np.empty(6), np.empty(6)
    for i in range(6):
        m[i] = cm * x[i] + am * y[i]
        k[i] = ck * x[i] + ak * y[i]
        r[i] = cm * ((x[i] - y[i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[i]) + am * d[i]
    cp, sp = np.cos(m[4]), np.sin(m[4])
    acc = np.empty(3)                                   # acceleration in (t, n, b)
    acc[0] = r[1] - m[2] * r[4] + m[3] * cp * r[5]
    acc[1] = r[2] + m[1] * r[4] - m[3] * sp * r[5]
    acc[2] = r[3] + (-m[1] * cp + m[2] * sp) * r[5]
    dacc_m, dacc_r = np.zeros((3, 6)), np.zeros((3, 6))
    dacc_r[0, 1], dacc_r[0, 4], dacc_r[0, 5] = 1.0, -m[2], m[3] * cp
    dacc_m[0, 2], dacc_m[0, 3], dacc_m[0, 4] = -r[4], cp * r[5], -m[3] * sp * r[5]
    dacc_r[1, 2], dacc_r[1, 4], dacc_r[1, 5] = 1.0, m[1], -m[3] * sp
    dacc_m[1, 1], dacc_m[1, 3], dacc_m[1, 4] = r[4], -sp * r[5], -m[3] * cp * r[5]
    dacc_r[2, 3], dacc_r[2, 5] = 1.0, -m[1] * cp + m[2] * sp
    dacc_m[2, 1], dacc_m[2, 2], dacc_m[2, 4] = -cp * r[5], sp * r[5], (m[1] * sp + m[2] * cp) * r[5]
    force, dforce = np.empty(3), np.zeros((3, 6))     # external force on the node in (t, n, b), d/dk
    if kind == FREE:
        mass = p[INERTIA] * (p[M] + p[MA])
        f0, f1, f2 = node_load3_jacobian(k, cur, up, p, dforce)
        force[0], force[1], force[2] = f0, f1, f2
    else:
        mass = p[INERTIA] * b[4]
        _body_force3(k, cur, up, b, side, force, dforce)
    first = 1 if kind == FREE else 0
    if kind == FREE:
        out[0] = x[0] / p[EA]
        jac[0, 0] = 1.0 / p[EA]
    for i in range(first, 3):
        out[i] = mass * acc[i] - force[i]
        for q in range(6):
            jac[i, q] = mass * (dacc_m[i, q] * cm + dacc_r[i, q] * cr) - dforce[i, q] * ck


@inner
def _body_force3(k, cur, up, b, side, force, dforce):
    """Force on an end body in (t, n, b) at the weighted state ``k`` and its derivative by ``k``:
    the cable's tension ``-side T t``, drag of the relative water, buoyancy and constant force."""
    cp, sp, ct, st = np.cos(k[4]), np.sin(k[4]), np.cos(k[5]), np.sin(k[5])
    e = np.empty((3, 3))                                # rows t, n, b in chart coordinates
    e[0, 0], e[0, 1], e[0, 2] = cp * ct, cp * st, sp
    e[1, 0], e[1, 1], e[1, 2] = -sp * ct, -sp * st, cp
    e[2, 0], e[2, 1], e[2, 2] = st, -ct, 0.0
    rel, lift = np.empty(3), np.empty(3)
    for i in range(3):
        rel[i] = cur[0] * e[i, 0] + cur[1] * e[i, 1] + cur[2] * e[i, 2] - k[1 + i]
        lift[i] = (b[5] * up[0] + b[7]) * e[i, 0] + (b[5] * up[1] + b[8]) * e[i, 1] + (b[5] * up[2] + b[9]) * e[i, 2]
    speed = np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    # d(component along t, n, b)/d(phi), d/d(theta) of a fixed chart vector with components a = (a_t, a_n, a_b)
    drel = np.zeros((3, 6))
    for i in range(3):
        drel[i, 1 + i] = -1.0
    cw = np.empty(3)
    for i in range(3):
        cw[i] = rel[i] + k[1 + i]                      # the current's components
    drel[0, 4], drel[0, 5] = cw[1], -cp * cw[2]
    drel[1, 4], drel[1, 5] = -cw[0], sp * cw[2]
    drel[2, 5] = cp * cw[0] - sp * cw[1]
    for i in range(3):
        force[i] = b[6] * speed * rel[i] + lift[i]
        for q in range(6):
            acc = 0.0
            for j in range(3):
                g = b[6] * ((speed if i == j else 0.0) + (rel[i] * rel[j] / speed if speed > 0.0 else 0.0))
                acc += g * drel[j, q]
            dforce[i, q] = acc
    force[0] -= side * k[0]
    dforce[0, 0] = -side
    dforce[0, 4] += lift[1]
    dforce[0, 5] -= cp * lift[2]
    dforce[1, 4] -= lift[0]
    dforce[1, 5] += sp * lift[2]
    dforce[2, 5] += cp * lift[0] - sp * lift[1]


@inner
def _end_rows3(x, y, d, cur, up, p, b0, b1, res, band):
    """The three rows of each end and their derivatives (:func:`end_jacobian3`) into ``res``, ``band``."""
    out, jac = np.empty(3), np.empty((3, 6))
    last = x.shape[0] - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, 6 * last + 3)
        end_jacobian3(x[node], y[node], d[node], cur[node], up, p, b0 if end == 0 else b1, side, out, jac)
        for i in range(3):
            res[row + i] = out[i]
            for q in range(6):
                band[UPPER + row + i - (6 * node + q), 6 * node + q] = jac[i, q]


@kernel
def _end_rows3_complex_step(x, y, d, cur, up, p, b, side, row, col0, res, band):
    """One end's rows by complex step (the tests' oracle)."""
    out = np.empty(3)
    zout = np.empty(3, dtype=np.complex128)
    z = np.empty(6, dtype=np.complex128)
    end_residual3(x, y, d, cur, up, p, b, side, out)
    res[row:row + 3] = out
    for k in range(6):
        z[:] = x
        z[k] += 1j * STEP
        end_residual3(z, y, d, cur, up, p, b, side, zout)
        for i in range(3):
            band[UPPER + row + i - (col0 + k), col0 + k] = zout[i].imag / STEP


@kernel
def interval_residual3(xl, xr, yl, yr, dl, dr, cl, cr, up, p, out):
    """The six rows of one interval, directly from the nodal M, K, F (complex-capable)."""
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    ml, mr = (1.0 - am) * xl + am * yl, (1.0 - am) * xr + am * yr
    kl, kr = (1.0 - ak) * xl + ak * yl, (1.0 - ak) * xr + ak * yr
    rl = (1.0 - am) * ((xl - yl) / (gamma * dt) - (1.0 - gamma) / gamma * dl) + am * dl
    rr = (1.0 - am) * ((xr - yr) / (gamma * dt) - (1.0 - gamma) / gamma * dr) + am * dr
    rate = 0.5 * (rl + rr)
    grad = (kr - kl) / p[DS]
    a, b2, c2, e = np.empty(6, dtype=out.dtype), np.empty(6, dtype=out.dtype), np.empty(6, dtype=out.dtype), \
        np.empty(6, dtype=out.dtype)
    mass_times(ml, rate, p, a)
    mass_times(mr, rate, p, b2)
    stiffness_times(kl, grad, c2)
    stiffness_times(kr, grad, e)
    fl = node_load3(kl[0], kl[1], kl[2], kl[3], kl[4], kl[5], cl, up, p)
    fr = node_load3(kr[0], kr[1], kr[2], kr[3], kr[4], kr[5], cr, up, p)
    for i in range(6):
        out[i] = p[INERTIA] * 0.5 * (a[i] + b2[i]) + 0.5 * (c2[i] + e[i])
    for i in range(3):
        out[i] -= 0.5 * (fl[i] + fr[i])


@kernel
def jacobian_complex_step3(x, y, d, cur, up, p, b0, b1, res, band):
    """The residual and Jacobian of :func:`assemble3`, every entry by complex step (test oracle)."""
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    out = np.empty(6)
    zout = np.empty(6, dtype=np.complex128)
    zl = np.empty(6, dtype=np.complex128)
    zr = np.empty(6, dtype=np.complex128)
    for j in range(1, n_nodes):
        row = 3 + 6 * (j - 1)
        interval_residual3(x[j - 1], x[j], y[j - 1], y[j], d[j - 1], d[j], cur[j - 1], cur[j], up, p, out)
        res[row:row + 6] = out
        for side in range(2):
            for k in range(6):
                zl[:] = x[j - 1]
                zr[:] = x[j]
                if side == 0:
                    zl[k] += 1j * STEP
                else:
                    zr[k] += 1j * STEP
                interval_residual3(zl, zr, y[j - 1], y[j], d[j - 1], d[j], cur[j - 1], cur[j], up, p, zout)
                col = 6 * (j - 1 + side) + k
                for i in range(6):
                    band[UPPER + row + i - col, col] = zout[i].imag / STEP
    _end_rows3_complex_step(x[0], y[0], d[0], cur[0], up, p, b0, -1.0, 0, 0, res, band)
    _end_rows3_complex_step(x[-1], y[-1], d[-1], cur[-1], up, p, b1, 1.0, 6 * n_nodes - 3, 6 * (n_nodes - 1),
                            res, band)
