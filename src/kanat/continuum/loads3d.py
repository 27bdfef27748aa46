"""The spatial continuum kernels' frame, matrices, nodal loads and end rows (:mod:`kanat.continuum.kernels3d`
describes them); :mod:`kanat.continuum.rows3d` assembles the interval rows and the Newton system from them.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.continuum.loads2d import (AK, AM, CN, CONTACT_RAMP, CT, DIAM, DS, DT, EA, FREE, FRICTION_SPEED,  # noqa: F401
                                       GAMMA, GRAV,
                                       INERTIA, MA, PRED, RHO, SB_C, SB_C0, SB_K, SB_MUA, SB_MUL, SB_N0, SB_N1,
                                       SB_N2, SB_ON, STEP, VELOCITY, W0, M, _law_segment, compliance, smooth_sign,
                                       strain)

from kanat.continuum.layout3d import *  # noqa: F403  the kernels read the layout as globals


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


@inner
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




@kernel
def seabed_force3(vel, rp, axis, p):
    """Seabed force per unstretched length (3, chart) on a node at ``rp + PRED vel`` moving at ``vel``,
    friction along ``axis`` (unit, in the seabed plane) and across it (module docstring; complex-capable)."""
    n0, n1, n2 = p[SB_N0], p[SB_N1], p[SB_N2]
    zero = 0.0 * vel[0]
    out = (zero, zero, zero)
    depth = p[SB_C0] - (n0 * (rp[0] + p[PRED] * vel[0]) + n1 * (rp[1] + p[PRED] * vel[1])
                        + n2 * (rp[2] + p[PRED] * vel[2]))
    if depth.real < 0.0:
        return out
    ramp = depth / CONTACT_RAMP if depth.real < CONTACT_RAMP else 1.0 + 0.0 * depth
    normal = p[DIAM] * (p[SB_K] * depth - p[SB_C] * ramp * (n0 * vel[0] + n1 * vel[1] + n2 * vel[2]))
    if normal.real < 0.0:
        return out
    a0, a1, a2 = axis[0], axis[1], axis[2]
    l0, l1, l2 = n1 * a2 - n2 * a1, n2 * a0 - n0 * a2, n0 * a1 - n1 * a0
    fa = -p[SB_MUA] * normal * smooth_sign((a0 * vel[0] + a1 * vel[1] + a2 * vel[2]) / FRICTION_SPEED)
    fl = -p[SB_MUL] * normal * smooth_sign((l0 * vel[0] + l1 * vel[1] + l2 * vel[2]) / FRICTION_SPEED)
    return (normal * n0 + fa * a0 + fl * l0, normal * n1 + fa * a1 + fl * l1, normal * n2 + fa * a2 + fl * l2)


@inner
def seabed_force3_jacobian(vel, rp, axis, p, force, g):
    """:func:`seabed_force3` (real) into ``force`` (3,) and ``g[i, j] = dF_i / dV_j`` (3, 3)."""
    for i in range(3):
        force[i] = 0.0
        for j in range(3):
            g[i, j] = 0.0
    n = np.empty(3)
    n[0], n[1], n[2] = p[SB_N0], p[SB_N1], p[SB_N2]
    depth, rate = p[SB_C0], 0.0
    for i in range(3):
        depth -= n[i] * (rp[i] + p[PRED] * vel[i])
        rate += n[i] * vel[i]
    if depth < 0.0:
        return
    ramp, slope = (depth / CONTACT_RAMP, 1.0 / CONTACT_RAMP) if depth < CONTACT_RAMP else (1.0, 0.0)
    normal = p[DIAM] * (p[SB_K] * depth - p[SB_C] * ramp * rate)
    if normal < 0.0:
        return
    stiff = -p[DIAM] * ((p[SB_K] - p[SB_C] * slope * rate) * p[PRED] + p[SB_C] * ramp)   # dN/dV = stiff n
    lat = np.empty(3)
    lat[0], lat[1], lat[2] = n[1] * axis[2] - n[2] * axis[1], n[2] * axis[0] - n[0] * axis[2], \
        n[0] * axis[1] - n[1] * axis[0]
    for i in range(3):
        force[i] = normal * n[i]
        for j in range(3):
            g[i, j] = n[i] * stiff * n[j]
    for which in range(2):
        mu = p[SB_MUA] if which == 0 else p[SB_MUL]
        if mu == 0.0:
            continue
        slide = 0.0
        for i in range(3):
            slide += (axis[i] if which == 0 else lat[i]) * vel[i]
        th = np.tanh(slide / FRICTION_SPEED)
        sech2 = 1.0 - th * th
        for i in range(3):
            di = axis[i] if which == 0 else lat[i]
            force[i] -= mu * normal * th * di
            for j in range(3):
                dj = axis[j] if which == 0 else lat[j]
                g[i, j] -= mu * di * (th * stiff * n[j] + normal * sech2 / FRICTION_SPEED * dj)


@kernel
def extra_load3(T, u, v, w, phi, theta, env, p):
    """``(f_t, f_n, f_b)`` of wave inertia and seabed contact (module docstring; complex-capable)."""
    t, n, b = frame(phi, theta)
    disp = p[M] - p[W0] / p[GRAV]
    a0, a1, a2 = env[AX3], env[AX3 + 1], env[AX3 + 2]
    ft = disp * (a0 * t[0] + a1 * t[1] + a2 * t[2])
    fn = (disp + p[MA]) * (a0 * n[0] + a1 * n[1] + a2 * n[2])
    fb = (disp + p[MA]) * (a0 * b[0] + a1 * b[1] + a2 * b[2])
    if p[SB_ON] != 0.0:
        vel = (u * t[0] + v * n[0] + w * b[0], u * t[1] + v * n[1] + w * b[1], u * t[2] + v * n[2] + w * b[2])
        f = seabed_force3(vel, env[RX3:RX3 + 3], env[DX3:DX3 + 3], p)
        ft = ft + f[0] * t[0] + f[1] * t[1] + f[2] * t[2]
        fn = fn + f[0] * n[0] + f[1] * n[1] + f[2] * n[2]
        fb = fb + f[0] * b[0] + f[1] * b[1] + f[2] * b[2]
    return ft, fn, fb


@inner
def _frame_rows(phi, theta, e):
    """Rows ``t, n, b`` of ``e`` (3, 3) in chart coordinates."""
    cp, sp, ct, st = np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta)
    e[0, 0], e[0, 1], e[0, 2] = cp * ct, cp * st, sp
    e[1, 0], e[1, 1], e[1, 2] = -sp * ct, -sp * st, cp
    e[2, 0], e[2, 1], e[2, 2] = st, -ct, 0.0


@inner
def _velocity_derivatives(y, e, dv):
    """``dv[q] = dV/dy_q`` (6, 3) of ``V = u t + v n + w b`` (rows of ``e``: t, n, b)."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    u, v, w = y[1], y[2], y[3]
    for j in range(3):
        dv[0, j] = 0.0
        dv[1, j] = e[0, j]
        dv[2, j] = e[1, j]
        dv[3, j] = e[2, j]
        dv[4, j] = u * e[1, j] - v * e[0, j]
        dv[5, j] = -u * cp * e[2, j] + v * sp * e[2, j] + w * (cp * e[0, j] - sp * e[1, j])


