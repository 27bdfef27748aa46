"""Fuzzing the case reader: every mutant of every example is a clear error or a valid case.

Each example in ``examples/`` is mutated (keys deleted, renamed or duplicated, values
replaced by other types, by huge, tiny, negative, NaN or infinite numbers and by numbers
written as text, subtrees wrapped, unwrapped or moved to the wrong place; the YAML text
cut, shuffled, re-indented or salted with YAML punctuation and control characters) and
read with :func:`kanat.io.parse_case`. The oracle is the contract of the reader: it
returns a :class:`~kanat.model.Case` or raises :class:`~kanat.errors.CaseError` carrying
at least one error that names the file; any other exception (or a ``RuntimeWarning``
from kanat, which the test configuration turns into an error) fails the test.

A second property holds the reader to what the dynamic models accept: every mutant of a
continuum or lumped example that the reader (``kanat validate``) finds valid is set up by
its model (:func:`kanat.api.dynamic_model`) without an error; a
:class:`~kanat.errors.CaseError` there is a refusal that validation missed.

The default run is derandomized (the same examples every time): 5000 mutants, 3000 of
the data and 2000 of the text, in about a minute; and 2500 mutants of the data of the
dynamic examples (some 450 of them valid, each then set up by its model) in about 30 s.
More, with a random seed (N mutants for the reader, 3 N / 10 more for the models)::

    KANAT_FUZZ_EXAMPLES=100000 python -m pytest -q tests/robustness/test_fuzz_cases.py
"""
from __future__ import annotations

import math
import os
import warnings

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kanat.api import dynamic_model
from kanat.errors import CaseError, Problem
from kanat.io import CaseWarning, parse_case
from kanat.io.yaml_loader import LineLoader
from kanat.model import Case
from kanat.model.case import DYNAMIC_MODELS

from helpers import ROOT

EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))
BASES = {p.name: yaml.load(p.read_text(), Loader=LineLoader) for p in EXAMPLES}  # noqa: S506
TEXTS = {p.name: p.read_text() for p in EXAMPLES}
FILE = "fuzz.yaml"

_REQUESTED = int(os.environ.get("KANAT_FUZZ_EXAMPLES", "0") or 0)
DATA_EXAMPLES = _REQUESTED * 3 // 5 if _REQUESTED else 3000
TEXT_EXAMPLES = _REQUESTED - DATA_EXAMPLES if _REQUESTED else 2000
SETUP_EXAMPLES = _REQUESTED * 3 // 10 if _REQUESTED else 2500
FUZZ = dict(deadline=None, database=None, derandomize=not _REQUESTED, print_blob=True,
            suppress_health_check=list(HealthCheck))

NASTY_NUMBERS = [0, -1, 1, 2, 3, 2**31, 2**53 + 1, 2**63 - 1, 2**63, 2**64, -2**63, 10**30,
                 10**400, 1e308, -1e308, 1.5e308, 1e300, 1e160, 1e20, 1e12, 1e9, 1e6,
                 5e-324, 1e-300, 1e-200, 1e-12, 1e-9, -1e-9, -0.0, 0.5, -0.5, 3.7,
                 math.nan, math.inf, -math.inf]
NASTY_TEXT = ["nan", ".nan", "NaN", "inf", "-inf", ".inf", "1e400", "-1e400", "1e-400", "1e7",
              "0x10", "0o17", "1_000", "1,5", "12:30:00", "2020-13-45", "2020-01-01", "", " ",
              "yes", "no", "on", "off", "null", "~", "true", "vessel", "free", "anchor",
              "anchor:[1, 2]", "anchor:[a, b, c]", "anchor:[1e999, 0, 0]", "anchor:[nan,0,0]",
              "anchor:[0, 0, -100]", "vessel:[0, 0, 0]", "sled", "towcable", "continuum",
              "lumped", "statics", "pitch", "regular", "jonswap", "straight", "turn",
              "generalized-alpha", "rk4", "<script>alert(1)</script>", "ü", "\t", "a" * 300,
              "x" * 5000, "\u202e", "🙂"]
KEY_WORDS = ["model", "name", "type", "kind", "segments", "length", "line_type", "from", "to",
             "diameter", "mass", "dt", "duration", "output_dt", "speed", "speed_kn", "period",
             "height", "harmonics", "time_points", "sections", "attachments", "seabed", "<<",
             "anchor", "body", "point", "offset", "profile", "velocity", "1", "", "~"]
