"""Every continuum time scheme, registered by import (style rule 2).

The generalized-α family is in :mod:`kanat.continuum.family`, Kaliukh & Vusatiuk's factorized and
wave-factorized schemes in :mod:`kanat.continuum.factorized.schemes`; both step the planar
or spatial model of :mod:`kanat.continuum.models` through ``scheme.step(model, state, dt)``.
"""
from kanat.continuum.factorized.schemes import Factorized, Factorized4, WaveFactorized, WaveFactorized2, WaveFactorized3
from kanat.continuum.family import (BackwardEuler, Box, ContinuumScheme, FamilyScheme, GeneralizedAlpha,
                                    GeneralizedTrapezoidal)
from kanat.schemes import registry

SCHEMES = registry(GeneralizedAlpha, Box, BackwardEuler, GeneralizedTrapezoidal,
                   Factorized, Factorized4, WaveFactorized, WaveFactorized2, WaveFactorized3)
"""Every continuum scheme by name."""

__all__ = ["SCHEMES", "BackwardEuler", "Box", "ContinuumScheme", "Factorized", "Factorized4", "FamilyScheme",
           "GeneralizedAlpha", "GeneralizedTrapezoidal", "WaveFactorized", "WaveFactorized2", "WaveFactorized3"]
