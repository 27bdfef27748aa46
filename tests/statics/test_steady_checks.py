"""Steady states are never silently wrong (kanat.statics.steady_checks, docs/statics.md).

Each reproducer is a one- or two-key change of an example whose steady state is physically
impossible; each must end ``failed: <check>: ...`` naming the cable, node and s, with the
figure the message quotes checked against an oracle of its own (a span, a drag, a catenary in
deep water). The property test mutates examples at random and recomputes every check from the
result's positions and tensions wherever the status says ``ok``.
"""
import math
import re
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from helpers import EXAMPLES
from kanat import api, load_case
from kanat.errors import KanatError
from kanat.statics.steady_checks import ABSURD_BREAKING_MULTIPLE, NodeArrays, check_steady, law_strain

KNOT = 1852.0 / 3600.0


def statics(name, changes=None):
    """The statics outcome of an example with ``changes``; RunFailedWarning kept quiet."""
    case = load_case(EXAMPLES / name)
    if changes:
        case = case.replace(changes)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", api.RunFailedWarning)
        return api.run(case, model="statics")


def number(text, label):
    """The number after ``label`` in a message."""
    return float(re.search(re.escape(label) + r" (-?[0-9.e+-]+)", text).group(1))


# --- the reproducers --------------------------------------------------------------------

def test_three_100_m_legs_for_anchors_600_m_away_fail_on_strain():
    outcome = statics("mooring_3leg.yaml", {f"cables[{i}].length": 100 for i in range(3)})
    assert outcome.status.startswith("failed: strain: ")
    assert re.search(r"cable 'leg\d' node \d+ \(s = [0-9.]+ m\)", outcome.status)
    assert "line_types.chain76.max_strain" in outcome.status
    # a leg spans at least the horizontal distance from its anchor to its fairlead (600 - 2.5 m)
    assert number(outcome.status, "strain") >= (600.0 - 2.5) / 100.0 - 1.0 - 1e-6
    assert outcome.dataset.attrs["status"] == outcome.status          # written all the same
    assert outcome.dataset.sizes["node"] == 3 * 65


def test_a_tow_at_1999_kn_fails_on_strain_at_least_the_bodys_drag_needs():
    outcome = statics("towed_body.yaml", {"vessel.track[0].speed_kn": 1999})
    assert outcome.status.startswith("failed: strain: ")
    assert "cable 'tow' node 0 (s = 0 m)" in outcome.status
    drag = 0.5 * 1025 * 0.3276 * (1999 * KNOT) ** 2                   # the body's drag alone [N]
    assert number(outcome.status, "strain") >= drag / 1.2717e7


def test_a_towed_body_in_100_m_of_water_fails_on_the_seabed_by_its_deep_water_depth():
    deep = statics("towed_body.yaml").dataset                        # 2000 m: the same shape, no seabed met
    outcome = statics("towed_body.yaml", {"environment.depth": 100})
    assert outcome.status.startswith("failed: seabed: body 'sled' at cable 'tow' node 100 (s = 1000 m) is ")
    assert "environment.depth is the seabed" in outcome.status
    body_depth = -float(deep.position[-1, 2])
    assert number(outcome.status, "is") == pytest.approx(body_depth - 100.0, rel=1e-3)
    from kanat.statics import solve_statics                           # the solver's own result says so too
    assert solve_statics(load_case(EXAMPLES / "towed_body.yaml").replace({"environment.depth": 100})
                         ).verdict.status == outcome.status


def test_a_huge_tangential_drag_fails_on_strain():
    outcome = statics("towed_body.yaml", {"line_types.towcable.drag_tangential": 1e7})
    assert outcome.status.startswith("failed: strain: ")
    # the tangential drag of the straight cable alone, 0.5 rho C_t pi d V^2 L, over EA
    drag = 0.5 * 1025 * 1e7 * math.pi * 0.0173 * (6 * KNOT) ** 2 * 1000
    assert drag / 1.2717e7 > 1e3 and number(outcome.status, "strain") > 0.1


def test_a_sinking_buoy_fails_on_the_seabed_a_line_length_below_it():
    with pytest.warns(Warning, match="it will sink"):
        case = load_case(EXAMPLES / "subsurface_buoy.yaml").replace({"bodies.buoy.net_buoyancy": -8500})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", api.RunFailedWarning)
        outcome = api.run(case, model="statics")
    assert outcome.status.startswith("failed: seabed: body 'buoy' at cable 'riser' node 80 (s = 400 m) is ")
    # hanging straight down from the anchor at 500 m: the riser's stretched length below it
    w = 1.0 * 9.80665 - 1025 * 9.80665 * math.pi * 0.016**2 / 4
    stretch = (8500 * 400 + w * 400**2 / 2) / 1.3e7
    assert number(outcome.status, "is") == pytest.approx(400 + stretch, abs=0.05)


