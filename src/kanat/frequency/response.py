"""The frequency-domain response: the linear system solved frequency by frequency, with the drag's
equivalent linearisation iterated to a fixed point (docs/frequency.md).

At each frequency ``omega`` of the excitation (:mod:`kanat.frequency.excitation`)::

    (1)  (K + i omega (C - J_U + D) - omega^2 M) X
             = f_p + (f_w + f_b + P_f sum_pairs (D_k u_w,k + I_k a_w,k)) eta_hat

``K, C, M`` the linearisation (:mod:`kanat.frequency.linearize`), ``J_U`` the drag's slope about
the mean flow which ``C`` holds and ``D`` replaces (:mod:`kanat.frequency.drag`; both assembled
through the pairs' maps, ``P_f D P_v^T``: :mod:`kanat.frequency.pairs`), ``f_p`` the vessel's
forcing (:mod:`kanat.frequency.assembly` eq. 1), ``f_w`` the surface buoys' waterplane lift,
``f_b`` the 6-DOF bodies' wave force and moment (:mod:`kanat.frequency.bodies` eq. 1), ``u_w, a_w``
the waves' velocity and acceleration at the elements' middles per unit amplitude
(:mod:`kanat.frequency.kinematics`; projected on a body's drag channel, zero on its channels on
its absolute velocity). ``D`` depends on the relative
velocity's statistics, which depend on ``X``: starting from the nodes at rest, the solves are
repeated with ``D`` the mean of the last two until it changes by less than
:data:`TOLERANCE` of its norm (Langley 1984, Spanos 1981). ``D`` is one matrix for all frequencies
under the stochastic rule (a sea state) and one per frequency under the describing functions (one
harmonic or several, :mod:`kanat.frequency.drag` eqs. 3-4: up to eight as sinusoids, beyond that the
eight largest over the line as sinusoids and the rest as one Gaussian).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from kanat.frequency import drag
from kanat.frequency.assembly import LinearModel
from kanat.frequency.bodies import wave_forces
from kanat.frequency.excitation import Excitation, vessel_displacement
from kanat.frequency.kinematics import water_velocity

TOLERANCE = 1e-4        # relative change of the equivalent drag at which the iteration stops
MAX_ITERATIONS = 200


@dataclass(frozen=True, eq=False)
class Response:
    """The solution of eq. (1).

    Attributes
    ----------
    free : ndarray of complex, shape (nf, n_dof)
        ``X`` per frequency (per unit wave amplitude for a spectral excitation).
    prescribed : ndarray of complex, shape (nf, p, 3)
        The vessel nodes' displacements.
    iterations : int
    converged : bool
    change : float
        The last iteration's relative change of ``D``.
    """

    free: np.ndarray
    prescribed: np.ndarray
    iterations: int
    converged: bool
    change: float


def water_kinematics(model: LinearModel, ex: Excitation) -> np.ndarray:
    """The waves' velocity at the pairs' element middles per unit amplitude, (nf, p, 3) complex
    (projected as each pair feels it: the bodies' channels, :mod:`kanat.frequency.pairs`)."""
    nf, p = len(ex.omega), len(model.pairs.node)
    if ex.sea is None:
        return np.zeros((nf, p, 3), complex)
    return np.einsum("prq,fpq->fpr", model.maps.flow, water_velocity(ex.sea, model.pairs.middle))


def solve(model: LinearModel, ex: Excitation) -> Response:
    """Eq. (1) at every frequency of ``ex``, iterated on the equivalent drag."""
    pairs, omega = model.pairs, ex.omega
    water = water_kinematics(model, ex) * ex.wave[:, None, None]
    prescribed = vessel_displacement(ex.motion, model.arms, model.heading)
    fixed = fixed_forcing(model, ex, water, prescribed)
    D = _equivalent(pairs, water, np.zeros((len(omega), len(pairs.node), 3), complex), ex)
    change, iterations = np.inf, 0
    while iterations < MAX_ITERATIONS:
        X = solve_linear(model, ex, D, water, fixed)
        iterations += 1
        new = equivalent_drag(model, ex, water, X)
        scale = max(float(np.max(np.abs(new))), float(np.max(np.abs(D))), 1e-300)
        change = float(np.max(np.abs(new - D))) / scale
        if change < TOLERANCE:
            break
        D = 0.5 * (D + new)
    return Response(X, prescribed, iterations, change < TOLERANCE, change)


def fixed_forcing(model: LinearModel, ex: Excitation, water: np.ndarray, prescribed: np.ndarray) -> np.ndarray:
    """The right-hand side of eq. (1) but the drag's, (nf, n_dof) complex: the vessel's forcing
    ``f_p`` (``prescribed`` (nf, p, 3) its nodes' displacements) and :func:`wave_excitation`."""
    vessel = prescribed.reshape(len(ex.omega), -1)
    fixed = np.stack([(model.coupling @ vessel[f] + 1j * w * (model.coupling_rate @ vessel[f])
                       + w ** 2 * (model.coupling_mass @ vessel[f])) for f, w in enumerate(ex.omega)])
    return fixed + wave_excitation(model, ex, water)


def solve_linear(model: LinearModel, ex: Excitation, D: np.ndarray, water: np.ndarray, fixed: np.ndarray,
                 drag_forcing: bool = True) -> np.ndarray:
    """``X`` (nf, n_dof) of eq. (1) for a given equivalent drag ``D`` (nf, p, 3, 3), ``water`` the
    pairs' water velocity (nf, p, 3) and ``fixed`` the rest of the right-hand side
    (:func:`fixed_forcing`); without ``drag_forcing`` the drag's wave forcing ``D u_w`` is left
    out (its damping kept)."""
    rhs = (fixed + model.maps.forces(np.einsum("fprq,fpq->fpr", D, water))) if drag_forcing else fixed
    base = model.lin.damping - model.drag_at_mean
    return _solve_all(model.lin, _dampings(model.maps, base, D), ex.omega, rhs)


def equivalent_drag(model: LinearModel, ex: Excitation, water: np.ndarray, X: np.ndarray) -> np.ndarray:
    """``D`` (nf, p, 3, 3) of the response ``X`` (nf, n_dof): the drag's equivalent linearisation
    at the relative velocity it leaves (:func:`_equivalent`)."""
    return _equivalent(model.pairs, water, model.maps.velocities(X), ex)


def wave_excitation(model: LinearModel, ex: Excitation, water: np.ndarray | None = None) -> np.ndarray:
    """The waves' forces on the system at rest but for drag, (nf, n_dof) complex: the lines' and point
    bodies' inertia ``I a_w`` (Froude-Krylov and added mass), the surface buoys' waterplane lift and
    the 6-DOF bodies' wave force and moment; ``water`` the pairs' water velocity
    (:func:`water_kinematics` times the wave), worked out when not given."""
    if water is None:
        water = water_kinematics(model, ex) * ex.wave[:, None, None]
    inertia = drag.inertia(model.pairs)
    out = model.maps.forces(1j * ex.omega[:, None, None] * np.einsum("prq,fpq->fpr", inertia, water))
    out += waterplane_forces(model, ex)
    if ex.sea is not None:
        out += wave_forces(model.bodies, ex.sea, ex.omega, model.size) * ex.wave[:, None]
    return out


def waterplane_forces(model: LinearModel, ex: Excitation) -> np.ndarray:
    """The waves' lift ``rho g A_w eta`` on the surface buoys, (nf, n_dof) complex: the elevation at
    each keel ``eta_hat e^{-i k (x cos beta + y sin beta)}``."""
    out = np.zeros((len(ex.omega), model.size), complex)
    if ex.sea is None or not len(model.waterplane_dof):
        return out
    sea, place = ex.sea, model.waterplane_place
    psi = np.multiply.outer(place[:, 0], sea.k * np.cos(sea.direction)) + np.multiply.outer(
        place[:, 1], sea.k * np.sin(sea.direction))                           # (b, nf)
    out[:, model.waterplane_dof] = (model.waterplane_stiffness[:, None] * np.exp(-1j * psi)).T * ex.wave[:, None]
    return out


def _dampings(maps, base: sp.csr_matrix, D: np.ndarray) -> list[sp.csr_matrix]:
    """``base + P_f D_f P_v^T`` per frequency, assembled once when ``D`` (nf, p, 3, 3) is the same
    at every frequency (the stochastic rule's broadcast)."""
    if D.shape[0] > 1 and D.strides[0] == 0:
        return [base + maps.assemble(D[0])] * D.shape[0]
    return [base + maps.assemble(D[f]) for f in range(D.shape[0])]


def _solve_all(lin, damping: list[sp.csr_matrix], omega: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """``X`` (nf, n_dof) of eq. (1), one sparse LU per frequency (``damping`` that frequency's)."""
    K, M = lin.stiffness.astype(complex), lin.mass.astype(complex)
    out = np.empty_like(rhs)
    for f, w in enumerate(omega):
        A = (K + 1j * w * damping[f] - w * w * M).tocsc()
        out[f] = spla.splu(A).solve(rhs[f])
    return out


def _equivalent(pairs: drag.DragPairs, water: np.ndarray, X: np.ndarray, ex: Excitation) -> np.ndarray:
    """``D`` (nf, p, 3, 3) of the relative velocity ``u_w - i omega X`` at each pair (drag module),
    ``X`` (nf, p, 3) the pairs' displacements (:meth:`kanat.frequency.pairs.PairMaps.velocities`):
    the describing functions' for harmonics (any number), else (a sea state) the stochastic rule's,
    the same at every frequency."""
    nf = X.shape[0]
    W = water - 1j * ex.omega[:, None, None] * X                        # (nf, p, 3)
    if not ex.spectral and nf == 1:
        return drag.describing(pairs, W[0])[None]
    if not ex.spectral:
        kept = drag.largest_harmonics(W)                                # the same sinusoids in every batch
        return _chunked(lambda part, amplitudes: drag.harmonic_describing(part, amplitudes.transpose(1, 0, 2), kept),
                        pairs, W.transpose(1, 0, 2), nf)
    covariance = np.einsum("f,fpr,fpq->prq", ex.spectrum * ex.bandwidth, W, W.conj()).real
    return np.broadcast_to(_chunked(drag.stochastic, pairs, covariance)[None], (nf, len(pairs.node), 3, 3))


CHUNK = 64      # pairs per batch of the expectations (memory: CHUNK x 4096 x 9 doubles)


def _chunked(function, pairs: drag.DragPairs, statistics: np.ndarray, nf: int | None = None) -> np.ndarray:
    """``function(pairs, statistics)`` over batches of :data:`CHUNK` pairs: (p, 3, 3), or with
    ``nf`` given (nf, p, 3, 3) from ``function``'s (nf, batch, 3, 3)."""
    p = len(pairs.node)
    out = np.empty((p, 3, 3) if nf is None else (nf, p, 3, 3))
    for start in range(0, p, CHUNK):
        part = slice(start, start + CHUNK)
        sub = drag.DragPairs(*(None if getattr(pairs, name) is None else getattr(pairs, name)[part]
                               for name in drag.DragPairs.__dataclass_fields__))
        if nf is None:
            out[part] = function(sub, statistics[part])
        else:
            out[:, part] = function(sub, statistics[part])
    return out
