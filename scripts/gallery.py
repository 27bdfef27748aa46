"""Regenerate the documentation's gallery: one picture per example case, drawn from a run.

    python scripts/gallery.py            # every example (about a minute on one core)
    python scripts/gallery.py towed_body # only the examples whose file name contains this

Each case file under ``examples/`` (YAML and MoorDyn) is loaded, solved or run in memory
with its own model, and drawn with the pictures of ``kanat.report`` -- the same code as
``kanat run --plot`` -- into ``docs/gallery/NAME.png`` (plus a 3-D overview,
``NAME_3d.png``, for systems of several cables or that leave the x–z plane). Long runs are
cut short (:data:`SHORT`), and the page says so. A case no model runs yet is drawn as
written (:func:`kanat.report.overview.plot_layout`), with the reason. The page
``docs/gallery.md`` is written last; ``tests/cli/test_docs_site.py`` checks that it shows
every example.
"""
from __future__ import annotations

import sys
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
OUT = ROOT / "docs" / "gallery"
PAGE = ROOT / "docs" / "gallery.md"
SHORT = {
    "trawl_following_4.5s_1to2.yaml": 360.0,
    "trawl_head_5.6s_1to4.yaml": 360.0,
    "trawl_head_8s_1to2.yaml": 360.0,
}
"""Examples run for a shorter time [s] than their case says (the speed step at 300 s is kept;
the explicit scheme needs about 10 s of wall time per 600 s of these runs)."""


def example_files() -> list[Path]:
    """Every case file of ``examples/``: YAML cases and MoorDyn input files (not notebooks)."""
    found = [*EXAMPLES.glob("*.yaml"), *EXAMPLES.glob("*.yml"), *EXAMPLES.glob("moordyn/*.dat"), *EXAMPLES.glob("moordyn/*/*.dat")]
    return sorted(found, key=lambda p: p.relative_to(EXAMPLES).as_posix())


@dataclass
class Entry:
    """One example on the page."""

    file: Path
    title: str = ""
    text: str = ""
    pictures: list[str] = field(default_factory=list)
    note: str = ""
    seconds: float = 0.0


def description(path: Path) -> str:
    """The first paragraph of the leading comment of a case file (``#`` lines); for a MoorDyn
    file, its free text between the title line and the first section (``---`` line)."""
    if path.suffix == ".dat":
        return _moordyn_description(path)
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith(("#", "!")) and line.strip():
            break
        text = line.lstrip("#!").strip()
        if not text and lines:
            break
        if text:
            lines.append(text)
    from kanat.model.reference import plain_text

    return plain_text(" ".join(lines))


def _moordyn_description(path: Path) -> str:
    """The lines after a MoorDyn file's title line, up to its first section or blank line."""
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines()[1:]:
        if not line.strip() or line.lstrip().startswith("-"):
            break
        lines.append(line.strip())
    return " ".join(lines)


