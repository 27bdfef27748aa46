"""The ``kanat`` command line: verbs mapped to :mod:`kanat.api` and the studies, nothing else.

Messages go through :mod:`logging` to standard error (rich on a terminal, plain
``kanat: level: message`` lines elsewhere): warnings by default, also what each step does
with ``--verbose``, errors only with ``--quiet``; ``--log-file`` keeps every record from
INFO up. Results and tables are printed on standard output (nothing with ``--quiet``),
never hard-wrapped when it is not a terminal. Every run ends with a ``status:`` line.
"""
from __future__ import annotations

import os

# One BLAS thread unless the user says otherwise: kanat's linear systems are small banded ones,
# where OpenBLAS's extra threads only spin (15 % more CPU for the same wall time on the main
# example; docs/performance.md). Set before anything imports NumPy.
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import logging  # noqa: E402
import math  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import Optional  # noqa: E402

import typer  # noqa: E402
from typer.core import TyperCommand  # noqa: E402

from kanat.cli_common import (LOG_FILE_HELP, MAX_NODE_STEPS_HELP, MAX_OUTPUT_HELP, QUIET_HELP, VERBOSE_HELP,  # noqa: E402
                              CONTEXT, console, describe, fail, load, print_problems, set_max_node_steps,
                              setup_logging, show)
from kanat.errors import KanatError  # noqa: E402

log = logging.getLogger("kanat")

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  rich_markup_mode=None, context_settings=CONTEXT,
                  help="Statics and dynamics of marine cable systems.")


def _version(value: bool):
    if value:
        from kanat.version import __version__

        print(f"kanat {__version__}")
        raise typer.Exit()


@app.callback()
def main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                      help="Print the version and exit."),
         quiet: bool = typer.Option(False, "--quiet", "-q", help=QUIET_HELP),
         verbose: bool = typer.Option(False, "--verbose", "-v", help=VERBOSE_HELP),
         log_file: Optional[Path] = typer.Option(None, "--log-file", help=LOG_FILE_HELP)):
    """kanat: towed cables and bodies, moorings and cable networks."""
    setup_logging(quiet, verbose, log_file)


@app.command()
def validate(case: Path = typer.Argument(..., help="Case file (YAML or MoorDyn input)."),
             max_output: Optional[str] = typer.Option(None, "--max-output", help=MAX_OUTPUT_HELP),
             max_node_steps: Optional[float] = typer.Option(None, "--max-node-steps", min=1.0,
                                                            help=MAX_NODE_STEPS_HELP)):
    """Check a case file and report every problem at once (exit 1 on errors)."""
    from kanat.io import check_case

    set_max_node_steps(max_node_steps)
    try:
        problems = check_case(case, max_output_bytes=max_output)
    except KanatError as error:
        fail(error, False, "cannot read the case")
    if problems:
        print_problems(problems)
    errors = sum(p.severity == "error" for p in problems)
    warnings = len(problems) - errors
    if errors:
        log.error(f"{case}: {errors} error(s), {warnings} warning(s)")
        raise typer.Exit(1)
    show(f"{case}: valid ({warnings} warning(s))")


