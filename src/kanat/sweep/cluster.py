"""Dask clusters for a study: find and reuse a running one, run cases on it, or start one.

A running cluster is used when the study is given its address or scheduler file
(``scheduler="tcp://127.0.0.1:8786"`` or ``scheduler="scheduler.json"``, as written by
``dask scheduler --scheduler-file scheduler.json``), or a ``distributed.Client``, or, with
no ``scheduler`` and no ``workers``, when Dask's own configuration names one
(``DASK_SCHEDULER_ADDRESS``, or ``scheduler-address`` in a Dask config file). Its workers
need kanat installed and must see the study directory at the same path.

:func:`local_cluster` starts a Dask ``LocalCluster`` on this machine (for Python users who
want Dask's dashboard, and for tests): one single-threaded worker process per core (the
runs hold the GIL most of the time, so processes, not threads, run cases side by side),
started by a fork server where the platform has one (``distributed.worker.multiprocessing-method:
forkserver``), without Dask's sampling profiler, every port chosen free on the loopback
interface. Workers are not forked from the calling process: it runs Dask's event loop and
the nannies' threads, and a fork taken while one of them holds a lock can leave the child,
or the nanny waiting on it, stuck for good (seen once in a test: a worker killed by its case,
restarted by a fork, and the study hung). A fork server is a single-threaded process with
Dask and NumPy already imported, so a worker still starts in a fraction of a second; kanat
is imported by its first case. ``kanat sweep --workers N`` uses kanat's own lighter local
cluster instead (:mod:`.processes`).
"""
from __future__ import annotations

import contextlib
import importlib.util
import multiprocessing
import os
import time
from pathlib import Path

from kanat.errors import KanatError

LOOPBACK = "127.0.0.1"
"""The local cluster listens on the loopback interface only (scheduler, workers, status page)."""

ALLOWED_FAILURES = 1
"""A case whose worker dies is tried once more on another worker, then recorded as failed.

Workers of a local cluster hold only the case they run (``worker-saturation: 1.0``), so a
crashing case never takes the blame onto a case queued behind it."""

CONNECT_TIMEOUT_S = 20.0
"""How long to wait for a cluster the user named."""

DISCOVER_TIMEOUT_S = 3.0
"""How long to wait for a cluster found in Dask's configuration before running without it."""


@contextlib.contextmanager
def local_cluster(workers: int | None = None):
    """A Dask ``LocalCluster`` of ``workers`` single-threaded processes and its client.

    Parameters
    ----------
    workers : int, optional
        Worker processes (default: every core).

    Yields
    ------
    distributed.Client
        Connected to the cluster; both are closed on leaving the block.
    """
    from kanat.extras import require

    require("studies", "dask.distributed", "a Dask cluster")
    import dask
    from dask.distributed import Client, LocalCluster

    n = workers or os.cpu_count() or 1
    if n < 1:
        raise KanatError(f"workers must be at least 1, got {workers}")
    method = "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"
    settings = {"distributed.worker.multiprocessing-method": method,
                "distributed.scheduler.allowed-failures": ALLOWED_FAILURES,
                "distributed.scheduler.worker-saturation": 1.0,    # a worker holds only the case it runs
                "distributed.worker.profile.enabled": False,        # its sampling thread slows a case ~5 %
                "distributed.admin.system-monitor.gil.enabled": False}
    with dask.config.set(settings):                       # for the cluster's life: restarted workers too
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, host=LOOPBACK, scheduler_port=0,
                               dashboard_address=f"{LOOPBACK}:0")
        try:
            client = Client(cluster)
            try:
                yield client
            finally:
                client.close()
        finally:
            cluster.close()


def configured_scheduler() -> str | None:
    """The scheduler address in Dask's configuration (``DASK_SCHEDULER_ADDRESS``), if any.

    None when Dask is not installed (the ``studies`` extra): then no cluster can be running
    for this study anyway.
    """
    if importlib.util.find_spec("dask") is None:
        return None
    import dask

    address = dask.config.get("scheduler-address", None)
    return str(address) if address else None


def connect(scheduler, timeout: float = CONNECT_TIMEOUT_S):
    """A client of a running cluster named by an address or a scheduler file.

    Parameters
    ----------
    scheduler : str or path-like
        ``tcp://host:port`` (any Dask address), or a scheduler file (JSON with its
        ``address``, written by ``dask scheduler --scheduler-file``).
    timeout : float
        Seconds to wait for the scheduler.

    Raises
    ------
    KanatError
        When the file cannot be read or the scheduler cannot be reached in ``timeout``.
    """
    from kanat.extras import require

    require("studies", "dask.distributed", "--scheduler")
    from dask.distributed import Client

    path = Path(str(scheduler)).expanduser()
    by_file = "://" not in str(scheduler) and (path.suffix == ".json" or path.is_file())
    try:
        if by_file:
            if not path.is_file():
                raise KanatError(f"the scheduler file {path} does not exist; start one with "
                                 f"dask scheduler --scheduler-file {path}, or give an address tcp://HOST:PORT")
            return Client(scheduler_file=str(path), timeout=f"{timeout}s")
        return Client(str(scheduler), timeout=f"{timeout}s")
    except (OSError, TimeoutError, ValueError) as error:
        raise KanatError(f"cannot reach the Dask scheduler {scheduler}: {error}") from None


def run_dask(jobs: list, on_done, client, runner) -> None:
    """Run ``jobs`` (``(name, args)`` pairs) as ``runner(*args)`` on ``client``'s cluster.

    ``on_done(name, record)`` is called as each finishes. A task whose worker dies (a
    crash, not an exception: those are records) is retried once by Dask
    (:data:`ALLOWED_FAILURES`, on clusters started here) and then recorded as failed.
    """
    from dask.distributed import as_completed

    futures = {client.submit(runner, *args, key=f"kanat-{name}-{time.time_ns()}", pure=False): name
               for name, args in jobs}
    for future in as_completed(futures):
        name = futures[future]
        try:
            record = future.result()
        except Exception as error:  # noqa: BLE001 - the worker died: recorded, the others go on
            record = {"status": "failed", "statistics": {}, "wall_time_s": float("nan"),
                      "message": f"the worker process running this case died ({type(error).__name__}: {error}); "
                                 "run the case alone (kanat run cases/NAME.yaml) to see why"}
        on_done(name, record)
