"""Every class of bad input gets its own clear error: no traceback, no hang, no nonsense.

One row per class of mistake or attack on a case file: the file itself (missing, a
directory, unreadable, binary, too large), its YAML (syntax, aliases, nesting, tags,
values YAML cannot hold) and its content (types, ranges, limits on the work of a run,
numbers that would overflow later arithmetic, inconsistent settings). For each class the
oracle is the reader's contract: :func:`kanat.io.check_case` returns an error naming the
file and holding the expected words (and the line, where the class has one),
:func:`kanat.io.load_case` raises :class:`~kanat.errors.CaseError`, ``kanat validate``
exits 1 without a traceback, and all of it within a few seconds.
"""
from __future__ import annotations

import math
import os
import textwrap
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import pytest
from typer.testing import CliRunner

from kanat.cli import app
from kanat.errors import CaseError
from kanat.io import check_case, check_text, load_case, parse_case
from kanat.model import limits

from helpers import EXAMPLES, ROOT

SECONDS = 10.0   # the slowest class (a 1 MiB file) reads in well under a second

# Line numbers of BASE (1-based) are used by the table below.
BASE = textwrap.dedent("""\
    name: bad-inputs
    model: continuum
    environment:
      depth: 2000
      current: {velocity: [0.5, 0, 0]}
      # waves go here
    line_types:
      towcable:
        diameter: 0.0173
        mass: 1.12
        weight_in_water: 8.89
        axial_stiffness: 1.2717e7
    bodies:
      sled: {mass: 1135, net_buoyancy: -4448, drag_area: 0.33}
    vessel:
      tow_point: [0, 0, 0]
      track:
        - {straight: {speed: 3.0, duration: 100}}
        - {turn: {radius: 640, angle_deg: 90}}
    cables:
      - name: tow
        line_type: towcable
        length: 1000
        segments: 100
        from: vessel
        to: sled
    simulation:
      duration: 600
      dt: 1.0
      output_dt: 1.0
    """)
PITCH = textwrap.dedent("""\
    name: pitch
    model: pitch
    pitch:
      inertia: 2.0e7
      natural_frequency: 1.0
      wave_moment_amplitude: 7.0e5
      wave_period: 10.0
      damping_ratio: 0.1
      stabilizer: {mode: rectangular, max_moment: 1.0e6}
      harmonics: 50
    """)
SPHERE = textwrap.dedent("""\
    name: sphere
    model: statics
    sphere_two_cables:
      dimensionless: {Psi: 0.02, LoL: 2.0, x_C: -1.732, QkL: 0.45, RkL: 0.4}
    """)


def edit(old: str, new: str, text: str = BASE) -> str:
    """Replace one exact occurrence of ``old``."""
    assert text.count(old) == 1, old
    return text.replace(old, new)


@dataclass(frozen=True)
class Bad:
    """One class of bad input.

    ``make(tmp_path, monkeypatch)`` returns the path to check; ``words`` must all be in
    one error's message; ``line`` is that error's line (None: not checked).
    """

    make: Callable
    words: tuple[str, ...]
    line: int | None = None
    cli: bool = True
    extra: dict = field(default_factory=dict)


def text(content: str | bytes, name: str = "case.yaml") -> Callable:
    def make(tmp_path, monkeypatch):
        path = tmp_path / name
        (path.write_bytes if isinstance(content, bytes) else path.write_text)(content)
        return path
    return make


def base(old: str, new: str, source: str = BASE) -> Callable:
    return text(edit(old, new, source))


def wave(old: str, new: str) -> Callable:
    """An edit of BASE with regular waves (line 6)."""
    return text(edit(old, new, edit("# waves go here", "waves: {type: regular, height: 2.0, period: 8.0, heading_deg: 180}")))


def edits(*pairs: tuple[str, str]) -> Callable:
    """Several edits of BASE, each of one exact occurrence."""
    source = BASE
    for old, new in pairs:
        source = edit(old, new, source)
    return text(source)


def _laughs(levels: int = 9) -> str:
    lines = ["a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    lines += [f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]" for i in range(1, levels)]
    return "\n".join(lines) + "\nmodel: statics\n"


def _missing(name):
    return lambda tmp_path, monkeypatch: tmp_path / name


def _next_to_example(tmp_path, monkeypatch):
    (tmp_path / "towed_body.yaml").write_text((EXAMPLES / "towed_body.yaml").read_text())
    return tmp_path / "towed_bdy.yaml"


def _directory(tmp_path, monkeypatch):
    (tmp_path / "cases").mkdir()
    (tmp_path / "cases" / "a.yaml").write_text(BASE)
    return tmp_path / "cases"


