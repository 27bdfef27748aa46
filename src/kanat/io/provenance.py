"""The provenance every result carries: the case itself, its hash, the version, the model.

Kept apart from :mod:`kanat.io.results` (which builds and reads xarray datasets) so that a run
streaming its result to a file never imports xarray and pandas (0.3 s of every ``kanat run``).
"""
from __future__ import annotations

import hashlib

from kanat.version import __version__


def case_sha256(case) -> str:
    """SHA-256 of what the user wrote that sets the numbers: the case's canonical JSON with every
    value equal to its default left out.

    Insensitive to YAML layout and comments, to keys written at their default values, and to keys
    a later release adds with defaults (a run started before that release resumes with it); any
    value that differs from its default, written or derived, changes it.
    """
    return _sha256(case.model_dump_json(by_alias=True, exclude_defaults=True))


def whole_case_sha256(case) -> str:
    """SHA-256 of the case's whole canonical JSON, defaults included: the ``case_sha256`` that
    earlier releases wrote, still taken for the same case when the model has not changed since
    (:func:`same_case`)."""
    return _sha256(case.model_dump_json(by_alias=True))


def case_hashes(case) -> tuple[str, str]:
    """The hashes a file written for ``case`` may carry: :func:`case_sha256`, then
    :func:`whole_case_sha256` (files of earlier releases)."""
    return case_sha256(case), whole_case_sha256(case)


def same_case(recorded: str | None, case) -> bool:
    """Whether the hash ``recorded`` in a result or checkpoint is ``case``'s (either form of
    :func:`case_hashes`)."""
    return recorded in case_hashes(case)


def _sha256(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


def case_yaml(case) -> str:
    """The case as YAML text that loads back to the same case (same :func:`case_sha256`)."""
    import yaml

    return yaml.safe_dump(case.model_dump(mode="json", by_alias=True, exclude_unset=True), sort_keys=False)


def provenance(case, *, model: str, scheme: str, wall_time_s: float = 0.0, status: str = "running", **extra) -> dict:
    """Global attributes every result file carries (case-format.md), the case itself included
    (``case_yaml``), so that a result alone reproduces its run."""
    attrs = {
        "kanat_version": __version__,
        "case_name": case.name or "",
        "case_sha256": case_sha256(case),
        "case_yaml": case_yaml(case),
        "model": model,
        "scheme": scheme,
        "wall_time_s": float(wall_time_s),
        "status": status,
        "Conventions": "CF-1.10",
    }
    attrs.update(extra)
    return attrs
