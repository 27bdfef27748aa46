"""Why a dynamic model found no initial state: the case's statics and their checks.

A dynamic model starts from a steady state of its own (the continuum model's Newton on the
steady box equations, the lumped model's equilibrium). When that fails, its solver's message
says what did not converge, not why: a tow whose body would hang 129 m under a 100 m seabed
ends as "the steady state on the seabed did not converge". :func:`steady_failure` solves the
case's statics (no winch, the environment at t = 0) under a short time budget and returns the
failed check of :mod:`kanat.statics.steady_checks` that says why (``seabed: body 'sled' at
cable 'tow' node 100 (s = 1000 m) is 129.1 m below the seabed ...``), or None.
"""
from __future__ import annotations

import logging
import warnings

from kanat.statics.budget import budget, seconds_limit

DIAGNOSIS_SECONDS = 10.0
"""Wall time the statics of a failed start may take [s] (the examples' take under 3 s; less when
``KANAT_STATICS_SECONDS`` says less)."""

log = logging.getLogger(__name__)


def steady_failure(case) -> str | None:
    """The failed steady check of ``case``'s statics, or None (they pass, or find no state).

    Parameters
    ----------
    case : kanat.model.Case
        A dynamic case whose model found no initial state.

    Returns
    -------
    str or None
        ``<check>: <message>`` (:attr:`kanat.statics.steady_checks.Verdict.failure`).
    """
    from kanat.statics.driver import solve_statics        # only on a failed start: SciPy's solvers cost 0.3 s

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")              # the case checks' notes on a statics variant
            statics = case.replace({"model": "statics", "winch": []})
            statics = statics.model_copy(update={"environment": statics.environment.at_start()})
            with budget("the statics of a failed start", seconds=min(DIAGNOSIS_SECONDS, seconds_limit())):
                return solve_statics(statics).verdict.failure
    except Exception as error:        # noqa: BLE001 - a diagnosis that fails explains nothing more
        log.debug(f"no statics to explain the failed start: {type(error).__name__}: {error}")
        return None
