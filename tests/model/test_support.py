"""The support table: what each solver models, checked against what the solvers do.

Oracles: the solvers themselves. Where the table says a solver refuses a feature, its own
set-up raises on a case using it; where it says a solver ignores or lacks a feature, the
solver's typed problem is identical with and without it; where it says the lumped model
has it, its network carries it.
"""
from __future__ import annotations

import dataclasses
import textwrap

import numpy as np
import pytest
import yaml
from helpers import EXAMPLES

from kanat.errors import CaseError
from kanat.io import check_text
from kanat.model import Case, Seabed
from kanat.model.support import (
    FEATURES,
    IGNORED,
    NO,
    SOLVERS,
    YES,
    feature,
    markdown_table,
    require_supported,
    seabed_reacher,
    unsupported,
)

TOW = textwrap.dedent("""\
    name: tow
    model: continuum
    environment: {depth: 3000}
    line_types:
      wire: {diameter: 0.02, mass: 1.2, axial_stiffness: 2.0e7}
    bodies:
      sled: {mass: 1000, net_buoyancy: -4000, drag_area: 0.3}
    vessel:
      track: [{straight: {speed: 2.0, duration: 100}}]
    cables:
      - {name: tow, line_type: wire, length: 1000, segments: 20, from: vessel, to: sled}
    simulation: {duration: 10, dt: 1.0}
    """)


def case_of(text: str = TOW, **changes) -> Case:
    data = yaml.safe_load(text)
    for key, value in changes.items():
        node, *path = key.split(".")
        target = data
        for part in [node, *path][:-1]:
            target = target.setdefault(part, {}) if not part.isdigit() else target[int(part)]
        last = [node, *path][-1]
        target[int(last) if last.isdigit() else last] = value
    return Case.model_validate(data)


def same(a, b) -> bool:
    """Equal, field by field, through dataclasses, mappings and arrays."""
    if dataclasses.is_dataclass(a):
        return type(a) is type(b) and all(same(getattr(a, f.name), getattr(b, f.name))
                                          for f in dataclasses.fields(a))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, (np.ndarray, list, tuple)):
        return np.array_equal(np.asarray(a), np.asarray(b))
    return a == b


NEW_KEYS = ("seabed", "seabed_friction", "seabed_lateral_friction", "seabed_slope",
            "bending_stiffness", "sections", "attachments", "vessel_motion", "winch",
            "six_dof_bodies", "body_fairleads", "vessel_fairleads", "point_properties")


def test_table_is_complete_and_consistent():
    names = [f.name for f in FEATURES]
    assert len(names) == len(set(names))
    for row in FEATURES:
        assert {row.level(s) for s in SOLVERS} <= {YES, NO, IGNORED}
        for solver in SOLVERS:
            if row.level(solver) == IGNORED:
                assert row.why(solver) or solver == "pitch", (row.name, solver)
    table = markdown_table()
    assert table.count("\n") == len(FEATURES) + 1 and "| feature | statics | continuum | lumped | pitch |" in table
    with pytest.raises(ValueError, match="unknown solver 'dynamic'"):
        FEATURES[0].level("dynamic")


STATICS_KEYS = ("seabed", "seabed_friction", "seabed_slope", "sections", "attachments", "six_dof_bodies",
                "body_fairleads", "vessel_fairleads", "point_properties", "bending_stiffness")
"""New keys that network statics models (tests/statics/test_network_statics.py,
tests/peers/test_network_statics_moorpy.py), and bending stiffness, which statics solves by the
lumped equilibrium (tests/lumped/test_lumped_bending.py)."""


@pytest.mark.parametrize("name", NEW_KEYS)
def test_no_solver_has_the_new_keys_yet(name):
    assert (feature(name).statics == YES) == (name in STATICS_KEYS)        # statics' part of the table


@pytest.mark.parametrize("model", ["continuum", "lumped"])
def test_the_dynamic_models_stop_at_the_strain_limit(model):
    """max_strain is used: a limit below the run's strain stops it, and says so."""
    import warnings

    import kanat

    text = (EXAMPLES / "speed_step_2d.yaml").read_text().replace("duration: 600", "duration: 5").replace(
        "    drag_tangential: 0.01\n", "    drag_tangential: 0.01\n    max_strain: 0.0001\n", 1)
    if model == "lumped":
        text = text.replace("model: continuum", "model: lumped").replace("segments: 100", "segments: 10").replace(
            "scheme: generalized-alpha", "scheme: generalized-alpha-lumped")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(text))
    assert ds.attrs["status"].startswith("failed:") and ("strain" in ds.attrs["status"]
                                                         or "stretched" in ds.attrs["status"])


