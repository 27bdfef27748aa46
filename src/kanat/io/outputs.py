"""Output files that never destroy what they should not: checks, an exclusive lock, atomic writes.

Every command that writes a file or a study directory goes through three steps:

1. :func:`check_output_file` (or :func:`check_output_directory` for a study) before any
   work: the output is not one of the inputs, not a directory (or not a file, for a
   study), its directory exists and can be written; each problem has its own
   :class:`~kanat.errors.KanatError` message.
2. :class:`OutputLock` for the whole run: an exclusive ``fcntl.flock`` on a sidecar file
   ``.NAME.lock`` beside the output, so a second run on the same output is refused at
   start with the first run's pid instead of corrupting the file. The kernel drops the
   lock when the process ends, however it ends; the sidecar is removed on release.
3. :func:`atomic_path` / :func:`write_text_atomic` for the write itself: the data go to a
   unique temporary name in the same directory, renamed over the output only when the
   writer succeeded (``os.replace`` is atomic within one file system), so a reader sees
   the old file or the new one, never half of one.

Example
-------
>>> out = check_output_file("run.nc", inputs=["case.yaml"])         # doctest: +SKIP
>>> with OutputLock(out):                                            # doctest: +SKIP
...     with atomic_path(out) as tmp:
...         dataset.to_netcdf(tmp)

Locks are advisory and local: they protect against other kanat runs on the same machine
(or a file system with working ``flock``), not against other programs.
"""
from __future__ import annotations

import contextlib
import datetime as _dt
import errno
import fcntl
import os
import re
import secrets
import socket
import sys
import time
from pathlib import Path

from kanat.errors import KanatError, OutputWriteError
from kanat.io.space import is_disk_full, not_written, require_room

LOCK_SUFFIX = ".lock"
"""The sidecar lock of ``dir/NAME`` is ``dir/.NAME.lock``."""

PART_SUFFIX = ".part"
"""Temporary files are ``dir/.NAME.<random>.part`` until renamed."""

_OWNER_WAIT_S = 0.5
"""How long a refused run waits for the lock holder to write its pid into the sidecar [s]."""

_LOCK_ATTEMPTS = 20
"""Acquire attempts when the sidecar is replaced under us (a holder releasing at that moment)."""


def same_path(a, b) -> bool:
    """True when ``a`` and ``b`` name the same file (hard links and symlinks included).

    Existing files are compared by device and inode (:func:`os.path.samefile`); otherwise
    the absolute paths with symlinks resolved are compared.
    """
    a, b = Path(a).expanduser(), Path(b).expanduser()
    try:
        return os.path.samefile(a, b)
    except OSError:
        return a.resolve(strict=False) == b.resolve(strict=False)


def _refuse_inputs(output: Path, inputs, flag: str) -> None:
    for source in inputs:
        if source is not None and same_path(output, source):
            raise KanatError(f"{flag} {output} is also an input ({source}); writing there would destroy it. "
                             "Choose another output name.")


def _check_directory(folder: Path, output: Path) -> None:
    """The directory that will hold ``output`` exists, is a directory and accepts new files."""
    if not folder.exists():
        raise KanatError(f"cannot write {output}: the directory {folder} does not exist. "
                         f"Create it first (mkdir -p {folder}) or choose another output.")
    if not folder.is_dir():
        raise KanatError(f"cannot write {output}: {folder} is not a directory.")
    probe = folder / f".kanat-write-test.{secrets.token_hex(6)}"
    try:
        fd = os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except OSError as error:
        why = {errno.EROFS: "it is on a read-only file system", errno.EACCES: "permission denied",
               errno.EPERM: "permission denied", errno.ENOSPC: "the disk is full",
               errno.EDQUOT: "the disk quota is exceeded"}.get(error.errno, error.strerror)
        raise KanatError(f"cannot write {output}: the directory {folder} is not writable ({why}). "
                         "Choose an output in a directory you can write to.") from None
    os.close(fd)
    probe.unlink(missing_ok=True)


