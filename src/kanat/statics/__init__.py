"""Statics (SPEC §3): steady cables by shooting, collocation and the closed-form catenary;
networks of catenary lines in 3-D; the seed 001 sphere on two cables."""
from kanat.statics.driver import METHODS, StaticsResult, solve_cable, solve_statics
from kanat.statics.network_setup import NeedsDrag
from kanat.statics.problem import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties
from kanat.statics.solution import CableSolution

__all__ = ["METHODS", "NeedsDrag", "BodyEnd", "CableBVP", "CableSolution", "FixedEnd", "FlowProfile", "LineProperties",
           "StaticsResult", "solve_cable", "solve_statics"]
