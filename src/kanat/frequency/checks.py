"""Whether a frequency-domain result can be trusted: the linearisation's own checks (docs/frequency.md).

* **slack**: a node whose dynamic tension reaches its mean goes slack in the time domain (a
  snap load follows), which no linear model represents: the largest tension swing (a harmonic
  excitation's amplitudes summed; a spectral one's most probable maximum
  ``sigma sqrt(2 ln N)``, ``N = duration / T_z`` zero-upcrossings, ``T_z = 2 pi sqrt(m0/m2)``;
  Cartwright & Longuet-Higgins 1956) against the mean. Fails the result (``status``).
* **drag iteration**: the equivalent linearisation did not reach its fixed point. Fails it.
* **touchdown**: a node resting on the seabed whose contact force swings (``k A u_z``: seabed
  stiffness, contact area, vertical motion as amplitude or :data:`EXTREME_SIGMAS` sigma) beyond its
  static value ``N`` lifts off in the time domain, where the linear model keeps it grounded on the
  seabed's stiffness; a suspended node whose downward motion reaches the seabed lands on it, which
  the linear model does not see either; a touchdown node (the last grounded one) whose horizontal
  motion exceeds its element's length moves the touchdown point by more than one element. A note:
  the tension away from the touchdown zone is often still sound.
* **offset nonlinearity**: the catenary's quasi-static tension re-solved at the vessel's mean
  place +- its excursion (the harmonics' amplitude, or :data:`kanat.frequency.nonlinearity.SIGMAS`
  sigma of a sea state) departs from the linear model's straight line by ``r``
  (:mod:`kanat.frequency.nonlinearity` eq. 1); beyond :data:`~kanat.frequency.nonlinearity.LIMIT`
  the motion is outside the linear range: a warning (in ``notes`` and as a
  :class:`~kanat.errors.CaseWarning`) with the measured ``r``; beyond
  :data:`~kanat.frequency.nonlinearity.REFUSE` it fails the result.
* **body motion**: a body's degree of freedom both driven and damped by the lines' drag, and
  sensitive to its equivalent linearisation (:mod:`kanat.frequency.body_linearity` eq. 2, beyond
  :data:`~kanat.frequency.body_linearity.LIMIT`), may be far from the time domain however small
  the tension's nonlinearity: a warning naming the body and the degree of freedom.
"""
from __future__ import annotations

import warnings

import numpy as np

from kanat.errors import CaseWarning, SolverError
from kanat.frequency import body_linearity, nonlinearity
from kanat.physics.seabed import seabed_of

EXTREME_SIGMAS = 3.0       # sigma multiple taken as a spectral response's excursion in the touchdown check
DEFAULT_EXPOSURE = 10800.0   # s: a 3-hour storm, when the case has no simulation.duration


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
    notes += _touchdown(model, ex, ds, case)
    failure, note = _offset(model, ex, response, ds, case)
    failures += [failure] if failure else []
    notes += [note] if note else []
    for warning in body_linearity.body_notes(model, ex, response, list(model.lin.net.body_names)):
        warnings.warn(f"the frequency-domain result: {warning}", CaseWarning, stacklevel=3)
        notes.append("warning: " + warning)
    status = "ok" if not failures else "failed: " + "; ".join(failures)
    return status, "; ".join(notes)


