"""Factorization by propagation direction (Kaliukh & Vusatiuk 2018, section 1; theory/time-schemes.md §2): one step.

Quasi-linearized on each step (``B = B(Y^n)``, ``D = D(Y^n)``), split by direction
(:mod:`kanat.continuum.factorized.characteristics`), and advanced with implicit upwind sweeps — the
"running count" of the paper, eqs. 9–11:

    (I + dt L+) Y^{n+1/2} = dt D^n + Y^n,   L+ Y = B+ (Y_i - Y_{i-1}) / ds,   i = 1 .. N-1 forward
    (I + dt L-) Y^{n+1}   = Y^{n+1/2},      L- Y = B- (Y_{i+1} - Y_i) / ds,   i = N-1 .. 1 backward

(the paper prints ``L-`` with the opposite sign, a misprint for the negative-speed upwind
difference). The four-factor variant (eqs. 12–15) sweeps ``B_1+`` forward, ``B_1-`` backward,
``B_2+`` forward and ``B_2-`` backward. Every sweep is an M-matrix recursion in the
characteristic variables of constant coefficients, so it is monotone and unconditionally
stable there; the scheme is first order in time and space, with a numerical viscosity
``c ds (1 + sigma) / 2`` per wave (docs/factorization.md measures what that costs).

Source. The paper takes ``D^n`` explicitly; with drag the explicit source limits the step
to ``dt < 2 / kappa`` with ``kappa = rho d C_n |v_r| / (m + m_a)`` (about 60 1/s for a 17 mm
tow cable at 3 m/s). ``implicit_source=True`` (default) linearizes it in the first sweep,
``D^n + J (Y^{n+1/2} - Y^n)`` with ``J = M^-1 dF/dY`` — still one dense solve per node.

Delta form. The paper's product acts on the states, so its steady state solves
``L Y - D + dt L+ L- Y = 0`` (and, with the linearized source, ``+ dt J L- Y``): the steady
tow it settles to depends on the step. ``delta=True`` sweeps the increment instead
(Beam & Warming's approximate factorization), ``(I + dt L+)(I + dt L-) dY = -dt (L Y^n - D^n)``,
whose steady state is the upwind discretization's whatever the step.

Ends. The inflow end of each sweep is solved first from its physical conditions and
outgoing characteristics with the latest neighbour (:func:`characteristics.end_state`); after
the last sweep both ends are solved again with the final neighbours.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum.factorized.characteristics import end_state, group_split
from kanat.continuum.stepper import NewtonFailure

TWO_SWEEPS = ((("l+", "t+"), True), (("l-", "t-"), False))
FOUR_SWEEPS = ((("l+",), True), (("l-",), False), (("t+",), True), (("t-",), False))
COMPRESSION = 1e-6          # |T| below this fraction of max T counts as slack (T = 0), not compression


def factorized_step(world, Y, dt: float, sweeps, implicit_source: bool = True, compiled: bool = True,
                    delta: bool = False):
    """The new nodal states (N+1, d) after one factorized step of ``dt`` from ``Y``.

    Parameters
    ----------
    world : kanat.continuum.factorized.system.World
    Y : ndarray, shape (N+1, d)
    sweeps : sequence of (tuple of str, bool)
        Parts of ``B`` (keys of :func:`characteristics.group_split`) and direction (True:
        forward) of each sweep: :data:`TWO_SWEEPS` or :data:`FOUR_SWEEPS`.
    implicit_source : bool
        Linearize ``D`` in the first sweep (module docstring).
    compiled : bool
        Run the whole step compiled (:mod:`.sweeps_compiled`); False runs this readable
        NumPy path (with the NumPy sweep), the tests' twin.
    delta : bool
        Sweep the increments ``Y^{n+1} - Y^n`` driven by the upwind residual (module docstring)
        instead of the paper's states.
    """
    system = world.system
    if compiled:
        return _compiled(world, Y, dt, sweeps, implicit_source, delta)
    _n, d = Y.shape
    B, D, M = system.characteristic_form(Y, world.current, world.up)
    c_l, c_t2 = system.speeds(Y)
    slack = max(np.max(np.abs(Y[:, 0])), 1.0) * COMPRESSION / system.normal_mass
    c_t2 = np.where((c_t2 < 0.0) & (c_t2 > -slack), 0.0, c_t2)
    parts = group_split(B, c_l, c_t2)
    sigma = dt / world.ds
    eye = np.eye(d)
    from kanat.continuum.factorized.dense import sweep_numpy as run      # numba's module: loaded when used
    offset = Y if delta else np.zeros_like(Y)        # X holds Y - offset: increments in delta form
    X = Y - offset
    if delta:
        residual = (np.einsum("nij,nj->ni", parts["l+"] + parts["t+"], Y - np.roll(Y, 1, axis=0))
                    + np.einsum("nij,nj->ni", parts["l-"] + parts["t-"], np.roll(Y, -1, axis=0) - Y)) / world.ds - D
    for index, (names, forward) in enumerate(sweeps):
        P = sum(parts[name] for name in names)
        sign = 1.0 if forward else -1.0
        A = eye + sign * sigma * P
        C = sign * sigma * P
        r = X.copy()
        if index == 0:
            r = -dt * residual if delta else r + dt * D
            if implicit_source:
                J = np.linalg.solve(M, system.load_jacobian(Y, world.current, world.up))
                A = A - dt * J
                if not delta:
                    r -= dt * np.einsum("nij,nj->ni", J, Y)
        if forward:
            X[0] = end_state(world, Y, -1.0, X[1] + offset[1], dt) - offset[0]
        else:
            X[-1] = end_state(world, Y, 1.0, X[-2] + offset[-2], dt) - offset[-1]
        X = run(A, C, r, X, forward)
    X = X + offset
    X[-1] = end_state(world, Y, 1.0, X[-2], dt)
    X[0] = end_state(world, Y, -1.0, X[1], dt)
    if not np.all(np.isfinite(X)):
        raise NewtonFailure("the factorized step is not finite (NaN)", int(np.argmax(~np.isfinite(X).all(axis=1))))
    return X


def _compiled(world, Y, dt, sweeps, implicit_source, delta):
    from kanat.continuum.factorized.sweeps_compiled import MESSAGES, OK, factorized_step_compiled, line_data

    system = world.system
    slack = max(np.max(np.abs(Y[:, 0])), 1.0) * COMPRESSION / system.normal_mass
    four = len(sweeps) == 4
    X, status, node = factorized_step_compiled(np.ascontiguousarray(Y, dtype=float), line_data(world), dt, four,
                                               implicit_source, slack, delta)
    if status != OK:
        raise NewtonFailure(MESSAGES[status], int(node))
    return X
