"""A posteriori estimate of the implicit lumped scheme's local time-integration error.

For Newmark's scheme, Zienkiewicz & Xie (1991, "A simple error estimator and adaptive time
stepping procedure for dynamic analysis", Earthquake Eng. Struct. Dyn. 20, 871-887) compare its
displacement update with the Taylor series of the exact motion: with ``a_n+1 - a_n = h a' + O(h^2)``
the update ``x_n+1 = x_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_n+1)`` differs from
``x(t_n+1)`` by ``(beta - 1/6) h^3 a'``. In the generalized-α family (Chung & Hulbert 1993) the
algorithmic acceleration ``a_n`` approximates ``a(t_n + (alpha_m - alpha_f) h)`` (the shift that
makes the scheme second order, ``gamma = 1/2 - alpha_m + alpha_f``), which adds
``(alpha_m - alpha_f)/2 h^3 a'`` to the update. The estimate for the family follows (derived as
Hulbert & Jang 1995, "Automatic time step control algorithms for structural dynamics", Comput.
Methods Appl. Mech. Eng. 126, 155-178, derive theirs; ``tests/lumped/test_time_error.py`` checks it
against the exact local error of an oscillator, to 2 %)::

    (1)  e_n+1 = (beta - 1/6 + (alpha_m - alpha_f) / 2) h^2 (a_n+1 - a_n)     per free node [m]

(Newmark's ``beta - 1/6`` for ``alpha_m = alpha_f = 0``; 1/9 for the lumped default, WBZ-α with
``rho_inf = 0.5``). The local error is ``O(h^3)`` where the motion is smooth: halving the step
divides it by 8 (and the run's accumulated, global, error by 4). It is judged against the step's own
motion, over the whole network::

    (2)  eta_n+1 = ||e_n+1|| / max(||x_n+1 - x_n||, d_0 sqrt(n_free))    (2-norms over the free nodes)
         d_0 = max(1e-6 m, RESOLUTION l_min)

and the run keeps its largest value: a relative error of the step's displacement, small where the
step follows the motion, near or above 1 where the motion within a step is not the one the step
takes (a snap, a slap on the seabed, a start the scheme damps). ``d_0`` is the line's own scale of rest
(:data:`RESOLUTION` of the network's shortest element ``l_min``): a step that moves its nodes by less
is a line at rest, and its error is judged against ``d_0``, not against a displacement of nothing (a
150 m chain laid still on the seabed moved 1e-7 m a step, and its error of 1.3e-6 m read 20 % of
it). It is not turned into a tension
error: the tensions at ``x_n+1 + e_n+1`` against those at ``x_n+1`` read 118 % on WD0050 at 0.1 s,
whose tensions move by 1.2 % at dt/2 (an axial part of ``e`` is not an error the run keeps: the stiff
axial modes, far above ``1/h``, sit at their quasi-static place after every step).

A start from rest (a line at rest under a vessel that moves, a sea or current switched on at ``t = 0``)
is a transient eq. (2) cannot judge: a step from rest moves by ``O(h^2)``, and eq. (2) reads the same
whatever the step there (:data:`START_STEPS`). The run's start is judged instead by a step pair: its first
:data:`START_STEPS` steps are taken again, on a copy, at ``h`` and at ``h/2``, and their tensions
compared at the steps' ends ``t_k``::

    (3)  delta = max_k max_j |T_j^h(t_k) - T_j^(h/2)(t_k)| / max_k max_j |T_j^(h/2)(t_k)|

the oracle the thresholds are measured with (the tensions at dt and dt/2), over the start only: it is
what eq. (2) misses there. A start the step resolves reads well below :data:`WARNING` (MoorDyn's WD0050
chain driven from rest: 0.0062 at 0.1 s, 0.0017 at its default 0.02 s); a start that rings the lines faster
than the step follows reads above it: ``examples/lazy_wave.yaml`` with its motion's ramp taken off, whose
fairlead accelerates at once (0.79 m/s^2 in heave from rest), its top tension ringing from 42 to 54 kN and
back within 0.2 s, reads 0.076 at 0.2 s, 0.075 at 0.1 s, 0.036 at its own 0.05 s and 0.014 at 0.025 s; as
shipped, its motion ramped up over 10 s, 0.0087 at 0.05 s. Its cost is
``3 START_STEPS`` steps once per run.

All three only observe: the steps are those of the scheme, bit for bit. The run keeps their maxima
over its steps, with where and when (:data:`SIZE` numbers, as the compiled steps keep them:
:func:`kanat.lumped.fast_implicit.steps`), and reports them as ``time_error_*`` attributes
(:func:`attributes`). The thresholds, :data:`WARNING` on eqs. (2) and (3) and :data:`FAILURE` on eq. (2), are measured
(docs/lumped.md, "Time-step error estimate"; ``tests/lumped/test_time_error.py``).
"""
from __future__ import annotations

