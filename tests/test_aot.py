"""The kernels compiled at install (:mod:`kanat.aot`) against numba's, and the guards that keep them honest.

* The install built the extension and it is current: a build that failed quietly (the
  extension is optional) would otherwise leave every run compiling without anyone noticing.
* Its kernels are numba's bit for bit (oracle: the just-in-time kernel on the same arrays): on
  every Newton iteration of plain runs and of runs with seabed, waves, inline bodies or a surface
  buoy, planar and spatial, and of a spatial run with bending stiffness.
* A source edited after the build makes the extension unused (fingerprint), and
  :data:`kanat.aot.SOURCES` lists every module the compiled kernels read.
* A 2-D run in a fresh process loads no numba, and writes the file a ``KANAT_AOT=0`` run writes.
"""
import os
import shutil
import subprocess
import sys
from importlib import import_module

import numpy as np
import pytest
import xarray as xr

from kanat import aot, api, warmup
from kanat.continuum import kernels2d, kernels3d

from helpers import EXAMPLES


def test_the_install_built_the_extension_and_it_is_current():
    compiled = aot.load()
    assert compiled is not None, "kanat._kernels is missing or stale: pip install -e . (or python -m kanat.aot_build)"
    assert compiled.fingerprint() == aot.fingerprint()


BENDING_3D = {**warmup.CASES["continuum-3d-bending"], "simulation": {
    **warmup.CASES["continuum-3d-bending"]["simulation"], "duration": 20.0}}


@pytest.mark.parametrize("case, changes, kernels, name", [
    (EXAMPLES / "speed_step_2d.yaml", {"simulation.duration": 60}, kernels2d, "assemble"),
    (EXAMPLES / "surface_mooring_waves.yaml", {"simulation.duration": 8}, kernels2d, "assemble"),
    (EXAMPLES / "turn_360_3d.yaml", {"simulation.duration": 60}, kernels3d, "assemble3"),
    (EXAMPLES / "subsurface_mooring.yaml", {"simulation.duration": 10, "simulation.dimensions": 3}, kernels3d,
     "assemble3"),
    (BENDING_3D, {}, kernels3d, "assemble3_bending"),
], ids=["plain-2d", "full-2d", "plain-3d", "full-3d", "bending-3d"])
def test_compiled_kernels_are_numbas_bit_for_bit(case, changes, kernels, name, monkeypatch):
    compiled = getattr(kernels, name)
    numba_kernel = getattr(import_module(aot.ENTRIES[name][0]), name)
    assert compiled is not numba_kernel                          # the install's kernel, not numba's
    calls = []

    def both(*args):
        res, band = args[-3], args[-2]
        compiled(*args)
        res2, band2 = np.full_like(res, np.nan), np.full_like(band, np.nan)
        numba_kernel(*args[:-3], res2, band2, args[-1])
        assert np.array_equal(res, res2) and np.array_equal(band, band2)
        calls.append(args[-1] is None)

    monkeypatch.setattr(kernels, name, both)
    case = api.load_case(case).replace(changes)
    assert api.run(case).summary.status == "ok"
    assert len(calls) > 20 and len(set(calls)) == 1          # one version throughout: plain, or full


