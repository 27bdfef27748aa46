"""The cable equations in the form the factorized schemes work on: ``Y_t + B(Y) Y_s = D(Y)``.

Kaliukh & Vusatiuk 2018 (eq. 1) writes the continuum cable as ``E W_t + B W_s = D`` with ``E`` the identity:
``B = M^-1 K`` and ``D = M^-1 F`` from the matrix form ``M Y_t + K Y_s = F`` of theory/continuum.md §1
(planar, ``Y = (T, u, v, phi)``) and §2.2 (spatial, ``Y = (T, u, v, w, phi, theta)``). Rows of
``B`` belong to unknowns, so the rows of one wave type are the rows of its unknowns:

    planar   longitudinal (T, u) = rows 0, 1      transverse (v, phi) = rows 2, 3
    spatial  longitudinal (T, u) = rows 0, 1      normal (v, phi) = rows 2, 4
                                                  binormal (w, theta) = rows 3, 5

Everything here is vectorized over nodes (arrays of shape (n, d) and (n, d, d), ``d = 2 dim``)
and *complex-safe* (``|x| x`` written ``x sqrt(x x)``) so the schemes differentiate loads and
end conditions by complex step. The spatial matrices are the rows of
:mod:`kanat.continuum.kernels3d` written as arrays; tests compare the two.

:class:`World` is what one step needs of the outside: the parameters, the current and the
vertical in the frame's coordinates, and both ends' physical data at the new time level. The
planar and the spatial models give it (``model.world(state, dt)``) and turn the new unknowns
back into a state (``model.advanced(state, start, y, chart, dt)``), so the schemes never ask
which model they step.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kanat.continuum import kernels2d as k

STEP = 1e-30                      # complex-step size
LONGITUDINAL = (0, 1)


@dataclass(frozen=True)
class EndData:
    """One end at the new time level, vectors in the frame's coordinates.

    Attributes
    ----------
    kind : int
        ``kernels2d.VELOCITY``, ``BODY`` or ``FREE``.
    velocity : ndarray, shape (dim,)
        Prescribed velocity [m/s] (kind velocity).
    mass : float
        Body mass plus added mass [kg].
    net_buoyancy : float
        [N], along the vertical.
    half_rho_cds : float
        ``0.5 rho C_D S`` [kg/m].
    force : ndarray, shape (dim,)
        Constant external force [N].
    """

    kind: int
    velocity: np.ndarray
    mass: float = 0.0
    net_buoyancy: float = 0.0
    half_rho_cds: float = 0.0
    force: np.ndarray | None = None


class CableSystem:
    """``M``, ``K``, ``F``, ``B``, ``D`` and the frame of a planar (dim 2) or spatial (dim 3) cable.

    Parameters
    ----------
    params : ndarray, shape (kernels2d.NPAR,)
    dim : {2, 3}
    """

    def __init__(self, params: np.ndarray, dim: int):
        self.p = params
        self.dim = dim
        self.nvar = 2 * dim
        self.mass_per_length = params[k.M]
        self.normal_mass = params[k.M] + params[k.MA]
        self.stiffness_axial = params[k.EA]

    # -- wave groups --------------------------------------------------------------------------
    def blocks(self, count: int) -> list[tuple[int, ...]]:
        """Unknown indices of each wave block: 2 (longitudinal | transverse) or 3 (spatial only)."""
        if self.dim == 2:
            if count != 2:
                raise ValueError("the planar cable has two wave types (longitudinal | transverse)")
            return [(0, 1), (2, 3)]
        if count == 2:
            return [(0, 1), (2, 3, 4, 5)]
        return [(0, 1), (2, 4), (3, 5)]

    # -- frame and kinematics -----------------------------------------------------------------
    def frame(self, Y) -> list:
        """Unit vectors ``[t, n]`` (planar) or ``[t, n, b]`` (spatial), each (n, dim), frame coordinates."""
        phi = Y[:, 4] if self.dim == 3 else Y[:, 3]
        cp, sp = np.cos(phi), np.sin(phi)
        if self.dim == 2:
            return [np.stack([cp, sp], axis=-1), np.stack([-sp, cp], axis=-1)]
        ct, st = np.cos(Y[:, 5]), np.sin(Y[:, 5])
        return [np.stack([cp * ct, cp * st, sp], axis=-1), np.stack([-sp * ct, -sp * st, cp], axis=-1),
                np.stack([st, -ct, 0.0 * st], axis=-1)]

    def velocity(self, Y):
        """Cable velocity ``u t + v n (+ w b)`` (n, dim)."""
        axes = self.frame(Y)
        return sum(Y[:, 1 + i, None] * axes[i] for i in range(self.dim))

    def speeds(self, Y):
        """Longitudinal speed (scalar) and transverse speed squared (n,) ``T / ((m + m_a)(1 + e))``."""
        T = Y[:, 0].real
        return np.sqrt(self.stiffness_axial / self.mass_per_length), T / (
            self.normal_mass * (1.0 + T / self.stiffness_axial))

    # -- the matrix form ----------------------------------------------------------------------
    def mass(self, Y):
        """``M(Y)`` (n, d, d) (theory/continuum.md §1–2)."""
        m, mn, ea = self.mass_per_length, self.normal_mass, self.stiffness_axial
        n = len(Y)
        M = np.zeros((n, self.nvar, self.nvar), dtype=Y.dtype)
        if self.dim == 2:
            T, u, v = Y[:, 0], Y[:, 1], Y[:, 2]
            M[:, 0, 1], M[:, 0, 3] = m, -m * v
            M[:, 1, 2], M[:, 1, 3] = mn, mn * u
            M[:, 2, 0] = 1.0 / ea
            M[:, 3, 3] = 1.0 + T / ea
            return M
        T, u, v, w, phi = Y[:, 0], Y[:, 1], Y[:, 2], Y[:, 3], Y[:, 4]
        cp, sp = np.cos(phi), np.sin(phi)
        M[:, 0, 1], M[:, 0, 4], M[:, 0, 5] = m, -m * v, m * w * cp
        M[:, 1, 2], M[:, 1, 4], M[:, 1, 5] = mn, mn * u, -mn * w * sp
        M[:, 2, 3], M[:, 2, 5] = mn, mn * (-u * cp + v * sp)
        M[:, 3, 0] = 1.0 / ea
        M[:, 4, 4] = 1.0 + T / ea
        M[:, 5, 5] = -(1.0 + T / ea) * cp
        return M

    def stiffness(self, Y):
        """``K(Y)`` (n, d, d)."""
        n = len(Y)
        K = np.zeros((n, self.nvar, self.nvar), dtype=Y.dtype)
        if self.dim == 2:
            T, u, v = Y[:, 0], Y[:, 1], Y[:, 2]
            K[:, 0, 0] = -1.0
            K[:, 1, 3] = -T
            K[:, 2, 1], K[:, 2, 3] = -1.0, v
            K[:, 3, 2], K[:, 3, 3] = -1.0, -u
            return K
        T, u, v, w, phi = Y[:, 0], Y[:, 1], Y[:, 2], Y[:, 3], Y[:, 4]
        cp, sp = np.cos(phi), np.sin(phi)
        K[:, 0, 0] = -1.0
        K[:, 1, 4] = -T
        K[:, 2, 5] = T * cp
        K[:, 3, 1], K[:, 3, 4], K[:, 3, 5] = -1.0, v, -w * cp
        K[:, 4, 2], K[:, 4, 4], K[:, 4, 5] = -1.0, -u, w * sp
        K[:, 5, 3], K[:, 5, 5] = -1.0, u * cp - v * sp
        return K

    def load_vector(self, Y, current, up):
        """Components ``[f_t, f_n (, f_b)]`` (each (n,)) of the distributed load per unstretched length.

        Weight in water and drag of the relative flow (theory/continuum.md §1–2): the tangential drag
        on ``pi d C_t``, the normal one from the normal relative speed ``sqrt(v_r^2 + w_r^2)``.
        """
        p = self.p
        axes = self.frame(Y)
        root = np.sqrt(1.0 + Y[:, 0] / p[k.EA])
        rel = [Y[:, 1 + i] - np.sum(current * axes[i], axis=1) for i in range(self.dim)]
        tangential = 0.5 * p[k.RHO] * np.pi * p[k.DIAM] * p[k.CT] * rel[0] * np.sqrt(rel[0] * rel[0]) * root
        normal_speed = np.sqrt(sum(r * r for r in rel[1:]))
        normal = 0.5 * p[k.RHO] * p[k.DIAM] * p[k.CN] * normal_speed * root
        weight = -p[k.W0] * up
        comps = [np.sum(weight * axes[0], axis=1) - tangential]
        comps += [np.sum(weight * axes[i], axis=1) - normal * rel[i] for i in range(1, self.dim)]
        return comps

    def loads(self, Y, current, up):
        """``F(Y)`` (n, d): the load components on the momentum rows, zero on the others."""
        F = np.zeros(Y.shape, dtype=Y.dtype)
        for i, comp in enumerate(self.load_vector(Y, current, up)):
            F[:, i] = comp
        return F

    def load_jacobian(self, Y, current, up):
        """``dF/dY`` (n, d, d) by complex step (node by node, all nodes at once)."""
        n, d = Y.shape
        J = np.zeros((n, d, d))
        Z = Y.astype(complex)
        for q in range(d):
            Z[:, q] += 1j * STEP
            J[:, :, q] = self.loads(Z, current, up).imag / STEP
            Z[:, q] = Y[:, q]
        return J

    def characteristic_form(self, Y, current, up):
        """``(B, D, M)`` at the nodes: ``B = M^-1 K`` (n, d, d), ``D = M^-1 F`` (n, d), ``M``."""
        M = self.mass(Y)
        B = np.linalg.solve(M, self.stiffness(Y))
        D = np.linalg.solve(M, self.loads(Y, current, up)[..., None])[..., 0]
        return B, D, M

    # -- ends ---------------------------------------------------------------------------------
    def end_residual(self, end: EndData, side: float, Y, Yold, dt: float, gamma: float, current, up):
        """The ``dim`` physical conditions of one end (theory/continuum.md §3) for a batch of candidate states.

        ``Y`` (b, d) candidate new states of the end node (complex allowed), ``Yold`` (d,) its
        old state; ``side`` -1 at ``s = 0``, +1 at ``s = L``; the body and free-end momentum
        balances are ``gamma``-weighted in time (``gamma = 1``: backward Euler). Returns (b, dim),
        components along each candidate's frame ``(t, n, b)``:

        - velocity: ``u - V.t, v - V.n (, w - V.b)``;
        - body: ``M_b (V - V_old)/dt - [gamma G(Y) + (1 - gamma) G(Y_old)]`` with
          ``G = -side T t + B_b z + 0.5 rho C_D S |U_r| U_r + F_ext``, ``U_r`` water relative to the body;
        - free: ``T / EA`` and the transverse components of the node's momentum balance
          ``(m + m_a) (V - V_old)/dt - [gamma f(Y) + (1 - gamma) f(Y_old)]``.
        """
        axes = self.frame(Y)
        dot = lambda a, b: np.sum(a * b, axis=-1)
        if end.kind == k.VELOCITY:
            return np.stack([Y[:, 1 + i] - dot(axes[i], end.velocity) for i in range(self.dim)], axis=-1)
        old = Yold[None, :]
        V, Vold = self.velocity(Y), self.velocity(old)
        if end.kind == k.FREE:
            cur = current[None, :]
            load = sum(c[:, None] * a for c, a in zip(self.load_vector(Y, cur, up), axes))
            load_old = sum(c[:, None] * a for c, a in zip(self.load_vector(old, cur, up), self.frame(old)))
            balance = self.normal_mass * (V - Vold) / dt - gamma * load - (1.0 - gamma) * load_old
            return np.stack([Y[:, 0] / self.stiffness_axial] + [dot(balance, axes[i]) for i in range(1, self.dim)],
                            axis=-1)

        def force(Z, vel, tangent):
            rel = current - vel
            speed = np.sqrt(np.sum(rel * rel, axis=-1))[:, None]
            return (-side * Z[:, 0, None] * tangent + end.net_buoyancy * up + end.half_rho_cds * speed * rel
                    + end.force)

        balance = (end.mass * (V - Vold) / dt - gamma * force(Y, V, axes[0])
                   - (1.0 - gamma) * force(old, Vold, self.frame(old)[0]))
        return np.stack([dot(balance, axes[i]) for i in range(self.dim)], axis=-1)


@dataclass(frozen=True)
class World:
    """What one step of a continuum scheme needs from the model, at the new time level.

    Attributes
    ----------
    system : CableSystem
    current : ndarray, shape (N+1, dim)
        Current at the nodes (frame coordinates) [m/s].
    up : ndarray, shape (dim,)
        The vertical in frame coordinates.
    start, end : EndData
    ds : float
        Segment length [m].
    """

    system: CableSystem
    current: np.ndarray
    up: np.ndarray
    start: EndData
    end: EndData
    ds: float


def end_data(end, velocity, rho, force) -> EndData:
    """An end condition's data at the new time level (vectors in the frame's coordinates)."""
    return EndData(end.kind, velocity, end.mass, end.net_buoyancy, 0.5 * rho * end.drag_area, force)
