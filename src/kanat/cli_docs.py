"""The documentation and set-up verbs of the ``kanat`` command line: ``schema``, ``export``, ``warmup``.

``kanat.cli`` calls :func:`register` to add them to its Typer app. ``kanat schema`` prints
the case file's JSON Schema (:func:`kanat.model.reference.json_schema`) or its Markdown
reference; ``kanat export`` turns a result file into files for other tools
(:mod:`kanat.io.export`: VTK for ParaView, tidy CSV); ``kanat warmup`` compiles the kernel
families ahead of the first run (:mod:`kanat.warmup`).

This module also joins the two halves of the reference page (:func:`reference_page`): the
case format, from the models, and the result names, from :mod:`kanat.io.schema`, which sit
in different layers of the package.
"""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from kanat.cli_common import fail, show

ATTRIBUTES = {
    "kanat_version": "version of kanat that wrote the file",
    "case_name": "the case's `name`",
    "case_sha256": "SHA-256 of the case's canonical JSON form with default values left out (insensitive to YAML "
                   "layout, comments, keys written at their defaults and keys a later release adds with defaults: "
                   "a run resumes across releases)",
    "case_yaml": "the case itself, as YAML that loads back to the same case",
    "model": "the model that ran: statics, continuum, lumped or pitch",
    "scheme": "time scheme (dynamic models) or statics method",
    "wall_time_s": "wall time of the run [s]",
    "status": "`ok`, or `failed: ...` saying why the run stopped (results up to then are kept); a steady state "
              "(statics, a dynamic run's t = 0) failing a check is `failed: CHECK: ...` (statics.md, \"Checks of a "
              "steady state\")",
    "warnings": "statics: the warnings of the checks of a steady state, one a line (a tension above the breaking "
                "load); absent when there are none",
    "Conventions": "CF conventions version the file follows",
    "dt": "time step used [s] (dynamic models)",
    "output_interval": "interval between stored outputs [s] (dynamic models)",
    "steps": "time steps taken (dynamic models)",
    "step_cuts": "steps halved after a failed Newton solve (implicit schemes)",
    "newton_iterations_mean": "mean Newton iterations per step (implicit schemes)",
    "setup_time_s, solver_time_s, compile_time_s": "wall time spent setting up, stepping and compiling kernels [s]",
    "notes": "what the run chose or adjusted (a step bounded by stability, ...); network statics: what its "
             "conventions did to the answer (seabed friction taken off an anchor's pull)",
    "scheme_*": "the scheme's parameters (`scheme_lambda_inf`, ...)",
    "method_CABLE, grounded_length_CABLE_m": "statics: the method that solved each cable and its length on the seabed",
    "snap_events": "number of slack-to-taut events (lumped model)",
    "time_error_estimate": "implicit lumped runs: the largest local time-integration error estimate of a step, as a "
                           "fraction of the step's displacement (lumped.md, \"Time-step error estimate\"); above 0.02 "
                           "the run warns, above 1 it fails",
    "time_error_time": "implicit lumped runs: the time of that step [s]",
    "time_error_displacement": "implicit lumped runs: the largest local displacement error of a node in one step [m]",
    "time_error_start": "implicit lumped runs: the start's tensions over its first 10 steps at dt against dt/2, their "
                        "largest difference as a fraction of the largest tension (lumped.md, \"Time-step error "
                        "estimate\"); above 0.02 the run warns, above 1 it fails",
    "time_error_start_time": "implicit lumped runs: the time of that difference [s]",
}
"""Global attributes of a result file and what they hold (the reference page lists them)."""

COORDINATES = {
    "time": (("time",), "s", "simulated time (dynamic results)"),
    "s": (("node",), "m", "unstretched arclength within its cable, from its `from` end"),
    "cable": (("node",), "1", "cable name of each node"),
    "segment_cable": (("segment",), "1", "cable name of each segment"),
    "xyz": (("xyz",), "–", "the labels x, y, z of the global frame (z up)"),
    "body": (("body",), "–", "body names"),
}


def _schemes() -> list[str]:
    from kanat.schemes import SCHEME_NAMES          # the one list (the registries are held to it)

    return sorted(SCHEME_NAMES)


def reference_page() -> str:
    """``docs/reference/case-format.md``: the case format and the result names, generated."""
    from kanat.io.schema import VARIABLES
    from kanat.model.reference_markdown import case_format_markdown, results_markdown

    head = ("# Case and result reference\n\n"
            "Generated from the code by `python scripts/docs_reference.py` (the pydantic models of "
            "`kanat.model` and the result table of `kanat.io.schema`); a test fails when this page "
            "and the code disagree. Conventions (axes, signs, units): [Concepts](../concepts.md). "
            "Which model takes which key: [Support table](support.md).\n\n")
    return (head + case_format_markdown(_schemes()) + "\n"
            + results_markdown(VARIABLES, COORDINATES, ATTRIBUTES))


def support_page() -> str:
    """``docs/reference/support.md``: the support table, generated."""
    from kanat.model.reference_markdown import support_markdown

    return ("# Which model supports which key\n\n"
            "Generated from `kanat.model.support` by `python scripts/docs_reference.py`. `kanat "
            "validate` and every solver read the same table: **no** is an error naming the key, "
            "*ignored* a warning saying why (the statics of a case with waves is the still-water "
            "steady state). Keys are in the [case reference](case-format.md).\n\n"
            + support_markdown())


