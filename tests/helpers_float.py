"""The tethered float that the lumped and continuum models' immersion tests share.

A 0.5 m spherical float (10 kg) clamped 20 m up a soft vertical tether from an anchor 20.25 m down,
a 0.5 m tail above it to a small body pulled up by 5 N: the tether's stretch puts the float at the
surface, where its immersed share balances the tension (``bodies.<name>.diameter``,
:mod:`kanat.physics.immersion` eq. (1)). The numbers keep the short names of the tests' closed
forms.
"""
import math

from kanat.model import Case

RHO, G = 1025.0, 9.81                                # water density [kg/m^3], gravity [m/s^2]
D, MF = 0.5, 10.0                                    # the float's diameter [m] and mass [kg]
FULL = RHO * G * math.pi / 6 * D**3                  # its buoyancy fully submerged [N]
W, EA, DL = 5.0, 2.0e4, 0.02                         # the tether's weight in water [N/m], EA [N], diameter [m]
DEPTH, SF, TOP = 20.25, 20.0, 0.5                    # the anchor's depth, the float's s, the tail above it [m]
ME, FE = 0.1, 5.0                                    # the pulling body's mass [kg] and upward force [N]
AREA_WEIGHT = RHO * G * math.pi * DL**2 / 4          # rho g A of the tether [N/m]


def tethered_float(model: str, duration: float = 0.05, dt: float = 0.05, waves: dict | None = None,
                   **simulation) -> Case:
    """The case for ``model`` (``"lumped"``, ``"continuum"``), run for ``duration`` at ``dt`` [s] in
    ``waves`` (a ``environment.waves`` block; None: still water), with further ``simulation`` keys."""
    environment = {"water_density": RHO, "gravity": G, "depth": 100.0}
    if waves:
        environment["waves"] = waves
    return Case.model_validate({
        "name": "tethered-float", "model": model, "environment": environment,
        "line_types": {"tether": {"diameter": DL, "mass": (W + AREA_WEIGHT) / G, "weight_in_water": W,
                                  "axial_stiffness": EA, "drag_normal": 1.2, "drag_tangential": 0.01}},
        "bodies": {"float": {"mass": MF, "net_buoyancy": FULL - MF * G, "drag_area": 0.1, "diameter": D},
                   "lift": {"mass": ME, "net_buoyancy": -ME * G, "force": [0, 0, FE], "drag_area": 0.01}},
        "cables": [{"name": "tether", "line_type": "tether", "length": SF + TOP, "segments": 41,
                    "from": f"anchor:[0, 0, {-DEPTH}]", "to": "lift", "attachments": [{"body": "float", "s": SF}]}],
        "simulation": {"duration": duration, "dt": dt, "output_dt": min(1.0, duration), **simulation}})
