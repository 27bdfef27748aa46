"""The work a steady solver may do before it gives up: CPU time and evaluations.

Shooting integrates the steady equations once per trial of its unknowns and collocation
iterates on a mesh it refines; on a case with no steady state (a line whose two ends are
one point, a current of hundreds of m/s) either can take tiny step after tiny step without
ever failing. Every evaluation of the steady equations (:func:`kanat.statics.problem.steady_rhs`,
:func:`kanat.statics.spatial.rhs`) is charged to the budget of the solve in progress, which
ends the solve with :class:`BudgetExceeded` (a clear message, written as the result's status)
once it has used :data:`MAX_SECONDS` of CPU or made :data:`MAX_EVALUATIONS` evaluations. Solvers
whose iterations are few and long (the lumped model's equilibrium, network statics) call
:func:`check_time` once an iteration.

The examples solve in under 3 s and with at most ~5 500 evaluations (subsurface_mooring.yaml);
the limits are 40 and 90 times that. The environment variable ``KANAT_STATICS_SECONDS`` sets
the time limit (a number of seconds).

The time is the process's CPU time (:func:`time.process_time`), not the wall clock: a solve that
makes no progress spends CPU as it spins, so it is caught all the same, while a solve that makes
progress on a machine shared with other work (a study's workers, a test suite) is not failed for
the time it waited for a core (WHOI's ``deep_s`` equilibrium: 29-37 s of CPU, which took up to
161 s of wall time beside other runs).

The budget is held in a :class:`contextvars.ContextVar` for the duration of one
``with budget(...)`` block (a solve), so that the solvers' signatures stay those of their
papers; outside such a block nothing is charged.
"""
from __future__ import annotations

import contextlib
import os
import time
from contextvars import ContextVar
from dataclasses import dataclass, field

from kanat.errors import KanatError

MAX_SECONDS = 120.0
"""CPU time of one steady solve [s] (the slowest example takes ~3 s; WHOI's ``deep_s`` ~30 s)."""
MAX_EVALUATIONS = 500_000
"""Evaluations of the steady equations in one solve (the examples make at most ~5 500)."""
SECONDS_ENV = "KANAT_STATICS_SECONDS"
CLOCK_EVERY = 64
"""Evaluations between two readings of the clock (an evaluation costs ~10 us, a reading ~0.1 us)."""


class BudgetExceeded(KanatError):
    """A steady solve that ran out of time or evaluations; not a :class:`~kanat.errors.SolverError`,
    so that no solver's fallback tries again with what is left."""


@dataclass
class Budget:
    """What one solve may still spend.

    Attributes
    ----------
    seconds : float
        CPU-time limit [s].
    evaluations : int
        Limit on evaluations of the steady equations.
    what : str
        The solve, for the message (``"statics of cable 'riser'"``).
    """

    seconds: float
    evaluations: int
    what: str = "the steady solve"
    started: float = field(default_factory=time.process_time)
    used: int = 0

    def charge(self, count: int = 1) -> None:
        """Count ``count`` evaluations; raise :class:`BudgetExceeded` past either limit."""
        self.used += count
        if self.used > self.evaluations:
            raise BudgetExceeded(
                f"{self.what} gave up after {self.used:,} evaluations of the steady equations "
                f"(the limit is {self.evaluations:,}; the examples need at most ~5,500): the solver "
                "is making no progress, which usually means the case has no steady state (both ends "
                "of a line at one point, a current of hundreds of m/s, ...); check the case")
        if self.used % CLOCK_EVERY == 0:
            self.check_time()

    def check_time(self) -> None:
        """Raise :class:`BudgetExceeded` past the time limit (an iteration of a solver whose
        iterations are few and long calls it each time)."""
        elapsed = time.process_time() - self.started
        if elapsed > self.seconds:
            work = f"; {self.used:,} evaluations of the steady equations" if self.used else ""
            raise BudgetExceeded(
                f"{self.what} gave up after {elapsed:.3g} s of CPU (the limit is {self.seconds:g} s{work}): "
                "the solver is making no "
                "progress, which usually means the case has no steady state (both ends of a "
                "line at one point, a current of hundreds of m/s, ...); check the case, or "
                f"raise the limit with {SECONDS_ENV}=600")


_ACTIVE: ContextVar[Budget | None] = ContextVar("kanat_statics_budget", default=None)


def seconds_limit() -> float:
    """:data:`MAX_SECONDS`, or the environment variable :data:`SECONDS_ENV` when set."""
    text = os.environ.get(SECONDS_ENV)
    if text is None or not text.strip():
        return MAX_SECONDS
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not value > 0 or value == float("inf"):
        raise KanatError(f"{SECONDS_ENV}={text!r} is not a number of seconds above 0 (e.g. 600)")
    return value


@contextlib.contextmanager
def budget(what: str = "the steady solve", seconds: float | None = None,
           evaluations: int = MAX_EVALUATIONS):
    """Run the block under a fresh budget (a nested block keeps the outer one).

    Parameters
    ----------
    what : str
        The solve, for the message.
    seconds : float, optional
        CPU-time limit [s]; default :func:`seconds_limit`.
    evaluations : int
        Limit on evaluations of the steady equations.
    """
    if _ACTIVE.get() is not None:
        yield _ACTIVE.get()
        return
    active = Budget(seconds_limit() if seconds is None else seconds, evaluations, what)
    token = _ACTIVE.set(active)
    try:
        yield active
    finally:
        _ACTIVE.reset(token)


def check_time() -> None:
    """The time limit of the solve in progress (nothing outside a :func:`budget`)."""
    active = _ACTIVE.get()
    if active is not None:
        active.check_time()


def charge(count: int = 1) -> None:
    """Charge ``count`` evaluations to the solve in progress (nothing outside a :func:`budget`)."""
    active = _ACTIVE.get()
    if active is not None:
        active.charge(count)
