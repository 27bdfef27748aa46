"""The direction of a free tail at rest in a uniform flow (:func:`kanat.physics.drag.trailing_direction`),
shared by the continuum and lumped models' first guesses, against the balance it solves: across the line,
the normal drag ``R sin^2 phi`` carries the weight's normal part ``|w| cos phi`` (``R = C |u|^2``)."""
import numpy as np
import pytest

from kanat.physics.drag import trailing_direction

C = 0.5 * 1025.0 * 0.08 * 1.2                    # 0.5 rho d C_n of examples/towed_array.yaml's array


@pytest.mark.parametrize("weight", [2.0, -2.0, 12.0, -50.0])
@pytest.mark.parametrize("flow", [(4.1, 0.0), (-0.5, 0.0), (0.0, 1.0), (0.3, -0.4)])
def test_a_tail_trails_where_normal_drag_carries_its_weight(weight, flow):
    t = trailing_direction(weight, C, flow)
    u = np.array([*flow, 0.0])
    assert np.linalg.norm(t) == pytest.approx(1.0, rel=1e-14)
    normal_flow = u - (u @ t) * t                                          # the flow across the line
    drag = C * np.linalg.norm(normal_flow) * normal_flow
    weight_force = np.array([0.0, 0.0, -weight])
    np.testing.assert_allclose(drag + weight_force - (weight_force @ t) * t, 0.0, atol=1e-12 * abs(weight))
    assert np.sign(t[2]) == -np.sign(weight)                              # down when heavy, up when buoyant
    assert t[:2] @ np.asarray(flow) > 0.0                                 # downstream


@pytest.mark.parametrize("weight, up", [(2.0, -1.0), (-2.0, 1.0)])
def test_in_still_water_a_tail_hangs_or_stands_plumb(weight, up):
    np.testing.assert_array_equal(trailing_direction(weight, C, (0.0, 0.0)), [0.0, 0.0, up])
