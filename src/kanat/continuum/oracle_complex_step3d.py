"""Complex-capable spatial residuals and the all-complex-step Jacobian: the tests' oracle.

The equations of :mod:`kanat.continuum.rows3d` and :func:`kanat.continuum.kernels3d.end_jacobian3`
written again directly from the docstrings, complex-capable, so complex-step differentiation gives
every Jacobian entry exactly. Compiled only by the tests.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import kernel

from kanat.continuum import kernels2d as k
from kanat.continuum import kernels3d as k3
from kanat.continuum.oracle_complex_step2d import cap_share


@kernel
def _acceleration(m, r):
    """Chart components of ``dV/dt`` from the ``[am]`` state ``m`` and rate ``r``."""
    t, n, b = k3.frame(m[4], m[5])
    cp, sp = np.cos(m[4]), np.sin(m[4])
    at = r[1] - m[2] * r[4] + m[3] * cp * r[5]
    an = r[2] + m[1] * r[4] - m[3] * sp * r[5]
    ab = r[3] + (-m[1] * cp + m[2] * sp) * r[5]
    return at * t[0] + an * n[0] + ab * b[0], at * t[1] + an * n[1] + ab * b[1], at * t[2] + an * n[2] + ab * b[2]


@kernel
def _velocity(y):
    t, n, b = k3.frame(y[4], y[5])
    return (y[1] * t[0] + y[2] * n[0] + y[3] * b[0], y[1] * t[1] + y[2] * n[1] + y[3] * b[1],
            y[1] * t[2] + y[2] * n[2] + y[3] * b[2])


@kernel
def end_residual3(x, y, d, env, up, p, b, side, out):
    """The three conditions of one end, complex-capable."""
    kind = int(b[k3.B3_KIND])
    if kind == k.VELOCITY:
        t, n, bb = k3.frame(x[4], x[5])
        out[0] = x[1] - (b[1] * t[0] + b[2] * t[1] + b[3] * t[2]) - b[k3.B3_PAYOUT]
        out[1] = x[2] - (b[1] * n[0] + b[2] * n[1] + b[3] * n[2])
        out[2] = x[3] - (b[1] * bb[0] + b[2] * bb[1] + b[3] * bb[2])
        return
    m, kk, r = k.weighted(x, y, d, p)
    cp, sp = np.cos(m[4]), np.sin(m[4])
    a = (r[1] - m[2] * r[4] + m[3] * cp * r[5], r[2] + m[1] * r[4] - m[3] * sp * r[5],
         r[3] + (-m[1] * cp + m[2] * sp) * r[5])        # along t, n, b
    t, n, bb = k3.frame(kk[4], kk[5])
    if kind == k.FREE:
        f = k3.node_load3(kk[0], kk[1], kk[2], kk[3], kk[4], kk[5], env[0:3], up, p)
        e = k3.extra_load3(kk[0], kk[1], kk[2], kk[3], kk[4], kk[5], env, p)
        mn = p[k.INERTIA] * (p[k.M] + p[k.MA])
        out[0] = x[0] / p[k.EA]
        out[1] = mn * a[1] - (f[1] + e[1])
        out[2] = mn * a[2] - (f[2] + e[2])
        return
    vel = _velocity(kk)
    z = 0.0 * kk[0]
    for j in range(3):
        z += up[j] * (env[k3.RX3 + j] + p[k.PRED] * vel[j])
    buoy = b[k3.B3_BUOY] + k3.surface_buoyancy3(z, b)[0]
    rel = (env[0] - vel[0], env[1] - vel[1], env[2] - vel[2])
    drag = b[k3.B3_DRAG] * np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    mass = p[k.INERTIA] * b[k3.B3_MASS]
    for i in range(3):
        e = t if i == 0 else (n if i == 1 else bb)
        total = 0.0 * kk[0]
        for j in range(3):
            total += (buoy * up[j] + b[k3.B3_F0 + j] + b[k3.B3_WAVE] * env[k3.AX3 + j] + drag * rel[j]) * e[j]
        tension = -side * kk[0] if i == 0 else 0.0 * kk[0]
        out[i] = mass * a[i] - (tension + total)


@kernel
def interval_residual3(xl, xr, yl, yr, dl, dr, el, er, up, p, out):
    """The six rows of one cable interval, directly from the nodal M, K, F (complex-capable)."""
    ml, kl, rl = k.weighted(xl, yl, dl, p)
    mr, kr, rr = k.weighted(xr, yr, dr, p)
    grad = (kr - kl) / p[k.DS]
    rate = 0.5 * (rl + rr) + 0.5 * p[k.CONV] * grad
    a, b2, c2, e = (np.empty(6, dtype=out.dtype), np.empty(6, dtype=out.dtype), np.empty(6, dtype=out.dtype),
                    np.empty(6, dtype=out.dtype))
    k3.mass_times(ml, rate, p, a)
    k3.mass_times(mr, rate, p, b2)
    k3.stiffness_times(kl, grad, c2)
    k3.stiffness_times(kr, grad, e)
    fl = k3.node_load3(kl[0], kl[1], kl[2], kl[3], kl[4], kl[5], el[0:3], up, p)
    fr = k3.node_load3(kr[0], kr[1], kr[2], kr[3], kr[4], kr[5], er[0:3], up, p)
    gl = k3.extra_load3(kl[0], kl[1], kl[2], kl[3], kl[4], kl[5], el, p)
    gr = k3.extra_load3(kr[0], kr[1], kr[2], kr[3], kr[4], kr[5], er, p)
    for i in range(6):
        out[i] = p[k.INERTIA] * 0.5 * (a[i] + b2[i]) + 0.5 * (c2[i] + e[i])
    for i in range(3):
        out[i] -= 0.5 * (fl[i] + fr[i] + gl[i] + gr[i])


@kernel
def junction_residual3(xa, xb, ya, yb, da, db, ea, up, p, out):
    """The six rows of a junction interval (an inline body), complex-capable."""
    va, vb = _velocity(xa), _velocity(xb)
    for i in range(3):
        out[i] = va[i] - vb[i]
    ma, ka, ra = k.weighted(xa, ya, da, p)
    mb, kb, rb = k.weighted(xb, yb, db, p)
    acc = _acceleration(ma, ra)
    ta = k3.frame(ka[4], ka[5])[0]
    tb = k3.frame(kb[4], kb[5])[0]
    vel = _velocity(ka)
    rel = (ea[0] - vel[0], ea[1] - vel[1], ea[2] - vel[2])
    drag = p[k.JB_DRAG] * np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    mass = p[k.INERTIA] * p[k.JB_MASS]
    buoy, wave = p[k.JB_BUOY] + 0.0 * vel[0], p[k.JB_WAVE] + 0.0 * vel[0]
    if p[k.JB_DIAMETER] > 0.0:
        z = 0.0 * vel[0]
        for i in range(3):
            z = z + up[i] * (ea[k3.RX3 + i] + p[k.PRED] * vel[i])
        wet = cap_share(z, p[k.JB_ETA], p[k.JB_DIAMETER])
        buoy = buoy - (1.0 - wet) * p[k.JB_FULL]
        wave = wave * wet
    for i in range(3):
        force = (kb[0] * tb[i] - ka[0] * ta[i] + buoy * up[i] + p[k.JB_F0 + i] + wave * ea[k3.AX3 + i]
                 + drag * rel[i])
        out[3 + i] = mass * acc[i] - force


@kernel
def jacobian_complex_step3(x, y, d, env, up, P, b0, b1, res, band):
    """The residual and Jacobian of :func:`rows3d.assemble3`, every entry by complex step (test oracle)."""
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    out = np.empty(6)
    zout = np.empty(6, dtype=np.complex128)
    zl = np.empty(6, dtype=np.complex128)
    zr = np.empty(6, dtype=np.complex128)
    for j in range(n_nodes - 1):
        row = 3 + 6 * j
        junction = P[j, k.KIND] == k.JUNCTION
        if junction:
            junction_residual3(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], up, P[j], out)
        else:
            interval_residual3(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], up, P[j], out)
        res[row:row + 6] = out
        for side in range(2):
            for q in range(6):
                zl[:] = x[j]
                zr[:] = x[j + 1]
                if side == 0:
                    zl[q] += 1j * k.STEP
                else:
                    zr[q] += 1j * k.STEP
                if junction:
                    junction_residual3(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], up, P[j], zout)
                else:
                    interval_residual3(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], up, P[j], zout)
                col = 6 * (j + side) + q
                for i in range(6):
                    band[k3.UPPER + row + i - col, col] = zout[i].imag / k.STEP
    last = n_nodes - 1
    _end_complex_step3(x[0], y[0], d[0], env[0], up, P[0], b0, -1.0, 0, 0, res, band)
    _end_complex_step3(x[last], y[last], d[last], env[last], up, P[last - 1], b1, 1.0, 6 * last + 3, 6 * last,
                       res, band)


@kernel
def _end_complex_step3(x, y, d, env, up, p, b, side, row, col0, res, band):
    out = np.empty(3)
    zout = np.empty(3, dtype=np.complex128)
    z = np.empty(6, dtype=np.complex128)
    end_residual3(x, y, d, env, up, p, b, side, out)
    res[row:row + 3] = out
    for q in range(6):
        z[:] = x
        z[q] += 1j * k.STEP
        end_residual3(z, y, d, env, up, p, b, side, zout)
        for i in range(3):
            band[k3.UPPER + row + i - (col0 + q), col0 + q] = zout[i].imag / k.STEP


# --- bending stiffness (:mod:`kanat.continuum.bending3d`): ten unknowns per node --------------------

@kernel
def _shear(y):
    """``S = S_n n + S_b b`` in chart components (complex-capable)."""
    t, n, b = k3.frame(y[4], y[5])
    return (y[6] * n[0] + y[7] * b[0], y[6] * n[1] + y[7] * b[1], y[6] * n[2] + y[7] * b[2])


@kernel
def interval_residual3_bending(xl, xr, yl, yr, dl, dr, el, er, up, p, out):
    """The ten rows of a cable interval with bending stiffness (bending3d docstring), complex-capable:
    the flexible rows of the first six unknowns, then the rod's terms at the interval's midpoint."""
    interval_residual3(xl[:6], xr[:6], yl[:6], yr[:6], dl[:6], dr[:6], el, er, up, p, out[:6])
    kl = k.weighted(xl, yl, dl, p)[1]
    kr = k.weighted(xr, yr, dr, p)[1]
    kb = 0.5 * (kl + kr)
    g = (kr - kl) / p[k.DS]
    c, s = np.cos(kb[4]), np.sin(kb[4])
    stretch = 1.0 + k.strain(kb[0], p)
    sn, sb, mn, mb = kb[6], kb[7], kb[8], kb[9]
    out[0] += sn * g[4] - sb * c * g[5]
    out[1] += -g[6] + sb * s * g[5]
    out[2] += -g[7] - sn * s * g[5]
    out[6] = p[k.EI] * c * g[5] - mn
    out[7] = p[k.EI] * g[4] - mb
    out[8] = g[8] - mb * s * g[5] - stretch * sb
    out[9] = g[9] + mn * s * g[5] + stretch * sn


@kernel
def junction_residual3_bending(xa, xb, ya, yb, da, db, ea, up, p, out):
    """An inline body's ten rows with bending: the shear of both sides on it, ``M = 0`` at both nodes."""
    junction_residual3(xa[:6], xb[:6], ya[:6], yb[:6], da[:6], db[:6], ea, up, p, out[:6])
    ka = k.weighted(xa, ya, da, p)[1]
    kb = k.weighted(xb, yb, db, p)[1]
    sa, sb = _shear(ka), _shear(kb)
    for i in range(3):
        out[3 + i] -= sb[i] - sa[i]
    out[6], out[7], out[8], out[9] = xa[8], xa[9], xb[8], xb[9]


