"""The kernel lookup's three modes (:data:`kanat.aot.KERNEL_MODES`) and the named element record.

* A small lumped run (a towed sled on a cable with bending stiffness, ``rk4`` and the implicit
  generalized-alpha) gives the same tensions and positions through the kernels compiled at install,
  numba's kernels and the plain twins (oracle: each mode against numba's; the twins sum in another
  order, so to round-off: 1e-9 relative after the run's steps).
* The element record is what numba and the install-time compiler take: its numba type is a named
  tuple of the fields' types, and the argument check refuses a plain tuple of the same arrays.
* ``KANAT_KERNELS`` chooses the mode for a process, and an unknown mode is a clear error.
"""
import os
import subprocess
import sys

import numpy as np
import pytest

from kanat import aot, api, warmup
from kanat.lumped import entries

TINY = warmup.CASES["lumped-rk4"]
CASE = {**TINY, "line_types": {"cable": {**warmup._CABLE, "bending_stiffness": 200.0}},
        "vessel": {**TINY["vessel"], "motion": [{"dof": "heave", "amplitude": 1.0, "period": 2.0}]},
        "cables": [{**TINY["cables"][0], "segments": 5}],
        "simulation": {"scheme": "rk4", "duration": 0.5, "output_dt": 0.05}}
RELATIVE = 1e-9             # the twins' other summation order, over the run's steps


def run(scheme: str):
    case = api.load_case({**CASE, "simulation": {**CASE["simulation"], "scheme": scheme}})
    outcome = api.run(case)
    assert outcome.summary.status == "ok"
    return outcome.dataset


@pytest.mark.slow
@pytest.mark.parametrize("scheme", ["rk4", "generalized-alpha-lumped"])
def test_a_small_run_is_the_same_through_every_kernel_mode(scheme):
    with aot.LOOKUP.numba_only():
        want = run(scheme)
    with aot.LOOKUP.python_only():
        twins = run(scheme)
    results = {"python": twins}
    if aot.current():                                   # an install with its compiled modules
        results["aot"] = run(scheme)
    for mode, got in results.items():
        for name in ("tension", "position"):
            assert name in want and want[name].size > 10
            np.testing.assert_allclose(got[name].values, want[name].values, rtol=RELATIVE,
                                       atol=RELATIVE * float(np.abs(want[name].values).max()),
                                       err_msg=f"{mode}: {name}")
    if "aot" in results:                                # the install's kernels are numba's bit for bit
        np.testing.assert_array_equal(results["aot"]["tension"].values, want["tension"].values)


def test_python_mode_runs_the_numpy_twin_of_an_entry_and_restores_the_lookup():
    before = aot.LOOKUP.current_mode()
    with aot.LOOKUP.python_only():
        assert aot.LOOKUP.interpreted
        found = aot.LOOKUP.kernel("element_forces")
        assert found.__module__ == "kanat.lumped.oracle_numpy" and found.__name__ == "element_forces_numpy"
        assert aot.LOOKUP.kernel("tensions").__module__ == "kanat.lumped.kernels"   # its own Python code
    assert aot.LOOKUP.current_mode() == before and not aot.LOOKUP.interpreted


def test_the_element_record_is_a_named_tuple_to_numba_and_checked_by_class():
    from kanat.aot_build import numba_type
    from numba import types

    typed = numba_type(entries.Elements)
    assert isinstance(typed, types.BaseNamedTuple) and typed.instance_class is entries.Elements
    assert len(typed) == len(entries.Elements._fields) == len(entries.Elements.SPECIFICATION)
    fields = [np.zeros(2, np.int64) if spec == aot.I1 else np.zeros(2) if spec == aot.F1 else np.zeros((1, 2))
              for spec in entries.Elements.SPECIFICATION]
    record = entries.Elements(*fields)
    assert aot.matches(record, entries.Elements)
    assert not aot.matches(tuple(fields), entries.Elements)                  # a plain tuple: numba's kernel
    assert not aot.matches(record._replace(length=np.zeros(2, np.float32)), entries.Elements)


@pytest.mark.parametrize("value, expected", [("python", "python True"), ("numba", "numba False"),
                                             ("aot", "aot False")])
def test_the_environment_chooses_the_mode(value, expected):
    script = "from kanat import aot; print(aot.LOOKUP.current_mode(), aot.LOOKUP.interpreted)"
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True,
                         env={**os.environ, "KANAT_KERNELS": value, "KANAT_AOT": "1"})
    assert out.stdout.strip() == expected


def test_an_unknown_mode_names_the_valid_ones():
    script = "from kanat import aot; aot.LOOKUP.current_mode()"
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         env={**os.environ, "KANAT_KERNELS": "fortran"})
    assert out.returncode != 0 and "KANAT_KERNELS='fortran': expected one of aot, numba, python" in out.stderr


def test_a_run_in_python_mode_imports_no_numba():
    """``KANAT_KERNELS=python`` runs the twins only: numba is not even imported."""
    script = ("import sys; sys.path.insert(0, sys.argv[1]); from test_kernel_modes import run\n"
              "run('rk4'); print('numba' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", script, os.path.dirname(__file__)], capture_output=True, text=True,
                         check=True, env={**os.environ, "KANAT_KERNELS": "python"})
    assert out.stdout.strip().splitlines()[-1] == "False"


@pytest.mark.slow
@pytest.mark.parametrize("family", sorted(warmup.CASES))
def test_every_familys_tiny_case_runs_on_the_plain_twins_as_on_numba(family):
    """Each family's tiny case (:data:`kanat.warmup.CASES`) through the plain twins and numba's kernels."""
    case = api.load_case(warmup.CASES[family])
    with aot.LOOKUP.numba_only():
        want = api.run(case).dataset
    with aot.LOOKUP.python_only():
        outcome = api.run(case)
    assert outcome.summary.status == "ok"
    got = outcome.dataset
    for name in ("tension", "position"):
        scale = float(np.nanmax(np.abs(want[name].values)))
        np.testing.assert_allclose(got[name].values, want[name].values, rtol=RELATIVE, atol=RELATIVE * scale,
                                   err_msg=f"{family}: {name}")
