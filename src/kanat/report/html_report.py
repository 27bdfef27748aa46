"""``kanat report``: one self-contained HTML page for a result file or a study directory."""
from __future__ import annotations

from pathlib import Path

from kanat.errors import KanatError


def write_report(source, output, nodes=None, window=None, bodies=None) -> Path:
    """Write the HTML report of a result file or of a study directory.

    Parameters
    ----------
    source : path-like
        A result file (netCDF) or a study directory (with ``summary.nc``).
    output : path-like
        The HTML file to write.
    nodes : sequence of int or str, optional
        Result files only: nodes for the time histories, statistics and spectra.
    window : (float or None, float or None), optional
        Result files only: time window of the statistics [s].
    bodies : sequence of str, optional
        Result files only: bodies for the depth histories and tables (default all).

    Returns
    -------
    pathlib.Path
        The page written.
    """
    from kanat.io.results import read_result
    from kanat.report.html_result import result_report
    from kanat.report.html_study import study_report

    source = Path(source)
    if source.is_dir():
        return study_report(source, output)
    if not source.exists():
        raise KanatError(f"{source} does not exist; give a result file (.nc) or a study directory")
    try:
        ds = read_result(source)
    except (OSError, ValueError) as error:
        raise KanatError(f"{source} is not a kanat result file (netCDF): {error}") from None
    if "case" in ds.dims and "parameters" in ds.attrs:           # a study's summary.nc: report the study
        return study_report(source.parent, output)
    return result_report(ds, output, str(source), nodes, window, bodies)