SALT = ["\x00", "\x07", "\x1b", "\ufeff", ":", ": ", "- ", "[", "]", "{", "}", "&a ", "*a",
        "!!python/object:os.system ", "!!binary ", "!foo ", "<<: ", "'", '"', "#", "|",
        ">", "%YAML 1.1\n", "---\n", "...\n", "\t", "\n", "? ", ",", "@", "`"]

numbers = st.one_of(st.sampled_from(NASTY_NUMBERS), st.integers(),
                    st.floats(allow_nan=True, allow_infinity=True),
                    st.builds(lambda m, e: m * 10.0**e, st.floats(-10, 10), st.integers(-320, 308)))
scalars = st.one_of(numbers, st.sampled_from(NASTY_TEXT), st.text(max_size=12), st.booleans(),
                    st.none())
values = st.one_of(scalars, st.lists(scalars, max_size=5),
                   st.lists(st.lists(numbers, max_size=4), max_size=3),
                   st.dictionaries(st.one_of(st.sampled_from(KEY_WORDS), st.text(max_size=6)),
                                   scalars, max_size=3))


# --- mutations of the data -------------------------------------------------------------

def paths(node, path=()):
    """Every key path of a YAML tree (dicts and lists), the root included."""
    found = [path]
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
    for key, child in items:
        found += paths(child, path + (key,))
    return found


def get(node, path):
    for key in path:
        node = node[key]
    return node


def copy_tree(node):
    if isinstance(node, dict):
        return {k: copy_tree(v) for k, v in node.items()}
    if isinstance(node, list):
        return [copy_tree(v) for v in node]
    return node


def is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def scaled(value, factor):
    try:
        return value * factor
    except OverflowError:  # an integer of 400 digits times 1e300
        return factor


def mutate(data, tree, draw):
    """Apply one random mutation to ``tree`` in place; return the (maybe new) root.

    Half the mutations hit a number of the case (where the overflow and range bugs are).
    """
    all_paths = paths(tree)
    leaves = [p for p in all_paths if p and is_number(get(tree, p))]
    if leaves and draw(st.booleans()):
        path = draw(st.sampled_from(leaves))
        op = draw(st.sampled_from(["replace", "scale", "scale", "nasty", "nasty", "retype"]))
    else:
        path = draw(st.sampled_from(all_paths))
        op = draw(st.sampled_from(["delete", "replace", "replace", "scale", "wrap", "unwrap",
                                   "rename", "insert", "move", "retype"]))
    if not path:
        return draw(values) if op == "replace" else tree
    parent, key = get(tree, path[:-1]), path[-1]
    value = parent[key]
    if op == "delete":
        del parent[key]
    elif op == "replace":
        parent[key] = draw(values)
    elif op == "nasty":
        parent[key] = draw(st.sampled_from(NASTY_NUMBERS))
    elif op == "scale":
        factor = draw(st.sampled_from([1e300, 1e-300, 1e160, 1e-200, -1, 1e9, 1e-9, 2**64, 0]))
        parent[key] = scaled(value, factor) if is_number(value) else factor
    elif op == "wrap":
        parent[key] = draw(st.sampled_from([[value], {draw(st.sampled_from(KEY_WORDS)): value},
                                            [value, value]]))
    elif op == "unwrap" and isinstance(value, (dict, list)) and value:
        parent[key] = next(iter(value.values())) if isinstance(value, dict) else value[0]
    elif op == "rename" and isinstance(parent, dict):
        new = draw(st.one_of(st.sampled_from(KEY_WORDS), st.text(max_size=8),
                             st.just(str(key)[:-1] if str(key) else "x"), st.integers()))
        parent[new] = parent.pop(key)
    elif op == "insert":
        target = value if isinstance(value, (dict, list)) else parent
        if isinstance(target, dict):
            target[draw(st.sampled_from(KEY_WORDS))] = draw(values)
        else:
            target.append(draw(values))
    elif op == "move":
        parent[key] = copy_tree(get(tree, draw(st.sampled_from(all_paths))))
    elif op == "retype":
        parent[key] = str(value) if not isinstance(value, str) else draw(numbers)
    return tree


# --- mutations of the text -------------------------------------------------------------

