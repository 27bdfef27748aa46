"""Statics timings: wall time of one complete solve, best and median of repeats (timeit).

Targets (foundation issue): a 1000 m towed cable with a towed body solves in under
50 ms; a full Naumov & Agievich solve in under 100 ms. Each solve is complete: from the case's
typed problem to the solution at every node, including root finding.
"""
from __future__ import annotations

import platform
import statistics
import timeit
from pathlib import Path

from kanat.io import load_case
from kanat.statics import solve_statics
from kanat.statics.setup import cable_problems
from kanat.statics.driver import solve_cable
from kanat.statics.sphere import SphereGroups
from kanat.statics.sphere_solvers import solve_sphere

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
REPEATS, NUMBER = 7, 5


def timed(label, target_ms, fn):
    fn()                                            # warm-up (imports, caches)
    runs = [t / NUMBER * 1e3 for t in timeit.repeat(fn, repeat=REPEATS, number=NUMBER)]
    best, median = min(runs), statistics.median(runs)
    verdict = "" if target_ms is None else ("meets" if median < target_ms else "MISSES") + f" < {target_ms} ms"
    print(f"| {label} | {best:.1f} | {median:.1f} | {verdict} |")


def main():
    print(f"machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}\n")
    print("| case | best [ms] | median [ms] | target |\n|---|---|---|---|")
    towed = load_case(EXAMPLES / "towed_body.yaml")
    problem = cable_problems(towed)["tow"]
    nodes = [i * 10.0 for i in range(101)]
    timed("towed body, 1000 m, 100 segments, shooting", 50, lambda: solve_cable(problem, "shooting", nodes))
    timed("towed body, 1000 m, 100 segments, collocation", None, lambda: solve_cable(problem, "collocation", nodes))
    timed("towed body, whole case (load-free solve_statics)", 50, lambda: solve_statics(towed))
    mooring = load_case(EXAMPLES / "mooring_current.yaml")
    timed("chain mooring in sheared current, seabed contact, shooting", None,
          lambda: solve_statics(mooring, "shooting"))
    timed("chain mooring in sheared current, seabed contact, collocation", None,
          lambda: solve_statics(mooring, "collocation"))
    groups = SphereGroups(Psi=0.02, LoL=2.0, x_C=-1.732, QkL=0.45, RkL=0.4)
    timed("Naumov & Agievich published case, shooting", 100, lambda: solve_sphere(groups, "published", "shooting"))
    timed("Naumov & Agievich published case, collocation", 100, lambda: solve_sphere(groups, "published", "collocation"))
    still = mooring.model_copy(update={"environment": mooring.environment.model_copy(
        update={"current": type(mooring.environment.current)()})})
    timed("same mooring without current, catenary fast path", None, lambda: solve_statics(still))


if __name__ == "__main__":
    main()
