"""The README's install commands one after the other, as a user runs them: ``pip install -e
".[plot]"``, then ``pip install -e ".[test]"``, in a new virtual environment, with the kernels
cached per machine (``kanat.aot_cache``, an empty cache at the start) and without
(``KANAT_KERNEL_CACHE=0``: every install compiles them, as before the cache).

Each round clones the checkout's committed state into a temporary folder (no module built
before), makes a venv with the machine's ``python3``, and times each ``pip install -v -e
CLONE[extra]`` (wall, and CPU of pip and everything it started); it reads what the build did
from pip's verbose output (``kanat kernels: N copied from the cache ..., M compiled``) and measures the
venv's size after each. Wheels come from pip's cache or the index: the first round downloads
what the later ones find in pip's cache.

Run: ``python benchmarks/bench_install_extras.py [--rounds cache,nocache] [--extras plot,test]``
(minutes per compile on a loaded machine); prints the Markdown table recorded in
docs/performance.md.
"""
from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import tempfile
import time
from pathlib import Path

from bench_install import ROOT, size_mb


def one_round(cached: bool, extras: list[str]) -> list[dict]:
    """Install each extra in turn into one new venv; a row per install."""
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        clone = folder / "kanat"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        subprocess.run(["python3", "-m", "venv", str(folder / "venv")], check=True)
        python = str(folder / "venv" / "bin" / "python")
        env = {**os.environ, "KANAT_KERNEL_CACHE": str(folder / "kernel-cache") if cached else "0"}
        env.pop("KANAT_AOT", None)
        subprocess.run([python, "-m", "pip", "install", "-q", "--upgrade", "pip"], env=env, check=True,
                       capture_output=True)
        rows = []
        for extra in extras:
            log = folder / f"pip-{extra}.log"
            with open(log, "w") as output:                  # pip -v shows the build's own output: what it did
                start_cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
                start = time.perf_counter()
                subprocess.run([python, "-m", "pip", "install", "-v", "-e", f"{clone}[{extra}]"], env=env,
                               cwd=folder, stdout=output, stderr=subprocess.STDOUT, check=True)
                wall = time.perf_counter() - start
                end_cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (end_cpu.ru_utime - start_cpu.ru_utime) + (end_cpu.ru_stime - start_cpu.ru_stime)
            found = re.search(r"kanat kernels: (\d+) copied from the cache \S+, (\d+) compiled", log.read_text())
            copied, compiled = (f"{found[1]}", f"{found[2]}") if found else ("?", "?")
            rows.append({"extra": extra, "wall": wall, "cpu": cpu, "copied": copied, "compiled": compiled,
                         "venv": size_mb(folder / "venv")})
        return rows


def main(rounds: list[str], extras: list[str]) -> None:
    table = {name: one_round(name == "cache", extras) for name in rounds}
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}\n")
    print("| kernel cache | install, in turn | wall [s] | CPU [s] | modules copied / compiled | venv after [MB] |")
    print("|---|---|---|---|---|---|")
    for name, rows in table.items():
        label = "per machine (empty at the start)" if name == "cache" else "off (`KANAT_KERNEL_CACHE=0`)"
        for row in rows:
            print(f"| {label} | `pip install -e \".[{row['extra']}]\"` | {row['wall']:.0f} | {row['cpu']:.0f} | "
                  f"{row['copied']} / {row['compiled']} | {row['venv']:.0f} |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", default="cache,nocache")
    parser.add_argument("--extras", default="plot,test")
    arguments = parser.parse_args()
    main(arguments.rounds.split(","), arguments.extras.split(","))
