"""``kanat.solve_frequency``: a case's linear response to its sea and vessel motion, as a Dataset.

Outputs (docs/frequency.md; ``X`` a complex amplitude, ``|X| cos(omega t + arg X)``):

* per unit of the excitation's reference amplitude (the wave amplitude, or without waves the vessel
  harmonic's): ``tension_rao_amplitude(frequency, node)`` [N/m], ``tension_rao_phase`` [rad],
  ``motion_rao_amplitude(frequency, node, xyz)`` [m/m], ``motion_rao_phase`` [rad],
  ``body_motion_rao_amplitude(frequency, body, dof)`` [m/m, rad/m], ``body_motion_rao_phase``;
* a harmonic excitation's own amplitudes: ``tension_amplitude(frequency, node)`` [N],
  ``tension_phase`` [rad], ``motion_amplitude(frequency, node, xyz)`` [m], ``motion_phase``;
* a spectral one's spectra: ``wave_spectrum(frequency)`` [m^2 s/rad], ``tension_spectrum(frequency,
  node)`` [N^2 s/rad] ``= |H_T|^2 S``, ``motion_spectrum(frequency, node, xyz)`` [m^2 s/rad], and
  ``frequency_width(frequency)`` [rad/s], the band each line stands for (the sea's bin width
  ``d omega``; the lines are unequally spaced, :mod:`kanat.frequency.excitation`): a spectrum's
  moments are ``sum omega^n S frequency_width``
  (:func:`kanat.analysis.spectral.spectral_moments` with ``width``);
* ``tension_std(node)`` [N], ``motion_std(node, xyz)`` [m], ``body_motion_std(body, dof)``: the
  square roots of ``sum S d omega`` (spectral) or ``sum |X|^2 / 2`` (harmonic);
* ``mean_tension(node)`` [N] and ``position(node, xyz)`` [m]: the equilibrium.
"""
from __future__ import annotations

import time
import warnings

import numpy as np
import xarray as xr

from kanat.errors import CaseWarning
from kanat.io.provenance import provenance
from kanat.frequency.assembly import element_tension, linear_model, node_displacements, node_tension
from kanat.frequency.checks import trust_checks
from kanat.frequency.excitation import excitation_of
from kanat.frequency.linearize import about_mean, after_ramps
from kanat.frequency.response import solve

DOFS = ("x", "y", "z", "roll", "pitch", "yaw")


def solve_frequency(case) -> xr.Dataset:
    """The frequency-domain response of a case (module docstring), linearised about the lumped
    model's equilibrium.

    Parameters
    ----------
    case : kanat.model.Case
        Excited by ``environment.waves`` (regular, components or JONSWAP) and/or ``vessel.motion``
        (harmonics, or RAOs in the case's sea).

    Returns
    -------
    xarray.Dataset
        Coordinate ``frequency`` [rad/s]; ``attrs["status"]`` is ``ok`` or says which check of the
        linearisation failed, ``attrs["notes"]`` what to beware of.
    """
    start = time.perf_counter()
    if case.model != "lumped":
        warnings.warn(f"the frequency domain linearises the lumped model (the system discretized as in "
                      f"model: lumped), not model: {case.model}", CaseWarning, stacklevel=2)
    ex = excitation_of(after_ramps(case))   # the steady state: a ramped current at its full speed
    steady = about_mean(case)               # ... and the vessel at its motion's mean place
    model = linear_model(steady)
    response = solve(model, ex)
    U = node_displacements(model, response.free, response.prescribed)
    tension = node_tension(model, element_tension(model, U, ex.omega))
    ds = _dataset(model, ex, U, tension)
    status, notes = trust_checks(model, ex, ds, response, steady)
    ds.attrs.update(provenance(case, model="frequency", scheme="frequency-domain", status=status,
                               wall_time_s=time.perf_counter() - start),
                    notes=notes, iterations=response.iterations)
    return ds