@pytest.mark.slow
def test_a_current_of_30_m_s_fails_on_strain():
    outcome = statics("mooring_current.yaml", {"environment.current.profile": [[0, 30, 0, 0], [-150, 30, 0, 0]]})
    assert outcome.status.startswith("failed: strain: ")          # was ok at strain 3.9, 12.7 km grounded
    ds = outcome.dataset
    position, s = ds.position.values, ds.s.values
    measured = np.max(np.linalg.norm(np.diff(position, axis=0), axis=1) / np.diff(s) - 1.0)
    strain = number(outcome.status, "strain")
    assert strain == pytest.approx(float(ds.tension.values[0]) / 5.1e8, rel=1e-3)    # T/EA at the node named
    # the largest segment's stretch: the mean of a strain that falls along the grounded chain (the 30 m/s
    # current drags it towards the fairlead: 0.8 MN per segment), 0.8 % below the anchor node's
    assert measured == pytest.approx(strain, rel=0.02)
    assert measured > 0.09


# --- the tension check: a warning, then a failure ---------------------------------------

@pytest.fixture(scope="module")
def mooring_tension():
    return float(statics("mooring_current.yaml").dataset.tension.max())


def test_a_tension_above_the_breaking_load_is_a_warning(mooring_tension):
    outcome = statics("mooring_current.yaml", {"line_types.chain76.breaking_load": mooring_tension / 2})
    assert outcome.ok
    assert "warning: tension" in outcome.text and "2 times the breaking load" in outcome.text
    assert "2 times the breaking load" in outcome.dataset.attrs["warnings"]
    assert "warnings" not in statics("mooring_current.yaml").dataset.attrs


def test_a_tension_far_above_the_breaking_load_fails(mooring_tension):
    multiple = 2 * ABSURD_BREAKING_MULTIPLE
    outcome = statics("mooring_current.yaml", {"line_types.chain76.breaking_load": mooring_tension / multiple})
    assert outcome.status.startswith("failed: tension: ")
    assert f"is {multiple:g} times the breaking load" in outcome.status


def test_kanat_solve_statics_warns_of_a_failed_steady_state():
    case = load_case(EXAMPLES / "towed_body.yaml").replace({"environment.depth": 100})
    with pytest.warns(api.RunFailedWarning, match="failed: seabed"):
        ds = api.solve_statics(case)
    assert ds.attrs["status"].startswith("failed: seabed: ")


def test_kanat_statics_exits_non_zero_and_keeps_the_file(tmp_path):
    from typer.testing import CliRunner
    from kanat.cli import app

    case = tmp_path / "shallow.yaml"
    case.write_text((EXAMPLES / "towed_body.yaml").read_text().replace("depth: 2000", "depth: 100"))
    done = CliRunner().invoke(app, ["statics", str(case), "-o", str(tmp_path / "out.nc")])
    assert done.exit_code == 1
    assert "failed: seabed" in done.output
    assert api.read_result(tmp_path / "out.nc").attrs["status"].startswith("failed: seabed")


# --- the checks on hand-made nodes --------------------------------------------------------

def straight(case, stretch=0.0, drop=0.0):
    """The towed body example's cable hanging straight down from the tow point, stretched."""
    s = np.linspace(0.0, 1000.0, 101)
    position = np.column_stack([0 * s, 0 * s, -(1 + stretch) * s - drop])
    return {"tow": NodeArrays(s, position, np.full(101, stretch * 1.2717e7))}


def test_a_straight_cable_within_its_limit_passes_and_beyond_it_fails():
    case = load_case(EXAMPLES / "towed_body.yaml")
    assert check_steady(case, straight(case, 0.05)).failure is None
    failure = check_steady(case, straight(case, 0.2)).failure
    assert failure.startswith("strain: strain 0.2 ")


def test_an_element_stretched_by_its_nodes_fails_whatever_its_tension():
    case = load_case(EXAMPLES / "towed_body.yaml")
    nodes = straight(case)["tow"]
    position = nodes.position.copy()
    position[1:, 2] -= 50.0                               # all but the tow point dropped by 50 m
    failure = check_steady(case, {"tow": NodeArrays(nodes.s, position, nodes.tension)}).failure
    assert failure.startswith("strain: ") and "node 1 (s = 10 m)" in failure
    assert number(failure, "strain") == pytest.approx(60.0 / 10.0 - 1.0, rel=1e-9)   # 60 m apart for 10 m


