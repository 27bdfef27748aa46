"""Checks of a run's numbers and work (:data:`kanat.model.checks.LIMIT_CHECKS`, and the time steps
and run length of :data:`kanat.model.checks.CHECKS`): magnitudes within their units' ranges,
segments, result size, node-steps and the pitch problem's Fourier series."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..schemes import DYNAMIC_MODELS
from ._base import fmt
from . import limits
from .findings import Findings, byte_size
from .run_cost import check_node_steps, run_cost

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

TIME_TOL = 1e-6             # relative tolerance on "multiple of dt"


def check_time_steps(case: Case, out: Findings) -> None:
    """dt fits in the duration and divides the output interval, which fits in the duration too."""
    sim = case.simulation
    if sim is None:
        return
    if sim.dt is None and case.model == "continuum":
        out.error(("simulation", "dt"), "the continuum model needs a time step dt [s] (e.g. 1.0 for a "
                  "1000 m tow; the lumped model is the one that can choose its own)")
        return
    if sim.dt is not None and sim.dt > sim.duration:
        out.error(("simulation", "dt"), f"dt {fmt(sim.dt)} s is longer than the duration "
                  f"{fmt(sim.duration)} s")
    elif sim.output_interval > sim.duration:
        given = "output_dt" if sim.output_dt is not None else "dt" if sim.dt is not None else None
        out.error(("simulation", given or "duration"),
                  f"the output interval ({fmt(sim.output_interval)} s"
                  f"{'' if given else ', the default when neither output_dt nor dt is given'}) is longer than "
                  f"the duration {fmt(sim.duration)} s: the run would take no step and store t = 0 alone; "
                  "give output_dt at most the duration")
    if sim.dt is None or sim.output_dt is None:
        return
    ratio = sim.output_dt / sim.dt
    steps = round(ratio)
    if steps < 1 or abs(ratio - steps) > TIME_TOL * max(1.0, ratio):
        low = max(1, math.floor(ratio))
        out.error(("simulation", "output_dt"),
                  f"output_dt {fmt(sim.output_dt)} s is not a multiple of dt {fmt(sim.dt)} s "
                  f"({ratio:.4g} steps); use e.g. {fmt(low * sim.dt)} s or "
                  f"{fmt((low + 1) * sim.dt)} s")


def check_magnitudes(case: Case, out: Findings) -> None:
    """Every number within the sane range of its unit (:data:`limits.UNIT_RANGES`)."""
    for q in limits.iter_quantities(case):
        sane = limits.unit_range(q.unit)
        unit = f" {q.unit}" if q.unit and q.unit != "-" else ""
        if abs(q.value) > sane.high:
            out.error(q.path, f"must be at most {sane.high:g}{unit} in magnitude (got "
                      f"{fmt(q.value)}{unit}; {sane.what})")
        elif q.positive and q.value < sane.low:
            out.error(q.path, f"must be at least {sane.low:g}{unit} (got {fmt(q.value)}{unit}, "
                      f"too small to compute with; {sane.what})")


def check_discretization(case: Case, out: Findings) -> None:
    """Segments per cable and in all (:data:`limits.MAX_SEGMENTS_PER_CABLE`, ``_TOTAL``)."""
    counts = [cable.segments for cable in case.cables]
    for i, n in enumerate(counts):
        if n > limits.MAX_SEGMENTS_PER_CABLE:
            out.error(("cables", i, "segments"), f"{n:,} segments is more than the limit of "
                      f"{limits.MAX_SEGMENTS_PER_CABLE:,} a cable (10 cm elements over 10 km; "
                      "the continuum model converges by 1000); use fewer segments")
    if sum(counts) > limits.MAX_SEGMENTS_TOTAL and max(counts) <= limits.MAX_SEGMENTS_PER_CABLE:
        out.error(("cables",), f"{sum(counts):,} segments in all cables is more than the limit "
                  f"of {limits.MAX_SEGMENTS_TOTAL:,} (about 1 kB of solver memory a node); "
                  "use fewer segments")
    sphere = case.sphere_two_cables
    if sphere is not None and sphere.n_nodes > limits.MAX_SEGMENTS_PER_CABLE + 1:
        out.error(("sphere_two_cables", "n_nodes"), f"{sphere.n_nodes:,} nodes is more than "
                  f"the limit of {limits.MAX_SEGMENTS_PER_CABLE + 1:,}; 101 (the default) "
                  "resolves the published profiles")


def check_run_size(case: Case, out: Findings) -> None:
    """Time steps, node-steps and the estimated result size of a dynamic run."""
    sim = case.simulation
    if sim is None or case.model not in DYNAMIC_MODELS:
        return
    cost = run_cost(case)
    nodes = cost.nodes
    where = ("simulation", "dt") if sim.dt is not None else ("simulation", "duration")
    try:
        refused = check_node_steps(cost.steps, cost.nodes, cost.step, cost.why)
    except ValueError as exc:
        out.error(("simulation",), str(exc))
        return
    if refused:
        out.error(where, f"duration {fmt(sim.duration)} s is {refused}")
    try:
        limit = limits.max_output_bytes(out.max_output_bytes)
    except ValueError as exc:
        out.error(("simulation",), str(exc))
        return
    outputs = _outputs(case)
    size = 8.0 * outputs * _values_per_output(case)
    if size > limit:
        key = "output_dt" if sim.output_dt is not None else "duration"
        out.error(("simulation", key), f"the result would hold about {byte_size(size)} ({outputs:,} "
                  f"outputs x {nodes:,} nodes x {limits.OUTPUT_VALUES_PER_NODE} values x 8 bytes), "
                  f"more than the limit of {byte_size(limit)}; store less often (output_dt), shorten "
                  f"the duration or use fewer segments, or raise the limit "
                  f"(kanat --max-output 8G, {limits.OUTPUT_BYTES_ENV}=8G, or max_output_bytes=\"8G\" in Python)")


def _outputs(case: Case) -> int:
    """Outputs a dynamic run of ``case`` stores, t = 0 included (1 for a steady model)."""
    sim = case.simulation
    if sim is None or case.model not in DYNAMIC_MODELS:
        return 1
    return math.floor(sim.duration / sim.output_interval * (1 + TIME_TOL)) + 1


def _values_per_output(case: Case) -> int:
    """Numbers a result stores per output: :data:`limits.OUTPUT_VALUES_PER_NODE` of every node,
    :data:`limits.OUTPUT_VALUES_PER_BODY` of every body and :data:`limits.OUTPUT_VALUES_PER_STEP`."""
    nodes = sum(cable.segments + 1 for cable in case.cables)
    return (limits.OUTPUT_VALUES_PER_NODE * nodes + limits.OUTPUT_VALUES_PER_STEP
            + limits.OUTPUT_VALUES_PER_BODY * len(case.bodies))


RESULT_CHUNK_OUTPUTS = 64
"""Outputs per HDF5 chunk of a run's result (:data:`kanat.io.stream.CHUNK_OUTPUTS`): the file holds
whole chunks."""
RESULT_FILE_BYTES = 64 * 1024
"""A result file's HDF5 metadata, coordinates, attributes and embedded case [bytes]."""


