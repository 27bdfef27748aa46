"""The lumped equilibrium of examples/surface_mooring_waves.yaml (chain on the seabed, nylon riser to a
surface buoy) from its own first guess, no ``position`` hints: the still-water catenaries of network
statics (kanat.lumped.catenary_guess, the surface buoy on its linear waterplane), corrected once for
the current's drag, then the taut Newton phase.

Oracles: in the 0.5 m/s current, the 3-D statics solver (kanat.statics.solve3d: shooting on the
continuous cable with drag, seabed and the buoy's waterplane); in still water, the closed form of a
line lying slack on the seabed and hanging vertically from the buoy (H = 0): the suspended chain
``l`` solves ``60 + l + stretch(T) = depth - d`` with the top tension ``T = 60 w_n + l w_c`` held by
the draft ``d = (m g + T) / (rho g A_w)``. There the grounded chain is slack and the buoy's horizontal
place is not unique; the column's foot sits on a node, so depth, tension and grounded length are
within one chain element's weight (length) of the closed form.

Measured: current, 23 taut Newton iterations (before: no convergence, 5.6 s), buoy 8.4 mm from 3-D
statics; still water 60+30 / 120+60 segments: buoy depth off 1.4 / 0.11 mm, top tension -42.7 /
-3.8 N of 3092.9 N, grounded length +0.54 / +0.04 m of 80.46 m.
"""
import math

import numpy as np
import pytest

import kanat
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.mooring_outputs import anchors_on_seabed, contact_length
from kanat.lumped.network import build_network
from kanat.statics.driver import stations
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

from tests.helpers import EXAMPLES

TEXT = ((EXAMPLES / "surface_mooring_waves.yaml").read_text().replace("model: continuum", "model: lumped")
        .replace("scheme: generalized-alpha", "scheme: rk4"))
STILL = TEXT.replace("  current: {velocity: [0.5, 0, 0]}\n", "")
RHO_G_AW = 1025 * 9.81 * 3.0            # N/m, the buoy's waterplane
W_CHAIN, W_NYLON, EA_CHAIN, EA_NYLON = 77.0, 0.8, 8.0e7, 2.0e6


def refined(text, refine):
    return kanat.load_case(text.replace("segments: 60", f"segments: {60 * refine}")
                           .replace("segments: 30", f"segments: {30 * refine}"))


def top_tension(net, x):
    return (np.linalg.norm(x[net.el_j[-1]] - x[net.el_i[-1]]) / net.el_length[-1] - 1.0) * EA_NYLON


def hanging_column():
    """Suspended chain, top tension and keel depth of the still-water line (module docstring)."""
    def gap(hanging):
        top = 60 * W_NYLON + W_CHAIN * hanging
        stretch = 60 * (W_CHAIN * hanging + 30 * W_NYLON) / EA_NYLON + W_CHAIN * hanging**2 / (2 * EA_CHAIN)
        return 60 + hanging + stretch - (100 - (7848 + top) / RHO_G_AW)
    low, high = 0.0, 100.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if gap(mid) < 0 else (low, mid)
    top = 60 * W_NYLON + W_CHAIN * low
    return low, top, -(7848 + top) / RHO_G_AW


def test_the_surface_mooring_in_its_current_settles_from_its_own_first_guess():
    case = kanat.load_case(TEXT)
    net = build_network(case)
    x, info = equilibrium(net, case)
    exact = solve_cable3(cable_problem3(case), "auto", stations(case.cables[0]))
    assert info["first_guess"] == "catenary"
    assert 0 < info["taut_iterations"] == info["iterations"] <= 40          # 23 measured
    assert info["residual"] < 1e-4
    assert np.linalg.norm(x[net.body_node[0]] - exact.position[-1]) < 0.02   # m; 8.4 mm measured
    assert abs(top_tension(net, x) - exact.tension[-1]) < 2e-3 * exact.tension[-1]


def test_the_surface_mooring_in_still_water_matches_the_hanging_column():
    hanging, exact_top, exact_z = hanging_column()
    grounded_exact = 120.0 - hanging
    for refine in (1, 2):
        case = refined(STILL, refine)
        net = build_network(case)
        x, info = equilibrium(net, case)
        element = 2.0 / refine                                              # m of chain
        grounded = contact_length(net, info["normal_force"], anchors_on_seabed(net, case.environment))[0]
        assert info["first_guess"] == "catenary" and info["residual"] < 1e-4
        assert abs(x[net.body_node[0]][2] - exact_z) < W_CHAIN * element / RHO_G_AW
        assert abs(top_tension(net, x) - exact_top) < W_CHAIN * element
        assert abs(grounded - grounded_exact) < element / 2 + 0.05
    assert math.isclose(exact_top, 3092.93, rel_tol=1e-5)                   # the closed form itself


@pytest.mark.slow
def test_a_floating_end_is_guessed_near_the_surface_and_down_the_current():
    """Without statics (the network's own guess): the buoy on the surface, its keel half its
    height down, downstream of the anchor; and from there the equilibrium still converges."""
    case = kanat.load_case(TEXT)
    net = build_network(case)
    buoy = net.x_guess[net.body_node[0]]
    assert buoy[2] == -1.0 and buoy[0] > -150.0
    x, info = equilibrium(net, case, net.x_guess)
    assert info["residual"] < 1e-4
    assert abs(x[net.body_node[0]][0] - (-50.94)) < 0.05
