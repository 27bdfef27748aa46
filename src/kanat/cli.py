"""The ``kanat`` command line: verbs mapped to the package's functions, nothing else."""
from __future__ import annotations

import time
from pathlib import Path
from typing import Optional

import typer
from rich.console import Console
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

import kanat
from kanat.errors import CaseError, KanatError

RUNNERS = {"continuum": "kanat.continuum.run", "lumped": "kanat.lumped"}
"""Dynamic models by name: the module whose ``run(case, output, ...)`` runs them."""

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
        console.print(Panel(Text(str(error), overflow="fold"), title=title, border_style="red", expand=False))
        raise typer.Exit(1)
    console.print(Panel(Text(f"{type(error).__name__}: {error}\n\nThis is a bug in kanat; rerun with --debug "
                             "for the traceback and report it with the case file.", overflow="fold"),
                        title="internal error", border_style="red", expand=False))
    raise typer.Exit(2)


def _print_problems(problems) -> None:
    table = Table(show_header=True, header_style="bold", expand=False)
    for column in ("where", "key", "severity", "problem"):
        table.add_column(column, overflow="fold")
    for p in problems:
        where = f"{p.file or '<case>'}:{p.line}" if p.line else (p.file or "<case>")
        style = "red" if p.severity == "error" else "yellow"
        table.add_row(Text(where), Text(p.key), Text(p.severity, style=style), Text(p.message))
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
    _statics(_load(case, debug), case, output, plot, method, debug)


