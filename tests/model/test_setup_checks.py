"""Validation and the dynamic models accept the same cases (:mod:`kanat.model.setup_checks`).

For every class of case that the continuum or the lumped model refuses when a run is set up,
``kanat validate`` reports it first, at its key and line; the model refuses it too, with a
dotted key; and the example it was made from is accepted by both. The copies the case checks
keep of the models' own facts (the scheme names, the attachment tolerance, the track's speeds)
are held equal to the models' here.
"""
from __future__ import annotations

import copy
import inspect
import math
import warnings

import pytest
import yaml

from kanat.api import SCHEMES, dynamic_model
from kanat.errors import CaseError, KanatError
from kanat.io import CaseWarning, check_text, parse_case
from kanat.io.yaml_loader import LineLoader
from kanat.model import Case, Vessel
from kanat.model.setup_checks import ATTACHMENT_SNAP, LAW_SAMPLES, LAW_STRAIN
from kanat.schemes import SCHEME_NAMES, SchemeName
from kanat.model.vessel import start_speeds

from helpers import EXAMPLES

FILE = "case.yaml"


# --- the copies of the models' facts -----------------------------------------------------

def test_the_scheme_names_are_the_registries():
    """Name for name, model for model: the list validation checks ``simulation.scheme`` against is
    what the registries hold (each registry is refused at import where it is not: test below)."""
    from kanat.continuum.family import FamilyScheme

    registered = {name: SchemeName(cls.model, cls.explicit,
                                   cls.model == "continuum" and not issubclass(cls, FamilyScheme))
                  for name, cls in SCHEMES.items()}
    assert registered == SCHEME_NAMES


def test_a_registry_that_differs_from_the_list_is_refused():
    """A listed name left out, a class stating another model than the list's: clear errors."""
    from dataclasses import dataclass
    from typing import ClassVar

    from kanat.errors import KanatError
    from kanat.lumped.integrators import ABM4, RK4
    from kanat.schemes import Scheme, registry

    with pytest.raises(KanatError, match=r"not registered \['generalized-alpha-lumped'\]"):
        registry(RK4, ABM4)
    with pytest.raises(KanatError, match="states model 'continuum'"):
        @dataclass(frozen=True)
        class Mislabelled(Scheme):
            name: ClassVar[str] = "rk4"
            model: ClassVar[str] = "continuum"


def test_the_model_names_are_the_front_doors():
    """Every model a case may name has an entry in the front door, and no other."""
    from kanat import api
    from kanat.schemes import MODELS

    assert sorted(api.MODELS) == sorted(MODELS)


def test_the_tolerances_are_the_models():
    from kanat.continuum.grid import elastic_law_knots
    from kanat.lumped.grid import SNAP_RTOL

    assert ATTACHMENT_SNAP == SNAP_RTOL
    defaults = inspect.signature(elastic_law_knots).parameters
    assert (LAW_STRAIN, LAW_SAMPLES) == (defaults["max_strain"].default, defaults["samples"].default)


TRACKS = {
    "a stop, then a turn": [{"straight": {"speed_kn": 6, "duration": 10}},
                            {"accelerate": {"to_speed": 0, "acceleration": 0.7}},
                            {"turn": {"rate_deg_s": 1, "duration": 5}}],
    "a ramp cut short": [{"straight": {"speed": 3.1, "duration": 10}},
                         {"accelerate": {"to_speed": 0.2, "acceleration": 0.3, "duration": 4}},
                         {"turn": {"radius": 300, "angle_deg": -45}}, {"straight": {"duration": 5}}],
    "a ramp and a hold": [{"accelerate": {"to_speed_kn": 7, "acceleration": 0.11, "duration": 100}},
                          {"heading": {"change_deg": 30, "rate_deg_s": 2}},
                          {"speed_step": {"to_speed": 1.3}}, {"turn": {"radius": 50, "angle_deg": 90}}],
    "speeds of their own": [{"straight": {"duration": 3}}, {"turn": {"radius": 9, "angle_deg": 9, "speed": 2}},
                            {"straight": {"speed_kn": 0.5, "duration": 3}}, {"turn": {"rate_deg_s": -1,
                                                                                       "angle_deg": -9}}],
}


