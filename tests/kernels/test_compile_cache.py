"""The install compiles the kernels once per machine (:mod:`kanat.aot_cache`).

Oracles: a build function that counts its calls (the second install with the same key must not
call it, and must get the first one's bytes), the key of an edited copy of the sources, and
``setup.py build_ext`` itself run against a cache holding this tree's compiled modules: it must
copy them bit for bit and compile nothing.
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from kanat import aot, aot_cache

from helpers import ROOT



@pytest.fixture
def cache(tmp_path, monkeypatch) -> Path:
    directory = tmp_path / "cache"
    monkeypatch.setenv(aot_cache.ENVIRONMENT, str(directory))
    return directory


class Counting:
    """A build writing each missing target with a counter in it, counting its calls."""

    def __init__(self):
        self.calls = 0

    def __call__(self, missing):
        self.calls += 1
        for target in missing:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(f"build {self.calls} of {target.name}".encode())
        return list(missing)


def targets(directory: Path) -> list[Path]:
    return [directory / f"{name}.so" for name in aot.MODULES]


def test_a_second_build_with_the_same_key_is_a_copy(cache, tmp_path):
    build = Counting()
    first = aot_cache.build_once(targets(tmp_path / "first"), build)
    second = aot_cache.build_once(targets(tmp_path / "second"), build)
    assert build.calls == 1
    assert first["built"] == targets(tmp_path / "first") and first["copied"] == []
    assert second["copied"] == targets(tmp_path / "second") and second["built"] == []
    assert first["key"] == second["key"] == aot_cache.key()
    for a, b in zip(targets(tmp_path / "first"), targets(tmp_path / "second")):
        assert a.read_bytes() == b.read_bytes() == f"build 1 of {a.name}".encode()
    assert (cache / aot_cache.key() / aot_cache.BUILT).is_file()


def test_a_changed_source_or_compiler_gives_a_new_key(tmp_path, monkeypatch):
    package = tmp_path / "kanat"
    shutil.copytree(Path(aot.__file__).parent, package, ignore=shutil.ignore_patterns("*.so", "__pycache__"))
    assert aot_cache.key(package) == aot_cache.key()
    rows = package / "lumped" / "kernels.py"
    rows.write_text(rows.read_text() + "\n")
    assert aot_cache.key(package) != aot_cache.key()
    before = aot_cache.key()
    monkeypatch.setattr(aot_cache, "_version", lambda name: "0.0.1" if name == "numba" else "1")
    assert aot_cache.key() != before


def test_an_unusable_cache_builds_in_place(tmp_path, monkeypatch, capsys):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    monkeypatch.setenv(aot_cache.ENVIRONMENT, str(blocker / "cache"))
    build = Counting()
    for place in ("first", "second"):
        outcome = aot_cache.build_once(targets(tmp_path / place), build)
        assert outcome["built"] == targets(tmp_path / place)
    assert build.calls == 2 and "were not cached" in capsys.readouterr().err
    monkeypatch.setenv(aot_cache.ENVIRONMENT, "0")                     # off
    assert aot_cache.root() is None and aot_cache.build_once(targets(tmp_path / "third"), build)["key"] is None
    assert build.calls == 3


def test_an_incomplete_entry_is_not_used(cache, tmp_path):
    entry = cache / aot_cache.key()
    entry.mkdir(parents=True)
    for target in targets(entry):
        target.write_bytes(b"half written")                                # no key.json: a build that died
    build = Counting()
    assert aot_cache.build_once(targets(tmp_path / "out"), build)["built"] and build.calls == 1


def test_the_cache_keeps_the_most_recently_used_entries(cache, tmp_path):
    for i in range(aot_cache.KEEP + 2):
        entry = cache / f"entry{i}"
        aot_cache.store(entry, [], {"i": i})
        os.utime(entry / aot_cache.BUILT, (1e9 + i, 1e9 + i))
    aot_cache.prune(cache)
    assert sorted(path.name for path in cache.iterdir()) == [f"entry{i}" for i in range(2, aot_cache.KEEP + 2)]


@pytest.mark.slow
def test_setup_copies_the_cached_modules_and_compiles_nothing(cache, tmp_path):
    """``setup.py build_ext`` with this tree's compiled modules in the cache under this tree's key."""
    if not aot.current():
        pytest.skip("this tree's kernels are not compiled (python -m kanat.aot_build)")
    built = [Path(aot.load(name).__file__) for name in aot.MODULES]
    aot_cache.store(cache / aot_cache.key(), built, aot_cache.ingredients())
    project = tmp_path / "project"                 # setup.py and the sources (the package metadata is pip's business)
    project.mkdir()
    shutil.copy(ROOT / "setup.py", project)
    (project / "src").symlink_to(ROOT / "src")
    lib = tmp_path / "lib"
    done = subprocess.run([sys.executable, "setup.py", "-q", "build_ext", "--build-lib", str(lib), "--build-temp",
                           str(tmp_path / "temp")], cwd=project, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert f"kanat kernels: {len(built)} copied from the cache {aot_cache.key()}, 0 compiled" in done.stderr
    for path in built:
        assert (lib / "kanat" / path.name).read_bytes() == path.read_bytes()
    assert not (tmp_path / "temp").exists() or not list((tmp_path / "temp").rglob("*.o"))


def test_a_restore_replaces_a_loaded_module_instead_of_rewriting_it(cache, tmp_path):
    """A run that has the old modules open (mapped) while an install restores new ones keeps reading
    its own bytes: the restore renames a whole new file over the name, it does not write into it."""
    aot_cache.build_once(targets(tmp_path / "first"), Counting())
    out = targets(tmp_path / "out")
    for target in out:
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(b"the module a run has loaded")
    with open(out[0], "rb") as loaded:
        result = aot_cache.build_once(out, Counting())
        assert result["copied"] == out
        assert loaded.read() == b"the module a run has loaded"
    assert out[0].read_bytes() == f"build 1 of {out[0].name}".encode()
    assert not [p for p in out[0].parent.iterdir() if p.name.startswith(".")]
