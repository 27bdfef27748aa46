"""Kernels compiled ahead of time, at install: loaded without numba, or not at all when unusable.

``pip install`` builds the extension module ``kanat._kernels`` from the continuum model's step
kernels (:data:`ENTRIES` lists them; ``setup.py`` builds them with numba's ahead-of-time
compiler, :mod:`kanat.aot_build`). Why: numba's import and its one-time initialisation at the
first kernel load cost about 0.45 s of CPU in every process, a third of the whole 2-D example
run (benchmarks/RESULTS.md), and a first run would compile for 4-12 s; a plain extension module
imports in under a millisecond and compiles nothing.

Two guards keep it honest:

* **Current sources.** The module carries a fingerprint of the sources it was compiled from
  (:data:`SOURCES`); :func:`load` compares it with the files on disk, so an edited kernel (in a
  source checkout) is never answered by stale machine code.
* **Exact argument types.** Machine code compiled ahead of time does not check what it is given
  (an array of another type or layout would be read as if it were right: a wrong answer or a
  crash). :func:`kernel` checks every argument against the entry's :class:`Array` / scalar
  specification first (a few microseconds) and hands anything else to numba's kernel, which
  types it and compiles for it.

When the module is stale or missing (no C compiler at install), or a call's arguments do not
match, the run uses numba's just-in-time kernels, which give the same numbers bit for bit
(tests/test_aot.py). ``KANAT_AOT=0`` in the environment makes a process use numba's kernels
throughout (to compare, or to debug a kernel).
"""
from __future__ import annotations

import hashlib
import importlib
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

SOURCES = ("jit.py", "continuum/layout2d.py", "continuum/loads2d.py", "continuum/rows2d.py", "continuum/layout3d.py",
           "continuum/loads3d.py", "continuum/rows3d.py", "continuum/bending3d.py", "physics/seabed.py", "aot.py",
           "aot_build.py")
"""The files whose code the extension holds (paths below the ``kanat`` package): every module
the compiled kernels read a function or a constant from, and the build's description."""


@dataclass(frozen=True)
class Array:
    """A C-ordered, aligned, writeable NumPy array of ``dtype`` with ``ndim`` dimensions."""

    dtype: str
    ndim: int


F1, F2 = Array("float64", 1), Array("float64", 2)
FLOAT = "float64"
"""Scalar specifications are type names (``"float64"``); ``None`` is Python's None; a tuple of
specifications is a tuple argument."""

_PLANAR = (F2, F2, F2, F2, F2, F1, F1, F1, F2)                 # x, y, d, env, P, b0, b1, res, band
_SPATIAL = (F2, F2, F2, F2, F1, F2, F1, F1, F1, F2)            # x, y, d, env, up, P, b0, b1, res, band
ENTRIES = {
    "assemble": ("kanat.continuum.rows2d", (_PLANAR + (None,), _PLANAR + (F1,))),
    "assemble3": ("kanat.continuum.rows3d", (_SPATIAL + (None,), _SPATIAL + (F1,))),
    "assemble3_bending": ("kanat.continuum.bending3d", (_SPATIAL + (None,), _SPATIAL + (F1,))),
}
"""Every compiled entry: its numba kernel's module, and the argument specifications of its
versions (``<name>__<i>`` in the extension). All return None. ``extras`` (the last argument) is
None for a plain cable and an array otherwise (:mod:`kanat.continuum.rows2d`)."""

_loaded: dict = {}


def fingerprint(root: Path | None = None) -> int:
    """A 60-bit digest of :data:`SOURCES` as they are in ``root`` (default: this package).

    The build bakes it into the extension (``fingerprint()``); :func:`load` compares the two.
    """
    root = root or Path(__file__).parent
    digest = hashlib.sha256()
    for name in SOURCES:
        digest.update(name.encode())
        digest.update((root / name).read_bytes())
    return int(digest.hexdigest()[:15], 16)


def load(name: str = "_kernels"):
    """The compiled module ``kanat.<name>`` when it was built and matches the sources, else None.

    Imports no numba. The answer is kept for the process.
    """
    if name not in _loaded:
        if os.environ.get("KANAT_AOT") == "0":
            _loaded[name] = None
            return None
        try:
            module = importlib.import_module(f"kanat.{name}")
            current = module.fingerprint() == fingerprint()
        except (ImportError, OSError, AttributeError):
            module, current = None, False
        _loaded[name] = module if current else None
    return _loaded[name]


def checker(spec) -> Callable[[object], bool]:
    """A test of whether a value is what ``spec`` (an :class:`Array`, a scalar type name, None or a
    tuple of them) describes, exactly as the compiled code reads it (NumPy's ``flags.carray``: C
    order, aligned, writeable). Made once per entry version: a call checks its arguments in about
    0.15 us each."""
    if spec is None:
        return lambda value: value is None
    if isinstance(spec, tuple):
        items, n = tuple(map(checker, spec)), len(spec)
        return lambda value: (type(value) is tuple and len(value) == n
                              and all(check(item) for check, item in zip(items, value)))
    if isinstance(spec, Array):
        dtype, ndim = np.dtype(spec.dtype), spec.ndim
        return lambda value: (type(value) is np.ndarray and value.dtype is dtype and value.ndim == ndim
                              and value.flags.carray)
    if spec == FLOAT:
        return lambda value: isinstance(value, float)
    raise ValueError(f"no such specification: {spec!r}")


def matches(value, spec) -> bool:
    """Whether ``value`` is what ``spec`` describes (:func:`checker`)."""
    return checker(spec)(value)


def kernel(name: str) -> Callable:
    """The entry ``name`` of :data:`ENTRIES`: its compiled versions when :func:`load` finds them
    current, each called only with arguments that match it (the one that matched last is tried
    first), numba's kernel otherwise."""
    home, versions = ENTRIES[name]

    def numba_kernel():
        return getattr(importlib.import_module(home), name)

    compiled = load()
    if compiled is None:
        return numba_kernel()
    candidates = [(getattr(compiled, f"{name}__{i}"), checker(spec)) for i, spec in enumerate(versions)]

    def run(*args):
        for index, (function, check) in enumerate(candidates):
            if check(args):
                if index:
                    candidates.insert(0, candidates.pop(index))
                return function(*args)
        return numba_kernel()(*args)                 # other types: numba compiles for them

    run.__name__ = run.__qualname__ = name
    run.__doc__ = f"{home}.{name}, compiled at install (kanat.aot_build); other argument types go to numba's."
    return run
