"""Courant numbers of a continuum grid and step, and the step a scheme is known to take.

``sigma_long = c_l dt / ds`` and ``sigma_tr = c_t dt / ds`` with ``c_l = sqrt(EA/m)`` and
``c_t = sqrt(T/((m + m_a)(1 + e)))`` at the largest tension of a state (Kaliukh & Vusatiuk 2018, section 4).
The generalized-α family is unconditionally stable; Kaliukh & Vusatiuk's factorized schemes are not,
in general (docs/factorization.md, "Stability"). A scheme with ``max_sigma_tr(dimensions)``
is refused, before the run starts, for a step whose ``sigma_tr`` exceeds it, with the largest
step it is known to take on the case.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.errors import KanatError


def courant_numbers(model, state, dt: float) -> tuple[float, float]:
    """``(sigma_long, sigma_tr)`` of a step ``dt`` on ``model``'s grid at ``state``."""
    p, ds = model.cable.params, model.cable.ds
    c_l = np.sqrt(p[k.EA] / p[k.M])
    tension = max(float(np.max(state.y[:, 0])), 0.0)
    c_t = np.sqrt(tension / ((p[k.M] + p[k.MA]) * (1.0 + tension / p[k.EA])))
    return c_l * dt / ds, c_t * dt / ds


def check_step(scheme, model, state, dt: float) -> None:
    """Refuse ``dt`` when it exceeds the transverse Courant number ``scheme`` is known to take.

    Raises
    ------
    kanat.errors.KanatError
        Naming the scheme, the case's Courant numbers and the largest step to use instead.
    """
    limit = scheme.max_sigma_tr(model.dimensions)
    if limit is None:
        return
    sigma_long, sigma_tr = courant_numbers(model, state, dt)
    if sigma_tr > limit:
        safe = dt * limit / sigma_tr
        raise KanatError(
            f"the {scheme.name} scheme is known to stay bounded only up to a transverse Courant number "
            f"sigma_tr = {limit:g} (docs/factorization.md, 'Stability'); this case at dt = {dt:g} s has "
            f"sigma_tr = {sigma_tr:.3g} (sigma_long = {sigma_long:.3g}). Use dt <= {safe:.3g} s, or the "
            "generalized-alpha scheme, which takes this step (check_stability=False runs it anyway)")
