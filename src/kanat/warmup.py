"""What each kind of run compiles, whether it still has to, and compiling it all ahead of use.

A run compiles its model's kernels once per machine (numba, cached on disk; :mod:`kanat.jit`).
:data:`FAMILIES` names what each kind of run compiles — model, dimensions, scheme — with the
compile time measured on the reference machine; :func:`pending` says, without compiling,
whether a family is still to be compiled (so a run can print "compiling kernels once, ~N s"
first), and :func:`warmup` compiles families by running a tiny case of each (``kanat
warmup``). The tiny cases go through the same run path as any case, so what they compile is
exactly what a run needs (tests/kernels/test_jit.py checks that a run after them compiles nothing).
"""
from __future__ import annotations

import time
from typing import Callable, Iterable

from kanat import aot
from kanat.jit import Family, planar, spatial
from kanat.jit import pending as family_pending

FAMILIES = {
    "continuum-2d": 3.7, "continuum-3d": 6.0, "factorized-2d": 12.9, "factorized-3d": 15.9,
    "wave-factorized-2d": 8.8, "wave-factorized-3d": 11.6, "lumped-rk4": 6.5, "lumped-abm4": 6.5,
    "lumped-implicit": 11.0, "continuum-3d-bending": 11.6,
}
"""Every family's name and its ``compile_s``: CPU seconds of the first run's compile measured by
``benchmarks/bench_compile.py`` (benchmarks/RESULTS.md; continuum-2d and the four factorized
families remeasured 2026-11-27 on a quiet machine; lumped-abm4 estimated from lumped-rk4)."""


def family(name: str) -> Family:
    """The :class:`kanat.jit.Family` ``name`` of :data:`FAMILIES`, importing only its own kernel
    modules (a continuum run asking whether it will compile does not load the lumped model)."""
    if name.startswith("lumped"):
        from kanat.lumped import fast, fast_implicit, kernels, output_loads

        step = {"lumped-rk4": fast.rk4_steps, "lumped-abm4": fast.abm4_steps, "lumped-implicit": fast_implicit.steps}
        entries = ((kernels.element_forces, None), (kernels.add_body_loads, None), (kernels.tensions, None),
                   (output_loads.output_loads, None), (step[name], None))
        return Family(name, entries, FAMILIES[name])
    from kanat.continuum import rows2d, rows3d

    if name == "continuum-3d-bending":
        from kanat.continuum import bending3d

        return Family(name, ((bending3d.assemble3_bending, None),), FAMILIES[name])
    flat = name.endswith("2d")
    entries = ((rows2d.assemble if flat else rows3d.assemble3, None),)
    if name.startswith("factorized"):
        from kanat.continuum.factorized import sweeps_compiled

        entries += ((sweeps_compiled._factorized_step, planar if flat else spatial),)
    elif name.startswith("wave-factorized"):
        from kanat.continuum.factorized import waves_compiled

        entries += ((waves_compiled._assemble_block, planar if flat else spatial),)
    return Family(name, entries, FAMILIES[name])


_SCHEME_FAMILY = {"generalized-alpha": "continuum", "box": "continuum", "backward-euler": "continuum",
                  "generalized-trapezoidal": "continuum", "factorized": "factorized", "factorized-4": "factorized",
                  "wave-factorized": "wave-factorized", "wave-factorized-2": "wave-factorized",
                  "wave-factorized-3": "wave-factorized", "rk4": "lumped-rk4", "abm4": "lumped-abm4",
                  "generalized-alpha-lumped": "lumped-implicit"}


def family_name(scheme: str, dimensions: int = 2, bending: bool = False) -> str | None:
    """The family a run of ``scheme`` (a registered scheme name) in ``dimensions`` compiles, or
    None for a scheme with no compiled kernels (a user's own). ``bending``: the cable has bending
    stiffness, which a 3-D run carries in kernels of its own (:mod:`kanat.continuum.bending3d`)."""
    base = _SCHEME_FAMILY.get(scheme)
    if base is None or base.startswith("lumped"):
        return base
    if base == "continuum" and dimensions == 3 and bending:
        return "continuum-3d-bending"
    return f"{base}-{3 if dimensions == 3 else 2}d"