# --- the table against the solvers ---------------------------------------------------------------

def two_cables() -> Case:
    text = TOW.replace("simulation:", "  - {name: b, line_type: wire, length: 50, segments: 5, "
                       "from: 'anchor:[0, 0, -100]', to: free}\nsimulation:")
    return case_of(text)


def test_continuum_refuses_what_the_table_says():
    from kanat.continuum.model2d import planar_cable
    from kanat.statics.setup import cable_problems

    several = two_cables()
    assert [p.key for p in unsupported(several, "continuum") if p.severity == "error"] == ["cables"]
    with pytest.raises(CaseError, match="takes one cable"):
        planar_cable(several)
    sideways = case_of(**{"environment.current": {"velocity": [0.5, 0.3, 0.0]}})
    assert not any(p.key == "environment.current" for p in unsupported(sideways, "continuum"))
    with pytest.raises(CaseError, match="y component"):
        cable_problems(sideways)                   # planar statics; the 3-D statics starts the continuum model
    loose = case_of(**{"cables": [{"name": "tow", "line_type": "wire", "length": 1000, "segments": 20,
                                   "from": "sled", "to": "vessel"}]})
    assert [p.key for p in unsupported(loose, "continuum")] == ["cables[0].from"]
    with pytest.raises(CaseError, match="first end must be the vessel or an anchor"):
        planar_cable(loose)
    assert unsupported(loose, "statics") == []
    cable_problems(loose)                          # statics takes a body at 'from'


@pytest.mark.parametrize("change, key", [
    ({"line_types.wire.axial_damping": 5.0e4}, "line_types.wire.axial_damping"),
])
def test_continuum_lacks_what_the_table_says(change, key):
    """The continuum model's cable is the same with and without the feature: it is not modelled."""
    from kanat.continuum.model2d import planar_cable

    plain, used = case_of(), case_of(**change)
    a, b = planar_cable(plain), planar_cable(used)
    assert (a.params == b.params).all() and a.start == b.start and a.end == b.end
    assert [p.key for p in unsupported(used, "continuum") if p.severity == "error"] == [key]
    assert unsupported(used, "lumped") == []


@pytest.mark.parametrize("change, key", [
    ({"line_types.wire.elastic_law": {"polynomial": [2.0e7, 1.0e8]}}, "line_types.wire.elastic_law"),
    ({"line_types.wire.drag_normal_coefficient": 0.9}, "line_types.wire.drag_normal_coefficient"),
    ({"bodies.sled.spreading_force": 3000.0}, "bodies.sled.spreading_force"),
    ({"bodies.sled.surface_buoy": {"waterplane_area": 1.0}}, "bodies.sled.surface_buoy"),
])
def test_statics_lacks_what_the_table_says(change, key):
    from kanat.statics.setup import cable_problems

    plain, used = case_of(), case_of(**change)
    assert same(cable_problems(plain), cable_problems(used))
    assert [p.key for p in unsupported(used, "statics") if p.severity == "error"] == [key]


@pytest.mark.parametrize("change, words", [
    ({"cables.0.to": "free"}, "free end"),
])
def test_statics_refuses_what_the_table_says(change, words):
    from kanat.statics.setup import cable_problems

    used = case_of(**change)
    assert any(p.severity == "error" for p in unsupported(used, "statics"))
    with pytest.raises(CaseError, match=words):
        cable_problems(used)


NETWORK = textwrap.dedent("""\
    name: net
    model: lumped
    environment: {depth: 100, waves: {type: regular, height: 1.0, period: 6.0}}
    line_types:
      chain: {diameter: 0.03, mass: 2.0, axial_stiffness: 5.0e7}
    bodies:
      buoy: {mass: 200, net_buoyancy: 5000, drag_area: 0.5, spreading_force: 100,
             surface_buoy: {waterplane_area: 1.0}}
    points:
      junction: {position: [0, 0, -60], mass: 10}
    cables:
      - {name: lower, line_type: chain, length: 40, segments: 4, from: 'anchor:[0, 0, -100]', to: junction}
      - {name: upper, line_type: chain, length: 20, segments: 2, from: 'anchor:[5, 0, -100]', to: buoy}
      - {name: link, line_type: chain, length: 5, segments: 1, from: junction, to: buoy}
    simulation: {duration: 1, dt: 0.01}
    """)