def test_arguments_the_compiled_code_would_misread_go_to_numba(monkeypatch):
    """Compiled code reads its arrays as its signature says, unchecked: anything else must not reach it."""
    good = np.zeros((3, 4))
    assert aot.matches(good, aot.F2) and aot.matches((good, None), (aot.F2, None))
    readonly = good.copy()
    readonly.flags.writeable = False
    for bad in (good[:, ::2], good.T, good.astype(np.float32), good[0], readonly, good.tolist(),
                np.asfortranarray(np.zeros((3, 4))), np.zeros((3, 4), dtype=int)):
        assert not aot.matches(bad, aot.F2)
    assert not aot.matches(np.zeros(1), None) and not aot.matches(None, aot.F1)
    assert not aot.matches([good], (aot.F2,)) and not aot.matches((good,), (aot.F2, aot.F2))
    assert aot.matches(1.5, aot.FLOAT) and aot.matches(np.float64(1.5), aot.FLOAT) and not aot.matches(1, aot.FLOAT)

    calls = []
    compiled = aot.load()
    monkeypatch.setattr(compiled, "assemble__0", lambda *args: calls.append(args))   # must not be called
    monkeypatch.setattr(aot, "_loaded", {"_kernels": compiled})
    assemble = aot.kernel("assemble")
    sizes = [(5, 4), (5, 4), (5, 4), (5, 6), (4, 40), (16,), (16,), (20,), (11, 20)]
    args = [np.asfortranarray(np.ones(shape)) if len(shape) == 2 else np.ones(shape) for shape in sizes]
    args[4][:, 12] = 1.0                                                   # dt: a finite answer
    expected = [a.copy() for a in args]
    rows2d = import_module("kanat.continuum.rows2d")
    rows2d.assemble(*expected, None)
    assemble(*args, None)                                                 # Fortran-ordered: numba's
    assert calls == []
    np.testing.assert_array_equal(args[-2], expected[-2])
    np.testing.assert_array_equal(args[-1], expected[-1])


def test_an_edited_source_makes_the_extension_unused(tmp_path):
    package = tmp_path / "kanat"
    shutil.copytree(os.path.dirname(aot.__file__), package, ignore=shutil.ignore_patterns("*.so", "__pycache__"))
    assert aot.fingerprint(package) == aot.fingerprint()
    rows = package / "continuum" / "rows2d.py"
    rows.write_text(rows.read_text().replace("band[:, :] = 0.0", "band[:, :] = 0.0 "))
    assert aot.fingerprint(package) != aot.fingerprint()
    # in a process that sees the edited sources, load() answers None: the run compiles with numba
    script = ("import sys; sys.path.insert(0, sys.argv[1]); import kanat, shutil, glob, os\n"
              "[shutil.copy(f, os.path.dirname(kanat.__file__)) for f in glob.glob(sys.argv[2])]\n"
              "from kanat import aot; print(aot.load() is None)")
    shared = os.path.join(os.path.dirname(aot.__file__), "_kernels*.so")
    out = subprocess.run([sys.executable, "-c", script, str(tmp_path), shared], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "True"


def test_sources_list_every_module_the_compiled_kernels_read():
    script = ("import sys, kanat.aot_build; kanat.aot_build.compiler()\n"
              "print('\\n'.join(m.__file__ for n, m in sys.modules.items() if n.startswith('kanat')))")
    files = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout.split()
    root = os.path.dirname(aot.__file__)
    read = {os.path.relpath(f, root) for f in files} - {"__init__.py", "continuum/__init__.py", "physics/__init__.py",
                                                         "version.py"}
    assert read == set(aot.SOURCES)


def test_a_planar_run_loads_no_numba_and_writes_what_numba_would(tmp_path):
    script = ("import sys, kanat.api as api\n"
              "outcome = api.run(api.load_case(sys.argv[1]), output=sys.argv[2])\n"
              "print(outcome.summary.status, 'numba' in sys.modules, 'scipy.optimize' in sys.modules)")
    runs = {}
    for flag in ("1", "0"):
        env = {**os.environ, "KANAT_AOT": flag}
        output = tmp_path / f"aot{flag}.nc"
        out = subprocess.run([sys.executable, "-c", script, str(EXAMPLES / "speed_step_2d.yaml"), str(output)],
                             capture_output=True, text=True, check=True, env=env)
        runs[flag] = out.stdout.split()
    assert runs["1"] == ["ok", "False", "False"] and runs["0"] == ["ok", "True", "False"]
    with xr.open_dataset(tmp_path / "aot1.nc") as a, xr.open_dataset(tmp_path / "aot0.nc") as b:
        assert set(a.data_vars) == set(b.data_vars) and len(a.data_vars) >= 8
        for name in a.data_vars:
            np.testing.assert_array_equal(a[name].values, b[name].values)