def pending(name: str | None) -> float | None:
    """Seconds the family ``name`` (:func:`family_name`) still has to compile, None if cached, or
    compiled at install and current (:mod:`kanat.aot`: every family's entries), or no such family.
    Reads the cache index only: costs milliseconds."""
    if name not in FAMILIES or aot.current():
        return None
    return family_pending(family(name))


# --- tiny cases, one per family ---------------------------------------------------------------------
_CABLE = {"diameter": 0.0173, "mass": 1.12, "weight_in_water": 8.89, "axial_stiffness": 1.2717e7,
          "added_mass": 0.24, "drag_normal": 1.5, "drag_tangential": 0.01}


def _continuum(scheme: str, dimensions: int) -> dict:
    dt = 1.0 if scheme == "generalized-alpha" else 0.005          # the factorized schemes' CFL limit
    return {"name": f"warmup-{scheme}-{dimensions}d", "model": "continuum",
            "line_types": {"cable": _CABLE}, "bodies": {"sled": {"mass": 1135, "net_buoyancy": -6686,
                                                                  "drag_area": 0.3276}},
            "vessel": {"tow_point": [0, 0, 0], "track": [{"straight": {"speed": 3.0, "duration": 10.0}}]},
            "cables": [{"name": "tow", "line_type": "cable", "length": 200, "segments": 5, "from": "vessel",
                        "to": "sled"}],
            "simulation": {"scheme": scheme, "duration": 2 * dt, "dt": dt, "output_dt": dt,
                           "dimensions": dimensions}}


def _lumped(scheme: str) -> dict:
    return {"name": f"warmup-{scheme}", "model": "lumped", "line_types": {"cable": _CABLE},
            "bodies": {"sled": {"mass": 1135, "net_buoyancy": -6686, "drag_area": 0.3276,
                                "position": [-10.0, 0.0, -99.0]}},
            "vessel": {"tow_point": [0, 0, 0], "track": [{"straight": {"speed": 1.0, "duration": 10.0}}]},
            "cables": [{"name": "tow", "line_type": "cable", "length": 100, "segments": 3, "from": "vessel",
                        "to": "sled"}],
            "simulation": {"scheme": scheme, "duration": 0.1, "output_dt": 0.01}}


CASES = {
    "continuum-2d": _continuum("generalized-alpha", 2), "continuum-3d": _continuum("generalized-alpha", 3),
    "factorized-2d": _continuum("factorized", 2), "factorized-3d": _continuum("factorized", 3),
    "wave-factorized-2d": _continuum("wave-factorized", 2), "wave-factorized-3d": _continuum("wave-factorized-2", 3),
    "lumped-rk4": _lumped("rk4"), "lumped-abm4": _lumped("abm4"), "lumped-implicit": _lumped("generalized-alpha-lumped"),
    "continuum-3d-bending": {**_continuum("generalized-alpha", 3), "name": "warmup-bending-3d",
                             "line_types": {"cable": {**_CABLE, "bending_stiffness": 50.0}}},
}
"""A tiny case (a case-file mapping) per family: what :func:`warmup` runs."""


def warmup(simulate: Callable, names: Iterable[str] | None = None, progress: Callable | None = None) -> dict:
    """Compile the families ``names`` (all by default) that are not cached yet.

    Parameters
    ----------
    simulate : callable
        ``simulate(case_mapping)`` runs a case in memory (the CLI passes
        ``lambda case: kanat.simulate(kanat.load_case(case))``); it is passed in so that this
        module stays below the front door.
    names : iterable of str, optional
        Family names (:data:`FAMILIES`).
    progress : callable, optional
        ``progress(name, estimate_s)`` before each family that compiles.

    Returns
    -------
    dict
        Seconds spent per family (0.0 for one already cached).
    """
    spent = {}
    for name in (list(FAMILIES) if names is None else list(names)):
        if name not in FAMILIES:
            raise KeyError(f"no kernel family '{name}'; valid: {', '.join(FAMILIES)}")
        estimate = pending(name)
        if estimate is None:
            spent[name] = 0.0
            continue
        if progress is not None:
            progress(name, estimate)
        start = time.perf_counter()
        simulate(CASES[name])
        spent[name] = time.perf_counter() - start
    return spent
