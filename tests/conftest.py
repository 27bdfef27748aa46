"""Fixtures shared by the test modules: the peers (MoorDyn, MoorPy) or a skip naming the extra
that brings them, and case files written to a test's own folder.

The default selection leaves out tests marked ``slow`` (``addopts`` in ``pyproject.toml``);
``python -m pytest -q -m slow`` runs them, ``-m ""`` runs everything (README, "Run the tests").
Helpers that are not fixtures live in ``helpers.py``.
"""
import shutil
from pathlib import Path

import pytest
import yaml

PEERS = "the peers extra (in the test extra: pip install -e '.[test]') provides {}"


@pytest.fixture(scope="session")
def moordyn():
    """The ``moordyn`` package (MoorDyn v2's Python API), or the test is skipped."""
    return pytest.importorskip("moordyn", reason=PEERS.format("moordyn"))


@pytest.fixture(scope="session")
def moorpy():
    """The ``moorpy`` package, or the test is skipped."""
    return pytest.importorskip("moorpy", reason=PEERS.format("moorpy"))


@pytest.fixture
def case_file(tmp_path):
    """``case_file(case, name="case.yaml")``: ``case`` (YAML text, or a dict dumped as YAML in its
    own key order) written to ``name`` in the test's temporary folder; returns the path."""
    def write(case, name: str = "case.yaml") -> Path:
        path = tmp_path / name
        path.write_text(case if isinstance(case, str) else yaml.safe_dump(case, sort_keys=False))
        return path
    return write


@pytest.fixture
def moordyn_folder(tmp_path):
    """``moordyn_folder(*files)``: ``files`` copied into the test's temporary folder, where MoorDyn
    writes its outputs beside its input; returns the copy of the first."""
    def copy(*files: Path) -> Path:
        for path in files:
            shutil.copy(path, tmp_path / Path(path).name)
        return tmp_path / Path(files[0]).name
    return copy
