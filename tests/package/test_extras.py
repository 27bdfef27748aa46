"""The light install: the base package runs cases without the optional packages, and a verb
that needs one says which extra to install. Oracles: Python's import system (the optional
modules blocked in a subprocess) and pyproject.toml."""
import subprocess
import sys
import tomllib

import pytest
import yaml

from kanat import extras
from kanat.errors import KanatError
from kanat.warmup import CASES

from helpers import ROOT

OPTIONAL = sorted({name for names in extras.EXTRAS.values() for name in names})


def test_require_returns_the_module():
    assert extras.require("plot", "matplotlib.figure").Figure is not None
    assert extras.available("plot")


@pytest.mark.parametrize("extra, module", [("plot", "matplotlib.figure"), ("report", "plotly.io"),
                                           ("studies", "dask.distributed"), ("vtk", "meshio")])
def test_a_missing_extra_names_the_pip_command(monkeypatch, extra, module):
    top = module.split(".")[0]
    for name in [n for n in sys.modules if n == top or n.startswith(top + ".")] + [top, module]:
        monkeypatch.setitem(sys.modules, name, None)                        # as if not installed
    with pytest.raises(KanatError, match=rf"pip install 'kanat\[{extra}\]'") as info:
        extras.require(extra, module, feature="kanat test-verb")
    assert str(info.value).startswith("kanat test-verb needs the optional package")


def test_pyproject_declares_the_extras_and_keeps_them_out_of_the_core():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    core = " ".join(project["dependencies"])
    for extra, names in extras.EXTRAS.items():
        listed = " ".join(project["optional-dependencies"][extra])
        for name in names:
            assert name not in core
            assert name in listed or (name == "distributed" and "dask[distributed]" in listed)
    assert set(extras.EXTRAS) <= {e.strip() for e in project["optional-dependencies"]["all"][0]
                                  .split("[")[1].rstrip("]").split(",")}


def run_without_extras(args, tmp_path):
    code = ("import sys; sys.modules.update({m: None for m in %r}); from kanat.cli import app; app(%r)"
            % (OPTIONAL, args))
    return subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("args", [["--version"], ["validate", "examples/towed_body.yaml"]])
def test_the_light_verbs_need_no_extra(args, tmp_path):
    done = run_without_extras(args, tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.slow
@pytest.mark.parametrize("family", ["continuum-2d", "lumped-implicit"])
def test_a_run_needs_no_extra(family, tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text(yaml.safe_dump(CASES[family], sort_keys=False))
    done = run_without_extras(["run", str(case), "-o", str(tmp_path / "out.nc")], tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (tmp_path / "out.nc").exists()
