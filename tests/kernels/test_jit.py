"""kanat.jit and kanat.warmup: whether a run will compile, and that a warmup leaves a run
nothing to compile. Oracles: numba's own dispatcher state and its compile events.

These are the runs of an install without the kernels compiled at install (no C compiler, or
``KANAT_AOT=0``): the tests that run cases use numba's kernels throughout (:func:`numba_kernels`).
"""
import numpy as np
import pytest
from numba import njit
from numba.core import event

from kanat import aot, jit, warmup
from kanat.api import SCHEMES, load_case, simulate
from kanat.jit import Family
from kanat.model import Case


class Compiles(event.Listener):
    """Counts numba compilations (cache loads are not compilations)."""

    def __init__(self):
        self.names = []

    def on_start(self, ev):
        self.names.append(ev.data["dispatcher"].py_func.__name__)

    def on_end(self, ev):
        pass


@pytest.fixture
def numba_kernels(monkeypatch):
    """This test's runs use numba's kernels, as an install without compiled ones does; what the
    process found before is restored after it."""
    monkeypatch.setenv("KANAT_AOT", "0")
    with aot.LOOKUP.numba_only():
        yield


def run_quietly(case):
    ds = simulate(case if isinstance(case, Case) else load_case(case))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    return ds


def test_pending_follows_the_dispatcher():
    @njit                                       # not cached on disk: only this process can know it
    def twice(x):
        return 2.0 * x

    family = Family("test", ((twice, None),), 1.5)
    assert not jit.is_cached(twice) and jit.pending(family) == 1.5
    assert twice(2.0) == 4.0
    assert jit.is_cached(twice) and jit.pending(family) is None
    assert not jit.is_cached(twice, accept=jit.planar)           # its one version is not a planar one


@pytest.mark.parametrize("name", sorted(SCHEMES))
def test_every_registered_scheme_has_a_family(name):
    for dimensions in (2, 3):
        family = warmup.family_name(name, dimensions)
        assert family in warmup.FAMILIES and family in warmup.CASES


def versions() -> dict:
    """Every kernel's versions in this process (compiled or loaded from the disk cache)."""
    return jit.compiled_versions()


def _after_warmup_compiles_nothing(name, case):
    """A run after the family's warmup neither compiles nor loads a kernel version the warmup
    did not (a version loaded from an older disk cache would hide a missing one)."""
    run_quietly(warmup.CASES[name])                  # what warmup() runs when the family is not cached
    assert warmup.pending(name) is None
    assert warmup.warmup(run_quietly, [name]) == {name: 0.0}          # and, cached, skips
    warm = versions()
    listener = Compiles()
    with event.install_listener("numba:compile", listener):
        run_quietly(case)
    assert listener.names == []
    assert versions() == warm


def test_a_planar_run_after_warmup_compiles_nothing(numba_kernels):
    case = load_case("examples/speed_step_2d.yaml").replace({"simulation.duration": 5.0, "cables[0].segments": 20})
    assert warmup.family_name(case.simulation.scheme, 2) == "continuum-2d"
    _after_warmup_compiles_nothing("continuum-2d", case)


@pytest.mark.slow
@pytest.mark.parametrize("name, example, changes", [
    ("continuum-3d", "turn_360_3d.yaml", {"simulation.duration": 10.0}),
    ("continuum-3d-bending", "turn_360_3d.yaml",
     {"simulation.duration": 10.0, "line_types.towcable.bending_stiffness": 50.0}),
    ("lumped-rk4", "trawl_head_5.6s_1to4.yaml", {"simulation.duration": 1.0}),
    ("lumped-implicit", "trawl_head_5.6s_1to4.yaml",
     {"simulation.duration": 1.0, "simulation.scheme": "generalized-alpha-lumped"}),
    ("wave-factorized-2d", "factorization_planar80.yaml", {"simulation.duration": 0.1, "simulation.output_dt": 0.05}),
    ("factorized-2d", "factorization_accel.yaml", {"simulation.duration": 0.02}),
])
def test_a_run_after_warmup_compiles_nothing(name, example, changes, numba_kernels):
    _after_warmup_compiles_nothing(name, load_case(f"examples/{example}").replace(changes))


def test_the_warmup_cases_are_tiny_and_valid():
    for name, case in warmup.CASES.items():
        parsed = load_case(case)
        bending = any(line.bending_stiffness > 0 for line in parsed.line_types.values())
        assert warmup.family_name(parsed.simulation.scheme, parsed.simulation.dimensions or 2, bending) == name
        assert sum(c.segments for c in parsed.cables) <= 5


@pytest.mark.slow
def test_a_cold_run_says_it_compiles_and_kanat_warmup_finds_it_done(tmp_path):
    """In fresh processes with an empty kernel cache and numba's kernels (``KANAT_AOT=0``, as
    without a C compiler at install): ``kanat run`` says it compiles (before it does), ``kanat
    warmup`` then finds the family cached (numba's cache index, read by :func:`kanat.jit.pending`),
    and a second run compiles nothing and says nothing of it."""
    import os
    import subprocess
    import sys

    import yaml

    case = tmp_path / "tiny.yaml"
    case.write_text(yaml.safe_dump(warmup.CASES["lumped-rk4"]))
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "cache"), "KANAT_AOT": "0"}

    def kanat(*args):
        done = subprocess.run([sys.executable, "-m", "kanat.cli", *args], env=env, capture_output=True,
                              text=True, timeout=300)
        return done.returncode, done.stdout, done.stderr

    code, _, err = kanat("run", str(case), "-o", str(tmp_path / "a.nc"))
    assert code == 0 and "compiling the lumped-rk4 kernels once" in err, err
    code, out, _ = kanat("warmup", "lumped-rk4")
    assert code == 0 and "lumped-rk4: already compiled" in out, out
    code, out, err = kanat("run", str(case), "-o", str(tmp_path / "b.nc"))
    assert code == 0 and "compiling" not in err and "compiling 0.00 s" in out, out + err
    code, _, err = kanat("warmup", "lumped-rk5")
    assert code == 1 and "valid: continuum-2d" in err


def test_a_run_rewrites_no_module_namespace(numba_kernels):
    """A kernel's name is the same object before and after numba compiles it: the run's modules'
    namespaces are as they were (no numba dispatcher put in place of a kernel)."""
    import sys

    from numba.core.dispatcher import Dispatcher

    from kanat.continuum import kernels2d, rows2d

    def namespaces():
        return {name: dict(vars(module)) for name, module in list(sys.modules.items()) if name.startswith("kanat")}

    run_quietly(warmup.CASES["continuum-2d"])                 # every module the run needs, imported
    before = namespaces()
    run_quietly(warmup.CASES["continuum-2d"])
    after = namespaces()
    assert isinstance(kernels2d.assemble, aot.EntryPoint) and isinstance(rows2d.assemble, jit.Deferred)
    assert rows2d.assemble.dispatcher is not None and rows2d.assemble.dispatcher.signatures
    for name, namespace in before.items():
        assert all(after[name][key] is value for key, value in namespace.items()), name
    assert not [f"{name}.{key}" for name, namespace in after.items() for key, value in namespace.items()
                if isinstance(value, Dispatcher)]
