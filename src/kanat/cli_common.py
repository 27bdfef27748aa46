"""What every verb of the command line shares: consoles, logging, loading a case, failing well."""
from __future__ import annotations

import logging
import sys
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

import typer

from kanat.cli_output import Stream

if TYPE_CHECKING:
    from rich.text import Text

CONTEXT = {"help_option_names": ["-h", "--help"]}
"""Typer context settings of every command: ``-h`` is ``--help``."""
console = Stream(stderr=True, soft_wrap=True)
"""Messages and progress (standard error; rich built on first need, :mod:`kanat.cli_output`)."""
out = Stream(soft_wrap=True, highlight=False)
"""Results and tables (standard output); soft-wrapped: a pipe gets whole lines."""
log = logging.getLogger("kanat")

QUIET_HELP = ("Print only errors: no warnings, no summary, no 'wrote FILE' line; the exit status tells "
              "success (0). --log-file still receives everything.")
VERBOSE_HELP = "Also log what each step does (case, model, scheme, step, method, initial state)."
LOG_FILE_HELP = ("Also write the log to this file: every record from INFO up (DEBUG with -v), the summary "
                 "included, with timestamps; -q does not apply to it.")
LOG_FILE_FORMAT = "%(asctime)s %(levelname)s %(name)s: %(message)s"


class _PlainFormatter(logging.Formatter):
    """``kanat: warning: message`` on one line per line of the message (no wrapping, no padding)."""

    def format(self, record: logging.LogRecord) -> str:
        text = f"kanat: {record.levelname.lower()}: {record.getMessage()}"
        if record.exc_info:
            text += "\n" + self.formatException(record.exc_info)
        return text


class _Stderr(logging.StreamHandler):
    """A stream handler writing to whatever ``sys.stderr`` is when a record comes."""

    @property
    def stream(self):
        return sys.stderr

    @stream.setter
    def stream(self, value) -> None:
        """Ignored: the stream is always the current ``sys.stderr``."""


def _not_shown(record: logging.LogRecord) -> bool:
    """False for records the user has already seen (a summary line on standard output, an error
    panel): they go to the log file only."""
    return not getattr(record, "shown", False)


def setup_logging(quiet: bool = False, verbose: bool = False, log_file: Path | None = None) -> None:
    """Route the ``kanat`` logger (and its children, ``kanat.dynamics``, ...).

    Standard error shows warnings and errors (``verbose``: also INFO and DEBUG;
    ``quiet``: errors only, and standard output is silenced too). On a terminal it goes
    through rich; elsewhere (a pipe, a file, a CI log) as plain ``kanat: level: message``
    lines, never wrapped. ``log_file`` receives every record from INFO up (DEBUG with
    ``verbose``), the run summary included, whatever ``quiet`` says.
    """
    shown = logging.ERROR if quiet else logging.DEBUG if verbose else logging.WARNING
    for old in log.handlers:
        old.close()
    log.handlers.clear()
    out.quiet = quiet
    if console.is_terminal:
        from rich.logging import RichHandler

        handler: logging.Handler = RichHandler(console=console.rich, show_time=False, show_path=False, markup=False)
    else:
        handler = _Stderr()
        handler.setFormatter(_PlainFormatter())
    handler.setLevel(shown)
    handler.addFilter(_not_shown)
    log.addHandler(handler)
    level = shown
    if log_file is not None:
        kept = logging.DEBUG if verbose else logging.INFO
        to_file = logging.FileHandler(log_file, encoding="utf-8")
        to_file.setLevel(kept)
        to_file.setFormatter(logging.Formatter(LOG_FILE_FORMAT))
        log.addHandler(to_file)
        level = min(level, kept)
    log.setLevel(level)
    log.propagate = False


def show(text: str | Text) -> None:
    """Print a result line on standard output (nothing with ``--quiet``) and keep it in the log file."""
    out.print(text, markup=False, emoji=False)
    log.info(_plain_text(text), extra={"shown": True})


def _plain_text(text: str | Text) -> str:
    """The text of a rich :class:`~rich.text.Text` (rich is loaded if one exists), else ``text``."""
    if isinstance(text, str) or "rich.text" not in sys.modules:
        return text
    from rich.text import Text

    return text.plain if isinstance(text, Text) else text


