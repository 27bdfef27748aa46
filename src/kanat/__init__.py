"""kanat: statics and dynamics of marine cable systems.

Public API
----------
load_case
    Read and validate a YAML case file (:mod:`kanat.io.case_file`).
solve_statics
    Steady state of a case (:mod:`kanat.statics`).
"""
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("kanat")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"