def _offset(model, ex, response, ds, case) -> tuple[str | None, str | None]:
    """``(failure, note)`` of the offset nonlinearity check (module docstring)."""
    weight = ex.spectrum * ex.bandwidth if ex.spectral else np.full(len(ex.omega), 0.5)
    excursions = nonlinearity.vessel_excursions(response.prescribed, weight, ex.spectral)
    if not excursions:
        return None, None
    how = f"{nonlinearity.SIGMAS:g} sigma" if ex.spectral else "amplitude"
    dynamic = nonlinearity.SIGMAS * ds.tension_std.values if ex.spectral else ds.tension_amplitude.values.sum(axis=0)
    try:
        checks = [nonlinearity.offset_check(model, case, excursion, dynamic) for excursion in excursions]
    except SolverError as error:
        return (f"outside the linear range: the static equilibrium with the vessel offset by its excursion "
                f"({how}) did not converge ({error}); run method: time"), None
    check = max(checks, key=lambda c: float(np.max(c.ratio)))
    ratio = check.ratio
    worst = int(np.argmax(ratio))
    where = f"node {worst} (cable {ds.cable.values[worst]}, s = {float(ds.s.values[worst]):.4g} m)"
    measured = (f"the quasi-static tension at the vessel's mean place +- {check.distance:.3g} m ({how}) departs "
                f"from the linear model's by {100 * ratio[worst]:.3g} % at {where}: {check.mean[worst]:.4g} N "
                f"moves to {check.up[worst]:.4g} and {check.down[worst]:.4g} N")
    beyond = (f"outside the linear range: {measured}, beyond the {100 * nonlinearity.LIMIT:g} % the linearisation "
              "holds to (the line's stiffness changes over the motion); run method: time")
    if ratio[worst] > nonlinearity.REFUSE:
        return beyond, None
    if ratio[worst] > nonlinearity.LIMIT:
        warnings.warn(f"the frequency-domain result is {beyond}", CaseWarning, stacklevel=3)
        return None, "warning: " + beyond
    return None, measured


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


def _touchdown(model, ex, ds, case) -> list[str]:
    net = model.lin.net
    idx = net.node_index
    grounded = (model.contact_force > 0.0)[idx]
    amplitude = ds.motion_amplitude.values if not ex.spectral else None
    motion = _excursion(ex, amplitude, ds.motion_std.values)
    notes = []
    clearance = _clearance(model, case)[idx]
    landing = ~grounded & np.isfinite(clearance) & (clearance < motion[:, 2])
    if np.any(landing):
        worst = np.flatnonzero(landing)[np.argmin(clearance[landing] - motion[landing, 2])]
        notes.append(f"{int(landing.sum())} suspended node(s) move down to the seabed (node {worst}: "
                     f"{motion[worst, 2]:.3g} m of motion, {clearance[worst]:.3g} m above it): they land in the "
                     "time domain; check the touchdown zone with method: time")
    if not np.any(grounded):
        return notes
    stiffness = (case.environment.with_seabed_contact().seabed.stiffness * net.node_contact_area)[idx]
    lift = grounded & (stiffness * motion[:, 2] > model.contact_force[idx])
    if np.any(lift):
        notes.append(f"{int(lift.sum())} grounded node(s) whose contact force swings beyond its static value "
                     f"(node {int(np.flatnonzero(lift)[0])}): they lift off in the time domain, where the linear model "
                     "holds them on the seabed's stiffness; check the touchdown zone with method: time")
    cable, length = ds.cable.values, _adjacent_length(net)[idx]
    after = np.concatenate([cable[1:], [""]]) == cable            # the next node is on the same cable
    before = np.concatenate([[""], cable[:-1]]) == cable
    touchdown = grounded & ((after & ~np.r_[grounded[1:], False]) | (before & ~np.r_[False, grounded[:-1]]))
    across = np.hypot(motion[:, 0], motion[:, 1])
    moving = touchdown & (across > length)
    if np.any(moving):
        notes.append(f"the touchdown point moves by more than one element ({across[moving].max():.3g} m against "
                     f"{length[moving].min():.3g} m elements): seabed contact is linearised at the equilibrium")
    return notes


def _clearance(model, case) -> np.ndarray:
    """Each node's height above the seabed at the equilibrium (n,) [m] (inf without ``depth``): the
    seabed every model applies (:meth:`kanat.model.Environment.with_seabed_contact`), so that a case
    giving ``depth`` alone is checked against its seabed too, even when no line reaches it at rest
    (a buoyant line, which then has no contact model)."""
    x = model.lin.position
    environment = case.environment.with_seabed_contact()
    if environment.seabed is None:
        return np.full(len(x), np.inf)
    bed = seabed_of(environment)
    return x[:, 2] - np.asarray(bed.height(x[:, 0], x[:, 1]), float)


def _adjacent_length(net) -> np.ndarray:
    """The shortest unstretched element at each node (n,) [m]."""
    out = np.full(net.n_nodes, np.inf)
    np.minimum.at(out, net.el_i, net.el_length)
    np.minimum.at(out, net.el_j, net.el_length)
    return out