def result_bytes(case: Case) -> float:
    """Estimated size of ``case``'s result file [bytes]: 8 bytes a number of every output, the outputs
    rounded up to whole chunks of :data:`RESULT_CHUNK_OUTPUTS` (one output for a steady model),
    and :data:`RESULT_FILE_BYTES`."""
    outputs = _outputs(case)
    if case.model in ("continuum", "lumped"):
        outputs = -(-outputs // RESULT_CHUNK_OUTPUTS) * RESULT_CHUNK_OUTPUTS
    return 8.0 * outputs * _values_per_output(case) + RESULT_FILE_BYTES


def check_run_length(case: Case, out: Findings) -> None:
    """A warning when a run's node-steps exceed :data:`limits.WARN_NODE_STEPS` (minutes to hours)."""
    cost = run_cost(case)
    if cost is None or cost.node_steps <= limits.WARN_NODE_STEPS:
        return
    where = ("simulation", "dt") if case.simulation.dt is not None else ("simulation", "duration")
    out.warning(where, f"a long run: {cost.steps:.3g} time steps of {cost.step:.3g} s ({cost.why}) x "
                f"{cost.nodes:,} nodes = {cost.node_steps:.3g} node-steps, at least "
                f"{cost.node_steps * limits.FASTEST_NODE_STEP_S / 60:.0f} minutes of computing "
                f"(the warning starts at {limits.WARN_NODE_STEPS:.3g}); a larger dt, an implicit "
                "scheme or fewer segments would shorten it")


def check_pitch_size(case: Case, out: Findings) -> None:
    """Harmonics and samples of the pitch problem's Fourier series."""
    for where, pitch in ((("pitch",), case.pitch), (("vessel", "pitch"), case.vessel.pitch)):
        if pitch is None:
            continue
        if pitch.harmonics > limits.MAX_HARMONICS:
            out.error((*where, "harmonics"), f"{pitch.harmonics:,} harmonics is more than the "
                      f"limit of {limits.MAX_HARMONICS:,}; 50 (the default) give the pitch to 1e-3")
        elif pitch.time_points > limits.MAX_TIME_POINTS:
            out.error((*where, "time_points"), f"{pitch.time_points:,} samples of the period is "
                      f"more than the limit of {limits.MAX_TIME_POINTS:,}")
        elif pitch.harmonics * pitch.time_points > limits.MAX_PITCH_SAMPLES:
            out.error((*where, "time_points"), f"harmonics x time_points = {pitch.harmonics:,} x "
                      f"{pitch.time_points:,} is more than the limit of "
                      f"{limits.MAX_PITCH_SAMPLES:,} values; use fewer of either")
