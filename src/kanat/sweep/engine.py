"""Running a study's cases: one case in a worker, and the engines that run many.

:func:`run_case` runs one variant (any model) and returns its record; it never raises:
a failure becomes ``status: failed`` with the message. Engines:

* ``"serial"``: in this process, one after another (debugging, the reference);
* ``None`` (default): a Dask ``LocalCluster`` of ``workers`` processes with one thread
  each, started here and closed at the end;
* a scheduler address (``"tcp://host:8786"``): an existing Dask cluster; its workers
  need kanat installed and must see the study directory at the same path (a shared
  file system);
* a ``distributed.Client``: used as it is (not closed).
"""
from __future__ import annotations

import os
import time
import traceback
import warnings
from pathlib import Path

from kanat.errors import KanatError

RUNNERS = {"continuum": "kanat.continuum.run", "lumped": "kanat.lumped"}
"""Dynamic models by name: the module whose ``run(case, output, ...)`` runs them."""


def _run_model(case, output: Path) -> str:
    """Run a validated case to ``output``; return its status (``ok`` or the failure)."""
    import importlib

    if case.model in RUNNERS:
        runner = importlib.import_module(RUNNERS[case.model])
        checkpoint = output.with_name(output.name + ".ckpt.npz")
        if output.exists() and checkpoint.exists():
            try:                                   # a killed study: continue the killed run
                return runner.run(case, output, resume=True).status
            except Exception:                      # noqa: BLE001 - stale or foreign checkpoint: start again
                pass
        return runner.run(case, output).status
    if case.model == "statics":
        from kanat.io.results import statics_dataset, write_result
        from kanat.statics import solve_statics

        start = time.perf_counter()
        result = solve_statics(case)
        write_result(statics_dataset(result, wall_time_s=time.perf_counter() - start), output)
        return "ok"
    if case.model == "pitch":
        from kanat.vessel.pitch import run_pitch_case

        run_pitch_case(case, output, None)
        return "ok"
    raise KanatError(f"model '{case.model}' cannot be run in a study")


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
        ``status`` (``ok`` or ``failed``), ``message``, ``wall_time_s``, ``statistics``
        (empty when the case failed) and ``worker`` (host:pid).
    """
    from kanat.analysis.summary import summary_statistics
    from kanat.io import parse_case
    from kanat.io.results import read_result

    start = time.perf_counter()
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
            record["message"] = status
    except Exception as error:  # noqa: BLE001 - a failing case is recorded, never raised
        record["message"] = f"{type(error).__name__}: {error}"
        record["traceback"] = traceback.format_exc(limit=6)
    record["wall_time_s"] = time.perf_counter() - start
    return record


def run_serial(jobs: list, on_done) -> None:
    """Run ``jobs`` (``(name, args)`` pairs) here, in order; ``on_done(name, record)`` after each."""
    for name, args in jobs:
        on_done(name, run_case(*args))


LOOPBACK = "127.0.0.1"
"""The local cluster listens on the loopback interface only (scheduler, workers, status page)."""


def local_cluster(workers: int | None):
    """A Dask ``LocalCluster`` of ``workers`` single-threaded processes (default: every core).

    One thread per process: the continuum and lumped runs hold the GIL most of the time, so
    processes, not threads, run cases side by side. Every port is chosen free at random on
    the loopback interface.
    """
    from dask.distributed import LocalCluster

    n = workers or os.cpu_count() or 1
    return LocalCluster(n_workers=n, threads_per_worker=1, processes=True, host=LOOPBACK, scheduler_port=0,
                        dashboard_address=f"{LOOPBACK}:0")


def run_dask(jobs: list, on_done, scheduler=None, workers: int | None = None) -> None:
    """Run ``jobs`` on Dask distributed (module docstring); ``on_done`` as each finishes.

    A task that dies with its worker (a crash, not an exception: those are records) is
    reported as failed with Dask's message.
    """
    from dask.distributed import Client, as_completed

    if workers is not None and workers < 1:
        raise KanatError(f"workers must be at least 1, got {workers}")
    owned, cluster = [], None
    if isinstance(scheduler, Client):
        client = scheduler
    elif scheduler is None:
        cluster = local_cluster(workers)
        client = Client(cluster)
        owned = [client, cluster]
    else:
        try:
            client = Client(scheduler, timeout="20s")
        except OSError as error:
            raise KanatError(f"cannot reach the Dask scheduler at {scheduler}: {error}") from None
        owned = [client]
    try:
        futures = {client.submit(run_case, *args, key=f"kanat-{name}-{time.time_ns()}", pure=False): name
                   for name, args in jobs}
        for future in as_completed(futures):
            name = futures[future]
            try:
                record = future.result()
            except Exception as error:  # noqa: BLE001 - the worker died
                record = {"status": "failed", "message": f"worker lost: {type(error).__name__}: {error}",
                          "statistics": {}, "wall_time_s": float("nan")}
            on_done(name, record)
    finally:
        for thing in owned:
            thing.close()
