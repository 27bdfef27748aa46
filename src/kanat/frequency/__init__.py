"""The frequency domain: the lumped system linearised about its equilibrium
(:mod:`kanat.frequency.linearize`) and its natural modes (:mod:`kanat.frequency.modes`)."""
from kanat.frequency.linearize import Linearization, linearize
from kanat.frequency.modes import modes

__all__ = ["Linearization", "linearize", "modes"]
