"""The kernels compiled at install (:mod:`kanat.aot`) against numba's, and the guards that keep them honest.

* The install built the extension and it is current: a build that failed quietly (the
  extension is optional) would otherwise leave every run compiling without anyone noticing.
* Its kernels are numba's bit for bit (oracle: the just-in-time kernel on the same arrays): on
  every Newton iteration of plain runs and of runs with seabed, waves, inline bodies or a surface
  buoy, planar and spatial, and of a spatial run with bending stiffness.
* A source edited after the build makes the extension unused (fingerprint), and
  :data:`kanat.aot.SOURCES` lists every module the compiled kernels read.
* Runs of every family compiled at install, in fresh processes, load no numba at all and write
  the file a ``KANAT_AOT=0`` run writes, to the last bit.
"""
import os
import shutil
import subprocess
import sys
from importlib import import_module
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

from kanat import aot, api, warmup
from kanat.continuum import kernels2d, kernels3d

from helpers import EXAMPLES

pytestmark = pytest.mark.skipif(os.environ.get("KANAT_AOT") == "0",
                                reason="KANAT_AOT=0: an install without the kernels compiled at install (docs/kernels.md)")


def test_the_install_built_the_extensions_and_they_are_current():
    assert aot.current(), "kanat's compiled kernels are missing or stale: pip install -e . (or python -m kanat.aot_build)"
    for name in aot.MODULES:
        assert aot.load(name).fingerprint() == aot.fingerprint()


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
    compiled = getattr(kernels, name)                             # the entry point the runs call
    numba_kernel = getattr(import_module(aot.ENTRIES[name].home), name)
    assert aot.kernel(name) is not numba_kernel                  # it runs the install's kernel, not numba's
    calls = []

    def both(x, step, res, band):
        compiled(x, step, res, band)
        res2, band2 = np.full_like(res, np.nan), np.full_like(band, np.nan)
        numba_kernel(x, step, res2, band2)
        assert np.array_equal(res, res2) and np.array_equal(band, band2)
        calls.append(step.extras is None)

    monkeypatch.setattr(kernels, name, both)
    case = api.load_case(case).replace(changes)
    assert api.run(case).summary.status == "ok"
    assert len(calls) > 20 and len(set(calls)) == 1          # one version throughout: plain, or full


