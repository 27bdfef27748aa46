"""Silencing a peer's console output in the benchmarks (MoorDyn-C prints its progress from C)."""
from __future__ import annotations

import contextlib
import os
import sys


@contextlib.contextmanager
def quiet():
    """Silence MoorDyn's console output (C-level stdout and stderr)."""
    sys.stdout.flush()
    saved = [os.dup(1), os.dup(2)]
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1), os.dup2(null.fileno(), 2)
        try:
            yield
        finally:
            os.dup2(saved[0], 1), os.dup2(saved[1], 2)
            [os.close(fd) for fd in saved]
