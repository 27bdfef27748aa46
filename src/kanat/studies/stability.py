"""Stability sweep of a continuum scheme over time steps (Kaliukh & Vusatiuk 2018, section 4; theory/time-schemes.md §3).

Kaliukh & Vusatiuk 2018 reports the Courant numbers within which its quasi-linearized wave-factorized
Crank–Nicolson scheme stays stable: ``sigma_long = c_l dt / ds`` in about [2, 200] and
``sigma_tr = c_t dt / ds`` in [1, 1000]. :func:`stability_sweep` measures this for any
scheme on any case: it runs the case once per time step, in memory, and reports for each
run the two Courant numbers (``c_l = sqrt(EA/m)``; ``c_t = sqrt(T/((m+m_a)(1+e)))`` at the
initial state's largest tension), whether the run stayed bounded, and how far it ended
from a reference solution (by default the generalized-α scheme at the smallest step).

A run is *bounded* when every step succeeded (no NaN, no unsolvable end, no compression
where the scheme needs tension) and its tension never exceeded ``BOUND_FACTOR`` times the
reference's largest tension.
"""
from __future__ import annotations

import dataclasses
import time

import numpy as np
import xarray as xr

from kanat import api, dynamics
from kanat.continuum.courant import courant_numbers
from kanat.continuum.models import model_for
from kanat.errors import SolverError
from kanat.continuum.schemes import SCHEMES
from kanat.schemes import get_scheme

BOUND_FACTOR = 10.0           # tension beyond this multiple of the reference's largest tension is unbounded
REFERENCE = "generalized-alpha"


class PeakTension:
    """Run-loop observer: the largest tension so far, the last state, and a stop beyond ``bound`` [N]."""

    def __init__(self, bound: float = np.inf):
        self.bound, self.peak, self.state = bound, 0.0, None

    def start(self, layout, resume_at=None):
        """Nothing to prepare."""

    def record(self, point) -> None:
        self.state = point.state
        self.peak = max(self.peak, float(np.max(np.abs(point.values["tension"]))))
        if self.peak > self.bound:
            raise dynamics.StopRun(f"tension {self.peak:.3g} N beyond the bound {self.bound:.3g} N at "
                                   f"t = {point.time:.4g} s")

    def flush(self):
        """Nothing buffered."""

    def finish(self, status, final, attrs):
        """Nothing to close."""


def run_in_memory(case, scheme, dt: float, duration: float, bound: float = np.inf):
    """Run ``case`` with ``scheme`` and step ``dt`` for ``duration`` through the run loop, checking the
    tension after every step: ``(last_state, peak_tension, status)``."""
    varied = case.replace({"simulation.dt": dt, "simulation.output_dt": dt,
                           "simulation.duration": round(duration / dt) * dt})
    peak = PeakTension(bound)
    with np.errstate(all="ignore"):
        summary = dynamics.run(lambda: api.dynamic_model(varied, scheme), [peak])
    return peak.state, peak.peak, summary.status.removeprefix("failed: ")


