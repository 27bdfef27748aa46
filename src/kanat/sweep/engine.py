"""One case of a study, run in a worker: :func:`run_case` (the engines are in :mod:`.execution`).

:func:`run_case` runs one variant (any model) and returns its record; it never raises:
a failure becomes ``status: failed`` with the message, and a result that could not be written
(a full disk) a record with ``stop`` set, on which the study stops.
"""
from __future__ import annotations

import os
import time
import traceback
import warnings
from pathlib import Path

from kanat.errors import KanatError, OutputWriteError

def _run_model(case, output: Path) -> str:
    """Run a validated case to ``output`` with :func:`kanat.api.run`; return its status.

    A killed study leaves its running case's checkpoint: that case continues from it
    (a stale or foreign checkpoint starts the case again).
    """
    from kanat import api

    checkpoint = output.with_name(output.name + ".ckpt.npz")
    if checkpoint.exists():
        try:
            return api.run(case, output=output, resume=True).status
        except KanatError:
            pass
    return api.run(case, output=output).status


def run_case(text: str, label: str, output: str, window=None) -> dict:
    """Run one case of a study and summarise its result (executed on a worker).

    Parameters
    ----------
    text : str
        The case file (YAML).
    label : str
        Its name in messages.
    output : str
        Result file path.
    window : (float or None, float or None), optional
        Time window of the summary statistics [s].

    Returns
    -------
    dict
        ``status`` (``ok`` or ``failed``), ``message``, ``wall_time_s``, ``cpu_time_s``
        (CPU time of the process running it meanwhile), ``statistics`` (empty when the
        case failed) and ``worker`` (host:pid).
    """
    from kanat.analysis.summary import summary_statistics
    from kanat.io import parse_case
    from kanat.io.results import read_result

    start, cpu = time.perf_counter(), time.process_time()
    record = {"status": "failed", "message": "", "statistics": {}, "worker": f"{os.uname().nodename}:{os.getpid()}"}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = parse_case(text, file=label)
            status = _run_model(case, Path(output))
        if status == "ok":
            record["statistics"] = summary_statistics(read_result(output), window)
            record["status"] = "ok"
        else:
            record["message"] = status.removeprefix("failed: ")
    except OutputWriteError as error:     # a full disk: the study stops (the case is not recorded)
        record["message"] = str(error)
        record["stop"] = True
    except Exception as error:  # noqa: BLE001 - a failing case is recorded, never raised
        record["message"] = f"{type(error).__name__}: {error}"
        record["traceback"] = traceback.format_exc(limit=6)
    record["wall_time_s"] = time.perf_counter() - start
    record["cpu_time_s"] = time.process_time() - cpu
    return record