@inner
def _add_projection(force, dforce_dv, y, e, dv, jac):
    """``jac[i, q] += d(F . e_i)/dy_q`` for a chart force ``F(V)`` with ``dF/dV`` (frame module docstring)."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    comp = np.empty(3)
    for i in range(3):
        comp[i] = force[0] * e[i, 0] + force[1] * e[i, 1] + force[2] * e[i, 2]
    for q in range(6):
        for i in range(3):
            acc = 0.0
            for j in range(3):
                gd = dforce_dv[j, 0] * dv[q, 0] + dforce_dv[j, 1] * dv[q, 1] + dforce_dv[j, 2] * dv[q, 2]
                acc += e[i, j] * gd
            jac[i, q] += acc
    jac[0, 4] += comp[1]
    jac[0, 5] += -cp * comp[2]
    jac[1, 4] += -comp[0]
    jac[1, 5] += sp * comp[2]
    jac[2, 5] += cp * comp[0] - sp * comp[1]


@inner
def extra_load3_jacobian(y, env, p, jac):
    """:func:`extra_load3` (real) at ``y`` (6,) and ``jac[i, q] = d f_i / d y_q`` (3, 6)."""
    for i in range(3):
        for q in range(6):
            jac[i, q] = 0.0
    e = np.empty((3, 3))
    _frame_rows(y[4], y[5], e)
    cp, sp = np.cos(y[4]), np.sin(y[4])
    disp = p[M] - p[W0] / p[GRAV]
    comp = np.empty(3)                                 # the water acceleration along t, n, b
    for i in range(3):
        comp[i] = env[AX3] * e[i, 0] + env[AX3 + 1] * e[i, 1] + env[AX3 + 2] * e[i, 2]
    c0, c1 = disp, disp + p[MA]
    f0, f1, f2 = c0 * comp[0], c1 * comp[1], c1 * comp[2]
    jac[0, 4], jac[0, 5] = c0 * comp[1], -c0 * cp * comp[2]
    jac[1, 4], jac[1, 5] = -c1 * comp[0], c1 * sp * comp[2]
    jac[2, 5] = c1 * (cp * comp[0] - sp * comp[1])
    if p[SB_ON] != 0.0:
        vel, force, g, dv = np.empty(3), np.empty(3), np.empty((3, 3)), np.empty((6, 3))
        for j in range(3):
            vel[j] = y[1] * e[0, j] + y[2] * e[1, j] + y[3] * e[2, j]
        seabed_force3_jacobian(vel, env[RX3:RX3 + 3], env[DX3:DX3 + 3], p, force, g)
        _velocity_derivatives(y, e, dv)
        _add_projection(force, g, y, e, dv, jac)
        f0 += force[0] * e[0, 0] + force[1] * e[0, 1] + force[2] * e[0, 2]
        f1 += force[0] * e[1, 0] + force[1] * e[1, 1] + force[2] * e[1, 2]
        f2 += force[0] * e[2, 0] + force[1] * e[2, 1] + force[2] * e[2, 2]
    return f0, f1, f2


@inner
def surface_buoyancy3(z, b):
    """Buoyancy of a surface buoy's waterplane ``rho g A_w clip(eta - z, 0, h)`` and its derivative by ``z``."""
    immersion = b[B3_ETA] - z
    if b[B3_WPA] == 0.0 or immersion.real <= 0.0:
        return 0.0 * z, 0.0
    if immersion.real >= b[B3_HEIGHT]:
        return b[B3_WPA] * b[B3_HEIGHT] + 0.0 * z, 0.0
    return b[B3_WPA] * immersion, -b[B3_WPA]