@app.command()
def statics(case: Path = typer.Argument(..., help="Case file (YAML or MoorDyn input)."),
            output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
            plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the solution to this PNG."),
            method: str = typer.Option("auto", "--method", help="auto | shooting | collocation | catenary"),
            debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Solve the steady state of a case and write it to OUTPUT."""
    _steady(load(case, debug, solver="statics"), case, output, plot, debug, model="statics", method=method)


@app.command()
def offsets(case: Path = typer.Argument(..., help="Case file (YAML or MoorDyn input) of a moored vessel."),
            direction: float = typer.Option(..., "--direction", help="Offset direction [deg], from x towards y."),
            to: float = typer.Option(..., "--to", help="Largest offset [m]."),
            steps: int = typer.Option(20, "--steps", min=1, help="Offsets after 0, evenly spaced."),
            output: Path = typer.Option(..., "-o", "--output", help="Result file: netCDF, or CSV for a .csv name."),
            each_body: bool = typer.Option(True, "--each-body/--system-only",
                                           help="With several coupled bodies, also move each alone, the others held."),
            plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the curves to this PNG."),
            debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Restoring force and every line's end tensions against the vessel's offset, written to OUTPUT;
    with several coupled bodies, also each body's own curve, that body moved alone."""
    from kanat import api
    from kanat.io.offsets_table import write_offsets_csv

    loaded = load(case, debug, solver="statics")
    _check_outputs(output, None, case, debug)
    try:
        table, curve, bodies = api.offset_table(loaded, direction, to, steps, each_body)
        write_offsets_csv(curve, output, bodies) if output.suffix.lower() == ".csv" else table.write(output)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "offsets failed")
    for one in (curve, *bodies.values()):
        _show_offset_curve(one, direction)
    show(f"wrote {output}")
    if plot is not None:
        from kanat.report.offsets_plot import plot_offsets

        plot_offsets(table.to_dataset(), plot)
        show(f"wrote {plot}")


def _show_offset_curve(curve, direction: float) -> None:
    """The offset curve's force along ``direction`` and largest tension, one line per offset."""
    if curve.body is not None:
        show(f"{curve.body} alone, the other bodies held:")
    show(f"offset [m]  force along {direction:g} deg [kN]  largest tension [kN]")
    unit = (math.cos(math.radians(direction)), math.sin(math.radians(direction)))
    for d, f, T in zip(curve.offset, curve.force, curve.tension):
        show(f"{d:10.3f}  {(f[0] * unit[0] + f[1] * unit[1]) / 1e3:26.3f}  {T.max() / 1e3:20.3f}")


SCHEME_HELP = "Override simulation.scheme"


def scheme_help() -> str:
    """``--scheme``'s help: the schemes of each dynamic model, from their registries
    (:func:`kanat.api.schemes`)."""
    from kanat.api import schemes

    by_model: dict[str, list[str]] = {}
    for name, cls in schemes().items():
        by_model.setdefault(cls.model, []).append(name)
    listed = "; ".join(f"{model}: {', '.join(sorted(names))}" for model, names in sorted(by_model.items()))
    return f"{SCHEME_HELP} ({listed})."


class _RunCommand(TyperCommand):
    """``kanat run``: its ``--scheme`` help lists the schemes when the help is shown (the
    registries import the models' kernels, too slow for every start of the command line)."""

    def format_help(self, ctx, formatter):
        for param in self.params:
            if param.name == "scheme":
                param.help = scheme_help()
        super().format_help(ctx, formatter)


