"""Counting a study's cases: done, failed, remaining; and a rich progress bar of them."""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class StudyProgress:
    """Counts of a running study (passed to the ``progress`` callback of :func:`kanat.sweep.sweep`).

    Attributes
    ----------
    total : int
    done : int
        Finished cases, ok or failed (including those finished before a resume).
    failed : int
    last : dict or None
        Record of the case that finished last.
    """

    total: int
    done: int = 0
    failed: int = 0
    last: dict | None = field(default=None, repr=False)

    @property
    def remaining(self) -> int:
        return self.total - self.done

    def finish(self, record: dict) -> None:
        self.done += 1
        self.failed += record["status"] != "ok"
        self.last = record


class _RichBar:
    """A rich bar: ``done/total``, failed and remaining counts, elapsed time, the last case."""

    def __init__(self, state: StudyProgress, console=None):
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        self._progress = Progress(TextColumn("cases"), BarColumn(), MofNCompleteColumn(),
                                  TextColumn("[green]{task.fields[ok]} ok[/] [red]{task.fields[failed]} failed[/] "
                                             "{task.fields[remaining]} remaining"),
                                  TimeElapsedColumn(), TextColumn("{task.fields[last]}"),
                                  console=console or Console(stderr=True))
        self._task = self._progress.add_task("study", total=state.total, completed=state.done,
                                             ok=state.done - state.failed, failed=state.failed,
                                             remaining=state.remaining, last="")

    def start(self) -> None:
        self._progress.start()

    def stop(self) -> None:
        self._progress.stop()

    def update(self, state: StudyProgress) -> None:
        last = state.last or {}
        mark = "" if last.get("status") == "ok" else " (failed)"
        self._progress.update(self._task, completed=state.done, ok=state.done - state.failed, failed=state.failed,
                              remaining=state.remaining, last=f"{last.get('name', '')}{mark}")


def rich_progress(state: StudyProgress, console=None) -> _RichBar:
    """A rich progress bar for a study; call ``start()``, ``update(state)``, ``stop()``."""
    return _RichBar(state, console)
