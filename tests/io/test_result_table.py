"""The statics file written without xarray (kanat.io.result_table) is the file of the xarray dataset.

``kanat statics`` writes its :class:`~kanat.io.result_table.ResultTable` directly; the Python API
returns the same table as an ``xarray.Dataset``. Both files are compared in HDF5 terms: the
dimensions (names, sizes, order), every variable (order, dimensions, dtype, storage, values) and
every attribute (order, type, value), the global ones included.
"""
import warnings

import h5netcdf
import numpy as np
import pytest
import xarray as xr

from helpers import EXAMPLES
from kanat import api
from kanat.io.result_table import ResultTable
from kanat.io.results import failed_dataset, write_result
from kanat.io.statics_table import failed_table

CASES = ["towed_body.yaml", "subsurface_mooring.yaml", "mooring_3leg.yaml", "sphere_two_cables.yaml",
         "sphere_two_cables_dimensional.yaml", "moordyn/clump_and_float.dat"]
"""A tow (a body, no anchor), a riser with inline floats, a network with stiffness, the Naumov & Agievich
problem without and with its scales, a MoorDyn network with points and no body."""


def _attrs(attrs) -> list:
    return [(key, type(value), np.asarray(value).tolist()) for key, value in attrs.items()]


def _contents(path) -> dict:
    with h5netcdf.File(path, "r") as f:
        return {
            "dimensions": [(name, dim.size, dim.isunlimited()) for name, dim in f.dimensions.items()],
            "variables": [(name, var.dimensions, var.dtype, var._h5ds.dtype, var.chunks, var.compression,
                           var._h5ds.fillvalue, np.asarray(var[...]).tolist(), _attrs(var.attrs))
                          for name, var in f.variables.items()],
            "attrs": _attrs(f.attrs),
        }


def _same_file(direct, through_xarray) -> None:
    a, b = _contents(direct), _contents(through_xarray)
    assert a["dimensions"] == b["dimensions"]
    assert [v[0] for v in a["variables"]] == [v[0] for v in b["variables"]]
    for mine, theirs in zip(a["variables"], b["variables"]):
        assert mine == theirs, mine[0]
    assert a["attrs"] == b["attrs"]


@pytest.mark.parametrize("name", CASES)
def test_the_statics_file_is_the_file_of_its_dataset(name, tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = api.load_case(EXAMPLES / name, solver="statics")
    outcome = api.run(case, output=tmp_path / "direct.nc", model="statics")      # as kanat statics writes it
    assert isinstance(outcome.held, ResultTable)
    dataset = outcome.dataset
    assert isinstance(dataset, xr.Dataset)
    _same_file(tmp_path / "direct.nc", write_result(dataset, tmp_path / "dataset.nc"))
    with xr.open_dataset(tmp_path / "direct.nc", engine="h5netcdf") as read:
        assert read.load().identical(dataset)


def test_a_failed_statics_file_is_the_file_of_its_dataset(tmp_path):
    case = api.load_case(EXAMPLES / "towed_body.yaml")
    failed_table(case, "shooting lost the solution", wall_time_s=0.25).write(tmp_path / "direct.nc")
    write_result(failed_dataset(case, "shooting lost the solution", wall_time_s=0.25), tmp_path / "dataset.nc")
    _same_file(tmp_path / "direct.nc", tmp_path / "dataset.nc")


def test_a_table_refuses_a_dimension_of_two_sizes():
    table = ResultTable({"a": (("node",), np.zeros(3), {}), "b": (("node",), np.zeros(4), {})})
    with pytest.raises(ValueError, match="dimension 'node' has sizes 3 and 4"):
        table.sizes
