"""Parameter studies: a base case, keys to vary and their values, every combination run.

Public API
----------
sweep(case, vary, out_dir, scheduler=None, workers=None, progress=None, window=None) -> StudyResult
    Run a study (cartesian product of the values), serially or on local worker
    processes as pays best, or on a running Dask cluster (:mod:`.execution`); resume a
    killed one.
plan_study(case, vary) -> StudyPlan
    The cases of a study, validated, without running them.
parse_values(spec, key="") -> list
    The value syntax: ``4,6,8``, ``4:8:2``, ``linspace(a,b,n)``, ``uniform(a,b,n,seed)``,
    ``normal(mean,std,n,seed)`` (:mod:`.values`).
read_summary(path) -> (Dataset, keys, statistics)
    A study's summary table (:mod:`.store` describes the directory).

A study that the disk cannot hold is refused before its first case: the estimated results of
the cases left to run (:func:`kanat.model.run_checks.result_bytes`) and their records must fit
in the free space. A disk that fills up all the same stops the study with one
:class:`~kanat.errors.OutputWriteError`: the finished cases stay recorded, the running case
keeps its partial result and checkpoint, and the same study run again once space is freed
continues from there.

Example
-------
>>> from kanat.sweep import sweep
>>> result = sweep("examples/speed_step_2d.yaml",
...                {"vessel.track[1].to_speed_kn": "8:12:2", "cables[0].length": [800, 1000]},
...                "study/", workers=2)                                    # doctest: +SKIP
>>> result.summary["top_tension_max"]                                     # doctest: +SKIP
"""
from __future__ import annotations

from dataclasses import dataclass
from os import PathLike

import xarray as xr

from kanat.errors import OutputWriteError
from kanat.io.space import require_room

from kanat.sweep.engine import run_case
from kanat.sweep.execution import cluster_pays, execute
from kanat.sweep.plan import CaseSpec, StudyPlan, plan_study
from kanat.sweep.progress import StudyProgress, rich_progress
from kanat.sweep.store import StudyStore, read_summary, summary_dataset
from kanat.sweep.values import parse_values

__all__ = ["CaseSpec", "StudyPlan", "StudyProgress", "StudyResult", "cluster_pays", "parse_values", "plan_study",
           "read_summary", "run_case", "summary_dataset", "sweep"]


@dataclass
class StudyResult:
    """What a study did.

    Attributes
    ----------
    out_dir : pathlib.Path
    summary : xarray.Dataset
        One row per case (:mod:`kanat.sweep.store`).
    ran, skipped, failed : int
        Cases run now, cases already finished before (resume), and failed cases (in all).
    engine : str
        Where the cases ran and why (:func:`kanat.sweep.execution.execute`).
    """

    out_dir: object
    summary: xr.Dataset
    ran: int
    skipped: int
    failed: int
    engine: str = ""

    @property
    def total(self) -> int:
        return self.summary.sizes.get("case", 0)


def sweep(case, vary: dict, out_dir, scheduler=None, workers: int | None = None, progress=None,
          window=None) -> StudyResult:
    """Run a parameter study.

    Parameters
    ----------
    case : path-like, kanat.model.Case or dict
        The base case; key paths are in case-file terms (``vessel.track[1].to_speed_kn``).
    vary : dict of str to values
        Key path -> list of values, or text in the syntax of :mod:`kanat.sweep.values`.
        Every combination is a case (the first key varies slowest).
    out_dir : path-like
        Study directory (created in an existing directory; an existing one of the same
        study is resumed: finished cases are skipped). It is locked for the study's
        duration (:class:`kanat.io.outputs.OutputLock`): a second study on it is refused.
    scheduler : None, "serial", str or distributed.Client
        None: chosen by the rule of :mod:`kanat.sweep.execution` (a running cluster in
        Dask's configuration, else serially in a child process or on a local cluster,
        whichever pays); ``"serial"``: no Dask, one case after another in this process;
        an address or a scheduler file (``.json``): that running Dask cluster; a Client:
        use it.
    workers : int, optional
        Start a local cluster of this many worker processes (always, whatever the rule).
    progress : callable, True or None
        ``progress(StudyProgress)`` after each finished case; True draws a rich bar.
    window : (float or None, float or None), optional
        Time window of the summary statistics [s].

    Returns
    -------
    StudyResult

    Raises
    ------
    KanatError or CaseError
        For a study that cannot start (bad key path or values, no valid case, another
        study in ``out_dir`` or one running on it, an output that is not a writable
        directory). A case that fails never raises: it is recorded.
    """
    from kanat.io.outputs import OutputLock, check_output_directory

    plan = plan_study(case, vary)
    inputs = [case] if isinstance(case, (str, PathLike)) else []
    root = check_output_directory(out_dir, inputs=inputs)
    with OutputLock(root):
        return _run(plan, StudyStore(root), scheduler, workers, progress, window)


RECORD_BYTES = 64 * 1024
"""Room for one case's record, its case file and its row of the summary [bytes]."""


def _stopped(store: StudyStore, name: str, state: StudyProgress, why: str) -> OutputWriteError:
    """The error that stops a study whose disk is full, in one sentence."""
    why = why.removesuffix("; free some space and continue with --resume")
    return OutputWriteError(f"the study in {store.root} stopped at case {name} ({state.done} of {state.total} "
                            f"cases finished and kept): {why}; free some space and run the same study again, "
                            "it continues with the cases not finished")


def _run(plan: StudyPlan, store: StudyStore, scheduler, workers, progress, window) -> StudyResult:
    """Prepare the study directory, run the unfinished cases, write the summary."""
    done = store.finished()
    todo = [c for c in plan.cases if c.name not in done]
    require_room(store.root / "summary.nc", sum(c.result_bytes + RECORD_BYTES for c in todo),
                 f"the study's {len(todo)} cases left to run (their results and records)",
                 "free some space, store less often (output_dt) or write the study to another disk")
    store.prepare(plan)
    state = StudyProgress(total=len(plan.cases), done=len(done),
                          failed=sum(r["status"] != "ok" for r in done.values()))
    specs = {c.name: c for c in plan.cases}
    reporter = rich_progress(state) if progress is True else None
    callback = reporter.update if reporter is not None else progress


    def on_done(name: str, outcome: dict) -> None:
        spec = specs[name]
        if outcome.get("stop"):
            raise _stopped(store, name, state, outcome["message"])
        record = {"index": spec.index, "name": name, "parameters": spec.parameters,
                  "result": str(store.result_file(name).relative_to(store.root)), **outcome}
        try:
            store.record(record)
            store.write_summary(plan)
        except OutputWriteError as error:
            store.record_file(name).unlink(missing_ok=True)       # run again when the study continues
            raise _stopped(store, name, state, str(error)) from None
        if record["status"] == "ok":                 # finished: its checkpoint is no longer needed
            store.checkpoint_file(name).unlink(missing_ok=True)
        state.finish(record)
        if callback is not None:
            callback(state)

    for spec in [c for c in todo if c.error]:        # invalid variants: recorded, never run
        on_done(spec.name, {"status": "failed", "message": spec.error, "statistics": {}, "wall_time_s": 0.0})
    jobs = [(c.name, (c.text, f"{plan.base} [{c.name}]", str(store.result_file(c.name)), window))
            for c in todo if not c.error]
    try:
        if reporter is not None:
            reporter.start()
        engine = execute(jobs, on_done, scheduler=scheduler, workers=workers)
    finally:
        if reporter is not None:
            reporter.stop()
    summary = store.write_summary(plan)
    return StudyResult(store.root, summary, ran=len(todo), skipped=len(done), failed=state.failed, engine=engine)
