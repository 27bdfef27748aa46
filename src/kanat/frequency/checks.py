"""Whether a frequency-domain result can be trusted: the linearisation's own checks (docs/frequency.md).

* **slack**: a node whose dynamic tension reaches its mean goes slack in the time domain (a
  snap load follows), which no linear model represents: the largest tension swing (a harmonic
  excitation's amplitudes summed; a spectral one's most probable maximum
  ``sigma sqrt(2 ln N)``, ``N = duration / T_z`` zero-upcrossings, ``T_z = 2 pi sqrt(m0/m2)``;
  Cartwright & Longuet-Higgins 1956) against the mean. Fails the result (``status``).
* **drag iteration**: the equivalent linearisation did not reach its fixed point. Fails it.
* **touchdown**: a node resting on the seabed whose vertical motion (amplitude or
  :data:`EXTREME_SIGMAS` sigma) exceeds :data:`LIFT_OFF_SHARE` of its element's length lifts off
  in the time domain, where the linear model keeps it grounded with the seabed's stiffness;
  likewise a touchdown node (the last grounded one) whose horizontal motion exceeds its element's
  length moves the touchdown point by more than one element. A note: the tension away from the
  touchdown zone is often still sound.
"""
from __future__ import annotations

import numpy as np

EXTREME_SIGMAS = 3.0       # sigma multiple taken as a spectral response's excursion in the touchdown check
DEFAULT_EXPOSURE = 10800.0   # s: a 3-hour storm, when the case has no simulation.duration
LIFT_OFF_SHARE = 0.1       # of the element length: a grounded node moving up more than this lifts off


def trust_checks(model, ex, ds, response, case) -> tuple[str, str]:
    """``(status, notes)`` of a frequency-domain result (module docstring)."""
    failures, notes = [], []
    if not response.converged:
        failures.append(f"the equivalent drag linearisation did not converge in {response.iterations} iterations "
                        f"(last change {response.change:.2g}); the sea may be too severe for a linear model: "
                        "run method: time")
    swing, what = _tension_swing(ds, ex, case)
    mean = ds.mean_tension.values
    ratio = swing / np.maximum(mean, 1e-300)
    worst = int(np.argmax(ratio))
    if ratio[worst] >= 1.0:
        failures.append(f"slack: the dynamic tension ({what} {swing[worst]:.4g} N) exceeds the mean "
                        f"({mean[worst]:.4g} N) at node {worst} (cable {ds.cable.values[worst]}, s = "
                        f"{float(ds.s.values[worst]):.4g} m): the line goes slack and snaps, which the linear "
                        "model does not represent; run method: time")
    else:
        notes.append(f"the largest dynamic tension ({what}) is {100 * ratio[worst]:.3g} % of the mean, at node {worst}")
    notes += _touchdown(model, ex, ds)
    status = "ok" if not failures else "failed: " + "; ".join(failures)
    return status, "; ".join(notes)


def _tension_swing(ds, ex, case) -> tuple[np.ndarray, str]:
    if not ex.spectral:
        return ds.tension_amplitude.values.sum(axis=0), "amplitude"
    S = ds.tension_spectrum.values
    m0 = S.sum(axis=0) * ex.bandwidth
    m2 = (ex.omega[:, None] ** 2 * S).sum(axis=0) * ex.bandwidth
    tz = 2.0 * np.pi * np.sqrt(m0 / np.maximum(m2, 1e-300))
    exposure = case.simulation.duration if case.simulation is not None else DEFAULT_EXPOSURE
    cycles = np.maximum(exposure / np.maximum(tz, 1e-300), np.e)
    return np.sqrt(m0) * np.sqrt(2.0 * np.log(cycles)), "most probable maximum over simulation.duration"


def _excursion(ex, amplitude: np.ndarray, std: np.ndarray) -> np.ndarray:
    return EXTREME_SIGMAS * std if ex.spectral else amplitude.sum(axis=0)


def _touchdown(model, ex, ds) -> list[str]:
    net = model.lin.net
    grounded_nodes = model.contact_force > 0.0
    if not np.any(grounded_nodes):
        return []
    idx = net.node_index
    grounded = grounded_nodes[idx]
    amplitude = ds.motion_amplitude.values if not ex.spectral else None
    motion = _excursion(ex, amplitude, ds.motion_std.values)
    length = _adjacent_length(net)[idx]
    notes = []
    lift = grounded & (motion[:, 2] > LIFT_OFF_SHARE * length)
    if np.any(lift):
        notes.append(f"{int(lift.sum())} grounded node(s) move up by more than {LIFT_OFF_SHARE:g} of their element "
                     f"length (up to {motion[lift, 2].max():.3g} m): they lift off in the time domain, where the "
                     "linear model holds them on the seabed's stiffness; check the touchdown zone with method: time")
    cable = ds.cable.values
    after = np.concatenate([cable[1:], [""]]) == cable            # the next node is on the same cable
    before = np.concatenate([[""], cable[:-1]]) == cable
    touchdown = grounded & ((after & ~np.r_[grounded[1:], False]) | (before & ~np.r_[False, grounded[:-1]]))
    across = np.hypot(motion[:, 0], motion[:, 1])
    moving = touchdown & (across > length)
    if np.any(moving):
        notes.append(f"the touchdown point moves by more than one element ({across[moving].max():.3g} m against "
                     f"{length[moving].min():.3g} m elements): seabed contact is linearised at the equilibrium")
    return notes


def _adjacent_length(net) -> np.ndarray:
    """The shortest unstretched element at each node (n,) [m]."""
    out = np.full(net.n_nodes, np.inf)
    np.minimum.at(out, net.el_i, net.el_length)
    np.minimum.at(out, net.el_j, net.el_length)
    return out
