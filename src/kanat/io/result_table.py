"""A result as plain arrays, and the one netCDF writer of results held whole in memory.

A steady result (statics) is small and written once: building an ``xarray.Dataset`` only to
write it would import xarray and pandas (and dask where it is installed), 0.4 s of CPU
against a solve of tens of milliseconds. A :class:`ResultTable` holds what its file holds —
variables with their dimensions, values and attributes, which of them are coordinates, the
global attributes — and writes it with h5netcdf (:func:`write_netcdf`), the writer
:func:`kanat.io.results.write_result` uses for a dataset too, so both give the same file.
:meth:`ResultTable.to_dataset` gives the ``xarray.Dataset`` the file reads back as, for
the Python API.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable

import numpy as np

from kanat.io.schema import netcdf_attr
from kanat.io.space import require_space


def _string_dtype():
    import h5py

    return h5py.string_dtype()


def write_netcdf(path, sizes: dict, variables: Iterable[tuple[str, tuple, np.ndarray, dict]], coords,
                 attrs: dict) -> Path:
    """Write a result to netCDF with h5netcdf, atomically (written beside ``path``, then renamed).

    Text variables are variable-length strings; every other variable keeps its dtype. A
    variable that is not a coordinate names, in its CF ``coordinates`` attribute, the
    non-dimension coordinates whose dimensions are among its own, so that xarray reads
    them back as coordinates.

    Parameters
    ----------
    path : path-like
    sizes : dict of str to int
        Every dimension and its size, in file order.
    variables : iterable of (name, dims, values, attrs)
        In file order.
    coords : collection of str
        Names of the variables that are coordinates.
    attrs : dict
        Global attributes.

    Returns
    -------
    pathlib.Path
    """
    import h5netcdf

    from kanat.io.outputs import atomic_path

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    variables = [(name, tuple(dims), np.asarray(values), var_attrs) for name, dims, values, var_attrs in variables]
    dims_of = {name: dims for name, dims, _, _ in variables}
    extra = [name for name in coords if name not in sizes]
    text_bytes = sum(len(repr(v)) for _, _, values, _ in variables if values.dtype.kind in "OUS"
                     for v in values.ravel())
    require_space(path, sum(v.nbytes for _, _, v, _ in variables) + text_bytes + len(repr(attrs)),
                  f"the result {path.name}")
    with atomic_path(path) as tmp, h5netcdf.File(tmp, "w") as f:
        f.dimensions = dict(sizes)
        for name, dims, values, var_attrs in variables:
            text = values.dtype.kind in "OUS"
            created = f.create_variable(name, dims, dtype=_string_dtype() if text else values.dtype)
            if values.size:
                created[...] = values.astype(object) if text else values
            out = {k: netcdf_attr(v) for k, v in var_attrs.items()}
            near = [c for c in extra if c != name and dims_of[c] and set(dims_of[c]) <= set(dims)]
            if near and name not in coords:
                out["coordinates"] = " ".join(near)
            created.attrs.update(out)
        f.attrs.update({k: netcdf_attr(v) for k, v in attrs.items()})
    return path


@dataclass(frozen=True)
class ResultTable:
    """A result's variables as NumPy arrays, in the order of its file (module docstring).

    Attributes
    ----------
    variables : dict of str to (tuple of str, ndarray, dict)
        ``name -> (dims, values, attrs)``; text as object arrays of ``str``.
    coords : tuple of str
        The variables that are coordinates (dimension coordinates and ``s``, ``cable``, ...).
    attrs : dict
        Global attributes (provenance, ``status``).
    """

    variables: dict = field(default_factory=dict)
    coords: tuple = ()
    attrs: dict = field(default_factory=dict)

    @property
    def sizes(self) -> dict[str, int]:
        """Every dimension and its size, in order of first use."""
        out: dict[str, int] = {}
        for dims, values, _ in self.variables.values():
            for dim, size in zip(dims, np.shape(values)):
                if out.setdefault(dim, size) != size:
                    raise ValueError(f"dimension '{dim}' has sizes {out[dim]} and {size}")
        return out

    def write(self, path) -> Path:
        """Write the result file (:func:`write_netcdf`)."""
        return write_netcdf(path, self.sizes, ((name, *entry) for name, entry in self.variables.items()),
                            self.coords, self.attrs)

    def to_dataset(self):
        """The ``xarray.Dataset`` of this result, as its file reads back."""
        import xarray as xr

        ds = xr.Dataset(dict(self.variables), attrs=dict(self.attrs))      # in the file's order
        return ds.set_coords([name for name in self.coords if name not in ds.dims])
