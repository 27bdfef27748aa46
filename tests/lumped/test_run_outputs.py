"""The run loop's output checks and the lumped model's mooring outputs, worked out once a run:

* the non-finite check (:func:`kanat.dynamics._non_finite`): finite values
  whose sum overflows still pass, a NaN or an infinity anywhere is found and named with its node;
* :class:`kanat.lumped.mooring_outputs.MooringOutputs` of a run gives at every output the numbers the
  module's functions give from scratch, and the anchor force of a chain resting on the seabed is the end
  element's pull (written out from the tensions) relieved of the half element's weight.
"""
import math

import numpy as np
import pytest

from kanat.dynamics import Point, Recorder, _non_finite, run
from kanat.io.schema import Layout
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.mooring_outputs import anchor_forces, anchors_on_seabed, contact_length, line_forces
from kanat.model import Case
from kanat.step_control import Steps

LAYOUT = Layout({"s": (("node",), np.array([0.0, 1.0, 2.0])), "cable": (("node",), np.array(["a", "a", "b"]))},
                {}, ("position", "tension"), {})


def point(**values):
    return Point(3, 1.5, values, None, Steps(), None)


def test_finite_values_whose_sum_overflows_pass():
    big = np.full((3, 3), 1e308)
    with np.errstate(over="ignore"):
        assert math.isinf(float(np.sum(big)))
    assert _non_finite(LAYOUT, point(position=big, tension=np.ones(3))) is None


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_non_finite_value_is_named_with_its_node(bad):
    tension = np.array([1.0, 2.0, 3.0])
    tension[2] = bad
    message = _non_finite(LAYOUT, point(position=np.zeros((3, 3)), tension=tension))
    assert "t = 1.5 s in tension at node 2 (cable 'b', s = 2 m)" in message


def test_opposite_infinities_do_not_cancel():
    assert "in position" in _non_finite(LAYOUT, point(position=np.array([[np.inf, -np.inf, 0.0]] * 3),
                                                      tension=np.ones(3)))


def chain_case():
    line = dict(diameter=0.1, mass=20.0, weight_in_water=170.0, axial_stiffness=5e8, axial_damping=1e6,
                drag_normal=2.4, drag_tangential=0.4, added_mass=8.0)
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 50.0, "seabed": {"stiffness": 1e5, "damping": 1e4, "friction": 0.5}},
        line_types={"chain": line}, vessel={"motion": [{"dof": "surge", "amplitude": 2.0, "period": 10.0,
                                                         "phase_deg": -90.0}]},
        cables=[dict(name="leg", line_type="chain", length=120.0, segments=24,
                     **{"from": "anchor:[-100, 0, -50]"}, to={"vessel": [0.0, 0.0, 0.0]})],
        simulation={"duration": 2.0, "output_dt": 0.5, "dt": 0.05}))


@pytest.mark.slow
def test_mooring_outputs_of_a_run_are_those_worked_out_from_scratch():
    case = chain_case()
    recorder, models = Recorder(), []

    def build():
        models.append(LumpedModel(case))
        return models[-1]

    assert run(build, [recorder]).ok
    model = models[0]
    net, system = model.net, model.system
    ds = recorder.dataset()
    # the last output from scratch: positions and velocities of the result, forces recomputed
    x = net.x_guess.copy()
    x[net.node_index] = ds.position.values[-1]
    v = np.zeros_like(x)
    v[net.node_index] = ds.velocity.values[-1]
    heading = system.prescribed(model.duration, x, v)
    F = system.loads(model.duration, x, v, heading)[0].copy()
    T = ds.segment_tension.values[-1]
    on_seabed = anchors_on_seabed(net, case.environment)
    np.testing.assert_array_equal(ds.seabed_contact_length.values[-1],
                                  contact_length(net, system.normal_force, on_seabed))
    np.testing.assert_array_equal(ds.anchor_force.values[-1],
                                  anchor_forces(net, F, system.normal_force, on_seabed, 0.5))
    a = system.solve_mass(x, F, system.loads(model.duration, x, v, heading)[1], np.zeros_like(x))
    np.testing.assert_array_equal(ds.body_force.values[-1].reshape(-1, 3), line_forces(system, model.duration, x, v,
                                                                                       a, heading, T))
    # the anchor's pull written out: the first element's tension along it, its half weight off the seabed
    assert on_seabed[0] and system.normal_force[net.el_j[0]] > 0.0
    d = x[net.el_j[0]] - x[net.el_i[0]]
    pull = T[0] * d / np.linalg.norm(d)
    half = 0.5 * net.el_weight[0] * net.el_length[0]
    force = ds.anchor_force.values[-1][0]
    assert force[0] == pytest.approx(max(pull[0] - 0.5 * half, 0.0), rel=0.02)
    assert force[2] == pytest.approx(pull[2], abs=0.02 * half)