def _broken_link(tmp_path, monkeypatch):
    link = tmp_path / "link.yaml"
    link.symlink_to(tmp_path / "gone.yaml")
    return link


def _fifo(tmp_path, monkeypatch):
    if not hasattr(os, "mkfifo"):
        pytest.skip("no named pipes on this platform")
    os.mkfifo(tmp_path / "pipe.yaml")
    return tmp_path / "pipe.yaml"


def _unreadable(tmp_path, monkeypatch):
    path = text(BASE)(tmp_path, monkeypatch)
    path.chmod(0)
    if os.access(path, os.R_OK):  # root reads anything: make open() refuse as it would
        import kanat.io.case_read as case_read

        def refuse(*args, **kwargs):
            raise PermissionError(13, "Permission denied")
        monkeypatch.setattr(case_read, "open", refuse, raising=False)
    return path


def _bad_env(tmp_path, monkeypatch):
    monkeypatch.setenv(limits.OUTPUT_BYTES_ENV, "lots")
    return text(BASE)(tmp_path, monkeypatch)


def _three_huge_cables(tmp_path, monkeypatch):
    second = "".join(f"  - {{name: tow{i}, line_type: towcable, length: 1000, segments: 60000, "
                     "from: vessel, to: free}\n" for i in (2, 3))
    return text(edit("segments: 100\n", "segments: 100000\n").replace(
        "    to: sled\n", "    to: sled\n" + second))(tmp_path, monkeypatch)


