"""Free space on the disk a result goes to, checked before writing.

HDF5 does not survive a write that fails for want of space: h5py then reports every dataset
it cannot close as an ignored exception and may crash the process (SIGSEGV) when the file is
closed. Every writer of a result or a checkpoint therefore asks :func:`require_space` first,
with what it is about to write and a margin (:data:`SPACE_MARGIN`), and stops with an
:class:`~kanat.errors.OutputWriteError` (one sentence) while the file on disk is still whole.

What is written whole in one go (a report, a study's summary and records, an export) is
estimated first and refused by :func:`require_room` when the disk cannot hold it; a disk that
fills up all the same while it is written (another program writing there) raises an error
that :func:`is_disk_full` recognises, and :func:`kanat.io.outputs.atomic_path` turns it into
one :class:`~kanat.errors.OutputWriteError` after removing the partial file
(:func:`not_written`).
"""
from __future__ import annotations

import errno
import shutil
import sys
from pathlib import Path

from kanat.errors import OutputWriteError

SPACE_MARGIN = 1024**2
"""Bytes kept free beyond what a block or a checkpoint needs (HDF5 metadata, the rename)."""
NO_SPACE = (errno.ENOSPC, errno.EDQUOT)
"""The errors of a write for want of space: a full disk, an exhausted quota."""
NO_SPACE_WORDS = ("No space left on device", "Disk quota exceeded", "errno = 28", "errno = 122")
"""How those errors read in the messages of libraries that do not keep ``errno`` (HDF5 via h5py)."""


def _free_bytes(path: Path) -> float:
    """Free space where ``path`` is (or would be) [bytes]; infinite when it cannot be told."""
    try:
        return float(shutil.disk_usage(path.parent).free)
    except OSError:
        return float("inf")


def close_quietly(file) -> None:
    """Close an HDF5 file whose disk is full: h5py reports each dataset it fails to close as an
    ignored exception (a screenful of tracebacks for one cause, already reported)."""
    hook = sys.unraisablehook
    sys.unraisablehook = lambda unraisable: None
    try:
        file.close()
    except (OSError, RuntimeError, ValueError):
        pass
    finally:
        sys.unraisablehook = hook


def require_space(path: Path, needed: float, what: str) -> None:
    """Refuse to write ``needed`` bytes beside ``path`` when the disk has not that much to spare.

    Raises
    ------
    OutputWriteError
        Naming ``what`` would have been written and how much space is left.
    """
    free = _free_bytes(path)
    if free < needed + SPACE_MARGIN:
        raise OutputWriteError(f"the disk holding {path.parent} is full ({free / 1024**2:.1f} MiB free, "
                               f"{(needed + SPACE_MARGIN) / 1024**2:.1f} MiB needed for {what})")


def mebibytes(n_bytes: float) -> str:
    """A size in MiB to one decimal (``12.5 MiB``)."""
    return f"{n_bytes / 1024**2:.1f} MiB"


def require_room(path: Path, needed: float, what: str, advice: str) -> None:
    """Refuse, before anything is written, ``what`` whose estimated size ``needed`` [bytes] the disk
    holding ``path`` cannot take (with :data:`SPACE_MARGIN` to spare).

    Raises
    ------
    OutputWriteError
        One sentence: what was refused, its size, the free space, and ``advice``.
    """
    path = Path(path)
    free = _free_bytes(path)
    if free < needed + SPACE_MARGIN:
        raise OutputWriteError(f"{what} needs about {mebibytes(needed + SPACE_MARGIN)} but the disk holding "
                               f"{path.parent} has {mebibytes(free)} free: nothing was written; {advice}")


def is_disk_full(error: BaseException) -> bool:
    """True for an error of a write for want of space (:data:`NO_SPACE`), however the library
    that met it words it."""
    if isinstance(error, OSError) and error.errno in NO_SPACE:
        return True
    text = str(error)
    return isinstance(error, (OSError, RuntimeError)) and any(words in text for words in NO_SPACE_WORDS)


def not_written(target: Path) -> OutputWriteError:
    """The error for ``target`` whose write the disk filled up during (its partial file removed)."""
    target = Path(target)
    return OutputWriteError(f"{target} was not written: the disk holding {target.parent} filled up while it was "
                            f"written ({mebibytes(_free_bytes(target))} free now); the partial file was "
                            "removed, free some space and write it again")