def test_a_node_beyond_the_reach_of_its_end_fails():
    case = load_case(EXAMPLES / "towed_body.yaml")
    s = np.concatenate([np.linspace(0.0, 500.0, 51), np.linspace(500.0, 1000.0, 51)])   # a station twice
    position = np.column_stack([0 * s, 0 * s, -s])
    position[51:, 0] += 2000.0                            # a jump where the station repeats: no element
    failure = check_steady(case, {"tow": NodeArrays(s, position, np.zeros(len(s)))}).failure
    assert failure.startswith("reach: cable 'tow' node 51 (s = 500 m) is ")
    assert number(failure, "is") == pytest.approx(math.hypot(2000.0, 500.0), rel=1e-5)


def test_an_end_off_its_anchor_fails():
    case = load_case(EXAMPLES / "mooring_current.yaml")
    a, b = np.array([-600.0, 0.0, -150.0]), np.array([0.0, 0.0, -5.0])
    s = np.linspace(0.0, 700.0, 71)
    position = a + np.outer(s / 700.0, b - a) + [0.0, 10.0, 0.0]        # a straight slack line, 10 m aside
    failure = check_steady(case, {"mooring": NodeArrays(s, position, np.zeros(71))}).failure
    assert failure.startswith("reach: the 'from' end of cable 'mooring' is 10 m from its anchor")


def test_a_non_finite_node_fails_first():
    case = load_case(EXAMPLES / "towed_body.yaml")
    nodes = straight(case)["tow"]
    position = nodes.position.copy()
    position[7, 2] = np.nan
    failure = check_steady(case, {"tow": NodeArrays(nodes.s, position, nodes.tension)}).failure
    assert failure.startswith("finite: ") and "node 7 (s = 70 m)" in failure


@pytest.mark.parametrize("law", [{"table": [[0.01, 1e5], [0.03, 4e5]]}, {"polynomial": [1e7, 5e8]}])
def test_the_law_inverted_gives_back_the_strain(law):
    case = load_case(EXAMPLES / "speed_step_2d.yaml").replace({"line_types.towcable.elastic_law": law})
    line = case.line_types["towcable"]
    strain = np.array([0.0, 0.005, 0.02, 0.03, 0.05])
    if "table" in law:
        e, T = np.array([0.0, 0.01, 0.03]), np.array([0.0, 1e5, 4e5])
        tension = np.where(strain <= 0.03, np.interp(strain, e, T), 4e5 + (strain - 0.03) * 3e5 / 0.02)
    else:
        tension = 1e7 * strain + 5e8 * strain**2
    assert law_strain(line, tension) == pytest.approx(strain, abs=1e-6)


def test_a_strain_beyond_the_law_table_fails_even_below_max_strain():
    case = load_case(EXAMPLES / "speed_step_2d.yaml").replace({
        "line_types.towcable.elastic_law": {"table": [[0.01, 1e5], [0.03, 4e5]]},
        "line_types.towcable.max_strain": 0.5})
    s = np.linspace(0.0, 1000.0, 101)
    nodes = NodeArrays(s, np.column_stack([0 * s, 0 * s, -s]), np.full(101, 5e5))   # 0.0367 by the law
    failure = check_steady(case, {"tow": nodes}).failure
    assert failure.startswith("strain: strain 0.03667 ") and "elastic_law table" in failure


# --- the initial state of a dynamic run ---------------------------------------------------

def initial_tension(name):
    """Largest tension of a dynamic example's initial state (the breaking load plays no part in it)."""
    model = api.dynamic_model(load_case(EXAMPLES / name))
    return float(np.max(model.outputs(model.initial())["tension"]))


def test_a_dynamic_runs_initial_state_fails_its_steady_checks_and_is_written(tmp_path):
    tension = initial_tension("towed_array.yaml")
    multiple = 2 * ABSURD_BREAKING_MULTIPLE
    case = load_case(EXAMPLES / "towed_array.yaml").replace({
        "line_types.array.breaking_load": tension / multiple, "simulation.duration": 10})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", api.RunFailedWarning)
        outcome = api.run(case, output=tmp_path / "out.nc")
    assert outcome.status.startswith("failed: tension: ")
    assert "in the initial state (t = 0)" in outcome.status
    assert number(outcome.status, "is") == pytest.approx(multiple, rel=1e-3)
    ds = api.read_result(tmp_path / "out.nc")
    assert ds.sizes["time"] == 1 and ds.attrs["status"] == outcome.status


def test_a_dynamic_runs_initial_state_above_the_breaking_load_is_logged_and_runs(caplog):
    tension = initial_tension("towed_array.yaml")
    case = load_case(EXAMPLES / "towed_array.yaml").replace({
        "line_types.array.breaking_load": tension / 2, "simulation.duration": 2})
    with caplog.at_level("WARNING", logger="kanat"):
        outcome = api.run(case)
    assert outcome.ok
    assert any("2 times the breaking load" in r.getMessage() and "initial state" in r.getMessage()
               for r in caplog.records)


