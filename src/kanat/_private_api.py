"""Every use kanat makes of another library's private API, in one place (docs/kernels.md).

Seven touch points, each tested on its own (tests/kernels/test_private_api.py), so that a release of
numba, h5netcdf or SciPy that changes one fails one test whose message names the library and version:

* :func:`compile_object_files` — ``numba.pycc.CC._compile_object_files``: the install compiles
  each module's kernels to an object file in a process of its own (numba compiles on one core)
  and links them afterwards (``setup.py``). The public ``CC.compile()`` compiles and links in one
  call, one module at a time.
* :func:`disk_cached_signatures` — ``Dispatcher._cache._cache_file._load_index()`` and the layout
  of its keys: whether a run would compile, read without compiling (:func:`kanat.jit.is_cached`).
* :func:`flush_hdf5` — h5netcdf's ``File._h5file``: the HDF5 file beneath a netCDF file being
  written, flushed so that a killed run leaves its outputs on disk (:mod:`kanat.io.stream`).
* :func:`dispatcher_type` — numba's ``_numba_type_`` hook: numba's ``typeof`` takes any object's
  ``_numba_type_`` as its type, which types a :class:`kanat.jit.Deferred` kernel as the dispatcher
  it stands for, so kernels call each other by their plain names before numba is loaded.
* :func:`named_tuple_type` — ``numba.core.types.BaseTuple.from_types``: numba's type of a named
  record (:func:`kanat.aot.record`) made from its fields' types, as ``typeof`` types an instance;
  the install-time build (:mod:`kanat.aot_build`) declares the entries' signatures with it.
* :func:`enable_disk_cache` — numba's ``Dispatcher.enable_caching()``, which places a function's
  disk cache by ``numba.config.CACHE_DIR`` when it is called: set for that call only, so that the
  kernels cache in a folder per version of their sources (:func:`kanat.jit.cache_directory`).
* :func:`banded_lapack` — SciPy's extension module ``scipy/linalg/_flapack``, loaded from its file
  without the ``scipy.linalg`` package around it: the continuum model's Newton steps and the lumped
  model's equilibrium and Python implicit steps (:mod:`kanat.lumped.band_solve`) call LAPACK's
  ``dgbsv`` from it, and ``import scipy.linalg`` (or ``scipy.sparse``) costs a run 0.1-0.3 s of CPU (it imports
  ``scipy._lib.array_api_compat``, which imports NumPy's f2py, ma, testing and polynomial
  packages) against ~0.01 s for the module alone. Where the file is not found, the public
  ``scipy.linalg.lapack`` module (the same functions).

The libraries are imported inside the functions: importing this module imports none of them.
"""
from __future__ import annotations

import functools
import hashlib
import importlib.machinery
import importlib.util
import os


class PrivateAPIChanged(RuntimeError):
    """A library no longer has the private API kanat uses (the message names library and version)."""


def _changed(library: str, what: str, error: Exception) -> PrivateAPIChanged:
    version = getattr(__import__(library), "__version__", "?")
    return PrivateAPIChanged(f"{library} {version} changed {what}, which kanat uses "
                             f"({type(error).__name__}: {error}); see docs/kernels.md")


def compile_object_files(cc, build_temp: str) -> list[str]:
    """Compile the kernels of numba's ``CC`` ``cc`` to object files in ``build_temp``, unlinked.

    Returns
    -------
    list of str
        The object files written (one: :func:`object_file`).

    Raises
    ------
    PrivateAPIChanged
        numba's ``CC`` has no ``_compile_object_files`` taking a directory and returning
        ``(objects, exports)``.
    """
    try:
        compile_objects = cc._compile_object_files
    except AttributeError as error:
        raise _changed("numba", "numba.pycc.CC._compile_object_files", error) from None
    objects, _ = compile_objects(build_temp)
    return list(objects)


def object_file(cc, build_temp: str) -> str:
    """Where :func:`compile_object_files` writes ``cc``'s object file: named after the module's
    output file, in ``build_temp`` (needed when it runs in another process)."""
    return os.path.join(build_temp, os.path.splitext(cc.output_file)[0] + ".o")


