"""The kernels compiled at install, kept per machine: compiled once, copied by every later install.

``pip install -e ".[plot]"`` and then ``pip install -e ".[test]"`` build the package twice; the
extension modules of :data:`kanat.aot.MODULES` are the same both times (the same kernel sources,
compiled by the same numba for the same Python), and compiling them takes minutes. ``setup.py``
therefore looks for them first in a user cache directory, under a key made of everything the
machine code depends on (:func:`key`), and stores what it compiles there for the next install.

Where: ``$KANAT_KERNEL_CACHE`` when set (``0`` turns the cache off), else
``$XDG_CACHE_HOME/kanat/kernels``, else ``~/.cache/kanat/kernels``; one directory per key, the
:data:`KEEP` most recently used kept. A cache that cannot be read or written is skipped with a
warning: the install compiles in place as it would without one.

Imported by ``setup.py`` and the tests only; it imports no numba.
"""
from __future__ import annotations

import hashlib
import json
import os
import platform
import shutil
import sys
import sysconfig
import tempfile
import time
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Callable, Iterable

from kanat import aot

ENVIRONMENT = "KANAT_KERNEL_CACHE"
"""The environment variable naming the cache directory (``0``: no cache)."""
FORMAT = 1
"""The layout of a cache entry; raised when it changes, which retires every entry."""
KEEP = 4
"""Entries kept: the most recently used (about 5.5 MB each)."""
BUILT = "key.json"
"""The file of an entry that names what its key was made of (written last: an entry without it
is incomplete and never used)."""


def root() -> Path | None:
    """The cache directory (module docstring), or None when ``$KANAT_KERNEL_CACHE`` is ``0``."""
    chosen = os.environ.get(ENVIRONMENT)
    if chosen == "0":
        return None
    if chosen:
        return Path(chosen)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "kanat" / "kernels"


def _version(package: str) -> str:
    try:
        return version(package)
    except PackageNotFoundError:
        return "none"


def ingredients(package: Path | None = None) -> dict:
    """What the machine code depends on: the kernel sources (:func:`kanat.aot.fingerprint` of
    :data:`kanat.aot.SOURCES` in ``package``, default this package), the compiler (numba,
    llvmlite), NumPy's headers, the Python ABI and the platform."""
    return {"format": FORMAT, "sources": aot.fingerprint(package), "numba": _version("numba"),
            "llvmlite": _version("llvmlite"), "numpy": _version("numpy"), "python": sys.version,
            "abi": sysconfig.get_config_var("EXT_SUFFIX") or "", "platform": sysconfig.get_platform(),
            "machine": platform.machine()}


def key(package: Path | None = None) -> str:
    """The cache key of the kernels of ``package`` compiled here: a digest of :func:`ingredients`."""
    text = json.dumps(ingredients(package), sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:20]


def _warn(message: str) -> None:
    print(f"warning: {message}", file=sys.stderr)


def restore(entry: Path, targets: Iterable[Path]) -> list[Path]:
    """Copy the files of the cache ``entry`` named like ``targets`` onto them; the targets copied.

    An incomplete entry (no :data:`BUILT`) or one that cannot be read gives nothing.
    """
    if not (entry / BUILT).is_file():
        return []
    copied = []
    for target in targets:
        cached = entry / Path(target).name
        try:
            if cached.is_file():
                Path(target).parent.mkdir(parents=True, exist_ok=True)
                _copy_whole(cached, Path(target))
                copied.append(Path(target))
        except OSError as error:
            _warn(f"the compiled kernel {cached} was not copied ({error}); compiling it")
    if copied:
        os.utime(entry / BUILT)                                # recently used: kept by prune()
    return copied


def _copy_whole(source: Path, target: Path) -> None:
    """Copy ``source`` to ``target`` whole (:func:`_write_whole`)."""
    _write_whole(target, lambda partial: shutil.copy2(source, partial))


def _write_whole(target: Path, fill) -> None:
    """Write ``target`` through a partial file in the same folder (``fill(path)`` writes it), then
    rename it over the name: a reader never sees half a file, and a process that has the old
    ``target`` loaded (a run going on while an install restores its kernels) keeps its own copy
    instead of having it rewritten under it."""
    handle, partial = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.")
    os.close(handle)
    try:
        fill(partial)
        os.replace(partial, target)
    finally:
        if os.path.exists(partial):
            os.unlink(partial)


def store(entry: Path, built: Iterable[Path], described: dict) -> bool:
    """Copy the ``built`` files into the cache ``entry`` (each written whole, then renamed, so a
    concurrent install never reads half a file), then its :data:`BUILT` file; whether it could."""
    try:
        entry.mkdir(parents=True, exist_ok=True)
        for path in built:
            _copy_whole(Path(path), entry / Path(path).name)
        text = json.dumps(described, indent=1, sort_keys=True)
        _write_whole(entry / BUILT, lambda partial: Path(partial).write_text(text))
    except OSError as error:
        _warn(f"the compiled kernels were not cached in {entry} ({error}); the next install compiles them again")
        return False
    prune(entry.parent)
    return True


def prune(directory: Path, keep: int = KEEP) -> None:
    """Remove all but the ``keep`` most recently used entries of the cache ``directory``."""
    try:
        entries = sorted((path for path in directory.iterdir() if (path / BUILT).is_file()),
                         key=lambda path: (path / BUILT).stat().st_mtime, reverse=True)
    except OSError:
        return
    for old in entries[keep:]:
        shutil.rmtree(old, ignore_errors=True)


def build_once(targets: Iterable[Path], build: Callable[[list[Path]], list[Path]],
               package: Path | None = None) -> dict:
    """Make the files ``targets`` (the extension modules, where the build puts them): copied
    from the cache entry of :func:`key` when it has them, else by ``build(missing)``, which
    returns those it made, then stored for the next install.

    Returns
    -------
    dict
        ``{"key", "copied", "built", "seconds"}``: the entry's key (None without a cache), the
        targets copied and built, and the seconds spent.
    """
    start = time.perf_counter()
    targets = [Path(target) for target in targets]
    directory = root()
    described = ingredients(package)
    name = key(package)
    entry = None if directory is None else directory / name
    copied = [] if entry is None else restore(entry, targets)
    missing = [target for target in targets if target not in copied]
    built = build(missing) if missing else []
    if entry is not None and built:
        store(entry, built, described)
    return {"key": None if entry is None else name, "copied": copied, "built": built,
            "seconds": time.perf_counter() - start}
