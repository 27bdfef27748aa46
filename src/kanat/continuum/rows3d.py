"""The spatial interval rows, inline bodies and the banded Newton system (theory/continuum.md §2, theory/time-schemes.md §1, theory/moorings.md).

As :mod:`kanat.continuum.rows2d` in 3-D (no bending stiffness): interval ``j`` carries the six
rows ``avg(M) r + avg(K) g - avg(F)`` of :mod:`kanat.continuum.kernels3d` with its own parameter
row ``P[j]`` (the winch's convective term ``+ c g / 2`` in the mean rate of the first interval),
and a junction interval carries an inline body: velocity continuity ``V_a = V_b`` (3 rows, new
level) and the body's momentum in chart components (3 rows)

    c0 (M_b + M_a) A_a^[am] - (T_b t_b - T_a t_a)^[ak] - B z - D - F - (M_a + rho Vol) a_w = 0

(a spherical float: ``B`` and the wave inertia keep their immersed share, :mod:`kanat.continuum.rows2d`).

The inputs are one named record, :class:`kernels3d.SpatialStep`, read by field name; its
``extras``: None for a plain cable (its branches compile away), as in :mod:`kanat.continuum.rows2d`.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.continuum import loads2d as k
from kanat.continuum import loads3d as k3


@kernel
def assemble3(x, step, res, band):
    """Residual (6(N+1),) and banded Jacobian (17, 6(N+1)) of one step at unknowns ``x`` (N+1, 6).

    ``step`` is the step's :class:`kernels3d.SpatialStep`: ``previous``, ``rate`` the old state and
    rate; ``water`` (N+1, NENV3) the nodal data in chart coordinates; ``vertical`` (3,) the chart
    components of the vertical ``z``; ``intervals`` (N, n_par) the interval rows; ``start``, ``end``
    the end conditions (NBPAR3); ``extras`` None for a plain cable.
    """
    flexible_rows(x, step.previous, step.rate, step, res, band, step.extras)


@inner
def flexible_rows(x, y, d, step, res, band, extras):
    """:func:`assemble3` with the old state and rate ``y``, ``d`` (N+1, 6) given apart (the bending
    kernel passes their first six columns, :mod:`kanat.continuum.bending3d`) and the record's
    ``extras`` an argument of its own: numba prunes its branches by type for arguments only."""
    env, up, P = step.water, step.vertical, step.intervals
    n_nodes = x.shape[0]
    band[:, :] = 0.0
    p = P[0]
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    wm, wk, wr = np.empty((n_nodes, 6)), np.empty((n_nodes, 6)), np.empty((n_nodes, 6))
    for j in range(n_nodes):
        for i in range(6):
            wm[j, i] = (1.0 - am) * x[j, i] + am * y[j, i]
            wk[j, i] = (1.0 - ak) * x[j, i] + ak * y[j, i]
            wr[j, i] = (1.0 - am) * ((x[j, i] - y[j, i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[j, i]) \
                + am * d[j, i]
    load, dload = _node_loads3(wk, env, up, P, extras)
    scratch, vectors = np.empty((6, 6, 6)), np.empty((2, 6))
    for j in range(n_nodes - 1):
        junction = False
        if extras is not None:
            junction = P[j, k.KIND] == k.JUNCTION
            if junction:
                _junction_rows3(j, x, wm, wk, wr, env, up, P[j], res, band)
        if not junction:
            _interval_rows3(j, wm, wk, wr, load, dload, P[j], scratch, vectors, res, band)
    _end_rows3(x, y, d, step, res, band, extras)


@inner
def _node_loads3(wk, env, up, P, extras):
    """Loads (n, 2 uses, 3) at the ``[ak]`` states, each with its interval's row, and their
    derivatives (n, 2, 3, 6) (:func:`kernels3d.node_load3_jacobian`, :func:`kernels3d.extra_load3_jacobian`)."""
    n_nodes = wk.shape[0]
    load = np.zeros((n_nodes, 2, 3))
    dload = np.zeros((n_nodes, 2, 3, 6))
    jac, extra = np.empty((3, 6)), np.empty((3, 6))
    for j in range(n_nodes):
        for use in range(2):
            row = j if use == 0 else j - 1
            if row < 0 or row >= n_nodes - 1 or P[row, k.KIND] == k.JUNCTION:
                continue
            if use == 1 and j < n_nodes - 1 and P[j, k.KIND] != k.JUNCTION and P[j, k.SECTION] == P[row, k.SECTION]:
                for i in range(3):
                    load[j, 1, i] = load[j, 0, i]
                    for q in range(6):
                        dload[j, 1, i, q] = dload[j, 0, i, q]
                continue
            p = P[row]
            f0, f1, f2 = k3.node_load3_jacobian(wk[j], env[j, k3.UX3:k3.UX3 + 3], up, p, jac)
            e0 = e1 = e2 = 0.0
            if extras is not None:
                e0, e1, e2 = k3.extra_load3_jacobian(wk[j], env[j], p, extra)
            load[j, use, 0], load[j, use, 1], load[j, use, 2] = f0 + e0, f1 + e1, f2 + e2
            for i in range(3):
                for q in range(6):
                    dload[j, use, i, q] = jac[i, q]
            if extras is not None:
                for i in range(3):
                    for q in range(6):
                        dload[j, use, i, q] += extra[i, q]
    return load, dload


@inner
def _interval_rows3(j, wm, wk, wr, load, dload, p, scratch, vectors, res, band):
    """The six rows of cable interval ``j`` and their derivatives by the states of its two nodes
    (``scratch`` (6, 6, 6) and ``vectors`` (2, 6) are work space)."""
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    c, ds, conv = p[k.INERTIA], p[k.DS], p[k.CONV]
    l, r = j, j + 1
    ml, mr, kl, kr, dm, dk = scratch[0], scratch[1], scratch[2], scratch[3], scratch[4], scratch[5]
    rate, grad = vectors[0], vectors[1]
    for i in range(6):
        grad[i] = (wk[r, i] - wk[l, i]) / ds
        rate[i] = 0.5 * (wr[l, i] + wr[r, i]) + 0.5 * conv * grad[i]
    k3.mass_matrix(wm[l], p, ml)
    k3.mass_matrix(wm[r], p, mr)
    k3.stiffness_matrix(wk[l], kl)
    k3.stiffness_matrix(wk[r], kr)
    row = 3 + 6 * j
    for i in range(6):
        acc = 0.0
        for q in range(6):
            acc += c * 0.5 * (ml[i, q] + mr[i, q]) * rate[q] + 0.5 * (kl[i, q] + kr[i, q]) * grad[q]
        if i < 3:
            acc -= 0.5 * (load[l, 0, i] + load[r, 1, i])
        res[row + i] = acc
    for side in range(2):
        node, use = (l, 0) if side == 0 else (r, 1)
        sign = -1.0 if side == 0 else 1.0
        k3.d_mass_times(wm[node], rate, p, dm)
        k3.d_stiffness_times(wk[node], grad, dk)
        for q in range(6):
            col = 6 * node + q
            for i in range(6):
                mass = 0.5 * (ml[i, q] + mr[i, q])
                value = (c * (0.5 * dm[i, q] * cm + 0.5 * mass * cr)
                         + 0.5 * dk[i, q] * ck + 0.5 * (kl[i, q] + kr[i, q]) * sign / ds * ck)
                if conv != 0.0:
                    # rate += conv g / 2: d(M rate)_i/dk_q = M_iq conv sign / (2 ds)
                    value += c * mass * 0.5 * conv * sign / ds * ck
                if i < 3:
                    value -= 0.5 * dload[node, use, i, q] * ck
                band[k3.UPPER + row + i - col, col] = value


@inner
def _junction_rows3(j, x, wm, wk, wr, env, up, p, res, band):
    """Rows of the junction interval ``j`` (an inline body; module docstring) and their derivatives."""
    a, b = j, j + 1
    row = 3 + 6 * j
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    jac = np.zeros((6, 12))
    ea, eb, dva, dvb = np.empty((3, 3)), np.empty((3, 3)), np.empty((6, 3)), np.empty((6, 3))
    # velocity continuity at the new level
    k3._frame_rows(x[a, 4], x[a, 5], ea)
    k3._frame_rows(x[b, 4], x[b, 5], eb)
    k3._velocity_derivatives(x[a], ea, dva)
    k3._velocity_derivatives(x[b], eb, dvb)
    for i in range(3):
        res[row + i] = (x[a, 1] * ea[0, i] + x[a, 2] * ea[1, i] + x[a, 3] * ea[2, i]) - (
            x[b, 1] * eb[0, i] + x[b, 2] * eb[1, i] + x[b, 3] * eb[2, i])
        for q in range(6):
            jac[i, q] = dva[q, i]
            jac[i, 6 + q] = -dvb[q, i]
    # the body's acceleration (node a, [am] level) in chart components
    m, r = wm[a], wr[a]
    cpm, spm = np.cos(m[4]), np.sin(m[4])
    em = np.empty((3, 3))
    k3._frame_rows(m[4], m[5], em)
    acc = np.empty(3)
    acc[0] = r[1] - m[2] * r[4] + m[3] * cpm * r[5]
    acc[1] = r[2] + m[1] * r[4] - m[3] * spm * r[5]
    acc[2] = r[3] + (-m[1] * cpm + m[2] * spm) * r[5]
    dacc_m, dacc_r = np.zeros((3, 6)), np.zeros((3, 6))
    dacc_r[0, 1], dacc_r[0, 4], dacc_r[0, 5] = 1.0, -m[2], m[3] * cpm
    dacc_m[0, 2], dacc_m[0, 3], dacc_m[0, 4] = -r[4], cpm * r[5], -m[3] * spm * r[5]
    dacc_r[1, 2], dacc_r[1, 4], dacc_r[1, 5] = 1.0, m[1], -m[3] * spm
    dacc_m[1, 1], dacc_m[1, 3], dacc_m[1, 4] = r[4], -spm * r[5], -m[3] * cpm * r[5]
    dacc_r[2, 3], dacc_r[2, 5] = 1.0, -m[1] * cpm + m[2] * spm
    dacc_m[2, 1], dacc_m[2, 2], dacc_m[2, 4] = -cpm * r[5], spm * r[5], (m[1] * spm + m[2] * cpm) * r[5]
    mass = p[k.INERTIA] * p[k.JB_MASS]
    # forces at the [ak] level
    ka, kb = wk[a], wk[b]
    eka, ekb, dvk = np.empty((3, 3)), np.empty((3, 3)), np.empty((6, 3))
    k3._frame_rows(ka[4], ka[5], eka)
    k3._frame_rows(kb[4], kb[5], ekb)
    k3._velocity_derivatives(ka, eka, dvk)
    rel = np.empty(3)
    for i in range(3):
        rel[i] = env[a, k3.UX3 + i] - (ka[1] * eka[0, i] + ka[2] * eka[1, i] + ka[3] * eka[2, i])
    speed = np.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2])
    hd = p[k.JB_DRAG]
    cpa, cpb = np.cos(ka[4]), np.cos(kb[4])
    buoy, dlift, wave, dshare = p[k.JB_BUOY], 0.0, p[k.JB_WAVE], 0.0
    dz = np.zeros(6)                                  # d(z)/d(weighted k state of node a), z = up . (R + PRED V)
    if p[k.JB_DIAMETER] > 0.0:                        # a float keeps its immersed share of its buoyancy
        z = 0.0
        for i in range(3):
            z += up[i] * (env[a, k3.RX3 + i] + p[k.PRED] * (ka[1] * eka[0, i] + ka[2] * eka[1, i] + ka[3] * eka[2, i]))
            for q in range(6):
                dz[q] += up[i] * p[k.PRED] * dvk[q, i]
        share, dshare = k.float_immersion(z, p[k.JB_ETA], p[k.JB_DIAMETER])
        buoy += (share - 1.0) * p[k.JB_FULL]
        wave *= share                                 # and its immersed share of the wave inertia
        dlift = p[k.JB_FULL] * dshare
    for i in range(3):
        force = (kb[0] * ekb[0, i] - ka[0] * eka[0, i] + buoy * up[i] + p[k.JB_F0 + i]
                 + wave * env[a, k3.AX3 + i] + hd * speed * rel[i])
        accel = acc[0] * em[0, i] + acc[1] * em[1, i] + acc[2] * em[2, i]
        res[row + 3 + i] = mass * accel - force
        for q in range(6):
            dam = dacc_m[0, q] * em[0, i] + dacc_m[1, q] * em[1, i] + dacc_m[2, q] * em[2, i]
            dar = dacc_r[0, q] * em[0, i] + dacc_r[1, q] * em[1, i] + dacc_r[2, q] * em[2, i]
            if q == 4:
                dam += acc[0] * em[1, i] - acc[1] * em[0, i]
            if q == 5:
                dam += -acc[0] * cpm * em[2, i] + acc[1] * spm * em[2, i] + acc[2] * (cpm * em[0, i] - spm * em[1, i])
            drag = 0.0
            for jj in range(3):
                g = hd * ((speed if i == jj else 0.0) + (rel[i] * rel[jj] / speed if speed > 0.0 else 0.0))
                drag -= g * dvk[q, jj]
            dfa = drag
            if dshare != 0.0:                         # the float's share by its height
                dfa += (dlift * up[i] + p[k.JB_WAVE] * env[a, k3.AX3 + i] * dshare) * dz[q]
            if q == 0:
                dfa -= eka[0, i]
            elif q == 4:
                dfa -= ka[0] * eka[1, i]
            elif q == 5:
                dfa += ka[0] * cpa * eka[2, i]
            dfb = 0.0
            if q == 0:
                dfb = ekb[0, i]
            elif q == 4:
                dfb = kb[0] * ekb[1, i]
            elif q == 5:
                dfb = -kb[0] * cpb * ekb[2, i]
            jac[3 + i, q] = mass * (dam * cm + dar * cr) - dfa * ck
            jac[3 + i, 6 + q] = -dfb * ck
    for q in range(12):
        col = 6 * a + q
        for i in range(6):
            band[k3.UPPER + row + i - col, col] = jac[i, q]


@inner
def _end_rows3(x, y, d, step, res, band, extras):
    """The three rows of each end and their derivatives (:func:`kernels3d.end_jacobian3`) into ``res``, ``band``."""
    env, up, P, b0, b1 = step.water, step.vertical, step.intervals, step.start, step.end
    out, jac = np.empty(3), np.empty((3, 6))
    last = x.shape[0] - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, 6 * last + 3)
        p = P[0] if end == 0 else P[last - 1]
        k3.end_jacobian3(x[node], y[node], d[node], env[node], up, p, b0 if end == 0 else b1, side, out, jac, extras)
        for i in range(3):
            res[row + i] = out[i]
            for q in range(6):
                band[k3.UPPER + row + i - (6 * node + q), 6 * node + q] = jac[i, q]
