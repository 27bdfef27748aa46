"""The lumped equilibrium's taut Newton phase (kanat.lumped.taut_newton) on the surface mooring of
examples/surface_mooring_waves.yaml: chain on the seabed (EA = 8e7 N, strain 5e-5 at its 4 kN)
and a nylon riser to a surface buoy, in its 0.5 m/s current.

Oracle: the 3-D statics solver (kanat.statics.solve3d, a shooting method on the continuous cable
with drag, seabed and the buoy's waterplane) on the same case. Started from the statics shape
sampled at its nodes, the lumped equilibrium used to fail (400 iterations, 107 N left); the taut
phase now meets the residual tolerance in a few Newton iterations, and the buoy's place and the
top tension approach statics as the elements shrink.

Measured (60 + 30 segments, then doubled): 7 and 5 iterations; buoy x off by 8.4 mm and 0.34 mm,
z by 2.7e-5 m and 1.7e-6 m; top element tension 4007.7 and 4009.0 N against 4009.3 N.
"""
import numpy as np
import pytest

import kanat
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import build_network
from kanat.statics.driver import stations
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

from tests.helpers import EXAMPLES

TEXT = ((EXAMPLES / "surface_mooring_waves.yaml").read_text().replace("model: continuum", "model: lumped")
        .replace("scheme: generalized-alpha", "scheme: rk4"))


def settle(refine):
    case = kanat.load_case(TEXT.replace("segments: 60", f"segments: {60 * refine}")
                           .replace("segments: 30", f"segments: {30 * refine}"))
    exact = solve_cable3(cable_problem3(case), "auto", stations(case.cables[0]))
    net = build_network(case)
    start = net.x_guess.copy()
    start[net.node_index] = exact.position
    x, info = equilibrium(net, case, start)
    top = np.linalg.norm(x[net.el_j[-1]] - x[net.el_i[-1]]) / net.el_length[-1] - 1.0
    return x[net.body_node[0]] - exact.position[-1], top * 2.0e6, exact.tension[-1], info


def test_the_surface_mooring_settles_by_taut_newton_onto_3d_statics():
    errors = []
    for refine in (1, 2):
        buoy, top, exact_top, info = settle(refine)
        assert 0 < info["taut_iterations"] == info["iterations"] <= 10
        assert info["residual"] < 1e-4                                 # N
        assert abs(top - exact_top) < 2e-3 / refine * exact_top         # 0.04 %, 0.009 % measured
        errors.append(np.linalg.norm(buoy))
    assert errors[0] < 0.02                                            # m
    assert errors[1] < errors[0] / 4