def stability_sweep(case, scheme, dts, duration: float | None = None, reference=None,
                    reference_dt: float | None = None) -> xr.Dataset:
    """Run ``case`` with ``scheme`` at every step in ``dts`` and report stability and accuracy.

    Parameters
    ----------
    case : kanat.model.Case
        A ``model: continuum`` case.
    scheme : str or ContinuumScheme
        The scheme under test (a name takes the case's ``gamma`` and ``lambda_inf``).
    dts : sequence of float
        Time steps [s].
    duration : float, optional
        Simulated time of each run (default: the case's duration); choose steps that divide
        it, so that every run ends at the same time.
    reference : str or ContinuumScheme, optional
        Scheme of the reference run (default generalized-α).
    reference_dt : float, optional
        Its step (default: the smallest of ``dts``).

    Returns
    -------
    xarray.Dataset
        Over dimension ``run``: ``dt``, ``sigma_long``, ``sigma_tr``, ``bounded``,
        ``status``, ``tension_error`` (largest |T - T_ref| at the end over the reference's
        largest tension), ``position_error`` (largest node distance at the end over the
        cable length), ``peak_tension`` and ``wall_time_s``; attributes name the case,
        the scheme and the reference, and give the stable Courant range
        (:func:`stable_range`).
    """
    sim = case.simulation
    chosen = get_scheme(scheme, SCHEMES, lambda_inf=sim.lambda_inf, gamma=sim.gamma)
    if "check_stability" in chosen.parameters():                # the sweep goes past the known range
        chosen = dataclasses.replace(chosen, check_stability=False)
    ref_scheme = get_scheme(reference or REFERENCE, SCHEMES, lambda_inf=sim.lambda_inf, gamma=sim.gamma)
    dts = np.sort(np.asarray(dts, dtype=float))
    duration = duration if duration is not None else sim.duration
    ref_dt = reference_dt or dts[0]
    ref_state, ref_peak, ref_status = run_in_memory(case, ref_scheme, ref_dt, duration)
    if ref_status != "ok":
        raise SolverError(f"the reference run ({ref_scheme.name}, dt = {ref_dt:g} s) failed: {ref_status}")
    model = model_for(case)
    initial = model.initial()
    length = model.cable.length
    rows = []
    for dt in dts:
        start = time.perf_counter()
        state, peak, status = run_in_memory(case, chosen, dt, duration, BOUND_FACTOR * ref_peak)
        wall = time.perf_counter() - start
        ok = status == "ok"
        sigma_long, sigma_tr = courant_numbers(model, initial, dt)
        tension_error = float(np.max(np.abs(state.y[:, 0] - ref_state.y[:, 0])) / ref_peak) if ok else np.nan
        position_error = float(np.max(np.linalg.norm(_positions(state) - _positions(ref_state), axis=1))
                               / length) if ok else np.nan
        rows.append((dt, sigma_long, sigma_tr, ok, status, tension_error, position_error, peak, wall))
    columns = list(zip(*rows))
    names = ["dt", "sigma_long", "sigma_tr", "bounded", "status", "tension_error", "position_error",
             "peak_tension", "wall_time_s"]
    ds = xr.Dataset({name: ("run", np.asarray(values, dtype=object if name == "status" else None))
                     for name, values in zip(names, columns)})
    low, high = stable_range(ds)
    ds.attrs.update(case_name=case.name, scheme=chosen.name, reference=ref_scheme.name, reference_dt=ref_dt,
                    duration=float(duration), segments=model.cable.segments, stable_sigma_long_min=low,
                    stable_sigma_long_max=high)
    for name, unit in (("dt", "s"), ("sigma_long", "1"), ("sigma_tr", "1"), ("peak_tension", "N"),
                       ("wall_time_s", "s"), ("tension_error", "1"), ("position_error", "1")):
        ds[name].attrs["units"] = unit
    return ds


def stable_range(ds: xr.Dataset) -> tuple[float, float]:
    """The widest contiguous range of ``sigma_long`` (sorted runs) in which every run stayed bounded.

    ``(nan, nan)`` when no run stayed bounded.
    """
    order = np.argsort(ds["sigma_long"].values)
    bounded = ds["bounded"].values.astype(bool)[order]
    sigma = ds["sigma_long"].values[order]
    best, current = (np.nan, np.nan, 0), None
    for i, ok in enumerate(bounded):
        if ok:
            current = (current[0], i) if current else (i, i)
            if current[1] - current[0] + 1 > best[2]:
                best = (sigma[current[0]], sigma[current[1]], current[1] - current[0] + 1)
        else:
            current = None
    return float(best[0]), float(best[1])


def _positions(state) -> np.ndarray:
    return state.xyz if hasattr(state, "xyz") else np.column_stack([state.xz[:, 0], state.xz[:, 1]])


DEFAULT_FACTORS = (1 / 16, 1 / 4, 1, 4, 16, 64)


def default_steps(case, factors=DEFAULT_FACTORS) -> np.ndarray:
    """Steps for a sweep around the case's own ``dt``: ``dt * factors``, kept to those that divide the duration."""
    dt, duration = case.simulation.dt, case.simulation.duration
    steps = [dt * f for f in factors]
    return np.array([s for s in steps if s <= duration and abs(duration / s - round(duration / s)) < 1e-6])


def summary(ds: xr.Dataset) -> str:
    """A plain-text table of a sweep, one line per run, and its stable range (for the command line)."""
    lines = [(f"{ds.attrs['scheme']} on {ds.attrs['case_name']} ({ds.attrs['segments']} segments), reference "
             f"{ds.attrs['reference']} at dt = {ds.attrs['reference_dt']:g} s"),
             f"{'dt [s]':>10} {'sigma_long':>11} {'sigma_tr':>9} {'bounded':>8} {'T error':>9} {'x error':>9}  status"]
    for i in range(ds.sizes["run"]):
        run = ds.isel(run=i)
        lines.append(f"{float(run.dt):10.4g} {float(run.sigma_long):11.4g} {float(run.sigma_tr):9.3g} "
                     f"{bool(run.bounded)!s:>8} {float(run.tension_error):9.2e} {float(run.position_error):9.2e}  "
                     f"{run.status.item()}")
    low, high = ds.attrs["stable_sigma_long_min"], ds.attrs["stable_sigma_long_max"]
    lines.append(f"bounded for sigma_long in [{low:.4g}, {high:.4g}] (Kaliukh & Vusatiuk 2018: about [2, 200])" if np.isfinite(low)
                 else "no run stayed bounded")
    return "\n".join(lines)
