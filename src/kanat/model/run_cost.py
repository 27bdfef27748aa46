"""The cost of a dynamic run, estimated from the case alone: time steps x nodes.

A lumped run under an explicit scheme (``rk4``, ``abm4``) steps at the scheme's safe step,
which the model computes from the network when it is built (:mod:`kanat.lumped.stepping`).
:func:`run_cost` estimates that step here, from each section's line type, with the same
equations for one element between two interior nodes of the line's own mass::

    omega = 2 sqrt(EA / (m L0^2))        highest axial frequency of the element pair
    sigma = 4 c / (m L0^2)               its viscous decay rate (Kelvin-Voigt c = axial_damping)
    |lambda| = omega if sigma < 2 omega, else sigma/2 + sqrt(sigma^2/4 - omega^2)
    h_safe = SAFETY x limit / max |lambda|

and, on a seabed, each node's contact (stiffness ``k_b d / m``, damping ``c_b d / m``, and the
friction rate ``mu w / (v_s m)``; eq. 4 of :mod:`kanat.lumped.stepping`). Bodies make their
nodes heavier and the step a little longer: the estimate errs on the safe side; the model checks the exact count again before it allocates anything
(:func:`check_node_steps`). ``kanat validate`` warns above :data:`limits.WARN_NODE_STEPS`
and refuses above :func:`limits.max_node_steps`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..schemes import DYNAMIC_MODELS
from . import limits

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

EXPLICIT_SCHEMES = ("rk4", "abm4")
"""Lumped schemes whose step is bounded by stability (their limits: :data:`limits.EXPLICIT_STABILITY`)."""


@dataclass(frozen=True)
class RunCost:
    """Estimated work of a dynamic run.

    Attributes
    ----------
    step : float
        Time step [s]: ``dt``, the implicit default, or an explicit scheme's safe step.
    steps : float
        ``duration / step``.
    nodes : int
        Nodes of all cables.
    why : str
        Where the step comes from, for messages.
    """

    step: float
    steps: float
    nodes: int
    why: str

    @property
    def node_steps(self) -> float:
        return self.steps * self.nodes


def _spectral_radius(omega: float, sigma: float) -> float:
    """``|lambda|`` of ``x'' + sigma x' + omega^2 x = 0``."""
    if sigma < 2.0 * omega:
        return omega
    return 0.5 * sigma + math.sqrt(max(0.25 * sigma * sigma - omega * omega, 0.0))


def _largest_rate(case: Case, line, element: float) -> tuple[float, str]:
    """``max |lambda|`` of one element of ``line`` of length ``element`` [1/s], and of its nodes on
    the seabed (module docstring), and which of the two sets it."""
    mass = line.mass * element
    rate = _spectral_radius(2.0 * math.sqrt(line.axial_stiffness / element / mass),
                            4.0 * line.axial_damping / element / mass)
    seabed = case.environment.seabed
    if seabed is not None:
        from ..physics.seabed import SLIP_VELOCITY              # (NumPy: only for a case with a seabed)

        env = case.environment
        per_mass = line.diameter / line.mass       # contact area / node mass, per metre alike
        weight = line.weight_in_water_value(env.water_density, env.gravity)
        contact = (_spectral_radius(math.sqrt(seabed.stiffness * per_mass), seabed.damping * per_mass)
                   + max(seabed.friction, seabed.lateral_friction) * max(weight, 0.0)
                   / (SLIP_VELOCITY * line.mass))
        if contact > rate:
            return contact, "the seabed contact"
    return rate, "the axial stiffness and damping"


def explicit_safe_step(case: Case, scheme: str) -> tuple[float, str]:
    """Estimated safe step of explicit ``scheme`` [s], and the section that sets it."""
    worst, where = 0.0, ""
    for cable in case.cables:
        element = cable.length / cable.segments
        for section in cable.sections:
            rate, what = _largest_rate(case, case.line_types[section.line_type], element)
            if rate > worst:
                worst, where = rate, f"{what} of cable '{cable.name}', line type '{section.line_type}'"
    step = limits.EXPLICIT_SAFETY * limits.EXPLICIT_STABILITY[scheme] / max(worst, 1e-300)
    return step, where


def run_cost(case: Case) -> RunCost | None:
    """The estimated work of a dynamic run of ``case`` (None for a steady model)."""
    sim = case.simulation
    if sim is None or case.model not in DYNAMIC_MODELS:
        return None
    nodes = sum(c.segments + 1 for c in case.cables)
    step, why = sim.step_or_default, "dt" if sim.dt is not None else "the default step"
    scheme = getattr(sim, "scheme", None)
    if case.model == "lumped" and scheme in EXPLICIT_SCHEMES and case.cables:
        safe, where = explicit_safe_step(case, scheme)
        if safe < step:
            step, why = safe, f"{scheme}'s safe step, set by {where}"
    return RunCost(step, sim.duration / step, nodes, why)


def check_node_steps(steps: float, nodes: int, step: float, why: str) -> str | None:
    """Why a run of ``steps`` steps of ``step`` [s] on ``nodes`` nodes is refused, or None.

    The model calls it with its exact step once built, before allocating anything.
    """
    limit = limits.max_node_steps()
    span = f"{steps:.3g} time steps of {step:.3g} s ({why})"
    if steps > limits.MAX_TIME_STEPS:
        return (f"{span}, more than the limit of {limits.MAX_TIME_STEPS:.3g} steps; use a larger dt, "
                "an implicit scheme (generalized-alpha-lumped), fewer segments or a shorter duration")
    if steps * nodes > limit:
        return (f"{span} x {nodes:,} nodes = {steps * nodes:.3g} node-steps, more than the limit of "
                f"{limit:.3g} ({_duration(limit)} of computing or more); use a larger dt, an implicit "
                "scheme, fewer segments or a shorter duration, or raise the limit "
                f"({limits.NODE_STEPS_ENV}=1e11, or kanat run --max-node-steps 1e11)")
    return None


def _duration(node_steps: float) -> str:
    """Wall time of ``node_steps`` at the cheapest measured cost (0.1 us a node-step), in words."""
    seconds = node_steps * limits.FASTEST_NODE_STEP_S
    for unit, scale in (("days", 86400.0), ("hours", 3600.0), ("minutes", 60.0)):
        if seconds >= 2 * scale:
            return f"{seconds / scale:.0f} {unit}"
    return f"{seconds:.0f} s"