def _weight(ex) -> np.ndarray:
    """Variance per ``|X|^2`` at each frequency: ``S d omega`` (spectral) or ``1/2`` (harmonic)."""
    return ex.spectrum * ex.bandwidth if ex.spectral else np.full(len(ex.omega), 0.5)


def _dataset(model, ex, U: np.ndarray, tension: np.ndarray) -> xr.Dataset:
    net, lin = model.lin.net, model.lin
    idx = net.node_index
    motion = U[:, idx]
    reference = np.where(ex.reference > 0, ex.reference, np.nan)
    weight = _weight(ex)
    body = np.zeros((len(ex.omega), len(net.body_names), 6), complex)
    body[:, :, :3] = U[:, net.body_node]
    for b, name in enumerate(net.rigid.names):
        body[:, net.body_names.index(name), 3:] = U[:, net.rigid.rot_node[b]]
    data = {
        "tension_rao_amplitude": (("frequency", "node"), np.abs(tension) / reference[:, None], {"units": "N/m"}),
        "tension_rao_phase": (("frequency", "node"), np.angle(tension), {"units": "rad"}),
        "tension_std": ("node", np.sqrt(weight @ np.abs(tension) ** 2), {"units": "N"}),
        "mean_tension": ("node", model.node_tension(model.mean_tension), {"units": "N"}),
        "motion_rao_amplitude": (("frequency", "node", "xyz"), np.abs(motion) / reference[:, None, None],
                                 {"units": "m/m"}),
        "motion_rao_phase": (("frequency", "node", "xyz"), np.angle(motion), {"units": "rad"}),
        "motion_std": (("node", "xyz"), np.sqrt(np.einsum("f,fnr->nr", weight, np.abs(motion) ** 2)), {"units": "m"}),
        "body_motion_rao_amplitude": (("frequency", "body", "dof"), np.abs(body) / reference[:, None, None],
                                      {"units": "m/m (angles: rad/m)"}),
        "body_motion_rao_phase": (("frequency", "body", "dof"), np.angle(body), {"units": "rad"}),
        "body_motion_std": (("body", "dof"), np.sqrt(np.einsum("f,fbd->bd", weight, np.abs(body) ** 2)),
                            {"units": "m (angles: rad)"}),
        "position": (("node", "xyz"), lin.position[idx], {"units": "m"}),
    }
    if ex.spectral:
        data["wave_spectrum"] = ("frequency", ex.spectrum, {"units": "m^2 s/rad"})
        data["frequency_width"] = ("frequency", np.full(len(ex.omega), ex.bandwidth), {"units": "rad/s"})
        data["tension_spectrum"] = (("frequency", "node"), np.abs(tension) ** 2 * ex.spectrum[:, None],
                                    {"units": "N^2 s/rad"})
        data["motion_spectrum"] = (("frequency", "node", "xyz"), np.abs(motion) ** 2 * ex.spectrum[:, None, None],
                                   {"units": "m^2 s/rad"})
    else:
        data["tension_amplitude"] = (("frequency", "node"), np.abs(tension), {"units": "N"})
        data["tension_phase"] = (("frequency", "node"), np.angle(tension), {"units": "rad"})
        data["motion_amplitude"] = (("frequency", "node", "xyz"), np.abs(motion), {"units": "m"})
        data["motion_phase"] = (("frequency", "node", "xyz"), np.angle(motion), {"units": "rad"})
    return xr.Dataset(
        data,
        coords={"frequency": ("frequency", ex.omega, {"units": "rad/s"}), "xyz": list(DOFS[:3]), "dof": list(DOFS),
                "body": list(net.body_names), "cable": ("node", net.node_cable.astype(str)),
                "s": ("node", net.node_s, {"units": "m"})},
        attrs={"model": "frequency", "discretization": "lumped",
               "excitation": "spectral" if ex.spectral else "harmonic",
               "phase_convention": "X(t) = |X| cos(omega t + phase); waves: eta = a cos(omega t - k x - phi)"})
