"""Whole-process times of the commands a user types, beside the solver's own time.

Each command runs as a fresh process (``python -m kanat.cli ...``, the same code as the
``kanat`` script) with the kernels compiled at install (``kanat.aot``; the "numba's kernels"
rows run the same command with ``KANAT_AOT=0``, from a warm numba cache), interleaved with the others, ``--repeats`` times
(default 5); the table gives medians of each process's CPU time (user + system) and peak
resident memory (``os.wait4``), its wall time, and for runs the ``solver_time_s`` the result
file records. The peer column is WHOI Cable's whole
process on the same case, built with ``-O2`` and measured on this machine kind (recorded
figures: WHOI Cable cannot be built here).

Python's bytecode cache is filled by the warm-up runs, as an installed package has it (pip compiles
kanat's bytecode at install): the commands run with ``PYTHONPYCACHEPREFIX`` set to a temporary
folder, even where the environment sets ``PYTHONDONTWRITEBYTECODE`` (which would make every process
compile kanat's source again: 0.15-0.2 s of CPU a command). ``--no-bytecode`` measures that too.

Run: ``python benchmarks/bench_whole_process.py [--repeats N] [--no-bytecode]`` (about a minute);
prints the Markdown table recorded in benchmarks/RESULTS.md.
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

NUMBA = {"KANAT_AOT": "0"}
"""The environment of a run with numba's kernels instead of those compiled at install (kanat.aot)."""
COMMANDS = {
    "kanat --version": (["--version"], None, "< 0.3 s CPU", "–", {}),
    "kanat validate speed_step_2d.yaml": (["validate", str(EXAMPLES / "speed_step_2d.yaml")], None, "< 0.3 s CPU",
                                          "–", {}),
    "kanat statics towed_body.yaml -o OUT": (["statics", str(EXAMPLES / "towed_body.yaml")], "out.nc", "–", "–", {}),
    "kanat run speed_step_2d.yaml -o OUT (2-D, 600 steps)": (["run", str(EXAMPLES / "speed_step_2d.yaml")], "out.nc",
                                                              "< 1.0 s CPU", "0.41 s CPU", {}),
    "the 2-D run with numba's kernels (KANAT_AOT=0)": (["run", str(EXAMPLES / "speed_step_2d.yaml")], "out.nc",
                                                       "–", "–", NUMBA),
    "kanat run turn_360_3d.yaml -o OUT (3-D, 1200 steps)": (["run", str(EXAMPLES / "turn_360_3d.yaml")], "out.nc",
                                                             "< 2.0 s CPU", "4.9 s CPU", {}),
    "the 3-D run with numba's kernels (KANAT_AOT=0)": (["run", str(EXAMPLES / "turn_360_3d.yaml")], "out.nc",
                                                       "–", "–", NUMBA),
    "kanat run mooring_buoy_decay.yaml -o OUT (lumped, 6-DOF buoy, seabed)": (
        ["run", str(EXAMPLES / "mooring_buoy_decay.yaml")], "out.nc", "–", "–", {}),
    "the lumped run with numba's kernels (KANAT_AOT=0)": (["run", str(EXAMPLES / "mooring_buoy_decay.yaml")],
                                                          "out.nc", "–", "–", NUMBA),
}
"""label: (arguments, output file name or None, target, WHOI Cable's whole process (docs/peers.md), environment)."""


ENVIRONMENT = dict(os.environ)
"""The commands' environment (:func:`main` sets how Python's bytecode is cached)."""


def run_once(args: list[str], output: Path | None, environment: dict) -> tuple[float, float, float]:
    """CPU [s], wall [s] and peak RSS [MiB] of one fresh process (its own ``rusage``)."""
    command = [sys.executable, "-m", "kanat.cli", *args] + (["-o", str(output)] if output is not None else [])
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               env={**ENVIRONMENT, **environment})
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed: {process.stderr.read().decode()[-500:]}")
    process.stderr.close()
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss / 1024.0


def solver_time(path: Path) -> float | None:
    """The ``solver_time_s`` a result file records (None for a steady result)."""
    import h5py

    with h5py.File(path, "r") as f:
        value = f.attrs.get("solver_time_s")
    return None if value is None else float(value.ravel()[0] if hasattr(value, 'ravel') else value)


def main(repeats: int, bytecode: bool = True) -> None:
    with tempfile.TemporaryDirectory() as folder:
        if bytecode:
            ENVIRONMENT.pop("PYTHONDONTWRITEBYTECODE", None)
            ENVIRONMENT["PYTHONPYCACHEPREFIX"] = str(Path(folder) / "bytecode")
        else:
            ENVIRONMENT["PYTHONDONTWRITEBYTECODE"] = "1"
            ENVIRONMENT.pop("PYTHONPYCACHEPREFIX", None)
        samples = {label: [] for label in COMMANDS}
        solver = {label: [] for label in COMMANDS}
        for label, (args, name, _, _, environment) in COMMANDS.items():   # warm-up: the kernels are cached
            run_once(args, Path(folder) / f"warm-{name}" if name else None, environment)
        for k in range(repeats):
            for label, (args, name, _, _, environment) in COMMANDS.items():      # interleaved
                output = Path(folder) / f"{k}-{name}" if name else None
                samples[label].append(run_once(args, output, environment))
                if output is not None and (t := solver_time(output)) is not None:
                    solver[label].append(t)
                    os.remove(output)
    load = os.getloadavg()
    print(f"{repeats} interleaved runs per command, medians; load average {load[0]:.2f} {load[1]:.2f}; bytecode "
          f"{'cached' if bytecode else 'compiled by every process (PYTHONDONTWRITEBYTECODE)'}\n")
    print("| command | CPU [s] | wall [s] | solver [s] | peak RSS [MiB] | target | WHOI Cable (docs/peers.md) |")
    print("|---|---|---|---|---|---|---|")
    for label, (_, _, target, peer, _) in COMMANDS.items():
        cpu, wall, rss = (statistics.median(x[i] for x in samples[label]) for i in range(3))
        solve = f"{statistics.median(solver[label]):.2f}" if solver[label] else "–"
        print(f"| `{label}` | {cpu:.2f} | {wall:.2f} | {solve} | {rss:.0f} | {target} | {peer} |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--no-bytecode", action="store_true", help="every process compiles kanat's source")
    arguments = parser.parse_args()
    main(arguments.repeats, not arguments.no_bytecode)
