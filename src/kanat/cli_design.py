"""The ``design`` verb of the ``kanat`` command line: :func:`kanat.design_checks.design`, its
tables written by :func:`kanat.design_checks.write_tables` and its page by
:func:`kanat.report.html_design.design_page`."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from kanat.cli_common import console, fail, load, log, show
from kanat.errors import KanatError


DESIGN_FAILS = 3     # exit status: a line or a fatigue life fails its check
NOT_CHECKED = 4      # exit status: a condition could not be checked (its runs failed)


def design_status(result) -> int:
    """The exit status of ``kanat design``: 0 when every check passes, :data:`NOT_CHECKED` when a
    condition could not be checked (whatever the others say: the answer is incomplete), else
    :data:`DESIGN_FAILS` when a check fails. A case that cannot be run at all exits 1, as every command."""
    if result.failures:
        return NOT_CHECKED
    return 0 if result.ok else DESIGN_FAILS


def register(app: typer.Typer) -> None:
    """Add the ``design`` verb to ``app``."""

    @app.command()
    def design(case: Path = typer.Argument(..., help="Mooring case with a design block (YAML)."),
               output: Path = typer.Option(..., "-o", "--output",
                                           help="Folder for utilisation.csv, fatigue.csv, report.html and "
                                                "the runs (resumed if it holds them)."),
               scheduler: Optional[str] = typer.Option(None, "--scheduler",
                                                       help="serial (default), a Dask scheduler address, or a "
                                                            "scheduler .json file."),
               workers: Optional[int] = typer.Option(None, "--workers",
                                                     help="Run on a local pool of this many worker processes."),
               debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
        """Design checks: utilisation of every line intact and damaged, fatigue life (docs/design.md).
        Exit status: 0 every check passes, 1 the case could not be run (as every command), 3 a line
        or a fatigue life fails its check, 4 a condition could not be checked (its runs failed)."""
        from kanat.design_checks import design as check, write_tables
        from rich.text import Text

        from kanat.report.html_design import design_page

        loaded = load(case, debug)
        try:
            result = check(loaded, output, progress=lambda text: console.print(Text(f"run {text}")), scheduler=scheduler,
                           workers=workers)
            paths = [*write_tables(result, output), design_page(result, output / "report.html")]
        except KanatError as error:
            fail(error, debug, "design check failed")
        for name, why in result.failures.items():
            log.warning(f"{name}: not checked: {why}")
        failing = result.utilisation[~result.utilisation["ok"].astype(bool)]
        log.info(f"runs on {result.engine}")
        show(f"{len(result.utilisation)} line checks, {len(failing)} failing; wrote "
             + ", ".join(str(p) for p in paths))
        raise typer.Exit(design_status(result))
