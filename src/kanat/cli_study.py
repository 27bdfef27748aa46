"""The study verbs of the ``kanat`` command line: ``study``, ``sweep``, ``report``, ``validate-suite``.

``kanat.cli`` calls :func:`register` to add them to its Typer app. Each verb maps to one
function of the package (:mod:`kanat.studies`, :func:`kanat.sweep.sweep`,
:func:`kanat.report.html_report.write_report`, :func:`kanat.validation.run_suite`) and
draws its pictures with :mod:`kanat.report`, nothing else.
"""
from __future__ import annotations

from pathlib import Path
from typing import List, Optional

import typer

from kanat.cli_common import CONTEXT, console, fail, load, log, show
from kanat.errors import KanatError

study = typer.Typer(no_args_is_help=True, rich_markup_mode=None, context_settings=CONTEXT,
                    help="The source papers' studies: Kaliukh & Vusatiuk 2018, Zhang, Zhang & Liu 2012 and Bezverkhyi 2006 comparisons, stability, Gaisha's "
                         "pitch, pitch-tow.")
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
                                                  help="serial, a Dask scheduler address, or a scheduler .json file "
                                                       "(default: serial, or a local pool when it pays)."),
          workers: Optional[int] = typer.Option(None, "--workers",
                                                help="Always start a local pool of this many worker processes."),
          window: Optional[str] = typer.Option(None, "--window", help="START:END of the summary statistics [s]."),
          report: Optional[Path] = typer.Option(None, "--report", help="Also write the study's HTML report."),
          debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run a parameter study: every combination of the varied values, one result file per case."""
    from rich.text import Text

    from kanat.io.outputs import check_output_file
    from kanat.report.html_report import report_inputs
    from kanat.sweep import sweep as run_sweep

    try:
        if report is not None:
            check_output_file(report, inputs=[case, *report_inputs(output)], flag="--report", example="study.html")
        result = run_sweep(case, parse_vary(vary), output, scheduler=scheduler, workers=workers, progress=True,
                           window=parse_window(window))
    except KeyboardInterrupt:
        log.warning(f"interrupted; rerun the same command to resume {output}")
        raise typer.Exit(130) from None
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "study failed to start")
    show(f"{result.total} cases in {result.out_dir}: {result.ran} run now, {result.skipped} already done, "
              f"{result.failed} failed; summary: {result.out_dir / 'summary.nc'}")
    show(f"engine: {result.engine}")
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
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "report failed")
    show(f"wrote {path} ({path.stat().st_size / 1e6:.1f} MB)")


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
        fail(error, debug, "report failed")
    _report(source, output, node or None, span, debug, body or None)


def validate_suite(output: Path = typer.Option(..., "-o", "--output", help="HTML file."),
                   only: Optional[List[str]] = typer.Option(None, "--only", help="Run only these check ids."),
                   debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run the fast validation cases and write their report (exit 1 if any fails)."""
    from rich.text import Text

    from kanat.io.outputs import check_output_file
    from kanat.report.html_validation import validation_report as write_validation_report
    from kanat.validation import run_suite

    try:
        check_output_file(output, example="validation.html")
        with console.status("running the validation suite ..."):
            results = run_suite(only)
        path = write_validation_report(results, output)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "validation suite failed")
    for r in results:
        style = "green" if r.passed else "red"
        show(Text(f"{'pass' if r.passed else 'FAIL'}  {r.check_id:<28} {r.measured_text}", style=style))
    failed = sum(not r.passed for r in results)
    show(f"{len(results) - failed}/{len(results)} checks pass; wrote {path}")
    if failed:
        raise typer.Exit(1)


