"""Mutate statics examples at random and count how their steady states end.

    python scripts/fuzz_steady_checks.py N [SEED] [--unchecked]

solves N random mutations (log-uniform speeds, depths, lengths, buoyancies and tangential
drag) of ``towed_body.yaml``, ``subsurface_buoy.yaml`` and ``mooring_3leg.yaml``, counts the
statuses (``ok``, each failed check, refused or no steady state, over 20 s) and recomputes
every check on each ``ok`` result with the oracle of ``tests/statics/test_steady_checks.py``
(``independent_checks``). ``--unchecked`` solves as the statics did before their checks
(every solved state ``ok``), to count the impossible states the checks now catch.
"""
from __future__ import annotations

import collections
import random
import signal
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from kanat import api, load_case  # noqa: E402
from kanat.errors import KanatError  # noqa: E402
from test_steady_checks import EXAMPLES, independent_checks  # noqa: E402

TIME_LIMIT_S = 20


class _Slow(Exception):
    """A solve that took more than :data:`TIME_LIMIT_S`."""


def _log_uniform(rng: random.Random, low: float, high: float) -> float:
    return 10 ** rng.uniform(np.log10(low), np.log10(high))


def mutations(rng: random.Random) -> dict:
    """One random mutation of each example, by file name."""
    u = lambda low, high: _log_uniform(rng, low, high)       # noqa: E731
    legs = u(80, 3000)
    return {
        "towed_body.yaml": {"vessel.track[0].speed_kn": u(0.1, 3000), "environment.depth": u(20, 6000),
                            "bodies.sled.net_buoyancy": -u(10, 1e6), "cables[0].length": u(10, 1e4),
                            "line_types.towcable.drag_tangential": rng.choice([0, 0.01, 1, 1e4, 1e7])},
        "subsurface_buoy.yaml": {"bodies.buoy.net_buoyancy": rng.choice([-1, 1]) * u(10, 1e6),
                                 "environment.depth": u(50, 6000), "cables[0].length": u(10, 5000)},
        "mooring_3leg.yaml": {**{f"cables[{i}].length": legs for i in range(3)}, "environment.depth": u(50, 1000)},
    }


def outcome_of(name: str, changes: dict) -> tuple[str, object, object]:
    """``(label, case, dataset)``: the status's check name, ``ok``, or why there is no state."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = load_case(EXAMPLES / name).replace(changes)
            signal.alarm(TIME_LIMIT_S)
            try:
                outcome = api.run(case, model="statics")
            finally:
                signal.alarm(0)
    except KanatError:
        return "refused or no steady state", None, None
    except _Slow:
        return f"over {TIME_LIMIT_S} s", None, None
    label = "ok" if outcome.ok else outcome.status.split(":")[1].strip()
    return label, case, outcome.dataset


def main(n: int, seed: int, unchecked: bool) -> None:
    if unchecked:
        import kanat.statics.driver as driver
        import kanat.statics.network_result as network
        from kanat.statics.steady_checks import Verdict

        driver.check_result = network.check_result = lambda result: Verdict()

    def _alarm(*_):
        raise _Slow()

    signal.signal(signal.SIGALRM, _alarm)
    rng, count, start = random.Random(seed), collections.Counter(), time.perf_counter()
    for _ in range(n):
        name, changes = rng.choice(list(mutations(rng).items()))
        label, case, ds = outcome_of(name, changes)
        count[label] += 1
        if label == "ok":
            try:
                independent_checks(case, ds)
            except AssertionError:
                count["ok but a check fails"] += 1
                print(f"ok but a check fails: {name} {changes}")
    print(f"{n} cases in {time.perf_counter() - start:.0f} s: {dict(count)}")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    main(int(args[0]), int(args[1]) if len(args) > 1 else 1, "--unchecked" in sys.argv)
