"""Kernels compiled ahead of time, at install: loaded without numba, or not at all when unusable.

``pip install`` builds the extension modules of :data:`MODULES` from the kernels runs call from
Python (:data:`ENTRIES` lists them; ``setup.py`` builds them with numba's ahead-of-time
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
(tests/kernels/test_aot.py). ``KANAT_AOT=0`` (or ``KANAT_KERNELS=numba``) in the environment makes a
process use numba's kernels throughout (to compare, or to debug a kernel); so does
:meth:`Lookup.numba_only` within a block. ``KANAT_KERNELS=python`` or :meth:`Lookup.python_only`
runs the plain twins instead, without numba (:data:`KERNEL_MODES`; docs/kernels.md).

Kernel inputs that belong together are named records (:func:`record`): a named tuple whose class
is its own argument specification, read by field name in the kernels.

Python code calls an entry through its :class:`EntryPoint` (``assemble = aot.register(...)``
beside its callers), always the same object; :data:`LOOKUP`, the one :class:`Lookup` of the
process, finds the compiled module or numba's kernel on the first call and keeps what it found
itself: no module's namespace is written.
"""
from __future__ import annotations

import collections
import contextlib
import functools
import hashlib
import importlib
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

SOURCES = ("jit.py", "aot.py", "aot_build.py", "physics/seabed.py", "physics/contact.py", "physics/hydrostatics.py",
           "continuum/layout2d.py", "continuum/loads2d.py", "continuum/rows2d.py", "continuum/kernels2d.py",
           "continuum/layout3d.py", "continuum/loads3d.py", "continuum/rows3d.py", "continuum/bending3d.py",
           "continuum/kernels3d.py", "lumped/kernels.py", "lumped/rigid.py", "lumped/fast.py", "lumped/fast_implicit.py",
           "lumped/bending.py", "lumped/output_loads.py", "lumped/entries.py", "continuum/factorized/dense.py",
           "continuum/factorized/sweeps_compiled.py", "continuum/factorized/waves_compiled.py")
"""The files whose code the extension holds (paths below the ``kanat`` package): every module
the compiled kernels read a function or a constant from, and those declaring the entries."""


@dataclass(frozen=True)
class Array:
    """A C-ordered, aligned, writeable NumPy array of ``dtype`` with ``ndim`` dimensions."""

    dtype: str
    ndim: int


FLOAT, INT, BOOL = "float64", "int64", "bool"
"""Scalar specifications; ``None`` is Python's None; a tuple of specifications a tuple argument;
a :func:`record` class a record of named fields."""
F1, F2, F3, F4 = Array(FLOAT, 1), Array(FLOAT, 2), Array(FLOAT, 3), Array(FLOAT, 4)
I1, I2, B1 = Array(INT, 1), Array(INT, 2), Array(BOOL, 1)


def record(name: str, module: str, **fields) -> type:
    """A named record: a :func:`collections.namedtuple` class ``module.name`` whose fields are
    ``fields`` (name: specification, in order), itself the specification of its instances.

    Kernels read a record's fields by name (``elements.length[k]``); numba types it as a named
    tuple (``types.NamedTuple`` of the fields' types, with the class), which both its just-in-time
    and its ahead-of-time compilers take, so adding a field is adding it here and filling it where
    the record is built. The class's ``SPECIFICATION`` holds the fields' specifications;
    ``narrowed(field=spec, ...)`` is a :class:`Record` specification with some fields' specifications
    replaced (an optional part given as None, whose code numba then prunes).
    """
    kind = collections.namedtuple(name, tuple(fields), module=module)
    kind.SPECIFICATION = tuple(fields.values())
    kind.narrowed = classmethod(_narrowed)
    return kind


@dataclass(frozen=True)
class Record:
    """The specification of a :func:`record` of class ``kind`` whose fields are ``specification``
    (the class's own ``SPECIFICATION``, or a narrowed one: ``kind.narrowed(...)``)."""

    kind: type
    specification: tuple


