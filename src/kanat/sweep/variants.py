"""Case variants: the base case's YAML data with some keys set, re-validated by :mod:`kanat.io`.

Key paths are written as in the case file and in kanat's error messages:
``environment.waves.period``, ``line_types.towcable.axial_stiffness``,
``cables[0].length``, ``vessel.track[1].to_speed_kn``. A track segment written as a
one-key mapping (``{speed_step: {to_speed_kn: 10}}``) is entered without naming its key,
so ``vessel.track[1].to_speed_kn`` reaches ``to_speed_kn`` there; naming it
(``vessel.track[1].speed_step.to_speed_kn``) works too. The last key of a path may be
absent from the base case (it is added, and validation says whether it is a valid key);
missing mappings on the way are added too.
"""
from __future__ import annotations

import copy
import json
import re
import warnings
from pathlib import Path as FilePath

import yaml

from kanat.errors import CaseError, KanatError
from kanat.model.paths import key_path

_TOKEN = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def parse_key(key: str) -> tuple:
    """``"vessel.track[1].to_speed_kn"`` -> ``("vessel", "track", 1, "to_speed_kn")``.

    Raises
    ------
    KanatError
        For an empty key or one that does not read back as written.
    """
    path = tuple(int(index) if index else name for name, index in _TOKEN.findall(key.strip()))
    if not path or key_path(path) != key.strip():
        raise KanatError(f"'{key}' is not a key path; write it as in the case file, e.g. "
                         "environment.waves.period or vessel.track[1].to_speed_kn")
    return path


def _child(node, elem, done: tuple, last: bool):
    """The container holding ``elem`` below ``node`` (entering one-key wrappers), creating it if needed."""
    where = key_path(done) or "the case"
    if isinstance(elem, int):
        if not isinstance(node, list):
            raise KanatError(f"{where}: [{elem}] needs a list there, but it is {_kind(node)}")
        if not 0 <= elem < len(node):
            raise KanatError(f"{key_path(done + (elem,))}: {where} has {len(node)} item(s), "
                             f"indices 0 to {len(node) - 1}")
        return node
    if not isinstance(node, dict):
        raise KanatError(f"{where}: '{elem}' needs a mapping there, but it is {_kind(node)}")
    if elem in node:
        return node
    if len(node) == 1:
        (wrapped,) = node.values()
        if isinstance(wrapped, dict) and (elem in wrapped or last):
            return wrapped                              # {speed_step: {to_speed_kn: ...}}
    if not last:
        node[elem] = {}
    return node


def _kind(value) -> str:
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a mapping"
    return f"the value {value!r}"


def set_value(data: dict, key: str, value) -> None:
    """Set ``key`` (a key path) to ``value`` in case data, in place.

    Raises
    ------
    KanatError
        Naming the key path when it cannot be reached in the data.
    """
    path = parse_key(key)
    node = data
    for i, elem in enumerate(path):
        last = i == len(path) - 1
        node = _child(node, elem, path[:i], last)
        if last:
            node[elem] = value
        else:
            node = node[elem]


def base_data(case) -> tuple[dict, str]:
    """The YAML data of a base case and the name used for it in messages.

    Parameters
    ----------
    case : path-like, kanat.model.Case or dict
        A case file (its data as written: key paths in case-file terms), a validated
        :class:`~kanat.model.Case` (its canonical data, units converted to SI; track
        segments become ``{kind: speed_step, to_speed: ...}``), or the data itself.
    """
    from kanat.io.yaml_loader import load_yaml
    from kanat.model import Case

    if isinstance(case, Case):
        return json.loads(case.model_dump_json(by_alias=True, exclude_unset=True)), case.name or "<case>"
    if isinstance(case, dict):
        return copy.deepcopy(case), "<case>"
    path = FilePath(case)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise KanatError(f"cannot read the base case {path}: {error.strerror}") from None
    doc = load_yaml(text, str(path))
    if doc.problems or not isinstance(doc.data, dict):
        raise CaseError(doc.problems) if doc.problems else KanatError(f"{path}: not a case (a YAML mapping)")
    return doc.data, str(path)


def variant_text(data: dict, assignments: dict) -> str:
    """YAML text of ``data`` with every ``key -> value`` of ``assignments`` set."""
    edited = copy.deepcopy(data)
    for key, value in assignments.items():
        set_value(edited, key, value)
    return yaml.safe_dump(edited, sort_keys=False, default_flow_style=None, width=120)


def validate_variant(text: str, label: str):
    """Validate a variant's YAML through :func:`kanat.io.parse_case` (warnings silenced).

    Returns
    -------
    (Case or None, str or None)
        The case, or None and the validation message naming the key. Any other exception
        from validation is a message too (naming its type): one variant never stops a study.
    """
    from kanat.io import parse_case

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return parse_case(text, file=label), None
    except KanatError as error:
        return None, str(error)
    except Exception as error:  # noqa: BLE001 - recorded as the variant's failure, never raised
        return None, f"{label}: the case could not be validated ({type(error).__name__}: {error})"


def short_labels(keys: list[str]) -> dict[str, str]:
    """A short label per key path for file names: the last key, or more where two clash."""
    labels = {}
    for key in keys:
        parts = [str(p) for p in parse_key(key) if not isinstance(p, int)]
        depth = 1
        while depth < len(parts) and sum(
                [str(q) for q in parse_key(k) if not isinstance(q, int)][-depth:] == parts[-depth:]
                for k in keys) > 1:
            depth += 1
        labels[key] = ".".join(parts[-depth:])
    return labels
