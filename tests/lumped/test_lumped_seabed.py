"""Seabed contact in the lumped model (kanat.physics.contact) against independent oracles:

* a grounded chain's equilibrium vs the closed-form elastic catenary with seabed
  (kanat.statics.catenary): grounded length, anchor and fairlead tension within 0.5 % at
  50 elements, and closer at 100;
* with friction, vs MoorPy's friction catenary (moorpy from PyPI, run side by side; skipped
  without it);
* a line lying on the seabed sinks by weight / (stiffness x diameter) and no more, and does not
  creep under zero load; friction holds a line on a slope below the friction angle and lets
  it slide above it at Coulomb's acceleration;
* the contact kernel against its NumPy twin; without ``environment.seabed`` a node below the
  seabed fails the run.
"""
import math

import numpy as np
import pytest

from kanat import api
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.mooring_outputs import anchor_forces
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem, nowhere
from kanat.model import Case
from kanat.physics import contact
from kanat.physics.seabed import seabed_of
from kanat.statics.catenary import elastic_catenary

G, RHO = 9.81, 1025.0
CHAIN = dict(diameter=0.1, mass=150.0, weight_in_water=1300.0, axial_stiffness=8e8, drag_normal=1.2,
             drag_tangential=0.5, added_mass=8.0)
DEPTH, SPAN, RISE, LENGTH = 100.0, 375.0, 90.0, 400.0


def grounded_case(segments, friction=0.0, **seabed):
    return Case.model_validate(dict(
        model="lumped", environment={"depth": DEPTH, "seabed": {"friction": friction, **seabed}},
        line_types={"chain": CHAIN},
        cables=[dict(name="leg", line_type="chain", length=LENGTH, segments=segments,
                     **{"from": f"anchor:[0, 0, {-DEPTH}]"}, to=f"anchor:[{SPAN}, 0, {RISE - DEPTH}]")],
        simulation={"duration": 1.0, "dt": 0.01}))


def settle(case):
    """The lumped equilibrium and the static forces at it: node forces (the anchors' as the
    model reports them, :func:`kanat.lumped.mooring_outputs.anchor_forces`) and normal forces."""
    net = build_network(case)
    x, _ = equilibrium(net, case)
    system = LumpedSystem(net, case, waves=False, steady_velocity=np.zeros(3))
    F = system.loads(0.0, x, np.zeros_like(x), 0.0)[0].copy()
    on_seabed = np.isclose(net.anchor_position[:, 2], -DEPTH)
    F[net.anchor_nodes] = anchor_forces(net, F, system.normal_force, on_seabed, case.environment.seabed.friction)
    return net, x, F, system.normal_force.copy()


def errors(segments):
    net, x, F, N = settle(grounded_case(segments))
    exact = elastic_catenary(SPAN, RISE, LENGTH, CHAIN["weight_in_water"], CHAIN["axial_stiffness"], seabed=True)
    anchor, fairlead = F[net.anchor_nodes]
    # what the fairlead does not hold up rests on the seabed: the touchdown's arclength from the anchor
    grounded = LENGTH + fairlead[2] / CHAIN["weight_in_water"]
    assert N.sum() / CHAIN["weight_in_water"] == pytest.approx(grounded, abs=2.0 * net.el_length[0])
    return (abs(grounded - exact.grounded_length) / exact.grounded_length,
            abs(math.hypot(anchor[0], anchor[1]) - exact.horizontal_tension) / exact.horizontal_tension,
            abs(np.linalg.norm(fairlead) - exact.tension_upper) / exact.tension_upper, exact)


def test_grounded_chain_matches_the_catenary_with_seabed_and_converges():
    coarse, fine = errors(12), errors(50)
    exact = fine[3]
    assert 100.0 < exact.grounded_length < 300.0                    # a real touchdown, not all or nothing
    for err_coarse, err in zip(coarse[:3], fine[:3]):
        assert err < 5e-3
        # converging with refinement, down to the soft seabed's own offset (4 mm of penetration)
        assert err < max(err_coarse / 4.0, 3e-4)
    assert max(coarse[:3]) > 1e-3                                    # the coarse grid is measurably off
    # no node deeper than the contact's static penetration w / (k_b d) (and a margin of 1 %)
    net, x, _, _ = settle(grounded_case(50))
    sink = CHAIN["weight_in_water"] / (3.0e6 * CHAIN["diameter"])
    assert -DEPTH - x[net.node_index, 2].min() < 1.01 * sink


def moorpy_catenary(moorpy, friction):
    fx_a, fz_a, fx_b, fz_b, info = moorpy.Catenary.catenary(SPAN, RISE, LENGTH, CHAIN["axial_stiffness"],
                                                            CHAIN["weight_in_water"], CB=friction, Tol=1e-12,
                                                            MaxIter=500)
    return math.hypot(fx_a, fz_a), math.hypot(fx_b, fz_b), info["LBot"]


