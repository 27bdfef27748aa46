"""Kernels compiled ahead of time, at install: loaded without numba, or None when unusable.

``pip install`` builds the extension module ``kanat._kernels`` from the continuum model's step
kernels (:mod:`kanat.aot_build` says what it holds and ``setup.py`` builds it with numba's
ahead-of-time compiler). Why: numba's import and its one-time initialisation at the first
kernel load cost about 0.45 s of CPU in every process, a third of the whole 2-D example run
(benchmarks/RESULTS.md), and a first run would compile for 4-12 s; a plain extension module
imports in under a millisecond and compiles nothing.

The module is used only while it is current: it carries a fingerprint of the sources it was
compiled from (:data:`SOURCES`), and :func:`load` compares it with the files on disk, so an
edited kernel (in a source checkout) is never answered by stale machine code; then, or when
the extension was not built (no C compiler at install), the run falls back to numba's
just-in-time kernels, which give the same numbers (tests/test_aot.py). ``KANAT_AOT=0`` in the
environment makes a process use numba's kernels throughout (to compare, or to debug a kernel).
"""
from __future__ import annotations

import hashlib
import importlib
import os
from pathlib import Path
from typing import Callable

SOURCES = ("jit.py", "continuum/layout2d.py", "continuum/loads2d.py", "continuum/rows2d.py", "continuum/layout3d.py",
           "continuum/loads3d.py", "continuum/rows3d.py", "continuum/bending3d.py", "physics/seabed.py", "aot_build.py")
"""The files whose code the extension holds (paths below the ``kanat`` package): every module
the compiled kernels read a function or a constant from, and the build description itself."""

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


def kernel(name: str, numba_kernel: Callable[[], Callable]) -> Callable:
    """The kernel ``name`` whose last argument is ``extras`` (None or an array), compiled at install.

    From the extension (its ``<name>_plain`` when ``extras`` is None, ``<name>_extras`` otherwise)
    when :func:`load` finds it current, else ``numba_kernel()``, numba's kernel, which also takes
    arguments the compiled versions do not (they are typed for C-ordered float64 arrays).
    """
    compiled = load()
    if compiled is None:
        return numba_kernel()
    plain, full = getattr(compiled, f"{name}_plain"), getattr(compiled, f"{name}_extras")

    def run(*args):
        try:
            if args[-1] is None:
                plain(*args[:-1])
            else:
                full(*args)
        except TypeError:                        # other array types: numba compiles for them
            numba_kernel()(*args)

    run.__name__ = run.__qualname__ = name
    run.__doc__ = f"{name}, compiled at install (kanat.aot_build)."
    return run