@kernel
def end_residual3_bending(x, y, d, env, up, p, b, side, out):
    """The five rows of one end with bending stiffness, complex-capable."""
    kind = int(b[k3.B3_KIND])
    if kind == k.FREE:
        out[0], out[1], out[2], out[3], out[4] = x[0] / p[k.EA], x[6] / p[k.EA], x[7] / p[k.EA], \
            x[8] / p[k.EA], x[9] / p[k.EA]
        return
    end_residual3(x[:6], y[:6], d[:6], env, up, p, b, side, out[:3])
    if kind != k.VELOCITY:
        kk = k.weighted(x, y, d, p)[1]
        out[1] += side * kk[6]
        out[2] += side * kk[7]
    if kind == k.VELOCITY and b[k3.NBPAR3] != 0.0:
        out[3], out[4] = x[4] - b[k3.NBPAR3 + 1], x[5] - b[k3.NBPAR3 + 2]
    else:
        out[3], out[4] = x[8], x[9]


@kernel
def jacobian_complex_step3_bending(x, y, d, env, up, P, b0, b1, res, band):
    """The residual and Jacobian of :func:`bending3d.assemble3_bending`, every entry by complex step."""
    n_nodes, nv = x.shape[0], 10
    width = (band.shape[0] - 1) // 2
    band[:, :] = 0.0
    out = np.empty(nv)
    zout = np.empty(nv, dtype=np.complex128)
    zl = np.empty(nv, dtype=np.complex128)
    zr = np.empty(nv, dtype=np.complex128)
    for j in range(n_nodes - 1):
        row = 5 + nv * j
        junction = P[j, k.KIND] == k.JUNCTION
        if junction:
            junction_residual3_bending(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], up, P[j], out)
        else:
            interval_residual3_bending(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], up,
                                       P[j], out)
        res[row:row + nv] = out
        for side in range(2):
            for q in range(nv):
                zl[:] = x[j]
                zr[:] = x[j + 1]
                if side == 0:
                    zl[q] += 1j * k.STEP
                else:
                    zr[q] += 1j * k.STEP
                if junction:
                    junction_residual3_bending(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], up, P[j], zout)
                else:
                    interval_residual3_bending(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], up,
                                               P[j], zout)
                col = nv * (j + side) + q
                for i in range(nv):
                    band[width + row + i - col, col] = zout[i].imag / k.STEP
    last = n_nodes - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, nv * last + 5)
        p, b = (P[0], b0) if end == 0 else (P[last - 1], b1)
        o = np.empty(5)
        zo = np.empty(5, dtype=np.complex128)
        z = np.empty(nv, dtype=np.complex128)
        end_residual3_bending(x[node], y[node], d[node], env[node], up, p, b, side, o)
        res[row:row + 5] = o
        for q in range(nv):
            z[:] = x[node]
            z[q] += 1j * k.STEP
            end_residual3_bending(z, y[node], d[node], env[node], up, p, b, side, zo)
            for i in range(5):
                band[width + row + i - (nv * node + q), nv * node + q] = zo[i].imag / k.STEP