def check_output_file(output, inputs=(), flag: str = "-o", example: str = "result.nc") -> Path:
    """Check that ``output`` can be written as a file, before any work is done.

    Parameters
    ----------
    output : path-like
        The file a command will write (created or replaced).
    inputs : iterable of path-like
        Files the command reads (case file, result being reported, ...); the output
        must be none of them. ``None`` entries are ignored.
    flag : str
        How the user gave the output, for messages (``-o``, ``--report``).
    example : str
        A file name suggested when ``output`` is a directory.

    Returns
    -------
    pathlib.Path
        ``output`` as an absolute path (symlinks in its directory resolved).

    Raises
    ------
    KanatError
        One message per problem: the output is an input; it is a directory; it exists
        but is not a regular file (a device, a pipe); its directory is missing, is not a
        directory or cannot be written (read-only, permission denied).
    """
    if output is None or not str(output).strip():
        raise KanatError(f"{flag}: no output file given")
    path = Path(output).expanduser()
    _refuse_inputs(path, inputs, flag)
    if path.is_dir():
        raise KanatError(f"{flag} {output} is a directory; give a file name, e.g. {path / example}")
    if path.exists() and not path.is_file():
        raise KanatError(f"{flag} {output} exists and is not a regular file (a device, pipe or socket); "
                         "give a file name")
    if path.is_symlink() and not path.exists():
        raise KanatError(f"{flag} {output} is a broken symbolic link; remove it or give another name")
    folder = path.parent.resolve(strict=False)
    _check_directory(folder, path)
    return folder / path.name


def check_output_directory(output, inputs=(), flag: str = "-o") -> Path:
    """Check that ``output`` can be used as a study directory (existing or to be created).

    Parameters
    ----------
    output : path-like
        The directory a study writes (``kanat sweep -o DIR``).
    inputs : iterable of path-like
        Files the study reads (the base case); none may be ``output`` itself.
    flag : str
        How the user gave the output, for messages.

    Returns
    -------
    pathlib.Path
        The absolute path of the directory.

    Raises
    ------
    KanatError
        When ``output`` is an input, exists and is not a directory, or neither it (when it
        exists) nor its parent (when it does not) can be written; a missing parent is
        reported as such (it is not created).
    """
    if output is None or not str(output).strip():
        raise KanatError(f"{flag}: no output directory given")
    path = Path(output).expanduser()
    _refuse_inputs(path, inputs, flag)
    if path.exists() and not path.is_dir():
        raise KanatError(f"{flag} {output} exists and is not a directory; a study writes a directory of files. "
                         "Give a new directory name.")
    path = path.resolve(strict=False)
    _check_directory(path if path.exists() else path.parent, path)
    return path


def lock_path(output) -> Path:
    """The sidecar lock file of ``output``: ``.NAME.lock`` in the same directory."""
    output = Path(output)
    return output.with_name(f".{output.name}{LOCK_SUFFIX}")


class OutputLock:
    """An exclusive lock on an output for the duration of a run (``with OutputLock(path):``).

    The lock is ``fcntl.flock(LOCK_EX | LOCK_NB)`` on :func:`lock_path` of the output,
    which records the holder's pid, host, start time and command line. A second
    :class:`OutputLock` on the same output — from another process, or another open in
    this one — fails at once with a :class:`~kanat.errors.KanatError` naming the holder's
    pid. Leaving the ``with`` block (normally or by an exception) releases the lock and
    removes the sidecar; a process that dies releases it through the kernel (its sidecar
    stays, unlocked, and is reused).

    Parameters
    ----------
    output : path-like
        The output file or directory to protect (it need not exist yet).
    """

    def __init__(self, output):
        self.output = Path(output)
        self.path = lock_path(self.output)
        self._fd: int | None = None

    @property
    def held(self) -> bool:
        return self._fd is not None

    def acquire(self) -> OutputLock:
        """Take the lock or raise :class:`~kanat.errors.KanatError` naming the run that holds it."""
        if self._fd is not None:
            return self
        for _ in range(_LOCK_ATTEMPTS):
            try:
                fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
            except OSError as error:
                raise KanatError(f"cannot lock {self.output}: cannot create {self.path} ({error.strerror})") from None
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as error:
                if error.errno not in (errno.EAGAIN, errno.EACCES, errno.EWOULDBLOCK):
                    os.close(fd)
                    raise KanatError(f"cannot lock {self.output}: {error.strerror}") from None
                owner = _read_owner(fd)
                os.close(fd)
                raise KanatError(f"{self.output} is in use by another kanat run ({owner}); wait for it to finish "
                                 "or choose another output.") from None
            if _is_current(fd, self.path):
                _write_owner(fd)
                self._fd = fd
                return self
            os.close(fd)                         # the holder removed this sidecar while we opened it: retry
        raise KanatError(f"cannot lock {self.output}: its lock file {self.path} keeps changing")

    def release(self) -> None:
        """Release the lock and remove the sidecar (nothing when not held)."""
        fd, self._fd = self._fd, None
        if fd is None:
            return
        try:
            if _is_current(fd, self.path):
                self.path.unlink(missing_ok=True)     # removed while still locked: no one can take a stale one
        finally:
            fcntl.flock(fd, fcntl.LOCK_UN)
            os.close(fd)

    def __enter__(self) -> OutputLock:
        return self.acquire()

    def __exit__(self, *exc) -> None:
        self.release()

    def __del__(self):
        if self._fd is not None:
            with contextlib.suppress(OSError):
                os.close(self._fd)


