"""The statics solvers that take a whole cable as submerged say how much of it was above the water.

Oracle: a cable hanging plumb from a tow point ``h`` above the water to a sinker, in still water, has
``h / (1 + T / EA)`` of unstretched length above the surface (its strain there, from its tension); in
the air that part weighs ``m g`` a metre instead of ``w``, so the top tension the solver gives is short
of the true one by ``(m g - w)`` times that length, the buoyancy the warning names.
"""
from __future__ import annotations

from pathlib import Path

import pytest

import kanat
from kanat.api import _statics

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
HEIGHT = 10.0     # m: the tow point above the water


def hanging(height: float):
    case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml")
    return case.replace({"vessel.tow_point": [0.0, 0.0, height], "vessel.track": [],
                         "cables": [{"name": "tow", "line_type": "towcable", "length": 100, "segments": 40,
                                     "from": "vessel", "to": "sled"}]})


@pytest.mark.filterwarnings("ignore:.*no track")
def test_a_cable_hung_from_above_the_water_is_said_to_keep_its_buoyancy_there():
    case = hanging(HEIGHT)
    table, text, result = _statics(case)
    assert table.attrs["status"] == "ok"
    warned = [w for w in table.attrs["warnings"].split("\n") if "above the water surface" in w]
    assert len(warned) == 1 and warned[0] in text
    line, env = case.line_types["towcable"], case.environment
    top = result.cables["tow"].tension[0]
    sinker = -case.bodies["sled"].net_buoyancy
    assert top == pytest.approx(sinker + line.weight_in_water * 100.0, rel=1e-9)   # all of it taken as wet
    length = HEIGHT / (1.0 + top / line.axial_stiffness)
    lift = line.mass * env.gravity - line.weight_in_water_value(env.water_density, env.gravity)
    said_length = float(warned[0].split(": ")[1].split(" m ")[0])
    said_lift = float(warned[0].split("keeps ")[1].split(" N ")[0])
    assert said_length == pytest.approx(length, rel=1e-3)            # the message's 4 digits
    assert said_lift == pytest.approx(lift * length, rel=1e-3)
    assert said_lift / top == pytest.approx(float(warned[0].split("(")[1].split(" %")[0]) / 100, rel=0.05)


@pytest.mark.filterwarnings("ignore:.*no track")
def test_a_cable_hung_from_the_surface_gets_no_such_warning():
    table, text, _ = _statics(hanging(0.0))
    assert table.attrs["status"] == "ok"
    assert "above the water surface" not in table.attrs.get("warnings", "") + text


@pytest.mark.filterwarnings("ignore:.*no track")
def test_a_buoyant_cable_above_the_water_is_no_steady_state():
    """The same plumb line made buoyant (weight in water -5 N/m): the solver holds its
    top ``h / (1 + T / EA)`` up by ``-w`` a metre, which in the air it would not have; the result fails
    and says that length and that buoyancy."""
    case = hanging(HEIGHT).replace({"line_types.towcable.weight_in_water": -5.0})
    line, env = case.line_types["towcable"], case.environment
    w = line.weight_in_water_value(env.water_density, env.gravity)
    assert w < 0.0
    table, text, result = _statics(case)
    status = table.attrs["status"]
    assert status.startswith("failed: buoyant_above_water: cable 'tow'")
    top = result.cables["tow"].tension[0]
    assert top == pytest.approx(-case.bodies["sled"].net_buoyancy + w * 100.0, rel=1e-9)    # all of it wet
    length = HEIGHT / (1.0 + top / line.axial_stiffness)
    said_length = float(status.split(": ")[3].split(" m ")[0])
    said_lift = float(status.split("held up there by ")[1].split(" N ")[0])
    assert said_length == pytest.approx(length, rel=1e-3)
    assert said_lift == pytest.approx(-w * length, rel=1e-3)


@pytest.mark.filterwarnings("ignore:.*no track")
def test_a_buoyant_cable_from_the_surface_is_a_steady_state():
    case = hanging(0.0).replace({"line_types.towcable.weight_in_water": -5.0})
    table, _, _ = _statics(case)
    assert table.attrs["status"] == "ok"
