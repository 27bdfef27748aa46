"""Wave factorization (Kaliukh & Vusatiuk 2018, sections 2 and 4; theory/time-schemes.md §3): one step, block by block.

The rows of ``Y_t + B Y_s = D`` are split by wave type (:meth:`CableSystem.blocks`): planar
longitudinal ``(T, u)`` | transverse ``(v, phi)``; spatial longitudinal | normal ``(v, phi)`` |
binormal ``(w, theta)``, or longitudinal | both transverse. Sub-step ``k`` solves only its
block's rows for only its block's unknowns ``x``, the other unknowns ``o`` frozen at their
latest values and their coupling moved to the right-hand side (paper eqs. 23–24, 29):

    (E + dt gamma B_k Lambda) Y^{n+k/K} = dt D_k + Y^{n+(k-1)/K}

Discretization. ``Lambda`` is the compact central difference of the box method at interval
midpoints (the same two-node stencil as the full scheme, so the same ends and the same
steady state), weighted ``gamma`` on the new level (``gamma = 1/2``: Crank–Nicolson). On
interval ``j`` (nodes ``j-1, j``), with bars two-node means, ``Y^a = gamma Y^L + (1 - gamma) Y^n``
the gamma-level of the latest state ``Y^L`` and ``Bbar = Mbar^-1 Kbar``, ``Dbar = Mbar^-1 Fbar``
at ``Y^a``:

    (xbar - xbar^n)/dt + [Bbar (gamma dY_new + (1 - gamma) dY^n)]_k / ds
        = [Dbar + gamma/2 Mbar^-1 sum_nodes dF/dx (x - x^L)]_k,    dY_new = (dx, d o^L)

— quasi-linear: ``Bbar`` is frozen for the sub-step and the loads are linearized in the
block's own unknowns (drag stays implicit); one banded solve per block (bandwidth
``3/2 n_k``) instead of the full Newton system. Each end contributes one physical condition
per wave type (its component of :meth:`CableSystem.end_residual` along ``t``, ``n``, ``b``:
one incoming characteristic per block and end), gamma-weighted in time and linearized the
same way. ``iterations > 1`` repeats the block sequence with the coefficients refreshed,
which converges to the Crank–Nicolson box scheme.

The steady state of the full box equations satisfies every block exactly, so a steady tow
stays steady to round-off.
"""
from __future__ import annotations

import numpy as np
from scipy.linalg import solve_banded

from kanat.continuum.factorized.sweeps_compiled import line_data
from kanat.continuum.factorized.system import STEP
from kanat.continuum.stepper import NewtonFailure
from kanat.continuum.factorized.waves_compiled import assemble_block


def wave_factorized_step(world, Y, dt: float, block_count: int, gamma: float = 0.5, iterations: int = 1,
                         compiled: bool = True):
    """The new nodal states (N+1, d) after one wave-factorized step of ``dt`` from ``Y``.

    ``compiled`` assembles each block with :func:`.waves_compiled.assemble_block`;
    False uses the NumPy assembly here (the tests' twin).
    """
    system = world.system
    blocks = system.blocks(block_count)
    Fn = system.loads(Y, world.current, world.up)
    latest = Y.copy()
    if compiled:
        line = line_data(world)
    for _ in range(iterations):
        for index, block in enumerate(blocks):
            components = _end_components(index, len(blocks), system.dim)
            if compiled:
                band, rhs, lower, upper = assemble_block(
                    Y, latest, Fn, line, dt, gamma, np.array(block, dtype=np.int64),
                    np.array(components, dtype=np.int64))
                x = _solve(band, rhs, lower, upper).reshape(len(Y), len(block))
            else:
                x = _block_solve(world, Y, Fn, latest, dt, gamma, block, components)
            latest[:, block] = x
    if not np.all(np.isfinite(latest)):
        raise NewtonFailure("the wave-factorized step is not finite (NaN)",
                            int(np.argmax(~np.isfinite(latest).all(axis=1))))
    return latest


def _end_components(index: int, count: int, dim: int) -> tuple[int, ...]:
    """Components (along t, n, b) of the end conditions that belong to block ``index``."""
    if index == 0:
        return (0,)
    return tuple(range(1, dim)) if count == 2 else (index,)


