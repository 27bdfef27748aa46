"""The study verbs of the ``kanat`` command line: ``sweep``, ``report``, ``validate-suite``.

``kanat.cli`` calls :func:`register` to add them to its Typer app. Each verb maps to one
function of the package (:func:`kanat.sweep.sweep`, :func:`kanat.report.html_report.write_report`,
:func:`kanat.validation.run_suite`), nothing else.
"""
from __future__ import annotations

from pathlib import Path
from typing import List, Optional

import typer
from rich.console import Console
from rich.panel import Panel
from rich.text import Text

from kanat.errors import CaseError, KanatError

console = Console(stderr=True)
out = Console()


def _fail(error: Exception, debug: bool, title: str) -> None:
    """Explain a failure in one paragraph and exit non-zero (traceback only with --debug)."""
    if debug:
        raise error
    known = isinstance(error, (KanatError, CaseError))
    text = str(error) if known else (f"{type(error).__name__}: {error}\n\nThis is a bug in kanat; rerun with "
                                     "--debug for the traceback and report it.")
    console.print(Panel(Text(text, overflow="fold"), title=title, border_style="red", expand=False))
    raise typer.Exit(1 if known else 2)


def parse_window(text: Optional[str]):
    """``"100:600"`` -> (100.0, 600.0); either side may be empty (``"100:"``)."""
    if not text:
        return None
    start, sep, end = text.partition(":")
    try:
        if not sep:
            raise ValueError
        return (float(start) if start.strip() else None, float(end) if end.strip() else None)
    except ValueError:
        raise KanatError(f"--window '{text}': write START:END in seconds, e.g. 100:600 or 100:") from None


def parse_vary(items: List[str]) -> dict:
    """``["KEY=VALUES", ...]`` -> ``{KEY: "VALUES"}`` (values parsed by :mod:`kanat.sweep.values`)."""
    vary = {}
    for item in items:
        key, sep, values = item.partition("=")
        if not sep or not key.strip():
            raise KanatError(f"--vary '{item}': write KEY=VALUES, e.g. environment.waves.period=5:8:1 or "
                             "vessel.track[1].to_speed_kn=4,6,8")
        if key.strip() in vary:
            raise KanatError(f"--vary {key.strip()} is given twice; give all its values at once")
        vary[key.strip()] = values
    return vary


def sweep(case: Path = typer.Argument(..., help="Base case file (YAML)."),
          vary: List[str] = typer.Option(..., "--vary", help="KEY=VALUES: 4,6,8 | 4:8:2 | linspace(a,b,n) | "
                                         "uniform(a,b,n,seed) | normal(mean,std,n,seed). Repeat per key."),
          output: Path = typer.Option(..., "-o", "--output", help="Study directory (resumed if it exists)."),
          scheduler: Optional[str] = typer.Option(None, "--scheduler",
                                                  help="Dask scheduler address, or 'serial' (default: local cluster)."),
          workers: Optional[int] = typer.Option(None, "--workers", help="Local cluster worker processes."),
          window: Optional[str] = typer.Option(None, "--window", help="START:END of the summary statistics [s]."),
          report: Optional[Path] = typer.Option(None, "--report", help="Also write the study's HTML report."),
          debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run a parameter study: every combination of the varied values, one result file per case."""
    from kanat.sweep import sweep as run_sweep

    try:
        result = run_sweep(case, parse_vary(vary), output, scheduler=scheduler, workers=workers, progress=True,
                           window=parse_window(window))
    except KeyboardInterrupt:
        console.print(f"[yellow]interrupted; rerun the same command to resume {output}[/yellow]")
        raise typer.Exit(130) from None
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "study failed to start")
    out.print(f"{result.total} cases in {result.out_dir}: {result.ran} run now, {result.skipped} already done, "
              f"{result.failed} failed; summary: {result.out_dir / 'summary.nc'}")
    if result.failed:
        summary = result.summary
        for name, status, message in zip(summary["name"].values, summary["status"].values, summary["message"].values):
            if status != "ok":
                console.print(Text(f"failed {name}: {str(message).splitlines()[0][:300]}", style="red"))
    if report is not None:
        _report(output, report, None, None, debug)


def _report(source: Path, output: Path, nodes, window, debug: bool, bodies=None) -> None:
    from kanat.report.html_report import write_report

    try:
        with console.status(f"writing the report of {source} ..."):
            path = write_report(source, output, nodes=nodes, window=window, bodies=bodies)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "report failed")
    out.print(f"wrote {path} ({path.stat().st_size / 1e6:.1f} MB)")


def report(source: Path = typer.Argument(..., help="Result file (.nc) or study directory."),
           output: Path = typer.Option(..., "-o", "--output", help="HTML file."),
           node: Optional[List[str]] = typer.Option(None, "--node", help="Node index or CABLE@S (repeat)."),
           body: Optional[List[str]] = typer.Option(None, "--body", help="Body name (repeat; default all)."),
           window: Optional[str] = typer.Option(None, "--window", help="START:END of the statistics [s]."),
           debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Write one self-contained HTML page (offline, interactive) for a result or a study."""
    try:
        span = parse_window(window)
    except KanatError as error:
        _fail(error, debug, "report failed")
    _report(source, output, node or None, span, debug, body or None)


def validate_suite(output: Path = typer.Option(..., "-o", "--output", help="HTML file."),
                   only: Optional[List[str]] = typer.Option(None, "--only", help="Run only these check ids."),
                   debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run the fast validation cases of SPEC §7 and write their report (exit 1 if any fails)."""
    from kanat.validation import run_suite, write_validation_report

    try:
        with console.status("running the validation suite ..."):
            results = run_suite(only)
        path = write_validation_report(results, output)
    except Exception as error:  # noqa: BLE001 - reported by _fail
        _fail(error, debug, "validation suite failed")
    for r in results:
        style = "green" if r.passed else "red"
        out.print(Text(f"{'pass' if r.passed else 'FAIL'}  {r.check_id:<28} {r.measured_text}", style=style))
    failed = sum(not r.passed for r in results)
    out.print(f"{len(results) - failed}/{len(results)} checks pass; wrote {path}")
    if failed:
        raise typer.Exit(1)


def register(app: typer.Typer) -> None:
    """Add ``sweep``, ``report`` and ``validate-suite`` to the ``kanat`` app."""
    app.command("sweep")(sweep)
    app.command("report")(report)
    app.command("validate-suite")(validate_suite)
