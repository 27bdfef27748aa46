"""Drag and fluid inertia of the lines in the frequency domain: equivalent linearisation.

The time domain lumps to each end ``a`` of element ``k`` the drag (:mod:`kanat.lumped.kernels`
eqs. 4-7)::

    (1)  f_a = h (c_n |v_n| v_n + c_t |v . t| (v . t) t),   v = u_w - v_a,  v_n = (I - t t) v,
         h = phi s L0 / 2

with ``u_w`` the water's velocity at the element's middle. About the mean relative flow ``U``
(current less the steady frame's velocity) the fluctuation ``w`` of ``v`` is replaced by the
matrix ``D`` minimising the mean square error of ``f(U + w) - f(U) - D w``:

* **irregular seas** (stochastic linearisation; Borgman 1967, Atalik & Utku 1976): for a
  Gaussian ``w`` of covariance ``Sigma``, ``D = E[J(U + w)]`` with ``J`` the Jacobian of (1),
  ``J(v) = h (c_n (|v_n| P + v_n v_n^T / |v_n|) + 2 c_t |v . t| t t^T)``. In one direction with
  ``U = 0`` this is ``c sqrt(8/pi) sigma_v``;
* **regular waves** (describing function; Krylov & Bogoliubov 1947, Gelb & Vander Velde 1968):
  for ``w = a cos(theta)``, ``D = (1/pi) int_0^{2 pi} J(U + a cos theta) sin^2(theta) d theta``
  (the fundamental of ``f``, by parts), ``8/(3 pi) c |a|`` in one direction with ``U = 0``;
* **a few harmonics at once** (a heave and a slow surge, a sea of a few listed components): each
  harmonic ``f`` gets its own ``D_f``, the describing function of that harmonic in the presence of
  the others (the multiple-input describing function; Gelb & Vander Velde 1968 ch. 5), for
  ``w = sum_g Re(W_g e^{i theta_g})`` with independent uniform phases::

      (3)  D_f = E[J(U + w) 2 sin^2(theta_f)]

  (one harmonic: the describing function above). The Gaussian rule would take the sum of a few
  sinusoids for a Gaussian of their variance, whose ``E|w|`` is ``sqrt(8/pi) sigma`` against a
  sinusoid's ``8/(3 pi) a``: 33 % too much drag on a dominant harmonic;
* **many harmonics** (more than :data:`SINUSOIDS`): the :data:`SINUSOIDS` largest harmonics (by
  ``sum_p |W_f|^2`` over all pairs, :func:`largest_harmonics`: chosen per pair, they flipped between
  nearly equal harmonics from one iteration of the response to the next, which then did not
  converge) stay sinusoids and the others are taken together as a Gaussian
  ``r`` of their covariance ``Sigma_r = sum_rest Re(W_g W_g^H) / 2``, the sinusoids-plus-Gaussian
  input of Gelb & Vander Velde 1968 (ch. 5)::

      (4)  D_f = E[J(U + w_s + r) 2 sin^2(theta_f)]   (f a sinusoid),   D_g = E[J(U + w_s + r)]   (g in r)

  the second the random-input describing function of a Gaussian part (its exact gain, Stein's
  lemma, whatever sinusoids ride on it). Eq. (4) is eq. (3) when the rest is Gaussian; the rest
  is a sum of harmonics no larger than the smallest sinusoid, nearer Gaussian the more of them
  there are. Measured against the exact mean of eq. (3) over all ``N`` phases (plain Monte Carlo,
  2^20 samples, 1e-3) for equal, random, one- and two-dominant amplitudes, with and without a mean
  flow, the largest error of any ``D_f``: eq. (3) on :data:`HARMONIC_SAMPLES` Sobol points, 1 %
  up to 8 harmonics, but 2-4.5 % at 32-64 (the torus's dimension); eq. (4) with 8 sinusoids,
  3.2 % at 9 equal harmonics (the one left to the Gaussian; 0.6 % at 64), 1.8 % for random
  amplitudes and 0.7 % with a dominant one at any ``N``; the Gaussian rule for the whole sum,
  22-26 % off a dominant harmonic at any ``N`` and 2.5 % off 8 equal ones
  (tests/frequency/test_frequency_drag_many.py). Hence eq. (3) up to :data:`SINUSOIDS` harmonics
  and eq. (4) beyond, whose cost does not grow with ``N`` beyond the covariance's sum.

Along the element the expectation is a folded normal's mean in closed form; across it, a
quasi-Monte Carlo mean over the normal plane's Gaussian (:data:`NORMAL_SAMPLES`); the describing function a rectangle rule in ``theta``
(:data:`PHASE_POINTS`) along the principal axis of the complex amplitude (an elliptic ``w`` is
taken on its major axis' phase). The waves force node ``a`` with the same ``D`` on the water's
velocity and with its inertia (kernels eq. 6)::

    (2)  F_a = D u_w + h' [(rho A + m_a) (I - t t) + (rho A + m_at) t t] a_w,   h' = phi L0 / 2

Point bodies and points with drag (kernels ``add_body_loads``) are *isotropic* pairs: their drag
``f = 1/2 rho C_D A |v| v`` with ``v = u_w - v_a`` the water's velocity at the body less its own,
``J(v) = 1/2 rho C_D A |v| (I + v v^T / |v|^2)``, and their Morison inertia ``(rho V + m_a) a_w``
(Froude–Krylov and added mass, the network's ``node_fluid_inertia``). Eqs. (1)-(2) cover them with
``t = 0``, ``h c_n = 1/2 rho C_D A``, ``c_t = 0`` and ``h' (rho A + m_a) = rho V + m_a``; their
stochastic ``D`` is a quasi-Monte Carlo mean over the three-dimensional Gaussian
(:func:`isotropic_stochastic`), ``4/3 sqrt(8/pi) sigma`` times ``1/2 rho C_D A`` in still water
under an isotropic ``sigma^2 I`` (the Maxwell speed's mean, ``E[v v^T/|v|] = E|v| I / 3``).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from scipy.special import erf, ndtri
from scipy.stats import qmc

NORMAL_SAMPLES = 2048  # Sobol points in the normal plane (and as many mirrored): E|v| to ~1e-3
PHASE_POINTS = 360    # over one period: the describing function of |x| x to 1e-4
TINY = 1e-12          # m/s: a relative speed taken as zero
HARMONIC_SAMPLES = 4096  # Sobol points on the torus of the harmonics' phases (eqs. 3-4): D_f to ~1e-3
SINUSOIDS = 8         # harmonics kept as sinusoids at a pair (eq. 4); the rest there: one Gaussian


@dataclass(frozen=True, eq=False)
class DragPairs:
    """Each free line node ``a`` with each element ``k`` it ends (eq. 1).

    Attributes
    ----------
    node, element : ndarray of int, shape (p,)
        The node and the element.
    dof : ndarray of int, shape (p,)
        The node's first degree of freedom in the linear system (``3 x`` its free index).
    tangent : ndarray, shape (p, 3)
        The element's unit tangent ``t`` at the equilibrium.
    normal, tangential : ndarray, shape (p,)
        ``h c_n`` and ``h c_t`` [N s^2/m^2].
    inertia_normal, inertia_tangential : ndarray, shape (p,)
        ``h' (rho A + m_a)`` and ``h' (rho A + m_at)`` [kg].
    mean : ndarray, shape (p, 3)
        The mean relative flow ``U`` [m/s].
    middle : ndarray, shape (p, 3)
        The element's middle (where the water's kinematics are taken) [m].
    """

    node: np.ndarray
    element: np.ndarray
    dof: np.ndarray
    tangent: np.ndarray
    normal: np.ndarray
    tangential: np.ndarray
    inertia_normal: np.ndarray
    inertia_tangential: np.ndarray
    mean: np.ndarray
    middle: np.ndarray
    isotropic: np.ndarray | None = None

    @property
    def bodies(self) -> np.ndarray:
        """Which pairs are isotropic (point bodies), shape (p,) bool."""
        return np.zeros(len(self.node), bool) if self.isotropic is None else self.isotropic


def drag_pairs(net, x: np.ndarray, free: np.ndarray, wet: np.ndarray, strain: np.ndarray,
               current, frame_velocity: np.ndarray, rho: float = 0.0) -> DragPairs:
    """:class:`DragPairs` of a network at positions ``x`` (n, 3); ``free`` the free nodes in DOF
    order, ``wet`` and ``strain`` (m,) the elements' wetted fraction and strain,
    ``current(points) -> (k, 3)`` the current [m/s]; the point bodies' isotropic pairs after the
    elements' (``rho`` the water's density [kg/m^3])."""
    lines = _line_pairs(net, x, free, wet, strain, current, frame_velocity)
    bodies = _body_pairs(net, x, free, current, frame_velocity, rho)
    return DragPairs(*(np.concatenate([getattr(lines, name), getattr(bodies, name)])
                       for name in DragPairs.__dataclass_fields__))


def _body_pairs(net, x, free, current, frame_velocity, rho) -> DragPairs:
    """The isotropic pairs of the free point-body nodes (module docstring)."""
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free] = np.arange(len(free))
    keep = position[net.load_node] >= 0
    node = np.asarray(net.load_node, dtype=np.int64)[keep]
    k = len(node)
    return DragPairs(node=node, element=-np.ones(k, dtype=np.int64), dof=3 * position[node],
                     tangent=np.zeros((k, 3)), normal=0.5 * rho * np.asarray(net.load_drag_area, float)[keep],
                     tangential=np.zeros(k), inertia_normal=np.asarray(net.node_fluid_inertia, float)[node],
                     inertia_tangential=np.zeros(k), mean=current(x[node]).reshape(k, 3) - frame_velocity,
                     middle=x[node], isotropic=np.ones(k, bool))


def _line_pairs(net, x, free, wet, strain, current, frame_velocity) -> DragPairs:
    """The elements' pairs (eq. 1)."""
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free] = np.arange(len(free))
    node = np.r_[net.el_i, net.el_j]
    element = np.r_[np.arange(net.n_elements), np.arange(net.n_elements)]
    keep = position[node] >= 0
    node, element = node[keep], element[keep]
    d = x[net.el_j] - x[net.el_i]
    t = d / np.linalg.norm(d, axis=1)[:, None]
    stretch = np.where(net.el_stretch_drag > 0, np.sqrt(np.maximum(1.0 + strain, 0.0)), 1.0)
    h = 0.5 * net.el_length * wet
    middle = 0.5 * (x[net.el_i] + x[net.el_j])
    mean = current(middle) - frame_velocity
    e = element
    return DragPairs(node=node, element=e, dof=3 * position[node], tangent=t[e],
                     normal=(h * stretch * net.el_cn)[e], tangential=(h * stretch * net.el_ct)[e],
                     inertia_normal=(h * (net.el_displaced + net.el_added_mass))[e],
                     inertia_tangential=(h * (net.el_displaced + net.el_added_tangential))[e],
                     mean=mean[e], middle=middle[e], isotropic=np.zeros(len(e), bool))