def test_lumped_has_what_the_table_says():
    from kanat.lumped.network import build_network
    from kanat.statics.setup import cable_problems

    case = case_of(NETWORK)
    assert [p.severity for p in unsupported(case, "lumped")] == []
    net = build_network(case)
    assert net.body_spreading.tolist() == [100.0] and net.buoy_area.tolist() == [1.0]
    assert net.node_mass.sum() == pytest.approx(200 + 10)
    keys = {p.key for p in unsupported(case, "statics") if p.severity == "error"}
    assert keys == {"bodies.buoy.spreading_force", "bodies.buoy.surface_buoy"}   # network statics takes the rest
    with pytest.raises(CaseError, match="network"):
        cable_problems(case)                       # the planar single-cable setup does not
    waves = [p for p in unsupported(case, "statics") if p.key == "environment.waves"]
    assert [p.severity for p in waves] == ["warning"] and "still-water" in waves[0].message


# --- messages, lines, and the check list ------------------------------------------------------------

def test_validate_reports_each_use_at_its_line_and_names_who_supports_it():
    text = TOW.replace("model: continuum", "model: continuum").replace(
        "  sled: {mass: 1000, net_buoyancy: -4000, drag_area: 0.3}",
        "  sled: {mass: 1000, net_buoyancy: -4000, drag_area: 0.3,\n         spreading_force: 100}")
    problems = [p for p in check_text(text, "case.yaml") if p.key == "bodies.sled.spreading_force"]
    assert len(problems) == 1
    (problem,) = problems
    assert (problem.severity, problem.line, problem.file) == ("error", 8, "case.yaml")
    assert problem.message == ("an otter board's spreading force: model 'continuum' does not support it; "
                               "supported by: lumped")


def test_bending_stiffness_is_taken_by_every_model_of_cables():
    case = case_of(**{"line_types.wire.bending_stiffness": 50.0, "simulation.dimensions": 3})
    assert unsupported(case, "continuum") == []                       # bending in 2-D and 3-D continuum runs
    assert unsupported(case_of(**{"line_types.wire.bending_stiffness": 50.0}), "continuum") == []
    assert unsupported(case, "lumped") == []                          # kanat.lumped.bending
    assert unsupported(case, "statics") == []                         # by the lumped equilibrium


def test_depth_alone_gives_the_default_seabed_where_cables_reach_it():
    shallow = case_of(**{"environment.depth": 500.0})
    assert unsupported(shallow, "lumped") == []                      # the default contact model, as continuum
    assert unsupported(shallow, "continuum") == []
    assert unsupported(shallow, "statics") == []
    assert shallow.with_seabed_contact().environment.seabed == Seabed()
    deep = case_of(**{"environment.depth": 3000.0})                  # 1000 m of cable in 3000 m
    assert deep.with_seabed_contact() is deep


def test_a_riser_held_up_by_its_buoy_does_not_reach_the_seabed():
    riser = case_of(**{"cables": [{"name": "riser", "line_type": "wire", "length": 400, "segments": 8,
                                   "from": "anchor:[0, 0, -500]", "to": "sled"}],
                       "bodies.sled.net_buoyancy": 8500.0, "environment.depth": 500.0})
    assert seabed_reacher(riser) is None and riser.with_seabed_contact() is riser
    sinking = case_of(**{"cables": [{"name": "riser", "line_type": "wire", "length": 400, "segments": 8,
                                     "from": "anchor:[0, 0, -500]", "to": "sled"}],
                         "environment.depth": 500.0})
    assert seabed_reacher(sinking) == "riser"
    assert sinking.with_seabed_contact().environment.seabed == Seabed()


def test_pitch_model_ignores_everything_else_with_warnings():
    case = case_of(**{"environment.waves": {"type": "regular", "height": 1.0, "period": 7.0}})
    assert {p.severity for p in unsupported(case, "pitch")} == {"warning"}
