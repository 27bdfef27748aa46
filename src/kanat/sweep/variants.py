"""Case variants: the base case's YAML data with some keys set, re-validated by :mod:`kanat.io`.

Key paths are those of :mod:`kanat.model.paths` (``cables[0].length``,
``vessel.track[1].to_speed_kn``), the same as :meth:`kanat.model.Case.replace` takes.
"""
from __future__ import annotations

import copy
import json
import warnings
from pathlib import Path as FilePath

import yaml

from kanat.errors import CaseError, KanatError
from kanat.model.paths import parse_key, set_value


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