def jacobian(pairs: DragPairs, v: np.ndarray) -> np.ndarray:
    """``J(v)`` of eq. (1) at relative velocities ``v`` (p, s, 3): shape (p, s, 3, 3)."""
    t = pairs.tangent[:, None, :]
    along = np.einsum("psr,psr->ps", v, np.broadcast_to(t, v.shape))
    vn = v - along[..., None] * t
    speed = np.linalg.norm(vn, axis=-1)
    unit = vn / np.maximum(speed, TINY)[..., None]
    P = np.eye(3) - np.einsum("pr,pq->pqr", pairs.tangent, pairs.tangent)[:, None]
    tt = np.einsum("pr,pq->pqr", pairs.tangent, pairs.tangent)[:, None]
    normal = speed[..., None, None] * (P + np.einsum("psr,psq->psrq", unit, unit))
    tangential = 2.0 * np.abs(along)[..., None, None] * tt
    return (pairs.normal[:, None, None, None] * normal + pairs.tangential[:, None, None, None] * tangential)


def stochastic(pairs: DragPairs, covariance: np.ndarray) -> np.ndarray:
    """``D = E[J(U + w)]`` (p, 3, 3) for Gaussian ``w`` of covariance (p, 3, 3): the elements'
    (:func:`line_stochastic`) and the point bodies' (:func:`isotropic_stochastic`)."""
    bodies = pairs.bodies
    out = np.empty((len(pairs.node), 3, 3))
    if np.any(~bodies):
        out[~bodies] = line_stochastic(_subset(pairs, ~bodies), covariance[~bodies])
    if np.any(bodies):
        out[bodies] = isotropic_stochastic(pairs.normal[bodies], pairs.mean[bodies], covariance[bodies])
    return out