@pytest.mark.parametrize("name", sorted(TRACKS))
def test_start_speeds_are_the_tracks(name):
    """Bit for bit: a turn's check sees the speed :func:`compile_phases` turns at."""
    from kanat.vessel.track import compile_phases

    track = Vessel.model_validate({"track": TRACKS[name]}).track
    speeds = start_speeds(track)
    for i, segment in enumerate(track):
        if segment.kind == "speed_step":      # no duration: it starts and ends at once
            continue
        before = len(compile_phases(track[:i]))
        assert compile_phases(track[:i + 1])[before].speed == speeds[i], (i, segment.kind)


# --- each class of refusal: validate reports it, the model refuses it ---------------------

def load(name: str) -> dict:
    return yaml.load((EXAMPLES / f"{name}.yaml").read_text(), Loader=LineLoader)  # noqa: S506 - a safe loader


def at(*path):
    """An edit setting ``path`` (its last key to the value given later)."""
    def setter(value):
        def edit(data):
            node = data
            for key in path[:-1]:
                node = node[key]
            node[path[-1]] = value
        return edit
    return setter


def delete(*path):
    def edit(data):
        node = data
        for key in path[:-1]:
            node = node[key]
        del node[path[-1]]
    return edit


def add_body(name, body, attachment=None, cable=0):
    def edit(data):
        data["bodies"][name] = body
        if attachment is not None:
            data["cables"][cable]["attachments"].append(attachment)
    return edit


def add_cable(cable, **bodies):
    def edit(data):
        data["cables"].append(cable)
        data["bodies"].update(bodies)
    return edit


def pitch_on_a_harmonic_beyond_the_series(data):
    pitch = data["vessel"]["pitch"]
    pitch.update(harmonics=5, damping_ratio=0.0, natural_frequency=7 * 2 * math.pi / pitch["wave_period"])


CLASSES = {
    "an unknown scheme": ("turn_375", at("simulation", "scheme")("rk9"), "simulation.scheme",
                          ("unknown continuum scheme 'rk9'", "generalized-alpha")),
    "a lumped scheme on the continuum model": ("turn_375", at("simulation", "scheme")("rk4"),
                                               "simulation.scheme", ("'rk4' is a lumped scheme",)),
    "a continuum scheme on the lumped model": ("lazy_wave", at("simulation", "scheme")("generalized-alpha"),
                                               "simulation.scheme", ("did you mean 'generalized-alpha-lumped'",)),
    "a turn of given radius after a stop": ("turn_375", at("vessel", "track", 0, "straight", "speed_kn")(0),
                                            "vessel.track[1]", ("needs a speed > 0", "track[0] ends at 0 m/s")),
    "a turn at a speed too small to turn": ("turn_375",
                                            at("vessel", "track", 0, "straight", "speed_kn")(5e-324),
                                            "vessel.track[1]", ("turns at 0 rad/s",)),
    "a 6-DOF body without its position": ("mooring_buoy_decay", delete("bodies", "buoy", "position"),
                                          "bodies.buoy.position", ("needs its position",)),
    "a 6-DOF body under an implicit scheme": ("mooring_buoy_decay",
                                              at("simulation", "scheme")("generalized-alpha-lumped"),
                                              "simulation.scheme", ("dof: 6", "abm4 or rk4")),
    "a fairlead on a point body": ("lazy_wave", at("cables", 0, "to")({"body": "clump", "offset": [1, 0, 0]}),
                                   "cables[0].to", ("needs a rigid body",)),
    "an attached body that ends the cable too": ("lazy_wave", at("cables", 0, "to")("clump"),
                                                 "cables[0].attachments[0].body", ("already placed",)),
    "a 6-DOF attached body": ("lazy_wave", at("bodies", "clump")({"mass": 2000, "net_buoyancy": -1.5e4, "dof": 6,
                                                                  "inertia": [1, 1, 1], "position": [0, 0, -50]}),
                              "cables[0].attachments[0].body", ("an inline attachment is a point",)),
    "an attachment on an anchored end": ("lazy_wave", at("cables", 0, "attachments", 0, "s")(0),
                                         "cables[0].attachments[0].body", ("cable end that is an anchor",)),
    "two attachments at one place": ("lazy_wave", add_body("clump2", {"mass": 10, "net_buoyancy": -100},
                                                           {"body": "clump2", "s": 230}),
                                     "cables[0].attachments[1].body", ("on one node",)),
    "a part of the network that nothing holds": (
        "mooring_buoy_decay", add_cable({"name": "loose", "line_type": "chain76", "length": 10, "segments": 2,
                                         "from": "free", "to": "weight"}, weight={"mass": 10, "net_buoyancy": -50}),
        "cables[3]", ("joined to neither the vessel nor an anchor", "weight")),
    "a factorized scheme on sections": ("subsurface_mooring", at("simulation", "scheme")("factorized"),
                                        "cables[0].sections", ("uniform flexible cable only",)),
    "a factorized scheme in waves": ("surface_mooring_waves", at("simulation", "scheme")("wave-factorized-2"),
                                     "environment.waves", ("uniform flexible cable only",)),
    "a continuum attachment at a cable end": ("subsurface_mooring", at("cables", 0, "attachments", 0, "s")(0),
                                              "cables[0].attachments[0].s", ("is that end's body",)),
    "an elastic law the continuum model cannot invert": (
        "turn_375", at("line_types", "towcable", "elastic_law")({"polynomial": [1e6, -3e6]}),
        "line_types.towcable.elastic_law", ("must increase with strain up to 0.5",)),
    "a JONSWAP gamma beyond DNV's normalization": (
        "mooring_buoy_waves", at("environment", "waves", "gamma")(1e6), "environment.waves.gamma",
        ("spectrum negative",)),
    "a seabed too soft to hold the lines": (
        "mooring_buoy_waves", at("environment", "seabed", "stiffness")(3e-194), "environment.seabed.stiffness",
        ("sink", "more than the depth")),
    "an undamped pitch on a harmonic beyond the series": (
        "pitch_tow_6kn", pitch_on_a_harmonic_beyond_the_series, "vessel.pitch.natural_frequency",
        ("harmonic n = 7", "beyond the 5 harmonics computed")),
}
NOT_A_NUMBER = {"a JONSWAP gamma beyond DNV's normalization", "a seabed too soft to hold the lines"}
"""Classes that the models do not refuse but set up with NaN (a RuntimeWarning)."""


