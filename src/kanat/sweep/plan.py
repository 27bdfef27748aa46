"""A study's plan: the cartesian product of the varied values, one validated variant per case.

Cases are numbered in the order of the product, the first key varying slowest
(``itertools.product``), and named ``case003_to_speed_kn=8_period=5.6`` (index, then each
varied key's short label and value), a name that is safe as a file name: every character
outside ``[A-Za-z0-9._=+-]`` becomes ``-`` (so ``--vary name=../../x`` gives
``case000_name=..-..-x``, one file name in the study's folders), the label is cut at
:data:`MAX_LABEL` characters, and the index keeps names unique.
"""
from __future__ import annotations

import hashlib
import itertools
import json
import re
from dataclasses import dataclass, field

from kanat.errors import KanatError
from kanat.sweep.values import format_value, parse_values
from kanat.model.run_checks import result_bytes
from kanat.sweep.variants import base_data, parse_key, short_labels, validate_variant, variant_text

MAX_CASES = 100_000
"""Largest study (a guard against typos in ranges)."""

MAX_LABEL = 120
"""Longest label after the index in a case name (file names stay far below 255 bytes)."""

_UNSAFE = re.compile(r"[^A-Za-z0-9._=+-]+")


@dataclass(frozen=True)
class CaseSpec:
    """One case of a study.

    Attributes
    ----------
    index : int
        Position in the product (0-based).
    name : str
        File-name stem of its case, result and record files.
    parameters : dict
        Key path -> value of every varied key.
    text : str
        The variant's case file (YAML).
    error : str or None
        Why the variant is not a valid case (then it is recorded as failed, never run).
    result_bytes : float
        Estimated size of its result file [bytes] (:func:`kanat.model.run_checks.result_bytes`).
    """

    index: int
    name: str
    parameters: dict
    text: str
    error: str | None = None
    result_bytes: float = 0.0


@dataclass(frozen=True)
class StudyPlan:
    """Every case of a study and what defines it.

    Attributes
    ----------
    base : str
        Base case file (or ``<case>``).
    values : dict
        Key path -> list of values, in the order given.
    cases : list of CaseSpec
    """

    base: str
    values: dict
    cases: list = field(default_factory=list)
    base_sha256: str = ""

    @property
    def keys(self) -> list[str]:
        return list(self.values)

    def manifest(self) -> dict:
        """What identifies the study on disk (``study.json``)."""
        return {"base_case": self.base, "base_sha256": self.base_sha256, "vary": self.values,
                "cases": [{"index": c.index, "name": c.name, "parameters": c.parameters} for c in self.cases]}


def case_name(index: int, parameters: dict, labels: dict, width: int) -> str:
    """``case003_to_speed_kn=8_period=5.6``: index and every varied value, file-name safe."""
    label = _UNSAFE.sub("-", "_".join(f"{labels[k]}={format_value(v)}" for k, v in parameters.items()))
    return f"case{index:0{width}d}_{label[:MAX_LABEL]}"


def plan_study(case, vary: dict) -> StudyPlan:
    """Build and validate every variant of a study.

    Parameters
    ----------
    case : path-like, kanat.model.Case or dict
        The base case (see :func:`kanat.sweep.variants.base_data`).
    vary : dict
        Key path -> values (a list, or text in the syntax of :mod:`kanat.sweep.values`).

    Returns
    -------
    StudyPlan

    Raises
    ------
    KanatError or CaseError
        When nothing is varied, a key path cannot be reached, the study is too large, or
        no variant at all is a valid case (the first one's problems, naming the key).
    """
    if not vary:
        raise KanatError("nothing to vary: give at least one KEY=VALUES (e.g. --vary environment.waves.period=5:8:1)")
    data, base = base_data(case)
    values = {key.strip(): parse_values(spec, key) for key, spec in vary.items()}
    for key in values:
        parse_key(key)
    count = 1
    for v in values.values():
        count *= len(v)
    if count > MAX_CASES:
        raise KanatError(f"{count} cases; a study holds at most {MAX_CASES}: vary fewer values")
    variant_text(data, {key: v[0] for key, v in values.items()})    # a key path that cannot be reached stops here
    labels, width = short_labels(list(values)), max(3, len(str(count - 1)))
    cases = []
    for index, combination in enumerate(itertools.product(*values.values())):
        parameters = dict(zip(values, combination))
        name = case_name(index, parameters, labels, width)
        try:
            text = variant_text(data, parameters)
        except KanatError as problem:                # a value that breaks the path of another key
            cases.append(CaseSpec(index, name, parameters, "", f"{base} [{name}]: {problem}"))
            continue
        variant, error = validate_variant(text, f"{base} [{name}]")
        size = 0.0 if variant is None else result_bytes(variant)
        cases.append(CaseSpec(index, name, parameters, text, error, size))
    if all(c.error for c in cases):
        raise KanatError(f"no case of the study is valid; the first one:\n{cases[0].error}")
    sha = hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()
    return StudyPlan(base, values, cases, sha)