def _narrowed(kind, **fields) -> Record:
    unknown = set(fields) - set(kind._fields)
    if unknown:
        raise ValueError(f"{kind.__name__} has no field {', '.join(sorted(unknown))}")
    return Record(kind, tuple(fields.get(name, spec) for name, spec in zip(kind._fields, kind.SPECIFICATION)))


def is_record(spec) -> bool:
    """Whether ``spec`` is a :func:`record` class or a :class:`Record`."""
    return isinstance(spec, Record) or isinstance(spec, type) and hasattr(spec, "SPECIFICATION")


def as_record(spec) -> Record:
    """The :class:`Record` of a :func:`record` class or :class:`Record` ``spec``."""
    return spec if isinstance(spec, Record) else Record(spec, spec.SPECIFICATION)


MODULES = ("_continuum", "_lumped", "_lumped_explicit")
"""The extension modules: the continuum model's kernels (the box scheme's and the factorized
schemes'), the lumped model's (its Python path and implicit steps), and its explicit steps;
compiled side by side at install (about 40 s of CPU each)."""


@dataclass(frozen=True)
class Entry:
    """A kernel compiled at install: numba's ``function`` in module ``home``, in one version per
    argument specification of ``versions`` (``<name>__<i>`` in the extension ``module``), returning
    ``returns``; ``twin``, ``"module.function"`` of its plain NumPy twin taking the same arguments
    (:meth:`Lookup.python_only` runs it), or None where the twin is the kernel's own Python code."""

    home: str
    function: str
    versions: tuple
    returns: object = None
    module: str = "_continuum"
    twin: str | None = None


ENTRIES: dict[str, Entry] = {}
"""Every compiled entry by name, filled by :func:`register` from the modules that call them
(``kanat.aot_build.DECLARING``)."""


def register(name: str, home: str, *versions, returns=None, function: str | None = None,
             module: str = "_continuum", twin: str | None = None) -> "EntryPoint":
    """Declare the entry ``name`` (:class:`Entry`; ``function`` defaults to ``name``); the
    :class:`EntryPoint` its callers call."""
    ENTRIES[name] = Entry(home, function or name, tuple(versions), returns, module, twin)
    return EntryPoint(name)


class EntryPoint:
    """What Python code calls for the entry ``name``: the same object whatever the process did
    before, each call handed to :data:`LOOKUP`'s kernel for the name (the compiled versions, or
    numba's kernel). Declared beside the callers: ``assemble = aot.register("assemble", ...)``."""

    def __init__(self, name: str):
        self.name = self.__name__ = self.__qualname__ = name

    def __call__(self, *args):
        return LOOKUP.kernel(self.name)(*args)

    def __repr__(self) -> str:
        return f"<kanat entry {self.name}>"


def fingerprint(root: Path | None = None) -> int:
    """A 60-bit digest of :data:`SOURCES` as they are in ``root`` (default: this package).

    The build bakes it into the extension (``fingerprint()``); :func:`load` compares the two.
    """
    if root is None:
        return _installed_fingerprint()
    digest = hashlib.sha256()
    for name in SOURCES:
        digest.update(name.encode())
        digest.update((root / name).read_bytes())
    return int(digest.hexdigest()[:15], 16)


@functools.cache
def _installed_fingerprint() -> int:
    """:func:`fingerprint` of this package, read once per process (every module is checked against it)."""
    return fingerprint(Path(__file__).parent)


RECENT = 16
"""Records a record checker remembers as checked (:func:`checker`); more are checked again."""


