"""``kanat report``: one self-contained HTML page for a result file or a study directory."""
from __future__ import annotations

from pathlib import Path

from kanat.errors import KanatError

STUDY_FILES = ("summary.nc", "summary.csv", "study.json")
"""A study's own files at its top level (a report may not be written over them)."""


def report_inputs(source) -> list[Path]:
    """Every file a report of ``source`` reads or that belongs to the study it shows.

    For a result file, the file itself; for a study directory (or its ``summary.nc``),
    the directory's summary, table and every case file, result and record.
    """
    source = Path(source)
    study = source if source.is_dir() else (source.parent if source.name == "summary.nc" else None)
    inputs = [source]
    if study is not None and (study / "summary.nc").exists():
        inputs += [study / name for name in STUDY_FILES]
        for folder in ("cases", "results", "records"):
            inputs += sorted((study / folder).glob("*")) if (study / folder).is_dir() else []
    return inputs


def write_report(source, output, nodes=None, window=None, bodies=None) -> Path:
    """Write the HTML report of a result (in memory or a file) or of a study directory.

    The output is checked first (:func:`kanat.io.outputs.check_output_file`: it may not be
    the source or any file of the study, a directory, or in a missing or read-only
    directory), locked while the page is built (:class:`kanat.io.outputs.OutputLock`: a
    second report to the same file is refused) and written atomically.

    Parameters
    ----------
    source : xarray.Dataset or path-like
        A result (as :func:`kanat.simulate` returns it), a result file (netCDF) or a study
        directory (with ``summary.nc``).
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
    from kanat.io.outputs import OutputLock, check_output_file

    if hasattr(source, "data_vars"):                     # an xarray.Dataset: a result in memory
        from kanat.report.html_result import result_report

        output = check_output_file(output, example="report.html")
        with OutputLock(output):
            return result_report(source, output, "a result in memory", nodes, window, bodies)
    source = Path(source)
    if not source.exists():
        raise KanatError(f"{source} does not exist; give a result file (.nc) or a study directory")
    output = check_output_file(output, inputs=report_inputs(source), example="report.html")
    with OutputLock(output):
        return _write(source, output, nodes, window, bodies)


def _write(source: Path, output: Path, nodes, window, bodies) -> Path:
    from kanat.io.results import read_result
    from kanat.report.html_result import result_report
    from kanat.report.html_study import study_report

    if source.is_dir():
        return study_report(source, output)
    try:
        ds = read_result(source)
    except (OSError, ValueError) as error:
        raise KanatError(f"{source} is not a kanat result file (netCDF): {error}") from None
    if "case" in ds.dims and "parameters" in ds.attrs:           # a study's summary.nc: report the study
        return study_report(source.parent, output)
    return result_report(ds, output, str(source), nodes, window, bodies)