KB = 1024
CLASSES: dict[str, Bad] = {
    # --- the file ------------------------------------------------------------------
    "missing file": Bad(_missing("nope.yaml"), ("the case file does not exist",)),
    "missing file, a close name exists": Bad(_next_to_example, ("did you mean 'towed_body.yaml'",)),
    "missing directory in the path": Bad(_missing("no/such/dir/case.yaml"), ("no directory",)),
    "a directory": Bad(_directory, ("is a directory", "a.yaml")),
    "a broken symbolic link": Bad(_broken_link, ("broken symbolic link",)),
    "a named pipe": Bad(_fifo, ("not a regular file",)),
    "a device": Bad(lambda t, m: Path(os.devnull), ("not a regular file",)),
    "an unreadable file": Bad(_unreadable, ("permission denied",)),
    "a NUL in the file name": Bad(lambda t, m: str(t / "a\0b.yaml"), ("cannot be opened",), cli=False),
    "a file name too long": Bad(lambda t, m: t / ("x" * 300 + ".yaml"), ("cannot be opened",)),
    "an empty path": Bad(lambda t, m: "", ("empty",), cli=False),
    "a file over the size limit": Bad(text("# " + "x" * (limits.MAX_DOCUMENT_BYTES + 10)),
                                      ("more than the limit", "bytes")),
    "invalid UTF-8": Bad(text(b"name: caf\xe9\nmodel: pitch\n"), ("not a UTF-8 text file", "line 1")),
    "UTF-16 text": Bad(text("model: pitch\n".encode("utf-16")), ("UTF-16",)),
    "a netCDF result given as a case": Bad(text(b"\x89HDF\r\n\x1a\n\x00\x00\x00"), ("netCDF",)),
    "a PNG image given as a case": Bad(text(b"\x89PNG\r\n\x1a\n\x00\x00"), ("PNG",)),
    "a NUL byte in the text": Bad(text(BASE + "\x00"), ("a NUL byte", "line 31"), 31),
    "a control character": Bad(base("name: bad-inputs", "name: bad\x07inputs"), ("U+0007",), 1),
    "an empty file": Bad(text(""), ("got an empty file",), 1),
    "only comments": Bad(text("# nothing\n\n# here\n"), ("got an empty file",), 1),
    "a null document": Bad(text("~\n"), ("a case must be a mapping",), 1),
    "a list, not a mapping": Bad(text("- model: pitch\n"), ("got a list",), 1),
    "a text, not a mapping": Bad(text("hello\n"), ("neither a YAML case",)),
    "a number, not a mapping": Bad(text("42\n"), ("got 42",), 1),
    # --- the YAML ------------------------------------------------------------------
    "two documents": Bad(text(PITCH + "---\n" + PITCH), ("another document",), 11),
    "a tab in the indentation": Bad(base("  depth: 2000", "\tdepth: 2000"), ("never tabs",), 4),
    "an unclosed bracket": Bad(base("velocity: [0.5, 0, 0]}", "velocity: [0.5, 0, 0}"),
                               ("YAML syntax error",)),
    "an unclosed quote": Bad(base("name: bad-inputs", "name: 'bad-inputs"), ("YAML syntax error",)),
    "a value with ': ' inside": Bad(base("to: sled", "to: anchor: [0, 0, -100]"),
                                    ("needs quotes",), 26),
    "bad indentation": Bad(base("  depth: 2000", "     depth: 2000"), ("YAML syntax error",)),
    "billion laughs": Bad(text(_laughs()), ("values", "refused before expanding"), 6),
    "a recursive alias": Bad(text("a: &a [1, *a]\nmodel: pitch\n"), ("recursive",), 1),
    "an undefined alias": Bad(text("model: pitch\npitch: *nothing\n"), ("anchor (&name)",), 2),
    "a duplicate anchor": Bad(text("a: &x 1\nb: &x 2\nmodel: pitch\n"), ("already defined at line 1",), 2),
    "too many aliases": Bad(text("a: &a 1\nb: [" + ", ".join(["*a"] * (limits.MAX_YAML_ALIASES + 1))
                                 + "]\nmodel: pitch\n"), ("aliases",), 2),
    "deep flow nesting": Bad(text("model: " + "[" * 5000 + "]" * 5000 + "\n"), ("levels deep",), 1),
    "deep block nesting": Bad(text("".join("  " * i + f"k{i}:\n" for i in range(200)) + "model: x\n"),
                              ("levels deep",)),
    "a python object tag": Bad(text("model: !!python/object/apply:os.system ['echo hi']\n"),
                               ("could not determine a constructor",), 1),
    "an unknown tag": Bad(text("model: !pitch x\n"), ("could not determine a constructor",), 1),
    "bad base64 in !!binary": Bad(text("name: !!binary 'zz'\nmodel: pitch\n"), ("base64",), 1),
    "a 5000-digit integer": Bad(base("segments: 100", "segments: " + "9" * 5000),
                                ("cannot read the value", "5000 characters"), 24),
    "a 13th month": Bad(base("name: bad-inputs", "name: 2024-13-01"), ("month must be in 1..12",), 1),
    "a merge of a scalar": Bad(text("<<: 1\nmodel: pitch\n"), ("merging",), 1),
    "a duplicate key": Bad(base("  mass: 1.12\n", "  mass: 1.12\n    mass: 1.5\n"),
                           ("duplicate key 'mass'", "lines 10 and 11"), 11),
    "a list as a mapping key": Bad(text("? [a, b]\n: 1\nmodel: pitch\n"), ("unhashable key",), 1),
    "a number as a name": Bad(base("  towcable:\n", "  1:\n"), ("a name must be text",), 8),
    # --- the schema ----------------------------------------------------------------
    "no model": Bad(base("model: continuum\n", ""), ("missing required key 'model'",), 1),
    "a misspelt model": Bad(base("model: continuum", "model: lumpd"), ("did you mean 'lumped'",), 2),
    "a model given as a list": Bad(base("model: continuum", "model: [continuum]"), ("is not one of",), 2),
    "an unknown top-level key": Bad(base("name: bad-inputs", "name: bad-inputs\nmodle: x"),
                                    ("unknown key 'modle'",), 2),
    "a misspelt nested key": Bad(base("diameter: 0.0173", "diamter: 0.0173"),
                                 ("did you mean 'diameter'",), 9),
    "a section written as a list": Bad(base("bodies:\n  sled:", "bodies:\n  - sled:"),
                                       ("must be a mapping",), 13),
    "a required key missing": Bad(base("    diameter: 0.0173\n", ""), ("missing required key 'diameter'",)),
    "a negative diameter": Bad(base("diameter: 0.0173", "diameter: -1"), ("greater than 0",), 9),
    "a diameter as text": Bad(base("diameter: 0.0173", "diameter: thin"), ("must be a number",), 9),
    "a NaN diameter": Bad(base("diameter: 0.0173", "diameter: .nan"), ("finite number",), 9),
    "an infinite diameter": Bad(base("diameter: 0.0173", "diameter: 1e400"), ("finite number",), 9),
    "a NaN written as text": Bad(base("diameter: 0.0173", "diameter: 'nan'"), ("finite number",), 9),
    "a boolean diameter": Bad(base("diameter: 0.0173", "diameter: yes"), ("must be a number, not true",), 9),
    "a quoted length": Bad(base("length: 1000", "length: '1000'"),
                           ("must be a number, not the text '1000'", "without quotes"), 23),
    "a quoted exponent": Bad(base("axial_stiffness: 1.2717e7", "axial_stiffness: '1e3'"),
                             ("not the text '1e3'",), 12),
    "a quoted segment count": Bad(base("segments: 100", 'segments: "100"'), ("not the text '100'",), 24),
    "a quoted vector component": Bad(base("tow_point: [0, 0, 0]", "tow_point: [0, '0', 0]"),
                                     ("not the text '0'",), 16),
    "a boolean segment count": Bad(base("segments: 100", "segments: true"), ("must be a number",), 24),
    "a fractional segment count": Bad(base("segments: 100", "segments: 2.5"), ("whole number",), 24),
    "zero segments": Bad(base("segments: 100", "segments: 0"), ("at least 1",), 24),
    "a list where a number goes": Bad(base("length: 1000", "length: [1000]"), ("must be a number",), 23),
    "a mapping where a list goes": Bad(base("tow_point: [0, 0, 0]", "tow_point: {x: 0}"),
                                       ("3 numbers",), 16),
    "a vector of 2 numbers": Bad(base("velocity: [0.5, 0, 0]", "velocity: [0.5, 0]"), ("3 numbers",), 5),
    # --- the work of a run ------------------------------------------------------------
    "a billion segments": Bad(base("segments: 100", "segments: 1e9"), ("100,000 a cable",), 24),
    "segments beyond 2^63": Bad(base("segments: 100", "segments: 18446744073709551616"),
                                ("more than the limit",), 24),
    "too many segments in all": Bad(_three_huge_cables, ("220,000 segments in all cables",)),
    "too many time steps": Bad(edits(("duration: 600", "duration: 1e8"), ("  dt: 1.0", "  dt: 0.1")),
                               ("time steps", "limit")),
    "too many node-steps": Bad(edits(("segments: 100", "segments: 50000"), ("  dt: 1.0", "  dt: 0.001"),
                                     ("output_dt: 1.0", "output_dt: 100.0")), ("node-steps",)),
    "an output over the size limit": Bad(edits(("segments: 100", "segments: 50000"),
                                               ("  dt: 1.0", "  dt: 0.1"), ("output_dt: 1.0", "output_dt: 0.1")),
        ("GiB", limits.OUTPUT_BYTES_ENV), 30),
    "a bad output limit in the environment": Bad(_bad_env, (limits.OUTPUT_BYTES_ENV, "not a size")),
    "10 000 000 000 harmonics": Bad(text(edit("harmonics: 50", "harmonics: 10000000000", PITCH)),
                                    ("harmonics is more than the limit",), 10),
    "harmonics at 2^63": Bad(text(edit("harmonics: 50", "harmonics: 9223372036854775808", PITCH)),
                             ("harmonics is more than the limit",), 10),
    "a billion time points": Bad(text(edit("harmonics: 50", "harmonics: 50\n  time_points: 1000000000",
                                           PITCH)), ("samples of the period",), 11),
    "harmonics x time points": Bad(text(edit("harmonics: 50", "harmonics: 10000\n  time_points: 100001",
                                             PITCH)), ("harmonics x time_points",), 11),
    "a billion sphere nodes": Bad(text(SPHERE + "  n_nodes: 1000000000\n"), ("nodes is more than",), 5),
    # --- numbers that overflow later arithmetic ----------------------------------------
    "diameter 1e160": Bad(base("diameter: 0.0173", "diameter: 1e160"), ("at most 1e+07 m",), 9),
    "diameter 1e-200": Bad(base("diameter: 0.0173", "diameter: 1e-200"), ("at least 1e-06 m",), 9),
    "output_dt 1.5e308": Bad(base("output_dt: 1.0", "output_dt: 1.5e308"), ("at most 1e+09 s",), 30),
    "output_dt 5e-324 (the smallest float)": Bad(base("output_dt: 1.0", "output_dt: 5e-324"),
                                                 ("at least 1e-07 s",), 30),
    "a 400-digit segment count": Bad(base("segments: 100", "segments: 1" + "0" * 400),
                                     ("more than the limit",), 24),
    "pitch natural frequency 1e300": Bad(text(edit("natural_frequency: 1.0", "natural_frequency: 1e300",
                                                   PITCH)), ("at most 10000 rad/s",), 5),
    "duration 1e12 with dt 1e-9": Bad(edits(("duration: 600", "duration: 1e12"), ("  dt: 1.0", "  dt: 1e-9")),
                                      ("at most 1e+09 s",), 28),
    "wave period 1e-200": Bad(wave("period: 8.0", "period: 1e-200"), ("at least 1e-07 s",), 6),
    "wave period 1e300": Bad(wave("period: 8.0", "period: 1e300"), ("at most 1e+09 s",), 6),
    "wave height 1e300": Bad(wave("height: 2.0", "height: 1e300"), ("at most 1e+07 m",), 6),
    "wave heading 1e300": Bad(wave("heading_deg: 180", "heading_deg: 1e300"), ("at most 1e+06 deg",), 6),
    "axial stiffness 1e300": Bad(base("axial_stiffness: 1.2717e7", "axial_stiffness: 1e300"),
                                 ("at most 1e+14 N",), 12),
    "mass per length 1e-300": Bad(base("mass: 1.12", "mass: 1e-300"), ("at least 1e-06 kg/m",), 10),
    "gravity 1e300": Bad(base("depth: 2000", "depth: 2000\n  gravity: 1e300"), ("at most 10000 m/s^2",), 5),
    "water density 1e-300": Bad(base("depth: 2000", "depth: 2000\n  water_density: 1e-300"),
                                ("at least 0.001 kg/m^3",), 5),
    "depth 1e300": Bad(base("depth: 2000", "depth: 1e300"), ("at most 1e+07 m",), 4),
    "current 1e10 m/s": Bad(base("velocity: [0.5, 0, 0]", "velocity: [1e10, 0, 0]"),
                            ("at most 1000 m/s",), 5),
    "speed 1e300 kn": Bad(base("speed: 3.0", "speed_kn: 1e300"), ("at most 2000 kn",), 18),
    "turn angle 1e300 deg": Bad(base("angle_deg: 90", "angle_deg: 1e300"), ("at most 1e+06 deg",), 19),
    "anchor at 1e300 m": Bad(base("to: sled", "to: 'anchor:[1e300, 0, -100]'"), ("at most 1e+07 m",), 26),
    "anchor at 1e999 m (infinite)": Bad(base("to: sled", "to: 'anchor:[1e999, 0, -100]'"),
                                        ("finite number",), 26),
    "body mass 1e-300 kg": Bad(base("mass: 1135", "mass: 1e-300"), ("at least 1e-06 kg",), 14),
    "pitch inertia 1e300": Bad(text(edit("inertia: 2.0e7", "inertia: 1e300", PITCH)), ("at most 1e+16",), 4),
    "pitch wave period 1e-200": Bad(text(edit("wave_period: 10.0", "wave_period: 1e-200", PITCH)),
                                    ("at least 1e-07 s",), 7),
    "lambda_inf 5": Bad(base("output_dt: 1.0", "output_dt: 1.0\n  lambda_inf: 5"), ("at most 0",), 31),
    # --- inconsistent content -------------------------------------------------------
    "dt longer than the duration": Bad(edits(("  dt: 1.0", "  dt: 1000"), ("output_dt: 1.0", "output_dt: 1000")),
                                       ("longer than the duration",), 29),
    "output_dt not a multiple of dt": Bad(base("output_dt: 1.0", "output_dt: 1.5"), ("not a multiple",), 30),
    "output_dt longer than the duration": Bad(base("output_dt: 1.0", "output_dt: 1000"),
                                              ("longer than the duration", "no step"), 30),
    "the continuum model without dt": Bad(edits(("  dt: 1.0\n", ""), ("  output_dt: 1.0\n", "")),
                                          ("needs a time step dt",)),
    "a dynamic model without simulation": Bad(text(BASE.split("simulation:")[0]), ("needs a 'simulation' block",)),
    "a dynamic model without cables": Bad(text(BASE.split("cables:")[0] + "simulation: {duration: 1, dt: 1}\n"),
                                          ("needs at least one cable",)),
    "an unknown wave type": Bad(wave("type: regular", "type: regullar"), ("not a valid",), 6),
    "a negative wave seed": Bad(base("# waves go here",
                                     "waves: {type: jonswap, hs: 2.0, tp: 8.0, seed: -1}"), ("at least 0",), 6),
    "a current profile with a repeated depth": Bad(base("current: {velocity: [0.5, 0, 0]}",
                                                        "current: {profile: [[0, 1, 0, 0], [0, 2, 0, 0]]}"),
                                                   ("appears in two rows",), 5),
    "both velocity and profile": Bad(base("current: {velocity: [0.5, 0, 0]}",
                                          "current: {velocity: [1, 0, 0], profile: [[0, 1, 0, 0]]}"),
                                     ("not both",), 5),
    "an anchor with 2 coordinates": Bad(base("to: sled", "to: 'anchor:[1, 2]'"), ("3 coordinates",), 26),
    "an anchor with words for numbers": Bad(base("to: sled", "to: 'anchor:[a, b, c]'"), ("must be 3 numbers",), 26),
    "an anchor below the seabed": Bad(base("to: sled", "to: 'anchor:[900, 0, -3000]'"), ("below the seabed",), 26),
    "an end naming nothing": Bad(base("to: sled", "to: sledd"), ("did you mean 'sled'",), 26),
    "both ends free": Bad(edits(("from: vessel", "from: free"), ("to: sled", "to: free")),
                          ("both ends are 'free'",), 21),
    "an unknown line type": Bad(base("line_type: towcable", "line_type: towcabel"),
                                ("did you mean 'towcable'",), 22),
    "two cables of one name": Bad(base("    to: sled\n", "    to: sled\n  - {name: tow, line_type: towcable, "
                                       "length: 10, segments: 1, from: sled, to: free}\n"),
                                  ("names must be unique",)),
    "an unknown track segment": Bad(base("{straight: {speed: 3.0, duration: 100}}",
                                         "{straigth: {speed: 3.0, duration: 100}}"), ("not a valid",), 18),
    "two segments in one item": Bad(base("{straight: {speed: 3.0, duration: 100}}",
                                         "{straight: {speed: 3.0, duration: 100}, turn: {radius: 1, angle_deg: 1}}"),
                                    ("own list item",), 18),
    "a turn radius without an angle": Bad(base("{turn: {radius: 640, angle_deg: 90}}",
                                               "{turn: {radius: 640, duration: 90}}"), ("give 'angle_deg'",), 19),
    "speed in m/s and knots": Bad(base("speed: 3.0", "speed: 3.0, speed_kn: 6"), ("not both",), 18),
    "weight in water above the weight in air": Bad(base("weight_in_water: 8.89", "weight_in_water: 100"),
                                                   ("exceeds the weight in air",), 11),
    "buoyancy below minus the weight": Bad(base("net_buoyancy: -4448", "net_buoyancy: -1e6"),
                                           ("negative buoyancy",), 14),
    "an elastic law with both forms": Bad(base("axial_stiffness: 1.2717e7", "axial_stiffness: 1.2717e7\n"
                                               "    elastic_law: {polynomial: [1e7], table: [[0.01, 1e5]]}"),
                                          ("exactly one of",), 13),
    "natural frequency and restoring": Bad(text(edit("natural_frequency: 1.0", "natural_frequency: 1.0\n"
                                                     "  restoring: 2.0e7", PITCH)), ("exactly one of",), 3),
    "an undamped pitch resonance": Bad(text(edit("damping_ratio: 0.1", "damping_ratio: 0", edit(
        "natural_frequency: 1.0", "natural_frequency: 0.6283185307179586", PITCH))), ("unbounded",), 5),
    "an unknown stabilizer mode": Bad(text(edit("mode: rectangular", "mode: rectangle", PITCH)),
                                      ("is not one of",), 9),
    "a sphere given both ways": Bad(text(SPHERE + "  dimensional: {flow_speed: 1, sphere_diameter: 1, "
                                         "net_buoyancy: 1, cable_diameter: 0.01, cable_length: 1, "
                                         "cable_weight: 1, line_length: 1, anchor_x: 0}\n"),
                                    ("exactly one of",), 3),
    "sphere anchors too close (x_C 0)": Bad(text(edit("x_C: -1.732", "x_C: 0", SPHERE)),
                                            ("differ by 1 cable lengths", "between 1 cable lengths and 3"), 4),
    "sphere anchors 1e-9 apart": Bad(text(edit("x_C: -1.732", "x_C: -1e-9", SPHERE)),
                                     ("cannot meet at the sphere",), 4),
    "sphere anchors out of reach": Bad(text(edit("x_C: -1.732", "x_C: -3", SPHERE)),
                                       ("reach only 3 cable lengths",), 4),
    "sphere chi 1": Bad(text(edit("RkL: 0.4}", "RkL: 0.4, chi: 1}", SPHERE)), ("must be below 1",), 4),
    "sphere with no load": Bad(text(edit("QkL: 0.45, RkL: 0.4", "QkL: 0, RkL: 0", SPHERE)),
                               ("both 0",), 4),
    "dimensional sphere anchors too close": Bad(text(edit("dimensionless: {Psi: 0.02, LoL: 2.0, x_C: -1.732, QkL: 0.45, RkL: 0.4}",
        "dimensional: {flow_speed: 0.5, sphere_diameter: 1.178, net_buoyancy: 69.19, cable_diameter: 0.01, "
        "cable_length: 100, cable_weight: 0.03075, line_length: 200, anchor_x: 50}", SPHERE)),
        ("differ by 100 m", "between 100 m and 300 m apart"), 4),
    "a body and a point of one name": Bad(base("bodies:", "points:\n  sled: {}\nbodies:"),
                                          ("names both a body and a point",)),
    "dimensions 2 with a turn": Bad(base("output_dt: 1.0", "output_dt: 1.0\n  dimensions: 2"),
                                    ("x-z plane only",), 31),
    # --- what a dynamic model would refuse when the run is set up -------------------------
    "an unknown scheme": Bad(base("output_dt: 1.0", "output_dt: 1.0\n  scheme: rk9"),
                             ("unknown continuum scheme 'rk9'", "generalized-alpha"), 31),
    "a scheme of the other model": Bad(base("output_dt: 1.0", "output_dt: 1.0\n  scheme: rk4"),
                                       ("'rk4' is a lumped scheme",), 31),
    "a factorized scheme in waves": Bad(edits(
        ("# waves go here", "waves: {type: regular, height: 2.0, period: 8.0}"),
        ("output_dt: 1.0", "output_dt: 1.0\n  scheme: factorized")), ("uniform flexible cable only",), 6),
    "a turn of given radius after a stop": Bad(base("speed: 3.0", "speed: 0"), ("needs a speed > 0",), 19),
    "a 6-DOF body without its position": Bad(edits(("model: continuum", "model: lumped"), (
        "sled: {mass: 1135, net_buoyancy: -4448, drag_area: 0.33}",
        "sled: {mass: 1135, net_buoyancy: -4448, dof: 6, inertia: [100, 100, 100]}")),
        ("needs its position",), 14),
    "an attachment at a cable end": Bad(edits(
        ("bodies:", "bodies:\n  clump: {mass: 10, net_buoyancy: -50}"),
        ("    to: sled\n", "    to: sled\n    attachments: [{body: clump, s: 0}]\n")), ("is that end's body",)),
    "an elastic law the continuum model cannot invert": Bad(base(
        "axial_stiffness: 1.2717e7", "axial_stiffness: 1.2717e7\n    elastic_law: {polynomial: [1e6, -3e6]}"),
        ("must increase with strain",), 13),
    "a JONSWAP gamma beyond its formula": Bad(base("# waves go here", "waves: {type: jonswap, hs: 2.0, tp: 8.0, "
                                                   "gamma: 100}"), ("spectrum negative",), 6),
    "a seabed too soft to hold the line": Bad(base("depth: 2000", "depth: 2000\n  seabed: {stiffness: 1e-9}"),
                                              ("more than the depth",), 5),
    "an undamped pitch on a harmonic beyond the series": Bad(text(edit(
        "harmonics: 50", "harmonics: 5", edit("damping_ratio: 0.1", "damping_ratio: 0", edit(
            "natural_frequency: 1.0", f"natural_frequency: {7 * 2 * math.pi / 10!r}", PITCH)))),
        ("beyond the 5 harmonics computed", "unbounded"), 5),
}