import numpy as np

from kanat.lumped.fast_implicit import MOTION_FLOOR

WARNING = 0.02
"""Eq. (2) or eq. (3) above which a run carries a note and a :class:`~kanat.errors.CaseWarning`. Measured (largest
over the run, after a start's steps): resolved runs 1.7e-3 (``examples/lazy_wave.yaml`` at its 0.05 s) and
0.0094 (MoorDyn's WD0050 chain driven at its fairlead, the default 0.1 s: fairlead tension within 0.5 % of
MoorDyn's, all tensions within 1.2 % of the largest at 0.05 s); unresolved runs 0.043 (WHOI seatex's chain in
a 1 m wave at its 0.05 s, snap peaks 45 % of the largest tension apart at dt/2) and 0.065 (WHOI breaking's
cable falling slack after its release, at 0.25 s; 0.051 at 0.125 s: tensions 56 % apart)."""
FAILURE = 1.0
"""Eq. (2) above which the run fails (at the output after the step): the step's error is as large as its
displacement, no motion at all. Below it the measured unresolved runs warn: 0.62 for a released 20 m wire
falling through its own slack at 10 ms (axial period 3.6 ms; snap peaks 12 times rk4's,
``tests/lumped/test_lumped_snap_step.py``), 0.065 for WHOI breaking."""
TARGET = 0.5 * WARNING
"""The eq. (2) a suggested step aims at."""
RESOLUTION = 1e-5
"""``d_0`` of eq. (2) as a fraction of the shortest element's length: a step moving every node by less
than this is the line at rest. Below it eq. (2) reads at most :data:`WARNING` for an error of ``2e-7 l``
per node, an axial strain error of 2e-7 (160 N on a chain of EA 8e8 N, 0.1 % of the pull of 100 m of it
hanging), which no tension, position or snap of a run reads. A 150 m chain (5 m elements) at rest on the
seabed of 100 m of water at dt 0.1 s: 0.199 with the floor at 1e-6 m alone, 0.0064 with this one. The
runs :data:`WARNING` and :data:`FAILURE` were measured on warn, fail or stay quiet as before
(``tests/lumped/test_time_error.py``, ``tests/whoi/test_whoi_time_error.py``)."""
SIZE = 9
"""The record's length: the largest eq. (1) [m], its time [s], free node; eq. (2), its time [s]; the start's
steps still to pass over in eq. (2); eq. (3), its time [s] (NaN until the start is checked); ``d_0`` of eq. (2)
[m] (:func:`motion_floor`)."""
START_STEPS = 10
"""Steps after a start (the run's, or the implicit scheme's restart after explicit steps) eq. (2) passes over.
A step from rest moves by ``O(h^2)``, not ``h v``: there eq. (2) compares the error with a displacement that
is not the motion's, and reads the same whatever the step. Measured on ``examples/lazy_wave.yaml`` with its
motion's ramp taken off (a line at rest whose fairlead starts from rest at 0.79 m/s^2) at dt 0.2, 0.1 and 0.05 s: 0.25 on the first step for all three
(``(beta - 1/6 + alpha_m/2) / beta`` for a step from rest), 0.013, 0.037 and 0.061 on the second (growing as
the step shrinks), 0.02 or less from the third; on WD0050 0.25 on the first step at 0.1 and 0.05 s
(``tests/lumped/test_time_error_start.py``). The run's start is judged by eq. (3)
instead (:func:`start_difference`), which does not divide by the start's displacement. A restart after
explicit steps (a moving state) passes over the same steps: the generalized-α accelerations the restart
hands the scheme are the equations', which the scheme's own lag by ``(alpha_m - alpha_f) h``."""


