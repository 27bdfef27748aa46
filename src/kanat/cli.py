"""The ``kanat`` command line: verbs mapped to the package's functions, nothing else."""
from __future__ import annotations

import time
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.panel import Panel
from rich.table import Table

import kanat
from kanat.errors import CaseError, KanatError

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Statics and dynamics of marine cable systems.")
console = Console(stderr=True)
out = Console()


def _version(value: bool):
    if value:
        out.print(f"kanat {kanat.__version__}")
        raise typer.Exit()


@app.callback()
def main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                      help="Print the version and exit.")):
    """kanat: towed cables and bodies, moorings and cable networks."""


def _fail(error: Exception, debug: bool, title: str) -> None:
    """Explain a failure in one paragraph and exit non-zero (traceback only with --debug)."""
    if debug:
        raise error
    if isinstance(error, CaseError):
        _print_problems(error.problems)
        raise typer.Exit(1)
    if isinstance(error, KanatError):
        console.print(Panel(str(error), title=title, border_style="red", expand=False))
        raise typer.Exit(1)
    console.print(Panel(f"{type(error).__name__}: {error}\n\nThis is a bug in kanat; rerun with --debug "
                        "for the traceback and report it with the case file.",
                        title="internal error", border_style="red", expand=False))
    raise typer.Exit(2)


def _print_problems(problems) -> None:
    table = Table(show_header=True, header_style="bold", expand=False)
    for column in ("where", "key", "severity", "problem"):
        table.add_column(column, overflow="fold")
    for p in problems:
        where = f"{p.file or '<case>'}:{p.line}" if p.line else (p.file or "<case>")
        style = "red" if p.severity == "error" else "yellow"
        table.add_row(where, p.key, f"[{style}]{p.severity}[/{style}]", p.message)
    console.print(table)


@app.command()
def validate(case: Path = typer.Argument(..., help="YAML case file.")):
    """Check a case file and report every problem at once (exit 1 on errors)."""
    from kanat.io import check_case

    problems = check_case(case)
    if problems:
        _print_problems(problems)
    errors = sum(p.severity == "error" for p in problems)
    warnings = len(problems) - errors
    if errors:
        console.print(f"[red]{case}: {errors} error(s), {warnings} warning(s)[/red]")
        raise typer.Exit(1)
    out.print(f"{case}: valid ({warnings} warning(s))")


@app.command()
def statics(case: Path = typer.Argument(..., help="YAML case file."),
            output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
            plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the solution to this PNG."),
            method: str = typer.Option("auto", "--method",
                                       help="auto | shooting | collocation | catenary"),
            debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Solve the steady state of a case and write it to OUTPUT."""
    _statics(case, output, plot, method, debug)


@app.command()
def run(case: Path = typer.Argument(..., help="YAML case file."),
        output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
        plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the result to this PNG."),
        debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run any case (the model named in the case file) and write it to OUTPUT."""
    from kanat.io import load_case

    try:
        model = load_case(case).model
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "cannot read the case")
    if model != "statics":
        _fail(KanatError(f"{case}: model '{model}' is not available in kanat {kanat.__version__}; this "
                         "version solves 'statics' cases. To get the steady (initial) state of this case, "
                         f"run: kanat statics {case} -o OUT.nc"), debug, "model not available")
    _statics(case, output, plot, "auto", debug)


def _statics(case: Path, output: Path, plot: Optional[Path], method: str, debug: bool) -> None:
    from kanat.io import load_case
    from kanat.io.results import failed_dataset, statics_dataset, write_result
    from kanat.statics import solve_statics

    try:
        loaded = load_case(case)
        start = time.perf_counter()
        with console.status(f"solving statics of {case.name} ..."):
            result = solve_statics(loaded, method=method)
        write_result(statics_dataset(result, wall_time_s=time.perf_counter() - start), output)
    except KanatError as error:
        if not isinstance(error, CaseError) and "loaded" in locals():
            write_result(failed_dataset(loaded, str(error), scheme=method), output)
            console.print(f"[yellow]wrote {output}: no solution, its status says why[/yellow]")
        _fail(error, debug, "statics failed")
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "statics failed")
    out.print(result.summary())
    out.print(f"wrote {output}")
    if plot is not None:
        from kanat.report.statics_plot import plot_statics

        try:
            plot_statics(result, plot)
        except Exception as error:  # noqa: BLE001 - reported by _fail
            _fail(error, debug, "plot failed")
        out.print(f"wrote {plot}")