# --- the property: ok means every check holds ------------------------------------------

def independent_checks(case, ds):
    """Every check of a steady state, recomputed from the result's node arrays."""
    position, tension, s = ds.position.values, ds.tension.values, ds.s.values
    cables = ds.cable.values.astype(str)
    assert np.all(np.isfinite(position)) and np.all(np.isfinite(tension))
    for cable in case.cables:
        mine = cables == cable.name
        line = case.line_types[cable.line_type]
        limit = line.strain_limit()
        r, T, arc = position[mine], tension[mine], s[mine]
        assert np.all(T / line.axial_stiffness <= limit * (1 + 1e-6))
        chord = np.linalg.norm(np.diff(r, axis=0), axis=1)
        step = np.diff(arc)
        assert np.all(chord[step > 0] <= step[step > 0] * (1 + limit) * (1 + 1e-6))
        if line.breaking_load is not None:
            assert T.max() <= ABSURD_BREAKING_MULTIPLE * line.breaking_load
        for end, k in ((cable.from_, 0), (cable.to, -1)):
            if end.kind == "anchor":
                assert np.linalg.norm(r[k] - end.position) <= 1e-3 + 1e-6 * cable.length
        assert np.all(np.linalg.norm(r - r[0], axis=1) <= arc * (1 + limit) + 1e-3)
        env = case.environment
        if env.depth is not None:                                      # flat seabeds in these examples
            w = max(line.weight_in_water_value(env.water_density, env.gravity), 0.0)
            sink = 0.0 if env.seabed is None else 10 * w / (env.seabed.stiffness * line.diameter)
            assert r[:, 2].min() >= -env.depth - sink - 1e-3


TOW = st.fixed_dictionaries({
    "vessel.track[0].speed_kn": st.floats(0.5, 3000.0),
    "environment.depth": st.floats(50.0, 5000.0),
    "bodies.sled.net_buoyancy": st.floats(-1e5, -100.0),
    "line_types.towcable.drag_tangential": st.sampled_from([0.0, 0.01, 1.0, 1e3, 1e7]),
    "cables[0].length": st.floats(50.0, 3000.0),
})
BUOY = st.fixed_dictionaries({
    "bodies.buoy.net_buoyancy": st.floats(-2e4, 1e5),
    "environment.depth": st.floats(100.0, 3000.0),
    "cables[0].length": st.floats(50.0, 2000.0),
})


LEGS = st.builds(lambda length, depth: {**{f"cables[{i}].length": length for i in range(3)},
                                         "environment.depth": depth},
                 st.floats(80.0, 3000.0), st.floats(50.0, 1000.0))


def _checked(name, changes):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = load_case(EXAMPLES / name).replace(changes)
            outcome = api.run(case, model="statics")
    except KanatError:                    # refused, or no steady state found: never a silent ok
        return
    if outcome.ok:
        independent_checks(case, outcome.dataset)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(TOW)
def test_every_ok_tow_passes_every_check(changes):
    _checked("towed_body.yaml", changes)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(BUOY)
def test_every_ok_subsurface_buoy_passes_every_check(changes):
    _checked("subsurface_buoy.yaml", changes)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(LEGS)
def test_every_ok_three_leg_mooring_passes_every_check(changes):
    _checked("mooring_3leg.yaml", changes)


def test_a_node_on_a_section_boundary_passes_when_either_line_does():
    """lazy_wave.yaml's riser: flowline to s = 230 m, buoyant modules to 330 m; the breaking loads
    set so that a tension passes one line type and fails the other."""
    case = load_case(EXAMPLES / "lazy_wave.yaml").replace({"line_types.flowline.breaking_load": 1e4,
                                                           "line_types.buoyant.breaking_load": 1e6})
    s = np.concatenate([np.linspace(0.0, 230.0, 24), np.linspace(240.0, 330.0, 10), np.linspace(336.0, 490.0, 16)])
    position = np.column_stack([-400.0 + s * 300.0 / 490.0, 0 * s, -100.0 + s * 90.0 / 490.0])   # a slack chord
    tension = np.zeros(len(s))
    tension[23] = 5e5                                     # at s = 230 m: 50 x the flowline's, 0.5 x the modules'
    assert check_steady(case, {"riser": NodeArrays(s, position, tension)}).failure is None
    tension[22] = 5e5                                     # at s = 220 m, inside the flowline: 50 times it
    failure = check_steady(case, {"riser": NodeArrays(s, position, tension)}).failure
    assert failure.startswith("tension: tension 500 kN at cable 'riser' node 22 (s = 220 m)")
    assert "is 50 times the breaking load 10 kN of line type 'flowline'" in failure
