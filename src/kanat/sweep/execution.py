"""Where a study's cases run — here, in local worker processes, or on a Dask cluster — and the choice.

Engines, by the ``scheduler`` and ``workers`` given to :func:`kanat.sweep.sweep`:

=====================================  =====================================================
``scheduler="serial"``                 here, one case after another (debugging, the
                                       reference; a crash of the process ends the study)
a ``distributed.Client``, an address   that running Dask cluster (:mod:`.cluster`)
or a scheduler file (``.json``)
``workers=N``                          a local cluster of N worker processes
                                       (:mod:`.processes`), started now
neither (the default)                  a running Dask cluster named in Dask's configuration
                                       if one answers; otherwise the rule below
=====================================  =====================================================

The local cluster is kanat's own: worker processes forked from the study's process (on
Linux; spawned elsewhere), each running one case at a time in its main thread and sending
its record back through a pipe. Forked workers start in milliseconds with everything
imported (33 ms to start two, run a trivial case on each and stop them), where a Dask
``LocalCluster`` of spawned workers takes about 3 s to start, import and close, and its
workers' sampling profiler adds about 5 % to each case's CPU time
(``benchmarks/RESULTS.md``); Dask remains the engine for clusters that already run, on this
machine or many.

**The rule (default engine).** The first two cases run one after the other in a child
process. The second one's wall time ``t`` estimates every remaining case's; the first
one's excess ``w = t1 - t`` is the one-time loading of the compiled kernels, which every
new worker process pays again. With ``R`` cases left and ``W`` cores, running them serially
takes ``R t`` and on a local cluster ``S + w + ceil(R / W) t``, ``S`` the cluster's own
start-up and shut-down (:data:`CLUSTER_STARTUP_S`). The cluster is started only when it
saves more than it costs::

    R t - ceil(R / W) t > S + w

so a handful of cases of a second stays serial and a study of cases of tens of seconds
goes parallel after its second case, the child that ran the first two becoming one of the
workers. ``--workers N`` always starts a local cluster, at once.

Every local case runs in a child process: a case that kills its process (a signal, the
memory limit) is recorded as failed with how it died, and a new child runs the rest.
"""
from __future__ import annotations

import math
import os
import time

from kanat.errors import KanatError

CLUSTER_STARTUP_S = 0.2
"""Start-up plus shut-down of a local cluster [s]: forking a worker and closing it take
a few milliseconds each; the margin covers the parent's bookkeeping. The workers' first
loading of the compiled kernels is not in it: the rule measures that on the study's own
first case (``w``)."""


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
        The engine that ran the cases and why, for the user.
    """
    from kanat.sweep import cluster, engine, processes

    runner = engine.run_case
    if workers is not None and workers < 1:
        raise KanatError(f"workers must be at least 1, got {workers}")
    if not jobs:
        return "nothing to run"
    if scheduler == "serial":
        for name, args in jobs:
            on_done(name, runner(*args))
        return "serial, in this process"
    if scheduler is not None:
        return _on_dask(jobs, on_done, runner, scheduler, cluster.CONNECT_TIMEOUT_S, "named")
    if workers is not None:
        processes.run_pool(jobs, on_done, runner, workers)
        return f"a local cluster of {workers} worker processes (--workers)"
    found = cluster.configured_scheduler()
    if found:
        try:
            return _on_dask(jobs, on_done, runner, found, cluster.DISCOVER_TIMEOUT_S, "configured")
        except KanatError:
            pass                                          # not running any more: decide as if none were set
    return _by_rule(jobs, on_done, runner)


def _on_dask(jobs, on_done, runner, scheduler, timeout: float, how: str) -> str:
    from kanat.sweep import cluster

    if not isinstance(scheduler, (str, os.PathLike)):   # a distributed.Client: used as it is
        cluster.run_dask(jobs, on_done, scheduler, runner)
        return f"the Dask cluster of the given client ({scheduler.scheduler.address})"
    client = cluster.connect(scheduler, timeout)
    try:
        cluster.run_dask(jobs, on_done, client, runner)
        return f"the running Dask cluster at {client.scheduler.address} ({how})"
    finally:
        client.close()


def _by_rule(jobs, on_done, runner) -> str:
    """Two cases in a child process, then the rest there or on a local cluster (module docstring)."""
    from kanat.sweep.processes import ChildProcess, run_pool

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
                    f"{cores} cores")
        if cluster_pays(case_s, len(rest), cores, warm_up_s, CLUSTER_STARTUP_S):
            run_pool(rest, on_done, runner, cores, first=child)
            return f"a local cluster of {cores} worker processes ({estimate})"
        for name, args in rest:
            on_done(name, child.run(args))
        return f"serial in a child process ({estimate})"
