"""How kanat compiles its kernels (numba), and whether a run is about to compile.

Every compiled kernel is declared with one of two decorators, so that the options live in
one place:

- :data:`kernel` — a kernel called from Python (and from other kernels);
- :data:`inner` — a helper called only from other kernels: numba builds no Python entry
  for it, which saves compile time on functions whose arguments are large tuples.

Both cache the machine code on disk, in a folder of its own per version of the kernel sources
(:func:`cache_directory`), so a kernel compiles once per machine and source version and never
runs a callee's stale code (numba's cache checks a kernel's own file only). Neither imports
numba: they return a :class:`Deferred` kernel, and numba loads when a kernel is first used
(:func:`load_numba`), which a run with the kernels compiled at install (:mod:`kanat.aot`) never
does. No module's namespace is rewritten: a kernel's name is its :class:`Deferred` throughout.
What a run
compiles is grouped in families (:class:`Family`: the top-level kernels of one model and
scheme, with the compile time measured on the reference machine); :func:`pending` tells,
without compiling, whether a family still has to be compiled, so a run can say
"compiling kernels once, ~N s" first. ``kanat.warmup`` compiles every family ahead of use.

Rules that keep compiling short (docs/performance.md has the measurements): scalar loops,
no array expressions, slice copies (``a[:] = b``), ``@`` or ``np.linalg`` in kernels a run
uses; no complex variants in a run (complex-step oracles are compiled by the tests only; the
factorized schemes' end conditions are the exception: their derivatives written out compiled no
faster than the complex step, docs/performance.md);
no ``inline="always"``; no integer constant passed straight to another kernel (numba
compiles a separate version for the literal) — pass a variable or restructure. Scratch
arrays come from ``np.empty`` with a float (or int64) dtype, zeroed by ``a[:] = 0.0`` where
needed: every ``np.zeros``, ``.copy()`` or other dtype spelling compiles numba's own
implementation of it once more (30–60 ms each). Every kernel's machine code includes all its
callees again (numba links and re-optimizes them into each caller's module), so a deep call
tree pays for its leaves at every level: ``benchmarks/profile_compile.py`` shows where a
family's seconds go, function by function.

A rule that keeps them fast: inside a loop over elements, nodes or points, no call to another
kernel that passes arrays or records of arrays (pass their entries as scalars, or loop inside
the callee), and a record's fields read into locals before the loop. Such a call cost 50-300 ns
each, several times the arithmetic it served (docs/performance.md, "Calls in the element loops").
"""
from __future__ import annotations

import logging
import os
import time
from dataclasses import dataclass
from pathlib import Path

from kanat import aot
from kanat._private_api import dispatcher_type, disk_cached_signatures, enable_disk_cache

OPTIONS = {"kernel": {"error_model": "numpy", "no_cfunc_wrapper": True},
           "inner": {"error_model": "numpy", "no_cpython_wrapper": True, "no_cfunc_wrapper": True}}
"""numba's options of the two decorators (the disk cache is turned on apart, :func:`cache_directory`).
error_model "numpy": a division by zero gives inf or nan
(the kernels' callers test for non-finite results) instead of a check and an exception on every
division, which costs compile time and stops vectorization. no_cfunc_wrapper: numba otherwise
builds a C-callable wrapper of every kernel for use as a first-class function value, which kanat
never does."""

CACHE_ENVIRONMENT = "KANAT_JIT_CACHE"
"""The environment variable that turns numba's disk cache of the kernels off (``0``): the
install-time build sets it (:mod:`kanat.aot_build`), so that it compiles every kernel from its
source and writes no cache."""
CACHE_KEEP = 8
"""Cache folders kept (:func:`cache_directory`): those of the most recently used source versions."""

COMPILE_SECONDS = [0.0]
"""Seconds numba has spent compiling kernels in this process (outermost calls only;
:class:`kanat.dynamics.CompileClock` reads it)."""

KERNELS: list = []
"""Every kernel declared in this process (:class:`Deferred`), in the order declared."""
_numba = None                       # numba's njit, once imported (:func:`load_numba`)


