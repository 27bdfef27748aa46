"""Zhang, Zhang & Liu's comparison of the generalized-α family on one case (its tables 3 and 4).

Each scheme runs the same case; a generalized-α run with a step ``REFERENCE_REFINE`` times
smaller is the reference. For each scheme the table gives the towed body's depth at the
start, its extreme depth and their difference (the depth change through the manoeuvre),
the largest deviation of the body depth from the reference, the mean Newton iterations
per step and the solver's time (compiling excluded).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from kanat import api
from kanat.continuum.schemes import BackwardEuler, Box, GeneralizedAlpha, GeneralizedTrapezoidal

SCHEMES = (Box(), BackwardEuler(), GeneralizedTrapezoidal(0.6), GeneralizedAlpha(-0.5))
REFERENCE_REFINE = 8


def compare_schemes(case, out_dir, schemes=SCHEMES) -> list[dict]:
    """Run ``case`` with every scheme and a fine reference; one row per scheme (see module doc)."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    sim = case.simulation
    fine = case.replace({"simulation.dt": sim.dt / REFERENCE_REFINE, "simulation.output_dt": sim.output_interval})
    reference = api.run(fine, output=out_dir / "reference.nc", scheme=GeneralizedAlpha(-0.5)).dataset
    ref_depth = reference.body_position.values[:, 0, 2]
    rows = []
    for scheme in schemes:
        label = _label(scheme)
        outcome = api.run(case, output=out_dir / f"{label}.nc", scheme=scheme)
        summary, ds = outcome.summary, outcome.dataset
        depth = ds.body_position.values[:, 0, 2]
        ref = np.interp(ds.time.values, reference.time.values, ref_depth)
        extreme = depth[np.argmax(np.abs(depth - depth[0]))]
        rows.append({"scheme": label, "status": summary.status, "depth_start_m": -depth[0],
                     "depth_extreme_m": -extreme, "depth_change_m": depth[0] - extreme,
                     "deviation_from_reference_m": float(np.max(np.abs(depth - ref))),
                     "newton_iterations_mean": summary.newton_iterations_mean, "solver_time_s": summary.solver_time_s})
    return rows


def _label(scheme) -> str:
    params = ",".join(f"{v:g}" for v in scheme.parameters().values())
    return scheme.name + (f"({params})" if params else "")


def table(rows) -> str:
    """Markdown table of :func:`compare_schemes` rows."""
    head = ("| scheme | depth at start [m] | extreme depth [m] | change [m] | max deviation from reference [m] "
            "| Newton iterations / step | solver time [s] |\n|---|---|---|---|---|---|---|")
    lines = [f"| {r['scheme']} | {r['depth_start_m']:.2f} | {r['depth_extreme_m']:.2f} | {r['depth_change_m']:.2f} "
             f"| {r['deviation_from_reference_m']:.3f} | {r['newton_iterations_mean']:.2f} | {r['solver_time_s']:.2f} |"
             for r in rows]
    return "\n".join([head, *lines])
