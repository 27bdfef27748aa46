"""Free space on the disk a result goes to, checked before writing.

HDF5 does not survive a write that fails for want of space: h5py then reports every dataset
it cannot close as an ignored exception and may crash the process (SIGSEGV) when the file is
closed. Every writer of a result or a checkpoint therefore asks :func:`require_space` first,
with what it is about to write and a margin (:data:`SPACE_MARGIN`), and stops with an
:class:`~kanat.errors.OutputWriteError` (one sentence) while the file on disk is still whole.
"""
from __future__ import annotations

import shutil
import sys
from pathlib import Path

from kanat.errors import OutputWriteError

SPACE_MARGIN = 1024**2
"""Bytes kept free beyond what a block or a checkpoint needs (HDF5 metadata, the rename)."""


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
