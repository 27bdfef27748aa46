"""Characteristics of the cable equations: the split of ``B`` by wave and direction, and the ends.

Splitting ``B`` (Kaliukh & Vusatiuk 2018, eqs. 3–7, 12–13; theory/time-schemes.md §2)
----------------------------------------------------
With ``Y_t + B Y_s = D``, ``B = M^-1 K``, the planar ``B`` is block upper triangular in
``((T, u), (v, phi))`` and its eigenvalues are, exactly,

    +-c_l = +-sqrt(EA / m)                           (longitudinal)
    +-c_t = +-sqrt(T / ((m + m_a)(1 + e)))            (transverse; double in 3-D)

``B`` is diagonalizable and its minimal polynomial is ``(B^2 - c_l^2)(B^2 - c_t^2)`` (in 3-D
too, where the transverse pair is double), so every spectral function of ``B`` is a
polynomial in ``B`` and the eigen-decomposition ``B = N K N^-1`` never has to be formed:

    R = (B^2 - c_t^2 I) / (c_l^2 - c_t^2)       projector on the longitudinal waves
    Q = I - R                                  projector on the transverse waves
    B_1+- = R (B +- c_l I) / 2                 = N K_1+- N^-1   (eq. 13)
    B_2+- = Q (B +- c_t I) / 2                 = N K_2+- N^-1
    B+ = B_1+ + B_2+,  B- = B_1- + B_2-        (eq. 7),  B+ + B- = B

``B_2+-`` stay finite as ``T -> 0`` (``c_t -> 0``: a free end). The closed form needs
``c_l != c_t`` and ``T >= 0``; :func:`split_numerical` does the same with
``numpy.linalg.eig`` (the tests' oracle, and the fallback for a matrix of another structure).

Ends through characteristics (theory/continuum.md §3, theory/time-schemes.md §2)
----------------------------------------------
At an end, the characteristics with speeds pointing *into* the cable carry what the end
imposes; the others leave the cable and carry the interior's information out. At ``s = 0``
the incoming ones are ``+c_l, +c_t``, at ``s = L`` ``-c_l, -c_t`` — ``dim`` of each at each end
(2 planar, 3 spatial), so each end takes ``dim`` physical conditions and ``dim``
compatibility relations of its outgoing characteristics, with one-sided differences into
the cable (``side = -1`` at ``s = 0``, ``+1`` at ``s = L``; node ``e`` the end, ``i`` its neighbour):

    l_k . [ (Y_e - Y_e^n)/dt + lambda_k side (Y_e - Y_i)/ds - D(Y_e) ] = 0,   k outgoing

``l_k`` are the left eigenvectors of ``B(Y_e^n)`` (rows spanning the row space of the outgoing
projector ``(I - side sign(B))/2``, ``sign(B) = R B / c_l + Q B / c_t``); ``l_k B = lambda_k l_k``
lets the relation be written with ``B``. The physical conditions
(:meth:`CableSystem.end_residual`, backward Euler in time):

    tow point, anchor     u = V.t,  v = V.n  (, w = V.b)                     (incoming: +-c_l, +-c_t)
    towed body            M_b dV/dt = -side T t + B_b z + 0.5 rho C_D S |U_r| U_r + F_ext
                          in its t, n (, b) components (Kaliukh & Vusatiuk 2018, eq. 26 with its depressor force)
    free end              T = 0 for the incoming longitudinal wave, and, since ``c_t = 0`` where
                          ``T = 0`` (the transverse characteristics stand still), the transverse
                          momentum ``(m + m_a) a.n = f.n`` (, ``a.b = f.b``) and the rotation
                          compatibility rows of ``M Y_t + K Y_s = F`` one-sided; the outgoing
                          longitudinal relation ``lambda = +c_l`` completes the ``2 dim`` rows.

Each end is ``2 dim`` nonlinear equations in the ``2 dim`` unknowns of its node, solved by
Newton with a complex-step Jacobian (:func:`solve_end`).
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.stepper import NewtonFailure

STEP = 1e-30
END_ITERATIONS = 30
END_TOLERANCE = 1e-11


def group_split(B, c_l, c_t2):
    """The four wave–direction parts of ``B`` (closed form; module docstring).

    Parameters
    ----------
    B : ndarray, shape (n, d, d)
    c_l : float or ndarray
        Longitudinal speed [m/s].
    c_t2 : ndarray, shape (n,)
        Transverse speed squared [m^2/s^2], >= 0.

    Returns
    -------
    dict
        ``{"l+", "l-", "t+", "t-"}`` -> (n, d, d): ``B_1+, B_1-, B_2+, B_2-`` of Kaliukh & Vusatiuk 2018, eq. 13.
    """
    n, d, _ = B.shape
    c_l = np.broadcast_to(np.asarray(c_l, dtype=float), (n,))
    c_t2 = np.asarray(c_t2, dtype=float)
    if np.any(c_t2 < 0.0):
        worst = int(np.argmin(c_t2))
        raise NewtonFailure("the cable is in compression, where the transverse characteristics are "
                            "complex and the split by direction does not exist", worst)
    c_t = np.sqrt(c_t2)
    eye = np.eye(d)
    B2 = B @ B
    R = (B2 - c_t2[:, None, None] * eye) / (c_l ** 2 - c_t2)[:, None, None]
    Q = eye - R
    cl, ct = c_l[:, None, None] * eye, c_t[:, None, None] * eye
    return {"l+": 0.5 * R @ (B + cl), "l-": 0.5 * R @ (B - cl),
            "t+": 0.5 * Q @ (B + ct), "t-": 0.5 * Q @ (B - ct)}


def direction_split(B, c_l, c_t2):
    """``(B+, B-)`` (each (n, d, d)): Kaliukh & Vusatiuk 2018, eq. 7, closed form."""
    parts = group_split(B, c_l, c_t2)
    return parts["l+"] + parts["t+"], parts["l-"] + parts["t-"]


def split_numerical(B, tol: float = 1e-9):
    """``(B+, B-)`` from ``numpy.linalg.eig`` (n, d, d): ``N K+- N^-1`` with the real parts of eigenvalues.

    Eigenvalues within ``tol`` (relative) of zero are given to neither part.
    """
    values, vectors = np.linalg.eig(B)
    scale = np.max(np.abs(values), axis=1, keepdims=True)
    lam = values.real
    plus = np.where(lam > tol * scale, lam, 0.0)
    minus = np.where(lam < -tol * scale, lam, 0.0)
    inverse = np.linalg.inv(vectors)
    make = lambda part: np.real(vectors @ (part[:, :, None] * inverse))
    return make(plus), make(minus)


def outgoing_rows(B, c_l, c_t2, side: float, transverse: bool = True):
    """Left eigenvectors of the characteristics leaving the cable at an end (rows, (m, d)).

    ``B`` (d, d) at the end node; ``side`` -1 at ``s = 0`` (outgoing: negative speeds), +1 at
    ``s = L`` (positive). ``transverse=False`` keeps only the longitudinal one (free end).
    The rows are an orthonormal basis of the row space of the outgoing projector.
    """
    parts = group_split(B[None], c_l, np.array([c_t2]))
    sign = "+" if side > 0 else "-"
    c_t = np.sqrt(c_t2)
    projector = parts["l" + sign][0] / (side * c_l)
    count = 1
    if transverse:
        projector = projector + parts["t" + sign][0] / (side * c_t)
        count = len(B) // 2
    _, _, vt = np.linalg.svd(projector)
    return vt[:count]


def solve_end(residual, x0, scale, node: int):
    """Newton on ``residual(x) = 0`` for one end node (complex-step Jacobian).

    Parameters
    ----------
    residual : callable
        Batch of candidates ``(b, d) -> (b, d)``, complex-safe; one call per iteration
        evaluates the residual and its ``d`` directional derivatives.
    x0 : ndarray, shape (d,)
        Start (the end's old state).
    scale : ndarray, shape (d,)
        Sizes of the unknowns for the convergence test.
    node : int
        Node index for the failure message.
    """
    x = np.array(x0, dtype=float)
    d = len(x)
    probe = np.vstack([np.zeros(d), np.eye(d)]) * (1j * STEP)
    for _ in range(END_ITERATIONS):
        values = residual(x[None, :] + probe)
        res, jac = values[0].real, values[1:].imag.T / STEP
        try:
            dx = np.linalg.solve(jac, -res)
        except np.linalg.LinAlgError:
            raise NewtonFailure("the end conditions are singular", node) from None
        x += dx
        if not np.all(np.isfinite(x)):
            raise NewtonFailure("the end state is not finite (NaN)", node)
        if np.max(np.abs(dx) / scale) < END_TOLERANCE:
            return x
    raise NewtonFailure(f"the end conditions did not converge in {END_ITERATIONS} iterations", node)


def end_state(world, Y, side: float, neighbour, dt: float):
    """The new state of one end node from its physical conditions and outgoing characteristics.

    Parameters
    ----------
    world : kanat.continuum.factorized.system.World
    Y : ndarray, shape (N+1, d)
        The old state (``Y^n``).
    side : float
        -1 for ``s = 0``, +1 for ``s = L``.
    neighbour : ndarray, shape (d,)
        The latest state of the node next to the end (used implicitly in the one-sided difference).
    dt : float

    Returns
    -------
    ndarray, shape (d,)
    """
    system = world.system
    e = 0 if side < 0 else len(Y) - 1
    end = world.start if side < 0 else world.end
    old = Y[e]
    current, up, ds, dim = world.current[e], world.up, world.ds, system.dim
    B, _, M = system.characteristic_form(old[None], current[None], up)
    B, M = B[0], M[0]
    Minv_T = np.linalg.inv(M).T
    c_l, c_t2 = system.speeds(old[None])
    free = end.kind == k.FREE
    rows = outgoing_rows(B, c_l, max(c_t2[0], 0.0), side, transverse=not free)
    K_old = system.stiffness(old[None])[0]
    cur = np.broadcast_to(current, (len(old) + 1, dim))

    def residual(x):
        physical = system.end_residual(end, side, x, old, dt, 1.0, current, up)
        F = system.loads(x, cur[:len(x)], up)
        gradient = side * (x - neighbour) / ds
        compat = ((x - old) / dt + gradient @ B.T - F @ Minv_T) @ rows.T
        parts = [physical, compat]
        if free:
            kinematic = (x - old) @ M.T / dt + gradient @ K_old.T - F
            parts.append(kinematic[:, dim + 1:])
        return np.concatenate(parts, axis=1)

    tension = max(np.max(np.abs(Y[:, 0])), 1.0)
    speed = max(np.max(np.abs(Y[:, 1:1 + dim])), 1.0)
    scale = np.array([tension] + [speed] * dim + [1.0] * (dim - 1))
    return solve_end(residual, old, scale, e)