@inner
def end_jacobian3(x, y, d, env, up, p, b, side, out, jac, extras):
    """The three rows of one end (theory/continuum.md §3; :mod:`kernels2d` docstring) into ``out`` (3,) and
    their derivatives by ``x`` into ``jac`` (3, 6), real.

    Weighted states as in :func:`kernels2d.end_jacobian`, frame derivatives as in
    :func:`node_load3_jacobian`, the body's drag ``b |w| w`` with derivative ``b (|w| I + w w^T / |w|)``.
    """
    for i in range(3):
        for q in range(6):
            jac[i, q] = 0.0
    kind = int(b[B3_KIND])
    if kind == VELOCITY:
        cp, sp, ct, st = np.cos(x[4]), np.sin(x[4]), np.cos(x[5]), np.sin(x[5])
        vt = b[1] * cp * ct + b[2] * cp * st + b[3] * sp
        vn = -b[1] * sp * ct - b[2] * sp * st + b[3] * cp
        vb = b[1] * st - b[2] * ct
        out[0], out[1], out[2] = x[1] - vt - b[B3_PAYOUT], x[2] - vn, x[3] - vb
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
        extra = np.zeros((3, 6))
        f0, f1, f2 = node_load3_jacobian(k, env[UX3:UX3 + 3], up, p, dforce)
        e0 = e1 = e2 = 0.0
        if extras is not None:
            e0, e1, e2 = extra_load3_jacobian(k, env, p, extra)
        force[0], force[1], force[2] = f0 + e0, f1 + e1, f2 + e2
        for i in range(3):
            for q in range(6):
                dforce[i, q] += extra[i, q]
    else:
        mass = p[INERTIA] * b[B3_MASS]
        _body_force3(k, env, up, p, b, side, force, dforce, extras)
    first = 1 if kind == FREE else 0
    if kind == FREE:
        out[0] = x[0] / p[EA]
        jac[0, 0] = 1.0 / p[EA]
    for i in range(first, 3):
        out[i] = mass * acc[i] - force[i]
        for q in range(6):
            jac[i, q] = mass * (dacc_m[i, q] * cm + dacc_r[i, q] * cr) - dforce[i, q] * ck


