"""The time schemes' common ground: the base class, the registry builder and the lookup (style rule 2).

Each dynamic model keeps its own registry, built by plain imports in its scheme module
(:data:`kanat.continuum.schemes.SCHEMES`, :data:`kanat.lumped.integrators.SCHEMES`), and
:data:`kanat.api.SCHEMES` joins them. A scheme is a small frozen dataclass whose fields are
its parameters, and whose class attributes say what it is:

1. ``name`` — the name used in case files (``simulation.scheme``);
2. ``model`` — ``"continuum"`` or ``"lumped"``;
3. ``order`` — its order of accuracy in time, measured by one parametrized test
   (``tests/test_scheme_order.py``) for every registered scheme;
4. ``explicit`` — whether its step is bounded by a stability limit.

A user's own scheme object works wherever a name does: :func:`get_scheme` passes
instances through.
"""
from __future__ import annotations

import dataclasses
from typing import ClassVar

from kanat.errors import KanatError


class Scheme:
    """Base class of every time scheme (see the module docstring for the contract)."""

    name: ClassVar[str] = ""
    model: ClassVar[str] = ""
    order: ClassVar[int] = 0
    explicit: ClassVar[bool] = False

    def parameters(self) -> dict:
        """The scheme's parameters, for the result's attributes."""
        return dataclasses.asdict(self) if dataclasses.is_dataclass(self) else {}


def registry(*classes: type[Scheme]) -> dict[str, type[Scheme]]:
    """Scheme classes by name; two classes with one name are an error."""
    found: dict[str, type[Scheme]] = {}
    for cls in classes:
        if cls.name in found:
            raise KanatError(f"two schemes are named '{cls.name}': {found[cls.name].__name__} and {cls.__name__}")
        found[cls.name] = cls
    return found


def get_scheme(spec, schemes: dict[str, type[Scheme]], **parameters) -> Scheme:
    """A scheme object from a name (with its parameters) or a scheme object.

    Parameters
    ----------
    spec : str or Scheme
    schemes : dict of str to Scheme class
        The model's registry.
    **parameters
        Passed to the class when it has a field of that name and the value is not None.

    Raises
    ------
    KanatError
        For an unknown name, listing the valid ones.
    """
    if isinstance(spec, Scheme):
        return spec
    if spec not in schemes:
        model = next(iter(schemes.values())).model if schemes else "this"
        raise KanatError(f"unknown {model} scheme '{spec}'; valid: {', '.join(sorted(schemes))}")
    cls = schemes[spec]
    fields = {f.name for f in dataclasses.fields(cls)} if dataclasses.is_dataclass(cls) else set()
    return cls(**{k: v for k, v in parameters.items() if k in fields and v is not None})


def label(scheme: Scheme) -> str:
    """The scheme's name and parameters, as ``generalized-alpha(lambda_inf=-0.5)``."""
    params = ",".join(f"{k}={v!r}" for k, v in scheme.parameters().items())
    return f"{scheme.name}({params})"