def checker(spec) -> Callable[[object], bool]:
    """A test of whether a value is what ``spec`` (an :class:`Array`, a scalar type name, None, a
    :func:`record` class, a :class:`Record` or a tuple of them) describes, exactly as the compiled
    code reads it (NumPy's ``flags.carray``: C order, aligned, writeable; a record of its own class
    only). Made once per entry version.

    A record's fields are checked the first time the checker sees it; after that, the record itself
    (its identity: a named tuple's fields cannot be replaced, and an array's type and layout are
    fixed when it is made) is enough, for the last :data:`RECENT` records it passed. A record built
    once per run (the network's elements, nodes, work arrays) so costs one ``is`` per call.
    """
    if spec is None:
        return _is_none
    if is_record(spec):
        return _record_checker(as_record(spec))
    if isinstance(spec, tuple):
        return _tuple_checker(tuple(map(checker, spec)))
    if isinstance(spec, Array):
        dtype, ndim = np.dtype(spec.dtype), spec.ndim
        return lambda value: (type(value) is np.ndarray and value.dtype is dtype and value.ndim == ndim
                              and value.flags.carray)
    if spec == FLOAT:
        return lambda value: isinstance(value, float)
    if spec == INT:
        return lambda value: isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))
    if spec == BOOL:
        return lambda value: isinstance(value, (bool, np.bool_))
    raise ValueError(f"no such specification: {spec!r}")


def _is_none(value) -> bool:
    return value is None


def _tuple_checker(items: tuple) -> Callable[[object], bool]:
    """:func:`checker` of a tuple of ``items`` checkers: a plain loop (no generator to create)."""
    n = len(items)

    def check(value) -> bool:
        if type(value) is not tuple or len(value) != n:
            return False
        for item, part in zip(items, value):
            if not item(part):
                return False
        return True
    return check


def _record_checker(spec: Record) -> Callable[[object], bool]:
    """:func:`checker` of a record: its class, then its fields once (see :func:`checker`)."""
    kind, fields, passed = spec.kind, _tuple_checker(tuple(map(checker, spec.specification))), {}

    def check(value) -> bool:
        if type(value) is not kind:
            return False
        if passed.get(id(value)) is value:                 # checked before (held here: its id is not reused)
            return True
        if not fields(tuple(value)):
            return False
        if len(passed) >= RECENT:
            passed.clear()
        passed[id(value)] = value
        return True
    return check


def matches(value, spec) -> bool:
    """Whether ``value`` is what ``spec`` describes (:func:`checker`)."""
    return checker(spec)(value)


KERNEL_MODES = ("aot", "numba", "python")
"""What :data:`LOOKUP` runs (``KANAT_KERNELS`` in the environment chooses for a process):
``aot`` the modules compiled at install where current, else numba's kernels (the default);
``numba`` numba's kernels throughout (also ``KANAT_AOT=0``); ``python`` the plain twins: an
entry's NumPy twin where it has one (:class:`Entry` ``twin``), else the kernel's own Python code
run by the interpreter, kernels it calls included (slow: small cases only, to test and debug)."""


def _environment_mode() -> str:
    """The kernel mode the environment asks for (:data:`KERNEL_MODES`)."""
    mode = os.environ.get("KANAT_KERNELS", "aot")
    if mode not in KERNEL_MODES:
        raise ValueError(f"KANAT_KERNELS={mode!r}: expected one of {', '.join(KERNEL_MODES)}")
    return "numba" if mode == "aot" and os.environ.get("KANAT_AOT") == "0" else mode


