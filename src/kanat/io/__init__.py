"""Files in and out: YAML case files (the only place with string keys) and results.

:func:`load_case`, :func:`parse_case` and :func:`check_case` read cases
(:mod:`kanat.io.case_file`); line-aware YAML loading is in :mod:`kanat.io.yaml_loader`.
"""
from .case_file import CaseWarning, check_case, check_text, load_case, parse_case

__all__ = ["CaseWarning", "check_case", "check_text", "load_case", "parse_case"]
