"""Step control shared by the dynamic models: a step that fails is retaken in halves.

One controller, :class:`Halving`, takes every implicit step of the continuum and the lumped
model (as diffrax's step-size controllers are objects apart from its solvers). Its contract:

1. a scheme's step is an *attempt* ``attempt(state, h) -> (state, iterations)`` that returns a new
   state (the one given is not touched) or raises :class:`StepRefused` (Newton did not converge);
2. a refused step of ``h`` is retaken as two steps of ``h / 2``, each retaken in halves again where
   it is refused, down to ``h / 2**levels``;
3. where even that fails, :meth:`Halving.take` raises :class:`StepsExhausted` holding the last
   refusal (the caller's message says where and what to try), or the caller's fallback takes the
   whole step (:meth:`Halving.retake`: the lumped model's explicit ``rk4``), said in the run's notes
   by :meth:`Halving.fallback_note`;
4. the work is counted once, as :class:`Steps`: one step per step asked for, the Newton
   iterations of every attempt whose state is kept (a refused one's too, where its refusal says
   them), and a cut for every refused attempt.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Steps:
    """Work done by a model's ``advance``: steps, Newton iterations (implicit schemes), step cuts."""

    steps: int = 0
    iterations: int = 0
    cuts: int = 0

    def __add__(self, other: Steps) -> Steps:
        return Steps(self.steps + other.steps, self.iterations + other.iterations, self.cuts + other.cuts)


class StepRefused(Exception):
    """An attempt at one step that did not converge.

    Parameters
    ----------
    message : str
        What failed (``"Newton did not converge in 12 iterations"``).
    iterations : int
        The Newton iterations the attempt spent, where they count in the run's work.
    """

    iterations: int = 0

    def __init__(self, message: str = "", iterations: int = 0):
        super().__init__(message)
        self.iterations = iterations


class StepsExhausted(Exception):
    """A step refused even as ``2**levels`` sub-steps.

    Attributes
    ----------
    refusal : StepRefused
        The last refused attempt (at the shortest sub-step).
    state : object
        The state that attempt started from.
    h : float
        That attempt's step [s].
    cuts : int
        The refused attempts of the whole step, the last included.
    """

    def __init__(self, refusal: StepRefused, state, h: float, cuts: int):
        super().__init__(str(refusal))
        self.refusal, self.state, self.h, self.cuts = refusal, state, h, cuts


Attempt = Callable[[object, float], tuple[object, int]]


@dataclass(frozen=True)
class Halving:
    """Step control by halving (module docstring).

    Attributes
    ----------
    levels : int
        Deepest halving: a step is retaken as at most ``2**levels`` sub-steps.
    """

    levels: int

    def take(self, attempt: Attempt, state, h: float) -> tuple[object, Steps]:
        """One step of ``h`` from ``state``: ``(state, Steps(1, iterations, cuts))``.

        Raises
        ------
        StepsExhausted
            When even the sub-steps of ``h / 2**levels`` are refused.
        """
        new, work = self._take(attempt, state, h, 0)
        return new, Steps(1, work.iterations, work.cuts)

    def retake(self, attempt: Attempt, state, h: float, fallback: Callable | None = None) -> tuple[object, Steps]:
        """A step of ``h`` already refused once (the refusal counted by the caller), taken as two halves.

        Where even the halves' halves fail, ``fallback(state, h) -> state`` takes the whole step: the
        work then counts the refused attempts as cuts, and no iterations of the sub-steps, whose
        states are dropped. Without a fallback, :class:`StepsExhausted` is raised.
        """
        try:
            new, work = self._halves(attempt, state, h, 0)
        except StepsExhausted as exhausted:
            if fallback is None:
                raise
            return fallback(state, h), Steps(0, 0, exhausted.cuts)
        return new, Steps(0, work.iterations, work.cuts)

    def fallback_note(self, count: int, fallback: str) -> str:
        """The run's note on the steps a fallback took."""
        return (f"{count} {fallback} steps at the explicit safe step where the implicit Newton iteration "
                f"failed even on the step cut to 1/{2 ** self.levels}")

    def _take(self, attempt: Attempt, state, h: float, level: int) -> tuple[object, Steps]:
        try:
            new, iterations = attempt(state, h)
            return new, Steps(0, iterations, 0)
        except StepRefused as refusal:
            if level >= self.levels:
                raise StepsExhausted(refusal, state, h, 1) from None
            spent = refusal.iterations
        try:
            new, work = self._halves(attempt, state, h, level)
        except StepsExhausted as exhausted:
            exhausted.cuts += 1
            raise
        return new, Steps(0, spent + work.iterations, 1 + work.cuts)

    def _halves(self, attempt: Attempt, state, h: float, level: int) -> tuple[object, Steps]:
        """The step of ``h`` (refused at ``level``) as two steps of ``h / 2`` at ``level + 1``."""
        half, first = self._take(attempt, state, 0.5 * h, level + 1)
        try:
            new, second = self._take(attempt, half, 0.5 * h, level + 1)
        except StepsExhausted as exhausted:
            exhausted.cuts += first.cuts
            raise
        return new, first + second
