"""Where a study's cases run: here, in a child process, or on a Dask cluster — and the choice.

Engines, by the ``scheduler`` and ``workers`` given to :func:`kanat.sweep.sweep`:

=====================================  =====================================================
``scheduler="serial"``                 here, one case after another (debugging, the
                                       reference; a crash of the process ends the study)
a ``distributed.Client``, an address   that running cluster (:mod:`.cluster`)
or a scheduler file
``workers=N``                          a local Dask cluster of N processes, started now
neither (the default)                  a running cluster named in Dask's configuration if
                                       there is one; otherwise the rule below
=====================================  =====================================================

**The rule (default engine).** The first two cases run one after the other in a child
process. The second one's wall time ``t`` estimates every remaining case's; the first
one's excess ``w = t1 - t`` is the one-time loading of the compiled kernels, which every
new worker process pays again. With ``R`` cases left and ``W`` cores, running them serially
takes ``R t`` and on a local cluster ``S + w + ceil(R / W) t``, ``S`` the cluster's own
start-up and shut-down (:data:`CLUSTER_STARTUP_S`, measured). The cluster is started only
when it saves more than it costs::

    R t - ceil(R / W) t > S + w

so a handful of second-long cases stays serial and a study of minute-long cases goes
parallel after its second case. ``--workers N`` always starts a cluster, at once.

Serial cases run in one long-lived child process (forked, so it starts with everything
imported): a case that crashes the interpreter (a signal, the memory limit) kills only
that process; it is recorded as failed with its exit status and a new child runs the rest.
"""
from __future__ import annotations

import math
import multiprocessing
import os
import signal
import time

from kanat.errors import KanatError

CLUSTER_STARTUP_S = 0.5
"""Start-up plus shut-down of a local cluster of forked workers [s]: about 0.3 s to start
two workers and 0.1 s to close them, measured on a 2-core x86_64 machine
(benchmarks/RESULTS.md), rounded up. The workers' first loading of the compiled kernels is
not in it: the rule measures that on the study's own first case."""


def cluster_pays(case_seconds: float, remaining: int, workers: int, warm_up_s: float = 0.0,
                 startup_s: float = CLUSTER_STARTUP_S) -> bool:
    """Whether a local cluster of ``workers`` saves more than it costs on ``remaining`` cases.

    ``remaining * t - ceil(remaining / workers) * t > startup_s + warm_up_s`` with
    ``t = case_seconds`` (module docstring).
    """
    if workers < 2 or remaining < 2:
        return False
    serial = remaining * case_seconds
    parallel = math.ceil(remaining / workers) * case_seconds
    return serial - parallel > startup_s + warm_up_s


def _crash_record(exitcode) -> dict:
    if exitcode is not None and exitcode < 0:
        try:
            how = f"killed by signal {signal.Signals(-exitcode).name}"
        except ValueError:
            how = f"killed by signal {-exitcode}"
    else:
        how = f"exit status {exitcode}"
    return {"status": "failed", "statistics": {}, "wall_time_s": float("nan"),
            "message": f"the process running this case died ({how}): a crash in compiled code or the memory limit; "
                       "run the case alone (kanat run cases/NAME.yaml) to see why"}


