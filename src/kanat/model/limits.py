"""Named limits that keep the work of a case bounded and its numbers in a sane range.

A case file is user input: a typo (``segments: 1e9``, ``dt: 1e-9``) or a hostile file
(a billion-laughs YAML) must be refused by ``kanat validate`` with a message, never by an
out-of-memory kill, an overflow deep inside a solver or a run that makes no progress.
Every limit here is named, with the reason for its value; the checks that apply them are
in :mod:`kanat.model.checks` (case contents) and :mod:`kanat.io.yaml_loader` (the YAML
text). The limits are far from every real case: the examples use at most 100 segments a
cable, 6000 steps and 50 harmonics.

Public names
------------
MAX_DOCUMENT_BYTES, MAX_YAML_DEPTH, MAX_YAML_NODES, MAX_YAML_ALIASES
    The YAML text.
MAX_SEGMENTS_PER_CABLE, MAX_SEGMENTS_TOTAL, MAX_TIME_STEPS, MAX_NODE_STEPS
    The work of a run.
WARN_NODE_STEPS, NODE_STEPS_ENV, max_node_steps, FASTEST_NODE_STEP_S
    When a run's length is worth a warning; the node-step limit in force (configurable).
EXPLICIT_STABILITY, EXPLICIT_SAFETY
    The explicit lumped schemes' stability limits (the estimated cost of their runs).
MAX_HARMONICS, MAX_TIME_POINTS, MAX_PITCH_SAMPLES
    The pitch problem's Fourier series.
DEFAULT_MAX_OUTPUT_BYTES, OUTPUT_BYTES_ENV, max_output_bytes
    The estimated size of a result file (configurable).
UNIT_RANGES, MAX_MAGNITUDE, Range
    The sane range of every physical quantity, by its unit.
"""
from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass

# --- the YAML text -------------------------------------------------------------------

MAX_DOCUMENT_BYTES = 1024**2
"""Largest case file [bytes]: 1 MiB. Case files are a few kB; a current profile of 20 000
rows is 0.6 MB. Long tables belong in files of their own."""

MAX_YAML_DEPTH = 32
"""Deepest nesting of YAML mappings and lists. The deepest real key,
``line_types.NAME.elastic_law.table[i][j]``, is 5 levels down; Python's recursion
(about 1000 frames) would fail near 300."""

MAX_YAML_NODES = 200_000
"""Most values (scalars, lists and mappings) in a document, counting each alias as a copy
of what it names. Reading and validating a case costs about 15 us a value (libyaml's
parser, Python construction and pydantic), so 200 000 values are 3 s; a 20 000-row
current profile is 100 000 values. A billion-laughs file (9 aliases of 9 aliases ... 9
levels deep: 3.9e8 values) is refused from the parser's events, before anything is
built or expanded."""

MAX_YAML_ALIASES = 10_000
"""Most alias uses (``*name``) in a document; a case reuses a line type or a track
segment a handful of times."""

# --- the work of a run ---------------------------------------------------------------

MAX_SEGMENTS_PER_CABLE = 100_000
"""Most elements of one cable: 10 cm elements over 10 km. The continuum model converges
by 1000 segments (``docs/continuum.md``) and costs 2-7 ms a step there
(``benchmarks/RESULTS.md``); 100 000 is 0.2-0.7 s a step."""

MAX_SEGMENTS_TOTAL = 200_000
"""Most elements of all cables together (two cables at the per-cable limit): the Newton
matrices and state of the models take about 1 kB a node, 200 MB here."""

MAX_TIME_STEPS = 200_000_000
"""Most time steps, ``duration / dt``. A 3-hour storm at dt = 1e-4 s (a small step for a
stiff chain in an explicit scheme) is 1.08e8 steps; every step costs at least a few
microseconds of Python, so 2e8 steps is already hours."""

MAX_NODE_STEPS = 2e10
"""Most node-steps, ``(segments + cables) x duration / dt``: at the measured cost of
0.1 us (compiled lumped model) to 7 us (3-D continuum model, ``benchmarks/RESULTS.md``)
per node and step, 2e10 is half an hour to a day and a half of one core. A 3-hour storm
of a 1000-segment line at dt = 0.01 s is 1.1e9."""