def _subset(pairs: DragPairs, which) -> DragPairs:
    return DragPairs(*(None if getattr(pairs, name) is None else getattr(pairs, name)[which]
                       for name in DragPairs.__dataclass_fields__))


def isotropic_stochastic(coefficient: np.ndarray, mean: np.ndarray, covariance: np.ndarray) -> np.ndarray:
    """``c E[|v| (I + v v^T / |v|^2)]`` (p, 3, 3) for ``v`` Gaussian of mean (p, 3) and covariance
    (p, 3, 3), ``c`` (p,) (module docstring): :data:`NORMAL_SAMPLES` scrambled Sobol points in three
    dimensions and their mirror images."""
    values, vectors = np.linalg.eigh(covariance)
    scale = vectors * np.sqrt(np.maximum(values, 0.0))[:, None, :]
    v = mean[:, None, :] + np.einsum("prq,sq->psr", scale, _space_samples())
    speed = np.linalg.norm(v, axis=-1)
    unit = v / np.maximum(speed, TINY)[..., None]
    J = speed[..., None, None] * (np.eye(3) + np.einsum("psr,psq->psrq", unit, unit))
    return coefficient[:, None, None] * J.mean(axis=1)


@functools.lru_cache(maxsize=1)
def _space_samples() -> np.ndarray:
    """Standard normal points in space (2 x :data:`NORMAL_SAMPLES`, 3): Sobol, seed 0, mirrored."""
    z = ndtri(qmc.Sobol(d=3, scramble=True, seed=0).random(NORMAL_SAMPLES))
    return np.vstack([z, -z])