def errors_of(data: dict) -> tuple[str, list]:
    text = yaml.safe_dump(data, sort_keys=False)
    return text, [p for p in check_text(text, FILE) if p.severity == "error"]


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_validate_reports_what_the_model_refuses(name):
    base, edit, key, words = CLASSES[name]
    data = load(base)
    assert errors_of(data)[1] == []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", CaseWarning)
        dynamic_model(parse_case(yaml.safe_dump(data, sort_keys=False)))       # the example is set up
    data = copy.deepcopy(data)
    edit(data)
    text, errors = errors_of(data)
    match = [p for p in errors if p.key == key and all(w in p.message for w in words)]
    assert match, [str(p) for p in errors]
    assert match[0].file == FILE and 1 <= match[0].line <= text.count("\n")
    case = Case.model_validate(data, context={})     # the data are valid: only the checks stop it
    failure = RuntimeWarning if name in NOT_A_NUMBER else KanatError
    with warnings.catch_warnings(), pytest.raises(failure) as refused:
        warnings.simplefilter("error", RuntimeWarning)
        dynamic_model(case)
    if isinstance(refused.value, CaseError):          # keys as written in the case, not tuples
        assert all("(" not in p.key for p in refused.value.problems), str(refused.value)


def test_the_statics_of_a_network_in_a_current_is_checked_as_the_lumped_network():
    """Network statics hands a network in a current to the lumped model's equilibrium, which builds
    the lumped network: a 6-DOF body there needs its position too (in still water it does not)."""
    from kanat.api import solve_statics

    data = load("mooring_3leg")
    del data["bodies"]["buoy"]["position"]
    assert errors_of(data)[1] == []                            # still water: network statics takes it
    data["environment"]["current"] = {"velocity": [0.5, 0, 0]}
    text, errors = errors_of(data)
    assert [p.key for p in errors] == ["bodies.buoy.position"], [str(p) for p in errors]
    case = Case.model_validate(data, context={})
    with warnings.catch_warnings(), pytest.raises(CaseError, match="bodies.buoy.position"):
        warnings.simplefilter("ignore", CaseWarning)
        solve_statics(case)
