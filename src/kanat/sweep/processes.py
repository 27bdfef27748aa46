"""Local worker processes for a study: one child that runs cases in turn, and a pool of them.

Children are forked from the study's process where the platform can (Linux): they start
in a few milliseconds with kanat and everything else already imported, run each case in
their main thread (no event loop, no profiler beside it) and send its record back through
a pipe. A case that kills its process (a signal, the memory limit) costs only that
process: its record says how it died, and a new child takes the next case.
"""
from __future__ import annotations

import contextlib
import multiprocessing
import signal
from multiprocessing.connection import wait


def start_method() -> str:
    """``fork`` where the platform has it, else ``spawn`` (then ``runner`` must be picklable)."""
    return "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"


def crash_record(exitcode) -> dict:
    """The record of a case whose process died with ``exitcode`` (negative: a signal)."""
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

    :meth:`send` starts a child if there is none; :meth:`receive` returns the case's
    record, or a failed one naming the exit status when the child died (the next
    :meth:`send` starts a new child).

    Parameters
    ----------
    runner : callable
        ``runner(*args) -> record``.
    """

    def __init__(self, runner):
        self.runner = runner
        self._process = None
        self.connection = None

    def send(self, args: tuple) -> None:
        """Give the child a case (``runner``'s arguments)."""
        if self._process is None:
            context = multiprocessing.get_context(start_method())
            here, there = context.Pipe()
            process = context.Process(target=_serve, args=(there, self.runner), daemon=True, name="kanat-case")
            process.start()
            there.close()
            self._process, self.connection = process, here
        try:
            self.connection.send(args)
        except OSError:
            pass                                         # died already: receive() says how

    def receive(self) -> dict:
        """The record of the case sent last (waits for it)."""
        try:
            return self.connection.recv()
        except (EOFError, OSError):
            process, self._process = self._process, None
            self.connection.close()
            process.join(10)
            return crash_record(process.exitcode)

    def run(self, args: tuple) -> dict:
        """Run one case in the child and return its record."""
        self.send(args)
        return self.receive()

    @property
    def pid(self) -> int | None:
        return self._process.pid if self._process is not None else None

    def close(self, kill: bool = False) -> None:
        """Stop the child: after its case (it takes no more), or at once with ``kill``."""
        process, self._process = self._process, None
        if process is None:
            return
        if not kill:
            with contextlib.suppress(OSError):
                self.connection.send(None)
            process.join(5)
        self.connection.close()
        if process.is_alive():
            process.kill()
            process.join()

    def __enter__(self) -> ChildProcess:
        return self

    def __exit__(self, exc_type, *exc) -> None:
        self.close(kill=exc_type is not None)              # Ctrl-C or an error here: stop the case now


def run_pool(jobs: list, on_done, runner, workers: int, first: ChildProcess | None = None) -> None:
    """Run ``jobs`` (``(name, args)`` pairs) on ``workers`` child processes, in order of submission.

    Each child takes the next case as soon as it has sent back its last record;
    ``on_done(name, record)`` is called here as each finishes. ``first``, an already
    running child (warm: its kernels loaded), is used as one of the workers and left open.
    """
    pending = list(reversed(jobs))
    with contextlib.ExitStack() as stack:
        children = [first] if first is not None else []
        while len(children) < min(workers, len(jobs)):
            children.append(stack.enter_context(ChildProcess(runner)))
        busy = {}
        for child in children:
            if pending:
                name, args = pending.pop()
                child.send(args)
                busy[child] = name
        while busy:
            ready = wait([child.connection for child in busy])
            for child in [c for c in busy if c.connection in ready]:
                on_done(busy.pop(child), child.receive())
                if pending:
                    name, args = pending.pop()
                    child.send(args)
                    busy[child] = name
