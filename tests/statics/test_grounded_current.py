"""The current along a line lying on the seabed: statics carries its drag to the anchor.

examples/mooring_current.yaml: a 700 m chain with 527 m on a frictionless seabed in 150 m of water,
in a current of 0.2 m/s at the seabed flowing from the anchor towards the fairlead. The grounded part
lies straight along the flow, so the flow drags it along itself by ``0.5 rho pi d C_t u^2`` per metre
(3.5 N/m) and the anchor holds that much more than the touchdown point over the grounded length
(``kanat.statics.problem.Grounding``, eq. G1): 1.86 kN, 6 % of the anchor's tension. Statics used
to leave it out (30.92 kN at the anchor where both dynamic models, settled on their seabed, give
32.8 kN).

Oracles: the closed form of the grounded part's balance (planar shooting and collocation and the
3-D solvers, to the solvers' tolerance) and the lumped model's equilibrium on its default seabed,
an independent discretization with seabed springs (70 and 140 segments: 0.05 % and 0.11 %).
"""
import math
import warnings

import numpy as np
import pytest

import kanat
from helpers import EXAMPLES
from kanat import api
from kanat.errors import SolverError
from kanat.statics.setup import cable_problems
from kanat.statics.driver import solve_cable
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

CASE = EXAMPLES / "mooring_current.yaml"
PULL = 0.5 * 1025.0 * math.pi * 0.137 * 0.4 * 0.2**2          # N/m along the grounded chain, towards touchdown


@pytest.mark.parametrize("method", ["shooting", "collocation"])
@pytest.mark.parametrize("solver", ["planar", "spatial"])
def test_the_anchor_holds_the_drag_along_the_grounded_part(method, solver):
    case = kanat.load_case(CASE)
    s = np.linspace(0.0, 700.0, 7001)
    if solver == "planar":
        solution = solve_cable(cable_problems(case)["mooring"], method, s)
    else:
        solution = solve_cable3(cable_problem3(case), method, s)
    grounded = solution.grounded_length
    assert 520.0 < grounded < 535.0
    on_bed = s <= grounded
    assert solution.tension[0] - solution.tension[on_bed][-1] == pytest.approx(PULL * s[on_bed][-1], rel=1e-9)
    np.testing.assert_allclose(solution.tension[on_bed], solution.tension[0] - PULL * s[on_bed], rtol=1e-9)


def test_statics_agrees_with_the_lumped_model_settled_on_its_seabed():
    statics = kanat.run(kanat.load_case(CASE))
    anchor = float(statics.dataset["tension"].values[0])
    for segments, tolerance in ((70, 1e-3), (140, 2e-3)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = kanat.load_case(CASE).replace({"model": "lumped", "cables[0].segments": segments,
                                                  "simulation.duration": 2.0, "simulation.dt": 0.05})
            model = api.dynamic_model(case)
            lumped = model.outputs(model.initial())["tension"][0]
        assert anchor == pytest.approx(lumped, rel=tolerance)
        assert abs(anchor - lumped) < 0.05 * PULL * 527.0          # the drag it carries, to 5 %


def test_a_current_pushing_the_grounded_part_to_its_anchor_beyond_the_pull_is_refused():
    """Flow from the fairlead towards the anchor strong enough that the grounded part's tension would
    fall below zero before the anchor: statics, which lays it straight, says it cannot."""
    text = CASE.read_text().replace("[-150, 0.2, 0, 0]", "[-150, -2.0, 0, 0]").replace(
        "[0, 1.0, 0, 0]", "[0, -0.2, 0, 0]").replace("[-50, 0.7, 0, 0]", "[-50, -0.5, 0, 0]")
    with pytest.raises(SolverError, match="towards its anchor .* harder than the line pulls it"):
        kanat.run(kanat.load_case(text))