def _block_solve(world, Yn, Fn, latest, dt, gamma, block, components):
    """Solve one block's banded system for its unknowns at all nodes, (N+1, nb)."""
    system, ds = world.system, world.ds
    n, _d = Yn.shape
    own = np.array(block)
    nb, h = len(block), len(components)
    Ya = gamma * latest + (1.0 - gamma) * Yn
    Ma, Ka = system.mass(Ya), system.stiffness(Ya)
    Mbar, Kbar = 0.5 * (Ma[1:] + Ma[:-1]), 0.5 * (Ka[1:] + Ka[:-1])
    Minv = np.linalg.inv(Mbar)
    Bbar = Minv @ Kbar
    FL = system.loads(latest, world.current, world.up)
    Fg = gamma * FL + (1.0 - gamma) * Fn
    Dbar = np.einsum("jab,jb->ja", Minv, 0.5 * (Fg[1:] + Fg[:-1]))
    J = _load_jacobian(system, latest, world, own)                       # (n, d, nb)
    Jl = 0.5 * gamma * Minv @ J[:-1]                                       # (N, d, nb)
    Jr = 0.5 * gamma * Minv @ J[1:]
    dYn = np.diff(Yn, axis=0)
    dYL = np.diff(latest, axis=0)
    dYL[:, own] = 0.0
    Bk = Bbar[:, own, :]                                                    # block rows (N, nb, d)
    Bkk = Bk[:, :, own]
    eye = np.eye(nb) / (2.0 * dt)
    left = eye - gamma * Bkk / ds - Jl[:, own, :]
    right = eye + gamma * Bkk / ds - Jr[:, own, :]
    xL, xn = latest[:, own], Yn[:, own]
    rhs = ((xn[:-1] + xn[1:]) / (2.0 * dt)
           - np.einsum("jab,jb->ja", Bk, (1.0 - gamma) * dYn + gamma * dYL) / ds
           + Dbar[:, own]
           - np.einsum("jab,jb->ja", Jl[:, own, :], xL[:-1]) - np.einsum("jab,jb->ja", Jr[:, own, :], xL[1:]))
    lower, upper = h + nb - 1, 2 * nb - 1 - h
    size = n * nb
    band = np.zeros((lower + upper + 1, size))
    b = np.empty(size)
    rows = h + nb * np.arange(n - 1)[:, None, None] + np.arange(nb)[None, :, None]      # (N, nb, 1)
    cols = nb * np.arange(n - 1)[:, None, None] + np.arange(nb)[None, None, :]           # (N, 1, nb)
    rows_b = np.broadcast_to(rows, (n - 1, nb, nb))
    band[upper + rows_b - cols, np.broadcast_to(cols, (n - 1, nb, nb))] = left
    band[upper + rows_b - cols - nb, np.broadcast_to(cols + nb, (n - 1, nb, nb))] = right
    b[h:h + nb * (n - 1)] = rhs.ravel()
    for side, node, row0 in ((-1.0, 0, 0), (1.0, n - 1, size - h)):
        coef, value = _end_rows(world, Yn, latest, dt, gamma, own, components, side, node)
        for i in range(h):
            for q in range(nb):
                col = nb * node + q
                band[upper + row0 + i - col, col] = coef[i, q]
            b[row0 + i] = value[i]
    return _solve(band, b, lower, upper).reshape(n, nb)


def _solve(band, rhs, lower, upper):
    try:
        return solve_banded((lower, upper), band, rhs, check_finite=False)
    except (np.linalg.LinAlgError, ValueError):
        raise NewtonFailure("the wave-factorized block is singular", 0) from None


def _load_jacobian(system, Y, world, own):
    """``dF/dY[:, :, own]`` (n, d, nb) by complex step."""
    n, d = Y.shape
    J = np.empty((n, d, len(own)))
    Z = Y.astype(complex)
    for c, q in enumerate(own):
        Z[:, q] += 1j * STEP
        J[:, :, c] = system.loads(Z, world.current, world.up).imag / STEP
        Z[:, q] = Y[:, q]
    return J


def _end_rows(world, Yn, latest, dt, gamma, own, components, side, node):
    """Linearized end conditions of one block: ``coef x = value`` (rows ``components``)."""
    system = world.system
    end = world.start if side < 0 else world.end
    nb = len(own)
    probe = np.zeros((nb + 1, Yn.shape[1]), dtype=complex)
    probe[1 + np.arange(nb), own] = 1j * STEP
    values = system.end_residual(end, side, latest[node][None, :] + probe, Yn[node], dt, gamma,
                                 world.current[node], world.up)[:, list(components)]
    coef = values[1:].imag.T / STEP
    return coef, coef @ latest[node, own] - values[0].real
