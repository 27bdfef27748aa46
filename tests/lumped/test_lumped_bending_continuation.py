"""The lumped equilibrium of a line with bending stiffness by continuation in EI
(kanat.lumped.equilibrium._bending_continuation): the flexible line's equilibrium, then EI raised in
stages. Checked on the taut beam of test_lumped_clamped against the tensioned-beam equation (an
analytic oracle), against the direct solve, and by its own residual under the full EI."""
import numpy as np
import pytest

from kanat.lumped import equilibrium as eq
from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem

from test_lumped_clamped import SPAN, beam_string, tensioned_beam


@pytest.fixture(scope="module", params=[True, False], ids=["clamped-clamped", "clamped-pinned"])
def continued(request, tmp_path_factory):
    case = beam_string(tmp_path_factory.mktemp("beam"), 40, request.param)
    net = build_network(case)
    x, info = eq._bending_continuation(net, case, None, True, 0.0)
    return request.param, case, net, x, info


def test_the_continuation_ends_at_a_true_equilibrium_of_the_full_bending_stiffness(continued):
    _, case, net, x, info = continued
    system = LumpedSystem(net, case, waves=False, steady_velocity=np.zeros(3))
    forces = eq._SteadyForces(system)(0.0, x[system.free_index])[0]
    assert info["fallback"] == "bending continuation" and info["bending_stages"] == len(eq.BENDING_STAGES)
    assert np.max(np.abs(forces)) <= eq._tolerance(net, x[system.free_index])
    assert np.max(np.abs(forces)) == pytest.approx(info["residual"], rel=1e-6, abs=1e-12)


def test_the_continuation_finds_the_direct_solve_s_equilibrium(continued):
    _, case, net, x, _ = continued
    direct, _ = eq.equilibrium(net, case)
    assert np.max(np.abs(x - direct)) < 1e-7                         # m, of a sag of 7.5-9.2 cm


def test_the_continued_beam_bends_as_the_beam_equation_says(continued):
    """0.50 % (clamped-clamped) and 0.37 % (clamped-pinned) of the sag at 40 segments, as the direct
    solve (test_lumped_clamped)."""
    clamped_b, _, net, x, info = continued
    pull = -info["loads"][net.anchors[1], 0]
    line = x[net.node_index]
    exact = tensioned_beam(line[:, 0], 1.0, pull, 1e6, SPAN, clamped_b)
    error = np.abs(line[:, 2] + 50.0 - exact).max() / np.abs(exact).max()
    assert error == pytest.approx(0.0050 if clamped_b else 0.0037, abs=5e-4)