@app.command(cls=_RunCommand)
def run(ctx: typer.Context,
        case: Optional[Path] = typer.Argument(None, help="Case file (YAML or MoorDyn input)."),
        output: Optional[Path] = typer.Option(None, "-o", "--output", help="Result file (netCDF); required."),
        from_result: Optional[Path] = typer.Option(None, "--from-result",
                                                   help="Run again the case embedded in this result file."),
        plot: Optional[Path] = typer.Option(None, "--plot", help="Also draw the result to this PNG."),
        scheme: Optional[str] = typer.Option(None, "--scheme", help=SCHEME_HELP + " (kanat run -h lists them)."),
        resume: bool = typer.Option(False, "--resume", help="Continue a killed run from its checkpoint."),
        checkpoint_every: Optional[int] = typer.Option(None, "--checkpoint-every", min=1,
                                                       help="Checkpoint every N output steps (N >= 1; "
                                                            "default: every 5 s of wall time)."),
        max_output: Optional[str] = typer.Option(None, "--max-output", help=MAX_OUTPUT_HELP),
        max_node_steps: Optional[float] = typer.Option(None, "--max-node-steps", min=1.0,
                                                       help=MAX_NODE_STEPS_HELP),
        debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Run any case with the model its file names, writing the result to OUTPUT as it goes."""
    from kanat import api

    if case is None and from_result is None:               # named before any missing option
        ctx.fail("Missing argument 'CASE': give a case file (YAML or MoorDyn input), or --from-result RESULT.nc.")
    if output is None:
        ctx.fail("Missing option '-o' / '--output': the result file (netCDF) to write.")
    set_max_node_steps(max_node_steps)
    if case is not None and from_result is not None:
        fail(KanatError("give a case file, or --from-result RESULT.nc (not both)"), debug, "nothing to run")
    if from_result is not None:
        try:
            loaded, case = api.case_of(from_result), from_result
        except Exception as error:  # noqa: BLE001 - reported by fail
            fail(error, debug, "cannot read the case of the result")
        log.info(f"the case of {from_result}: {describe(loaded)}")
    else:
        loaded = load(case, debug, max_output)
    _check_outputs(output, plot, case, debug)
    if isinstance(api.MODELS.get(loaded.model), api.Steady):
        _steady(loaded, case, output, plot, debug, model=loaded.model)
        return
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", api.RunFailedWarning)        # the status is reported below
            outcome = _with_progress(loaded.simulation.duration, lambda progress: api.run(
                loaded, scheme=scheme, output=output, resume=resume, progress=progress,
                checkpoint_every=checkpoint_every))
    except KeyboardInterrupt:
        log.warning(f"interrupted; {output} keeps what was computed; continue with --resume")
        raise typer.Exit(130)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "run failed")
    if not outcome.ok:
        fail(KanatError(f"{outcome.status}\n\nThe results up to the failure are in {output}."), debug,
             "run stopped")
    show(outcome.text)
    show(f"wrote {output}")
    if plot is not None:
        from kanat.report.run_plot import plot_run

        plot_run(outcome.dataset, plot)
        show(f"wrote {plot}")


def _with_progress(duration: float, start):
    """Run ``start(progress)`` under a progress bar of simulated time (on a terminal only)."""
    if not console.is_terminal:
        return start(None)
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    columns = (TextColumn("t = {task.completed:.1f} / {task.total:g} s"), BarColumn(), TimeElapsedColumn(),
               TextColumn("{task.fields[info]}"))
    with Progress(*columns, console=console.rich, transient=True) as bar:
        task = bar.add_task("run", total=duration, info="")

        def progress(t, info):
            text = f"Newton {info['newton_iterations']:.2f}/step" if "newton_iterations" in info else ""
            bar.update(task, completed=t, info=text)
        return start(progress)


@app.command()
def pitch(case: Path = typer.Argument(..., help="Case file with a pitch block."),
          output: Path = typer.Option(..., "-o", "--output", help="Result file (netCDF)."),
          plot: Optional[Path] = typer.Option(None, "--plot",
                                              help="Directory for the figures (or a PNG for fig. 2)."),
          debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Ship pitch with the reactive stabilizer (Gaisha): steady pitch per control mode."""
    _steady(load(case, debug), case, output, plot, debug, model="pitch")


@app.command()
def catalog(name: Optional[str] = typer.Argument(None, help="A catalogue line; omit to list them."),
            diameter: Optional[float] = typer.Option(None, "-d", "--nominal-diameter",
                                                     help="Nominal diameter [m] (with NAME)."),
            grade: Optional[str] = typer.Option(None, "-g", "--grade", help="Chain grade R3 ... R5."),
            water_density: float = typer.Option(1025.0, "--water-density", help="[kg/m^3], for added mass.")):
    """The line catalogue: its lines, or one line's line-type keys (docs/design.md)."""
    from kanat import catalog as line_catalog

    if name is None:
        typer.echo(line_catalog.catalog_table())
        return
    if diameter is None:
        raise typer.BadParameter("give the nominal diameter in metres, e.g. -d 0.076", param_hint="-d")
    try:
        typer.echo(line_catalog.line_type_text(name, diameter, grade, water_density))
    except line_catalog.CatalogError as error:
        typer.echo(f"error: {error}", err=True)
        raise typer.Exit(2) from None


@app.command()
def modes(case: Path = typer.Argument(..., help="Case file (YAML or MoorDyn input)."),
          count: int = typer.Option(10, "-n", "--modes", min=1, help="How many modes, lowest first."),
          output: Optional[Path] = typer.Option(None, "-o", "--output", help="Also write them (netCDF)."),
          debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Natural frequencies and mode shapes of the lumped system about its equilibrium."""
    from kanat.frequency import modes as natural_modes
    from kanat.frequency.modes import modes_table

    loaded = load(case, debug)
    if output is not None:
        _check_outputs(output, None, case, debug)
    try:
        with console.status(f"linearising {case.name} ..."):
            ds = natural_modes(loaded, n=count)
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "modes failed")
    show(modes_table(ds))
    if output is not None:
        ds.to_netcdf(output)
        show(f"wrote {output}")


def _check_outputs(output: Path, plot: Optional[Path], case: Path, debug: bool) -> None:
    """Refuse, before any work, an output that is an input, a directory or unwritable."""
    from kanat.io.outputs import check_output_file

    try:
        check_output_file(output, inputs=[case])
        if plot is not None:
            check_output_file(plot, inputs=[case, output], flag="--plot", example="picture.png")
    except KanatError as error:
        fail(error, debug, "cannot write there")


def _steady(loaded, case: Path, output: Path, plot: Optional[Path], debug: bool, model: str,
            method: str = "auto") -> None:
    """Solve a steady model (statics, pitch), write its result and, optionally, its pictures."""
    from kanat import api
    from kanat.errors import CaseError, OutputWriteError

    _check_outputs(output, plot, case, debug)
    try:
        with console.status(f"solving {model} of {case.name} ..."), warnings.catch_warnings():
            warnings.simplefilter("ignore", api.RunFailedWarning)        # the status is reported below
            outcome = api.run(loaded, output=output, model=model, method=method)
    except KeyboardInterrupt:
        log.warning(f"interrupted; {output} says so and holds no steady state")
        raise typer.Exit(130)
    except KanatError as error:
        if not isinstance(error, (CaseError, OutputWriteError)):
            log.warning(f"wrote {output}: no solution, its status says why")
        fail(error, debug, f"{model} failed")
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, f"{model} failed")
    _log_solved(model, outcome.held)
    show(outcome.text)
    if not outcome.ok:                           # a steady state that fails its checks, written all the same
        fail(KanatError(f"{outcome.status}\n\nThe failed steady state is in {output}."), debug, f"{model} failed")
    show(f"status: {outcome.status}")           # as a dynamic run's summary ends
    if plot is not None:
        _draw(model, outcome.solution, plot)
    show(f"wrote {output}" + (f" and {plot}" if plot is not None else ""))


def _log_solved(model: str, ds) -> None:
    """Log how a steady model was solved: the method asked for, and the one of each cable (statics) or
    stabilizer mode (pitch). ``ds``: the result's dataset or table (its ``attrs`` and ``sizes``)."""
    attrs = ds.attrs
    methods = {k[len("method_"):]: v for k, v in attrs.items() if k.startswith("method_")}
    nodes = f", {ds.sizes['node']} nodes" if "node" in ds.sizes else ""
    part = "cable" if model == "statics" else "mode"
    solved = "; ".join(f"{part} {name} by {how}" for name, how in methods.items())
    log.info(f"{model} solved (method {attrs.get('scheme', '')}{nodes})" + (f": {solved}" if solved else "")
             + f" in {float(attrs.get('wall_time_s', 0.0)):.2f} s")


def _draw(model: str, solution, plot: Path) -> None:
    if model == "pitch":
        from kanat.report.pitch_plot import plot_pitch_case
        from kanat.studies.pitch import figure_data

        plot_pitch_case(solution, figure_data(solution), plot)
    else:
        from kanat.report.statics_plot import plot_statics

        plot_statics(solution, plot)


from kanat.cli_docs import register as register_docs  # noqa: E402 - kanat schema, kanat export
from kanat.cli_design import register as register_design  # noqa: E402 - kanat design
from kanat.cli_import import register as register_import  # noqa: E402 - kanat import
from kanat.cli_study import register  # noqa: E402 - the study verbs: study, sweep, report, validate-suite

register(app)
register_import(app)
register_design(app)
register_docs(app)


if __name__ == "__main__":  # python -m kanat.cli
    app()
