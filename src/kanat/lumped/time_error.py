"""A posteriori estimate of the implicit lumped scheme's local time-integration error.

For Newmark's scheme, Zienkiewicz & Xie (1991, "A simple error estimator and adaptive time
stepping procedure for dynamic analysis", Earthquake Eng. Struct. Dyn. 20, 871-887) compare its
displacement update with the Taylor series of the exact motion: with ``a_n+1 - a_n = h a' + O(h^2)``
the update ``x_n+1 = x_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_n+1)`` differs from
``x(t_n+1)`` by ``(beta - 1/6) h^3 a'``. In the generalized-α family (Chung & Hulbert 1993) the
algorithmic acceleration ``a_n`` approximates ``a(t_n + (alpha_m - alpha_f) h)`` (the shift that
makes the scheme second order, ``gamma = 1/2 - alpha_m + alpha_f``), which adds
``(alpha_m - alpha_f)/2 h^3 a'`` to the update; the estimate of Hulbert & Jang (1995, "Automatic
time step control algorithms for structural dynamics", Comput. Methods Appl. Mech. Eng. 126,
155-178) for the family follows::

    (1)  e_n+1 = (beta - 1/6 + (alpha_m - alpha_f) / 2) h^2 (a_n+1 - a_n)     per free node [m]

(Newmark's ``beta - 1/6`` for ``alpha_m = alpha_f = 0``; 1/9 for the lumped default, WBZ-α with
``rho_inf = 0.5``). The local error is ``O(h^3)`` where the motion is smooth: halving the step
divides it by 8 (and the run's accumulated, global, error by 4). Its effect on the tensions is
measured, not linearised: the element tensions at ``x_n+1 + e_n+1`` against those at ``x_n+1``,
relative to the largest tension of the network at that step::

    (2)  r_n+1 = max_k |T_k(x_n+1 + e_n+1) - T_k(x_n+1)| / max(max_k |T_k(x_n+1)|, 1 N)

Both only observe: the steps are those of the scheme, bit for bit. The run keeps their maxima
over its steps, with where and when (:class:`TimeErrorEstimate`, eight numbers, as the compiled
steps keep them: :func:`kanat.lumped.fast_implicit.steps`), and reports eq. (2) as
``time_error_estimate``. Its thresholds (:data:`WARNING`, :data:`FAILURE`) are measured
(docs/lumped.md, "Time-step error estimate"; ``tests/lumped/test_time_error.py``).
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import entries
from kanat.lumped.fast_implicit import TENSION_FLOOR

WARNING = 0.02
"""Eq. (2) above which a run carries a note and a :class:`~kanat.errors.CaseWarning`: a step's error moves
a tension by 2 % of the network's largest. Resolved runs measured 0.00004-0.004 (the suite's MoorDyn
side-by-side cases and the lumped examples); unresolved ones 0.05-9 (WHOI's surface, seatex and
breaking cases at their own steps)."""
FAILURE = 0.5
"""Eq. (2) above which the run fails (at the output after the step): a single step moves a tension by half
the network's largest, so the tensions around it are not a solution of the equations at any precision."""
TARGET = 0.5 * WARNING
"""The eq. (2) a suggested step aims at."""
SIZE = 8
"""The record's length: displacement error [m], its time [s], free node; eq. (2), its time [s], element,
tension error [N], tension scale [N]."""


def error_factor(coefficients) -> float:
    """The factor of eq. (1) for ``(alpha_m, alpha_f, gamma, beta)``."""
    am, af, _, beta = coefficients
    return beta - 1.0 / 6.0 + 0.5 * (am - af)


def empty() -> np.ndarray:
    """A record (:data:`SIZE`,) before the first step."""
    return np.zeros(SIZE)


def observe(estimate, t, h, coefficients, a0, a1, x, v, free_index, el) -> None:
    """Update ``estimate`` with one step (the Python path; the compiled twin is
    :func:`kanat.lumped.fast_implicit.steps`).

    Parameters
    ----------
    estimate : ndarray (SIZE,)
        Running maxima, updated in place.
    t, h : float
        The step's end ``t_n+1`` and its size [s].
    coefficients : tuple
        ``(alpha_m, alpha_f, gamma, beta)``.
    a0, a1 : ndarray (n_free, 3)
        The free nodes' algorithmic accelerations at ``t_n`` and ``t_n+1`` [m/s^2].
    x, v : ndarray (n, 3)
        All nodes' positions and velocities at ``t_n+1``.
    free_index : ndarray (n_free,)
    el : kanat.lumped.entries.Elements
    """
    e = error_factor(coefficients) * h * h * (np.asarray(a1) - np.asarray(a0))       # eq. (1)
    size = np.linalg.norm(e, axis=1)
    f = int(np.argmax(size)) if len(size) else 0
    if len(size) and size[f] > estimate[0]:
        estimate[0:3] = size[f], t, f
    tension, moved = np.empty(el.length.shape[0]), np.empty(el.length.shape[0])
    entries.tensions(x, v, el, tension)
    shifted = np.array(x, dtype=float)
    shifted[free_index] += e
    entries.tensions(shifted, v, el, moved)
    scale = max(float(np.max(np.abs(tension), initial=0.0)), TENSION_FLOOR)
    error = np.abs(moved - tension)                                                    # eq. (2)
    k = int(np.argmax(error)) if len(error) else 0
    if len(error) and error[k] / scale > estimate[3]:
        estimate[3:8] = error[k] / scale, t, k, error[k], scale


def suggested_step(h: float, relative: float) -> float:
    """The step that would bring eq. (2) to :data:`TARGET`: the local error scales as ``h^3``."""
    return h * (TARGET / relative) ** (1.0 / 3.0) if relative > TARGET else h


def attributes(estimate) -> dict:
    """The result attributes of a run's estimate (``time_error_*``, documented in docs/results.md)."""
    return {"time_error_estimate": float(estimate[3]), "time_error_time": float(estimate[4]),
            "time_error_tension": float(estimate[6]), "time_error_displacement": float(estimate[0])}


def verdict(estimate, h: float, where) -> tuple[str, str] | None:
    """``("warning" | "failure", sentence)`` when eq. (2) is past :data:`WARNING`, else None; ``where(k)``
    names element ``k``."""
    relative = float(estimate[3])
    if relative <= WARNING:
        return None
    kind = "failure" if relative > FAILURE else "warning"
    k = int(estimate[5])
    text = (f"the time step does not resolve the motion: the local time-integration error estimate of the implicit "
            f"scheme at dt {h:.4g} s moves a tension by {100 * relative:.3g} % of the largest "
            f"({estimate[6]:.4g} N of {estimate[7]:.4g} N, at t = {estimate[4]:.6g} s in {where(k)}; a node by "
            f"{estimate[0]:.3g} m in one step), more than the {100 * (FAILURE if kind == 'failure' else WARNING):g} % "
            f"allowed; tensions can be tens of per cent off. This local error falls as dt^3 (the run's as dt^2): "
            f"rerun with dt <= {suggested_step(h, relative):.3g} s or scheme rk4")
    return kind, text
