"""Statics (theory/statics.md): steady cables by shooting, collocation and the closed-form catenary;
networks of catenary lines in 3-D; the Naumov & Agievich sphere on two cables.

The solvers (:mod:`kanat.statics.driver`) are imported on first use of their names: they
bring SciPy's ``integrate`` and ``optimize``, which a dynamic run starting from
:mod:`kanat.statics.march` does not need (0.2 s of CPU per process).
"""
from kanat.statics.problem import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties
from kanat.statics.solution import CableSolution

__all__ = ["METHODS", "NeedsDrag", "NeedsLumped", "BodyEnd", "CableBVP", "CableSolution", "FixedEnd", "FlowProfile", "LineProperties",
           "StaticsResult", "solve_cable", "solve_statics"]


def __getattr__(name):
    if name in ("METHODS", "StaticsResult", "solve_cable", "solve_statics"):
        from kanat.statics import driver

        return getattr(driver, name)
    if name in ("NeedsDrag", "NeedsLumped"):
        from kanat.statics import network_setup

        return getattr(network_setup, name)
    raise AttributeError(f"module 'kanat.statics' has no attribute {name!r}")
