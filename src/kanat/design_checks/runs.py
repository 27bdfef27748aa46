"""The runs of a design check, on the study engine (:func:`kanat.sweep.execution.execute`):
one after another in this process, on local worker processes or on a Dask cluster; the
tables are the same whatever ran them.

Every run writes ``<folder>/runs/<condition>/<sea state>_seed<k>.nc``. A file that is
complete (``status`` ok) and of the same case (``case_sha256``) is not run again, so a stopped
check resumes where it stopped; a file of another case, or an unfinished one, is run anew.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from kanat.io.provenance import case_yaml, same_case
from kanat.model import Case
from kanat.model.design import SeaState

from .conditions import Condition


@dataclass(frozen=True)
class Job:
    """One run: a condition's case in a sea state with a seed, and its result file."""

    condition: Condition
    sea_state: SeaState
    seed: int
    case: Case
    path: Path

    @property
    def label(self) -> str:
        return f"{self.condition.name}/{self.sea_state.name}/seed {self.seed}"


def run_file(folder: Path, condition: str, sea_state: str, seed: int) -> Path:
    """Where a run's result goes (``:`` of ``damaged:<cable>`` written ``_``)."""
    return folder / "runs" / condition.replace(":", "_") / f"{sea_state}_seed{seed}.nc"


def complete(job: Job) -> bool:
    """Whether the job's result file holds a finished run of the same case."""
    if not job.path.exists():
        return False
    from kanat.io.results import read_result

    try:
        with read_result(job.path) as ds:
            return ds.attrs.get("status") == "ok" and same_case(ds.attrs.get("case_sha256"), job.case)
    except Exception:  # noqa: BLE001 - an unreadable file is run again
        return False


def run_jobs(jobs: list[Job], scheduler=None, workers: int | None = None,
             progress: Callable[[str], None] | None = None) -> tuple[dict[str, str], str]:
    """Run the jobs whose files are not complete.

    Parameters
    ----------
    jobs : list of Job
    scheduler : str, distributed.Client or None
        ``serial`` (None), a Dask scheduler address or file, or a client
        (:func:`kanat.sweep.execution.execute`).
    workers : int, optional
        A local pool of this many worker processes.
    progress : callable, optional
        ``progress(message)`` after each run.

    Returns
    -------
    failures : dict of str to str
        Job label -> why it failed.
    engine : str
        What ran them, for the user.
    """
    from kanat.sweep.execution import execute

    pending = [job for job in jobs if not complete(job)]
    for job in pending:
        job.path.parent.mkdir(parents=True, exist_ok=True)
        job.path.unlink(missing_ok=True)
    failures: dict[str, str] = {}
    done = [len(jobs) - len(pending)]

    def finished(name: str, record: dict) -> None:
        done[0] += 1
        if record["status"] != "ok":
            failures[name] = record["message"] or "the run failed"
        if progress is not None:
            progress(f"{done[0]}/{len(jobs)} {name}: {record['status']}")

    work = [(job.label, (case_yaml(job.case), job.label, str(job.path), None)) for job in pending]
    engine = execute(work, finished, scheduler="serial" if scheduler is None and workers is None else scheduler,
                     workers=workers)
    return failures, engine
