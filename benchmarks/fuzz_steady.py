"""A fuzz round of steady states: the shipped examples with their keys mutated, each case read,
solved to its steady state and classified.

Mutations (1 or 2 per case, from a seeded generator): a number scaled by a power of ten
(1e-6 ... 1e6), a number's sign flipped, a key or list item deleted, a value's type swapped
(a number written as text, text as a number, a list as its first item, a mapping as a list of its
values). The steady state is the statics of a statics example and the initial state (t = 0) of a
dynamic one (its run cut to one time step).

Every case must end in one of (the contract of issue 22):

* ``error``: a clear error (:class:`~kanat.errors.CaseError` whose errors name the file and the
  key, or the line of a missing top-level key, or another :class:`~kanat.errors.KanatError` with
  its one message): no traceback;
* ``failed``: a steady state whose status is ``failed: ...`` (a check named);
* ``ok``: a steady state whose status is ``ok`` and that passes the steady checks again, recomputed
  from the result as written (positions, tensions, bodies), all of them for statics and those a
  dynamic model leaves to them plus finiteness and strain at t = 0.

Anything else breaks the contract: ``unnamed`` (an error without file or key), ``unexpected``
(another exception: a crash), ``hang`` (no answer within the per-case time limit: the worker is
killed) and ``ok-failing`` (ok but a check fails). Each case runs in a worker process that is
replaced after a hang.

Run the full round (2,400 cases, 27 min on a 2-core machine under a load of 10) and print the counts::

    python benchmarks/fuzz_steady.py --cases 2400 --seed 22 --limit 60

The test suite runs a sample (tests/robustness/test_fuzz_steady.py). The full round with seed 22
(benchmarks/RESULTS.md): 1,479 clear errors, 140 failed steady states, 779 ok ones all passing the
checks, 0 exceptions; 2 cases past the 60 s limit (one ok in 65 s alone, one a continuum model's
steady state on the seabed of 6,000 segments that outgrew 7 GiB).
"""
from __future__ import annotations

import argparse
import collections
import json
import multiprocessing
import os
import random
import sys
import time
import warnings
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
BASES = ["mooring_3leg", "mooring_buoy_decay", "mooring_buoy_waves", "mooring_current", "turn_375",
         "speed_step_2d", "subsurface_buoy", "subsurface_mooring", "surface_mooring_waves", "tow_payout_turn",
         "towed_array", "towed_body", "turn_360_3d", "whoi/bimoor", "whoi/cmo", "whoi/loops", "whoi/mine",
         "whoi/multi_leg", "whoi/multi_leg_3d", "whoi/mpl"]
"""Examples whose steady state takes a few seconds at most (the others' would dominate the round)."""
FILE = "fuzz.yaml"
POWERS = (-6, -3, -2, -1, 1, 2, 3, 6)
CONTRACT = ("error", "failed", "ok")
"""The outcomes the contract allows; any other breaks it."""
DYNAMIC_CHECKS = ("finite", "strain", "tension", "reach", "bodies")
"""The checks recomputed on an ok initial state of a dynamic model (the seabed is its own contact's)."""


# --- mutations ------------------------------------------------------------------------------

def paths(node, path=()):
    """Every key path of a YAML tree below the root."""
    found = []
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
    for key, child in items:
        found.append(path + (key,))
        found += paths(child, path + (key,))
    return found


def is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def mutate(tree, rng: random.Random) -> str:
    """Apply one mutation to ``tree`` in place; return what it did (``scale cables.0.length 1e3``)."""
    every = paths(tree)
    numbers = [p for p in every if is_number(_get(tree, p))]
    op = rng.choice(["scale", "scale", "flip", "delete", "swap"] if numbers else ["delete", "swap"])
    path = rng.choice(numbers if op in ("scale", "flip") else every)
    parent, key = _get(tree, path[:-1]), path[-1]
    value = parent[key]
    where = ".".join(map(str, path))
    if op == "scale":
        power = rng.choice(POWERS)
        parent[key] = value * 10.0 ** power
        return f"scale {where} 1e{power}"
    if op == "flip":
        parent[key] = -value
        return f"flip {where}"
    if op == "delete":
        del parent[key]
        return f"delete {where}"
    parent[key] = _swapped(value, rng)
    return f"swap {where}"


def _swapped(value, rng: random.Random):
    if is_number(value):
        return rng.choice([str(value), [value], {"value": value}, True])
    if isinstance(value, str):
        return rng.choice([1.0, 0, [value], None])
    if isinstance(value, list):
        return value[0] if value else 0
    if isinstance(value, dict):
        return list(value.values())
    return "text"


def _get(node, path):
    for key in path:
        node = node[key]
    return node


def cases(count: int, seed: int):
    """``count`` cases ``(index, base, mutations, text)``, the same for the same seed."""
    rng = random.Random(seed)
    trees = {name: (EXAMPLES / f"{name}.yaml").read_text() for name in BASES}
    for index in range(count):
        name = BASES[index % len(BASES)]
        tree = yaml.safe_load(trees[name])
        done = [mutate(tree, rng) for _ in range(rng.choice([1, 1, 2]))]
        yield index, name, done, yaml.safe_dump(tree, sort_keys=False)


# --- one case ------------------------------------------------------------------------------

