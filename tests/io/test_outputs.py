"""Output safety (issue 14 item 5): outputs that are inputs, directories, missing or read-only
directories are refused each with its own message; an exclusive lock refuses a second run on
the same output (across processes, naming the holder's pid) and is released however the
run ends; atomic writes leave the old file or the new one, never a part.

Oracles: the file system itself (inode identity, the bytes on disk), the kernel's flock
semantics observed from a second process, and a process run as an unprivileged user.
"""
import os
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import pytest

from kanat.errors import KanatError
from kanat.io.outputs import (OutputLock, atomic_path, check_output_directory, check_output_file, lock_path,
                              remove_temporaries, same_path, write_text_atomic)


def test_output_that_is_an_input_is_refused(tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text("name: x\n")
    os.symlink(case, tmp_path / "link.yaml")
    os.link(case, tmp_path / "hard.yaml")
    for output in (case, tmp_path / "link.yaml", tmp_path / "hard.yaml", tmp_path / "sub" / ".." / "case.yaml"):
        with pytest.raises(KanatError, match=r"is also an input .*case\.yaml.*destroy it"):
            check_output_file(output, inputs=[case])
    assert case.read_text() == "name: x\n"
    assert check_output_file(tmp_path / "run.nc", inputs=[case, None]) == tmp_path.resolve() / "run.nc"
    assert same_path(tmp_path / "hard.yaml", case) and not same_path(tmp_path / "run.nc", case)


def test_each_bad_output_has_its_own_message(tmp_path):
    with pytest.raises(KanatError, match=r"is a directory; give a file name, e\.g\. .*result\.nc"):
        check_output_file(tmp_path)
    with pytest.raises(KanatError, match=r"the directory .*missing does not exist\. Create it first"):
        check_output_file(tmp_path / "missing" / "run.nc")
    (tmp_path / "plain").write_text("")
    with pytest.raises(KanatError, match=r"plain is not a directory"):
        check_output_file(tmp_path / "plain" / "run.nc")
    with pytest.raises(KanatError, match="not a regular file"):
        check_output_file("/dev/null")
    with pytest.raises(KanatError, match="no output file given"):
        check_output_file("")
    with pytest.raises(KanatError, match="exists and is not a directory; a study writes a directory"):
        check_output_directory(tmp_path / "plain")
    with pytest.raises(KanatError, match="does not exist"):
        check_output_directory(tmp_path / "missing" / "study")
    assert check_output_directory(tmp_path / "study") == tmp_path.resolve() / "study"
    assert not list(tmp_path.glob(".kanat-write-test*"))          # the writability probe cleans up


def _as_nobody(function, *args):
    """Run ``function(*args)`` in a forked child with uid/gid 65534; return its KanatError text or ''."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:                                                  # the child: drop root, try, report
        try:
            os.close(read)
            if os.getuid() == 0:
                os.setgroups([])
                os.setgid(65534)
                os.setuid(65534)
            try:
                function(*args)
                message = ""
            except KanatError as error:
                message = str(error)
            os.write(write, message.encode())
        finally:
            os._exit(0)
    os.close(write)
    with os.fdopen(read) as pipe:
        text = pipe.read()
    os.waitpid(pid, 0)
    return text


def test_read_only_directory_is_refused():
    root = Path(tempfile.mkdtemp(prefix="kanat-ro-"))           # outside pytest's private tmp (mode 700)
    try:
        os.chmod(root, 0o755)
        readonly = root / "readonly"
        readonly.mkdir(mode=0o555)
        os.chmod(readonly, 0o555)
        text = _as_nobody(check_output_file, readonly / "run.nc")
        assert "not writable (permission denied)" in text and "readonly" in text, text
        text = _as_nobody(check_output_directory, readonly / "study")
        assert "not writable (permission denied)" in text, text
        writable = root / "open"
        writable.mkdir(mode=0o777)
        os.chmod(writable, 0o777)
        assert _as_nobody(check_output_file, writable / "run.nc") == ""
    finally:
        for folder in (root / "readonly", root / "open"):
            if folder.exists():
                os.chmod(folder, 0o755)
        import shutil

        shutil.rmtree(root)


HOLDER = textwrap.dedent("""
    import sys, time
    from kanat.io.outputs import OutputLock
    lock = OutputLock(sys.argv[1]).acquire()
    print("locked", flush=True)
    if sys.argv[2] == "exit":
        sys.stdin.readline()
        lock.release()
    else:
        time.sleep(120)
""")


def _holder(output, mode):
    proc = subprocess.Popen([sys.executable, "-c", HOLDER, str(output), mode], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "locked"
    return proc


def test_lock_refuses_a_second_process_and_names_its_pid(tmp_path):
    output = tmp_path / "same.nc"
    proc = _holder(output, "exit")
    try:
        assert lock_path(output).exists()
        with pytest.raises(KanatError, match=rf"same\.nc is in use by another kanat run \(pid {proc.pid} on "):
            OutputLock(output).acquire()
    finally:
        proc.stdin.write("\n")
        proc.stdin.close()
        proc.wait(timeout=30)
    assert not lock_path(output).exists()                         # released and removed by its holder
    with OutputLock(output) as lock:
        assert lock.held
        with pytest.raises(KanatError, match=f"pid {os.getpid()}"):
            OutputLock(output).acquire()                          # a second open in this process too
    assert not lock.held and not lock_path(output).exists()


def test_lock_of_a_killed_process_is_free_and_exceptions_release(tmp_path):
    output = tmp_path / "run.nc"
    proc = _holder(output, "sleep")
    with pytest.raises(KanatError, match=f"pid {proc.pid}"):
        OutputLock(output).acquire()
    proc.kill()                                                  # SIGKILL: no cleanup code runs
    proc.wait(timeout=30)
    assert lock_path(output).exists()                             # the sidecar stays, unlocked
    with OutputLock(output):
        assert f"pid {os.getpid()}" in lock_path(output).read_text()
    with pytest.raises(RuntimeError, match="boom"):
        with OutputLock(output):
            raise RuntimeError("boom")
    with OutputLock(output):                                     # free again after the exception
        pass


def test_atomic_writes_replace_whole_or_not_at_all(tmp_path):
    target = tmp_path / "summary.csv"
    write_text_atomic(target, "old\n")
    with pytest.raises(ValueError):
        with atomic_path(target) as tmp:
            tmp.write_text("half of the new")
            raise ValueError("the writer failed")
    assert target.read_text() == "old\n" and sorted(p.name for p in tmp_path.iterdir()) == ["summary.csv"]
    inode = target.stat().st_ino
    with atomic_path(target) as tmp:
        assert tmp.parent == tmp_path and tmp.name.startswith(".summary.csv.") and tmp.name.endswith(".part")
        tmp.write_text("new\n")
        assert target.read_text() == "old\n"                      # untouched until the rename
    assert target.read_text() == "new\n" and target.stat().st_ino != inode
    with atomic_path(target) as a, atomic_path(target) as b:
        assert a != b                                             # concurrent writers never share a name
        a.write_text("a")
        b.write_text("b")
    assert target.read_text() == "a" and sorted(p.name for p in tmp_path.iterdir()) == ["summary.csv"]
    write_text_atomic(target, "last\n")
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask         # an ordinary file, not a private temp



def test_temporaries_of_a_killed_writer_are_removed_and_nothing_else(tmp_path):
    names = [".summary.nc.0123abcd.part", ".summary.nc.0123abcd.part.part", "run.nc.part", ".hidden",
             ".summary.nc.lock", "summary.nc"]
    for name in names:
        (tmp_path / name).write_text("x")
    removed = remove_temporaries(tmp_path)
    assert sorted(p.name for p in removed) == names[:2]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(names[2:])