@pytest.fixture(params=sorted(CLASSES), ids=sorted(CLASSES))
def bad(request, tmp_path, monkeypatch):
    entry = CLASSES[request.param]
    return entry, entry.make(tmp_path, monkeypatch)


def test_there_are_at_least_80_classes():
    assert len(CLASSES) >= 80


def test_the_base_cases_are_valid():
    for source in (BASE, PITCH, SPHERE):
        assert [p for p in check_text(source) if p.severity == "error"] == []


def test_each_class_gets_its_own_error_in_bounded_time(bad):
    entry, path = bad
    start = time.perf_counter()
    problems = check_case(path)
    elapsed = time.perf_counter() - start
    errors = [p for p in problems if p.severity == "error"]
    match = [p for p in errors if all(w in p.message for w in entry.words)]
    assert match, [str(p) for p in problems]
    assert match[0].file == (str(path) if str(path) else None) or match[0].file == str(path)
    if entry.line is not None:
        assert match[0].line == entry.line, str(match[0])
    assert elapsed < SECONDS
    with pytest.raises(CaseError):
        load_case(path)


def test_kanat_validate_prints_it_and_exits_1(bad):
    entry, path = bad
    if not entry.cli:
        pytest.skip("the command line cannot take this path")
    result = CliRunner().invoke(app, ["validate", str(path)])
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output and isinstance(result.exception, SystemExit)
    assert "error" in result.output