@pytest.mark.parametrize("friction", [0.3, 1.0, 2.0])
def test_friction_catenary_matches_moorpy_side_by_side(friction, moorpy):
    """MoorPy 1.3.0, ``catenary(375, 90, 400, EA=8e8, W=1300, CB)``: the grounded part's tension
    falls by ``CB W`` per metre from the touchdown towards the anchor (to zero, with CB = 2)."""
    anchor_moorpy, fairlead_moorpy, grounded = moorpy_catenary(moorpy, friction)
    net, x, F, N = settle(grounded_case(100, friction=friction))
    anchor, fairlead = F[net.anchor_nodes]
    horizontal = math.hypot(anchor[0], anchor[1])
    fair = np.linalg.norm(fairlead)
    assert fair == pytest.approx(fairlead_moorpy, rel=5e-3)
    scale = fairlead_moorpy                                  # the anchor tension may be zero
    assert abs(horizontal - anchor_moorpy) < 5e-3 * scale
    if friction == 2.0:
        assert anchor_moorpy == 0.0                          # the case where friction takes it all
    else:
        assert anchor_moorpy > 0.1 * scale


def flat_line_case(friction=0.0, slope_deg=0.0, length=20.0, segments=10, duration=5.0, dt=0.002):
    """A line laid straight on the seabed (along +x, i.e. up the slope) between two free points, at
    its static penetration."""
    line = dict(CHAIN, drag_normal=0.0, drag_tangential=0.0, added_mass=0.0)
    angle = math.radians(slope_deg)
    sink = CHAIN["weight_in_water"] * math.cos(angle) / (3.0e6 * CHAIN["diameter"])   # static penetration
    start = np.array([0.0, 0.0, -DEPTH]) - sink * np.array([-math.sin(angle), 0.0, math.cos(angle)])
    end = start + length * np.array([math.cos(angle), 0.0, math.sin(angle)])
    return Case.model_validate(dict(
        model="lumped",
        environment={"depth": DEPTH, "seabed": {"friction": friction, "lateral_friction": friction,
                                                "slope_deg": slope_deg}},
        line_types={"chain": line}, points={"tail": {"position": start.tolist()}, "tip": {"position": end.tolist()}},
        cables=[dict(name="line", line_type="chain", length=length, segments=segments, **{"from": "tail"}, to="tip")],
        simulation={"duration": duration, "dt": dt, "output_dt": 0.25, "scheme": "rk4", "initial_state": "as_given"}))


def laid_positions(net, case):
    """The as-given start: the line straight along the slope at its static penetration."""
    tip = np.array(case.points["tip"].position)
    angle = math.radians(case.environment.seabed.slope_deg)
    along = np.array([math.cos(angle), 0.0, math.sin(angle)])
    return tip - (LENGTH_OF(case) - net.node_s)[:, None] * along


def LENGTH_OF(case):
    return case.cables[0].length


def test_a_line_on_the_seabed_sinks_by_its_weight_over_the_stiffness_and_does_not_creep():
    case = flat_line_case(friction=0.5, duration=10.0)
    ds = api.run(case).dataset
    assert ds.attrs["status"] == "ok"
    z = ds.position.values[:, :, 2]
    sink = CHAIN["weight_in_water"] / (3.0e6 * CHAIN["diameter"])
    interior = z[-1, 1:-1]                     # end nodes carry half an element each: the same pressure
    np.testing.assert_allclose(-DEPTH - interior, sink, rtol=1e-3)
    assert -DEPTH - z.min() < 1.001 * sink
    drift = np.abs(ds.position.values[-1, :, 0] - ds.position.values[0, :, 0]).max()
    assert drift < 1e-9                        # zero load, zero velocity: no creep at all
    assert ds.seabed_contact_length.values[-1, 0] == pytest.approx(20.0)


