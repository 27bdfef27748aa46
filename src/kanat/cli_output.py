"""The command line's two output streams, with rich built only where it shows.

Off a terminal (a pipe, a file, a CI log) a message is plain text, and rich's import (about
0.025 s of CPU, a tenth of ``kanat validate``) buys nothing there: :class:`Stream` writes such a
message itself, character for character what :meth:`rich.console.Console.print` writes off a
terminal (``tests/cli/test_cli_output_stream.py`` compares the two), and builds its rich console
on first need: a terminal, a table, a panel, a status line, a progress bar, a styled
:class:`rich.text.Text`, markup, or a character rich rewrites (a tab, a control code).
"""
from __future__ import annotations

import builtins
import os
import sys
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rich.console import Console

RICH_ENVIRONMENT = ("FORCE_COLOR", "TTY_COMPATIBLE", "DATABRICKS_RUNTIME_VERSION")
"""Variables under which rich may take a pipe for a terminal or write to a notebook
(:attr:`rich.console.Console.is_terminal`): with one of them set, rich itself decides."""
PLAIN_OPTIONS = {"markup": False, "emoji": False}
"""The print options a plain message needs (markup and emoji codes would rewrite its text)."""


def _plain(text: str) -> bool:
    """True if rich would write ``text`` as it is off a terminal: printable characters and
    line breaks only (rich strips control codes and expands tabs)."""
    return all(line.isprintable() for line in text.split("\n"))


def _may_need_rich(file) -> bool:
    """False only where :attr:`rich.console.Console.is_terminal` is certainly False and rich
    writes to ``file`` itself: not a tty, none of :data:`RICH_ENVIRONMENT` set, no IPython."""
    if any(name in os.environ for name in RICH_ENVIRONMENT) or hasattr(builtins, "get_ipython"):
        return True
    isatty = getattr(file, "isatty", None)
    try:
        return isatty is not None and bool(isatty())
    except ValueError:                    # a closed file: rich says "not a terminal" too
        return False


class Stream:
    """Standard output or standard error of the command line: :class:`rich.console.Console`'s
    ``print``, ``status``, ``is_terminal`` and ``quiet``, the console built on first need.

    Parameters
    ----------
    stderr : bool
        Write to standard error (else standard output), whichever object ``sys.stderr`` or
        ``sys.stdout`` is when something is written, as rich does.
    **options
        The rich console's options (``soft_wrap``, ``highlight``, ...).
    """

    def __init__(self, stderr: bool = False, **options: Any) -> None:
        self.stderr = stderr
        self.options = options
        self._quiet = False
        self._console: Console | None = None

    @property
    def file(self):
        """The stream written to now."""
        return sys.stderr if self.stderr else sys.stdout

    @property
    def rich(self) -> Console:
        """The rich console (built on first use, with this stream's ``quiet``)."""
        if self._console is None:
            from rich.console import Console

            self._console = Console(stderr=self.stderr, quiet=self._quiet, **self.options)
        return self._console

    @property
    def quiet(self) -> bool:
        """Print nothing (``--quiet``; rich also sets it on a broken pipe)."""
        return self._console.quiet if self._console is not None else self._quiet

    @quiet.setter
    def quiet(self, value: bool) -> None:
        self._quiet = value
        if self._console is not None:
            self._console.quiet = value

    @property
    def is_terminal(self) -> bool:
        """rich's :attr:`~rich.console.Console.is_terminal`, without rich where it can only be False."""
        if self._console is None and not _may_need_rich(self.file):
            return False
        return self.rich.is_terminal

    def print(self, *objects: Any, **options: Any) -> None:
        """:meth:`rich.console.Console.print`; one plain string printed with ``markup=False,
        emoji=False`` off a terminal is written here, with the line end rich adds."""
        text = objects[0] if len(objects) == 1 else None
        if (isinstance(text, str) and options.keys() <= {*PLAIN_OPTIONS, "highlight"}
                and all(options.get(key) == value for key, value in PLAIN_OPTIONS.items())
                and _plain(text) and not self.is_terminal):
            self._write(text + "\n", objects, options)
        else:
            self.rich.print(*objects, **options)

    def _write(self, text: str, objects: tuple, options: dict) -> None:
        """Write and flush as rich does; a broken pipe ends the process as rich ends it."""
        if self.quiet:
            return
        file = self.file
        try:
            file.write(text)
            file.flush()
        except UnicodeEncodeError:            # nothing written: rich raises it with its advice
            self.rich.print(*objects, **options)
        except BrokenPipeError:
            self.rich.on_broken_pipe()

    def status(self, *args: Any, **kwargs: Any):
        """:meth:`rich.console.Console.status` (a spinner on a terminal)."""
        return self.rich.status(*args, **kwargs)
