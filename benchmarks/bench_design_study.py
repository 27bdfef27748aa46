"""Wall time of a design study (issue 25): sea states x 4 conditions x seeds, whole process.

The study is ``examples/design/mooring_design.yaml`` (a 6-DOF buoy on three chain legs; the
conditions intact and each leg removed: 4) over ``--sea-states`` JONSWAP sea states (Hs 1 to 6 m,
Tp 6 to 12 s, spread evenly) and ``--seeds`` seeds, each run simulating ``--duration`` seconds.
The issue's study is 20 x 4 x 3 (240 runs); on a loaded machine run it smaller first.

Each engine runs the whole check as a user runs it, in a fresh process (imports, statics of the
conditions, the runs, the tables and the report), interleaved ``--repeats`` times:

* ``kanat design CASE -o DIR --scheduler serial``: one run after another;
* ``kanat design CASE -o DIR --workers 2``: kanat's local pool of 2 worker processes;
* Python, Dask: ``kanat.design(case, output, scheduler=client)`` with a Dask ``LocalCluster`` of
  2 workers (``kanat.sweep.cluster.local_cluster``; started by the process and counted in its
  wall time, as a scheduler the study reaches by address would be started beforehand).

Every engine's ``utilisation.csv`` must equal the serial one (the tables are the same whatever ran
the runs). The load average before each run is printed: other processes on the machine skew the
speed-ups.

Run: ``python benchmarks/bench_design_study.py --sea-states 20 --seeds 3 --duration 600``
(the issue's size) or smaller; prints markdown rows for RESULTS.md.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fatigue_scatter import SeaStateCell  # noqa: E402
from studies import SEA_STATES, kanat_command, timed_process, write_study  # noqa: E402

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "design" / "mooring_design.yaml"
DASK = ("import sys; import kanat; from kanat.design_checks import design, write_tables\n"
        "from kanat.sweep.cluster import local_cluster\n"
        "if __name__ == '__main__':\n"
        "    case = kanat.load_case(sys.argv[1])\n"
        "    with local_cluster(2) as client:\n"
        "        write_tables(design(case, sys.argv[2], scheduler=client), sys.argv[2])")
ENGINES = {"serial": ["--scheduler", "serial"], "2 workers": ["--workers", "2"], "Dask 2 workers": None}


def study_case(folder: Path, sea_states: int, seeds: int, duration: float) -> Path:
    """The example with ``sea_states`` sea states of ``duration`` s and ``seeds`` seeds, in ``folder``."""
    data = yaml.safe_load(EXAMPLE.read_text())
    data["design"].update(seeds=seeds, conditions=["intact", "damaged"], sea_states=SEA_STATES)
    cells = [SeaStateCell(hs, tp, 0.0, 0.9 / sea_states)
             for hs, tp in zip(np.linspace(1.0, 6.0, sea_states), np.linspace(6.0, 12.0, sea_states))]
    return write_study(folder, data, cells, duration, "study.yaml")


def whole_check(case: Path, out: Path, options: list[str] | None) -> dict:
    """One design process: wall and CPU time (its children included) and the load before it."""
    if options is None:
        command = [sys.executable, "-c", DASK, str(case), str(out)]
    else:
        command = kanat_command() + ["design", str(case), "-o", str(out), *options]
    timed = timed_process(command, accepted=(0, 3))         # 3: a line fails its check, which is a result
    return {**timed, "table": pd.read_csv(out / "utilisation.csv")}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sea-states", type=int, default=20)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--duration", type=float, default=600.0, help="simulated seconds per run")
    parser.add_argument("--repeats", type=int, default=1)
    args = parser.parse_args()
    runs_per_check = args.sea_states * 4 * args.seeds
    with tempfile.TemporaryDirectory(prefix="kanat-bench-design-") as scratch:
        folder = Path(scratch)
        case = study_case(folder, args.sea_states, args.seeds, args.duration)
        found = {name: [] for name in ENGINES}
        for k in range(args.repeats):
            for name, options in ENGINES.items():
                found[name].append(whole_check(case, folder / f"{name.replace(' ', '-')}-{k}", options))
        serial = statistics.median(r["wall"] for r in found["serial"])
        reference = found["serial"][0]["table"]
        print(f"{args.sea_states} sea states x 4 conditions x {args.seeds} seeds = {runs_per_check} runs of "
              f"{args.duration:g} s; {os.cpu_count()} cores\n")
        print("| engine, whole process | wall (median) | vs serial | CPU (process tree) | per run | load before |"
              "\n|---|---|---|---|---|---|")
        for name, rows in found.items():
            for r in rows:
                pd.testing.assert_frame_equal(r["table"], reference, check_exact=False, rtol=1e-12)
            wall = statistics.median(r["wall"] for r in rows)
            what = f"`kanat design ... {' '.join(ENGINES[name])}`" if ENGINES[name] is not None else "Python, Dask"
            loads = ", ".join(f"{r['load']:.2f}" for r in rows)
            print(f"| {what} ({name}) | {wall:.1f} s | {serial / wall:.2f}x | "
                  f"{statistics.median(r['cpu'] for r in rows):.1f} s | {wall / runs_per_check:.2f} s | {loads} |")
        print(f"\nload average after: {os.getloadavg()[0]:.2f}; the utilisation tables of every engine equal "
              "the serial one")


if __name__ == "__main__":
    main()
