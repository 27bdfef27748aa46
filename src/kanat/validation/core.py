"""Validation checks: a registry of small functions, each with its oracle and tolerance.

A check is a function returning ``(measured, expected)`` (numbers) or a
:class:`CheckResult`; it is registered with :func:`check`, which records its theory/validation-cases.md case,
what it measures, the oracle (with its source) and the tolerance. :func:`run_suite` runs
them and turns every outcome, exceptions included, into a :class:`CheckResult`.
"""
from __future__ import annotations

import time
import traceback
from dataclasses import dataclass, replace

import numpy as np

from kanat.errors import KanatError


@dataclass(frozen=True)
class Tolerance:
    """``|measured - expected| <= abs + rel * |expected|``; text says it in words."""

    abs: float = 0.0
    rel: float = 0.0

    def accepts(self, measured: float, expected: float) -> bool:
        return bool(np.isfinite(measured) and abs(measured - expected) <= self.abs + self.rel * abs(expected))

    def __str__(self) -> str:
        parts = ([f"± {self.abs:.3g}"] if self.abs else []) + ([f"± {100 * self.rel:.3g} %"] if self.rel else [])
        return " + ".join(parts) or "exact"


@dataclass(frozen=True)
class CheckResult:
    """The outcome of one check.

    Attributes
    ----------
    check_id, spec, title, oracle, units : str
        What was checked, its theory/validation-cases.md case, the oracle (and source) and the units.
    tolerance : Tolerance
    measured, expected : float
    passed : bool
    seconds : float
        Wall time of the check.
    error : str
        The exception message when the check could not run (then ``passed`` is False).
    """

    check_id: str
    spec: str
    title: str
    oracle: str
    tolerance: Tolerance
    units: str = ""
    measured: float = float("nan")
    expected: float = float("nan")
    passed: bool = False
    seconds: float = 0.0
    error: str = ""

    @property
    def measured_text(self) -> str:
        if self.error:
            return f"error: {self.error.splitlines()[0]}"
        units = f" {self.units}" if self.units else ""
        return f"{self.measured:.6g}{units} (expected {self.expected:.6g}{units} {self.tolerance})"


@dataclass(frozen=True)
class Check:
    """A registered check (see :func:`check`)."""

    check_id: str
    spec: str
    title: str
    oracle: str
    tolerance: Tolerance
    units: str
    function: object

    def run(self) -> CheckResult:
        base = CheckResult(self.check_id, self.spec, self.title, self.oracle, self.tolerance, self.units)
        start = time.perf_counter()
        try:
            measured, expected = self.function()
            measured, expected = float(measured), float(expected)
            result = replace(base, measured=measured, expected=expected,
                             passed=self.tolerance.accepts(measured, expected))
        except Exception as error:  # noqa: BLE001 - a check that cannot run fails, with its message
            result = replace(base, error=f"{type(error).__name__}: {error}\n{traceback.format_exc(limit=4)}")
        return replace(result, seconds=time.perf_counter() - start)


REGISTRY: dict[str, Check] = {}
"""Checks by id, in the order registered (filled when :mod:`kanat.validation` is imported)."""


def check(check_id: str, spec: str, title: str, oracle: str, tolerance: Tolerance, units: str = ""):
    """Register a check function returning ``(measured, expected)``."""
    def register(function):
        REGISTRY[check_id] = Check(check_id, spec, title, oracle, tolerance, units, function)
        return function
    return register


def run_suite(only=None) -> list[CheckResult]:
    """Run the registered checks (all, or those whose ids are in ``only``).

    Raises
    ------
    KanatError
        For an unknown id in ``only`` (listing the valid ones).
    """
    ids = list(REGISTRY) if not only else list(only)
    unknown = [i for i in ids if i not in REGISTRY]
    if unknown:
        raise KanatError(f"unknown check(s) {', '.join(unknown)}; valid: {', '.join(REGISTRY)}")
    return [REGISTRY[i].run() for i in ids]


NOT_IN_SUITE = [
    ("7.6", "cross-model towed-body speed step by every continuum scheme and the lumped model, converging together",
     "minutes of runs on refined grids"),
    ("7.7", "Kaliukh & Vusatiuk 2018: full vs factorized algorithms, 2- vs 3-block wave factorization, CFL ranges, speed-ups",
     "long runs (benchmarks)"),
    ("7.8", "Zhang, Zhang & Liu 2012: the 375° turn with the four time schemes (kanat study compare-schemes)", "a 740 s 3-D run per scheme"),
    ("7.9", "Gaisha: the M0 surfaces", "a scan over M0 (kanat pitch --plot)"),
    ("7.10", "Bezverkhyi 2006: the branched trawl findings; energy conservation of the lumped model over 100 periods",
     "tests/lumped/test_lumped_oracles.py (slow marker), examples/trawl_*"),
]
"""theory/validation-cases.md cases too slow for the suite: (case, what, where it is checked instead)."""
