"""The discrete steady state of a cable resting on the seabed: Newton on the dense system.

In a time step a node's position is predicted from its own velocity, so seabed contact keeps
the Jacobian banded (:mod:`kanat.continuum.kernels2d`). In the steady state there is no step:
the positions are the integral of ``(1 + e) t`` from the first end (:func:`model2d.positions`),
so the contact force at a node depends on every state between it and the first end. Newton then
uses the full Jacobian

    J = J_band + (dR/dr) (dr/dx)     (solved as a low-rank update of the band: Woodbury's formula)

with ``J_band`` the kernels' banded Jacobian at frozen positions, ``dR/dr`` the residual's
derivative by the positions in the nodal data (one-sided finite differences towards lower
coordinates, into the seabed where contact acts; nodes of one parity at a time: an interval's
rows see one node of each parity), and ``dr/dx`` the positions' exact
derivative (dense, lower block-triangular). Only the positions the residual sees (nodes near
the seabed, a surface buoy) make columns of ``dR/dr``, so ``J`` is the band plus a product of rank
``k`` (their count times 3): one banded factorization with ``k`` right-hand sides and a ``k x k``
dense solve per iteration. A fixed far end held by its position replaces its velocity rows:
rows of the identity in the band, the position's derivative in the low-rank part. It runs once
per run, from the statics solution.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum.newton import MAX_ITERATIONS, TOLERANCE, NewtonFailure

POSITION_STEP = 1e-7      # m: finite-difference step on node positions (contact is linear in them)
MAX_ANGLE_STEP = 0.3      # rad: a Newton step turning any angle further is scaled down
MAX_DENSE_BYTES = 2 * 1024**3
"""Largest dense matrices (``dR/dr`` and ``dr/dx``) one steady iteration may hold [bytes]: both are
``n nv x n dim``, so a cable of 6,000 segments on the seabed would need 7 GB; it is refused
before they are allocated (the lumped model, or fewer segments, solves it)."""


def _pinning_rows(band: np.ndarray, width: int, rows: np.ndarray, columns: np.ndarray) -> np.ndarray:
    """``band`` with ``rows`` replaced by unit rows on ``columns`` (``row i`` -> ``x[columns[i]]``)."""
    out = band.copy()
    n = band.shape[1]
    for row, column in zip(rows, columns):
        for col in range(max(0, row - width), min(n, row + width + 1)):
            out[width + row - col, col] = 0.0
        out[width + row - column, column] = 1.0
    return out


def _position_sensitivity(residual, x, env, res, columns, nv: int) -> np.ndarray:
    """``dR/dr`` (n_rows, n_nodes * dim) by finite differences on the nodal positions."""
    n = len(x)
    dim = len(columns)
    out = np.zeros((x.size, n * dim))
    half = nv // 2
    for c, column in enumerate(columns):
        for parity in range(2):
            shifted = env.copy()
            shifted[parity::2, column] -= POSITION_STEP       # downwards: into the seabed, where contact acts
            change = (res - residual(x, shifted)[0]) / POSITION_STEP
            for node in range(parity, n, 2):
                low, high = max(0, half + nv * (node - 1)), min(x.size, half + nv * (node + 1))
                out[low:high, dim * node + c] = change[low:high]
    return out


def _woodbury(band, width, U, V, rhs):
    """Solve ``(B + U V) x = rhs`` with ``B`` banded: ``x = w - Z (I + V Z)^-1 V w``, ``w = B^-1 rhs``,
    ``Z = B^-1 U`` (one banded factorization, ``k`` columns of ``U``, a ``k x k`` dense solve)."""
    from scipy.linalg import solve_banded        # here: a run that never touches the seabed skips scipy.linalg

    solved = solve_banded((width, width), band, np.column_stack([rhs, U]), check_finite=False)
    w, Z = solved[:, 0], solved[:, 1:]
    small = np.eye(U.shape[1]) + V @ Z
    return w - Z @ np.linalg.solve(small, V @ w)


def steady_with_positions(guess, layout, columns, residual, derivative, scale, angles, width: int,
                          target=None, pinned=()) -> np.ndarray:
    """Newton's method on the steady rows with positions tied to the states (module docstring).

    Parameters
    ----------
    guess : ndarray, shape (n, nv)
    layout : callable
        ``layout(x) -> (env, r)``: nodal data holding the positions of ``x``, and the positions.
    columns : tuple of int
        The columns of ``env`` holding the position components.
    residual : callable
        ``residual(x, env) -> (res, band)`` (the kernels' assembly at those nodal data).
    derivative : callable
        ``derivative(x) -> D`` (n, dim, n nv): the positions' derivatives by the states.
    scale : ndarray, shape (nv,)
        Increment scales for the convergence test.
    angles : sequence of int
        The unknowns that are angles (a step is limited to :data:`MAX_ANGLE_STEP` in them).
    width : int
        Bandwidth of the banded Jacobian.
    target : ndarray or None
        The position of a fixed far end (an anchor), in the coordinates of ``layout``'s positions:
        its velocity rows are replaced by ``r_N(x) = target``. Without them a cable between two
        fixed points has no steady equation for where it ends (its velocities are zero for any
        shape), so its steady state would be a family.
    pinned : sequence of int
        With ``target``: the far node's unknowns (tension and angles) that span that family. The
        band is factorized with its far-end rows pinning them (so it is regular), and the
        target rows enter through the low-rank part.
    """
    x = guess.copy()
    n, nv = x.shape
    need = 2 * x.size * n * len(columns) * 8
    if need > MAX_DENSE_BYTES:
        raise NewtonFailure(f"the steady state on the seabed of {n - 1:,} segments needs {need / 1024**2:,.0f} MiB "
                            f"of dense matrices (more than {MAX_DENSE_BYTES / 1024**2:,.0f} MiB): use fewer "
                            "segments on the seabed part, or model: lumped", 0)
    angles = list(angles)
    scales = np.tile(scale, n)
    for iteration in range(1, 3 * MAX_ITERATIONS + 1):
        env, _ = layout(x)
        res, band = residual(x, env)
        if not np.all(np.isfinite(res)):
            raise NewtonFailure("the steady residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // nv))
        drdx = derivative(x).reshape(-1, x.size)
        sensitivity = _position_sensitivity(residual, x, env, res, columns, nv)
        used = np.flatnonzero(np.any(sensitivity != 0.0, axis=0))          # positions the residual sees
        U, V = sensitivity[:, used], drdx[used]
        if target is not None:                                             # the far end held by position
            rows = np.arange(x.size - nv // 2, x.size - nv // 2 + len(columns))
            weight = scale[0] / max(np.max(np.abs(target)), 1.0)
            res = res.copy()
            res[rows] = (layout(x)[1][-1] - target) * weight
            pins = nv * (n - 1) + np.asarray(pinned)
            band = _pinning_rows(band, width, rows, pins)     # J rows = pinning rows + (target - pinning)
            U = U.copy()
            U[rows] = 0.0
            picks = np.zeros((x.size, len(rows)))
            picks[rows, np.arange(len(rows))] = 1.0
            pinning = np.zeros((len(rows), x.size))
            pinning[np.arange(len(rows)), pins] = 1.0
            V = np.vstack([V, drdx[-len(columns):] * weight - pinning])
            U = np.column_stack([U, picks])
        try:
            dx = _woodbury(band, width, U, V, -res).reshape(x.shape)
        except (np.linalg.LinAlgError, ValueError):
            raise NewtonFailure("the steady Newton matrix is singular", int(np.argmax(np.abs(res)) // nv)) from None
        turn = np.max(np.abs(dx[:, angles])) if angles else 0.0
        if turn > MAX_ANGLE_STEP:
            dx *= MAX_ANGLE_STEP / turn
        x += dx
        if turn <= MAX_ANGLE_STEP and np.max(np.abs(dx.ravel()) / scales) < TOLERANCE:
            return x
    raise NewtonFailure(f"the steady state on the seabed did not converge in {3 * MAX_ITERATIONS} Newton "
                        "iterations", int(np.argmax(np.abs(res)) // nv))
