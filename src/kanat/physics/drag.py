"""Hydrodynamic drag of cables and bodies (quadratic, Morison form).

Both functions take the velocity of the water *relative to* the cable or body
(water velocity minus structure velocity), so the force points with the flow.
"""
from __future__ import annotations

import numpy as np


def cable_drag(tangent, water_velocity, strain, diameter, drag_normal, drag_tangential, density):
    """Drag force per unit unstretched length on a cable element (theory/continuum.md §1).

    ``f = 0.5 rho d C_n sqrt(1+e) |U_n| U_n + 0.5 rho pi d C_t sqrt(1+e) |U_t| U_t``
    with ``U_t = (U.t) t`` and ``U_n = U - U_t``. The factor ``sqrt(1+e)`` is the
    stretched length ``(1+e)`` times the diameter reduced by ``1/sqrt(1+e)``
    (constant volume); the tangential coefficient is referred to ``pi d``.

    Parameters
    ----------
    tangent : ndarray, shape (..., k)
        Unit tangent(s), ``k`` = 2 (x, z) or 3.
    water_velocity : ndarray, shape (..., k)
        Water velocity relative to the cable [m/s].
    strain : ndarray, shape (...)
        Axial strain ``e`` [-].
    diameter, drag_normal, drag_tangential, density : float
        ``d`` [m], ``C_n``, ``C_t`` [-], ``rho`` [kg/m^3].

    Returns
    -------
    ndarray, shape (..., k)
        Force per unit unstretched length [N/m].
    """
    u_t = np.sum(water_velocity * tangent, axis=-1, keepdims=True)
    normal = water_velocity - u_t * tangent
    speed_n = np.sqrt(np.sum(normal * normal, axis=-1, keepdims=True))
    area = np.sqrt(1.0 + np.asarray(strain))[..., None] * 0.5 * density * diameter
    return area * (drag_normal * speed_n * normal + np.pi * drag_tangential * np.abs(u_t) * u_t * tangent)


def axial_drag(u_t, diameter, drag_tangential, density):
    """Drag along a cable lying still, per unit length, from the flow's component ``u_t`` along it:
    the tangential term of :func:`cable_drag` unstretched, ``0.5 rho pi d C_t |u_t| u_t`` [N/m]
    (arrays broadcast). Statics uses it on the part of a line resting on the seabed, whose normal
    drag the seabed bears (:class:`kanat.statics.problem.Grounding`)."""
    u_t = np.asarray(u_t, dtype=float)
    return 0.5 * density * np.pi * np.asarray(diameter) * np.asarray(drag_tangential) * np.abs(u_t) * u_t


def body_drag(water_velocity, drag_area, density):
    """Quadratic drag of a body, ``0.5 rho (C_D S) |U| U`` [N] (theory/continuum.md §3, Kaliukh & Vusatiuk 2018, eq. 26).

    Parameters
    ----------
    water_velocity : ndarray, shape (k,)
        Water velocity relative to the body [m/s].
    drag_area : float
        ``C_D * S`` [m^2].
    density : float
        Water density [kg/m^3].
    """
    water_velocity = np.asarray(water_velocity, dtype=float)
    return 0.5 * density * drag_area * np.linalg.norm(water_velocity) * water_velocity


def critical_angle(weight, normal_drag, speed):
    """Angle below the flow of a cable at rest in a uniform flow whose normal drag carries its
    weight with no tension curvature: the trailing angle of a free tail (theory/continuum.md eq. (C15))::

        R sin^2(phi) = |w| cos(phi),   cos(phi) = (-|w| + sqrt(w^2 + 4 R^2)) / (2 R),   R = C U^2

    Parameters
    ----------
    weight : float or ndarray
        Weight in water per unit length ``w`` [N/m] (its sign does not enter: a buoyant tail
        trails at the same angle above the flow).
    normal_drag : float or ndarray
        ``C = 0.5 rho d C_n`` [N s^2/m^3].
    speed : float or ndarray
        Speed of the relative flow ``U`` [m/s].

    Returns
    -------
    float or ndarray
        ``phi`` [rad], in [0, pi/2]; pi/2 (hanging) where there is no normal drag.
    """
    w = np.abs(np.asarray(weight, dtype=float))
    r = np.asarray(normal_drag, dtype=float) * np.asarray(speed, dtype=float) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        cosine = np.where(r > 0.0, (-w + np.sqrt(w * w + 4.0 * r * r)) / (2.0 * np.where(r > 0.0, r, 1.0)), 0.0)
    phi = np.arccos(np.clip(cosine, 0.0, 1.0))
    return float(phi) if np.ndim(phi) == 0 else phi


def trailing_direction(weight, normal_drag, flow) -> np.ndarray:
    """Unit direction (3,) along a free tail at rest in a uniform horizontal flow, from its attached
    end towards its free end: along ``flow`` at the critical angle ``phi`` (:func:`critical_angle`)
    below it for a heavy line (``w > 0``) and above it for a buoyant one (``w < 0``); straight down
    or straight up in still water (``phi = pi/2``)::

        t = (cos(phi) u / |u|, -sign(w) sin(phi)),   R sin^2(phi) = |w| cos(phi),   R = C |u|^2

    theory/continuum.md eq. (C15). A line neutral in water (``w = 0``) takes the heavy side.

    Parameters
    ----------
    weight : float
        Weight in water per unit length ``w`` [N/m].
    normal_drag : float
        ``C = 0.5 rho d C_n`` [N s^2/m^3].
    flow : array_like, shape (2,)
        Horizontal relative flow ``u`` (water past the line) [m/s].

    Returns
    -------
    ndarray, shape (3,)
    """
    flow = np.asarray(flow, dtype=float)[:2]
    speed = float(np.hypot(flow[0], flow[1]))
    phi = critical_angle(weight, normal_drag, speed)
    along = flow / speed if speed > 0.0 else np.zeros(2)
    rise = np.sin(phi) if weight < 0.0 else -np.sin(phi)
    return np.array([np.cos(phi) * along[0], np.cos(phi) * along[1], rise])