WARN_NODE_STEPS = 1e9
"""Node-steps above which ``kanat validate`` warns that a run will be long: 2 minutes
(compiled lumped model) to 2 hours (3-D continuum model) of one core."""

NODE_STEPS_ENV = "KANAT_MAX_NODE_STEPS"
"""Environment variable overriding :data:`MAX_NODE_STEPS` (a number, ``1e11``); ``kanat run
--max-node-steps`` and ``kanat validate --max-node-steps`` set it for one command."""

FASTEST_NODE_STEP_S = 1e-7
"""Wall time of one node-step of the compiled lumped model [s], the cheapest measured
(``benchmarks/RESULTS.md``): what a number of node-steps costs at the very least."""

EXPLICIT_STABILITY = {"rk4": 2.8, "abm4": 0.3}
"""Largest stable ``|lambda h|`` of the lumped model's explicit schemes (their
``stability_limit``, :mod:`kanat.lumped.integrators`, which reads it from here): RK4's
imaginary-axis bound 2 sqrt(2) = 2.83 (real axis 2.79); ABM4 (PECE) 0.3, weakly unstable
on the imaginary axis beyond."""

EXPLICIT_SAFETY = 0.8
"""Margin below the stability limit at which an explicit scheme steps (:mod:`kanat.lumped.stepping`)."""

MAX_HARMONICS = 10_000
"""Most harmonics of the pitch problem's Fourier series: the rectangular law's coefficients
fall as 1/n, so N harmonics leave an error near 1/N of the moment; 50 (the default) give
1e-3 in pitch (``tests/vessel/test_pitch.py``)."""

MAX_TIME_POINTS = 1_000_001
"""Most samples of the steady pitch period (401 by default)."""

MAX_PITCH_SAMPLES = 10_000_000
"""Most ``harmonics x time_points``: the series is evaluated as one array of that many
numbers (80 MB in float64) per mode."""

# --- the result file -----------------------------------------------------------------

DEFAULT_MAX_OUTPUT_BYTES = 2 * 1024**3
"""Largest estimated result of a dynamic run [bytes]: 2 GiB, which a laptop can write,
read back and plot. Raise it with :data:`OUTPUT_BYTES_ENV` or the ``max_output_bytes``
argument of :func:`kanat.load_case` / :func:`kanat.io.check_case`."""

OUTPUT_BYTES_ENV = "KANAT_MAX_OUTPUT_BYTES"
"""Environment variable overriding :data:`DEFAULT_MAX_OUTPUT_BYTES` (a number of bytes,
``4e9``, or with a binary suffix: ``512M``, ``8G``, ``1T``)."""

OUTPUT_VALUES_PER_NODE = 8
"""Numbers stored per node and output step: position (3), velocity (3), tension, and the
tension of the element that follows the node."""

OUTPUT_VALUES_PER_BODY = 3
"""Numbers stored per body and output step: its position."""

OUTPUT_VALUES_PER_STEP = 7
"""Numbers stored once per output step: time, tow point (3), heading, pitch, Newton
iterations."""

_SUFFIXES = {"": 1, "K": 1024, "M": 1024**2, "G": 1024**3, "T": 1024**4}
_SIZE = re.compile(r"^\s*([0-9.eE+-]+)\s*([KMGT]?)(?:I?B)?\s*$", re.I)


def parse_bytes(text: str) -> float:
    """A size in bytes from ``"4e9"``, ``"512M"``, ``"8G"``, ``"1TiB"`` (binary suffixes).

    Raises
    ------
    ValueError
        When ``text`` is not a positive, finite size.
    """
    match = _SIZE.match(str(text))
    if match is None:
        raise ValueError(text)
    value = float(match[1]) * _SUFFIXES[match[2].upper()]
    if not math.isfinite(value) or value <= 0:
        raise ValueError(text)
    return value