def line_stochastic(pairs: DragPairs, covariance: np.ndarray) -> np.ndarray:
    """``D = E[J(U + w)]`` (p, 3, 3) for Gaussian ``w`` of covariance (p, 3, 3) (module docstring).

    Along the element, ``E[2 |U_t + w_t|]`` in closed form (a folded normal's mean); across it, the
    expectation over the normal plane's Gaussian by :data:`NORMAL_SAMPLES` scrambled Sobol points
    and their mirror images (quasi-Monte Carlo; the kink of ``|v|`` rules out a Gauss rule)."""
    t = pairs.tangent
    sigma_t = np.sqrt(np.maximum(np.einsum("pr,prq,pq->p", t, covariance, t), 0.0))
    mean_t = np.abs(np.einsum("pr,pr->p", pairs.mean, t))
    folded = np.where(sigma_t > TINY, sigma_t * np.sqrt(2.0 / np.pi) * np.exp(-0.5 * (mean_t / np.maximum(sigma_t, TINY)) ** 2)
                      + mean_t * erf(mean_t / (np.sqrt(2.0) * np.maximum(sigma_t, TINY))), mean_t)
    tt = np.einsum("pr,pq->prq", t, t)
    E = normal_basis(t)                                                   # (p, 3, 2)
    plane = np.einsum("pra,prq,pqb->pab", E, covariance, E)
    values, vectors = np.linalg.eigh(plane)
    scale = vectors * np.sqrt(np.maximum(values, 0.0))[:, None, :]
    v = np.einsum("pr,pra->pa", pairs.mean, E)[:, None, :] + np.einsum("pab,sb->psa", scale, _normal_samples())
    speed = np.linalg.norm(v, axis=-1)
    unit = v / np.maximum(speed, TINY)[..., None]
    J = speed[..., None, None] * (np.eye(2) + np.einsum("psa,psb->psab", unit, unit))
    across = np.einsum("pra,pab,pqb->prq", E, J.mean(axis=1), E)
    return pairs.normal[:, None, None] * across + (2.0 * pairs.tangential * folded)[:, None, None] * tt