class Deferred:
    """A numba kernel: its dispatcher is made when it is first needed.

    The name a kernel module gives a kernel is always this object, whatever the process did
    before: importing a kernel module imports no numba (a run whose kernels were compiled at install,
    :mod:`kanat.aot`, never needs it). A call, or any attribute of numba's dispatcher (such as
    ``signatures``), loads numba (:func:`load_numba`) and makes this kernel's dispatcher. numba's
    compiler, typing a kernel that calls another, reads the callee's type from it
    (``_numba_type_``: numba's type of the callee's dispatcher), so kernels call each other by
    their plain names.
    """

    def __init__(self, function, options: dict):
        self.py_func, self.options, self.dispatcher = function, options, None
        self.__name__, self.__qualname__ = function.__name__, function.__qualname__
        self.__module__, self.__doc__ = function.__module__, function.__doc__

    def _real(self):
        if self.dispatcher is None:
            load_numba()
            dispatcher = _numba(**self.options)(self.py_func)
            directory = cache_directory()
            if directory is not None:
                _enable_cache(dispatcher, directory)
            self.dispatcher = dispatcher
        return self.dispatcher

    @property
    def _numba_type_(self):
        """numba's type of this kernel's dispatcher (what ``numba.typeof`` answers for the kernel)."""
        return dispatcher_type(self._real())

    def __call__(self, *args):
        if aot.LOOKUP.interpreted:                        # KANAT_KERNELS=python: the plain twin
            return aot.LOOKUP.twin_of(self.py_func)(*args)
        dispatcher = self.dispatcher if self.dispatcher is not None else self._real()
        return dispatcher(*args)

    def __getattr__(self, name):
        if name.startswith("__") or name in ("py_func", "options", "dispatcher"):     # copying, probing
            raise AttributeError(name)
        return getattr(self._real(), name)

    def __repr__(self) -> str:
        return f"<kanat kernel {self.__module__}.{self.__qualname__}>"


def _decorator(kind: str):
    def decorate(function):
        deferred = Deferred(function, OPTIONS[kind])
        KERNELS.append(deferred)
        return deferred
    return decorate


kernel = _decorator("kernel")
"""A kernel called from Python (and from other kernels)."""
inner = _decorator("inner")
"""A helper called only from other kernels: numba builds no Python entry for it."""


def dispatcher_of(function):
    """numba's dispatcher of a kernel (deferred or not); loads numba."""
    return function._real() if isinstance(function, Deferred) else function


def cache_directory() -> Path | None:
    """The folder of numba's disk cache of the kernels: ``kanat-<fingerprint>`` (the digest
    :func:`kanat.aot.fingerprint` of every kernel source, :data:`kanat.aot.SOURCES`, in hex) in
    ``NUMBA_CACHE_DIR``, or in ``$XDG_CACHE_HOME/kanat/numba`` (else ``~/.cache/kanat/numba``)
    when that is not set; None when :data:`CACHE_ENVIRONMENT` is ``0`` (no disk cache).

    Why a folder per version of the sources: numba's cache answers a kernel from its index when the
    kernel's own file is unchanged (its index is keyed by that file's time stamp and size, and by
    the kernel's bytecode), but the machine code it holds includes every kernel it calls, compiled
    when it was cached. A callee edited in another file (or a record's fields, or a constant read
    from another module) would run as it was before: stale code, or NaN where the arguments no
    longer mean what the old code reads (numba issue #6845, "cache invalidation does not track
    dependent functions"). With the folder named after every kernel source, any edit starts an
    empty cache, and the kernels are compiled afresh, each with its current callees.
    """
    if os.environ.get(CACHE_ENVIRONMENT) == "0":
        return None
    from numba import config

    base = config.CACHE_DIR or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "kanat", "numba")
    return Path(base) / f"kanat-{aot.fingerprint():015x}"


def _enable_cache(dispatcher, directory: Path) -> None:
    """Turn on numba's disk cache of ``dispatcher`` in ``directory``
    (:func:`kanat._private_api.enable_disk_cache`), pruning old folders first when it is new."""
    if not directory.is_dir():
        _prune(directory.parent)
    enable_disk_cache(dispatcher, str(directory))
    try:
        os.utime(directory)                                     # in use: kept by _prune
    except OSError:
        pass