def schemes_page() -> str:
    """``docs/schemes.md``: every time scheme of :data:`kanat.api.SCHEMES`, generated."""
    import dataclasses

    from kanat.api import SCHEMES
    from kanat.model.reference import plain_text
    from kanat.model.reference_markdown import _cell

    pages = {"continuum": "continuum.md", "lumped": "lumped.md"}
    lines = ["# Time schemes", "",
             "Generated from the scheme registry (`kanat.api.SCHEMES`) by `python scripts/docs_reference.py`. "
             "A case names its scheme in `simulation.scheme`; `kanat run --scheme NAME` overrides it; from "
             "Python a scheme object works wherever a name does (`kanat.simulate(case, scheme=...)`). The "
             "order is measured for every scheme by one test (`tests/schemes/test_scheme_order.py`); explicit "
             "schemes have a stable step of their own.", "",
             "| name | model | order | explicit | parameters (default) | what it is |", "|---|---|---|---|---|---|"]
    for name, cls in SCHEMES.items():
        scheme = cls()
        fields = dataclasses.fields(cls) if dataclasses.is_dataclass(cls) else ()
        params = ", ".join(f"`{f.name}` ({f.default!r})" for f in fields) or "–"
        summary = _cell(plain_text(" ".join((cls.__doc__ or "").strip().split("\n\n")[0].split())))
        lines.append(f"| `{name}` | [{cls.model}]({pages.get(cls.model, 'index.md')}) | {scheme.order} | "
                     f"{'yes' if cls.explicit else 'no'} | {params} | {summary} |")
    lines += ["", "The continuum schemes are described with their equations in [Continuum model](continuum.md) "
              "(box method and the generalized-α family) and [Factorized schemes](factorization.md) (Kaliukh & Vusatiuk 2018); "
              "the lumped ones in [Lumped network model](lumped.md).", ""]
    return "\n".join(lines)


def schema(output: Optional[Path] = typer.Option(None, "-o", "--output",
                                                 help="Write to this file instead of standard output."),
           markdown: bool = typer.Option(False, "--markdown",
                                         help="The Markdown reference of cases and results instead.")):
    """Print the JSON Schema of case files (editors use it to complete and check YAML)."""
    from kanat.model.reference import schema_text

    text = reference_page() if markdown else schema_text(_schemes())
    if output is None:
        typer.echo(text, nl=False)
        return
    try:
        output.write_text(text, encoding="utf-8")
    except OSError as error:
        from kanat.errors import KanatError

        fail(KanatError(f"cannot write {output}: {error.strerror}"), False, "schema")
    show(f"wrote {output}")


def export(result: Path = typer.Argument(..., help="Result file (netCDF) of kanat run or statics."),
           vtk: Optional[Path] = typer.Option(None, "--vtk", help="Directory for a VTK time series "
                                              "(.vtu per output, .pvd collection for ParaView)."),
           csv: Optional[Path] = typer.Option(None, "--csv", help="Directory for one tidy CSV per variable."),
           debug: bool = typer.Option(False, "--debug", help="Show tracebacks.")):
    """Export a result for other tools: VTK for ParaView (--vtk DIR), tidy CSV (--csv DIR)."""
    from kanat.errors import KanatError
    from kanat.io.export import export_csv, export_vtk
    from kanat.io.results import read_result

    if vtk is None and csv is None:
        fail(KanatError("say what to write: --vtk DIR and/or --csv DIR"), debug, "nothing to export")
    try:
        ds = read_result(result)
        if vtk is not None:
            pvd = export_vtk(ds, vtk)
            show(f"wrote {pvd} (open it in ParaView)")
        if csv is not None:
            files = export_csv(ds, csv)
            show(f"wrote {len(files)} CSV files to {csv}")
    except FileNotFoundError:
        fail(KanatError(f"{result}: no such file"), debug, "export failed")
    except Exception as error:  # noqa: BLE001 - reported by fail
        fail(error, debug, "export failed")


def warmup(families: Optional[list[str]] = typer.Argument(
        None, help="Kernel families to compile (default all): continuum-2d, continuum-3d, factorized-2d, "
                   "factorized-3d, wave-factorized-2d, wave-factorized-3d, lumped-rk4, lumped-abm4, "
                   "lumped-implicit.")):
    """Compile the numba kernels once, ahead of the first run (cached on disk for every later run).

    Needed only where the install could not compile them (no C compiler: pip then installs without
    them) or after editing a kernel in a source checkout; otherwise every family reports "already
    compiled"."""
    import logging
    import warnings

    import kanat
    from kanat import warmup as kernels

    log = logging.getLogger("kanat")
    unknown = [name for name in families or () if name not in kernels.FAMILIES]
    if unknown:
        from kanat.errors import KanatError

        fail(KanatError(f"no kernel family {', '.join(map(repr, unknown))}; valid: {', '.join(kernels.FAMILIES)}"),
             False, "warmup")

    def simulate(case):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            kanat.simulate(kanat.load_case(case))

    spent = kernels.warmup(simulate, families or None,
                           lambda name, estimate: log.warning(f"compiling {name} kernels once, ~{estimate:.0f} s"))
    for name, seconds in spent.items():
        show(f"{name}: {'already compiled' if seconds == 0.0 else f'compiled in {seconds:.1f} s'}")
    if not kernels.aot.current():
        show("(the kernels compiled at install are missing or stale: `pip install -e .` in the checkout, or "
             "`python -m kanat.aot_build`, compiles them again)")


def register(app: typer.Typer) -> None:
    """Add ``schema``, ``export`` and ``warmup`` to the ``kanat`` app."""
    from kanat.cli_common import CONTEXT

    app.command(context_settings=CONTEXT)(schema)
    app.command(context_settings=CONTEXT)(export)
    app.command(context_settings=CONTEXT)(warmup)