def normal_basis(t: np.ndarray) -> np.ndarray:
    """Two unit vectors (p, 3, 2) normal to the unit tangents ``t`` (p, 3) and to each other."""
    axis = np.eye(3)[np.argmin(np.abs(t), axis=1)]
    e1 = np.cross(t, axis)
    e1 /= np.linalg.norm(e1, axis=1)[:, None]
    return np.stack([e1, np.cross(t, e1)], -1)


@functools.lru_cache(maxsize=1)
def _normal_samples() -> np.ndarray:
    """Standard normal points in the plane (2 x :data:`NORMAL_SAMPLES`, 2): Sobol, seed 0, mirrored."""
    z = ndtri(qmc.Sobol(d=2, scramble=True, seed=0).random(NORMAL_SAMPLES))
    return np.vstack([z, -z])


def describing(pairs: DragPairs, amplitude: np.ndarray) -> np.ndarray:
    """``D`` (p, 3, 3) of the describing function for ``w = Re(W e^{i theta})``, ``W`` the complex
    amplitudes (p, 3) (module docstring)."""
    square = np.einsum("pr,pr->p", amplitude, amplitude)
    B = amplitude * np.exp(-0.5j * np.angle(square))[:, None]          # mostly real: the major axis
    theta = 2.0 * np.pi * np.arange(PHASE_POINTS) / PHASE_POINTS
    w = B.real[:, None, :] * np.cos(theta)[None, :, None] - B.imag[:, None, :] * np.sin(theta)[None, :, None]
    weights = 2.0 * np.sin(theta) ** 2 / PHASE_POINTS
    return np.einsum("psrq,s->prq", jacobian(pairs, pairs.mean[:, None, :] + w), weights)


def multiple_describing(pairs: DragPairs, amplitudes: np.ndarray) -> np.ndarray:
    """``D_f`` (nf, p, 3, 3) of eq. (3) for ``w = sum_f Re(W_f e^{i theta_f})``, ``W`` the complex
    amplitudes (nf, p, 3) of the harmonics at each pair: :data:`HARMONIC_SAMPLES` scrambled Sobol
    points on the phases' torus, each harmonic turned to its major axis as in :func:`describing`."""
    nf = amplitudes.shape[0]
    square = np.einsum("fpr,fpr->fp", amplitudes, amplitudes)
    B = amplitudes * np.exp(-0.5j * np.angle(square))[..., None]
    theta = _torus_samples(nf)                                               # (s, nf)
    w = (np.einsum("fpr,sf->psr", B.real, np.cos(theta)) - np.einsum("fpr,sf->psr", B.imag, np.sin(theta)))
    weights = 2.0 * np.sin(theta) ** 2 / len(theta)                          # (s, nf)
    return np.einsum("psrq,sf->fprq", jacobian(pairs, pairs.mean[:, None, :] + w), weights)


@functools.lru_cache(maxsize=SINUSOIDS)
def _torus_samples(n: int) -> np.ndarray:
    """Phases (:data:`HARMONIC_SAMPLES`, n) on ``[0, 2 pi)^n``: Sobol, seed 0."""
    return 2.0 * np.pi * qmc.Sobol(d=n, scramble=True, seed=0).random(HARMONIC_SAMPLES)


