"""The block assembly of the wave-factorized step, compiled (numba).

The same banded system as :func:`kanat.continuum.factorized.waves._block_solve` builds with
NumPy (its readable twin; the tests compare the two): the gamma-weighted box rows of one
wave block at every interval and its linearized end conditions, in LAPACK band storage
for :func:`scipy.linalg.solve_banded`.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import kernel

from kanat import aot

from kanat.continuum.factorized.sweeps_compiled import (FactorizedLine, load_jacobian, lu_factor, lu_solve,
                                                       mass_stiffness, physical)

STEP = 1e-30


def assemble_block(Yn, latest, Fn, line, dt, gamma, own, comps):
    """Band (lower + upper + 1, n nb), right-hand side (n nb,) and bandwidths of one block.

    ``line`` is the cable's :class:`~.sweeps_compiled.FactorizedLine` (:func:`.sweeps_compiled.line_data`;
    a planar cable's ``vertical`` None: the kernel compiles its planar branches only).
    """
    block = aot.kernel("assemble_block")
    return block(Yn, latest, Fn, line, dt, gamma, own, comps)


aot.register("assemble_block", __name__, *((aot.F2, aot.F2, aot.F2, line, aot.FLOAT, aot.FLOAT, aot.I1, aot.I1)
                                           for line in (FactorizedLine.narrowed(vertical=None), FactorizedLine)),
             returns=(aot.F2, aot.F1, aot.INT, aot.INT), function="_assemble_block")     # planar and spatial


@kernel
def _assemble_block(Yn, latest, Fn, line, dt, gamma, own, comps):
    """:func:`assemble_block` compiled; nodal load derivatives written out, the ends' by complex step."""
    cur, up, p, dim, ds = line.current, line.vertical, line.parameters, line.dimensions, line.spacing
    par0, par1 = line.start, line.end
    n, d = Yn.shape
    nb, h = own.shape[0], comps.shape[0]
    lower, upper = h + nb - 1, 2 * nb - 1 - h
    size = n * nb
    band = np.empty((lower + upper + 1, size))
    rhs = np.empty(size)
    is_own = np.empty(d, dtype=np.int64)              # 1 for the block's own unknowns
    band[:, :] = 0.0
    rhs[:] = 0.0
    is_own[:] = 0
    for q in own:
        is_own[q] = 1
    Ms, Ks = np.empty((n, d, d)), np.empty((n, d, d))
    Fg = np.empty((n, d))
    J = np.empty((n, d, nb))
    ya, f, df = np.empty(d), np.empty(d), np.empty((d, d))
    z = np.empty(d, dtype=np.complex128)
    for i in range(n):
        for q in range(d):
            ya[q] = gamma * latest[i, q] + (1.0 - gamma) * Yn[i, q]
        mass_stiffness(ya, p, up, Ms[i], Ks[i])
        load_jacobian(latest[i], cur[i], up, p, f, df)
        for q in range(d):
            Fg[i, q] = gamma * f[q] + (1.0 - gamma) * Fn[i, q]
            for c in range(nb):
                J[i, q, c] = df[q, own[c]]
    Mbar, LU = np.empty((d, d)), np.empty((d, d))
    piv = np.empty(d, dtype=np.int64)
    col, sol = np.empty(d), np.empty(d)
    Bbar, Dbar = np.empty((d, d)), np.empty(d)
    Jl, Jr = np.empty((d, nb)), np.empty((d, nb))
    for j in range(n - 1):
        for a in range(d):
            for b in range(d):
                Mbar[a, b] = 0.5 * (Ms[j, a, b] + Ms[j + 1, a, b])
        lu_factor(Mbar, LU, piv)
        for b in range(d):
            for a in range(d):
                col[a] = 0.5 * (Ks[j, a, b] + Ks[j + 1, a, b])
            lu_solve(LU, piv, col, sol)
            for a in range(d):
                Bbar[a, b] = sol[a]
        for a in range(d):
            col[a] = 0.5 * (Fg[j, a] + Fg[j + 1, a])
        lu_solve(LU, piv, col, Dbar)
        for c in range(nb):
            for a in range(d):
                col[a] = 0.5 * gamma * J[j, a, c]
            lu_solve(LU, piv, col, sol)
            for a in range(d):
                Jl[a, c] = sol[a]
            for a in range(d):
                col[a] = 0.5 * gamma * J[j + 1, a, c]
            lu_solve(LU, piv, col, sol)
            for a in range(d):
                Jr[a, c] = sol[a]
        for ia in range(nb):
            a = own[ia]
            row = h + nb * j + ia
            value = (Yn[j, a] + Yn[j + 1, a]) / (2.0 * dt) + Dbar[a]
            for b in range(d):
                other = latest[j + 1, b] - latest[j, b] if is_own[b] == 0 else 0.0
                value -= Bbar[a, b] * ((1.0 - gamma) * (Yn[j + 1, b] - Yn[j, b]) + gamma * other) / ds
            for c in range(nb):
                value -= Jl[a, c] * latest[j, own[c]] + Jr[a, c] * latest[j + 1, own[c]]
                eye = 1.0 / (2.0 * dt) if c == ia else 0.0
                left = eye - gamma * Bbar[a, own[c]] / ds - Jl[a, c]
                right = eye + gamma * Bbar[a, own[c]] / ds - Jr[a, c]
                cl, cr = nb * j + c, nb * (j + 1) + c
                band[upper + row - cl, cl] = left
                band[upper + row - cr, cr] = right
            rhs[row] = value
    for side in (-1.0, 1.0):
        node = 0 if side < 0 else n - 1
        row0 = 0 if side < 0 else size - h
        par = par0 if side < 0 else par1
        out = np.empty(dim, dtype=np.complex128)
        base = np.empty(h)
        for c in range(-1, nb):
            for q in range(d):
                z[q] = latest[node, q]
            if c >= 0:
                z[own[c]] += 1j * STEP
            physical(z, Yn[node], par, side, dt, gamma, cur[node], up, p, dim, out)
            for i in range(h):
                if c < 0:
                    base[i] = out[comps[i]].real
                else:
                    coef = out[comps[i]].imag / STEP
                    colx = nb * node + c
                    band[upper + row0 + i - colx, colx] = coef
        for i in range(h):
            acc = -base[i]
            for c in range(nb):
                colx = nb * node + c
                acc += band[upper + row0 + i - colx, colx] * latest[node, own[c]]
            rhs[row0 + i] = acc
    return band, rhs, lower, upper