# --- the limits themselves --------------------------------------------------------------

def test_a_quoted_number_names_its_key_path(tmp_path):
    path = tmp_path / "case.yaml"
    path.write_text(edit("axial_stiffness: 1.2717e7", "axial_stiffness: '1e3'"))
    found = [p for p in check_case(path) if "not the text" in p.message]
    assert [(p.key, p.line) for p in found] == [("line_types.towcable.axial_stiffness", 12)]


def test_output_limit_from_argument_and_environment(monkeypatch):
    big = edit("segments: 100", "segments: 50000", edit("  dt: 1.0", "  dt: 0.1",
                                                         edit("output_dt: 1.0", "output_dt: 0.1")))
    # 6001 outputs x (8 x 50001 nodes + 7 + 3 x 1 body) x 8 bytes
    expected = 8.0 * 6001 * (8 * 50001 + 7 + 3)
    assert any("GiB" in p.message for p in check_text(big))
    assert not [p for p in check_text(big, max_output_bytes=expected * 1.001) if p.severity == "error"]
    assert [p for p in check_text(big, max_output_bytes=expected * 0.999) if p.severity == "error"]
    monkeypatch.setenv(limits.OUTPUT_BYTES_ENV, "32G")
    assert not [p for p in check_text(big) if p.severity == "error"]
    with pytest.raises(CaseError, match="17.9 GiB"):
        parse_case(big, max_output_bytes="16G")


