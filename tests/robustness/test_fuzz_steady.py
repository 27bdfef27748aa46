"""A sample of the fuzz round of steady states (benchmarks/fuzz_steady.py): examples with keys
scaled by powers of ten, signs flipped, keys deleted and types swapped, each read and solved to its
steady state in a worker process with a time limit.

Oracle: the contract of issue 22. Every case is a clear error (a CaseError naming file and key,
or a KanatError's one message), a ``failed: ...`` steady state, or an ``ok`` one that passes the
steady checks recomputed from the result as written; never a traceback, a hang or an ok state
failing a check. The full round (2,400 cases) is a script; its counts are in benchmarks/RESULTS.md.
"""
import sys

import pytest

from helpers import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
import fuzz_steady  # noqa: E402

SAMPLE = 60
"""Cases of the sample: the full round's first 60 with its seed (25 s on an idle 2-core machine,
about 80 s under a load of 10)."""


@pytest.mark.slow
def test_a_sample_of_mutated_examples_keeps_the_contract():
    summary = fuzz_steady.fuzz_round(SAMPLE, seed=22, limit=60.0)
    assert summary["broken"] == [], summary["broken"]
    outcomes = summary["outcomes"]
    assert sum(outcomes.get(k, 0) for k in fuzz_steady.CONTRACT) == SAMPLE
    assert all(outcomes.get(k, 0) > 0 for k in fuzz_steady.CONTRACT), outcomes     # every kind is exercised


def test_mutations_are_the_same_for_the_same_seed_and_change_the_cases():
    import yaml

    first = list(fuzz_steady.cases(40, seed=3))
    assert first == list(fuzz_steady.cases(40, seed=3))
    originals = {name: yaml.safe_load((fuzz_steady.EXAMPLES / f"{name}.yaml").read_text())
                 for name in fuzz_steady.BASES}
    changed = [index for index, name, _, text in first if yaml.safe_load(text) != originals[name]]
    assert len(changed) >= 36                    # a zero scaled or flipped stays what it was
