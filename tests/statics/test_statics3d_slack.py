"""A slack grounded line in still water: refused at once, with why and what to do.

The surface mooring of ``surface_mooring_waves.yaml`` without its current and waves: the chain's
grounded part is slack, so the single-cable steady state is not unique and the 3-D solvers used to
search for one for minutes (45 s of CPU) before failing. The refusal comes before any solver runs:
the steady equations' right-hand sides are never evaluated.
"""
import pytest

from helpers import EXAMPLES
from kanat import api
from kanat.errors import SolverError
from kanat.statics import collocation3d, shooting3d
from kanat.statics.setup3d import cable_problem3
from kanat.statics.solve3d import solve_cable3

WHY = "no unique single-cable steady state"
WHAT = "model: lumped"


def still_mooring():
    case = api.load_case(EXAMPLES / "surface_mooring_waves.yaml")
    return case.replace({"environment.current": {"velocity": [0.0, 0.0, 0.0]}, "environment.waves": None})


@pytest.fixture
def evaluations(monkeypatch):
    """Counts of the steady right-hand sides the shooting and collocation solvers evaluate."""
    count = {"rhs": 0}

    def counted(function):
        def wrapper(*args, **kwargs):
            count["rhs"] += 1
            return function(*args, **kwargs)
        return wrapper
    monkeypatch.setattr(shooting3d, "rhs_point", counted(shooting3d.rhs_point))
    monkeypatch.setattr(collocation3d, "rhs", counted(collocation3d.rhs))
    return count


@pytest.mark.parametrize("method", ["auto", "shooting", "collocation"])
def test_the_still_water_surface_mooring_is_refused_before_any_solver_runs(method, evaluations):
    with pytest.raises(SolverError, match=WHY) as error:
        solve_cable3(cable_problem3(still_mooring()), method)
    assert WHAT in str(error.value) and "slack in still water" in str(error.value)
    assert evaluations["rhs"] == 0


def test_the_continuum_run_starts_from_a_small_pull_and_says_so():
    """The refused steady state does not stop a continuum run any more (simulation.slack: continue):
    it starts from the steady state under a small pull on its body, released at t = 0, and its notes
    say so (tests/continuum/test_continuum_slack.py checks that start against the catenary)."""
    model = api.dynamic_model(still_mooring())
    model.initial()
    assert any("pull" in note for note in model.notes)


def test_with_its_current_the_mooring_still_solves():
    case = api.load_case(EXAMPLES / "surface_mooring_waves.yaml").replace({"environment.waves": None})
    solution = solve_cable3(cable_problem3(case), "auto")
    assert solution.grounded_length > 0.0 and min(solution.tension) > 0.0
