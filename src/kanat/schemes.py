"""One registry of time schemes for every dynamic model (STYLE rule 2).

Each model's scheme module lists its scheme classes in a tuple ``SCHEMES``; this
module gathers them by name. A scheme is a small frozen dataclass whose fields are its
parameters, and whose class attributes say what it is:

1. ``name`` — the name used in case files (``simulation.scheme``);
2. ``model`` — ``"continuum"`` or ``"lumped"``;
3. ``order`` — its order of accuracy in time, measured by one parametrized test;
4. ``explicit`` — whether its step is bounded by a stability limit.

A user's own scheme object works wherever a name does: :func:`get_scheme` passes
instances through.
"""
from __future__ import annotations

import dataclasses
import importlib
from typing import ClassVar

from kanat.errors import KanatError

SCHEME_MODULES = ("kanat.continuum.schemes", "kanat.lumped.integrators")


class Scheme:
    """Base class of every time scheme (see the module docstring for the contract)."""

    name: ClassVar[str] = ""
    model: ClassVar[str] = ""
    order: ClassVar[int] = 0
    explicit: ClassVar[bool] = False

    def parameters(self) -> dict:
        """The scheme's parameters, for the result's attributes."""
        return dataclasses.asdict(self) if dataclasses.is_dataclass(self) else {}


def scheme_classes(model: str | None = None) -> dict[str, type[Scheme]]:
    """Every registered scheme class by name, optionally only those of ``model``."""
    found: dict[str, type[Scheme]] = {}
    for module_name in SCHEME_MODULES:
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as error:
            if error.name and module_name.startswith(error.name):
                continue                                    # that model is not part of this build
            raise
        for cls in module.SCHEMES:
            if model is None or cls.model == model:
                found[cls.name] = cls
    return found


def get_scheme(spec, model: str, **parameters) -> Scheme:
    """A scheme object from a name (with its parameters) or a scheme object.

    Raises
    ------
    KanatError
        For an unknown name, listing the valid names for ``model``.
    """
    if isinstance(spec, Scheme):
        return spec
    classes = scheme_classes(model)
    if spec not in classes:
        valid = ", ".join(sorted(classes)) or "none in this build"
        raise KanatError(f"unknown {model} scheme '{spec}'; valid: {valid}")
    cls = classes[spec]
    fields = {f.name for f in dataclasses.fields(cls)} if dataclasses.is_dataclass(cls) else set()
    return cls(**{k: v for k, v in parameters.items() if k in fields and v is not None})


def label(scheme: Scheme) -> str:
    """The scheme's name and parameters, as ``generalized-alpha(lambda_inf=-0.5)``."""
    params = ",".join(f"{k}={v!r}" for k, v in scheme.parameters().items())
    return f"{scheme.name}({params})"