@inner
def _body_force3(k, env, up, p, b, side, force, dforce, extras):
    """Force on an end body in (t, n, b) at the weighted state ``k`` and its derivative by ``k``: the
    cable's tension ``-side T t``, drag of the relative water, buoyancy (a surface buoy's with its
    immersion), constant force and wave inertia."""
    cp, sp = np.cos(k[4]), np.sin(k[4])
    e = np.empty((3, 3))                                # rows t, n, b in chart coordinates
    _frame_rows(k[4], k[5], e)
    dv = np.empty((6, 3))
    _velocity_derivatives(k, e, dv)
    lift_z = dlift = 0.0
    if extras is not None:                     # None: a plain cable, no surface buoy (rows3d docstring)
        z = 0.0
        for j in range(3):
            z += up[j] * (env[RX3 + j] + p[PRED] * (k[1] * e[0, j] + k[2] * e[1, j] + k[3] * e[2, j]))
        lift_z, dlift = surface_buoyancy3(z, b)
    total = np.empty(3)                                 # buoyancy + force + wave inertia (chart)
    for j in range(3):
        total[j] = (b[B3_BUOY] + lift_z) * up[j] + b[B3_F0 + j] + b[B3_WAVE] * env[AX3 + j]
    rel, lift = np.empty(3), np.empty(3)
    for i in range(3):
        rel[i] = env[UX3] * e[i, 0] + env[UX3 + 1] * e[i, 1] + env[UX3 + 2] * e[i, 2] - k[1 + i]
        lift[i] = total[0] * e[i, 0] + total[1] * e[i, 1] + total[2] * e[i, 2]
    speed = np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    drel = np.zeros((3, 6))
    for i in range(3):
        drel[i, 1 + i] = -1.0
    cw = np.empty(3)
    for i in range(3):
        cw[i] = rel[i] + k[1 + i]                      # the water velocity's components
    drel[0, 4], drel[0, 5] = cw[1], -cp * cw[2]
    drel[1, 4], drel[1, 5] = -cw[0], sp * cw[2]
    drel[2, 5] = cp * cw[0] - sp * cw[1]
    hd = b[B3_DRAG]
    for i in range(3):
        force[i] = hd * speed * rel[i] + lift[i]
        up_i = up[0] * e[i, 0] + up[1] * e[i, 1] + up[2] * e[i, 2]
        for q in range(6):
            acc = 0.0
            for j in range(3):
                g = hd * ((speed if i == j else 0.0) + (rel[i] * rel[j] / speed if speed > 0.0 else 0.0))
                acc += g * drel[j, q]
            dz = p[PRED] * (up[0] * dv[q, 0] + up[1] * dv[q, 1] + up[2] * dv[q, 2])
            dforce[i, q] = acc + dlift * dz * up_i
    force[0] -= side * k[0]
    dforce[0, 0] = -side
    dforce[0, 4] += lift[1]
    dforce[0, 5] -= cp * lift[2]
    dforce[1, 4] -= lift[0]
    dforce[1, 5] += sp * lift[2]
    dforce[2, 5] += cp * lift[0] - sp * lift[1]