def error_factor(coefficients) -> float:
    """The factor of eq. (1) for ``(alpha_m, alpha_f, gamma, beta)``."""
    am, af, _, beta = coefficients
    return beta - 1.0 / 6.0 + 0.5 * (am - af)


def motion_floor(element_length) -> float:
    """``d_0`` of eq. (2) [m] for a network of elements of unstretched lengths ``element_length`` (m,) [m]."""
    shortest = float(np.min(element_length, initial=np.inf))
    return max(MOTION_FLOOR, RESOLUTION * shortest) if np.isfinite(shortest) else MOTION_FLOOR


def empty(floor: float = MOTION_FLOOR) -> np.ndarray:
    """A record (:data:`SIZE`,) before the first step, with ``d_0`` of eq. (2) ``floor`` [m]
    (:func:`motion_floor`)."""
    record = np.zeros(SIZE)
    restart(record)
    record[6:8] = np.nan
    record[8] = floor
    return record


def restart(estimate) -> None:
    """Pass over the next :data:`START_STEPS` steps (after a start)."""
    estimate[5] = START_STEPS


def start_pending(estimate) -> bool:
    """Whether the run's start is still to be checked by eq. (3)."""
    return bool(np.isnan(estimate[6]))


def start_difference(times, coarse, fine) -> tuple[float, float]:
    """Eq. (3) of a start's step pair: ``(delta, t_k)``, its value and the time of its largest difference.

    Parameters
    ----------
    times : ndarray (k,)
        The ends ``t_k`` of the start's steps [s].
    coarse, fine : ndarray (k, m)
        The element tensions at ``t_k`` of the steps of ``h`` and of ``h/2`` [N].
    """
    coarse, fine = np.asarray(coarse, dtype=float), np.asarray(fine, dtype=float)
    if not coarse.size:
        return 0.0, float("nan")
    gap = np.max(np.abs(coarse - fine), axis=1)
    k = int(np.argmax(gap))
    return float(gap[k] / max(np.max(np.abs(fine)), np.finfo(float).tiny)), float(times[k])


def observe(estimate, t, h, coefficients, x0, a0, a1, x) -> None:
    """Update ``estimate`` with one step (the Python path; the compiled twin is
    :func:`kanat.lumped.fast_implicit.observe_error`).

    Parameters
    ----------
    estimate : ndarray (SIZE,)
        Running maxima, updated in place.
    t, h : float
        The step's end ``t_n+1`` and its size [s].
    coefficients : tuple
        ``(alpha_m, alpha_f, gamma, beta)``.
    x0, x : ndarray (n_free, 3)
        The free nodes' positions at ``t_n`` and ``t_n+1`` [m].
    a0, a1 : ndarray (n_free, 3)
        The free nodes' algorithmic accelerations at ``t_n`` and ``t_n+1`` [m/s^2].
    """
    if estimate[5] > 0.0:
        estimate[5] -= 1.0
        return
    e = error_factor(coefficients) * h * h * (np.asarray(a1) - np.asarray(a0))       # eq. (1)
    size = np.linalg.norm(e, axis=1)
    if not len(size):
        return
    f = int(np.argmax(size))
    if size[f] > estimate[0]:
        estimate[0:3] = size[f], t, f
    moved = np.linalg.norm(np.asarray(x) - np.asarray(x0))
    floor = max(MOTION_FLOOR, float(estimate[8])) * np.sqrt(len(size))
    ratio = np.linalg.norm(e) / max(moved, floor)                                        # eq. (2)
    if ratio > estimate[3]:
        estimate[3:5] = ratio, t


