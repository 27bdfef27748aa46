"""Zhang, Zhang & Liu's comparison (theory/validation-cases.md case 8) on a shortened turn: the paper's qualitative ranking.

The paper: generalized-α and the box method agree with the experiment, backward Euler and the
generalized trapezoidal scheme deviate (first order); generalized-α, backward Euler and the
generalized trapezoidal scheme converge in fewer Newton iterations than the box method.
"""

import pytest

from kanat.studies.scheme_comparison import compare_schemes, table
from kanat.io import parse_case

from helpers import EXAMPLES

EXAMPLE = (EXAMPLES / "turn_375.yaml").read_text()


@pytest.fixture(scope="module")
def rows(tmp_path_factory):
    text = EXAMPLE.replace("segments: 100", "segments: 40").replace("duration: 741", "duration: 250")
    return {r["scheme"]: r for r in compare_schemes(parse_case(text), tmp_path_factory.mktemp("s002"))}


@pytest.mark.slow
def test_all_schemes_complete_the_turn(rows):
    assert all(r["status"] == "ok" for r in rows.values())
    assert "| generalized-alpha(-0.5) |" in table(list(rows.values()))


@pytest.mark.slow
def test_second_order_schemes_are_closest_to_the_reference(rows):
    dev = {k: r["deviation_from_reference_m"] for k, r in rows.items()}
    assert dev["backward-euler"] > dev["generalized-trapezoidal(0.6)"] > dev["generalized-alpha(-0.5)"]
    assert dev["backward-euler"] > 10 * dev["box"]


@pytest.mark.slow
def test_box_needs_more_newton_iterations_than_the_dissipative_schemes(rows):
    its = {k: r["newton_iterations_mean"] for k, r in rows.items()}
    for name in ("backward-euler", "generalized-trapezoidal(0.6)", "generalized-alpha(-0.5)"):
        assert its["box"] > its[name]
