"""The validation suite: the fast cases of theory/validation-cases.md, each with its oracle, tolerance and measured value.

Public API
----------
run_suite(only=None) -> list of CheckResult
    Run every registered check (or those named); a check that raises fails with its message.
REGISTRY
    The checks by id (:mod:`.checks_statics`, :mod:`.checks_dynamics`).
NOT_IN_SUITE
    The theory/validation-cases.md cases too slow for the suite, and where they are checked instead.
"""
from kanat.validation import checks_dynamics, checks_statics  # noqa: F401 - registers the checks
from kanat.validation.core import NOT_IN_SUITE, REGISTRY, Check, CheckResult, Tolerance, check, run_suite


__all__ = ["NOT_IN_SUITE", "REGISTRY", "Check", "CheckResult", "Tolerance", "check", "run_suite"]
