"""numba's disk cache never serves a kernel whose callees changed (docs/kernels.md, "numba's disk cache").

numba's cache answers a kernel from its index when the kernel's own file is unchanged; the machine
code it holds includes the kernels it calls, as they were when it was cached (numba issue #6845).
kanat keys the cache folder by the digest of every kernel source (:func:`kanat.jit.cache_directory`),
and the install-time build caches through the same folder (:mod:`kanat.aot_build`).

Oracle: the callee's formula as edited, evaluated by hand. Each check runs fresh processes on a
copy of the package (the copy is edited, never this tree) with one ``NUMBA_CACHE_DIR`` reused
throughout, as a user's reinstall or a rebuilt checkout reuses it.
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import kanat
from kanat import aot

CALLEE = "physics/contact.py"
FORMULA = "    height = -bed.depth + bed.tan_slope * x\n"
EDITED = "    height = -bed.depth + bed.tan_slope * x + 0.25\n"   # the seabed raised 0.25 m

CALLER = '''
from kanat.jit import kernel
from kanat.physics.contact import Bed, penetration_at


@kernel
def depth(x, z, bed):
    return penetration_at(x, 0.0, z, bed)[0]


print(repr(depth(2.0, -30.0, Bed(depth=40.0, tan_slope=0.1, cos_slope=0.8, sin_slope=0.6))))
'''
"""A kernel in a file that never changes, calling a kanat kernel of another file (the seabed's
penetration, kanat.physics.contact): (height - z) cos(slope), height = -depth + slope x."""


def penetration(offset: float) -> float:
    """The oracle: the penetration ``CALLER`` prints, with the seabed height raised by ``offset``."""
    height = -40.0 + 0.1 * 2.0 + offset
    return (height + 30.0) * 0.8


@pytest.fixture
def package(tmp_path):
    """A copy of the kanat package beside the caller's script, and a run of the script in a fresh
    process with one numba cache folder throughout (the kernels compiled by numba: ``KANAT_AOT=0``)."""
    source = Path(kanat.__file__).parent
    shutil.copytree(source, tmp_path / "src" / "kanat",
                    ignore=shutil.ignore_patterns("__pycache__", "*.so", "*.pyd"))
    (tmp_path / "caller.py").write_text(CALLER)
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "src"), "NUMBA_CACHE_DIR": str(tmp_path / "numba"),
           "KANAT_AOT": "0"}
    env.pop("KANAT_JIT_CACHE", None)

    def run() -> float:
        done = subprocess.run([sys.executable, str(tmp_path / "caller.py")], env=env, capture_output=True,
                              text=True, timeout=300, cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        return float(done.stdout.strip().splitlines()[-1])

    return SimpleNamespace(root=tmp_path, callee=tmp_path / "src" / "kanat" / CALLEE, run=run, env=env)


@pytest.mark.slow
def test_a_changed_callee_in_another_file_is_compiled_again(package):
    text = package.callee.read_text()
    assert FORMULA in text, f"{CALLEE} no longer holds the formula this test edits"
    first = package.run()
    assert first == pytest.approx(penetration(0.0), rel=1e-12)
    assert package.run() == first                                   # the cache is used again
    package.callee.write_text(text.replace(FORMULA, EDITED))
    assert package.run() == pytest.approx(penetration(0.25), rel=1e-12)  # not the cached first value
    folders = sorted(path.name for path in (package.root / "numba").iterdir())
    assert len(folders) == 2 and all(name.startswith("kanat-") for name in folders), folders


@pytest.mark.slow
@pytest.mark.parametrize("build", [True, False], ids=["build", "run"])
def test_the_build_and_a_run_cache_only_in_their_sources_folder(build, tmp_path):
    """In the build's process (:func:`kanat.aot_build.compiler` called first) as in a run's, numba's
    disk cache is written in the folder of the current kernel sources only, ``kanat-<fingerprint>``
    (:func:`kanat.jit.cache_directory`), never beside the sources or in another version's folder."""
    prologue = "import kanat.aot_build\nkanat.aot_build.compiler('_lumped_explicit')\n" if build else ""
    (tmp_path / "caller.py").write_text(prologue + CALLER)
    cache = tmp_path / "numba"
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache), "KANAT_AOT": "0"}
    env.pop("KANAT_JIT_CACHE", None)
    done = subprocess.run([sys.executable, str(tmp_path / "caller.py")], env=env, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert float(done.stdout.split()[-1]) == pytest.approx(penetration(0.0), rel=1e-12)
    written = sorted({path.relative_to(cache).parts[0] for path in cache.rglob("*.nb*")})
    assert written == [f"kanat-{aot.fingerprint():015x}"]


BUILD = '''
import sys
import kanat.aot_build
from kanat import aot, jit
from kanat.physics.contact import Bed

kanat.aot_build.compiler("_lumped_explicit")          # the build's process, as setup.py makes it
from numba.pycc import CC
import caller

cc = CC("built")
cc.output_dir = sys.argv[1]
cc.verbose = False
signature = kanat.aot_build.numba_type(aot.FLOAT)(*map(kanat.aot_build.numba_type, (aot.FLOAT, aot.FLOAT, Bed)))
cc.export("depth", signature)(kanat.aot_build._calling(jit.dispatcher_of(caller.depth), 3))
cc.compile()
sys.path.insert(0, sys.argv[1])
import built
print(repr(built.depth(2.0, -30.0, Bed(depth=40.0, tan_slope=0.1, cos_slope=0.8, sin_slope=0.6))))
'''
"""An install-time module built the way :mod:`kanat.aot_build` builds one (numba's ``pycc``, the
entry calling numba's kernel), of the kernel of ``CALLER``."""


@pytest.mark.slow
def test_a_module_built_with_a_reused_cache_holds_the_changed_callee(package):
    """The incident: numba's kernels run (cache filled), a callee edited, the module built again
    with the same ``NUMBA_CACHE_DIR``: it holds the edited callee."""
    assert package.run() == pytest.approx(penetration(0.0), rel=1e-12)
    package.callee.write_text(package.callee.read_text().replace(FORMULA, EDITED))
    (package.root / "build.py").write_text(BUILD)
    output = package.root / "out"
    output.mkdir()
    done = subprocess.run([sys.executable, str(package.root / "build.py"), str(output)], env=package.env,
                          capture_output=True, text=True, timeout=600, cwd=package.root)
    assert done.returncode == 0, done.stderr
    assert float(done.stdout.split()[-1]) == pytest.approx(penetration(0.25), rel=1e-12)