def max_output_bytes(value: float | str | None = None) -> float:
    """The output-size limit in force [bytes].

    Parameters
    ----------
    value : float, str or None
        An explicit limit (a number of bytes or a string for :func:`parse_bytes`); None:
        the environment variable :data:`OUTPUT_BYTES_ENV`, else
        :data:`DEFAULT_MAX_OUTPUT_BYTES`.

    Raises
    ------
    ValueError
        When the argument or the environment variable is not a positive size; the message
        names where the bad value came from.
    """
    if value is None:
        env = os.environ.get(OUTPUT_BYTES_ENV, "").strip()
        if not env:
            return float(DEFAULT_MAX_OUTPUT_BYTES)
        try:
            return parse_bytes(env)
        except ValueError:
            raise ValueError(f"the environment variable {OUTPUT_BYTES_ENV}={env!r} is not a "
                             "size in bytes (e.g. 4e9, 512M, 8G)") from None
    try:
        return parse_bytes(value) if isinstance(value, str) else _positive(value)
    except (TypeError, ValueError):
        raise ValueError(f"max_output_bytes={value!r} is not a size in bytes "
                         "(e.g. 4e9, '512M', '8G')") from None


def max_node_steps() -> float:
    """The node-step limit in force: :data:`NODE_STEPS_ENV` when set, else :data:`MAX_NODE_STEPS`.

    Raises
    ------
    ValueError
        When the environment variable is not a number above 0.
    """
    env = os.environ.get(NODE_STEPS_ENV, "").strip()
    if not env:
        return MAX_NODE_STEPS
    try:
        return _positive(env)
    except ValueError:
        raise ValueError(f"the environment variable {NODE_STEPS_ENV}={env!r} is not a number of "
                         "node-steps above 0 (e.g. 1e11)") from None


def _positive(value: float) -> float:
    value = float(value)
    if not math.isfinite(value) or value <= 0:
        raise ValueError(value)
    return value


# --- the sane range of each physical quantity -----------------------------------------

@dataclass(frozen=True)
class Range:
    """Sane magnitudes of one kind of quantity.

    Attributes
    ----------
    high : float
        Largest magnitude ``|x|`` of any value of this unit.
    low : float
        Smallest value of a quantity that must be positive (a length, a mass, a period, a
        time step: a scale that the solvers divide by); 0 for none. Signed quantities and
        those that may be 0 have no floor.
    what : str
        Why: a sentence on what the range spans, quoted in messages.
    """

    high: float
    low: float
    what: str


UNIT_RANGES: dict[str, Range] = {
    "m": Range(1e7, 1e-6, "lengths range from a 1 um fibre to 10 000 km"),
    "m^2": Range(1e8, 1e-10, "areas range up to 10 km x 10 km"),
    "s": Range(1e9, 1e-7, "times range from 0.1 us to 30 years"),
    "kg": Range(1e10, 1e-6, "masses range from 1 mg to ten million tonnes"),
    "kg/m": Range(1e5, 1e-6, "masses per length range from a fishing line to 100 t/m"),
    "kg/m^3": Range(1e5, 1e-3, "densities range from a gas to 100 t/m^3"),
    "kg/m^2": Range(1e6, 0.0, "dimensional drag coefficients stay below 1e6 kg/m^2"),
    "kg m^2": Range(1e16, 1e-9, "a 500 000 t ship's pitch inertia is about 5e12 kg m^2"),
    "m/s": Range(1e3, 1e-9, "speeds stay below 1000 m/s; sound in water travels at 1500"),
    "kn": Range(2e3, 1e-9, "speeds stay below 2000 kn"),
    "m/s^2": Range(1e4, 1e-6, "accelerations range up to 1000 g"),
    "N": Range(1e14, 1e-3, "a steel bar of 1 m^2 section has EA = 2e11 N"),
    "N/m": Range(1e8, 0.0, "the heaviest chains weigh about 1e4 N/m"),
    "N s": Range(1e14, 0.0, "axial damping stays below 1e14 N s"),
    "N m": Range(1e16, 0.0, "a ship's wave moments stay below 1e12 N m"),
    "N m/rad": Range(1e18, 1e-9, "a ship's pitch restoring is about 1e12 N m/rad"),
    "N m s/rad": Range(1e18, 1e-12, "damping gains stay below 1e18 N m s/rad"),
    "rad/s": Range(1e4, 1e-6, "angular frequencies range over periods from 0.6 ms to 70 days"),
    "deg": Range(1e6, 0.0, "angles range up to 2777 turns"),
    "deg/s": Range(1e4, 1e-9, "turn rates range from 1e-9 to 1e4 deg/s"),
    "-": Range(1e9, 1e-12, "dimensionless numbers range from 1e-12 to 1e9"),
}
"""Sane range of every quantity by the unit its field declares
(:func:`kanat.model._base.quantity`). The bounds are decades beyond any marine cable
system and keep products of a few quantities finite in double precision (squares of
1e18 are 1e36, far from the 1.8e308 overflow), so that no check or solver overflows."""