def classify(text: str) -> tuple[str, str]:
    """The outcome of one case and its message (see the module docstring)."""
    from kanat import api
    from kanat.errors import CaseError, KanatError
    from kanat.io import parse_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            case = parse_case(text, FILE)
        except CaseError as error:
            errors = [p for p in error.problems if p.severity == "error"]
            named = errors and all(p.file == FILE and (p.key or p.line) for p in errors)   # a root key: its line
            first = errors[0] if errors else None
            where = "" if first is None else f"{first.file}:{first.line}: {first.key}: {first.message}"
            return ("error" if named else "unnamed"), where[:300]
        except KanatError as error:
            return "error", str(error)[:300]
        except Exception as error:  # noqa: BLE001 - counted: it breaks the contract
            return "unexpected", f"reading: {type(error).__name__}: {error}"[:300]
        if case.model not in ("statics", "continuum", "lumped") or case.sphere_two_cables is not None:
            return "error", f"model {case.model}: no steady state to check"
        try:
            outcome = api.run(_one_step(case))
            status = outcome.status
            if status != "ok":
                return "failed", status[:300]
            failure = recheck(case, outcome.dataset)
        except KanatError as error:
            return "error", str(error).splitlines()[0][:300]
        except Exception as error:  # noqa: BLE001 - counted: it breaks the contract
            return "unexpected", f"solving: {type(error).__name__}: {error}"[:300]
    return ("ok", "") if failure is None else ("ok-failing", failure[:300])


def _one_step(case):
    """A dynamic case cut to its initial state and one step; a statics case as it is."""
    if case.model == "statics":
        return case
    sim = case.simulation
    step = sim.dt or sim.output_interval
    return case.replace({"simulation.duration": step, "simulation.output_dt": step})


def recheck(case, ds) -> str | None:
    """The steady checks recomputed from a result as written; the first failure or None."""
    import numpy as np

    from kanat.statics.steady_checks import check_steady, nodes_by_cable

    if "time" in ds.dims:
        ds = ds.isel(time=0)
        only = DYNAMIC_CHECKS
    else:
        only = None
    if "position" not in ds:
        return None
    nodes = nodes_by_cable(ds["cable"].values, ds["s"].values, ds["position"].values, ds["tension"].values)
    if only is None and "grounded_length" in ds and "cable_name" in ds:
        for name, length in zip(np.asarray(ds["cable_name"].values).astype(str), ds["grounded_length"].values):
            if name in nodes:
                object.__setattr__(nodes[name], "grounded_length", float(length))
    bodies = attitudes = None
    if "body" in ds.dims and "body_position" in ds:
        names = [str(b) for b in ds["body"].values]
        bodies = dict(zip(names, ds["body_position"].values))
        if "body_attitude" in ds:
            attitudes = dict(zip(names, ds["body_attitude"].values))
    return check_steady(case, nodes, only=only, bodies=bodies, attitudes=attitudes).failure


# --- the round -----------------------------------------------------------------------------

MEMORY_LIMIT = 6 * 1024**3
"""Address space a worker may take [bytes]: a case that wants more ends in MemoryError (counted as
``unexpected``) instead of crowding out the machine."""


def _worker(connection) -> None:
    import resource

    os.environ.setdefault("KANAT_STATICS_SECONDS", "30")
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    import logging

    logging.disable(logging.WARNING)
    sys.stdout = open(os.devnull, "w")                      # kernels' compile notes
    while True:
        text = connection.recv()
        if text is None:
            return
        connection.send(classify(text))


class Worker:
    """A process that classifies cases, killed and replaced when one overruns its limit."""

    def __init__(self):
        self.start()

    def start(self) -> None:
        context = multiprocessing.get_context("spawn")
        self.connection, child = context.Pipe()
        self.process = context.Process(target=_worker, args=(child,), daemon=True)
        self.process.start()

    def classify(self, text: str, limit: float) -> tuple[str, str]:
        self.connection.send(text)
        if self.connection.poll(limit):
            try:
                return self.connection.recv()
            except EOFError:
                pass
            self.process.join()
            code = self.process.exitcode
            self.start()
            return "unexpected", f"the worker died (exit code {code})"
        self.process.kill()
        self.process.join()
        self.start()
        return "hang", f"no answer within {limit:g} s"

    def close(self) -> None:
        self.connection.send(None)
        self.process.join(timeout=10)


def fuzz_round(count: int, seed: int, limit: float, log=None) -> dict:
    """Classify ``count`` cases; return the counts by outcome, by base and the cases that break
    the contract."""
    worker = Worker()
    counts, by_check, broken = collections.Counter(), collections.Counter(), []
    started = time.perf_counter()
    try:
        for index, name, done, text in cases(count, seed):
            outcome, message = worker.classify(text, limit)
            counts[outcome] += 1
            if outcome == "failed":
                by_check[_kind(message)] += 1
            if outcome == "error" and message.startswith(f"{FILE}:"):
                counts["error with file, line and key" if not message.startswith(f"{FILE}:None:")
                       else "error with file and key, no line"] += 1
            if outcome not in CONTRACT:
                broken.append({"index": index, "base": name, "mutations": done, "outcome": outcome,
                               "message": message})
            if log is not None:
                log.write(json.dumps({"index": index, "base": name, "mutations": done, "outcome": outcome,
                                      "message": message}) + "\n")
                log.flush()
    finally:
        worker.close()
    return {"cases": count, "seed": seed, "limit_s": limit, "seconds": time.perf_counter() - started,
            "outcomes": dict(counts), "failed_by_check": dict(by_check.most_common()), "broken": broken}


def _kind(status: str) -> str:
    """What a failed status is about: the steady check's name, or the first words of a model's message."""
    text = status.removeprefix("failed: ")
    head = text.split(":")[0]
    return head if len(head) < 20 else " ".join(text.split()[:3])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=2400)
    parser.add_argument("--seed", type=int, default=22)
    parser.add_argument("--limit", type=float, default=60.0, help="seconds a case may take")
    parser.add_argument("--log", type=Path, help="JSON lines, one per case")
    args = parser.parse_args()
    log = args.log.open("w") if args.log else None
    summary = fuzz_round(args.cases, args.seed, args.limit, log)
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
