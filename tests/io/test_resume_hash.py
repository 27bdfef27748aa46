"""The case hash a run's checkpoints and result carry (kanat.io.provenance.case_sha256): what the
user wrote that sets the numbers, so that a run started before a release that adds model keys
(with defaults) resumes with that release, while any changed value refuses the resume.

Oracles: a model grown by keys with defaults (pydantic.create_model on the case and its
simulation block) validating the same case, the old whole-model hash (which that growth changes),
every value of a case changed in turn, and a killed run resumed by the grown model equal to an
uninterrupted run.
"""
import warnings

import numpy as np
import pytest
from pydantic import ValidationError, create_model

from helpers import EXAMPLES, killed_run, run, short_case
from kanat import load_case
from kanat.errors import KanatError
from kanat.io.provenance import case_sha256, same_case, whole_case_sha256
from kanat.io.results import read_result
from kanat.io.stream import Checkpoint
from kanat.model.case import Case
from kanat.model.simulation import Simulation


def quiet_load(source):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(source)


def grown(case):
    """``case`` validated by the case model of a later release: a new defaulted key at the top and
    one in the simulation block."""
    simulation = create_model("LaterSimulation", __base__=Simulation, future_tolerance=(float, 1e-3))
    later = create_model("LaterCase", __base__=Case, simulation=(simulation | None, None),
                         future_switch=(bool, False))
    return later.model_validate(case.model_dump(by_alias=True))


@pytest.fixture(scope="module")
def step_case():
    return quiet_load(short_case(duration=20, segments=10, before=5))


def test_keys_added_with_defaults_keep_the_hash(step_case):
    later = grown(step_case)
    assert later.simulation.future_tolerance == 1e-3 and later.future_switch is False
    assert whole_case_sha256(later) != whole_case_sha256(step_case)       # the old form refused the resume
    assert case_sha256(later) == case_sha256(step_case)
    assert same_case(case_sha256(step_case), later)


def test_a_value_written_at_its_default_keeps_the_hash():
    text = (EXAMPLES / "mooring_3leg.yaml").read_text()
    written = text.replace("  water_density: 1025\n", "  water_density: 1025\n  gravity: 9.81\n")
    assert written != text
    assert case_sha256(quiet_load(written)) == case_sha256(quiet_load(text))
    changed = text.replace("  water_density: 1025\n", "  water_density: 1025\n  gravity: 9.80\n")
    assert case_sha256(quiet_load(changed)) != case_sha256(quiet_load(text))


def leaves(data, path=()):
    """``(path, value)`` of every number and flag in a dumped case."""
    if isinstance(data, dict):
        for key, value in data.items():
            yield from leaves(value, (*path, key))
    elif isinstance(data, list):
        for k, value in enumerate(data):
            yield from leaves(value, (*path, k))
    elif isinstance(data, (bool, int, float)):
        yield path, data


def changed(data, path, value):
    if not path:
        return value
    head, *rest = path
    copy = dict(data) if isinstance(data, dict) else list(data)
    copy[head] = changed(data[head], rest, value)
    return copy


@pytest.mark.parametrize("example", ["mooring_3leg.yaml", "speed_step_2d.yaml"])
def test_every_value_changed_changes_the_hash(example):
    """Every number and flag of the case, defaults included, changed in turn: a different hash
    whenever the case validates and differs."""
    case = quiet_load(EXAMPLES / example)
    data = case.model_dump(by_alias=True)
    own, tried = case_sha256(case), 0
    for path, value in leaves(data):
        new = (not value) if isinstance(value, bool) else value * 1.1 + 0.5
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                other = Case.model_validate(changed(data, path, new))
            except (ValidationError, ValueError):
                continue
        if other.model_dump() == case.model_dump():
            continue
        tried += 1
        assert case_sha256(other) != own, path
    assert tried >= 20


def test_a_checkpoint_is_taken_by_the_same_case_only(step_case, tmp_path):
    result = tmp_path / "run.nc"
    Checkpoint(1.0, 2, case_sha256(step_case), "rk4", {"x": np.zeros(3)}, {}).save(result)
    assert Checkpoint.load(result, case_sha256(grown(step_case)), "rk4").outputs == 2
    longer = step_case.replace({"simulation.duration": 21})
    with pytest.raises(KanatError, match="different case"):
        Checkpoint.load(result, case_sha256(longer), "rk4")
    # a checkpoint of an earlier release (the whole-model hash) with the model unchanged since
    Checkpoint(1.0, 2, whole_case_sha256(step_case), "rk4", {"x": np.zeros(3)}, {}).save(result)
    assert Checkpoint.load(result, case_sha256(step_case), "rk4", (whole_case_sha256(step_case),)).time == 1.0
    with pytest.raises(KanatError, match="different case"):
        Checkpoint.load(result, case_sha256(step_case), "rk4")


@pytest.mark.slow
def test_a_run_killed_before_a_release_resumes_with_it_bit_for_bit(step_case, tmp_path):
    run(step_case, tmp_path / "full.nc")
    killed_run(step_case, tmp_path / "part.nc", at=10.0, every=2)
    resumed = run(grown(step_case), tmp_path / "part.nc", resume=True)
    assert resumed.ok
    a, b = read_result(tmp_path / "full.nc"), read_result(tmp_path / "part.nc")
    np.testing.assert_array_equal(a["time"].values, b["time"].values)
    for name in ("position", "tension"):
        np.testing.assert_array_equal(b[name].values, a[name].values)
