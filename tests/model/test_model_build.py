"""Every case model builds its validator (they are built on first use, not at import: a model
whose schema cannot be built would otherwise only fail when a case first used it)."""
import pytest

import kanat.model  # noqa: F401 - defines every case model
from kanat.model._base import KanatModel
from kanat.io import load_case

from helpers import EXAMPLES


def case_models(base=KanatModel):
    for model in base.__subclasses__():
        yield model
        yield from case_models(model)


MODELS = sorted(set(case_models()), key=lambda model: f"{model.__module__}.{model.__qualname__}")


def test_every_case_model_is_found():
    assert len(MODELS) >= 35                      # Case, its parts, the problem blocks (39 when written)


@pytest.mark.parametrize("model", MODELS, ids=lambda model: model.__qualname__)
def test_every_case_model_builds_its_validator(model):
    model.model_rebuild(force=True)
    assert model.__pydantic_complete__
    assert model.__pydantic_validator__.title == model.__name__


def test_a_loaded_case_validates_again_to_itself():
    """The deferred validators give back the case they read: dump and validate again."""
    case = load_case(EXAMPLES / "speed_step_2d.yaml")
    again = type(case).model_validate(case.model_dump())
    assert again == case and len(again.cables[0].sections) == len(case.cables[0].sections) >= 1