def disk_cached_signatures(dispatcher) -> list | None:
    """The signatures numba's disk cache holds for ``dispatcher`` on this machine and for its
    current source, or None when numba's cache is not laid out as expected.

    The cache index maps ``(signature, codegen magic tuple, (sha256 of the bytecode, sha256 of
    the closure))`` to a data file (numba's ``_CacheImpl``/``IndexDataCacheFile``); the index is
    read and filtered, nothing is loaded or compiled.
    """
    try:
        index = dispatcher._cache._cache_file._load_index()
        magic = dispatcher.targetctx.codegen().magic_tuple()
    except (AttributeError, OSError, EOFError, ValueError):
        return None
    code = hashlib.sha256(dispatcher.py_func.__code__.co_code).hexdigest()
    try:
        return [key[0] for key in index if key[1] == magic and key[2][0] == code]
    except (TypeError, IndexError):
        return None


def flush_hdf5(file) -> None:
    """Flush the HDF5 file beneath the h5netcdf ``File`` ``file`` (h5netcdf's own ``flush``
    writes the netCDF attributes only).

    Raises
    ------
    PrivateAPIChanged
        h5netcdf's ``File`` has no ``_h5file`` with a ``flush()``.
    """
    try:
        flush = file._h5file.flush
    except AttributeError as error:
        raise _changed("h5netcdf", "File._h5file", error) from None
    flush()


@functools.cache
def banded_lapack():
    """SciPy's LAPACK wrappers (``dgbsv`` and the rest of ``scipy.linalg.lapack``'s double-precision
    routines), loaded from the extension module's file alone (module docstring); the public
    ``scipy.linalg.lapack`` where that file is not where SciPy keeps it.

    A later ``import scipy.linalg`` finds the same module (tests/kernels/test_private_api.py).
    """
    spec = importlib.util.find_spec("scipy")                       # finds, does not import, SciPy
    folder = os.path.join(os.path.dirname(spec.origin), "linalg") if spec and spec.origin else ""
    for suffix in importlib.machinery.EXTENSION_SUFFIXES:
        path = os.path.join(folder, "_flapack" + suffix)
        if os.path.isfile(path):
            module_spec = importlib.util.spec_from_file_location("scipy.linalg._flapack", path)
            module = importlib.util.module_from_spec(module_spec)
            module_spec.loader.exec_module(module)
            return module
    from scipy.linalg import lapack
    return lapack


def enable_disk_cache(dispatcher, directory: str) -> None:
    """Turn on numba's disk cache of ``dispatcher`` (made without ``cache=True``) in ``directory``.

    Raises
    ------
    PrivateAPIChanged
        numba's dispatcher has no ``enable_caching`` or its configuration no ``CACHE_DIR``.
    """
    from numba.core import config

    try:
        enable, chosen = dispatcher.enable_caching, config.CACHE_DIR
    except AttributeError as error:
        raise _changed("numba", "Dispatcher.enable_caching or config.CACHE_DIR", error) from None
    config.CACHE_DIR = directory
    try:
        enable()
    finally:
        config.CACHE_DIR = chosen


def dispatcher_type(dispatcher):
    """numba's type of the dispatcher ``dispatcher``: what a stand-in object gives as its
    ``_numba_type_``, which numba's ``typeof`` takes as the object's type (:class:`kanat.jit.Deferred`).

    Raises
    ------
    PrivateAPIChanged
        numba's dispatcher has no ``_numba_type_``.
    """
    try:
        return dispatcher._numba_type_
    except AttributeError as error:
        raise _changed("numba", "Dispatcher._numba_type_", error) from None


def named_tuple_type(item_types, kind: type):
    """numba's type of an instance of the named tuple class ``kind`` whose items have the numba
    types ``item_types``, as ``numba.typeof`` types one (a ``NamedTuple``, or a ``NamedUniTuple``
    where every item has one type), made without an instance.

    Raises
    ------
    PrivateAPIChanged
        numba's ``types.BaseTuple`` has no ``from_types`` taking the items' types and the class.
    """
    from numba.core import types

    try:
        from_types = types.BaseTuple.from_types
    except AttributeError as error:
        raise _changed("numba", "numba.core.types.BaseTuple.from_types", error) from None
    return from_types(tuple(item_types), kind)