def _quiet(call, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return call(*args, **kwargs)


def _shortened(case, duration: float):
    """The case with ``simulation.duration`` set to ``duration`` (validated again)."""
    from kanat.api import load_case

    data = case.model_dump(mode="json", by_alias=True, exclude_unset=True)
    data["simulation"] = {**data["simulation"], "duration": duration}
    return _quiet(load_case, data)


def _layout(path: Path, entry: Entry, error) -> None:
    """Draw a case no model runs yet as written."""
    from kanat.io.case_read import read_case_text
    from kanat.io.case_source import read_document
    from kanat.model import Case
    from kanat.report.overview import plot_layout

    text, _ = read_case_text(path)
    case = Case.model_validate(read_document(text, str(path)).data)
    reasons = [p.message for p in getattr(error, "problems", []) if p.severity == "error"] or [str(error)]
    entry.note = (f"No model runs this case yet ({len(reasons)} error(s); the first: {reasons[0]}), so the "
                  "picture shows the case as written: straight lines between the ends it places.")
    plot_layout(case, OUT / f"{entry.pictures[0]}", note="no model runs this case yet")


def draw(path: Path) -> Entry:
    """Run one example and draw its pictures."""
    from kanat import api
    from kanat.errors import CaseError
    from kanat.report.geometry import is_planar
    from kanat.report.overview import plot_overview
    from kanat.report.pitch_plot import plot_period
    from kanat.report.run_plot import plot_run

    stem = path.relative_to(EXAMPLES).as_posix().replace("/", "_").rsplit(".", 1)[0]
    entry = Entry(path, path.relative_to(ROOT).as_posix(), description(path), [f"{stem}.png"])
    start = time.perf_counter()
    try:
        case = _quiet(api.load_case, path)
    except CaseError as error:
        _layout(path, entry, error)
        entry.seconds = time.perf_counter() - start
        return entry
    entry.title = f"{entry.title} — {case.name}" if case.name else entry.title
    if path.name in SHORT and case.simulation is not None and case.simulation.duration > SHORT[path.name]:
        entry.note = (f"Run here for the first {SHORT[path.name]:g} s of its {case.simulation.duration:g} s "
                      "to keep the gallery quick to regenerate.")
        case = _shortened(case, SHORT[path.name])
    try:
        outcome = _quiet(api.run, case)
    except Exception as error:  # noqa: BLE001 - the page says what failed, with the case as written
        _layout(path, entry, error)
        entry.note = f"The run fails ({type(error).__name__}: {str(error)[:300]}); the picture shows the case as written."
        entry.seconds = time.perf_counter() - start
        return entry
    if case.model == "pitch":
        plot_period(outcome.solution, OUT / entry.pictures[0])
    else:
        plot_run(outcome.dataset, OUT / entry.pictures[0])
        ds = outcome.dataset
        if "position" in ds and (len(case.cables) > 1 or not is_planar(ds)):
            entry.pictures.append(f"{stem}_3d.png")
            plot_overview(ds, OUT / entry.pictures[1])
    entry.seconds = time.perf_counter() - start
    return entry


def page(entries: list[Entry], seconds: float) -> str:
    """``docs/gallery.md``."""
    import os

    load = f", load average {os.getloadavg()[0]:.0f} at the end" if hasattr(os, "getloadavg") else ""
    lines = ["# Gallery", "",
             "Every example case in `examples/`, run with its own model and drawn by the same code "
             "as `kanat run CASE -o OUT.nc --plot OUT.png` (statics results: `kanat statics`; the "
             "pitch case: its figure 2). The pictures are generated by `python scripts/gallery.py` "
             f"from the examples (about {seconds:.0f} s on one core{load}) and committed, so they change only "
             "when the code or the examples do; a test checks that every example is here.", "",
             "What each picture shows depends on the kind of system (`kanat.report.kinds`): towed "
             "systems the top tension, the bodies' depth and the cable's shape; moored systems the "
             "fairlead tensions (never the anchor ends), the bodies' surge, heave and pitch, and plan "
             "and elevation with each line in its own colour, named in the legend; networks every "
             "cable in its own colour and named. The HTML report's histories show the same.", "",
             "Geometry is drawn with equal scales on both axes, in elevation (x–z, z up, 0 at the "
             "mean surface) and, for systems that leave that plane, in plan (x–y, y to port). When "
             "the tow point moves, positions are drawn relative to it, so that snapshots overlay; "
             "see [Concepts](concepts.md) for the axes. Systems of several cables or in 3-D also get "
             "a 3-D overview.", ""]
    for entry in entries:
        anchor = entry.pictures[0].rsplit(".", 1)[0]
        lines += [f"## {entry.title} {{#{anchor}}}", "", entry.text, ""]
        if entry.note:
            lines += [f"*{entry.note}*", ""]
        lines += [f"![{entry.file.name}](gallery/{name})" for name in entry.pictures] + [""]
    return "\n".join(lines).rstrip() + "\n"


def main(argv: list[str]) -> int:
    import matplotlib

    matplotlib.use("Agg")
    OUT.mkdir(parents=True, exist_ok=True)
    chosen = [p for p in example_files() if not argv or any(a in p.name for a in argv)]
    start, entries = time.perf_counter(), []
    for path in chosen:
        entry = draw(path)
        print(f"{entry.file.relative_to(ROOT)}: {', '.join(entry.pictures)} ({entry.seconds:.1f} s)")
        entries.append(entry)
    if argv:
        print("a subset was drawn: docs/gallery.md is left as it was")
        return 0
    PAGE.write_text(page(entries, time.perf_counter() - start), encoding="utf-8")
    print(f"wrote {PAGE.relative_to(ROOT)} ({time.perf_counter() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
