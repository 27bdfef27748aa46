"""Pictures and HTML pages of results and studies.

The package is itself the public API's ``report`` function::

    import kanat
    ds = kanat.simulate(kanat.load_case("examples/speed_step_2d.yaml"))
    kanat.report(ds, "speed_step.html")          # or a result file, or a study directory

``kanat.report(source, html_path, ...)`` is :func:`kanat.report.html_report.write_report`.
A package cannot also be a plain function of its parent (``import kanat.report`` binds the
name ``kanat.report`` to the package), so the package's module object is made callable
(Python allows a module's ``__class__`` to be a subclass of ``ModuleType``); everything in
its modules stays importable as usual.
"""
from __future__ import annotations

import sys
import types


def report(source, output, nodes=None, window=None, bodies=None):
    """Write one self-contained HTML page for a result or a study: ``kanat report`` in Python.

    Parameters
    ----------
    source : xarray.Dataset or path-like
        A result (as :func:`kanat.simulate` returns it), a result file or a study directory.
    output : path-like
        The HTML file to write (never the source, nor a file of the study).
    nodes, window, bodies
        As :func:`kanat.report.html_report.write_report`.

    Returns
    -------
    pathlib.Path
        The page written.
    """
    from kanat.report.html_report import write_report

    return write_report(source, output, nodes, window, bodies)


class _CallableModule(types.ModuleType):
    """This package's module type: calling the package calls :func:`report`."""

    def __call__(self, source, output, nodes=None, window=None, bodies=None):
        return report(source, output, nodes, window, bodies)


sys.modules[__name__].__class__ = _CallableModule