@pytest.mark.parametrize("text, value", [("4e9", 4e9), ("512M", 512 * 1024**2), ("8G", 8 * 1024**3),
                                         ("1TiB", 1024**4), (" 2 gb ", 2 * 1024**3)])
def test_parse_bytes(text, value):
    assert limits.parse_bytes(text) == value


@pytest.mark.parametrize("text", ["", "lots", "-1", "0", "nan", "inf", "1e400"])
def test_parse_bytes_refuses(text):
    with pytest.raises(ValueError):
        limits.parse_bytes(text)


def test_limits_are_far_from_every_example():
    """The examples use at most 100 segments a cable, 6000 steps and 50 harmonics: each
    limit is at least 100 times that, and every example is valid with the default limits."""
    assert limits.MAX_SEGMENTS_PER_CABLE >= 100 * 100
    assert limits.MAX_TIME_STEPS >= 100 * 6000 and limits.MAX_HARMONICS >= 100 * 50
    for path in sorted(EXAMPLES.glob("*.yaml")):
        assert [p for p in check_case(path) if p.severity == "error"] == [], path.name


def test_a_case_at_the_limits_is_accepted():
    at = edit("segments: 100", f"segments: {limits.MAX_SEGMENTS_PER_CABLE}",
              edit("output_dt: 1.0", "output_dt: 60.0"))
    assert [p for p in check_text(at) if p.severity == "error"] == []
    over = edit("segments: 100", f"segments: {limits.MAX_SEGMENTS_PER_CABLE + 1}",
                edit("output_dt: 1.0", "output_dt: 60.0"))
    assert [p.key for p in check_text(over) if p.severity == "error"] == ["cables[0].segments"]


