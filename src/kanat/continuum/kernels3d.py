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
far end (3)]``, a band of 8 sub- and super-diagonals. Derivatives of ``M(m) r`` and
``K(k) g`` are written out; the nodal loads are differentiated by complex step.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from kanat.continuum.kernels2d import (AK, AM, CN, CT, DIAM, DS, DT, EA, FREE, GAMMA, INERTIA, MA, RHO,
                                       STEP, VELOCITY, W0, M, compliance, strain)

LOWER = UPPER = 8
# End parameters: [kind, Vt1, Vt2, Vp (velocity, chart), mass, net_buoyancy, half_rho_cds, F1, F2, Fp]
NBPAR3 = 10


@njit(cache=True)
def frame(phi, theta):
    """Chart components of ``(t, n, b)`` (each a 3-tuple) at angles ``phi, theta``."""
    cp, sp, ct, st = np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta)
    return (cp * ct, cp * st, sp), (-sp * ct, -sp * st, cp), (st, -ct, 0.0 * st)


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def stiffness_times(y, g, out):
    """``out = K(y) g``."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    out[0] = -g[0]
    out[1] = -y[0] * g[4]
    out[2] = y[0] * cp * g[5]
    out[3] = -g[1] + y[2] * g[4] - y[3] * cp * g[5]
    out[4] = -g[2] - y[1] * g[4] + y[3] * sp * g[5]
    out[5] = -g[3] + (y[1] * cp - y[2] * sp) * g[5]


@njit(cache=True)
def mass_matrix(y, p, out):
    """``out = M(y)`` (6, 6), the rows of :func:`mass_times` written out (one law lookup)."""
    m, mn = p[M], p[M] + p[MA]
    cp, sp = np.cos(y[4]), np.sin(y[4])
    stretch = 1.0 + strain(y[0], p)
    out[:, :] = 0.0
    out[0, 1], out[0, 4], out[0, 5] = m, -m * y[2], m * y[3] * cp
    out[1, 2], out[1, 4], out[1, 5] = mn, mn * y[1], -mn * y[3] * sp
    out[2, 3], out[2, 5] = mn, mn * (-y[1] * cp + y[2] * sp)
    out[3, 0] = compliance(y[0], p)
    out[4, 4] = stretch
    out[5, 5] = -stretch * cp


@njit(cache=True)
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


@njit(cache=True)
def d_mass_times(y, r, p, out):
    """``out[i, q] = d(M(y) r)_i / d y_q`` for fixed ``r``."""
    m, mn = p[M], p[M] + p[MA]
    cp, sp = np.cos(y[4]), np.sin(y[4])
    flex, stretch = compliance(y[0], p), 1.0 + strain(y[0], p)
    out[:, :] = 0.0
    out[0, 2], out[0, 3], out[0, 4] = -m * r[4], m * cp * r[5], -m * y[3] * sp * r[5]
    out[1, 1], out[1, 3], out[1, 4] = mn * r[4], -mn * sp * r[5], -mn * y[3] * cp * r[5]
    out[2, 1], out[2, 2], out[2, 4] = -mn * cp * r[5], mn * sp * r[5], mn * (y[1] * sp + y[2] * cp) * r[5]
    out[4, 0] = r[4] * flex
    out[5, 0], out[5, 4] = -cp * r[5] * flex, stretch * sp * r[5]


@njit(cache=True)
def d_stiffness_times(y, g, out):
    """``out[i, q] = d(K(y) g)_i / d y_q`` for fixed ``g``."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    out[:, :] = 0.0
    out[1, 0] = -g[4]
    out[2, 0], out[2, 4] = cp * g[5], -y[0] * sp * g[5]
    out[3, 2], out[3, 3], out[3, 4] = g[4], -cp * g[5], y[3] * sp * g[5]
    out[4, 1], out[4, 3], out[4, 4] = -g[4], sp * g[5], y[3] * cp * g[5]
    out[5, 1], out[5, 2], out[5, 4] = cp * g[5], -sp * g[5], (-y[1] * sp - y[2] * cp) * g[5]


@njit(cache=True)
def _node_loads(wk, cur, up, p):
    """Loads (n, 3) at the ``[ak]`` states and their derivatives (n, 3, 6) by complex step."""
    n_nodes = wk.shape[0]
    load = np.empty((n_nodes, 3))
    dload = np.empty((n_nodes, 3, 6))
    z = np.empty(6, dtype=np.complex128)
    for j in range(n_nodes):
        f = node_load3(wk[j, 0], wk[j, 1], wk[j, 2], wk[j, 3], wk[j, 4], wk[j, 5], cur[j], up, p)
        load[j, 0], load[j, 1], load[j, 2] = f[0], f[1], f[2]
        for i in range(6):
            for q in range(6):
                z[q] = wk[j, q]
            z[i] += 1j * STEP
            g = node_load3(z[0], z[1], z[2], z[3], z[4], z[5], cur[j], up, p)
            for row in range(3):
                dload[j, row, i] = g[row].imag / STEP
    return load, dload


@njit(cache=True)
def assemble3(x, y, d, cur, up, p, b0, b1, res, band):
    """Residual (6(N+1),) and banded Jacobian (17, 6(N+1)) of one step at unknowns ``x`` (N+1, 6).

    ``y, d``: old state and rate; ``cur`` (N+1, 3) current in chart coordinates; ``up`` (3,)
    the chart components of the vertical ``z``; ``b0, b1`` end conditions (NBPAR3).
    """
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    wm = (1.0 - am) * x + am * y
    wk = (1.0 - ak) * x + ak * y
    wr = (1.0 - am) * ((x - y) / (gamma * dt) - (1.0 - gamma) / gamma * d) + am * d
    load, dload = _node_loads(wk, cur, up, p)
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    c, ds = p[INERTIA], p[DS]
    ml, mr, kl, kr = np.empty((6, 6)), np.empty((6, 6)), np.empty((6, 6)), np.empty((6, 6))
    dm, dk = np.empty((6, 6)), np.empty((6, 6))
    rate, grad, out = np.empty(6), np.empty(6), np.empty(6)
    for j in range(1, n_nodes):
        l, r = j - 1, j
        rate[:] = 0.5 * (wr[l] + wr[r])
        grad[:] = (wk[r] - wk[l]) / ds
        mass_matrix(wm[l], p, ml)
        mass_matrix(wm[r], p, mr)
        stiffness_matrix(wk[l], kl)
        stiffness_matrix(wk[r], kr)
        row = 3 + 6 * (j - 1)
        out[:] = c * 0.5 * (ml + mr) @ rate + 0.5 * (kl + kr) @ grad
        out[0:3] -= 0.5 * (load[l] + load[r])
        res[row:row + 6] = out
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
    _end_rows3(x[0], y[0], d[0], cur[0], up, p, b0, -1.0, 0, 0, res, band)
    _end_rows3(x[-1], y[-1], d[-1], cur[-1], up, p, b1, 1.0, 6 * n_nodes - 3, 6 * (n_nodes - 1), res, band)


@njit(cache=True)
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


@njit(cache=True)
def _end_rows3(x, y, d, cur, up, p, b, side, row, col0, res, band):
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


@njit(cache=True)
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


@njit(cache=True)
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
    _end_rows3(x[0], y[0], d[0], cur[0], up, p, b0, -1.0, 0, 0, res, band)
    _end_rows3(x[-1], y[-1], d[-1], cur[-1], up, p, b1, 1.0, 6 * n_nodes - 3, 6 * (n_nodes - 1), res, band)
