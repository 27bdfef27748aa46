"""How far a body's motion hangs on the drag's linearisation (docs/frequency.md).

The equivalent drag ``D`` of :mod:`kanat.frequency.response` (eq. 1) is exact only for the
fundamental of a sinusoidal (or Gaussian) relative velocity; the time domain's drag ``|v| v``
also has harmonics and couples the motions, which the linear model drops. A body's degree of
freedom whose response is decided by that drag is as wrong as the linearisation of the drag is.
At the converged ``D``, with the solves of eq. (1) repeated at the same frequencies, each
degree of freedom ``d`` of each body gets:

* its sensitivity to the equivalent drag, the response's elasticity (``X(D)`` the body's motion,
  its amplitude for a harmonic excitation, its standard deviation for a spectral one)::

      (1)  e_d = |X_d((1 + h) D) - X_d((1 - h) D)| / (2 h |X_d(D)|),   h = STEP

  (0 for a motion the drag does not touch; about 1 for a resonant motion damped by drag alone,
  ``X ~ F / D``; more for a motion that is a small difference of terms the drag sets: the yaw of
  a buoy between its legs, 2.1);
* the drag-forced part of its response: ``s_d = |X_d - X_d(no f_D)| / |X_d|``, ``X(no f_D)``
  the response with the drag's wave forcing ``P_f D u_w`` left out (its damping kept);

and the measure::

    (2)  r_d = e_d s_d

A motion both driven by the drag and sensitive to its linearisation has a large ``r``; a motion
the drag only damps (``s`` small) or hardly touches (``e`` small) has ``r`` near 0. The measure
and its limit are empirical, calibrated on one moored buoy against the time domain (:data:`LIMIT`). Beyond
:data:`LIMIT` the frequency domain warns, naming the body and the degree of freedom. A translation
(rotation) below :data:`NEGLIGIBLE` of the body's largest translation (rotation) is not judged: a
head sea's sway, roll and yaw of a nearly symmetric system, 1e-6 of its surge and 1e-5 of its
pitch, matter to no check, and their ratios of eq. (1) are those of round-off.
"""
from __future__ import annotations

import numpy as np

from kanat.frequency import response as linear_response
from kanat.frequency.assembly import node_displacements

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
STEP = 0.05         # relative change of the equivalent drag for the elasticity of eq. (1)
LIMIT = 0.10        # r of eq. (2) beyond which a body's motion is warned of: calibrated on the buoy of
                    # examples/mooring_buoy_waves.yaml in regular 9 s seas from 30 deg against the time
                    # domain (tests/frequency/test_frequency_body_linearity.py): yaw r = 0.012 at 0.25 m
                    # high (3.6 % off), 0.22 at 0.5 m (27 % off), 0.20 at 1 m (32 % off); roll r = 0.044
                    # at 1 m (1.8 % off) and every other motion below 0.01 and within 1.2 %
NEGLIGIBLE = 1e-3    # of the body's largest translation (rotation): a smaller one is not judged


def drag_measures(model, ex, response) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(e, s, r, size)`` of eqs. (1)-(2), each (body, 6): the elasticity, the drag-forced part,
    their product and the response ``X`` (amplitude or standard deviation [m or rad]); NaN for a
    point body's rotations."""
    water = linear_response.water_kinematics(model, ex) * ex.wave[:, None, None]
    D = linear_response.equivalent_drag(model, ex, water, response.free)
    fixed = linear_response.fixed_forcing(model, ex, water, response.prescribed)

    def motion(scale: float, drag_forcing: bool = True) -> np.ndarray:
        X = linear_response.solve_linear(model, ex, scale * D, water, fixed, drag_forcing)
        return _body_size(model, ex, X, response.prescribed)

    size = motion(1.0)
    safe = np.where(size > 0, size, np.nan)
    e = np.abs(motion(1.0 + STEP) - motion(1.0 - STEP)) / (2.0 * STEP * safe)
    s = np.abs(size - motion(1.0, drag_forcing=False)) / safe
    return e, s, e * s, size


def body_notes(model, ex, response, body_names) -> list[str]:
    """A warning per body whose motions' ``r`` (eq. 2) exceeds :data:`LIMIT`, naming the degrees of
    freedom with their ``r``, ``e`` and ``s``; none without bodies."""
    if not len(body_names):
        return []
    e, s, r, size = drag_measures(model, ex, response)
    notes = []
    for b, name in enumerate(body_names):
        judged = judged_dofs(size[b]) & np.isfinite(r[b])
        poor = np.flatnonzero(judged & (r[b] > LIMIT))
        if not len(poor):
            continue
        which = ", ".join(f"{DOFS[d]} (r = {r[b, d]:.2g}: elasticity {e[b, d]:.2g}, drag-forced "
                          f"{100 * s[b, d]:.2g} %)" for d in poor)
        notes.append(f"body '{name}': its {which} is decided by the lines' drag and its equivalent "
                     f"linearisation (r beyond {LIMIT:g}): the time domain may differ by tens of % (a buoy's yaw "
                     "at r = 0.22: 27 %, docs/frequency.md); check it with method: time")
    return notes


def judged_dofs(size: np.ndarray) -> np.ndarray:
    """Which of a body's six motions (6,) are judged: ``size`` (6,) at least :data:`NEGLIGIBLE` of the
    largest translation's (for a translation) or rotation's (for a rotation), and not zero."""
    out = np.zeros(6, bool)
    for part in (slice(0, 3), slice(3, 6)):
        group = np.nan_to_num(size[part])
        out[part] = (group > 0.0) & (group >= NEGLIGIBLE * group.max(initial=0.0))
    return out


def _body_size(model, ex, X: np.ndarray, prescribed: np.ndarray) -> np.ndarray:
    """Each body's six motions' amplitude (harmonic: the harmonics' summed) or standard deviation
    (spectral), (body, 6); NaN for a point body's rotations."""
    net = model.lin.net
    U = node_displacements(model, X, prescribed)
    body = np.full((len(ex.omega), len(net.body_names), 6), np.nan, complex)
    body[:, :, :3] = U[:, net.body_node]
    for b, name in enumerate(net.rigid.names):
        body[:, net.body_names.index(name), 3:] = U[:, net.rigid.rot_node[b]]
    if ex.spectral:
        return np.sqrt(np.einsum("f,fbd->bd", ex.spectrum * ex.bandwidth, np.abs(body) ** 2))
    return np.abs(body).sum(axis=0)
