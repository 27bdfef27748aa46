"""Kaliukh & Vusatiuk's three comparisons (Kaliukh & Vusatiuk 2018), one function and one command each.

    kanat study factorization accel      -o DIR    # towed vehicle from rest (section 3)
    kanat study factorization planar80   -o DIR    # 80 m tow 15 -> 20 kn (section 4.1, table 1)
    kanat study factorization spatial100 -o DIR    # 100 m tow, 45 deg turn (section 4.2, table 2)

Each writes a CSV table and a PNG figure into ``DIR`` and prints the table. The cases are
``examples/factorization_*.yaml``; their comments list the published data and the unpublished
data chosen here. "Full" is the generalized-α box scheme (theory/time-schemes.md §1) at the same grid and
step; the other columns are Kaliukh & Vusatiuk's schemes (:mod:`kanat.continuum.factorized.schemes`).

Angles are chart-free: ``inclination`` is the tangent's angle below the horizontal (the
paper's ``phi`` for a cable trailing astern), ``azimuth`` the heading of its horizontal part
measured from astern (``atan2(t_y, -t_x)``; the paper's ``theta`` has another origin).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from kanat import api, dynamics
from kanat.continuum.models import model_for
from kanat.io import parse_case

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
FULL = "generalized-alpha"


@dataclass(frozen=True)
class Trace:
    """States of one run at its output times, and its cost.

    Attributes
    ----------
    scheme : str
    times : ndarray
        Times of the states kept [s].
    states : list
        The continuum model's states at ``times``.
    wall_time_s : float
        The run's solver time (compiling excluded) [s].
    steps : int
    status : str
    model : object
        The continuum model (planar or spatial adapter) the states belong to.
    """

    scheme: str
    times: np.ndarray
    states: list
    wall_time_s: float
    steps: int
    status: str = "ok"
    model: object = None


def case_text(name: str, path=None) -> str:
    """The YAML text of ``examples/factorization_<name>.yaml`` (or of ``path``)."""
    path = Path(path) if path else EXAMPLES / f"factorization_{name}.yaml"
    if not path.exists():
        raise FileNotFoundError(f"{path} not found; pass the case file with --case (the examples folder of "
                                "the kanat source tree holds it)")
    return path.read_text()


class KeepStates:
    """Run-loop observer keeping the model's states at the outputs in ``times`` [s]."""

    def __init__(self, times):
        self.wanted = {round(float(t), 9) for t in times}
        self.times, self.states = [], []

    def start(self, layout, resume_at=None):
        """Nothing to prepare."""

    def record(self, point) -> None:
        if round(point.time, 9) in self.wanted:
            self.times.append(point.time)
            self.states.append(point.state)

    def flush(self):
        """Nothing buffered."""

    def finish(self, status, final, attrs):
        """Nothing to close."""


def simulate(case, scheme, times, dt=None) -> Trace:
    """Run ``case`` in memory through the run loop with ``scheme`` and keep the states at ``times``
    (multiples of ``dt``, default the case's)."""
    dt = dt or case.simulation.dt
    counts = np.round(np.asarray(times, float) / dt).astype(int)
    every = int(np.gcd.reduce(counts[counts > 0])) if np.any(counts > 0) else 1
    varied = case.replace({"simulation.dt": dt, "simulation.output_dt": every * dt,
                           "simulation.duration": counts.max() * dt})
    keep = KeepStates(np.asarray(times, float))
    models = []

    def build():
        models.append(api.dynamic_model(varied, scheme))
        return models[-1]
    summary = dynamics.run(build, [keep])
    status = summary.status.removeprefix("failed: ")
    return Trace(models[0].scheme.name, np.asarray(keep.times), keep.states, summary.solver_time_s,
                 summary.steps, status, models[0].cable_model)


def profile(model, state, s, stations) -> dict:
    """Tension, inclination and azimuth at arclengths ``stations`` (interpolated between nodes)."""
    t = model.tangents(state)
    inclination = np.arctan2(-t[:, 2], np.hypot(t[:, 0], t[:, 1]))
    azimuth = np.unwrap(np.arctan2(t[:, 1], -t[:, 0]))
    at = lambda v: np.interp(stations, s, v)
    return {"tension": at(model.outputs(state)["tension"]), "inclination": at(inclination), "azimuth": at(azimuth)}


def body_relative(state, model) -> np.ndarray:
    """Body position relative to the tow point (x, z) [m]: distance astern ``-x`` and depth ``-z``."""
    xyz = model.outputs(state)["position"][-1] - model.origin(state.t)
    return np.array([-xyz[0], -xyz[2]])


def accel(segments: int = 24, dt: float = 0.002, schemes=(FULL, "factorized", "factorized-4", "wave-factorized"),
          path=None) -> pd.DataFrame:
    """Section 3: depth and distance astern of the towed vehicle against time, every scheme.

    Returns a table with columns ``time, scheme, distance, depth`` and the run costs in
    ``attrs`` (wall time per scheme).
    """
    text = case_text("accel", path).replace("segments: 24,", f"segments: {segments},")
    case = parse_case(text)
    times = np.round(np.arange(0.0, case.simulation.duration + 1e-9, 0.05), 10)
    model = model_for(case)
    rows, walls = [], {}
    for name in schemes:
        trace = simulate(case, name, times, dt)
        walls[name] = trace.wall_time_s
        for t, state in zip(trace.times, trace.states):
            distance, depth = body_relative(state, model)
            rows.append({"time": t, "scheme": name, "distance": distance, "depth": depth})
    table = pd.DataFrame(rows)
    table.attrs["wall_time_s"] = walls
    return table


