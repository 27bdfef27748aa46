"""Every private API kanat uses (:mod:`kanat._private_api`), one test per touch point.

A numba, h5netcdf or SciPy release that changes one of them fails its test here, with a message naming
the library and its version (docs/kernels.md says what each touch point is for and what replaces
it). Oracles: the object file on disk, numba's own compile of a one-line function (its signature),
the HDF5 file read back by h5py in another process, a result worked by hand, numba's own
``typeof`` of an instance and SciPy's public ``solve_banded``.
"""
import subprocess
import sys

import h5netcdf
import numba
import numpy as np
import pytest

from kanat import _private_api
from kanat._private_api import PrivateAPIChanged

NUMBA = f"numba {numba.__version__}"


@pytest.mark.filterwarnings("ignore::numba.NumbaPendingDeprecationWarning")
def test_numba_pycc_compiles_object_files_unlinked(tmp_path):
    """``CC._compile_object_files(build_temp)``: what setup.py compiles, one module per process."""
    from numba.pycc import CC

    cc = CC("_private_api_probe")
    cc.output_dir = str(tmp_path)
    cc.verbose = False

    @cc.export("twice", "f8(f8)")
    def twice(x):
        return 2.0 * x

    try:
        objects = _private_api.compile_object_files(cc, str(tmp_path))
    except PrivateAPIChanged as error:
        pytest.fail(str(error))
    expected = _private_api.object_file(cc, str(tmp_path))
    assert objects == [expected], f"{NUMBA}: CC._compile_object_files wrote {objects}, not {expected}"
    with open(expected, "rb") as obj:
        head = obj.read(4)
    assert head == b"\x7fELF" or sys.platform != "linux", f"{NUMBA}: {expected} is no object file"


