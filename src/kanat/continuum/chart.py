"""Charts of the spatial angles (theory/continuum.md §2): choosing the pole and re-charting a state exactly.

The angles ``(phi, theta)`` are azimuth–elevation about a pole ``p``; the frame is singular
where a tangent is parallel to the pole. No fixed pole is safe for a towed cable in a
tight low-speed turn (the lower cable hangs vertical while the upper trails in every
horizontal direction), so the run *re-charts*: before a step, if any tangent comes within
``RECHART_COS`` of the pole, the pole moves to the direction least aligned with all the
tangents of the cable (the eigenvector of the smallest eigenvalue of ``sum t t^T``) and
the state and its rate are rewritten in the new chart. Physical vectors (tangent,
velocity, acceleration, tangent rate) are unchanged by a re-chart, so the step that
follows is the same step in other coordinates.

A chart is a rotation matrix ``R`` whose columns are ``(e1, e2, p)`` in global coordinates.
"""
from __future__ import annotations

import numpy as np

RECHART_COS = 0.9        # re-chart when |t . p| exceeds this (tangent within ~26 deg of the pole)


def frames(y: np.ndarray, chart: np.ndarray):
    """Global unit vectors ``t, n, b`` (each (n, 3)) of states ``y`` (n, 6) in ``chart``."""
    cp, sp, ct, st = np.cos(y[:, 4]), np.sin(y[:, 4]), np.cos(y[:, 5]), np.sin(y[:, 5])
    n = len(y)
    local_t, local_n, local_b = np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3))   # np.column_stack's
    np.multiply(cp, ct, out=local_t[:, 0])                                                # layout, built in place
    np.multiply(cp, st, out=local_t[:, 1])
    local_t[:, 2] = sp
    np.multiply(-sp, ct, out=local_n[:, 0])
    np.multiply(-sp, st, out=local_n[:, 1])
    local_n[:, 2] = cp
    local_b[:, 0] = st
    np.negative(ct, out=local_b[:, 1])
    local_b[:, 2] = 0.0
    return local_t @ chart.T, local_n @ chart.T, local_b @ chart.T


def choose_chart(tangents: np.ndarray) -> np.ndarray:
    """The chart whose pole is least aligned with all ``tangents`` (n, 3), ``e1`` along their mean."""
    scatter = tangents.T @ tangents
    _, vectors = np.linalg.eigh(scatter)
    pole = vectors[:, 0]
    reference = np.array([0.0, 0.0, 1.0]) if abs(pole[2]) < 0.9 else np.array([0.0, 1.0, 0.0])
    if pole @ reference < 0:
        pole = -pole
    mean = tangents.mean(axis=0)
    e1 = mean - (mean @ pole) * pole
    if np.linalg.norm(e1) < 1e-6:
        e1 = np.cross(pole, reference if abs(pole @ reference) < 0.9 else np.array([1.0, 0.0, 0.0]))
    e1 /= np.linalg.norm(e1)
    return np.column_stack([e1, np.cross(pole, e1), pole])


def angles(tangents: np.ndarray, chart: np.ndarray):
    """``(phi, theta)`` of global unit ``tangents`` (n, 3) in ``chart``; theta unwrapped along the cable."""
    local = tangents @ chart
    phi = np.arcsin(np.clip(local[:, 2], -1.0, 1.0))
    theta = np.unwrap(np.arctan2(local[:, 1], local[:, 0]))
    return phi, theta


def needs_rechart(y: np.ndarray) -> bool:
    """True when a tangent is within ``RECHART_COS`` of the pole."""
    return bool(np.max(np.abs(np.sin(y[:, 4]))) > RECHART_COS)


def rechart(y: np.ndarray, rate: np.ndarray, chart: np.ndarray, new: np.ndarray):
    """State and rate (n, nv) rewritten from ``chart`` into the ``new`` chart (exact).

    Velocity ``V``, acceleration ``dV/dt`` and tangent rate ``dt/dt = phi_t n - cos(phi) theta_t b``
    are physical vectors; the new components and angle rates follow from them. With bending
    stiffness (nv = 10) so are the shear ``S = S_n n + S_b b`` and the moment ``M = M_n n + M_b b``
    (normal to ``t``, which a re-chart keeps) and their rates: ``S'_n = S.n'`` and
    ``d(S'_n)/dt = dS/dt.n' + S.dn'/dt`` with ``dn/dt = -phi_t t + sin(phi) theta_t b``,
    ``db/dt = theta_t (cos(phi) t - sin(phi) n)``.
    """
    t, n, b = frames(y, chart)
    T, u, v, w, phi = y[:, 0], y[:, 1], y[:, 2], y[:, 3], y[:, 4]
    Td, ud, vd, wd, phid, thetad = rate[:, :6].T
    cp, sp = np.cos(phi), np.sin(phi)
    velocity = u[:, None] * t + v[:, None] * n + w[:, None] * b
    accel = ((ud - v * phid + w * cp * thetad)[:, None] * t + (vd + u * phid - w * sp * thetad)[:, None] * n
             + (wd - u * cp * thetad + v * sp * thetad)[:, None] * b)
    tangent_rate = phid[:, None] * n - (cp * thetad)[:, None] * b
    phi2, theta2 = angles(t, new)
    y2 = np.column_stack([T, np.zeros((len(T), 3)), phi2, theta2])
    t2, n2, b2 = frames(y2, new)
    dot = lambda a, c: np.sum(a * c, axis=1)  # noqa: E731
    u2, v2, w2 = dot(velocity, t2), dot(velocity, n2), dot(velocity, b2)
    c2, s2 = np.cos(phi2), np.sin(phi2)
    phid2 = dot(tangent_rate, n2)
    thetad2 = -dot(tangent_rate, b2) / c2
    y2[:, 1:4] = np.column_stack([u2, v2, w2])
    rate2 = np.column_stack([Td, dot(accel, t2) + v2 * phid2 - w2 * c2 * thetad2,
                             dot(accel, n2) - u2 * phid2 + w2 * s2 * thetad2,
                             dot(accel, b2) + u2 * c2 * thetad2 - v2 * s2 * thetad2, phid2, thetad2])
    if y.shape[1] == 6:
        return y2, rate2
    dn = -phid[:, None] * t + (sp * thetad)[:, None] * b                  # dn/dt, db/dt (old frame)
    db = thetad[:, None] * (cp[:, None] * t - sp[:, None] * n)
    dn2 = -phid2[:, None] * t2 + (s2 * thetad2)[:, None] * b2               # dn'/dt, db'/dt
    db2 = thetad2[:, None] * (c2[:, None] * t2 - s2[:, None] * n2)
    extra, extra_rate = [], []
    for first in (6, 8):                                                   # the shear, then the moment
        a_n, a_b = y[:, first], y[:, first + 1]
        vector = a_n[:, None] * n + a_b[:, None] * b
        change = (rate[:, first, None] * n + a_n[:, None] * dn + rate[:, first + 1, None] * b
                  + a_b[:, None] * db)
        extra += [dot(vector, n2), dot(vector, b2)]
        extra_rate += [dot(change, n2) + dot(vector, dn2), dot(change, b2) + dot(vector, db2)]
    return np.column_stack([y2, *extra]), np.column_stack([rate2, *extra_rate])