class Lookup:
    """Where the entries' code comes from, for the process (:data:`KERNEL_MODES`): the extension
    modules compiled at install when current (:meth:`module`), else numba's kernels;
    ``KANAT_AOT=0`` or :meth:`numba_only` chooses numba's throughout, ``KANAT_KERNELS=python`` or
    :meth:`python_only` the plain twins. :data:`LOOKUP` is the one instance; what it finds is
    kept in it, never written into a module's namespace."""

    def __init__(self):
        self.modules: dict = {}
        self.kernels: dict = {}
        self.mode: str | None = None                      # None: the environment's (_environment_mode)

    @property
    def interpreted(self) -> bool:
        """Whether kernels run as plain Python (the ``python`` mode): :class:`kanat.jit.Deferred`
        asks it at every call."""
        return self.current_mode() == "python"

    def current_mode(self) -> str:
        """The mode in force (:data:`KERNEL_MODES`)."""
        if self.mode is None:
            self.mode = _environment_mode()
        return self.mode

    def module(self, name: str = "_continuum"):
        """The compiled module ``kanat.<name>`` when it was built and matches the sources, else None.

        Imports no numba. The answer is kept for the process (until :meth:`numba_only`)."""
        if name not in self.modules:
            module = None
            if self.current_mode() == "aot":
                try:
                    module = importlib.import_module(f"kanat.{name}")
                    module = module if module.fingerprint() == fingerprint() else None
                except (ImportError, OSError, AttributeError):
                    module = None
            self.modules[name] = module
        return self.modules[name]

    def kernel(self, name: str) -> Callable:
        """The entry ``name`` of :data:`ENTRIES` (:func:`kernel`), made once and kept."""
        found = self.kernels.get(name)
        if found is None:
            if self.current_mode() == "python":
                found = twin(name)
            else:
                found = _kernel(name, self.module(ENTRIES[name].module))
            self.kernels[name] = found
        return found

    def twin_of(self, function: Callable) -> Callable:
        """The plain twin of a numba kernel's Python ``function``: the NumPy twin of the entry it
        is, if any, else ``function`` itself."""
        for name, entry in ENTRIES.items():
            if entry.twin is not None and entry.function == function.__name__ and entry.home == function.__module__:
                return twin(name)
        return function

    @contextlib.contextmanager
    def numba_only(self):
        """Within the block, every entry runs numba's kernel (as an install without the compiled
        modules, or ``KANAT_AOT=0``); what was found before is restored after it."""
        with self._mode("numba"):
            yield self

    @contextlib.contextmanager
    def python_only(self):
        """Within the block, every kernel runs its plain twin (``KANAT_KERNELS=python``); what was
        found before is restored after it."""
        with self._mode("python"):
            yield self

    @contextlib.contextmanager
    def _mode(self, mode: str):
        saved = self.modules, self.kernels, self.mode
        self.modules, self.kernels, self.mode = {}, {}, mode
        try:
            yield
        finally:
            self.modules, self.kernels, self.mode = saved


LOOKUP = Lookup()
"""The process's :class:`Lookup`."""


def current() -> bool:
    """Whether every module of :data:`MODULES` was built and matches the sources."""
    return all(load(name) is not None for name in MODULES)


def load(name: str = "_continuum"):
    """The compiled module ``kanat.<name>`` when it was built and matches the sources, else None
    (:meth:`Lookup.module`)."""
    return LOOKUP.module(name)


def kernel(name: str) -> Callable:
    """The entry ``name`` of :data:`ENTRIES`: its compiled versions when :func:`load` finds them
    current, each called only with arguments that match it (the one that matched last is tried
    first), numba's kernel otherwise. Made once per process (:data:`LOOKUP` keeps it)."""
    return LOOKUP.kernel(name)


def twin(name: str) -> Callable:
    """The plain twin of the entry ``name``: its NumPy twin (:class:`Entry` ``twin``) or the
    kernel's own Python code."""
    entry = ENTRIES[name]
    if entry.twin is not None:
        home, function = entry.twin.rsplit(".", 1)
        return getattr(importlib.import_module(home), function)
    return getattr(importlib.import_module(entry.home), entry.function).py_func


def _kernel(name: str, compiled) -> Callable:
    """:func:`kernel` of the entry ``name``, with the extension module ``compiled`` or None."""
    entry = ENTRIES[name]

    def numba_kernel():
        return getattr(importlib.import_module(entry.home), entry.function)

    if compiled is None:
        return numba_kernel()
    candidates = [(getattr(compiled, f"{name}__{i}"), checker(tuple(spec))) for i, spec in enumerate(entry.versions)]

    order = list(candidates)                         # the version that matched last first

    def run(*args):
        for candidate in order:
            function, check = candidate
            if check(args):
                if candidate is not order[0]:
                    order.remove(candidate)
                    order.insert(0, candidate)
                return function(*args)
        _numba_used.add(name)                        # other types: numba compiles for them (kanat.jit says so)
        return numba_kernel()(*args)

    run.__name__ = run.__qualname__ = name
    run.__doc__ = f"{entry.home}.{entry.function}, compiled at install (kanat.aot_build); other arguments go to numba's."
    return run


_numba_used: set = set()
"""Entries that were called with arguments no compiled version takes (the tests read it)."""