def mutate_text(text, draw):
    """Apply one random edit to the YAML text."""
    lines = text.split("\n")
    i = draw(st.integers(0, len(lines) - 1))
    op = draw(st.sampled_from(["duplicate", "delete", "salt", "salt", "indent", "swap",
                               "truncate", "alias"]))
    if op == "duplicate":
        lines.insert(i, lines[i])
    elif op == "delete":
        del lines[i]
    elif op == "salt":
        column = draw(st.integers(0, len(lines[i])))
        lines[i] = lines[i][:column] + draw(st.sampled_from(SALT)) + lines[i][column:]
    elif op == "indent":
        lines[i] = (" " * draw(st.integers(0, 6))) + lines[i].lstrip(" ")
    elif op == "swap":
        j = draw(st.integers(0, len(lines) - 1))
        lines[i], lines[j] = lines[j], lines[i]
    elif op == "truncate":
        return text[:draw(st.integers(0, len(text)))]
    elif op == "alias" and ":" in lines[i]:
        head, _, value = lines[i].partition(":")
        lines[i] = head + ": " + draw(st.sampled_from(["&a " + value.strip(), "*a", "*b",
                                                       "&a [*a]", "{<<: *a}"]))
    return "\n".join(lines)


# --- the contract ----------------------------------------------------------------------

def read(text: str) -> Case | CaseError:
    """Read a mutant; any exception but CaseError propagates and fails the test."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", CaseWarning)
        try:
            return parse_case(text, FILE)
        except CaseError as error:
            return error


def assert_contract(text: str) -> None:
    outcome = read(text)
    if isinstance(outcome, CaseError):
        assert outcome.problems and all(isinstance(p, Problem) for p in outcome.problems)
        errors = [p for p in outcome.problems if p.severity == "error"]
        assert errors, outcome.problems
        assert all(p.file == FILE and isinstance(p.message, str) and p.message for p in errors)
        assert all(p.line is None or 1 <= p.line <= text.count("\n") + 2 for p in errors)
    else:
        assert isinstance(outcome, Case)


def dump(tree) -> str:
    return yaml.safe_dump(tree, sort_keys=False, allow_unicode=True, width=100)


@pytest.mark.slow
@settings(max_examples=DATA_EXAMPLES, **FUZZ)
@given(st.sampled_from(sorted(BASES)), st.integers(1, 3), st.data())
def test_mutated_case_data_is_an_error_or_a_case(name, count, data):
    tree = copy_tree(BASES[name])
    for _ in range(count):
        tree = mutate(data, tree, data.draw)
    assert_contract(dump(tree))


@pytest.mark.slow
@settings(max_examples=TEXT_EXAMPLES, **FUZZ)
@given(st.sampled_from(sorted(TEXTS)), st.integers(1, 3), st.data())
def test_mutated_case_text_is_an_error_or_a_case(name, count, data):
    text = TEXTS[name]
    for _ in range(count):
        text = mutate_text(text, data.draw)
    assert_contract(text)


# --- validation and the dynamic models accept the same cases ----------------------------

DYNAMIC = sorted(name for name, tree in BASES.items()
                 if isinstance(tree, dict) and tree.get("model") in DYNAMIC_MODELS)


def assert_set_up(text: str) -> None:
    """A mutant that validates is set up by its dynamic model without an error."""
    outcome = read(text)
    if not isinstance(outcome, Case) or outcome.model not in DYNAMIC_MODELS:
        return
    try:
        dynamic_model(outcome)
    except CaseError as error:
        pytest.fail(f"kanat validate accepts this case but its {outcome.model} model refuses it:\n"
                    f"{error}\n--- the case ---\n{text}")


@pytest.mark.slow
@settings(max_examples=SETUP_EXAMPLES, **FUZZ)
@given(st.sampled_from(DYNAMIC), st.integers(1, 3), st.data())
def test_a_mutant_that_validates_is_set_up_by_its_model(name, count, data):
    tree = copy_tree(BASES[name])
    for _ in range(count):
        tree = mutate(data, tree, data.draw)
    assert_set_up(dump(tree))


@pytest.mark.parametrize("name", sorted(TEXTS))
def test_every_example_is_valid_unmutated(name):
    """The fuzzing starts from valid cases (else every mutant would be an error)."""
    assert isinstance(read(TEXTS[name]), Case)
