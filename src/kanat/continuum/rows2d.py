"""The planar interval rows, inline bodies and the banded Newton system (theory/continuum.md §1, theory/time-schemes.md §1, theory/moorings.md).

Interval ``j`` (nodes ``j, j+1``) carries the box-method equations at its midpoint with its own
parameter row ``p = P[j]`` (:mod:`kanat.continuum.kernels2d` has the layout). ``M`` and ``K`` are
linear in ``Y``, so their two-node averages are ``M`` and ``K`` of the averaged state; ``F`` is
nonlinear and averaged as such. With ``Yb`` the two-node mean, ``g = (Y_{j+1} - Y_j) / ds`` and
``r`` the mean rate (``+ c g / 2`` with ``c`` the winch's convective speed, first interval only):

    R0 = c0 m (r_u - Yb_v r_phi)              - g_T + Sb g_phi - Fb_t
    R1 = c0 (m + m_a)(r_v + Yb_u r_phi)       - H(Tb) g_phi - g_S - Fb_n
    R2 = c0 e'(Tb) r_T     - g_u + Yb_v g_phi
    R3 = c0 (1 + e(Tb)) r_phi - g_v - Yb_u g_phi
    R4 = EI g_phi - Mb                                   (bending only: curvature, M = EI kappa)
    R5 = g_M + (1 + e(Tb)) Sb                            (bending only: moment balance)

``H(T)`` is ``T`` itself, or the tension floor of a slack interval (:func:`loads2d.transverse_tension`;
``simulation.slack: continue``).

The shear ``S`` and moment ``M`` rows and terms exist only when the cable has bending stiffness
(``nv = 6``, Gobat & Grosenbaugh 2001): with the force ``T t + S n`` the momentum rows gain
``+S phi_s`` and ``-S_s``, and ``dM/ds + (1 + e) S = 0``. Inertia terms use the
``[am]``-weighted states and all others the ``[ak]``-weighted ones (:mod:`kanat.continuum.schemes`);
``c0 = 0`` gives the discrete steady problem.

A *junction* interval joins nodes ``a = j`` and ``b = j + 1`` at the same arclength with a body
clamped there (an attachment): two rows of velocity continuity ``V_a = V_b`` (new level), two of
the body's momentum in global components

    c0 (M_b + M_a) A_a^[am] - (T_b t_b + S_b n_b - T_a t_a - S_a n_a)^[ak] - B z - D - F - (M_a + rho Vol) a_w = 0

(``A = (u_t - v phi_t) t + (v_t + u phi_t) n`` the acceleration of node ``a``, ``D`` the drag of
the water relative to it; for a spherical float ``B = B_net - (1 - f(z)) B_f`` and the wave inertia
``f(z) (M_a + rho Vol) a_w``, ``f`` its immersed share at the predicted height ``z = R + PRED V`` under
the wave elevation, :mod:`kanat.physics.immersion`), and with bending ``M_a = M_b = 0`` (a pinned connection). The
tension and angle jump across it by exactly the body's load.

All derivatives are written out; :mod:`kanat.continuum.oracle_complex_step2d` checks them by complex step.

The inputs of :func:`assemble` are one named record, :class:`kernels2d.PlanarStep`, read by field
name. Its last field, ``extras``, is None for a plain cable (no seabed within
reach, no waves, no inline bodies, no bending stiffness, no surface buoy) and an array otherwise:
numba prunes the ``extras is not None`` branches of the plain version at compile time, so a
plain run compiles none of that code (``kanat.jit``'s compile budget); the two versions give the
same numbers where both apply (the tests compare them).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.continuum import loads2d as k


@kernel
def assemble(x, step, res, band):
    """Residual ``res`` (nv (N+1),) and banded Jacobian ``band`` at unknowns ``x`` (N+1, nv).

    ``step`` is the step's :class:`kernels2d.PlanarStep`: ``previous`` and ``rate`` (N+1, nv) the
    old state and rate, ``water`` (N+1, NENV) the nodal water and position data, ``intervals``
    (N, n_par) the parameter row of every interval, ``start``, ``end`` the end conditions at
    ``s = 0`` and ``s = L``, ``extras`` None for a plain cable. ``band[w + row - col, col]`` holds
    ``dR[row]/dx[col]`` (LAPACK banded storage, ``w`` = :func:`kernels2d.bandwidth`).
    """
    _assemble(x, step, res, band, step.extras)


@inner
def _assemble(x, step, res, band, extras):
    """:func:`assemble`, with the record's ``extras`` an argument of its own: numba prunes the
    ``extras is not None`` branches by its type (None), which it does for arguments only."""
    y, d, env, P = step.previous, step.rate, step.water, step.intervals
    n_nodes, nv = x.shape[0], x.shape[1]
    width = (band.shape[0] - 1) // 2
    band[:, :] = 0.0
    p = P[0]
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    wm = np.empty((n_nodes, nv))
    wk = np.empty((n_nodes, nv))
    wr = np.empty((n_nodes, nv))
    for j in range(n_nodes):
        for i in range(nv):
            rate = (x[j, i] - y[j, i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[j, i]
            wm[j, i] = (1.0 - am) * x[j, i] + am * y[j, i]
            wk[j, i] = (1.0 - ak) * x[j, i] + ak * y[j, i]
            wr[j, i] = (1.0 - am) * rate + am * d[j, i]
    load, dload = _node_loads(wk, env, P, extras)
    chain = np.empty(3)
    chain[0], chain[1], chain[2] = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    for j in range(n_nodes - 1):
        junction = False
        if extras is not None:
            junction = P[j, k.KIND] == k.JUNCTION
            if junction:
                _junction_rows(j, x, wm, wk, wr, env, P[j], chain, width, res, band)
        if not junction:
            _interval_rows(j, wm, wk, wr, load, dload, P[j], chain, width, res, band, extras)
    _end_rows(x, step, width, res, band, extras)


@inner
def _node_loads(wk, env, P, extras):
    """Loads (f_t, f_n) at every node as the left (use 0) and right (use 1) node of its intervals,
    each with that interval's parameters, and their derivatives by the node's states.

    A node inside a section is evaluated once; a node between two sections twice.
    """
    n_nodes, nv = wk.shape[0], wk.shape[1]
    load = np.empty((n_nodes, 2, 2))
    dload = np.empty((n_nodes, 2, 2, nv))
    load[:] = 0.0
    dload[:] = 0.0
    jac, extra = np.empty((2, 4)), np.empty((2, 4))
    for j in range(n_nodes):
        for use in range(2):
            row = j if use == 0 else j - 1
            if row < 0 or row >= n_nodes - 1 or P[row, k.KIND] == k.JUNCTION:
                continue
            if use == 1 and j < n_nodes - 1 and P[j, k.KIND] != k.JUNCTION and P[j, k.SECTION] == P[row, k.SECTION]:
                for i in range(2):
                    load[j, 1, i] = load[j, 0, i]
                    for q in range(nv):
                        dload[j, 1, i, q] = dload[j, 0, i, q]
                continue
            p = P[row]
            ft, fn = k.node_load_jacobian(wk[j, 0], wk[j, 1], wk[j, 2], wk[j, 3], env[j, k.UX], env[j, k.UZ], p, jac)
            et = en = 0.0
            if extras is not None:
                et, en = k.extra_load_jacobian(wk[j, 0], wk[j, 1], wk[j, 2], wk[j, 3], env[j], p, extra)
            load[j, use, 0], load[j, use, 1] = ft + et, fn + en
            for i in range(2):
                for q in range(4):
                    dload[j, use, i, q] = jac[i, q]
            if extras is not None:
                for i in range(2):
                    for q in range(4):
                        dload[j, use, i, q] += extra[i, q]
    return load, dload


@inner
def _interval_rows(j, wm, wk, wr, load, dload, p, chain, width, res, band, extras):
    """Rows of cable interval ``j`` (module docstring) and their exact derivatives."""
    nv = wm.shape[1]
    l, r = j, j + 1
    c, ds, conv = p[k.INERTIA], p[k.DS], p[k.CONV]
    mass, normal_mass = p[k.M], p[k.M] + p[k.MA]
    mb1, mb2, mb0 = 0.5 * (wm[l, 1] + wm[r, 1]), 0.5 * (wm[l, 2] + wm[r, 2]), 0.5 * (wm[l, 0] + wm[r, 0])
    kb0, kb1, kb2 = 0.5 * (wk[l, 0] + wk[r, 0]), 0.5 * (wk[l, 1] + wk[r, 1]), 0.5 * (wk[l, 2] + wk[r, 2])
    g0, g1, g2, g3 = ((wk[r, 0] - wk[l, 0]) / ds, (wk[r, 1] - wk[l, 1]) / ds,
                      (wk[r, 2] - wk[l, 2]) / ds, (wk[r, 3] - wk[l, 3]) / ds)
    r0, r1, r2, r3 = (0.5 * (wr[l, 0] + wr[r, 0]) + 0.5 * conv * g0, 0.5 * (wr[l, 1] + wr[r, 1]) + 0.5 * conv * g1,
                      0.5 * (wr[l, 2] + wr[r, 2]) + 0.5 * conv * g2, 0.5 * (wr[l, 3] + wr[r, 3]) + 0.5 * conv * g3)
    row = nv // 2 + nv * j
    res[row] = c * mass * (r1 - mb2 * r3) - g0 - 0.5 * (load[l, 0, 0] + load[r, 1, 0])
    held, held_slope = k.transverse_tension(kb0, p)
    res[row + 1] = c * normal_mass * (r2 + mb1 * r3) - held * g3 - 0.5 * (load[l, 0, 1] + load[r, 1, 1])
    t0, e0, flex = k._law_segment(mb0, p)
    stretch = 1.0 + e0 + flex * (mb0 - t0)
    res[row + 2] = c * flex * r0 - g1 + kb2 * g3
    res[row + 3] = c * stretch * r3 - g2 - kb1 * g3
    kb4 = g4 = kb5 = g5 = stretch_k = flex_k = 0.0
    if extras is not None:
        if nv == 6:
            kb4, kb5 = 0.5 * (wk[l, 4] + wk[r, 4]), 0.5 * (wk[l, 5] + wk[r, 5])
            g4, g5 = (wk[r, 4] - wk[l, 4]) / ds, (wk[r, 5] - wk[l, 5]) / ds
            tk, ek, flex_k = k._law_segment(kb0, p)
            stretch_k = 1.0 + ek + flex_k * (kb0 - tk)
            res[row] += kb4 * g3
            res[row + 1] -= g4
            res[row + 4] = p[k.EI] * g3 - kb5
            res[row + 5] = g5 + stretch_k * kb4
    dm = np.empty((nv, nv))          # dR[row i] / d(weighted state of one node)[q], for m, k, r
    dk = np.empty((nv, nv))
    dr = np.empty((nv, nv))
    for side in range(2):
        node, use = (l, 0) if side == 0 else (r, 1)
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
        dk[1, 0] = -0.5 * held_slope * g3
        dk[1, 3] = -held * sign / ds
        dr[2, 0] = 0.5 * c * flex
        dk[2, 1] = -sign / ds
        dk[2, 2] = 0.5 * g3
        dk[2, 3] = kb2 * sign / ds
        dm[3, 0] = 0.5 * c * r3 * flex
        dr[3, 3] = 0.5 * c * stretch
        dk[3, 1] = -0.5 * g3
        dk[3, 2] = -sign / ds
        dk[3, 3] = -kb1 * sign / ds
        if extras is not None:
            if nv == 6:
                dk[0, 4] = 0.5 * g3
                dk[0, 3] += kb4 * sign / ds
                dk[1, 4] = -sign / ds
                dk[4, 3] = p[k.EI] * sign / ds
                dk[4, 5] = -0.5
                dk[5, 5] = sign / ds
                dk[5, 4] = 0.5 * stretch_k
                dk[5, 0] = 0.5 * flex_k * kb4
        for q in range(nv):
            dk[0, q] -= 0.5 * dload[node, use, 0, q]
            dk[1, q] -= 0.5 * dload[node, use, 1, q]
        if conv != 0.0:                                  # r += conv g / 2: d/dk = dr conv sign / ds
            for i in range(4):
                for q in range(4):
                    dk[i, q] += dr[i, q] * conv * sign / ds
        for q in range(nv):
            col = nv * node + q
            for i in range(nv):
                band[width + row + i - col, col] = dm[i, q] * chain[0] + dk[i, q] * chain[1] + dr[i, q] * chain[2]


@inner
def _junction_rows(j, x, wm, wk, wr, env, p, chain, width, res, band):
    """Rows of the junction interval ``j`` (an inline body; module docstring) and their derivatives."""
    nv = x.shape[1]
    bend = nv == 6
    a, b = j, j + 1
    row = nv // 2 + nv * j
    # velocity continuity at the new level
    ca, sa, cb, sb = np.cos(x[a, 3]), np.sin(x[a, 3]), np.cos(x[b, 3]), np.sin(x[b, 3])
    res[row] = (x[a, 1] * ca - x[a, 2] * sa) - (x[b, 1] * cb - x[b, 2] * sb)
    res[row + 1] = (x[a, 1] * sa + x[a, 2] * ca) - (x[b, 1] * sb + x[b, 2] * cb)
    jac = np.empty((nv, 2 * nv))                      # rows of this interval by (node a, node b) unknowns
    jac[:, :] = 0.0
    jac[0, 1], jac[0, 2], jac[0, 3] = ca, -sa, -x[a, 1] * sa - x[a, 2] * ca
    jac[1, 1], jac[1, 2], jac[1, 3] = sa, ca, x[a, 1] * ca - x[a, 2] * sa
    jac[0, nv + 1], jac[0, nv + 2], jac[0, nv + 3] = -cb, sb, x[b, 1] * sb + x[b, 2] * cb
    jac[1, nv + 1], jac[1, nv + 2], jac[1, nv + 3] = -sb, -cb, -(x[b, 1] * cb - x[b, 2] * sb)
    # the body's momentum, global x and z
    cm, ck, cr = chain[0], chain[1], chain[2]
    mass = p[k.INERTIA] * p[k.JB_MASS]
    m1, m2, m3 = wm[a, 1], wm[a, 2], wm[a, 3]
    q1, q2, q3 = wr[a, 1], wr[a, 2], wr[a, 3]
    cmm, smm = np.cos(m3), np.sin(m3)
    at_, an_ = q1 - m2 * q3, q2 + m1 * q3                   # acceleration along t(m3), n(m3)
    acc_x, acc_z = at_ * cmm - an_ * smm, at_ * smm + an_ * cmm
    Ta, ua, va, pa = wk[a, 0], wk[a, 1], wk[a, 2], wk[a, 3]
    Tb, pb = wk[b, 0], wk[b, 3]
    Sa = Sb = 0.0
    if bend:
        Sa, Sb = wk[a, 4], wk[b, 4]
    cka, ska, ckb, skb = np.cos(pa), np.sin(pa), np.cos(pb), np.sin(pb)
    wx = env[a, k.UX] - (ua * cka - va * ska)                 # water relative to the body
    wz = env[a, k.UZ] - (ua * ska + va * cka)
    speed = np.sqrt(wx * wx + wz * wz)
    hd = p[k.JB_DRAG]
    fx = (Tb * ckb - Sb * skb) - (Ta * cka - Sa * ska) + hd * speed * wx + p[k.JB_F0] + p[k.JB_WAVE] * env[a, k.AX]
    fz = (Tb * skb + Sb * ckb) - (Ta * ska + Sa * cka) + hd * speed * wz + p[k.JB_F2] + p[k.JB_BUOY] \
        + p[k.JB_WAVE] * env[a, k.AZ]
    dlift = dwave = 0.0
    if p[k.JB_DIAMETER] > 0.0:                 # a float keeps its immersed share of buoyancy and wave inertia
        share, dshare = k.float_immersion(env[a, k.RZ] + p[k.PRED] * (ua * ska + va * cka), p[k.JB_ETA],
                                          p[k.JB_DIAMETER])
        fx += (share - 1.0) * p[k.JB_WAVE] * env[a, k.AX]
        fz += (share - 1.0) * (p[k.JB_FULL] + p[k.JB_WAVE] * env[a, k.AZ])
        dlift = (p[k.JB_FULL] + p[k.JB_WAVE] * env[a, k.AZ]) * dshare * p[k.PRED]
        dwave = p[k.JB_WAVE] * env[a, k.AX] * dshare * p[k.PRED]
    res[row + 2] = mass * acc_x - fx
    res[row + 3] = mass * acc_z - fz
    # d(acc)/d(m1, m2, m3) and /d(q1, q2, q3)
    dacc_m = np.empty((2, 4))
    dacc_r = np.empty((2, 4))
    dacc_m[:, :] = 0.0
    dacc_r[:, :] = 0.0
    dacc_m[0, 1], dacc_m[1, 1] = q3 * -smm, q3 * cmm
    dacc_m[0, 2], dacc_m[1, 2] = -q3 * cmm, -q3 * smm
    dacc_m[0, 3], dacc_m[1, 3] = -at_ * smm - an_ * cmm, at_ * cmm - an_ * smm
    dacc_r[0, 1], dacc_r[1, 1] = cmm, smm
    dacc_r[0, 2], dacc_r[1, 2] = -smm, cmm
    dacc_r[0, 3], dacc_r[1, 3] = -m2 * cmm - m1 * smm, -m2 * smm + m1 * cmm
    g00 = g01 = g11 = 0.0
    if speed > 0.0:
        g00, g01, g11 = hd * (speed + wx * wx / speed), hd * wx * wz / speed, hd * (speed + wz * wz / speed)
    # d(w)/d(ua, va, pa) = -dV/d(...)
    dw = np.empty((2, 3))
    dw[0, 0], dw[1, 0] = -cka, -ska
    dw[0, 1], dw[1, 1] = ska, -cka
    dw[0, 2], dw[1, 2] = ua * ska + va * cka, -(ua * cka - va * ska)
    dfa = np.empty((2, 6))                            # d(fx, fz)/d(weighted k state of node a)
    dfb = np.empty((2, 6))
    dfa[:, :] = 0.0
    dfb[:, :] = 0.0
    dfa[0, 0], dfa[1, 0] = -cka, -ska
    for q in range(3):
        dfa[0, 1 + q] = g00 * dw[0, q] + g01 * dw[1, q]
        dfa[1, 1 + q] = g01 * dw[0, q] + g11 * dw[1, q]
    dfa[0, 3] += Ta * ska + Sa * cka
    dfa[1, 3] += -Ta * cka + Sa * ska
    if dlift != 0.0 or dwave != 0.0:           # the float's share by z = R + PRED (u sin + v cos)
        for i, slope in ((0, dwave), (1, dlift)):
            dfa[i, 1] += slope * ska
            dfa[i, 2] += slope * cka
            dfa[i, 3] += slope * (ua * cka - va * ska)
    dfb[0, 0], dfb[1, 0] = ckb, skb
    dfb[0, 3], dfb[1, 3] = -Tb * skb - Sb * ckb, Tb * ckb - Sb * skb
    if bend:
        dfa[0, 4], dfa[1, 4] = ska, -cka
        dfb[0, 4], dfb[1, 4] = -skb, ckb
    for i in range(2):
        for q in range(4):
            jac[2 + i, q] = mass * (dacc_m[i, q] * cm + dacc_r[i, q] * cr)
        for q in range(min(nv, 6)):
            jac[2 + i, q] -= dfa[i, q] * ck
            jac[2 + i, nv + q] -= dfb[i, q] * ck
    if bend:
        res[row + 4], jac[4, 5] = x[a, 5], 1.0
        res[row + 5], jac[5, nv + 5] = x[b, 5], 1.0
    for q in range(2 * nv):
        col = nv * a + q
        for i in range(nv):
            band[width + row + i - col, col] = jac[i, q]


@inner
def _end_rows(x, step, width, res, band, extras):
    """The rows of each end and their derivatives (:func:`kernels2d.end_jacobian`) into ``res``, ``band``."""
    y, d, env, P, b0, b1 = step.previous, step.rate, step.water, step.intervals, step.start, step.end
    nv = x.shape[1]
    half = nv // 2
    out = np.empty(half)
    jac = np.empty((half, nv))
    last = x.shape[0] - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, nv * last + half)
        p = P[0] if end == 0 else P[last - 1]
        k.end_jacobian(x[node], y[node], d[node], env[node], p, b0 if end == 0 else b1, side, out, jac, extras)
        for i in range(half):
            res[row + i] = out[i]
            for q in range(nv):
                band[width + row + i - (nv * node + q), nv * node + q] = jac[i, q]
