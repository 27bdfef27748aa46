"""A fresh install as a user does it: a new virtual environment and ``pip install -e .``, with and
without the kernels compiled at install (``KANAT_AOT=0`` skips them: runs then compile with numba
on first use).

Each round clones the checkout's committed state into a temporary folder (no module built
before), makes a venv with the machine's ``python3`` and runs ``pip install -e CLONE`` in it,
timing the whole pip process (wall, and CPU of pip and everything it started) and then one
``kanat run examples/speed_step_2d.yaml`` on an empty numba cache: the first run a user sees.
Wheels come from pip's cache or the machine's index, as for any install here.

Run: ``python benchmarks/bench_install.py [--repeats N]`` (about 2 minutes a round); prints the
Markdown table recorded in benchmarks/RESULTS.md.
"""
from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def timed(command: list[str], env: dict, cwd: Path) -> tuple[float, float, str]:
    """Wall and CPU seconds (the command and its children) of ``command``, and its output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{done.stderr[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.stdout


def size_mb(folder: Path) -> float:
    """Disk use of ``folder`` [MB]."""
    return sum(f.stat().st_size for f in folder.rglob("*") if f.is_file() and not f.is_symlink()) / 1e6


def one_round(kernels: bool) -> dict:
    """Install into a new venv, then run the main example once on an empty numba cache."""
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        clone = folder / "kanat"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        subprocess.run(["python3", "-m", "venv", str(folder / "venv")], check=True)
        python = folder / "venv" / "bin" / "python"
        env = {**os.environ, "NUMBA_CACHE_DIR": str(folder / "numba-cache")}
        env.pop("KANAT_AOT", None)
        if not kernels:
            env["KANAT_AOT"] = "0"
        subprocess.run([str(python), "-m", "pip", "install", "-q", "--upgrade", "pip"], env=env, check=True,
                       capture_output=True)
        wall, cpu, _ = timed([str(python), "-m", "pip", "install", "-q", "-e", str(clone)], env, folder)
        built = sorted(p.name.split(".")[0] for p in (clone / "src" / "kanat").glob("_*.so"))
        first = timed([str(python), "-m", "kanat.cli", "run", str(clone / "examples" / "speed_step_2d.yaml"),
                       "-o", str(folder / "out.nc")], env, folder)
        compiling = float(first[2].split("compiling ")[1].split(" s")[0])
        return {"wall": wall, "cpu": cpu, "venv": size_mb(folder / "venv"), "built": built,
                "first_wall": first[0], "first_cpu": first[1], "first_compiling": compiling}


def main(repeats: int) -> None:
    rows = {True: [], False: []}
    for _ in range(repeats):
        for kernels in (True, False):                       # interleaved
            rows[kernels].append(one_round(kernels))
    load = os.getloadavg()
    print(f"{repeats} interleaved rounds, medians; load average {load[0]:.2f} {load[1]:.2f}\n")
    print("| install | pip install -e . wall [s] | CPU [s] | venv [MB] | modules built | first `kanat run "
          "speed_step_2d.yaml`: CPU [s] | of which compiling [s] |")
    print("|---|---|---|---|---|---|---|")
    for kernels, label in ((True, "with the kernels compiled at install"), (False, "`KANAT_AOT=0` (numba at first use)")):
        r = rows[kernels]
        med = {k: statistics.median(x[k] for x in r) for k in ("wall", "cpu", "venv", "first_cpu", "first_compiling")}
        print(f"| {label} | {med['wall']:.1f} | {med['cpu']:.1f} | {med['venv']:.0f} | "
              f"{', '.join(r[0]['built']) or 'none'} | {med['first_cpu']:.2f} | {med['first_compiling']:.2f} |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=1)
    main(parser.parse_args().repeats)