@app.command()
def run(case: Path = typer.Argument(..., help="YAML case file."),
        output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
        plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the result to this PNG."),
        scheme: Optional[str] = typer.Option(None, "--scheme", help="Override simulation.scheme."),
        resume: bool = typer.Option(False, "--resume", help="Continue a killed run from its checkpoint."),
        checkpoint_every: Optional[int] = typer.Option(None, "--checkpoint-every",
                                                       help="Checkpoint every N output steps."),
        debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run any case (the model named in the case file) and write it to OUTPUT as it goes."""
    loaded = _load(case, debug)
    if loaded.model == "statics":
        _statics(loaded, case, output, plot, "auto", debug)
        return
    if loaded.model == "pitch":
        _pitch(loaded, output, plot, debug)
        return
    runners = RUNNERS
    if loaded.model not in runners:
        _fail(KanatError(f"{case}: model '{loaded.model}' is not available in kanat {kanat.__version__} "
                         f"(available: statics, {', '.join(runners)}). To get the steady (initial) state of "
                         f"this case, run: kanat statics {case} -o OUT.nc"), debug, "model not available")
    import importlib

    runner = importlib.import_module(runners[loaded.model])
    try:
        summary = _with_progress(loaded.simulation.duration, lambda progress: runner.run(
            loaded, output, scheme=scheme, resume=resume, progress=progress, checkpoint_every=checkpoint_every))
    except KeyboardInterrupt:
        console.print(f"[yellow]interrupted; {output} keeps what was computed; continue with --resume[/yellow]")
        raise typer.Exit(130)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "run failed")
    if not summary.ok:
        _fail(KanatError(f"{summary.status}\n\nThe results up to the failure are in {output}."), debug,
              "run stopped")
    out.print(summary.summary())
    out.print(f"wrote {output}")
    if plot is not None:
        from kanat.io.results import read_result
        from kanat.report.run_plot import plot_run

        plot_run(read_result(output), plot)
        out.print(f"wrote {plot}")


def _with_progress(duration: float, start):
    """Run ``start(progress)`` under a progress bar of simulated time, wall time and Newton iterations."""
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    columns = (TextColumn("t = {task.completed:.1f} / {task.total:g} s"), BarColumn(), TimeElapsedColumn(),
               TextColumn("{task.fields[info]}"))
    with Progress(*columns, console=console, transient=True) as bar:
        task = bar.add_task("run", total=duration, info="")

        def progress(t, info):
            text = f"Newton {info['newton_iterations']:.2f}/step" if "newton_iterations" in info else ""
            bar.update(task, completed=t, info=text)
        return start(progress)


@app.command()
def pitch(case: Path = typer.Argument(..., help="YAML case file with a pitch block."),
          output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
          plot: Optional[Path] = typer.Option(None, "--plot",
                                              help="Directory for the figures (or a PNG for fig. 2)."),
          debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Ship pitch with the reactive stabilizer (seed 003): steady pitch per control mode."""
    _pitch(_load(case, debug), output, plot, debug)


@app.command("pitch-tow")
def pitch_tow(case: Path = typer.Argument(..., help="Continuum tow case with a vessel.pitch block."),
              output: Path = typer.Option(..., "-o", "--output", help="Directory for results and the plot."),
              debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Tow through the vessel's pitch once per stabilizer mode; print the top-tension statistics."""
    from kanat.vessel.coupled import compare_modes

    loaded = _load(case, debug)
    try:
        with console.status("running the tow once per stabilizer mode ..."):
            table = compare_modes(loaded, output)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "coupled run failed")
    typer.echo(table)


@app.command()
def stability(case: Path = typer.Argument(..., help="YAML continuum case."),
              scheme: str = typer.Option(..., "--scheme", help="Scheme to sweep (e.g. wave-factorized)."),
              output: Optional[Path] = typer.Option(None, "-o", "--output", help="netCDF of the sweep."),
              plot: Optional[Path] = typer.Option(None, "--plot", help="Stability map (PNG)."),
              dts: Optional[str] = typer.Option(None, "--dt", help="Comma-separated time steps [s]."),
              debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run a case over a range of time steps: CFL numbers, bounded or not, error against a reference."""
    from kanat.continuum.stability import default_steps, stability_sweep, summary

    loaded = _load(case, debug)
    try:
        steps = [float(v) for v in dts.split(",")] if dts else default_steps(loaded)
        with console.status(f"sweeping {len(steps)} time steps ..."):
            ds = stability_sweep(loaded, scheme, steps)
        if output is not None:
            from kanat.io.results import write_result

            write_result(ds, output)
        if plot is not None:
            from kanat.report.stability_plot import plot_stability_map

            plot_stability_map(ds, plot)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "stability sweep failed")
    typer.echo(summary(ds))


def _pitch(loaded, output: Path, plot: Optional[Path], debug: bool) -> None:
    from kanat.vessel.pitch import run_pitch_case

    try:
        with console.status("solving the pitch steady state ..."):
            _, table = run_pitch_case(loaded, output, plot)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "pitch failed")
    typer.echo(table)
    out.print(f"wrote {output}" + (f" and figures at {plot}" if plot is not None else ""))


@app.command("compare-schemes")
def compare_schemes(case: Path = typer.Argument(..., help="YAML continuum case."),
                    output: Path = typer.Option(..., "-o", "--output", help="Directory for the result files."),
                    debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run a continuum case with box, backward Euler, generalized trapezoidal and generalized-α
    against a fine reference, and print seed 002's comparison table."""
    from kanat.continuum.compare import compare_schemes as compare, table

    loaded = _load(case, debug)
    try:
        with console.status("running every scheme and a fine reference ..."):
            rows = compare(loaded, output)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "comparison failed")
    typer.echo(table(rows))


def _load(case: Path, debug: bool):
    """Load a case, printing its warnings in yellow; explain and exit if it cannot be read."""
    import warnings

    from kanat.io import load_case

    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            loaded = load_case(case)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "cannot read the case")
    for warning in caught:
        console.print(Text(str(warning.message), style="yellow", overflow="fold"))
    return loaded


def _statics(loaded, case: Path, output: Path, plot: Optional[Path], method: str, debug: bool) -> None:
    from kanat.io.results import failed_dataset, statics_dataset, write_result
    from kanat.statics import solve_statics

    try:
        start = time.perf_counter()
        with console.status(f"solving statics of {case.name} ..."):
            result = solve_statics(loaded, method=method)
        write_result(statics_dataset(result, wall_time_s=time.perf_counter() - start), output)
        if plot is not None:
            from kanat.report.statics_plot import plot_statics

            plot_statics(result, plot)
    except KanatError as error:
        if not isinstance(error, CaseError):
            write_result(failed_dataset(loaded, str(error), scheme=method), output)
            console.print(f"[yellow]wrote {output}: no solution, its status says why[/yellow]")
        _fail(error, debug, "statics failed")
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "statics failed")
    out.print(result.summary())
    out.print(f"wrote {output}" + (f" and {plot}" if plot is not None else ""))


from kanat.cli_study import register  # noqa: E402 - the study verbs: sweep, report, validate-suite

register(app)


if __name__ == "__main__":  # python -m kanat.cli
    app()
