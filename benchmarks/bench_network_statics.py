"""Network statics against MoorPy on the same moorings: solve time and whole-process time.

Target (issue 11): network statics of a 3-leg chain mooring with seabed contact in under
50 ms, measured side by side with MoorPy's ``System.solveEquilibrium``.

* In-process, interleaved (kanat, MoorPy, kanat, ...), medians of REPEATS: kanat's whole
  ``kanat.statics.solve_statics(case)`` (network set-up, first guess, Newton, every node's
  position and tension, anchor and body forces, the condensed stiffness) against MoorPy's
  ``solveEquilibrium`` on a freshly built system (its build timed apart).
* Whole process, interleaved, medians of PROCESS_REPEATS: ``kanat statics FILE -o OUT.nc``
  against a Python process that imports MoorPy, reads the same MoorDyn file and solves it.

Run from the repository root: ``python benchmarks/bench_network_statics.py`` (MoorPy from
the ``peers`` extra). Results: benchmarks/RESULTS.md.
"""
from __future__ import annotations

import contextlib
import io
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

REPEATS = 21
PROCESS_REPEATS = 7
TARGET_MS = 50.0
CASES = {
    "3-leg chain mooring of a buoy, 448 m of each leg on the seabed": ROOT / "tests/data/network/buoy_3leg_seabed.yaml",
    "MoorDyn buoy_spread_mooring.dat: 6-DOF buoy, fairlead offsets, 3 chain legs on the seabed":
        ROOT / "examples/moordyn/buoy_spread_mooring.dat",
    "two line types and clump weights, 3 legs (9 free points in MoorPy)":
        ROOT / "tests/data/moorpy/buoy_two_line_types_clumps.yaml",
}
MOORPY_FILE_COPY = " 20|10 ", " 20    "          # MoorPy 1.3 reads 1 or 3 drag areas for a body


def _load(path):
    from kanat.api import load_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path, solver="statics")


def _moorpy(path, case):
    """A fresh MoorPy system of the case: MoorPy reads a MoorDyn file itself."""
    import moorpy as mp

    from moorpy_systems import moorpy_system

    if path.suffix == ".dat":
        with tempfile.TemporaryDirectory() as folder:
            copy = Path(folder) / path.name
            copy.write_text(path.read_text().replace(*MOORPY_FILE_COPY))
            with contextlib.redirect_stdout(io.StringIO()):
                ms = mp.System(file=str(copy))
                ms.initialize()
        return ms
    return moorpy_system(case)[0]


def in_process(label, path):
    from kanat.statics import solve_statics

    case = _load(path)
    solve_statics(case)                                       # warm-up: imports, first calls
    kanat_ms, moorpy_ms, build_ms = [], [], []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for _ in range(REPEATS):
            start = time.perf_counter()
            solve_statics(case)
            kanat_ms.append(1e3 * (time.perf_counter() - start))
            start = time.perf_counter()
            ms = _moorpy(path, case)
            build_ms.append(1e3 * (time.perf_counter() - start))
            start = time.perf_counter()
            with contextlib.redirect_stdout(io.StringIO()):
                ms.solveEquilibrium(tol=1e-6, maxIter=5000)
            moorpy_ms.append(1e3 * (time.perf_counter() - start))
    k, m = statistics.median(kanat_ms), statistics.median(moorpy_ms)
    verdict = ("meets" if k < TARGET_MS else "MISSES") + f" < {TARGET_MS:g} ms"
    print(f"| {label} | {k:.1f} | {m:.1f} | {statistics.median(build_ms):.1f} | {m / k:.2f} | {verdict} |")


MOORPY_PROCESS = """
import contextlib, io, sys, warnings
warnings.simplefilter("ignore")
import moorpy as mp
with contextlib.redirect_stdout(io.StringIO()):
    ms = mp.System(file=sys.argv[1]); ms.initialize(); ms.solveEquilibrium(tol=1e-6, maxIter=5000)
"""


def whole_process(path):
    kanat_cli = Path(sys.executable).with_name("kanat")
    times = {"kanat": [], "moorpy": []}
    with tempfile.TemporaryDirectory() as folder:
        copy = Path(folder) / path.name
        copy.write_text(path.read_text().replace(*MOORPY_FILE_COPY))
        commands = {"kanat": [str(kanat_cli), "-q", "statics", str(path), "-o", str(Path(folder) / "out.nc")],
                    "moorpy": [sys.executable, "-c", MOORPY_PROCESS, str(copy)]}
        for _ in range(PROCESS_REPEATS):
            for name, command in commands.items():
                start = time.perf_counter()
                subprocess.run(command, check=True, capture_output=True, env={**os.environ, "PYTHONWARNINGS": "ignore"})
                times[name].append(time.perf_counter() - start)
    k, m = statistics.median(times["kanat"]), statistics.median(times["moorpy"])
    print(f"| `kanat statics {path.relative_to(ROOT)} -o OUT.nc` | {k:.2f} s | MoorPy process (import, read, "
          f"solve) {m:.2f} s |")


def main():
    load = os.getloadavg()[0]
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"load average before: {load:.2f}\n")
    print("| case | kanat solve_statics [ms] | MoorPy solveEquilibrium [ms] | MoorPy build [ms] | "
          "MoorPy / kanat | target |\n|---|---|---|---|---|---|")
    for label, path in CASES.items():
        in_process(label, path)
    print("\n| whole process | kanat | MoorPy |\n|---|---|---|")
    whole_process(ROOT / "examples/moordyn/buoy_spread_mooring.dat")
    print(f"\nload average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
