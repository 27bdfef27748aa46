"""What one Newton iteration of the lumped implicit scheme costs, in force evaluations of the
explicit scheme — the constants of the default-scheme choice (``kanat.lumped.stepping``).

Both through the fused compiled paths a run uses (:func:`kanat.lumped.advance.advance`): RK4 at
its safe step (cost per force evaluation), generalized-α at 0.05 s (cost per Newton iteration,
and iterations per step), after a first stretch that loads the kernels; lines of 20, 100 and 400
segments (the towed cable of ``bench_lumped_towed.py``) and Bezverkhyi's towed network in waves.

Run: ``python benchmarks/bench_lumped_cost.py``.
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_lumped_towed as towed  # noqa: E402

from kanat.api import load_case  # noqa: E402
from kanat.lumped.advance import _arrays, advance  # noqa: E402
from kanat.lumped.equilibrium import equilibrium  # noqa: E402
from kanat.lumped.integrators import SCHEMES  # noqa: E402
from kanat.lumped.network import build_network  # noqa: E402
from kanat.lumped.snap import SnapTracker  # noqa: E402
from kanat.lumped.stepping import step_info  # noqa: E402
from kanat.lumped.system import LumpedSystem  # noqa: E402
from kanat.schemes import get_scheme  # noqa: E402

STEPS = 400


def measure(case) -> dict:
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = equilibrium(net, case)[0]
    free = system.free_index
    info = step_info(net, x)
    out = {"nodes": net.n_nodes}
    for name in ("rk4", "generalized-alpha-lumped"):
        scheme = get_scheme(name, SCHEMES)
        h = info.safe_step(scheme) if scheme.explicit else 0.05
        state = scheme.start(system, 0.0, x[free], np.zeros((len(free), 3)), h)
        tracker = SnapTracker(0.0, np.zeros(net.n_elements))
        T = np.zeros(net.n_elements)
        state, _ = advance(scheme, system, state, h, 20, tracker, lambda s: T)        # load the kernels
        evaluations, iterations = system.evaluations, getattr(state, "iterations", 0)
        start = time.perf_counter()
        state, _ = advance(scheme, system, state, h, STEPS, tracker, lambda s: T)
        spent = time.perf_counter() - start
        out[name] = spent / (system.evaluations - evaluations)
        if not scheme.explicit:
            out["iterations"] = (state.iterations - iterations) / STEPS
    out["bandwidth"] = _arrays(system).bandwidth
    return out


def main() -> None:
    print(f"load average before: {os.getloadavg()[0]:.2f}\n")
    print("| case | nodes | band half-width | RK4 force evaluation [us] | Newton iteration [us] | ratio "
          "| iterations per step at 0.05 s |")
    print("|---|---|---|---|---|---|---|")
    cases = {f"towed line, {n} segments": load_case(towed.case_dict()).replace({"cables[0].segments": n})
             for n in (20, 100, 400)}
    cases["Bezverkhyi 2006 network in waves"] = load_case(Path(__file__).resolve().parents[1]
                                                   / "examples/trawl_head_5.6s_1to4.yaml")
    for label, case in cases.items():
        m = measure(case)
        eval_us, iter_us = 1e6 * m["rk4"], 1e6 * m["generalized-alpha-lumped"]
        print(f"| {label} | {m['nodes']} | {m['bandwidth']} | {eval_us:.2f} | {iter_us:.1f} | "
              f"{iter_us / eval_us:.1f} | {m['iterations']:.2f} |", flush=True)
    print(f"\nload average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
