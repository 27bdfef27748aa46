"""The ``kanat import`` verb: a MoorDyn input file (v1 or v2) to a kanat YAML case.

``kanat.cli`` calls :func:`register` to add it to its Typer app. The verb maps to
:func:`kanat.io.moordyn.read_moordyn` and :func:`kanat.io.moordyn.case_yaml`, nothing else;
the written case loads back to the same system (``kanat validate case.yaml`` then says
which models can run it).
"""
from __future__ import annotations

from pathlib import Path

import typer

from kanat.cli_common import console, log, print_problems, show


def import_file(source: Path, output: Path) -> int:
    """Convert ``source`` to the YAML case ``output``; print what happened; exit status.

    Returns
    -------
    int
        0 when written, 1 when the file cannot be imported (its problems are printed).
    """
    from rich.text import Text

    from kanat.errors import KanatError
    from kanat.model.validation import validate_data
    from kanat.io.moordyn import case_yaml, looks_like_moordyn, read_moordyn
    from kanat.io.outputs import check_output_file, write_text_atomic
    from kanat.model.support import unsupported

    try:
        text = source.read_text(encoding="utf-8")
        target = check_output_file(output, inputs=[source], example="case.yaml")
    except (OSError, UnicodeDecodeError) as error:
        console.print(Text(f"{source}: cannot read it ({getattr(error, 'strerror', None) or error})",
                           style="red"))
        return 1
    except KanatError as error:
        console.print(Text(str(error), style="red"))
        return 1
    if not looks_like_moordyn(text):
        console.print(Text(f"{source} is not a MoorDyn input file (it has no '--- LINE TYPES ---' "
                           "and '--- LINES ---' sections)", style="red"))
        return 1
    imported = read_moordyn(text, str(source))
    case, problems = (None, []) if imported.data is None else validate_data(
        imported.data, str(source), imported.lines)
    errors = [p for p in imported.problems + problems if p.severity == "error"]
    if case is None or errors:
        print_problems(sorted(imported.problems + problems, key=lambda p: p.line or 0))
        console.print(Text(f"{source}: not imported ({len(errors)} error(s))", style="red"))
        return 1
    write_text_atomic(target, case_yaml(imported, source.name))
    notes = [p for p in imported.problems if p.severity == "warning"]
    show(f"wrote {target}: MoorDyn v{imported.version}, {len(case.cables)} line(s), "
              f"{len(case.points)} point(s), {len(case.bodies)} bod{'y' if len(case.bodies) == 1 else 'ies'}"
              + (f"; {len(notes)} MoorDyn setting(s) not imported (listed in its header)" if notes else ""))
    missing = [p for p in unsupported(case, case.model) if p.severity == "error"]
    if missing:
        log.warning(f"model '{case.model}' cannot run it as it is ({len(missing)} use(s) of features it "
                    f"does not support; kanat validate {target} lists them)")
    return 0


def register(app: typer.Typer) -> None:
    """Add the ``import`` verb to ``app``."""

    @app.command("import")
    def import_(source: Path = typer.Argument(..., help="MoorDyn input file (v1 or v2)."),
                output: Path = typer.Option(..., "-o", "--output", help="YAML case to write.")):
        """Convert a MoorDyn input file into a kanat YAML case (names line1, point1, body1)."""
        raise typer.Exit(import_file(source, output))
