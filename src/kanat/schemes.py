"""The models' and time schemes' names and common ground: the base class, the registry builder
and the lookup (style rule 2).

:data:`MODELS` and :data:`SCHEME_NAMES` are the one list of the names a case file may give in
``model`` and ``simulation.scheme``: the case's data and checks (:mod:`kanat.model`), which sit
below the models, read them here, and each model's registry is held to them when it is built
(:func:`registry`). Each dynamic model keeps its own registry, built by plain imports in its
scheme module (:data:`kanat.continuum.schemes.SCHEMES`, :data:`kanat.lumped.integrators.SCHEMES`),
and :data:`kanat.api.SCHEMES` joins them. A scheme is a small frozen dataclass whose fields are
its parameters, and whose class attributes say what it is:

1. ``name`` — the name used in case files (``simulation.scheme``);
2. ``model`` — ``"continuum"`` or ``"lumped"`` (for a listed name: from :data:`SCHEME_NAMES`);
3. ``order`` — its order of accuracy in time, measured by one parametrized test
   (``tests/schemes/test_scheme_order.py``) for every registered scheme;
4. ``explicit`` — whether its step is bounded by a stability limit (for a listed name: from
   :data:`SCHEME_NAMES`).

A user's own scheme object works wherever a name does: :func:`get_scheme` passes
instances through.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import ClassVar

from kanat.errors import KanatError

MODELS = ("statics", "continuum", "lumped", "pitch")
"""Every model by its case-file name (``model``)."""
DYNAMIC_MODELS = ("continuum", "lumped")
"""The models that run in time (:mod:`kanat.dynamics`), each with its registry of schemes."""


@dataclass(frozen=True)
class SchemeName:
    """What a case's checks know of one time scheme, before any model is loaded.

    Attributes
    ----------
    model : {"continuum", "lumped"}
        The model whose registry holds it.
    explicit : bool
        Its step is bounded by a stability limit (the lumped model's explicit schemes are the
        ones that take 6-DOF bodies).
    uniform_cable_only : bool
        It steps a uniform, perfectly flexible cable only (Kaliukh & Vusatiuk's factorized schemes,
        outside the generalized-alpha family).
    """

    model: str
    explicit: bool = False
    uniform_cable_only: bool = False


SCHEME_NAMES: dict[str, SchemeName] = {
    "generalized-alpha": SchemeName("continuum"),
    "box": SchemeName("continuum"),
    "backward-euler": SchemeName("continuum"),
    "generalized-trapezoidal": SchemeName("continuum"),
    "factorized": SchemeName("continuum", uniform_cable_only=True),
    "factorized-4": SchemeName("continuum", uniform_cable_only=True),
    "wave-factorized": SchemeName("continuum", uniform_cable_only=True),
    "wave-factorized-2": SchemeName("continuum", uniform_cable_only=True),
    "wave-factorized-3": SchemeName("continuum", uniform_cable_only=True),
    "rk4": SchemeName("lumped", explicit=True),
    "abm4": SchemeName("lumped", explicit=True),
    "generalized-alpha-lumped": SchemeName("lumped"),
}
"""Every scheme a case may name in ``simulation.scheme``, by name: the one list. A scheme class
of a listed name takes its ``model`` and ``explicit`` from here (:meth:`Scheme.__init_subclass__`),
and :func:`registry` refuses a model's registry that leaves out a listed name or registers one
not listed."""


def schemes_of(model: str) -> list[str]:
    """The names of ``model``'s schemes (:data:`SCHEME_NAMES`), sorted."""
    return sorted(name for name, known in SCHEME_NAMES.items() if known.model == model)


class Scheme:
    """Base class of every time scheme (see the module docstring for the contract)."""

    name: ClassVar[str] = ""
    model: ClassVar[str] = ""
    order: ClassVar[int] = 0
    explicit: ClassVar[bool] = False

    def __init_subclass__(cls, **kwargs):
        """A class of a listed name (:data:`SCHEME_NAMES`) takes its ``model`` and ``explicit`` from the
        list; one stating others is an error."""
        super().__init_subclass__(**kwargs)
        known = SCHEME_NAMES.get(cls.__dict__.get("name"))
        if known is None:
            return
        for attribute in ("model", "explicit"):
            stated = cls.__dict__.get(attribute, getattr(known, attribute))
            if stated != getattr(known, attribute):
                raise KanatError(f"scheme '{cls.name}' states {attribute} {stated!r}; kanat.schemes.SCHEME_NAMES "
                                 f"lists it with {getattr(known, attribute)!r}")
        cls.model, cls.explicit = known.model, known.explicit

    def parameters(self) -> dict:
        """The scheme's parameters, for the result's attributes."""
        return dataclasses.asdict(self) if dataclasses.is_dataclass(self) else {}


def registry(*classes: type[Scheme]) -> dict[str, type[Scheme]]:
    """Scheme classes by name.

    Two classes with one name are an error, and so is a set of classes of the models in it that
    differs from :data:`SCHEME_NAMES` (a listed name left out, a name not listed).
    """
    found: dict[str, type[Scheme]] = {}
    for cls in classes:
        if cls.name in found:
            raise KanatError(f"two schemes are named '{cls.name}': {found[cls.name].__name__} and {cls.__name__}")
        found[cls.name] = cls
    listed = {name for name, known in SCHEME_NAMES.items() if known.model in {cls.model for cls in classes}}
    if set(found) != listed:
        raise KanatError(f"the registry of schemes {sorted(found)} differs from kanat.schemes.SCHEME_NAMES: "
                         f"not registered {sorted(listed - set(found))}, not listed {sorted(set(found) - listed)}")
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