def test_billion_laughs_is_refused_without_expanding():
    """9 levels of 9 aliases: 3.9e8 values if expanded; refused in milliseconds."""
    start = time.perf_counter()
    problems = check_text(_laughs(9))
    assert time.perf_counter() - start < 1.0
    assert "refused before expanding" in problems[0].message
    # a few aliases expanding to a modest size are fine YAML
    assert check_text(_laughs(3)) and "refused" not in " ".join(p.message for p in check_text(_laughs(3)))


def test_a_large_legitimate_table_is_read():
    """A 10 000-row current profile (350 kB) validates, in seconds."""
    rows = "".join(f"      - [{-0.1 * i:.1f}, 0.5, 0, 0]\n" for i in range(10000))
    case = edit("  current: {velocity: [0.5, 0, 0]}\n", "  current:\n    profile:\n" + rows)
    start = time.perf_counter()
    assert [p for p in check_text(case) if p.severity == "error"] == []
    assert time.perf_counter() - start < SECONDS


def test_the_limits_page_lists_every_limit_and_range():
    """docs/limits.md names every limit of the module and every unit's range as set there."""
    page = (ROOT / "docs" / "limits.md").read_text()
    for name in [n for n in dir(limits) if n.startswith("MAX_")]:
        assert f"`{name}`" in page, name
    rows = {line.split("|")[1].strip(" `"): line.split("|")[2:4] for line in page.splitlines()
            if line.startswith("| `") and line.count("|") == 5}
    for unit, sane in limits.UNIT_RANGES.items():
        floor, ceiling = (cell.strip() for cell in rows[unit])
        assert float(ceiling) == sane.high, unit
        assert (floor == "-" and sane.low == 0) or float(floor) == sane.low, unit
    assert limits.OUTPUT_BYTES_ENV in page and "max_output_bytes" in page
