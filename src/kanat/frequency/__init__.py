"""The frequency domain: the lumped system linearised about its equilibrium
(:mod:`kanat.frequency.linearize`), its natural modes (:mod:`kanat.frequency.modes`) and its
response to the sea and the vessel's motion (:mod:`kanat.frequency.solve`)."""
from kanat.frequency.linearize import Linearization, linearize
from kanat.frequency.modes import modes
from kanat.frequency.solve import solve_frequency

__all__ = ["Linearization", "linearize", "modes", "solve_frequency"]