def largest_harmonics(amplitudes: np.ndarray) -> np.ndarray:
    """The :data:`SINUSOIDS` harmonics of eq. (4) (k,): the largest by ``sum_p |W_f|^2`` over the pairs
    of ``amplitudes`` (nf, p, 3), the same at every pair, so that the choice does not flip from pair to
    pair, nor between iterations of the response, where two harmonics are nearly equal there."""
    energy = np.einsum("fpr,fpr->f", amplitudes, amplitudes.conj()).real
    return np.sort(np.argsort(-energy, kind="stable")[:SINUSOIDS])


def harmonic_describing(pairs: DragPairs, amplitudes: np.ndarray, sinusoids: np.ndarray | None = None) -> np.ndarray:
    """``D_f`` (nf, p, 3, 3) for ``w = sum_f Re(W_f e^{i theta_f})``, any number of harmonics: eq. (3)
    (:func:`multiple_describing`) for up to :data:`SINUSOIDS`, else eq. (4).

    Parameters
    ----------
    pairs : DragPairs
    amplitudes : ndarray, shape (nf, p, 3)
        Complex amplitudes ``W_f`` of the relative velocity at each pair [m/s].
    sinusoids : ndarray of int, shape (k,), optional
        The harmonics eq. (4) keeps as sinusoids (default: :func:`largest_harmonics` of ``amplitudes``;
        a caller working on batches of pairs passes those of all of them).
    """
    nf, p = amplitudes.shape[:2]
    if nf <= SINUSOIDS:
        return multiple_describing(pairs, amplitudes)
    kept = largest_harmonics(amplitudes) if sinusoids is None else np.asarray(sinusoids)
    rest = np.ones((nf, p), bool)
    rest[kept] = False
    covariance = 0.5 * np.einsum("fp,fpr,fpq->prq", rest, amplitudes, amplitudes.conj()).real
    sinusoids = amplitudes[kept]                                             # (k, p, 3)
    square = np.einsum("kpr,kpr->kp", sinusoids, sinusoids)
    B = sinusoids * np.exp(-0.5j * np.angle(square))[..., None]
    theta, z = _mixed_samples()                                              # (s, k), (s, 3)
    values, vectors = np.linalg.eigh(covariance)
    scale = vectors * np.sqrt(np.maximum(values, 0.0))[:, None, :]
    w = (np.einsum("kpr,sk->psr", B.real, np.cos(theta)) - np.einsum("kpr,sk->psr", B.imag, np.sin(theta))
         + np.einsum("prq,sq->psr", scale, z))
    J = jacobian(pairs, pairs.mean[:, None, :] + w)                          # (p, s, 3, 3)
    out = np.broadcast_to(J.mean(axis=1), (nf, p, 3, 3)).copy()              # the Gaussian part's gain
    own = np.einsum("psrq,sk->kprq", J, 2.0 * np.sin(theta) ** 2 / len(theta))
    out[kept] = own
    return out


@functools.lru_cache(maxsize=1)
def _mixed_samples() -> tuple[np.ndarray, np.ndarray]:
    """Eq. (4)'s points: :data:`HARMONIC_SAMPLES` scrambled Sobol points (seed 0) in
    ``SINUSOIDS + 3`` dimensions, the first as phases on ``[0, 2 pi)``, the last three as standard
    normal coordinates."""
    u = qmc.Sobol(d=SINUSOIDS + 3, scramble=True, seed=0).random(HARMONIC_SAMPLES)
    return 2.0 * np.pi * u[:, :SINUSOIDS], ndtri(u[:, SINUSOIDS:])


def tangent_at_mean(pairs: DragPairs) -> np.ndarray:
    """``J(U)`` (p, 3, 3): the drag's slope about the mean flow, which the linearisation's ``C``
    already holds (:mod:`kanat.frequency.linearize`)."""
    return jacobian(pairs, pairs.mean[:, None, :])[:, 0]


def inertia(pairs: DragPairs) -> np.ndarray:
    """The matrices of eq. (2) on the water's acceleration, shape (p, 3, 3) [kg]."""
    tt = np.einsum("pr,pq->prq", pairs.tangent, pairs.tangent)
    return pairs.inertia_normal[:, None, None] * (np.eye(3) - tt) + pairs.inertia_tangential[:, None, None] * tt