def suggested_step(h: float, relative: float) -> float:
    """The step that would bring eq. (2) to :data:`TARGET`: ``e`` scales as ``h^3`` and a step's displacement
    as ``h``, so eq. (2) as ``h^2``."""
    return h * (TARGET / relative) ** 0.5 if relative > TARGET else h


def attributes(estimate) -> dict:
    """The result attributes of a run's estimate (docs/results.md); eq. (3)'s once the start is checked."""
    out = {"time_error_estimate": float(estimate[3]), "time_error_time": float(estimate[4]),
           "time_error_displacement": float(estimate[0])}
    if not start_pending(estimate):
        out.update({"time_error_start": float(estimate[6]), "time_error_start_time": float(estimate[7])})
    return out


def findings(estimate, h: float, where) -> dict:
    """``{"steps": (kind, sentence), "start": (kind, sentence)}`` for eq. (2) and eq. (3) past :data:`WARNING`
    (``kind`` "warning" or "failure"; a cause below it is left out); ``where(f)`` names free node ``f``."""
    found = {"steps": _stepping(estimate, h, where), "start": _start(estimate, h)}
    return {cause: part for cause, part in found.items() if part is not None}


def verdict(estimate, h: float, where) -> tuple[str, str] | None:
    """``("warning" | "failure", sentence)`` when eq. (2) or eq. (3) is past :data:`WARNING` (the graver
    kind, the sentences of both causes), else None; ``where(f)`` names free node ``f``."""
    found = list(findings(estimate, h, where).values())
    if not found:
        return None
    kind = "failure" if any(part[0] == "failure" for part in found) else "warning"
    return kind, "; ".join(part[1] for part in found)


def _kind(relative: float) -> tuple[str, float] | None:
    """The verdict on a relative error and the threshold it passed, or None below :data:`WARNING`."""
    if not relative > WARNING:
        return None
    return ("failure", FAILURE) if relative > FAILURE else ("warning", WARNING)


def _stepping(estimate, h, where) -> tuple[str, str] | None:
    relative = float(estimate[3])
    found = _kind(relative)
    if found is None:
        return None
    kind, limit = found
    return kind, (
        f"the time step does not resolve the motion: the implicit scheme's local time-integration error estimate "
        f"at dt {h:.4g} s is {100 * relative:.3g} % of a step's displacement at t = {estimate[4]:.6g} s (more than "
        f"{100 * limit:g} %; a node's largest error in one step is {estimate[0]:.3g} m, at t = {estimate[1]:.6g} s, "
        f"{where(int(estimate[2]))}); rerun with dt <= "
        f"{suggested_step(h, relative):.3g} s (the local error falls as dt^3, this ratio as dt^2, where the motion "
        "is smooth; through snaps, below the shortest axial nodal period) or scheme rk4")


def _start(estimate, h) -> tuple[str, str] | None:
    """Eq. (3)'s verdict: a warning, never a failure. The start's tensions at dt and dt/2 may differ by
    all of the largest one (a dropped anchor's line snapping taut at 0.2 s: 1.004) while what the run
    is for, later, is resolved (the anchor resting on the seabed on its weight,
    tests/whoi/test_whoi_events.py); eq. (2), which judges every step, fails a run whose steps are wrong."""
    relative = float(estimate[6])                           # NaN before the check: no verdict
    if not relative > WARNING:
        return None
    limit = WARNING
    return "warning", (
        f"the time step does not resolve the start: over the first {START_STEPS} steps the tensions at dt "
        f"{h:.4g} s and at dt/2 differ by {100 * relative:.3g} % of the largest tension at t = {estimate[7]:.6g} s "
        f"(more than {100 * limit:g} %); a start that rings the lines (a vessel motion, waves or a current "
        "starting at full strength on a line at rest) needs a step that follows the ringing: give vessel.motion, "
        "environment.waves or environment.current a ramp, or rerun with a smaller dt (until dt and dt/2 agree)")
