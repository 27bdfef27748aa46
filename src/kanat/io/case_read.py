"""Read a case file's text, turning every way that can fail into one clear problem.

A user error about the file itself (it is missing, a directory, unreadable, a binary or
UTF-16 file, far too large) is a :class:`~kanat.errors.Problem` naming the file, never a
traceback; :mod:`kanat.io.case_file` reports it like any other problem of the case.
"""
from __future__ import annotations

import os
import stat
from os import PathLike
from pathlib import Path as FilePath

from ..errors import Problem
from ..model import limits
from ..model._base import suggest


def _missing(path: FilePath) -> str:
    """Why a path does not exist, with the closest case file's name when there is one."""
    if path.is_symlink():
        return f"is a broken symbolic link (to {os.readlink(path)})"
    parent = path.parent
    if not parent.is_dir():
        return f"does not exist (no directory {parent})"
    try:
        names = sorted(p.name for p in parent.iterdir() if p.suffix in (".yaml", ".yml"))[:500]
    except OSError:
        names = []
    return f"does not exist{suggest(path.name, names)}"


def _stat_problem(path: FilePath) -> str | None:
    """Why ``path`` is not a readable regular file of sane size, or None."""
    try:
        info = path.stat()
    except FileNotFoundError:
        return _missing(path)
    except PermissionError:
        return "cannot be reached: permission denied on a directory in its path"
    except (OSError, ValueError) as exc:  # a NUL in the name, a name too long, a loop
        return f"cannot be opened: {getattr(exc, 'strerror', None) or exc}"
    if stat.S_ISDIR(info.st_mode):
        try:
            inside = sorted(p.name for p in path.iterdir() if p.suffix in (".yaml", ".yml"))
        except OSError:
            inside = []
        hint = f" (it holds {', '.join(inside[:5])}" + (", ...)" if len(inside) > 5 else ")") \
            if inside else ""
        return f"is a directory; give a YAML file{hint}"
    if not stat.S_ISREG(info.st_mode):
        return "is not a regular file (a device, pipe or socket); give a YAML case file"
    if info.st_size > limits.MAX_DOCUMENT_BYTES:
        return (f"is {info.st_size:,} bytes, more than the limit of "
                f"{limits.MAX_DOCUMENT_BYTES:,} for a case file (cases are a few kB)")
    return None


_SIGNATURES = {b"\x89HDF": "an HDF5/netCDF file (a result?)", b"CDF\x01": "a netCDF file",
               b"\xff\xfe": "UTF-16 text; save it as UTF-8", b"\xfe\xff": "UTF-16 text; save it "
               "as UTF-8", b"\x89PNG": "a PNG image", b"PK\x03\x04": "a zip archive",
               b"%PDF": "a PDF document"}


def _decode(raw: bytes) -> tuple[str | None, str | None, int | None]:
    """UTF-8 text of a file's bytes, or why not with the line of the first bad byte."""
    try:
        return raw.decode("utf-8"), None, None
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        kind = next((what for sig, what in _SIGNATURES.items() if raw.startswith(sig)), None)
        what = f"this looks like {kind}" if kind else "save it as UTF-8 text"
        return None, (f"not a UTF-8 text file (byte 0x{raw[exc.start]:02x} at line {line}, "
                      f"offset {exc.start}: {exc.reason}); {what}"), line


def read_case_text(path: str | PathLike[str]) -> tuple[str | None, list[Problem]]:
    """The text of a case file, or the one problem that stops it from being read.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    text : str or None
        The file's UTF-8 text; None when it cannot be read.
    problems : list of Problem
        Empty, or the one reason (with the file, and the line of a bad byte): a missing
        file (with the closest name beside it), a broken link, a directory (with the case
        files in it), a pipe or device, no permission, more than
        :data:`~kanat.model.limits.MAX_DOCUMENT_BYTES`, bytes that are not UTF-8 (naming a
        netCDF result, UTF-16 text or an image). Never raises.
    """
    file = os.fspath(path) if isinstance(path, (str, PathLike)) else str(path)
    where = FilePath(file)
    why = _stat_problem(where) if file else "is empty: give a case file"
    if why is None:
        try:
            with open(where, "rb") as handle:
                raw = handle.read(limits.MAX_DOCUMENT_BYTES + 1)
        except PermissionError:
            why = "cannot be read: permission denied (check its permissions, e.g. chmod u+r)"
        except OSError as exc:
            why = f"cannot be read: {exc.strerror or exc}"
    if why is not None:
        return None, [Problem("", f"the case file {why}", file, None)]
    if len(raw) > limits.MAX_DOCUMENT_BYTES:
        return None, [Problem("", f"the case file is more than {limits.MAX_DOCUMENT_BYTES:,} "
                              "bytes, the limit for a case file", file, None)]
    text, why, line = _decode(raw)
    if text is None:
        return None, [Problem("", why, file, line)]
    return text, []