def test_arguments_the_compiled_code_would_misread_go_to_numba():
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
    compiled = SimpleNamespace(assemble__0=lambda *args: calls.append(args),      # neither must be called
                               assemble__1=lambda *args: calls.append(args))
    assemble = aot._kernel("assemble", compiled)
    from kanat.continuum.layout2d import NPAR

    # the rows hold a 1-knot law, read within them
    sizes = [(5, 4), (5, 4), (5, 4), (5, 6), (4, NPAR + 4), (16,), (16,), (20,), (11, 20)]
    args = [np.asfortranarray(np.ones(shape)) if len(shape) == 2 else np.ones(shape) for shape in sizes]
    args[4][:, 12] = 1.0                                                   # dt: a finite answer
    expected = [a.copy() for a in args]
    rows2d = import_module("kanat.continuum.rows2d")
    rows2d.assemble(expected[0], kernels2d.PlanarStep(*expected[1:7], None), *expected[7:])
    assemble(args[0], kernels2d.PlanarStep(*args[1:7], None), *args[7:])   # Fortran-ordered fields: numba's
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
    # a process that sees the edited sources beside the built modules uses none of them
    script = ("import sys; sys.path.insert(0, sys.argv[1]); import kanat, shutil, glob, os\n"
              "copied = [shutil.copy(f, os.path.dirname(kanat.__file__)) for f in glob.glob(sys.argv[2])]\n"
              "from kanat import aot; print(len(copied), [aot.load(name) for name in aot.MODULES])")
    shared = os.path.join(os.path.dirname(aot.__file__), "_*.so")
    out = subprocess.run([sys.executable, "-c", script, str(tmp_path), shared], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == f"{len(aot.MODULES)} {[None] * len(aot.MODULES)}"


def test_the_build_needs_numba_and_numpy_only():
    """pip builds the extension in an environment holding the build requirements only (numba,
    NumPy, setuptools): describing it must import nothing else (here: everything else refused)."""
    script = ("import sys, importlib.abc\n"
              "class Refuse(importlib.abc.MetaPathFinder):\n"
              "    def find_spec(self, name, path, target=None):\n"
              "        if name.split('.')[0] in {'scipy', 'pydantic', 'yaml', 'xarray', 'h5netcdf', 'h5py', 'typer',\n"
              "                                  'rich'}:\n"
              "            raise ImportError(f'{name} is not in the build environment')\n"
              "sys.meta_path.insert(0, Refuse())\n"
              "import kanat.aot_build\n"
              "print(sum(len(cc._exported_functions) for cc in kanat.aot_build.compilers()))")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    for module in import_module("kanat.aot_build").DECLARING:
        import_module(module)
    exported = len(aot.MODULES) + sum(len(entry.versions) for entry in aot.ENTRIES.values())   # and fingerprints
    assert int(out.stdout) == exported > 30


def test_sources_list_every_module_the_compiled_kernels_read():
    """Every module defining a kernel the build compiles, the layouts they read and the entries'
    declarations are fingerprinted (an edit anywhere there must retire the extension)."""
    script = ("import sys, kanat.aot_build; kanat.aot_build.compilers()\n"
              "from kanat.jit import KERNELS\n"
              "print('\\n'.join(sorted({sys.modules[k.__module__].__file__ for k in KERNELS})))")
    files = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout.split()
    root = os.path.dirname(aot.__file__)
    kernels = {os.path.relpath(f, root) for f in files}
    assert kernels >= {"continuum/rows2d.py", "continuum/rows3d.py", "lumped/fast_implicit.py", "physics/contact.py"}
    declared = {"jit.py", "aot.py", "aot_build.py", "continuum/kernels2d.py", "continuum/kernels3d.py",
                "lumped/entries.py"}                                   # and the kernels' compile options
    layouts = {"continuum/layout2d.py", "continuum/layout3d.py", "physics/seabed.py"}
    assert set(aot.SOURCES) == kernels | declared | layouts


RUN = """import sys, kanat.api as api
from kanat import aot
case = api.load_case(sys.argv[1])
if len(sys.argv) > 3:
    case = case.replace({"simulation.duration": float(sys.argv[3]), **eval(sys.argv[4])})
outcome = api.run(case, output=sys.argv[2])
from kanat.jit import compiled_versions
jit = sorted(compiled_versions())
print(outcome.summary.status, outcome.summary.steps > 0, "numba" in sys.modules, sorted(aot._numba_used), jit)
"""


@pytest.mark.parametrize("example, duration, changes", [
    ("speed_step_2d.yaml", None, {}),
    ("turn_360_3d.yaml", 100.0, {}),
    ("mooring_buoy_decay.yaml", 5.0, {}),                                     # rk4, 6-DOF body, seabed
    ("lazy_wave.yaml", 10.0, {}),                                             # implicit, seabed
    ("mooring_buoy_waves.yaml", 3.0, {"simulation.scheme": "abm4"}),
    ("trawl_head_8s_1to2.yaml", 2.0, {"simulation.scheme": "generalized-alpha-lumped"}),   # no seabed
    ("factorization_planar80.yaml", 2.0, {}),                                       # wave-factorized, planar
    ("factorization_spatial100.yaml", 1.0, {}),                                     # wave-factorized-2, spatial
    ("factorization_accel.yaml", 1.0, {}),                                          # factorized, planar
    ("factorization_spatial100.yaml", 1.0, {"simulation.scheme": "factorized"}),
])
def test_runs_compile_nothing_and_write_what_numba_would(example, duration, changes, tmp_path):
    """Whole runs in fresh processes, with the install's kernels and with numba's (KANAT_AOT=0):
    the same file to the last bit; with the install's, numba is not even imported."""
    answers = {}
    for flag in ("1", "0"):
        output = tmp_path / f"aot{flag}.nc"
        extra = [] if duration is None else [str(duration), repr(changes)]
        out = subprocess.run([sys.executable, "-c", RUN, str(EXAMPLES / example), str(output), *extra],
                             capture_output=True, text=True, check=True, env={**os.environ, "KANAT_AOT": flag})
        answers[flag] = out.stdout.strip().splitlines()[-1]
    assert answers["1"] == "ok True False [] []"
    assert answers["0"].startswith("ok True True [] ") and answers["0"] != "ok True True [] []"
    with xr.open_dataset(tmp_path / "aot1.nc") as a, xr.open_dataset(tmp_path / "aot0.nc") as b:
        assert set(a.data_vars) == set(b.data_vars) and len(a.data_vars) >= 5
        for name in a.data_vars:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)


def test_a_first_run_of_every_family_compiles_nothing(tmp_path):
    """A fresh machine's first runs: an empty numba cache, each family's tiny case run by
    ``kanat run`` — nothing is announced, nothing compiled, nothing written to the cache."""
    import yaml

    cache = tmp_path / "cache"
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache)}
    for name, case in warmup.CASES.items():
        path = tmp_path / f"{name}.yaml"
        path.write_text(yaml.safe_dump(case))
        done = subprocess.run([sys.executable, "-m", "kanat.cli", "run", str(path), "-o", str(tmp_path / f"{name}.nc")],
                              env=env, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        assert "compiling 0.00 s" in done.stdout and "compiling the" not in done.stderr, (name, done.stdout)
    assert not cache.exists() or not any(cache.rglob("*.nbi"))