@study.command("factorization")
def factorization(comparison: str = typer.Argument(..., help="accel | planar80 | spatial100"),
            output: Path = typer.Option(Path("."), "-o", "--output", help="Folder for the table and the figure."),
            case: Optional[Path] = typer.Option(None, "--case", help="Case file (default examples/factorization_*)."),
            debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Kaliukh & Vusatiuk's comparisons of the full and the factorized schemes (tables and figures)."""
    import numpy as np
    import pandas as pd

    from kanat.report.stability_plot import plot_accel, plot_planar80, plot_spatial100
    from kanat.studies import factorization as study000

    if comparison not in ("accel", "planar80", "spatial100"):
        fail(KanatError(f"unknown comparison '{comparison}'; choose accel, planar80 or spatial100"), debug,
             "Kaliukh & Vusatiuk 2018")
    output.mkdir(parents=True, exist_ok=True)
    pd.set_option("display.width", 200)
    pd.set_option("display.max_columns", 30)
    try:
        with console.status(f"running Kaliukh & Vusatiuk's {comparison} comparison ..."):
            if comparison == "spatial100":
                table, history = study000.spatial100(path=case)
            else:
                table = getattr(study000, comparison)(path=case)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "Kaliukh & Vusatiuk 2018 comparison failed")
    table.to_csv(output / f"factorization_{comparison}.csv", index=False)
    if comparison == "accel":
        plot_accel(table, output / "factorization_accel.png")
        show(table[np.isclose(table.time % 1.0, 0.0)].pivot(index="time", columns="scheme",
                                                            values=["distance", "depth"]).round(4).to_string())
    elif comparison == "planar80":
        plot_planar80(table, output / "factorization_planar80.png")
        show(table.round(4).to_string(index=False))
        show(f"speed-up of the wave-factorized scheme: {table.attrs['speedup']}")
    else:
        history.to_csv(output / "factorization_spatial100_history.csv", index=False)
        plot_spatial100(table, history, output / "factorization_spatial100.png")
        show(table.T.round(4).to_string())
        show(history[np.isclose(history.time % 10.0, 0.0)].round(5).to_string(index=False))
    if "wall_time_s" in table.attrs:
        show(f"solver time [s]: { {k: round(v, 2) for k, v in table.attrs['wall_time_s'].items()} }")
    show(f"wrote {output}")


@study.command("compare-schemes")
def compare_schemes(case: Path = typer.Argument(..., help="Continuum case file."),
                    output: Path = typer.Option(..., "-o", "--output", help="Directory for the result files."),
                    debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Zhang, Zhang & Liu 2012: box, backward Euler, generalized trapezoidal and generalized-α against a fine reference."""
    from kanat.studies.scheme_comparison import compare_schemes as compare, table

    loaded = load(case, debug)
    try:
        with console.status("running every scheme and a fine reference ..."):
            rows = compare(loaded, output)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "comparison failed")
    show(table(rows))


@study.command("stability")
def stability(case: Path = typer.Argument(..., help="Continuum case file."),
              scheme: str = typer.Option(..., "--scheme", help="Scheme to sweep (e.g. wave-factorized)."),
              output: Optional[Path] = typer.Option(None, "-o", "--output", help="netCDF of the sweep."),
              plot: Optional[Path] = typer.Option(None, "--plot", help="Stability map (PNG)."),
              dts: Optional[str] = typer.Option(None, "--dt", help="Comma-separated time steps (s)."),
              debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run a case over a range of time steps: Courant numbers, bounded or not, error against a reference."""
    from kanat.studies.stability import default_steps, stability_sweep, summary

    loaded = load(case, debug)
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
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "stability sweep failed")
    show(summary(ds))


