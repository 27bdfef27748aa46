"""Bending stiffness in the spatial continuum model: Gobat & Grosenbaugh's rod (2001, WHOI Cable) in 3-D.

A cable whose line type has bending stiffness ``EI`` has ten unknowns per node,
``Y = (T, u, v, w, phi, theta, S_n, S_b, M_n, M_b)``: the six of :mod:`kanat.continuum.kernels3d`,
the shear force ``S = S_n n + S_b b`` and the bending moment ``M = M_n n + M_b b`` in the chart's
frame (torsion neglected, as WHOI Cable does). With the force ``F = T t + S`` and the frame's turn
along ``s`` (``t_s = phi_s n - cos(phi) theta_s b``, ``n_s = -phi_s t + sin(phi) theta_s b``,
``b_s = theta_s (cos(phi) t - sin(phi) n)``), the curvature ``kappa = t x t_s = cos(phi) theta_s n
+ phi_s b`` and ``t x F = S_n b - S_b n``, the momentum rows gain ``-dS/ds`` and four rows follow:

    row 0  (flexible) + S_n phi_s - S_b cos(phi) theta_s                  momentum . t
    row 1  (flexible) - S_n,s + S_b sin(phi) theta_s                      momentum . n
    row 2  (flexible) - S_b,s - S_n sin(phi) theta_s                      momentum . b
    row 6  EI cos(phi) theta_s - M_n = 0                                    curvature . n  (M = EI kappa)
    row 7  EI phi_s - M_b = 0                                               curvature . b
    row 8  M_n,s - M_b sin(phi) theta_s - (1 + e) S_b = 0                   moment balance . n
    row 9  M_b,s + M_n sin(phi) theta_s + (1 + e) S_n = 0                   moment balance . b

(``dM/ds + (1 + e) t x F = 0`` projected on ``n`` and ``b``; its ``t`` part, torsion, is left out.)
The rows are the projections of vector equations, so they hold in any chart: a re-chart
(:func:`kanat.continuum.chart.rechart`) rewrites ``S`` and ``M`` in the new frame as it does ``V``.
For a cable in a vertical plane charted with the pole normal to it (``theta_s = 0``, or ``phi = 0``
with a horizontal pole) rows 0, 1, 7, 9 (or their mirror) are the planar rows of
:mod:`kanat.continuum.rows2d` and rows 6, 8 give ``M_n = S_b = 0``;
:mod:`kanat.continuum.oracle_sympy3d` derives the ten rows symbolically and the tests compare.

Box method: the bending terms are taken at the interval's midpoint, from the ``[ak]`` two-node
means ``kb`` and the gradients ``g = (Y_r - Y_l) / ds`` (as the planar rows, where they are linear
in them), with ``1 + e`` of the mean tension. Ends (5 rows each): a prescribed velocity (tow point,
anchor) is pinned, ``M_n = M_b = 0``, or clamped, ``phi = phi0, theta = theta0`` (the tests'
cantilever; no case key clamps one); an end body carries ``-side (T t + S)`` and ``M = 0``; a free
end ``T = S_n = S_b = M_n = M_b = 0``. An inline body (junction) carries ``T t + S`` of both sides
and holds ``M = 0`` on its two nodes (pinned). A section without ``EI`` has ``M = 0``.

The flexible rows are those of :func:`kanat.continuum.rows3d.assemble3`
(:func:`~kanat.continuum.rows3d.flexible_rows`) on the first six unknowns, moved into this layout,
so the plain 3-D kernels compile none of this: only a case with bending stiffness compiles
:func:`assemble3_bending`. Rows ``[start (5); interval 0 (10); ...; far end (5)]``, a band of 14
sub- and super-diagonals. All derivatives are written out;
:mod:`kanat.continuum.oracle_complex_step3d` checks them by complex step.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.continuum import loads2d as k
from kanat.continuum import loads3d as k3
from kanat.continuum.rows3d import flexible_rows

from kanat.continuum.layout3d import B3_CLAMP, B3_PHI0, B3_THETA0, NBPAR3_BENDING  # noqa: F401  (layout3d)
from kanat.continuum.layout3d import NV_BENDING as NV, WIDTH_BENDING as WIDTH

SN, SB, MN, MB = 6, 7, 8, 9         # the shear and moment unknowns


@kernel
def bending_terms(kb, g, p, out, dk, dg):
    """The bending terms of an interval's ten rows (module docstring) at its mean state ``kb`` (10,)
    and gradient ``g`` (10,) into ``out`` (10,; rows 3-5 zero), with ``dk = d out / d kb`` and
    ``dg = d out / d g`` (10, 10)."""
    for i in range(NV):
        out[i] = 0.0
        for q in range(NV):
            dk[i, q] = 0.0
            dg[i, q] = 0.0
    c, s = np.cos(kb[4]), np.sin(kb[4])
    knot, e0, flex = k._law_segment(kb[0], p)
    stretch = 1.0 + e0 + flex * (kb[0] - knot)
    ei = p[k.EI]
    sn, sb, mn, mb = kb[SN], kb[SB], kb[MN], kb[MB]
    g4, g5 = g[4], g[5]
    out[0] = sn * g4 - sb * c * g5
    dk[0, SN], dk[0, SB], dk[0, 4] = g4, -c * g5, sb * s * g5
    dg[0, 4], dg[0, 5] = sn, -sb * c
    out[1] = -g[SN] + sb * s * g5
    dg[1, SN], dk[1, SB], dk[1, 4], dg[1, 5] = -1.0, s * g5, sb * c * g5, sb * s
    out[2] = -g[SB] - sn * s * g5
    dg[2, SB], dk[2, SN], dk[2, 4], dg[2, 5] = -1.0, -s * g5, -sn * c * g5, -sn * s
    out[6] = ei * c * g5 - mn
    dk[6, 4], dg[6, 5], dk[6, MN] = -ei * s * g5, ei * c, -1.0
    out[7] = ei * g4 - mb
    dg[7, 4], dk[7, MB] = ei, -1.0
    out[8] = g[MN] - mb * s * g5 - stretch * sb
    dg[8, MN], dk[8, MB], dk[8, 4], dg[8, 5] = 1.0, -s * g5, -mb * c * g5, -mb * s
    dk[8, SB], dk[8, 0] = -stretch, -flex * sb
    out[9] = g[MB] + mn * s * g5 + stretch * sn
    dg[9, MB], dk[9, MN], dk[9, 4], dg[9, 5] = 1.0, s * g5, mn * c * g5, mn * s
    dk[9, SN], dk[9, 0] = stretch, flex * sn


@kernel
def assemble3_bending(x, step, res, band):
    """Residual (10(N+1),) and banded Jacobian (29, 10(N+1)) of one step at unknowns ``x`` (N+1, 10).

    Arguments as :func:`kanat.continuum.rows3d.assemble3` (``step`` a :class:`kernels3d.SpatialStep`);
    its ``start``, ``end`` with the clamp entries (:data:`NBPAR3_BENDING`).
    """
    _assemble_bending(x, step, res, band, step.extras)


@inner
def _assemble_bending(x, step, res, band, extras):
    """:func:`assemble3_bending`, with the record's ``extras`` an argument of its own (pruned by type)."""
    y, d, P = step.previous, step.rate, step.intervals
    n = x.shape[0]
    x6, y6, d6 = np.empty((n, 6)), np.empty((n, 6)), np.empty((n, 6))
    for j in range(n):
        for i in range(6):
            x6[j, i], y6[j, i], d6[j, i] = x[j, i], y[j, i], d[j, i]
    res6, band6 = np.empty(6 * n), np.empty((2 * k3.UPPER + 1, 6 * n))
    flexible_rows(x6, y6, d6, step, res6, band6, extras)
    band[:, :] = 0.0
    for r in range(res.shape[0]):
        res[r] = 0.0
    for j in range(n - 1):                              # the flexible interval rows, moved
        for i in range(6):
            r6, r10 = 3 + 6 * j + i, 5 + NV * j + i
            res[r10] = res6[r6]
            for side in range(2):
                node = j + side
                for q in range(6):
                    c6, c10 = 6 * node + q, NV * node + q
                    band[WIDTH + r10 - c10, c10] = band6[k3.UPPER + r6 - c6, c6]
    p = P[0]
    am, ak, gamma, dt = p[k.AM], p[k.AK], p[k.GAMMA], p[k.DT]
    wk = np.empty((n, NV))
    for j in range(n):
        for i in range(NV):
            wk[j, i] = (1.0 - ak) * x[j, i] + ak * y[j, i]
    kb, g, out = np.empty(NV), np.empty(NV), np.empty(NV)
    dk, dg = np.empty((NV, NV)), np.empty((NV, NV))
    for j in range(n - 1):
        if P[j, k.KIND] == k.JUNCTION:
            _junction_bending(j, x, wk, P[j], res, band)
        else:
            _interval_bending(j, wk, P[j], kb, g, out, dk, dg, res, band)
    _ends_bending(x, step, res, band, extras)


