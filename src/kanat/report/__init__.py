"""Pictures and HTML pages of results and studies.

The public API's ``report`` is the function :func:`report` here::

    import kanat
    ds = kanat.simulate(kanat.load_case("examples/speed_step_2d.yaml"))
    kanat.report(ds, "speed_step.html")          # or a result file, or a study directory

``kanat.report`` is that plain function, not this package: ``import kanat`` imports the
package (which imports nothing else) and then binds the name ``report`` to the function, so a
later ``import kanat.report.run_plot`` finds the package already loaded and leaves the name
alone. The package's modules are imported with ``from``
(``from kanat.report.run_plot import plot_run``, ``from kanat.report import html_report``);
``import kanat.report.html_report as h`` does not work, since its name lookup meets the function.
"""
from __future__ import annotations


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
