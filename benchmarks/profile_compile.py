"""Where a family's first-run compile time goes, function by function (numba's compile events).

Runs the shortened example of one family (:data:`bench_compile.EXAMPLES`) in a fresh process
with an empty ``NUMBA_CACHE_DIR`` and records numba's ``numba:compile`` events: for every
compiled function and type signature, its inclusive time (from the start of its compile to
its end, callees included) and its exclusive time (callees' compiles taken out), in CPU seconds
of the process, and of that the time spent in LLVM (numba's ``CodeLibrary.add_ir_module``, which
optimizes the function, and ``finalize``, which links every callee in again, optimizes the whole
module and generates its machine code; summed over the versions of a name). The rest is numba's
Python front end (typing and lowering to LLVM IR). A deep call tree pays for its leaves at every
level of ``finalize``. Functions compiled for more than one signature are the duplicated
specializations to look for (literal ints, None vs array, float vs complex). CPU-bound: run it
on a quiet machine and repeat.

Run: ``python benchmarks/profile_compile.py FAMILY [--top 30]``.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent

CHILD = r"""
import json, sys, time, resource
from numba.core import codegen, event
from kanat.api import load_case, simulate

records, stack = [], []
llvm = {}                       # library name: CPU s in LLVM (parsing, optimizing, machine code)


def timed(method):
    def wrapper(library, *args):
        start = time.process_time()
        method(library, *args)
        llvm[library.name] = llvm.get(library.name, 0.0) + time.process_time() - start
    return wrapper


codegen.CPUCodeLibrary.add_ir_module = timed(codegen.CPUCodeLibrary.add_ir_module)
codegen.CPUCodeLibrary.finalize = timed(codegen.CPUCodeLibrary.finalize)

class Listener(event.Listener):
    def on_start(self, ev):
        stack.append([ev.data["dispatcher"], ev.data["args"], time.process_time(), 0.0])

    def on_end(self, ev):
        dispatcher, args, start, inside = stack.pop()
        total = time.process_time() - start
        if stack:
            stack[-1][3] += total
        records.append([dispatcher, ev.data["args"], total, total - inside])

case = load_case(sys.argv[1])
with event.install_listener("numba:compile", Listener()):
    simulate(case)
usage = resource.getrusage(resource.RUSAGE_SELF)
rows = []
for dispatcher, args, total, own in records:
    func = dispatcher.py_func
    rows.append([f"{func.__module__}.{func.__qualname__}", str(args), total, own, llvm.get(func.__qualname__, 0.0)])
print(json.dumps({"records": rows, "cpu": usage.ru_utime + usage.ru_stime}))
"""


def profile(case: Path) -> dict:
    """The compile records of one run of ``case`` on an empty numba cache."""
    env = dict(os.environ, KANAT_AOT="0", NUMBA_CACHE_DIR=tempfile.mkdtemp())   # numba's kernels, compiled here
    done = subprocess.run([sys.executable, "-c", CHILD, str(case)], env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(done.stderr[-3000:])
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    sys.path.insert(0, str(HERE))
    from bench_compile import EXAMPLES, short_case

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("family", choices=list(EXAMPLES))
    parser.add_argument("--top", type=int, default=30)
    args = parser.parse_args(argv)
    example, changes = EXAMPLES[args.family]
    result = profile(short_case(example, changes, Path(tempfile.mkdtemp())))
    records = result["records"]
    top_level = sum(r[3] for r in records)
    llvm = sum({r[0]: r[4] for r in records}.values())
    print(f"{args.family} ({example}): {len(records)} compiled versions, {top_level:.2f} s of compiling "
          f"({llvm:.2f} s of it in LLVM), "
          f"{result['cpu']:.2f} s CPU of the whole process\n")
    print("| function | signature | exclusive [s] | of it LLVM [s] | inclusive [s] |\n|---|---|---|---|---|")
    for name, sig, total, own, llvm in sorted(records, key=lambda r: -r[3])[:args.top]:
        print(f"| {name.replace('kanat.continuum.', '')} | {sig[:60]} | {own:.3f} | {llvm:.3f} | {total:.3f} |")
    versions = defaultdict(list)
    for name, sig, _total, own, _llvm in records:
        versions[name].append((sig, own))
    repeated = {name: v for name, v in versions.items() if len(v) > 1}
    if repeated:
        print("\nCompiled for more than one signature:")
        for name, v in sorted(repeated.items(), key=lambda kv: -sum(o for _s, o in kv[1])):
            print(f"- {name}: " + "; ".join(f"{s[:60]} ({o:.2f} s)" for s, o in v))


if __name__ == "__main__":
    main()