@inner
def _interval_bending(j, wk, p, kb, g, out, dk, dg, res, band):
    """Add the bending terms of cable interval ``j`` and their derivatives (``kb``... work space)."""
    ds, ck = p[k.DS], 1.0 - p[k.AK]
    for i in range(NV):
        kb[i] = 0.5 * (wk[j, i] + wk[j + 1, i])
        g[i] = (wk[j + 1, i] - wk[j, i]) / ds
    bending_terms(kb, g, p, out, dk, dg)
    row = 5 + NV * j
    for i in range(NV):
        res[row + i] += out[i]
    for side in range(2):
        node = j + side
        sign = -1.0 if side == 0 else 1.0
        for q in range(NV):
            col = NV * node + q
            for i in range(NV):
                band[WIDTH + row + i - col, col] += (0.5 * dk[i, q] + sign / ds * dg[i, q]) * ck


@inner
def _shear_vector(y, e, out, dv):
    """``S = S_n n + S_b b`` (chart, into ``out`` (3,)) of the state ``y`` with frame rows ``e`` (t, n, b),
    and ``dv[q] = dS/dy_q`` (10, 3): ``n_phi = -t``, ``n_theta = sin(phi) b``, ``b_theta = cos(phi) t - sin(phi) n``."""
    cp, sp = np.cos(y[4]), np.sin(y[4])
    sn, sb = y[SN], y[SB]
    for i in range(3):
        out[i] = sn * e[1, i] + sb * e[2, i]
        for q in range(NV):
            dv[q, i] = 0.0
        dv[SN, i], dv[SB, i] = e[1, i], e[2, i]
        dv[4, i] = -sn * e[0, i]
        dv[5, i] = sn * sp * e[2, i] + sb * (cp * e[0, i] - sp * e[1, i])