def describe(case) -> str:
    """One line on a loaded case: its model, cables, segments, bodies, points, and scheme and step."""
    segments = sum(cable.segments for cable in case.cables)
    parts = [f"model {case.model}",
             f"{len(case.cables)} cable(s) of {segments} segment(s) in all",
             f"{len(case.bodies)} bod{'y' if len(case.bodies) == 1 else 'ies'}, {len(case.points)} point(s)"]
    sim = case.simulation
    if sim is not None:
        step = f"dt {sim.dt:g} s" if sim.dt is not None else "dt chosen by the model"
        parts.append(f"scheme {sim.scheme or 'the model default'}, {step}, duration {sim.duration:g} s")
    return f"case '{case.name}' is valid: " + "; ".join(parts)


def fail(error: Exception, debug: bool, title: str) -> None:
    """Explain a failure in one paragraph and exit non-zero (traceback only with ``--debug``)."""
    from kanat.errors import CaseError, KanatError

    if debug:
        raise error
    if isinstance(error, CaseError):
        print_problems(error.problems)
        raise typer.Exit(1)
    if isinstance(error, KanatError):
        _explain(str(error), title)
        raise typer.Exit(1)
    _explain(f"{type(error).__name__}: {error}\n\nThis is a bug in kanat; rerun with --debug for the traceback "
             "and report it with the case file.", "internal error")
    raise typer.Exit(2)


def _explain(text: str, title: str) -> None:
    """A red panel on a terminal, a plain unwrapped ``kanat: error: TITLE: ...`` elsewhere (a pipe, a
    CI log); the log file keeps it either way."""
    if console.is_terminal:
        from rich.panel import Panel
        from rich.text import Text

        console.print(Panel(Text(text, overflow="fold"), title=title, border_style="red", expand=False))
    else:
        console.print(f"kanat: error: {title}: {text}", markup=False, emoji=False, highlight=False)
    if log.handlers:                            # set up by the command line: the log file keeps it
        log.error(f"{title}: {text}", extra={"shown": True})


def print_problems(problems) -> None:
    """A table of case problems: where, key, severity, what is wrong (one line each off a terminal);
    errors only with ``--quiet``."""
    if out.quiet:
        problems = [p for p in problems if p.severity == "error"]
    if not problems:
        return
    if not console.is_terminal:
        for p in problems:
            console.print(str(p), markup=False, emoji=False, highlight=False)
        return
    from rich.table import Table
    from rich.text import Text

    table = Table(show_header=True, header_style="bold", expand=False)
    for column in ("where", "key", "severity", "problem"):
        table.add_column(column, overflow="fold")
    for p in problems:
        where = f"{p.file or '<case>'}:{p.line}" if p.line else (p.file or "<case>")
        style = "red" if p.severity == "error" else "yellow"
        table.add_row(Text(where), Text(p.key), Text(p.severity, style=style), Text(p.message))
    console.print(table)


MAX_OUTPUT_HELP = "Largest result a run may write, e.g. 8G (default: KANAT_MAX_OUTPUT_BYTES, else 2G)."
MAX_NODE_STEPS_HELP = ("Largest run allowed, in node-steps (time steps x nodes), e.g. 1e11 (default: "
                       "KANAT_MAX_NODE_STEPS, else 2e10: half an hour to a day of computing).")


def set_max_node_steps(value: float | None) -> None:
    """``--max-node-steps``: the limit for this command, through the environment variable the case
    checks and the models read (:func:`kanat.model.limits.max_node_steps`)."""
    import os

    from kanat.model import limits

    if value is not None:
        os.environ[limits.NODE_STEPS_ENV] = repr(float(value))


def load(case: Path, debug: bool, max_output: str | None = None, solver: str | None = None):
    """Load a case, logging its warnings; explain and exit if it cannot be read. ``solver``:
    check what that model supports instead of the case's own (``kanat statics``)."""
    from kanat.api import load_case

    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            loaded = load_case(case, max_output_bytes=max_output, solver=solver)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "cannot read the case")
    for warning in caught:
        log.warning(str(warning.message))
    log.info(f"{case}: {describe(loaded)}")
    return loaded