def test_numba_disk_cache_index_lists_the_cached_signatures(tmp_path, monkeypatch):
    """``Dispatcher._cache._cache_file._load_index()`` and its keys: what ``kanat.jit.is_cached``
    reads to tell whether a run will compile."""
    (tmp_path / "probe_cached.py").write_text(
        "from numba import njit\n\n\n@njit(cache=True)\ndef thrice(x):\n    return 3.0 * x\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    from probe_cached import thrice

    assert _private_api.disk_cached_signatures(thrice) == [], f"{NUMBA}: a cache index before any compile"
    assert thrice(2.0) == 6.0
    cached = _private_api.disk_cached_signatures(thrice)
    assert cached is not None, (f"{NUMBA} changed Dispatcher._cache._cache_file._load_index() or its keys "
                                "(signature, codegen magic tuple, (bytecode sha256, closure sha256))")
    assert [tuple(signature) for signature in cached] == [(numba.float64,)], f"{NUMBA}: index keys {cached}"


def test_h5netcdf_file_flushes_the_hdf5_file_beneath(tmp_path):
    """h5netcdf's ``File._h5file``: flushed, a file still open for writing holds its data on disk."""
    path = tmp_path / "open.nc"
    with h5netcdf.File(path, "w") as f:
        f.dimensions["time"] = None
        var = f.create_variable("x", ("time",), dtype=float)
        f.resize_dimension("time", 3)
        var[:] = [1.0, 2.0, 3.0]
        f.flush()
        try:
            _private_api.flush_hdf5(f)
        except PrivateAPIChanged as error:
            pytest.fail(str(error))
        script = "import h5py, sys; print(h5py.File(sys.argv[1], 'r')['x'][:].tolist())"
        read = subprocess.run([sys.executable, "-c", script, str(path)], capture_output=True, text=True,
                              env={"HDF5_USE_FILE_LOCKING": "FALSE", "PATH": ""})
        assert read.returncode == 0 and read.stdout.strip() == "[1.0, 2.0, 3.0]", (
            f"h5netcdf {h5netcdf.__version__}: the file open for writing was not flushed: {read.stderr[-300:]}")


BANDED = """
import sys
from kanat._private_api import banded_lapack
lapack = banded_lapack()
print(lapack.__name__, 'scipy.linalg' in sys.modules)
import numpy as np
from scipy.linalg import solve_banded
from scipy.linalg.lapack import dgbsv
ab = np.array([[0.0, 1.0, 2.0, 1.0], [5.0, 6.0, 7.0, 8.0], [1.0, 2.0, 1.0, 0.0]])
rhs = np.array([1.0, -2.0, 3.0, 0.5])
work = np.zeros((4, 4), order="F")
work[1:] = ab
_, _, x, info = lapack.dgbsv(1, 1, work, rhs.copy())
print(info, lapack.dgbsv is dgbsv, np.abs(x - solve_banded((1, 1), ab, rhs)).max())
"""


def test_scipy_lapack_loads_without_scipy_linalg():
    """SciPy's ``_flapack`` loaded alone (no ``scipy.linalg`` imported), the same ``dgbsv`` as
    ``scipy.linalg.lapack``'s once SciPy is imported, its band solve ``solve_banded``'s."""
    lines = subprocess.run([sys.executable, "-c", BANDED], capture_output=True, text=True,
                           check=True).stdout.split("\n")
    assert lines[0] == "scipy.linalg._flapack False", (
        f"SciPy's _flapack was not found beside scipy/linalg (kanat._private_api.banded_lapack): {lines[0]}")
    info, same, error = lines[1].split()
    assert (info, same) == ("0", "True")
    assert float(error) < 1e-15


def test_numba_types_an_object_by_its_numba_type_hook():
    """``_numba_type_``: an object that gives a dispatcher's type is called as that kernel from another
    (how kernels call a ``kanat.jit.Deferred`` by its plain name). Oracle: ``2 x + 1`` by hand."""
    @numba.njit
    def twice(x):
        return 2.0 * x

    class StandIn:
        @property
        def _numba_type_(self):
            return _private_api.dispatcher_type(twice)

    stand_in = StandIn()

    @numba.njit
    def caller(x):
        return stand_in(x) + 1.0

    assert numba.typeof(stand_in) == numba.typeof(twice), f"{NUMBA} no longer types an object by _numba_type_"
    assert caller(3.0) == 7.0, f"{NUMBA}: a kernel calling a stand-in by its _numba_type_"


def test_numba_types_a_named_tuple_from_its_items_types():
    """``types.BaseTuple.from_types``: a record's type made from its fields' types, as the install-time
    build declares it, is the type ``numba.typeof`` gives an instance (mixed and uniform fields)."""
    from collections import namedtuple

    from numba import types

    Mixed, Uniform = namedtuple("Mixed", "values count"), namedtuple("Uniform", "first second")
    array = types.Array(types.float64, 1, "C")
    for kind, items, instance in ((Mixed, (array, types.int64), Mixed(np.zeros(2), 3)),
                                  (Uniform, (types.float64, types.float64), Uniform(1.0, 2.0))):
        made = _private_api.named_tuple_type(items, kind)
        assert made == numba.typeof(instance), f"{NUMBA}: {made} is not how numba types a {kind.__name__}"


def test_numba_caches_a_dispatcher_in_the_folder_given(tmp_path):
    """``enable_caching`` under a ``CACHE_DIR`` set for the call: the compiled function's index and
    data land in that folder, and numba's own setting is restored."""
    import numba
    from numba.core import config

    @numba.njit
    def thrice(x):
        return 3.0 * x

    before = config.CACHE_DIR
    _private_api.enable_disk_cache(thrice, str(tmp_path))
    assert config.CACHE_DIR == before
    assert thrice(2.0) == 6.0
    written = sorted(path.suffix for path in tmp_path.rglob("*.nb*"))
    assert ".nbi" in written and ".nbc" in written, (
        f"numba {numba.__version__}: enable_caching wrote {written} in the folder given")


def test_a_missing_private_api_is_named_with_its_library_version():
    with pytest.raises(PrivateAPIChanged, match=f"h5netcdf {h5netcdf.__version__} changed File._h5file"):
        _private_api.flush_hdf5(object())
    with pytest.raises(PrivateAPIChanged, match=f"numba {numba.__version__} changed numba.pycc.CC"):
        _private_api.compile_object_files(object(), "build")
    assert _private_api.disk_cached_signatures(np.sin) is None
    with pytest.raises(PrivateAPIChanged, match=f"numba {numba.__version__} changed Dispatcher._numba_type_"):
        _private_api.dispatcher_type(object())
