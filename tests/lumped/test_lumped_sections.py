"""Multi-section cables and inline attachments in the lumped model (kanat.lumped.grid):

* the grid puts a node at every section joint and attachment (moving the nearest node or
  splitting an element), elements take their section's line type;
* a vertical line of two sections with a clump weight between hangs with the tension of
  statics (the weight below each point: closed form) and each element stretched by T / EA of
  its own section;
* a two-section line between anchors matches the elastic catenary of each section joined
  (tension continuous, slope continuous), solved here by shooting on H and V independently;
* each section's strain limit is its own.
"""
import math

import numpy as np
import pytest
from scipy.optimize import fsolve

from kanat import api
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.grid import cable_grid
from kanat.lumped.network import build_network
from kanat.model import Case
from kanat.statics.catenary import catenary_profile

CHAIN = dict(diameter=0.1, mass=150.0, weight_in_water=1300.0, axial_stiffness=8e8, drag_normal=1.2)
ROPE = dict(diameter=0.15, mass=16.0, weight_in_water=30.0, axial_stiffness=1e8, drag_normal=1.2)


def case_of(cables, bodies=None, **extra):
    return Case.model_validate(dict(model="lumped", line_types={"chain": CHAIN, "rope": ROPE},
                                    bodies=bodies or {}, cables=cables,
                                    simulation={"duration": 1.0, "dt": 0.01}, **extra))


def test_the_grid_places_joints_and_attachments_on_nodes():
    case = case_of([dict(name="c", sections=[{"line_type": "chain", "length": 100, "segments": 10},
                                             {"line_type": "rope", "length": 50, "segments": 5}],
                         attachments=[{"body": "clump", "s": 33.0}, {"body": "float", "s": 100.0},
                                      {"body": "buoy", "s": 104.0}],
                         **{"from": "anchor:[0, 0, -100]"}, to="anchor:[140, 0, -20]")],
                     bodies={"clump": dict(mass=1000, net_buoyancy=-8000),
                             "float": dict(mass=100, net_buoyancy=5000),
                             "buoy": dict(mass=100, net_buoyancy=5000)})
    grid = cable_grid(case.cables[0])
    s = grid.s
    assert [s[k] for k in grid.attachment_node] == [33.0, 100.0, 104.0]
    assert 100.0 in s and len(s) == 16 + 1                      # the joint; one element split at 104
    assert np.all(np.diff(s) > 0) and np.min(np.diff(s)) >= 4.0 - 1e-12
    assert list(grid.section) == [0] * 10 + [1] * 6
    net = build_network(case)
    assert net.el_type == ["chain"] * 10 + ["rope"] * 6
    assert [net.node_s[net.node_index == net.names[b]][0] for b in ("clump", "float", "buoy")] == [33.0, 100.0, 104.0]


def test_a_vertical_two_section_line_with_a_clump_hangs_as_statics_says():
    """Hanging from an anchor above: the tension at height s (from the bottom end) is the weight of
    everything below it; each element is stretched by its own T / EA."""
    clump = 20000.0
    case = case_of([dict(name="c", sections=[{"line_type": "rope", "length": 40, "segments": 8},
                                             {"line_type": "chain", "length": 60, "segments": 12}],
                         attachments=[{"body": "clump", "s": 40.0}],
                         **{"from": "free"}, to="anchor:[0, 0, -10]")],
                   bodies={"clump": dict(mass=2500, net_buoyancy=-clump)})
    net = build_network(case)
    x, _ = equilibrium(net, case)
    length = np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1)
    T = np.array([(8e8 if t == "chain" else 1e8) for t in net.el_type]) * (length / net.el_length - 1.0)
    s_mid = 0.5 * (net.node_s[1:] + net.node_s[:-1])
    below = np.where(s_mid < 40.0, 30.0 * s_mid, 30.0 * 40.0 + clump + 1300.0 * (s_mid - 40.0))
    np.testing.assert_allclose(T, below, rtol=1e-6)
    assert np.allclose(x[net.node_index, :2], 0.0, atol=1e-6)     # straight down


def joined_catenary(span, rise, pieces):
    """Shooting on (H, V at the lower end) through pieces (length, w, EA) of elastic catenary."""
    def end(hv):
        h, v = hv
        x = z = 0.0
        for L, w, ea in pieces:
            p = catenary_profile(np.array([0.0, L]), h, v, w, ea)
            x, z, v = x + p[0][-1], z + p[1][-1], v + w * L
        return [x - span, z - rise]
    h, v = fsolve(end, [2e5, 1e5], xtol=1e-13)
    return h, v, v + sum(w * L for L, w, _ in pieces)


def test_a_two_section_line_matches_the_joined_elastic_catenaries():
    span, rise = 300.0, 80.0
    case = case_of([dict(name="c", sections=[{"line_type": "chain", "length": 200, "segments": 40},
                                             {"line_type": "rope", "length": 150, "segments": 30}],
                         **{"from": "anchor:[0, 0, -200]"}, to=f"anchor:[{span}, 0, {rise - 200}]")])
    net = build_network(case)
    x, _ = equilibrium(net, case)
    h, v_low, v_top = joined_catenary(span, rise, [(200.0, 1300.0, 8e8), (150.0, 30.0, 1e8)])
    d = x[net.el_j] - x[net.el_i]
    ea = np.array([(8e8 if t == "chain" else 1e8) for t in net.el_type])
    T = ea * (np.linalg.norm(d, axis=1) / net.el_length - 1.0)
    horizontal = T * np.abs(d[:, 0]) / np.linalg.norm(d, axis=1)
    np.testing.assert_allclose(horizontal, h, rtol=2e-3)
    assert T[-1] == pytest.approx(math.hypot(h, v_top - 0.5 * 30.0 * 5.0), rel=2e-3)   # the last element's middle
    joint = net.node_index[40]
    z_joint = catenary_profile(np.array([0.0, 200.0]), h, v_low, 1300.0, 8e8)[1][-1]
    assert x[joint, 2] + 200.0 == pytest.approx(z_joint, abs=0.05)


def test_each_section_has_its_own_strain_limit():
    weak = dict(ROPE, max_strain=0.001)
    case = Case.model_validate(dict(
        model="lumped", line_types={"chain": CHAIN, "weak": weak},
        cables=[dict(name="c", sections=[{"line_type": "chain", "length": 50, "segments": 5},
                                         {"line_type": "weak", "length": 50, "segments": 5}],
                     **{"from": "anchor:[0, 0, -50]"}, to="anchor:[99.9, 0, -50]")],
        simulation={"duration": 0.2, "dt": 0.01}))
    status = api.run(case).dataset.attrs["status"]
    assert "stretched" in status and "> 0.1 %" in status          # the weak section's limit, not 10 %
    assert any(f"element {k} " in status for k in range(5, 10))      # an element of the weak section
