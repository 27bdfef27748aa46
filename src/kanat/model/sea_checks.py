"""Checks of a case's sea and tow (part of :data:`kanat.model.checks.CHECKS`): waves against their
breaking limits, a towed cable's vessel track, and a 2-D run kept in the x-z plane."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ._base import fmt
from .environment import JonswapWaves, RegularWaves
from .findings import Findings
from .vessel import Heading, Turn

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

BREAKING_STEEPNESS = 1 / 7  # Miche's limit of H / wavelength for regular waves
BREAKING_DEPTH_RATIO = 0.78 # depth-limited breaking, H / depth (McCowan)
DEEP_WATER_KH = 20.0        # k h beyond which tanh(k h) = 1 to 1e-17: deep water


def wavelength(period: float, gravity: float, depth: float | None) -> float:
    """Linear-wave length [m] from ``omega^2 = g k tanh(k h)`` (deep water if no depth)."""
    omega = 2 * math.pi / period
    k = omega**2 / gravity
    if depth is not None and k * depth < DEEP_WATER_KH:
        k = k / math.sqrt(math.tanh(k * depth))  # good start in all depths
        for _ in range(50):
            f = gravity * k * math.tanh(k * depth) - omega**2
            df = gravity * (math.tanh(k * depth) + k * depth / math.cosh(k * depth) ** 2)
            step = f / df
            k -= step
            if abs(step) < 1e-12 * k:
                break
    return 2 * math.pi / k


def check_waves(case: Case, out: Findings) -> None:
    """Waves steeper than the breaking limit, or higher than the depth allows."""
    env = case.environment
    waves = env.waves
    if isinstance(waves, RegularWaves):
        height, period, keys = waves.height, waves.period, ("height", "period")
    elif isinstance(waves, JonswapWaves):
        height, period, keys = waves.hs, waves.tp, ("hs", "tp")
    elif waves is not None:        # components: the steepest one, as a regular wave of height 2a
        omega, amplitude = max(waves.components, key=lambda row: row[1] / wavelength(2 * math.pi / row[0],
                                                                                         env.gravity, env.depth))[:2]
        height, period, keys = 2 * amplitude, 2 * math.pi / omega, ("components", "period 2 pi/omega")
    else:
        return
    length = wavelength(period, env.gravity, env.depth)
    where = "deep water" if env.depth is None else f"depth {fmt(env.depth)} m"
    steepness = height / length
    if steepness > BREAKING_STEEPNESS:
        out.warning(("environment", "waves", keys[0]),
                    f"{keys[0]} {fmt(height)} m over the wavelength {length:.4g} m ({where}, "
                    f"{keys[1]} {fmt(period)} s) is a steepness of {steepness:.3g}, above the "
                    f"breaking limit 1/7 = {BREAKING_STEEPNESS:.3g}")
    if env.depth is not None and height > BREAKING_DEPTH_RATIO * env.depth:
        out.warning(("environment", "waves", keys[0]),
                    f"{keys[0]} {fmt(height)} m exceeds {BREAKING_DEPTH_RATIO} × depth = "
                    f"{BREAKING_DEPTH_RATIO * env.depth:.4g} m: such waves break in this depth")


def check_towing(case: Case, out: Findings) -> None:
    """A towed cable needs a vessel track (and a tow speed, for the statics)."""
    towed = [c.name for c in case.cables if any(e.kind == "vessel" and e.offset is None for e in c.ends)]
    if not towed:                  # none, or only fairleads of a moored vessel (they need no track)
        return
    if not case.vessel.track:
        moves = " but for its prescribed motion (vessel.motion)" if case.vessel.motion.is_used else ""
        out.warning(("vessel", "track"), f"cable '{towed[0]}' hangs from the vessel but the "
                    f"vessel has no track: the tow point stays at rest (speed 0 m/s){moves}")
    elif case.model == "statics" and case.vessel.initial_speed == 0:
        out.warning(("vessel", "track", 0), "the initial tow speed is 0 m/s: the statics will "
                    "hang the cable in still water; give the first segment a speed")


def _out_of_plane(case: Case) -> list[str]:
    """Features that leave the x-z plane."""
    found = [f"vessel.track[{i}] is a {s.kind}" for i, s in enumerate(case.vessel.track)
             if isinstance(s, (Turn, Heading))]
    found += [f"cables[{i}].{k} has y = {fmt(e.position[1])} m" for i, c in enumerate(case.cables)
              for k, e in (("from", c.from_), ("to", c.to))
              if e.kind == "anchor" and e.position[1] != 0]
    if case.vessel.tow_point[1] != 0:
        found.append(f"vessel.tow_point has y = {fmt(case.vessel.tow_point[1])} m")
    found += [f"bodies.{n}.force has y = {fmt(b.force[1])} N" for n, b in case.bodies.items()
              if b.force[1] != 0]
    current = case.environment.current
    rows = current.profile or ((0.0, *(current.velocity or (0.0, 0.0, 0.0))),)
    if any(r[2] != 0 for r in rows):
        found.append("the current has a y component")
    waves = case.environment.waves
    if waves is not None and abs(math.sin(math.radians(waves.heading_deg))) > 1e-9:
        found.append(f"the waves travel at heading {fmt(waves.heading_deg)} deg")
    return found


def check_dimensions(case: Case, out: Findings) -> None:
    """``dimensions: 2`` only when everything stays in the x-z plane."""
    if case.simulation is None or case.simulation.dimensions != 2:
        return
    found = _out_of_plane(case)
    if found:
        out.error(("simulation", "dimensions"), "dimensions: 2 models the x-z plane only, but "
                  + "; ".join(found) + "; use dimensions: 3 or auto")
