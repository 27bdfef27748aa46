"""The towed array with a free tail (examples/towed_array.yaml) that the continuum and lumped models'
free-tail tests share: its buoyant variant, still water, a heavy tow cable ahead of a buoyant tail,
the flows it is towed in, and the steady state of either model.
"""
import numpy as np

from helpers import EXAMPLES
from kanat import api, load_case

BUOYANT = {"line_types.array.weight_in_water": -2.0, "vessel.tow_point": [0, 0, -100.0]}
STILL = [{"straight": {"speed_kn": 0, "duration": 200}}]
ARRAY = {"diameter": 0.08, "mass": 5.2, "weight_in_water": -2.0, "axial_stiffness": 2.0e6, "added_mass": 5.15,
         "drag_normal": 1.2, "drag_tangential": 0.008}
TWO_SECTIONS = {
    "line_types": {"array": ARRAY, "wire": {"diameter": 0.02, "mass": 1.5, "weight_in_water": 12.0,
                                            "axial_stiffness": 3.0e7, "drag_normal": 1.2, "drag_tangential": 0.008}},
    "cables[0]": {"name": "array", "from": "vessel", "to": "free",
                  "sections": [{"line_type": "wire", "length": 150, "segments": 30},
                               {"line_type": "array", "length": 150, "segments": 30}]},
}
FLOWS = {
    "tow": {},
    "tow against a current": {"environment.current": {"velocity": [0.5, 0, 0]}},
    "current only": {"vessel.track": STILL, "environment.current": {"velocity": [1.0, 0, 0]}},
    "cross current 3-D": {"environment.current": {"velocity": [0, 1.0, 0]}, "simulation.dimensions": 3},
    "tow 3-D": {"simulation.dimensions": 3},
    "heavy tow cable, buoyant tail": TWO_SECTIONS,
}


def array_case(model="continuum", segments=60, **changes):
    """examples/towed_array.yaml in ``model`` on ``segments`` elements, with ``changes`` (Case.replace keys)."""
    case = load_case(EXAMPLES / "towed_array.yaml").replace({"model": model, "cables[0].segments": segments})
    return case.replace(changes)


def steady(case):
    """The initial steady state of a dynamic model: node positions (n, 3) and tensions (n,)."""
    model = api.dynamic_model(case)
    out = model.outputs(model.initial())
    return out["position"], out["tension"]


def with_segments(changes: dict, segments: int) -> dict:
    """``changes`` on a grid of ``segments`` elements (split evenly between the sections)."""
    if "cables[0]" not in changes:
        return {"cables[0].segments": segments, **changes}
    cable = dict(changes["cables[0]"])
    cable["sections"] = [{**section, "segments": segments // 2} for section in cable["sections"]]
    return {**changes, "cables[0]": cable}


def richardson(values: np.ndarray) -> np.ndarray:
    """The second-order extrapolation of ``values`` on a grid and on one twice as fine: ``f_2 + (f_2 - f_1) / 3``."""
    return values[1] + (values[1] - values[0]) / 3
