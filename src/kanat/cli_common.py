"""What every verb of the command line shares: consoles, logging, loading a case, failing well."""
from __future__ import annotations

import logging
import warnings
from pathlib import Path

import typer
from rich.console import Console
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

CONTEXT = {"help_option_names": ["-h", "--help"]}
"""Typer context settings of every command: ``-h`` is ``--help``."""
console = Console(stderr=True, soft_wrap=True)
"""Messages and progress (standard error)."""
out = Console(soft_wrap=True, highlight=False)
"""Results and tables (standard output); soft-wrapped: a pipe gets whole lines."""
log = logging.getLogger("kanat")


def setup_logging(quiet: bool = False, verbose: bool = False, log_file: Path | None = None) -> None:
    """Send the ``kanat`` logger to standard error through rich, and to ``log_file`` if given."""
    from rich.logging import RichHandler

    level = logging.ERROR if quiet else logging.DEBUG if verbose else logging.INFO
    log.handlers.clear()
    log.setLevel(min(level, logging.DEBUG) if log_file else level)
    handler = RichHandler(console=console, show_time=False, show_path=False, markup=False)
    handler.setLevel(level)
    log.addHandler(handler)
    if log_file is not None:
        to_file = logging.FileHandler(log_file)
        to_file.setFormatter(logging.Formatter("%(asctime)s %(levelname)s %(message)s"))
        log.addHandler(to_file)
    log.propagate = False


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
    """A red panel on a terminal; plain, unwrapped lines elsewhere (a log file, a pipe)."""
    if console.is_terminal:
        console.print(Panel(Text(text, overflow="fold"), title=title, border_style="red", expand=False))
    else:
        console.print(Text(f"{title}: {text}"))


def print_problems(problems) -> None:
    """A table of case problems: where, key, severity, what is wrong (one line each off a terminal)."""
    if not console.is_terminal:
        for p in problems:
            console.print(Text(str(p)))
        return
    table = Table(show_header=True, header_style="bold", expand=False)
    for column in ("where", "key", "severity", "problem"):
        table.add_column(column, overflow="fold")
    for p in problems:
        where = f"{p.file or '<case>'}:{p.line}" if p.line else (p.file or "<case>")
        style = "red" if p.severity == "error" else "yellow"
        table.add_row(Text(where), Text(p.key), Text(p.severity, style=style), Text(p.message))
    console.print(table)


MAX_OUTPUT_HELP = "Largest result a run may write, e.g. 8G (default: KANAT_MAX_OUTPUT_BYTES, else 2G)."


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
    return loaded