@inner
def _junction_bending(j, x, wk, p, res, band):
    """An inline body's rows with bending: the shear of both sides in its momentum (rows 3-5), and
    ``M = 0`` on its two nodes (rows 6-9, new level)."""
    a, b = j, j + 1
    row = 5 + NV * j
    ck = 1.0 - p[k.AK]
    e, shear, dv = np.empty((3, 3)), np.empty(3), np.empty((NV, 3))
    for side in range(2):
        node = a + side
        sign = -1.0 if side == 0 else 1.0               # force on the body: S_b - S_a
        k3._frame_rows(wk[node, 4], wk[node, 5], e)
        _shear_vector(wk[node], e, shear, dv)
        for i in range(3):
            res[row + 3 + i] -= sign * shear[i]
            for q in range(NV):
                col = NV * node + q
                band[WIDTH + row + 3 + i - col, col] -= sign * dv[q, i] * ck
    for i in range(4):
        node, q = (a, MN + i) if i < 2 else (b, MN + i - 2)
        res[row + 6 + i] = x[node, q]
        band[WIDTH + row + 6 + i - (NV * node + q), NV * node + q] = 1.0


@inner
def _ends_bending(x, step, res, band, extras):
    """The five rows of each end (module docstring) and their derivatives into ``res``, ``band``."""
    y, d, env, up, P, b0, b1 = step.previous, step.rate, step.water, step.vertical, step.intervals, step.start, step.end
    out, jac = np.empty(5), np.empty((5, NV))
    out3, jac3 = np.empty(3), np.empty((3, 6))
    last = x.shape[0] - 1
    for end in range(2):
        node, side, row = (0, -1.0, 0) if end == 0 else (last, 1.0, NV * last + 5)
        p = P[0] if end == 0 else P[last - 1]
        b = b0 if end == 0 else b1
        for i in range(5):
            out[i] = 0.0
            for q in range(NV):
                jac[i, q] = 0.0
        kind = int(b[k3.B3_KIND])
        if kind == k.FREE:
            for i in range(5):
                q = 0 if i == 0 else SN + i - 1
                out[i], jac[i, q] = x[node, q] / p[k.EA], 1.0 / p[k.EA]
        else:
            k3.end_jacobian3(x[node], y[node], d[node], env[node], up, p, b, side, out3, jac3, extras)
            for i in range(3):
                out[i] = out3[i]
                for q in range(6):
                    jac[i, q] = jac3[i, q]
            ak = p[k.AK]
            if kind != k.VELOCITY:                      # a body: -side S on it
                out[1] += side * ((1.0 - ak) * x[node, SN] + ak * y[node, SN])
                out[2] += side * ((1.0 - ak) * x[node, SB] + ak * y[node, SB])
                jac[1, SN], jac[2, SB] = side * (1.0 - ak), side * (1.0 - ak)
            if kind == k.VELOCITY and b[B3_CLAMP] != 0.0:
                out[3], jac[3, 4] = x[node, 4] - b[B3_PHI0], 1.0
                out[4], jac[4, 5] = x[node, 5] - b[B3_THETA0], 1.0
            else:
                out[3], jac[3, MN] = x[node, MN], 1.0
                out[4], jac[4, MB] = x[node, MB], 1.0
        for i in range(5):
            res[row + i] = out[i]
            for q in range(NV):
                band[WIDTH + row + i - (NV * node + q), NV * node + q] = jac[i, q]
