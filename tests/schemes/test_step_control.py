"""The step controller both dynamic models share (kanat.step_control): halving, its counts, its end.

Oracles: a step retaken in halves is the same arithmetic as the shorter steps taken directly
(explicit Euler on y' = -y, bit for bit), and the counts follow from the halving tree: a step
refused down to ``h / 2**k`` costs ``2**k - 1`` cuts. The continuum model's run with a scheme that
refuses every step longer than ``dt / 4`` is, bit for bit, the plain run at ``dt / 4``.
"""
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest

from kanat.step_control import Halving, StepRefused, Steps, StepsExhausted

from helpers import EXAMPLES, quiet



def euler(longest: float, iterations: int = 2):
    """An attempt of explicit Euler on y' = -y that refuses steps longer than ``longest``."""
    def attempt(state, h):
        t, y = state
        if h > longest * (1 + 1e-12):
            raise StepRefused("too long", iterations=7)
        return (t + h, y - h * y), iterations
    return attempt


@pytest.mark.parametrize("depth", [0, 1, 2, 3])
def test_a_step_refused_down_to_a_depth_is_the_shorter_steps_bit_for_bit(depth):
    h = 0.1
    state, work = Halving(levels=4).take(euler(h / 2**depth), (0.0, 1.0), h)
    t, y = 0.0, 1.0
    for _ in range(2**depth):
        t, y = t + h / 2**depth, y - h / 2**depth * y
    assert state == (t, y)
    refused = 2**depth - 1                                 # every node of the halving tree above the leaves
    assert work == Steps(1, 2 * 2**depth + 7 * refused, refused)


def test_a_step_refused_at_every_depth_is_exhausted_at_the_shortest():
    levels, h = 3, 0.1
    with pytest.raises(StepsExhausted) as caught:
        Halving(levels).take(euler(0.0), (0.0, 1.0), h)
    assert caught.value.h == pytest.approx(h / 2**levels)
    assert caught.value.state == (0.0, 1.0)
    assert caught.value.cuts == levels + 1                 # the first branch, refused at each depth
    assert str(caught.value) == "too long"


def test_a_retaken_step_falls_back_with_its_cuts_and_no_iterations():
    """A step already refused once: halves refused too (levels 2: h/2 and h/4 refused), so the
    fallback takes the whole step; its work is the three refusals and no iterations."""
    taken = []

    def fallback(state, h):
        taken.append(h)
        return (state[0] + h, 0.0)

    state, work = Halving(levels=2).retake(euler(0.0), (0.0, 1.0), 0.1, fallback)
    assert taken == [0.1] and state == (0.1, 0.0)
    assert work == Steps(0, 0, 2)
    note = Halving(levels=3).fallback_note(5, "rk4")
    assert note == ("5 rk4 steps at the explicit safe step where the implicit Newton iteration failed even on "
                    "the step cut to 1/8")


def test_a_partly_refused_halving_counts_every_refusal():
    """The first half goes at h/2, the second needs quarters (a refusal that depends on the state)."""
    def attempt(state, h):
        t, y = state
        if h > 0.05 + 1e-12 or (t >= 0.05 - 1e-12 and h > 0.025 + 1e-12):
            raise StepRefused("stiff here")
        return (t + h, y - h * y), 1

    state, work = Halving(levels=3).take(attempt, (0.0, 1.0), 0.1)
    assert state[0] == pytest.approx(0.1)
    assert work == Steps(1, 3, 2)                         # h and the second h/2 refused; h/2, h/4, h/4 taken


@pytest.mark.slow
def test_the_continuum_model_cuts_its_steps_through_the_controller():
    """A generalized-α that refuses steps longer than dt/4 (a Newton failure) runs the speed step as
    the plain scheme does at dt/4, bit for bit, with three cuts a step."""
    from kanat import api
    from kanat.continuum.family import GeneralizedAlpha
    from kanat.continuum.newton import NewtonFailure
    from kanat.io import load_case

    @dataclass(frozen=True)
    class Refusing(GeneralizedAlpha):
        name: ClassVar[str] = "refusing-generalized-alpha"
        longest: float = 0.25

        def step(self, model, state, dt):
            if dt > self.longest * (1 + 1e-12):
                raise NewtonFailure("refused", 0)
            return super().step(model, state, dt)

    case = load_case(EXAMPLES / "speed_step_2d.yaml").replace({"simulation.duration": 4.0})
    with quiet():
        cut = api.run(case, scheme=Refusing()).dataset
        plain = api.run(case.replace({"simulation.dt": 0.25}), scheme="generalized-alpha").dataset
    assert cut.attrs["status"] == "ok" and cut.attrs["steps"] == 4 and cut.attrs["step_cuts"] == 12
    for name in ("position", "tension", "velocity"):
        np.testing.assert_array_equal(cut[name].values, plain[name].values)
