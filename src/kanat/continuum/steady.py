"""The discrete steady state of a cable resting on the seabed: Newton on the dense system.

In a time step a node's position is predicted from its own velocity, so seabed contact keeps
the Jacobian banded (:mod:`kanat.continuum.kernels2d`). In the steady state there is no step:
the positions are the integral of ``(1 + e) t`` from the first end (:func:`model2d.positions`),
so the contact force at a node depends on every state between it and the first end. Newton then
uses the full Jacobian

    J = J_band + (dR/dr) (dr/dx)

with ``J_band`` the kernels' banded Jacobian at frozen positions, ``dR/dr`` the residual's
derivative by the positions in the nodal data (one-sided finite differences towards lower
coordinates, into the seabed where contact acts; nodes of one parity at a time: an interval's
rows see one node of each parity), and ``dr/dx`` the positions' exact
derivative (dense, lower block-triangular). It runs once per run, from the statics solution,
and costs a dense solve per iteration (0.1 s at 300 nodes).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum.stepper import MAX_ITERATIONS, TOLERANCE, NewtonFailure

POSITION_STEP = 1e-7      # m: finite-difference step on node positions (contact is linear in them)
MAX_ANGLE_STEP = 0.3      # rad: a Newton step turning any angle further is scaled down


def _band_to_dense(band: np.ndarray, width: int) -> np.ndarray:
    n = band.shape[1]
    dense = np.zeros((n, n))
    for offset in range(-width, width + 1):          # band[width + row - col, col]
        cols = np.arange(max(0, -offset), min(n, n - offset))
        dense[cols + offset, cols] = band[width + offset, cols]
    return dense


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


def steady_with_positions(guess, layout, columns, residual, derivative, scale, angles, width: int,
                          target=None) -> np.ndarray:
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
    """
    x = guess.copy()
    n, nv = x.shape
    angles = list(angles)
    scales = np.tile(scale, n)
    for iteration in range(1, 3 * MAX_ITERATIONS + 1):
        env, _ = layout(x)
        res, band = residual(x, env)
        if not np.all(np.isfinite(res)):
            raise NewtonFailure("the steady residual is not finite (NaN)", int(np.argmax(~np.isfinite(res)) // nv))
        dense = _band_to_dense(band, width)
        drdx = derivative(x)
        dense += _position_sensitivity(residual, x, env, res, columns, nv) @ drdx.reshape(-1, x.size)
        if target is not None:
            rows = slice(x.size - nv // 2, x.size - nv // 2 + len(columns))
            res = res.copy()
            res[rows] = (layout(x)[1][-1] - target) * scale[0] / max(np.max(np.abs(target)), 1.0)
            dense[rows] = drdx[-1] * scale[0] / max(np.max(np.abs(target)), 1.0)
        try:
            dx = np.linalg.solve(dense, -res).reshape(x.shape)
        except np.linalg.LinAlgError:
            raise NewtonFailure("the steady Newton matrix is singular", int(np.argmax(np.abs(res)) // nv)) from None
        turn = np.max(np.abs(dx[:, angles])) if angles else 0.0
        if turn > MAX_ANGLE_STEP:
            dx *= MAX_ANGLE_STEP / turn
        x += dx
        if turn <= MAX_ANGLE_STEP and np.max(np.abs(dx.ravel()) / scales) < TOLERANCE:
            return x
    raise NewtonFailure(f"the steady state on the seabed did not converge in {3 * MAX_ITERATIONS} Newton "
                        "iterations", int(np.argmax(np.abs(res)) // nv))
