"""Optional parts of kanat and the pip extra that brings each.

The base install (``pip install kanat``, or ``pip install -e .`` in a checkout) reads cases,
solves statics, runs the dynamic models and writes results. Pictures, HTML reports, parameter
studies on a cluster and VTK export need more packages, each group behind an extra:

=========  ==========================  ==============================================
extra      packages                    needed by
=========  ==========================  ==============================================
plot       matplotlib                  ``--plot`` options, the study figures
report     plotly, jinja2              ``kanat report``, ``kanat validate-suite --html``
studies    dask[distributed]           studies run on workers (``--workers``)
vtk        meshio                      ``kanat export --format vtk``
all        all of the above
=========  ==========================  ==============================================

A verb that needs one calls :func:`require` before importing the package, so a missing extra
stops it with one sentence naming the command that installs it, never a traceback.
"""
from __future__ import annotations

import importlib
import importlib.util
from types import ModuleType

from kanat.errors import KanatError

EXTRAS = {
    "plot": ("matplotlib",),
    "report": ("plotly", "jinja2"),
    "studies": ("dask", "distributed"),
    "vtk": ("meshio",),
}
"""The importable packages each extra installs."""


def require(extra: str, module: str, feature: str | None = None) -> ModuleType:
    """Import ``module`` (one that extra ``extra`` installs) or stop with the pip command.

    Parameters
    ----------
    extra : str
        A key of :data:`EXTRAS`.
    module : str
        The module to import, e.g. ``"matplotlib.figure"`` or ``"dask.distributed"``.
    feature : str, optional
        What needs it, for the message (``"kanat report"``, ``"--plot"``).

    Returns
    -------
    module

    Raises
    ------
    KanatError
        The module cannot be imported; the message names the extra and the pip command.
    """
    if extra not in EXTRAS:
        raise ValueError(f"no extra named '{extra}'; valid: {', '.join(EXTRAS)}")
    try:
        return importlib.import_module(module)
    except ImportError as error:
        package = (error.name or module).split(".")[0]
        who = feature or f"this part of kanat ({module})"
        raise KanatError(f"{who} needs the optional package '{package}', which the base install leaves out; "
                         f"install it with: pip install 'kanat[{extra}]' (in a checkout: "
                         f"pip install -e '.[{extra}]'), or everything with 'kanat[all]'") from None


def available(extra: str) -> bool:
    """Whether every package of ``extra`` can be imported (without importing them)."""
    return all(importlib.util.find_spec(name) is not None for name in EXTRAS[extra])