def _is_current(fd: int, path: Path) -> bool:
    """Whether ``fd`` is still the file at ``path`` (same device and inode)."""
    try:
        here, there = os.fstat(fd), os.stat(path)
    except FileNotFoundError:
        return False
    return (here.st_dev, here.st_ino) == (there.st_dev, there.st_ino)


def _write_owner(fd: int) -> None:
    started = _dt.datetime.now().isoformat(timespec="seconds")
    command = " ".join(sys.argv)[:300]
    text = f"pid {os.getpid()} on {socket.gethostname()}, started {started}: {command}\n"
    os.ftruncate(fd, 0)
    os.pwrite(fd, text.encode("utf-8", "replace"), 0)


def _read_owner(fd: int) -> str:
    """What the lock holder wrote about itself (it may be writing it right now: wait a little)."""
    deadline = time.monotonic() + _OWNER_WAIT_S
    while True:
        text = os.pread(fd, 1000, 0).decode("utf-8", "replace").strip()
        if text or time.monotonic() > deadline:
            return text or "pid unknown"
        time.sleep(0.02)


_TEMPORARY = re.compile(r"\..+\.[0-9a-f]{8}\.part(\.part)?")
"""Names made by :func:`_temporary_name` (and a writer's own ``.part`` of one)."""


def _temporary_name(target: Path) -> Path:
    return target.with_name(f".{target.name}.{secrets.token_hex(4)}{PART_SUFFIX}")


def remove_temporaries(folder) -> list[Path]:
    """Remove the temporary files of :func:`atomic_path` left in ``folder`` by a killed writer.

    Only call this while holding the :class:`OutputLock` of what ``folder`` belongs to:
    then no other writer can be using them. Returns the files removed.
    """
    removed = []
    for path in Path(folder).glob(".*.part*"):
        if _TEMPORARY.fullmatch(path.name) and path.is_file():
            path.unlink(missing_ok=True)
            removed.append(path)
    return removed


@contextlib.contextmanager
def atomic_path(target):
    """A temporary path beside ``target``, renamed over it when the block succeeds.

    The writer creates and closes the file at the yielded path; on leaving the block
    without an exception it replaces ``target`` in one ``os.replace``. On an exception
    the temporary file is removed and ``target`` is left as it was.

    Parameters
    ----------
    target : path-like
        The final file (its directory must exist).

    Yields
    ------
    pathlib.Path
        ``dir/.NAME.<random>.part``: unique, so concurrent writers never share it.

    Examples
    --------
    >>> with atomic_path("summary.nc") as tmp:                         # doctest: +SKIP
    ...     dataset.to_netcdf(tmp)
    """
    target = Path(target)
    tmp = _temporary_name(target)
    try:
        yield tmp
        if not tmp.exists():
            raise KanatError(f"the writer of {target} did not create its file")
        os.replace(tmp, target)
    except BaseException as error:
        tmp.unlink(missing_ok=True)
        if is_disk_full(error) and not isinstance(error, OutputWriteError):
            raise not_written(target) from None
        raise


def write_bytes_atomic(target, data: bytes) -> Path:
    """Write ``data`` to ``target`` atomically (temporary file, fsync, rename); return ``target``."""
    target = Path(target)
    require_room(target, len(data), str(target), "free some space and write it again")
    with atomic_path(target) as tmp:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        try:
            view = memoryview(data)
            while view:
                view = view[os.write(fd, view):]
            os.fsync(fd)
        finally:
            os.close(fd)
    return target


def write_text_atomic(target, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``target`` atomically; return ``target``."""
    return write_bytes_atomic(target, text.encode("utf-8"))

