"""How far the vessel's motion carries the lines out of their linear range (docs/frequency.md).

The linear model holds the lines' stiffness at the mean position. A catenary's is not constant: a
chain stiffens as the vessel moves away from its anchor and softens as it moves towards it. The
check re-solves the static equilibrium (:func:`kanat.lumped.equilibrium.equilibrium`, the lumped
model's own) with every vessel point displaced by ``+d`` and by ``-d`` from its mean place, ``d``
the vessel's largest excursion (below), and compares each node's quasi-static tension
``T(+d)``, ``T(-d)`` with the mean's ``T(0)``. Written ``T(+-d) = T(0) +- a + b``, the linear model
keeps ``a`` and drops ``b``, so its relative error at the excursion is::

    (1)  r = |T(+d) + T(-d) - 2 T(0)| / |T(+d) - T(-d)|

(for a tension quadratic in the offset, ``T = T0 + k d + c d^2``, ``r = |c d / k|``: the
change of the tangent stiffness ``(k(+d) - k(-d)) / (k(+d) + k(-d))`` across the excursion).
The denominator is floored at :data:`FLOOR` of the largest over the nodes, so that a node the
offset barely loads (a leg across the motion) is judged against the system's swing, not its own,
and at twice the linear result's own tension swing at the node (the harmonics' amplitudes summed,
or :data:`SIGMAS` sigma), so that the dropped term is weighed against the tension the result
predicts, and at :data:`QUIET` of the node's mean tension, so that a system the offset hardly
loads (a tow heaved with its vessel in a uniform flow: 2.7 N of 12 kN) is not judged by a term
that does not matter against its tension.

The excursions ``d`` (p, 3) of the p vessel points are along the principal axes ``e`` of their
displacements' covariance ``C = sum_f w_f Re(u_f u_f^H)`` (``w_f = S d omega`` for a spectral
excitation, ``1/2`` for a harmonic one) whose variance ``lambda`` is at least :data:`AXES` of the
largest (a slow surge and a wave-frequency heave are checked each on its own):
``d = SIGMAS sqrt(lambda) e`` for a sea state, and ``d = sum_f |e . u_f| e`` (the harmonics'
amplitudes summed) for a harmonic excitation. The worst axis is the check's.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.system import LumpedSystem

LIMIT = 0.05        # r of eq. (1) beyond which the result is warned of: calibrated on the time-domain
                    # comparisons of tests/frequency (the 300 m chain surging 1 m: r = 0.146, its
                    # peaks 7-11 % off the time domain's; Hs 3 m: r = 0.033, within 5 %)
REFUSE = 0.20       # r beyond which the result fails (the chain surging 2 m: r = 0.29, its tension
                    # std 10 % and its peaks 34-53 % off the time domain's)
SIGMAS = 2.0        # a sea state's excursion in standard deviations of the vessel's motion
FLOOR = 0.1         # of the largest quasi-static swing: the least denominator of eq. (1)
AXES = 0.01         # of the largest variance: the least of a principal axis that is checked
QUIET = 0.01        # of the node's mean tension: the least denominator of eq. (1)


@dataclass(frozen=True)
class OffsetCheck:
    """The quasi-static tensions at the vessel's mean place and excursion (module docstring).

    Attributes
    ----------
    excursion : ndarray, shape (p, 3)
        ``d`` of every vessel point [m], global axes.
    mean, up, down : ndarray, shape (node,)
        ``T(0)``, ``T(+d)``, ``T(-d)`` at the output nodes [N].
    dynamic : ndarray, shape (node,)
        The linear result's tension swing at the nodes [N] (module docstring).
    """

    excursion: np.ndarray
    mean: np.ndarray
    up: np.ndarray
    down: np.ndarray
    dynamic: np.ndarray

    @property
    def ratio(self) -> np.ndarray:
        """``r`` (node,) of eq. (1), its denominator floored (module docstring)."""
        swing = np.abs(self.up - self.down)
        least = np.maximum(np.maximum(FLOOR * swing.max(), 2.0 * self.dynamic), QUIET * np.abs(self.mean))
        return np.abs(self.up + self.down - 2.0 * self.mean) / np.maximum(np.maximum(swing, least), 1e-300)

    @property
    def distance(self) -> float:
        """The largest vessel point's excursion ``|d|`` [m]."""
        return float(np.max(np.linalg.norm(self.excursion, axis=1)))


def vessel_excursions(prescribed: np.ndarray, weight: np.ndarray, spectral: bool) -> list[np.ndarray]:
    """The excursions ``d`` (p, 3) of the module docstring, largest first, from the vessel points'
    complex displacements (nf, p, 3) and the variance weights (nf,); none when the vessel does not
    move."""
    nf, p = prescribed.shape[:2]
    if p == 0:
        return []
    u = prescribed.reshape(nf, -1)
    covariance = np.einsum("f,fa,fb->ab", weight, u, u.conj()).real
    values, vectors = np.linalg.eigh(covariance)
    out = []
    for k in np.argsort(values)[::-1]:
        if values[k] <= 0.0 or values[k] < AXES * values.max():
            break
        axis = vectors[:, k]
        size = SIGMAS * math.sqrt(values[k]) if spectral else float(np.abs(u @ axis).sum())
        out.append((size * axis).reshape(p, 3))
    return out


def offset_check(model, case, excursion: np.ndarray, dynamic: np.ndarray) -> OffsetCheck:
    """The quasi-static tensions at the vessel's mean place and ``+- excursion`` (p, 3) [m];
    ``dynamic`` (node,) the linear result's tension swing [N].

    Raises
    ------
    SolverError
        If the equilibrium at an offset place does not converge.
    """
    net = model.lin.net
    c, s = math.cos(model.heading), math.sin(model.heading)
    local = np.stack([c * excursion[:, 0] + s * excursion[:, 1], -s * excursion[:, 0] + c * excursion[:, 1],
                      excursion[:, 2]], -1)                          # the arms are in vessel axes
    tensions = [_static_tension(model, case, dataclasses.replace(net, vessel_offset=net.vessel_offset + sign * local))
                for sign in (1.0, -1.0)]
    return OffsetCheck(excursion, model.node_tension(model.mean_tension), *tensions, np.asarray(dynamic, float))


def _static_tension(model, case, net) -> np.ndarray:
    """The output nodes' tension (node,) of ``net``'s equilibrium, from the mean one's positions."""
    x, _ = equilibrium(net, case, x0=model.lin.position, friction=False)
    moving = LumpedSystem(net, case, waves=False, friction=False)
    system = LumpedSystem(net, case, waves=False, steady_velocity=moving.frame_velocity(), friction=False)
    free = system.free_index
    full, velocity, _, heading = system.full(0.0, x[free], np.zeros_like(x[free]))
    system.loads(0.0, full, velocity, heading)
    return model.node_tension(system.tension.copy())