MAX_MAGNITUDE = 1e18
"""Largest magnitude of a number of a unit not in :data:`UNIT_RANGES` (a new key)."""

GENERIC_RANGE = Range(MAX_MAGNITUDE, 0.0, "no number of a case exceeds 1e18")
"""The range used for units not in :data:`UNIT_RANGES`."""


def unit_range(unit: str | None) -> Range:
    """The sane range of a quantity of ``unit`` (:data:`GENERIC_RANGE` if unknown)."""
    return UNIT_RANGES.get(unit or "", GENERIC_RANGE)


@dataclass(frozen=True)
class Quantity:
    """One number of a validated case, with what is known of it.

    Attributes
    ----------
    path : tuple
        Key path as written in the case file (``("cables", 0, "length")``).
    value : float
    unit : str or None
        The unit its field declares (a column's unit for table rows).
    positive : bool
        Its field must be strictly positive (a scale: it has a floor).
    """

    path: tuple
    value: float
    unit: str | None
    positive: bool


def _field_facts(info) -> tuple[str | None, bool]:
    """Declared unit and strict positivity of a pydantic field."""
    extra = info.json_schema_extra
    unit = extra.get("unit") if isinstance(extra, dict) else None
    positive = any(getattr(m, "gt", None) is not None and m.gt >= 0 for m in info.metadata)
    return unit, positive


def _column_unit(unit: str | None, column: int) -> str | None:
    """Unit of one column of a table field whose unit lists the columns (``"m, m/s"``)."""
    if unit is None or ", " not in unit:
        return unit
    units = unit.split(", ")
    return units[min(column, len(units) - 1)]


def _values(value, path: tuple, unit: str | None, positive: bool, column: int | None = None):
    """Numbers inside one field value (number, tuple, row, dict or nested model)."""
    if isinstance(value, bool) or value is None:
        return
    if isinstance(value, float):
        yield Quantity(path, value, _column_unit(unit, column or 0), positive)
    elif isinstance(value, (tuple, list)):
        rows = any(isinstance(v, (tuple, list)) for v in value)
        for i, item in enumerate(value):
            yield from _values(item, path + (i,), unit, positive, None if rows else i)
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from _values(item, path + (key,), unit, positive)
    elif hasattr(type(value), "model_fields"):
        yield from iter_quantities(value, path)


def iter_quantities(model, path: tuple = ()):
    """Every float written in a validated model, recursively, at its case-file key path.

    Only fields the case sets are visited: defaults are sane, and values derived by the
    model (a cable's totals from its sections) are checked where they were written.
    Integer fields (counts, seeds) are left to their own limits. A track segment's name
    (``straight``) is put in its path as the case file writes it; a cable end's fields
    are reported at the end (``cables[0].from``), where ``anchor:[x, y, z]`` is written.

    Parameters
    ----------
    model : pydantic.BaseModel
    path : tuple
        Key path of ``model`` in the case.

    Yields
    ------
    Quantity
    """
    segment_key = getattr(model, "KEY", "")
    if isinstance(segment_key, str) and segment_key:
        path = path + (segment_key,)
    hidden = type(model).__name__ == "CableEnd"
    written = model.model_fields_set
    for name, info in type(model).model_fields.items():
        if name not in written:
            continue
        unit, positive = _field_facts(info)
        here = path if hidden else path + (info.alias or name,)
        yield from _values(getattr(model, name), here, unit, positive)