@study.command("trawl")
def trawl(cases: List[Path] = typer.Argument(..., help="Bezverkhyi 2006 case files (examples/trawl_*.yaml)."),
            output: Path = typer.Option(..., "-o", "--output", help="Folder for .nc, .png and .md."),
            reuse: bool = typer.Option(False, "--reuse", help="Reuse DIR/<case>.nc when it exists."),
            debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Bezverkhyi's towing cases: tension figures, tables and the paper's findings."""
    from kanat.report.lumped_plot import plot_trawl
    from kanat.studies.trawl import run_cases

    try:
        with console.status(f"running {len(cases)} Bezverkhyi 2006 case(s) ..."):
            done = run_cases(cases, output, reuse)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "Bezverkhyi 2006 study failed")
    failed = False
    for path, ds, text in done:
        if ds.attrs.get("status") != "ok":
            console.print(f"{path}: {ds.attrs.get('status')}")
            failed = True
            continue
        plot_trawl(ds, output / f"{path.stem}.png")
        (output / f"{path.stem}.md").write_text(text)
        show(text)
    if failed:
        raise typer.Exit(1)


@study.command("pitch")
def pitch_scan(case: Path = typer.Argument(..., help="Case file with a pitch block (examples/pitch_stabilizer.yaml)."),
               output: Path = typer.Option(..., "-o", "--output", help="Folder for scan.csv and the figures."),
               debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Gaisha's pitch studies: the steady pitch per mode, the (t, M0) surfaces, the omega_0 scan
    and the band where the stabilizer more than halves the amplitude."""
    import numpy as np

    from kanat import api
    from kanat.extras import require
    from kanat.studies.pitch import figure_data

    loaded = load(case, debug)
    try:
        require("plot", "matplotlib", "kanat study pitch")
        from kanat.report.pitch_plot import plot_pitch_case

        output.mkdir(parents=True, exist_ok=True)
        with console.status("solving the pitch modes and scanning omega_0 ..."):
            outcome = api.run(loaded, model="pitch")
            solution, data = outcome.solution, figure_data(outcome.solution)
        scan = data.scan
        modes = list(scan.amplitude)
        rows = np.column_stack([scan.natural_frequency, *(scan.amplitude[m] for m in modes),
                                *(scan.max_abs[m] for m in modes)])
        header = ",".join(["omega0_rad_s", *(f"amplitude_{m}_rad" for m in modes),
                           *(f"max_abs_{m}_rad" for m in modes)])
        np.savetxt(output / "scan.csv", rows, delimiter=",", header=header, comments="")
        figures = plot_pitch_case(solution, data, output)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "pitch study failed")
    show(outcome.text)
    if data.band is not None:
        show(f"the stabilizer more than halves the amplitude for {data.band[0]:.3g} < omega_0 <= "
             f"{data.band[1]:.3g} rad/s")
    show(f"wrote {output / 'scan.csv'} and {len(figures)} figures to {output}")


@study.command("pitch-tow")
def pitch_tow(case: Path = typer.Argument(..., help="Continuum tow case with a vessel.pitch block."),
              output: Path = typer.Option(..., "-o", "--output", help="Directory for results and the plot."),
              modes: Optional[List[str]] = typer.Option(None, "--mode", help="Stabilizer mode (repeat)."),
              transient: Optional[float] = typer.Option(None, "--transient",
                                                        help="Seconds left out of the statistics."),
              case_phase: bool = typer.Option(False, "--case-phase",
                                              help="Start every mode at the case's phase_deg."),
              debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Tow through the vessel's pitch once per stabilizer mode; print the top-tension statistics."""
    from kanat.report.coupled_plot import plot_coupled
    from kanat.studies.pitch_tow import DEFAULT_MODES, compare_modes

    loaded = load(case, debug)
    try:
        with console.status("running the tow once per stabilizer mode ..."):
            comparison, summary = compare_modes(loaded, output, tuple(modes or DEFAULT_MODES), transient=transient,
                                                start_at_rest=not case_phase)
        plot_coupled(summary, Path(output) / "coupled.png")
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "coupled run failed")
    show(comparison.table())
    show(f"wrote {output}/<mode>.nc, summary.nc, coupled.png")


def register(app: typer.Typer) -> None:
    """Add ``study``, ``sweep``, ``report`` and ``validate-suite`` to the ``kanat`` app (and the
    older names ``compare-schemes``, ``stability`` and ``pitch-tow`` of the study verbs)."""
    app.add_typer(study, name="study")
    app.command("sweep")(sweep)
    app.command("report")(report)
    app.command("validate-suite")(validate_suite)
    for name, verb in (("compare-schemes", compare_schemes), ("stability", stability), ("pitch-tow", pitch_tow)):
        app.command(name, hidden=True)(verb)
