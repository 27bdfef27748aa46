"""The kernels compiled at install (:mod:`kanat.aot`) against numba's, and the guards that keep them honest.

* The install built the extension and it is current: a build that failed quietly (the
  extension is optional) would otherwise leave every run compiling without anyone noticing.
* Its ``assemble`` is numba's ``rows2d.assemble`` bit for bit (oracle: the just-in-time kernel
  on the same arrays): on every Newton iteration of a plain run and of a run with seabed,
  waves and a surface buoy.
* A source edited after the build makes the extension unused (fingerprint), and
  :data:`kanat.aot.SOURCES` lists every module the compiled kernels read.
* A 2-D run in a fresh process loads no numba, and writes the file a ``KANAT_AOT=0`` run writes.
"""
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

from kanat import aot, api
from kanat.continuum import kernels2d, rows2d

from helpers import EXAMPLES


def test_the_install_built_the_extension_and_it_is_current():
    compiled = aot.load()
    assert compiled is not None, "kanat._kernels is missing or stale: pip install -e . (or python -m kanat.aot_build)"
    assert compiled.fingerprint() == aot.fingerprint()


@pytest.mark.parametrize("example, changes", [
    ("speed_step_2d.yaml", {"simulation.duration": 60}),
    ("surface_mooring_waves.yaml", {"simulation.duration": 8}),
])
def test_compiled_assemble_is_numbas_bit_for_bit(example, changes, monkeypatch):
    compiled = kernels2d.assemble
    assert compiled is not rows2d.assemble                       # the install's kernel, not numba's
    calls = []

    def both(x, y, d, env, P, b0, b1, res, band, extras):
        compiled(x, y, d, env, P, b0, b1, res, band, extras)
        res2, band2 = np.full_like(res, np.nan), np.full_like(band, np.nan)
        rows2d.assemble(x, y, d, env, P, b0, b1, res2, band2, extras)
        assert np.array_equal(res, res2) and np.array_equal(band, band2)
        calls.append(extras is None)

    monkeypatch.setattr(kernels2d, "assemble", both)
    case = api.load_case(EXAMPLES / example).replace(changes)
    assert api.run(case).summary.status == "ok"
    assert len(calls) > 50 and len(set(calls)) == 1          # one version throughout: plain, or full


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
    script = ("import sys; import kanat.aot_build, kanat.continuum.rows2d\n"
              "print('\\n'.join(m.__file__ for n, m in sys.modules.items() if n.startswith('kanat')))")
    files = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout.split()
    root = os.path.dirname(aot.__file__)
    read = {os.path.relpath(f, root) for f in files} - {"__init__.py", "continuum/__init__.py", "physics/__init__.py",
                                                         "version.py", "aot.py"}
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
