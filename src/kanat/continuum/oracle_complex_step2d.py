"""Complex-capable planar residuals and the all-complex-step Jacobian: the tests' oracle.

The same equations as :mod:`kanat.continuum.rows2d` and :func:`kanat.continuum.kernels2d.end_jacobian`,
written once more directly from the module docstrings (``|x| x`` as ``x sqrt(x x)``, branches on
real parts), so that complex-step differentiation gives every Jacobian entry exactly (error
~1e-16 relative). Compiled only by the tests; a run never imports this module.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import kernel

from kanat.continuum import kernels2d as k


@kernel
def end_residual(x, y, d, env, p, b, side, out):
    """The rows of one end (:mod:`kernels2d` docstring), complex-capable."""
    nv = x.shape[0]
    bend = nv == 6
    kind = int(b[k.B_KIND])
    if kind == k.VELOCITY:
        c, s = np.cos(x[3]), np.sin(x[3])
        out[0] = x[1] - (b[k.B_V0] * c + b[k.B_V1] * s) - b[k.B_PAYOUT]
        out[1] = x[2] - (-b[k.B_V0] * s + b[k.B_V1] * c)
        if bend:
            out[2] = x[3] - b[k.B_PHI0] if b[k.B_CLAMP] != 0.0 else x[5]
        return
    m, kk, r = k.weighted(x, y, d, p)
    if kind == k.FREE:
        if bend:
            out[0], out[1], out[2] = x[0] / p[k.EA], x[4] / p[k.EA], x[5] / p[k.EA]
            return
        ft, fn = k.node_load(kk[0], kk[1], kk[2], kk[3], env[k.UX], env[k.UZ], p)
        et, en = k.extra_load(kk[0], kk[1], kk[2], kk[3], env, p)
        out[0] = x[0] / p[k.EA]
        out[1] = p[k.INERTIA] * (p[k.M] + p[k.MA]) * (r[2] + m[1] * r[3]) - (fn + en)
        return
    c, s = np.cos(kk[3]), np.sin(kk[3])
    wt = env[k.UX] * c + env[k.UZ] * s - kk[1]
    wn = -env[k.UX] * s + env[k.UZ] * c - kk[2]
    at, an = env[k.AX] * c + env[k.AZ] * s, -env[k.AX] * s + env[k.AZ] * c
    speed = np.sqrt(wt * wt + wn * wn)
    z = env[k.RZ] + p[k.PRED] * (kk[1] * s + kk[2] * c)
    buoy = b[k.B_BUOY] + k.surface_buoyancy(z, b)[0]
    shear = kk[4] if bend else 0.0 * kk[0]
    mass = p[k.INERTIA] * b[k.B_MASS]
    drag = b[k.B_DRAG] * speed
    out[0] = mass * (r[1] - m[2] * r[3]) - (-side * kk[0] + buoy * s + drag * wt + b[k.B_F0] * c + b[k.B_F1] * s
                                          + b[k.B_WAVE] * at)
    out[1] = mass * (r[2] + m[1] * r[3]) - (-side * shear + buoy * c + drag * wn - b[k.B_F0] * s + b[k.B_F1] * c
                                          + b[k.B_WAVE] * an)
    if bend:
        out[2] = x[5]


@kernel
def interval_residual(xl, xr, yl, yr, dl, dr, el, er, p, out):
    """The rows of one cable interval (:mod:`rows2d` docstring), complex-capable."""
    nv = xl.shape[0]
    ml, kl, rl = k.weighted(xl, yl, dl, p)
    mr, kr, rr = k.weighted(xr, yr, dr, p)
    mb = 0.5 * (ml + mr)
    kb = 0.5 * (kl + kr)
    grad = (kr - kl) / p[k.DS]
    rate = 0.5 * (rl + rr) + 0.5 * p[k.CONV] * grad
    ftl, fnl = k.node_load(kl[0], kl[1], kl[2], kl[3], el[k.UX], el[k.UZ], p)
    ftr, fnr = k.node_load(kr[0], kr[1], kr[2], kr[3], er[k.UX], er[k.UZ], p)
    etl, enl = k.extra_load(kl[0], kl[1], kl[2], kl[3], el, p)
    etr, enr = k.extra_load(kr[0], kr[1], kr[2], kr[3], er, p)
    c = p[k.INERTIA]
    mass, normal_mass = p[k.M], p[k.M] + p[k.MA]
    out[0] = c * mass * (rate[1] - mb[2] * rate[3]) - grad[0] - 0.5 * (ftl + ftr + etl + etr)
    out[1] = (c * normal_mass * (rate[2] + mb[1] * rate[3]) - k.transverse_tension(kb[0], p)[0] * grad[3]
              - 0.5 * (fnl + fnr + enl + enr))
    out[2] = c * k.compliance(mb[0], p) * rate[0] - grad[1] + kb[2] * grad[3]
    out[3] = c * (1.0 + k.strain(mb[0], p)) * rate[3] - grad[2] - kb[1] * grad[3]
    if nv == 6:
        out[0] += kb[4] * grad[3]
        out[1] -= grad[4]
        out[4] = p[k.EI] * grad[3] - kb[5]
        out[5] = grad[5] + (1.0 + k.strain(kb[0], p)) * kb[4]


@kernel
def cap_share(z, eta, diameter):
    """Immersed volume share of a sphere centred at ``z``, complex-capable: the cap of height
    ``h = clip(eta - z + a, 0, 2a)`` holds ``pi h^2 (3a - h) / 3`` of ``4 pi a^3 / 3``."""
    a = 0.5 * diameter
    h = eta - z + a
    if h.real <= 0.0:
        return 0.0 * z
    if h.real >= diameter:
        return 1.0 + 0.0 * z
    return h * h * (3.0 * a - h) / (4.0 * a * a * a)


@kernel
def junction_residual(xa, xb, ya, yb, da, db, ea, p, out):
    """The rows of a junction interval (an inline body, :mod:`rows2d` docstring), complex-capable."""
    nv = xa.shape[0]
    ca, sa, cb, sb = np.cos(xa[3]), np.sin(xa[3]), np.cos(xb[3]), np.sin(xb[3])
    out[0] = (xa[1] * ca - xa[2] * sa) - (xb[1] * cb - xb[2] * sb)
    out[1] = (xa[1] * sa + xa[2] * ca) - (xb[1] * sb + xb[2] * cb)
    ma, ka, ra = k.weighted(xa, ya, da, p)
    mb, kb, rb = k.weighted(xb, yb, db, p)
    cm, sm = np.cos(ma[3]), np.sin(ma[3])
    at, an = ra[1] - ma[2] * ra[3], ra[2] + ma[1] * ra[3]
    acc_x, acc_z = at * cm - an * sm, at * sm + an * cm
    sa_, sb_ = 0.0 * ka[0], 0.0 * kb[0]
    if nv == 6:
        sa_, sb_ = ka[4], kb[4]
    cka, ska, ckb, skb = np.cos(ka[3]), np.sin(ka[3]), np.cos(kb[3]), np.sin(kb[3])
    wx = ea[k.UX] - (ka[1] * cka - ka[2] * ska)
    wz = ea[k.UZ] - (ka[1] * ska + ka[2] * cka)
    drag = p[k.JB_DRAG] * np.sqrt(wx * wx + wz * wz)
    fx = (kb[0] * ckb - sb_ * skb) - (ka[0] * cka - sa_ * ska) + drag * wx + p[k.JB_F0] + p[k.JB_WAVE] * ea[k.AX]
    fz = (kb[0] * skb + sb_ * ckb) - (ka[0] * ska + sa_ * cka) + drag * wz + p[k.JB_F2] + p[k.JB_BUOY] \
        + p[k.JB_WAVE] * ea[k.AZ]
    if p[k.JB_DIAMETER] > 0.0:
        z = ea[k.RZ] + p[k.PRED] * (ka[1] * ska + ka[2] * cka)
        dry = 1.0 - cap_share(z, p[k.JB_ETA], p[k.JB_DIAMETER])
        fx = fx - dry * p[k.JB_WAVE] * ea[k.AX]
        fz = fz - dry * (p[k.JB_FULL] + p[k.JB_WAVE] * ea[k.AZ])
    mass = p[k.INERTIA] * p[k.JB_MASS]
    out[2] = mass * acc_x - fx
    out[3] = mass * acc_z - fz
    if nv == 6:
        out[4] = xa[5]
        out[5] = xb[5]


@kernel
def jacobian_complex_step(x, y, d, env, P, b0, b1, res, band):
    """The residual and Jacobian of :func:`kernels2d.assemble`, every entry by complex step."""
    n_nodes, nv = x.shape[0], x.shape[1]
    half = nv // 2
    width = (band.shape[0] - 1) // 2
    band[:, :] = 0.0
    out = np.empty(nv)
    zout = np.empty(nv, dtype=np.complex128)
    zl = np.empty(nv, dtype=np.complex128)
    zr = np.empty(nv, dtype=np.complex128)
    for j in range(n_nodes - 1):
        row = half + nv * j
        junction = P[j, k.KIND] == k.JUNCTION
        if junction:
            junction_residual(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], P[j], out)
        else:
            interval_residual(x[j], x[j + 1], y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], P[j], out)
        for i in range(nv):
            res[row + i] = out[i]
        for side in range(2):
            for q in range(nv):
                for i in range(nv):
                    zl[i] = x[j, i]
                    zr[i] = x[j + 1, i]
                if side == 0:
                    zl[q] += 1j * k.STEP
                else:
                    zr[q] += 1j * k.STEP
                if junction:
                    junction_residual(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], P[j], zout)
                else:
                    interval_residual(zl, zr, y[j], y[j + 1], d[j], d[j + 1], env[j], env[j + 1], P[j], zout)
                col = nv * (j + side) + q
                for i in range(nv):
                    band[width + row + i - col, col] = zout[i].imag / k.STEP
    last = n_nodes - 1
    _end_complex_step(x[0], y[0], d[0], env[0], P[0], b0, -1.0, 0, 0, width, res, band)
    _end_complex_step(x[last], y[last], d[last], env[last], P[last - 1], b1, 1.0, nv * last + half, nv * last,
                      width, res, band)


@kernel
def _end_complex_step(x, y, d, env, p, b, side, row, col0, width, res, band):
    nv = x.shape[0]
    half = nv // 2
    out = np.empty(half)
    zout = np.empty(half, dtype=np.complex128)
    z = np.empty(nv, dtype=np.complex128)
    end_residual(x, y, d, env, p, b, side, out)
    for i in range(half):
        res[row + i] = out[i]
    for q in range(nv):
        for i in range(nv):
            z[i] = x[i]
        z[q] += 1j * k.STEP
        end_residual(z, y, d, env, p, b, side, zout)
        for i in range(half):
            band[width + row + i - (col0 + q), col0 + q] = zout[i].imag / k.STEP