def planar80(segment_counts=(5, 10), dt: float = 0.01, times=(0.0, 10.0, 24.0), scheme: str = "wave-factorized",
             path=None) -> pd.DataFrame:
    """Section 4.1, table 1: tension and inclination along the cable, full vs ``scheme``.

    One row per (segments, t, s) with both schemes' values, their relative difference in
    percent, and the wall times (``attrs["wall_time_s"]``, ``attrs["speedup"]``).
    """
    base = case_text("planar80", path)
    stations = np.array([0.0, 20.0, 40.0, 60.0, 80.0])
    rows, walls, speedup = [], {}, {}
    for segments in segment_counts:
        case = parse_case(base.replace("segments: 10,", f"segments: {segments},"))
        s = np.linspace(0.0, 80.0, segments + 1)
        full, fact = simulate(case, FULL, times, dt), simulate(case, scheme, times, dt)
        walls[(segments, FULL)], walls[(segments, scheme)] = full.wall_time_s, fact.wall_time_s
        speedup[segments] = full.wall_time_s / fact.wall_time_s
        for t, a, b in zip(full.times, full.states, fact.states):
            pa, pb = profile(full.model, a, s, stations), profile(fact.model, b, s, stations)
            for i, station in enumerate(stations):
                rows.append({"segments": segments, "time": t, "s": station,
                             "tension_full": pa["tension"][i], f"tension_{scheme}": pb["tension"][i],
                             "tension_diff_pct": 100 * (pb["tension"][i] / pa["tension"][i] - 1),
                             "inclination_full": pa["inclination"][i],
                             f"inclination_{scheme}": pb["inclination"][i],
                             "inclination_diff_pct": 100 * (pb["inclination"][i] / pa["inclination"][i] - 1)})
    table = pd.DataFrame(rows)
    table.attrs.update(wall_time_s=walls, speedup=speedup)
    return table


def spatial100(dt: float = 0.05, times=(0.0, 10.0, 60.0), schemes=(FULL, "wave-factorized-2", "wave-factorized-3"),
               path=None, history_every: float = 1.0) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Section 4.2, table 2: T, inclination and azimuth at s = 0, 40, 100 m; full vs two and three blocks.

    Returns the table and a history (every ``history_every`` s) of each split's largest
    deviation from the full scheme in ``w`` (binormal velocity) and azimuth — the paper's
    observation that the three-block split accumulates error there.
    """
    case = parse_case(case_text("spatial100", path))
    stations = np.array([0.0, 40.0, 100.0])
    s = np.linspace(0.0, 100.0, case.cables[0].segments + 1)
    history_times = np.round(np.arange(0.0, max(times) + 1e-9, history_every), 10)
    grid = np.union1d(history_times, times)
    runs = [simulate(case, name, grid, dt) for name in schemes]
    traces = {trace.scheme: trace for trace in runs}
    rows = []
    for t in times:
        i = int(np.argmin(np.abs(grid - t)))
        row = {"time": t}
        for name, trace in traces.items():
            if i >= len(trace.states):
                continue
            values = profile(trace.model, trace.states[i], s, stations)
            for j, station in enumerate(stations):
                for key in ("tension", "inclination", "azimuth"):
                    row[f"{key}_{int(station)}_{name}"] = values[key][j]
        rows.append(row)
    history = []
    full = runs[0]
    for trace in runs[1:]:
        name = trace.scheme
        for t, a, b in zip(grid, full.states, trace.states):
            wa, wb = _binormal_speed(full.model, a), _binormal_speed(trace.model, b)
            za, zb = profile(full.model, a, s, s)["azimuth"], profile(trace.model, b, s, s)["azimuth"]
            history.append({"time": t, "scheme": name, "w_error": np.max(np.abs(wb - wa)),
                            "azimuth_error": np.max(np.abs(zb - za)),
                            "tension_error_pct": 100 * np.max(np.abs(b.y[:, 0] / a.y[:, 0] - 1))})
    table = pd.DataFrame(rows)
    table.attrs["wall_time_s"] = {name: trace.wall_time_s for name, trace in traces.items()}
    table.attrs["status"] = {name: trace.status for name, trace in traces.items()}
    return table, pd.DataFrame(history)


def _binormal_speed(model, state) -> np.ndarray:
    """The velocity's component out of the cable's local vertical plane (chart-free ``w``) [m/s]."""
    t, velocity = model.tangents(state), model.outputs(state)["velocity"]
    horizontal = np.cross(t, np.array([0.0, 0.0, 1.0]))
    norm = np.linalg.norm(horizontal, axis=1, keepdims=True)
    return np.sum(velocity * horizontal / np.where(norm > 0, norm, 1.0), axis=1)
