"""First-run compile cost per kind of run: ``kanat run`` on a fresh numba cache, then again.

For each example (one per kernel family, :data:`kanat.warmup.FAMILIES`), shortened to a few
steps, the whole process ``kanat run CASE -o OUT.nc`` runs with an empty ``NUMBA_CACHE_DIR``
(cold: what a fresh machine's first run pays) and then with the cache it left (warm). The
compile cost is cold minus warm, in CPU seconds of the whole process (less sensitive than wall
time to other load on the machine); wall times beside. With ``--baseline DIR`` (a checkout of an
older kanat) the same runs of that tree interleave with this one's (A B A B ...). Medians of
``--repeats``. ``kanat warmup`` time (all families, cold) last.

It measures numba's just-in-time compile, so the runs use numba's kernels (``KANAT_AOT=0``): with
the kernels compiled at install (``kanat.aot``) a first run compiles nothing at all
(``benchmarks/bench_install.py`` times that install and first run).

Run: ``python benchmarks/bench_compile.py [--repeats 3] [--baseline /path/to/old/checkout] [--tree /path]
[--families NAME ...] [--no-warmup]``.
"""
from __future__ import annotations

import argparse
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = {                       # family: (example, changes to keep it to a few steps)
    "continuum-2d": ("speed_step_2d.yaml", {"duration": 5.0}),
    "continuum-3d": ("turn_360_3d.yaml", {"duration": 10.0}),
    "lumped-rk4": ("trawl_head_5.6s_1to4.yaml", {"duration": 1.0}),
    "lumped-implicit": ("trawl_head_5.6s_1to4.yaml", {"duration": 1.0, "scheme": "generalized-alpha-lumped",
                                                        "dt": 0.05}),
    "factorized-2d": ("factorization_accel.yaml", {"duration": 0.02}),
    "factorized-3d": ("factorization_spatial100.yaml", {"scheme": "factorized", "dt": 0.005, "duration": 0.02,
                                                  "output_dt": 0.005}),
    "wave-factorized-2d": ("factorization_planar80.yaml", {"duration": 0.5}),
    "wave-factorized-3d": ("factorization_spatial100.yaml", {"duration": 1.0}),
}


def short_case(example: str, changes: dict, folder: Path) -> Path:
    data = yaml.safe_load((ROOT / "examples" / example).read_text())
    data["simulation"].update(changes)
    path = folder / f"{Path(example).stem}-{changes.get('scheme', 'default')}.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def timed(command: list[str], env: dict) -> tuple[float, float, str]:
    """(wall s, CPU s of the child, last line of its output) of one whole process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
    return wall, cpu, (done.stdout.strip().splitlines() or [""])[-1]


def kanat_command(tree: Path | None, case: Path, out: Path) -> tuple[list[str], dict]:
    env = dict(os.environ, KANAT_AOT="0")            # numba's kernels: the install's compile nothing
    if tree is not None:
        env["PYTHONPATH"] = str(tree / "src")
    return [sys.executable, "-c", "import sys; from kanat.cli import app; sys.exit(app())", "run", str(case),
            "-o", str(out)], env


def cold_and_warm(tree: Path | None, case: Path, folder: Path) -> dict:
    cache = Path(tempfile.mkdtemp(dir=folder))
    command, env = kanat_command(tree, case, folder / "out.nc")
    env["NUMBA_CACHE_DIR"] = str(cache)
    cold = timed(command, env)
    warm = timed(command, env)
    return {"cold_wall": cold[0], "cold_cpu": cold[1], "warm_wall": warm[0], "warm_cpu": warm[1]}


def warmup_all(tree: Path | None, folder: Path) -> tuple[float, float]:
    env = dict(os.environ, KANAT_AOT="0", NUMBA_CACHE_DIR=str(Path(tempfile.mkdtemp(dir=folder))))
    if tree is not None:
        env["PYTHONPATH"] = str(tree / "src")
    code = ("from kanat import warmup; from kanat.api import load_case, simulate; "
            "warmup.warmup(lambda c: simulate(load_case(c)))")
    wall, cpu, _ = timed([sys.executable, "-c", code], env)
    return wall, cpu


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--baseline", type=Path, help="an older kanat checkout to compare with")
    parser.add_argument("--tree", type=Path, help="the checkout to measure (default: the installed kanat)")
    parser.add_argument("--families", nargs="+", default=list(EXAMPLES), choices=list(EXAMPLES))
    parser.add_argument("--no-warmup", action="store_true", help="skip the closing `kanat warmup` timing")
    args = parser.parse_args(argv)
    folder = Path(tempfile.mkdtemp())
    trees = {"this": args.tree} if args.baseline is None else {"baseline": args.baseline, "this": args.tree}
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"load average before: {os.getloadavg()[0]:.2f}\n")
    header = "| family (example, shortened) | tree | compile = cold - warm, CPU [s] | cold wall [s] | warm wall [s] |"
    print(header + "\n|---|---|---|---|---|")
    for family in args.families:
        example, changes = EXAMPLES[family]
        case = short_case(example, changes, folder)
        runs = {name: [] for name in trees}
        for _ in range(args.repeats):
            for name, tree in trees.items():                       # interleaved A B A B ...
                runs[name].append(cold_and_warm(tree, case, folder))
        for name, rows in runs.items():
            med = {k: statistics.median(r[k] for r in rows) for k in rows[0]}
            print(f"| {family} ({example}) | {name} | {med['cold_cpu'] - med['warm_cpu']:.2f} | "
                  f"{med['cold_wall']:.2f} | {med['warm_wall']:.2f} |", flush=True)
    if not args.no_warmup:
        wall, cpu = warmup_all(args.tree, folder)
        print(f"\n`kanat warmup` equivalent (every family, cold cache): {wall:.1f} s wall, {cpu:.1f} s CPU")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
