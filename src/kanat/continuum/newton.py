"""Newton's limits and failure, shared by the continuum model's time step and steady state.

:mod:`kanat.continuum.stepper` (a time step) and :mod:`kanat.continuum.steady` (the steady state
on the seabed) both iterate Newton's method with these limits and raise :class:`NewtonFailure`.
"""
from __future__ import annotations

from kanat.errors import SolverError
from kanat.step_control import StepRefused

MAX_ITERATIONS = 20
TOLERANCE = 1e-10        # on increments scaled by (tension scale, speed scale, speed scale, 1 rad)


class NewtonFailure(SolverError, StepRefused):
    """Newton did not converge; ``node`` is where the largest residual sits (a refused step of
    :mod:`kanat.step_control`: the run cuts it)."""

    def __init__(self, message: str, node: int):
        super().__init__(message)
        self.node = node