def _prune(base: Path, keep: int = CACHE_KEEP) -> None:
    """Remove all but the ``keep - 1`` most recently used ``kanat-*`` cache folders of ``base``
    (a new one is about to be made; :func:`_enable_cache` marks a folder used)."""
    import shutil

    try:
        folders = sorted(base.glob("kanat-*"), key=lambda path: path.stat().st_mtime, reverse=True)
    except OSError:
        return
    for old in folders[keep - 1:]:
        shutil.rmtree(old, ignore_errors=True)


def compiled_versions() -> dict:
    """``{"module.kernel": signatures}`` of every kernel numba has compiled or loaded a version of
    in this process (none when the compiled-at-install modules ran everything)."""
    return {f"{k.__module__}.{k.__qualname__}": tuple(k.dispatcher.signatures) for k in KERNELS
            if k.dispatcher is not None and k.dispatcher.signatures}


def load_numba():
    """Import numba and listen to its compile events (:data:`COMPILE_SECONDS`, and a warning where
    the user expects no compiling). Done once per process; each kernel makes its own dispatcher
    when first needed (:class:`Deferred`)."""
    global _numba
    if _numba is not None:
        return
    from numba import njit
    from numba.core import event

    _numba = njit
    event.register("numba:compile", _compile_listener(event.Listener))


def _compile_listener(base):
    """numba's compile-event listener (its base class comes with numba, loaded on demand)."""

    class Listener(base):
        depth, began, told = 0, 0.0, False

        def on_start(self, ev):
            if self.depth == 0:
                self.began = time.perf_counter()
                if not self.told and aot.current():         # the user expects no compiling: say why there is some
                    self.told = True
                    logging.getLogger("kanat").warning(
                        f"compiling numba's {ev.data['dispatcher'].py_func.__qualname__} (and what it calls) once "
                        "for this run's argument types, which the kernels compiled at install do not take; cached "
                        "for later runs")
            self.depth += 1

        def on_end(self, ev):
            self.depth -= 1
            if self.depth == 0:
                COMPILE_SECONDS[0] += time.perf_counter() - self.began

    return Listener()


@dataclass(frozen=True)
class Family:
    """The kernels one kind of run compiles.

    Attributes
    ----------
    name : str
        ``continuum-2d``, ``lumped-rk4``, ... (``kanat.warmup.FAMILIES``).
    entries : tuple of (dispatcher, accept)
        The top-level kernels the run calls from Python (compiling them compiles everything
        they call), each with ``accept(signature) -> bool`` choosing its version for this
        family (:func:`planar`, :func:`spatial`) or None for any version.
    compile_s : float
        Measured compile time of the family on a cold cache (2-core x86_64 reference
        machine, benchmarks/RESULTS.md) [s].
    """

    name: str
    entries: tuple
    compile_s: float


def planar(signature) -> bool:
    """The planar version of a kernel shared by planar and spatial runs: the vertical is None, an
    argument of its own or a field of a record argument (the factorized schemes' ``FactorizedLine``)."""
    from numba import types

    return any(isinstance(t, types.NoneType) or isinstance(t, types.BaseNamedTuple)
               and any(isinstance(field, types.NoneType) for field in t.types) for t in signature)


def spatial(signature) -> bool:
    """The spatial version of a kernel shared by planar and spatial runs."""
    return not planar(signature)


def is_cached(dispatcher, accept=None) -> bool:
    """Whether ``dispatcher`` runs without compiling: a version (one that ``accept`` takes) is
    compiled in this process already, or its disk cache holds one for this machine and source."""
    accept = accept or (lambda signature: True)
    dispatcher = dispatcher_of(dispatcher)
    if any(accept(signature) for signature in dispatcher.signatures):
        return True
    cached = disk_cached_signatures(dispatcher) or ()      # None: numba internals moved, assume not cached
    return any(accept(signature) for signature in cached)


def pending(family: Family) -> float | None:
    """Seconds of compiling ``family`` would cost now (its measured ``compile_s``), or None if
    every kernel of it is cached or the kernels run as plain Python (``KANAT_KERNELS=python``).
    Cheap: reads the cache index, compiles nothing."""
    if aot.LOOKUP.interpreted:
        return None
    cached = all(is_cached(dispatcher, accept) for dispatcher, accept in family.entries)
    return None if cached else family.compile_s