@pytest.mark.parametrize("slope_deg, friction", [(10.0, 0.5), (35.0, 0.5)], ids=["holds", "slides"])
def test_friction_holds_below_the_friction_angle_and_slides_above(slope_deg, friction):
    """Down-slope pull ``w sin(a)`` per length against ``mu w cos(a)``: held (creeping at most at
    the regularization's ``v_s atanh(tan(a) / mu)``) when ``tan(a) < mu``, else sliding at
    ``a = (w / m) (sin(a) - mu cos(a))`` (no drag or added mass on this line)."""
    duration = 3.0
    ds = api.run(flat_line_case(friction, slope_deg, duration=duration)).dataset
    assert ds.attrs["status"] == "ok"
    angle = math.radians(slope_deg)
    moved = ds.position.values[-1, :, 0] - ds.position.values[0, :, 0]
    ratio = math.tan(angle) / friction
    if ratio < 1.0:
        creep = contact.SLIP_VELOCITY * math.atanh(ratio) * duration
        assert np.all(np.abs(moved) < 1.05 * creep) and creep < 2e-3    # held: millimetres in 3 s
    else:
        w, m = CHAIN["weight_in_water"], CHAIN["mass"]
        accel = w / m * (math.sin(angle) - friction * math.cos(angle))
        t = ds.time.values
        along = (ds.position.values[:, 5, 0] - ds.position.values[0, 5, 0]) / math.cos(angle)
        fit = np.polyfit(t[t > 1.0], along[t > 1.0], 2)
        assert -2.0 * fit[0] == pytest.approx(accel, rel=0.02)           # sliding down-slope (-x)


def test_without_a_seabed_block_the_run_rests_on_the_default_seabed():
    """``depth`` alone: the default ``environment.seabed``, as the continuum model applies it."""
    runs = []
    for environment in ({"depth": 50.0}, {"depth": 50.0, "seabed": {}}):
        case = Case.model_validate(dict(
            model="lumped", environment=environment, line_types={"chain": CHAIN},
            cables=[dict(name="leg", line_type="chain", length=120.0, segments=12,
                         **{"from": "anchor:[0, 0, -50]"}, to="anchor:[60, 0, -10]")],
            simulation={"duration": 2.0, "dt": 0.01}))
        runs.append(api.run(case).dataset)
    assert [ds.attrs["status"] for ds in runs] == ["ok", "ok"]
    np.testing.assert_array_equal(runs[0].tension.values, runs[1].tension.values)
    assert runs[0].seabed_contact_length.values[-1, 0] > 0.0


def contact_twin(x, v, el_i, el_j, area, depth, slope_deg, kb, cb, mu_a, mu_l, vs):
    """NumPy twin of contact.contact_forces in dynamics mode (eqs. 1-4 written out afresh)."""
    angle = math.radians(slope_deg)
    nrm = np.array([-math.sin(angle), 0.0, math.cos(angle)])
    delta = (-depth + math.tan(angle) * x[:, 0] - x[:, 2]) * math.cos(angle)
    d = x[el_j] - x[el_i]
    unit = d / np.linalg.norm(d, axis=1)[:, None]
    tangent = np.zeros_like(x)
    np.add.at(tangent, el_i, unit)
    np.add.at(tangent, el_j, unit)
    F = np.zeros_like(x)
    for a in np.flatnonzero((delta > 0) & (area > 0)):
        N = max(0.0, kb * delta[a] - cb * min(delta[a] / contact.DAMPING_RAMP, 1.0) * v[a] @ nrm) * area[a]
        t = tangent[a] - (tangent[a] @ nrm) * nrm
        t /= np.linalg.norm(t)
        slip = v[a] - (v[a] @ nrm) * nrm
        va = slip @ t
        lateral = slip - va * t
        speed = np.linalg.norm(lateral)
        F[a] = N * nrm - mu_a * N * np.tanh(va / vs) * t - (mu_l * N * np.tanh(speed / vs) / speed * lateral
                                                            if speed > 0 else 0.0)
    return F


def test_contact_kernel_matches_its_numpy_twin():
    case = flat_line_case(friction=0.4, slope_deg=12.0)
    net = build_network(case)
    rng = np.random.default_rng(3)
    x = laid_positions(net, case)
    full = np.zeros((net.n_nodes, 3))
    full[net.node_index] = x + rng.normal(0.0, 0.01, x.shape)
    v = rng.normal(0.0, 0.01, full.shape)
    block = case.environment.seabed.model_copy(update={"lateral_friction": 0.2})   # lateral unlike axial
    bed = contact.bed_of(seabed_of(case.environment))
    law = contact.contact_law(block)
    F, N = np.zeros_like(full), np.zeros(net.n_nodes)
    empty = nowhere(net.n_nodes)                            # no equilibrium friction (kanat.lumped.entries.Laid)
    contact.contact_forces(full, v, net.el_i, net.el_j, net.node_contact_area, bed, law, empty,
                           np.zeros_like(full), F, N)
    want = contact_twin(full, v, net.el_i, net.el_j, net.node_contact_area, case.environment.depth, 12.0,
                        block.stiffness, block.damping, 0.4, 0.2, contact.SLIP_VELOCITY)
    assert np.count_nonzero(N) > 5
    np.testing.assert_allclose(F, want, rtol=1e-12, atol=1e-9 * np.abs(want).max())