def _serve(connection, runner) -> None:
    """The child's loop: run each received argument tuple, send back its record, until None."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)         # Ctrl-C is the parent's to handle
    while True:
        try:
            args = connection.recv()
        except EOFError:
            return
        if args is None:
            return
        connection.send(runner(*args))


class ChildProcess:
    """One child process that runs cases one after another (``with ChildProcess(runner) as child``).

    Forked where the platform can (the child starts with everything imported). When a case
    kills the child, :meth:`run` returns a failed record naming the exit status and the
    next call starts a new child.

    Parameters
    ----------
    runner : callable
        ``runner(*args) -> record``; picklable where the start method is ``spawn``.
    """

    def __init__(self, runner):
        self.runner = runner
        self._process = None
        self._connection = None

    def _start(self) -> None:
        method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
        context = multiprocessing.get_context(method)
        here, there = context.Pipe()
        process = context.Process(target=_serve, args=(there, self.runner), daemon=True, name="kanat-case")
        process.start()
        there.close()
        self._process, self._connection = process, here

    def run(self, args: tuple) -> dict:
        """Run one case in the child; its record, or a failed record if the child died."""
        if self._process is None:
            self._start()
        try:
            self._connection.send(args)
            return self._connection.recv()
        except (EOFError, OSError):
            process, self._process = self._process, None
            self._connection.close()
            process.join(10)
            return _crash_record(process.exitcode)

    @property
    def pid(self) -> int | None:
        return self._process.pid if self._process is not None else None

    def close(self) -> None:
        """Stop the child (it finishes nothing more)."""
        process, self._process = self._process, None
        if process is None:
            return
        try:
            self._connection.send(None)
        except OSError:
            pass
        self._connection.close()
        process.join(5)
        if process.is_alive():
            process.kill()
            process.join()

    def __enter__(self) -> ChildProcess:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def execute(jobs: list, on_done, scheduler=None, workers: int | None = None) -> str:
    """Run a study's ``jobs`` on the engine chosen as the module docstring says.

    Parameters
    ----------
    jobs : list of (str, tuple)
        Case name and the arguments of :func:`kanat.sweep.engine.run_case`.
    on_done : callable
        ``on_done(name, record)`` after each case, in this process.
    scheduler, workers
        As :func:`kanat.sweep.sweep`.

    Returns
    -------
    str
        The engine that ran the cases, for the user (``serial in a child process (...)``).
    """
    from kanat.sweep import cluster, engine

    runner = engine.run_case
    if not jobs:
        return "nothing to run"
    if workers is not None and workers < 1:
        raise KanatError(f"workers must be at least 1, got {workers}")
    if scheduler == "serial":
        for name, args in jobs:
            on_done(name, runner(*args))
        return "serial, in this process"
    if scheduler is not None:
        return _on_cluster(jobs, on_done, runner, scheduler, CONNECT)
    if workers is not None:
        with cluster.local_cluster(workers) as client:
            cluster.run_dask(jobs, on_done, client, runner)
        return f"a local Dask cluster of {workers} worker processes (--workers)"
    found = cluster.configured_scheduler()
    if found:
        try:
            return _on_cluster(jobs, on_done, runner, found, DISCOVER)
        except KanatError:
            pass                                          # not running any more: decide as if none were set
    return _by_rule(jobs, on_done, runner)


CONNECT, DISCOVER = "named", "configured"


def _on_cluster(jobs, on_done, runner, scheduler, how: str) -> str:
    from dask.distributed import Client

    from kanat.sweep import cluster

    if isinstance(scheduler, Client):
        cluster.run_dask(jobs, on_done, scheduler, runner)
        return f"the Dask cluster of the given client ({scheduler.scheduler.address})"
    timeout = cluster.CONNECT_TIMEOUT_S if how == CONNECT else cluster.DISCOVER_TIMEOUT_S
    client = cluster.connect(scheduler, timeout)
    try:
        cluster.run_dask(jobs, on_done, client, runner)
        return f"the running Dask cluster at {client.scheduler.address} ({how})"
    finally:
        client.close()


def _by_rule(jobs, on_done, runner) -> str:
    """Two cases in a child process, then the rest there or on a local cluster (module docstring)."""
    from kanat.sweep import cluster

    cores = os.cpu_count() or 1
    seconds = []
    with ChildProcess(runner) as child:
        for name, args in jobs[:2]:
            start = time.perf_counter()
            on_done(name, child.run(args))
            seconds.append(time.perf_counter() - start)
        rest = jobs[2:]
        case_s = seconds[-1]
        warm_up_s = max(seconds[0] - case_s, 0.0)
        estimate = (f"a case {case_s:.2f} s after a first one of {seconds[0]:.2f} s, {len(rest)} left, "
                    f"{cores} cores, start-up {CLUSTER_STARTUP_S:g} s")
        if not cluster_pays(case_s, len(rest), cores, warm_up_s, CLUSTER_STARTUP_S):
            for name, args in rest:
                on_done(name, child.run(args))
            return f"serial in a child process ({estimate})"
    with cluster.local_cluster(cores) as client:
        cluster.run_dask(rest, on_done, client, runner)
    return f"a local Dask cluster of {cores} worker processes ({estimate})"
