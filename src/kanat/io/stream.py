"""Results written as a run goes, and checkpoints to resume a killed run.

A dynamic run streams its result into ``OUT.nc.part``: the time-independent variables at
once, then one slice per output along the unlimited ``time`` dimension, written in
blocks and flushed to disk (HDF5 included) at least every ``FLUSH_WALL_S`` seconds and
before every checkpoint. ``status`` says ``running`` until the run ends; then the file
gets its final status and attributes and is renamed to ``OUT.nc``, so an earlier result
at ``OUT.nc`` is replaced only by a complete one. A killed run leaves ``OUT.nc.part``:
readable, with everything up to its last flushed output, and continued by ``--resume``.

A :class:`Checkpoint` is the solver's full state at an output time, written atomically
(write, then rename) beside the result (``OUT.nc.ckpt.npz``). Resuming truncates the
result to the checkpoint's output count and continues from its state, so a resumed run
gives the same answer as an uninterrupted one, bit for bit. The checkpoint records the
case's SHA-256 and the scheme (name and parameters) and refuses a different one.

The file is written with h5netcdf directly (no round trip through an ``xarray.Dataset``);
names, units and coordinates come from :mod:`kanat.io.schema`, as for the in-memory
recorder, so both read back as the same dataset.
"""
from __future__ import annotations

import contextlib
import json
import math
import os
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kanat._private_api import flush_hdf5
from kanat.errors import KanatError, OutputWriteError
from kanat.io.schema import TIME_COORD, Layout, attributes, netcdf_attr, time_dims
from kanat.io.space import close_quietly, require_space

CHUNK_OUTPUTS = 64
"""Outputs per HDF5 chunk along ``time`` (appends stay cheap; reads by time stay quick)."""
def part_path(path) -> Path:
    """Where a run streams its result until it ends: ``OUT.nc.part``."""
    path = Path(path)
    return path.with_name(path.name + ".part")


def _string_dtype():
    import h5py

    return h5py.string_dtype()


class ResultStream:
    """Run-loop observer: the result file, streamed (module docstring).

    Parameters
    ----------
    path : path-like
        The final result file ``OUT.nc``.
    """

    FLUSH_WALL_S = 1.0

    def __init__(self, path):
        self.path = Path(path)
        self.part = part_path(self.path)
        self._file = None
        self._buffer: list[tuple[float, dict]] = []
        self._oldest = 0.0
        self._names: tuple = ()
        self._bytes_per_output = 0.0
        self._written = 0              # outputs in the file (h5netcdf's size of an unlimited dimension scans
                                       # every variable: 20 ms a flush on a three-line mooring)

    # --- observer protocol ---------------------------------------------------------

    def start(self, layout: Layout, resume_at: int | None = None) -> None:
        """Create the file, or reopen a killed run's file truncated to ``resume_at`` outputs."""
        import h5netcdf

        self._names = layout.time_variables
        sizes = layout.sizes()
        self._bytes_per_output = 8.0 * (1 + sum(math.prod(sizes[d] for d in time_dims(name)[1:])
                                                for name in self._names))
        if resume_at is None:
            self._create(layout)
        elif not self.part.exists():
            if not self.path.exists():
                raise KanatError(f"no result {self.path} (or {self.part}) to resume; run without --resume")
            os.replace(self.path, self.part)
        with self._writing("the start of the run"):
            self._file = h5netcdf.File(self.part, "a")
            if resume_at is not None:
                self._file.resize_dimension("time", resume_at)
            self._written = resume_at or 0
            self._file.attrs["status"] = "running"
            self._sync()

    def record(self, point) -> None:
        """Buffer one output (a :class:`kanat.dynamics.Point`); write the buffer when it is older
        than ``FLUSH_WALL_S``."""
        if not self._buffer:
            self._oldest = time.perf_counter()
        self._buffer.append((point.time, point.values))
        if time.perf_counter() - self._oldest > self.FLUSH_WALL_S:
            self.flush()

    def flush(self) -> None:
        """Write the buffered slices as one block and push them to disk.

        Raises
        ------
        OutputWriteError
            When the disk cannot take the block (checked before writing: the new chunks
            of every variable and a margin), or a write fails.
        """
        if not self._buffer:
            return
        f = self._file
        n, m = self._written, len(self._buffer)
        require_space(self.part, (m + 2 * CHUNK_OUTPUTS) * self._bytes_per_output, f"{m} more outputs")
        with self._writing(f"{m} more outputs"):
            f.resize_dimension("time", n + m)
            f.variables["time"][n:n + m] = [t for t, _ in self._buffer]
            for name in self._names:
                f.variables[name][n:n + m, ...] = np.stack([values[name] for _, values in self._buffer])
            self._sync()
        self._written = n + m
        self._buffer.clear()

    def kept(self) -> str:
        """What the result file holds, for the message of a run stopped by a write error."""
        try:
            import h5netcdf

            with h5netcdf.File(self.part, "r") as f:
                times = f.variables["time"][...]
        except (OSError, KeyError, ValueError):
            return f"{self.part} may be damaged"
        if len(times) == 0:
            return f"{self.part} holds no output yet"
        return f"{self.part} keeps the outputs up to t = {float(times[-1]):.6g} s"

    @contextlib.contextmanager
    def _writing(self, what: str):
        """Turn an OS error while writing ``what`` into an :class:`OutputWriteError`."""
        try:
            yield
        except OutputWriteError:
            raise
        except OSError as error:
            raise OutputWriteError(f"writing {what} to {self.part} failed ({error})") from error

    def finish(self, status: str, final: dict, attrs: dict) -> None:
        """Write what is buffered, the end-of-run variables and attributes; rename to ``OUT.nc``.

        A run that ends with ``ok`` needs no resuming, so its checkpoint is removed; an
        interrupted or failed run keeps it for ``--resume``.
        """
        self.flush()
        f = self._file
        needed = sum(np.asarray(values).nbytes for _, values in final.values())
        require_space(self.part, needed + 64 * 1024, "the end of the run")
        with self._writing("the end of the run"):
            for name, (dims, values) in final.items():
                self._final_variable(name, dims, np.asarray(values))
            for key, value in {**attrs, "status": status}.items():
                f.attrs[key] = netcdf_attr(value)
            f.close()
        self._file = None
        os.replace(self.part, self.path)
        if status == "ok":
            Checkpoint.path_for(self.path).unlink(missing_ok=True)

    def abandon(self) -> None:
        """Close the file as a killed run leaves it: status ``running``, unflushed outputs lost
        (a close that fails, on a full disk, leaves the file as its last flush did)."""
        if self._file is not None:
            self._buffer.clear()
            close_quietly(self._file)
            self._file = None

    # --- the file --------------------------------------------------------------------

    def _create(self, layout: Layout) -> None:
        import h5netcdf

        self.path.parent.mkdir(parents=True, exist_ok=True)
        sizes = layout.sizes()
        static = sum(np.asarray(values).nbytes for _, values in layout.static.values())
        require_space(self.part, static + 2 * CHUNK_OUTPUTS * self._bytes_per_output, "a new result file")
        try:
            self._write_layout(layout, sizes)
        except OSError as error:
            self.part.unlink(missing_ok=True)
            raise OutputWriteError(f"creating {self.part} failed ({error})") from error

    def _write_layout(self, layout: Layout, sizes: dict) -> None:
        import h5netcdf

        with h5netcdf.File(self.part, "w") as f:
            f.dimensions = {**sizes, "time": None}
            for name, values in layout.labels.items():
                var = f.create_variable(name, (name,), dtype=_string_dtype())
                var[:] = np.array(list(values), dtype=object)
            for name, (dims, values) in layout.static.items():
                values = np.asarray(values)
                text = values.dtype.kind in "OUS"
                var = f.create_variable(name, dims, dtype=_string_dtype() if text else values.dtype)
                var[...] = values.astype(object) if text else values
                var.attrs.update(attributes(name, dims))
            t = f.create_variable("time", ("time",), dtype="f8", chunks=(CHUNK_OUTPUTS,))
            t.attrs.update(TIME_COORD.attrs())
            for name in layout.time_variables:
                dims = time_dims(name)
                shape = tuple(max(sizes[d], 1) for d in dims[1:])
                var = f.create_variable(name, dims, dtype="f8", chunks=(CHUNK_OUTPUTS,) + shape,
                                        fillvalue=np.nan)
                var.attrs.update(attributes(name, dims))
            f.attrs.update({k: netcdf_attr(v) for k, v in layout.attrs.items()})

    def _final_variable(self, name: str, dims: tuple, values: np.ndarray) -> None:
        f = self._file
        for dim, size in zip(dims, values.shape):
            if dim not in f.dimensions:
                f.dimensions[dim] = None                   # unlimited: a resumed run rewrites it
            if f.dimensions[dim].isunlimited():
                f.resize_dimension(dim, size)
        var = f.variables[name] if name in f.variables else f.create_variable(name, dims, dtype=values.dtype)
        if values.size:
            var[...] = values
        var.attrs.update(attributes(name, dims))

    def _sync(self) -> None:
        """Push everything written so far to disk, HDF5 metadata included.

        ``h5netcdf.File.flush`` writes only the netCDF attributes; the HDF5 file beneath
        must be flushed too, or a killed run leaves datasets of length 0 on disk.
        """
        self._file.flush()
        flush_hdf5(self._file)


@dataclass(frozen=True)
class Checkpoint:
    """A solver's state at an output time, enough to continue the run exactly.

    Attributes
    ----------
    time : float
        Simulated time [s].
    outputs : int
        Output slices written up to and including this time.
    case_sha256 : str
    scheme : str
        The scheme's name and parameters (a resume must use the same).
    state : dict of str to ndarray
        The solver's arrays (positions, velocities, multistep history, ...).
    info : dict
        Small JSON-able extras (step counters, statistics).
    """

    time: float
    outputs: int
    case_sha256: str
    scheme: str
    state: dict
    info: dict

    @staticmethod
    def path_for(result_path) -> Path:
        return Path(str(result_path) + ".ckpt.npz")

    def save(self, result_path) -> Path:
        """Write atomically beside the result file (write, sync, then rename): a checkpoint that
        cannot be written whole leaves the previous one as it was.

        Raises
        ------
        OutputWriteError
            When the disk cannot take it (checked before writing) or a write fails.
        """
        path = self.path_for(result_path)
        tmp = path.with_name(path.name + ".part.npz")
        meta = json.dumps({"time": self.time, "outputs": self.outputs, "case_sha256": self.case_sha256,
                           "scheme": self.scheme, "info": self.info})
        needed = len(meta) + sum(np.asarray(v).nbytes + 1024 for v in self.state.values())
        require_space(path, 2 * needed, "a checkpoint")
        try:
            with open(tmp, "wb") as stream:
                np.savez(stream, __meta__=np.array(meta), **self.state)
                stream.flush()
                os.fsync(stream.fileno())
            os.replace(tmp, path)
        except OSError as error:
            tmp.unlink(missing_ok=True)
            raise OutputWriteError(f"writing the checkpoint {path} failed ({error})") from error
        return path

    @classmethod
    def load(cls, result_path, case_sha256: str, scheme: str, accepted: tuple[str, ...] = ()) -> Checkpoint:
        """Read the checkpoint of ``result_path``; refuse one written for another case (a hash other
        than ``case_sha256`` and the ``accepted`` ones, :func:`kanat.io.provenance.case_hashes`) or
        another scheme."""
        path = cls.path_for(result_path)
        if not path.exists():
            raise KanatError(f"no checkpoint {path} to resume from; run without --resume to start afresh")
        with np.load(path) as data:
            meta = json.loads(str(data["__meta__"]))
            state = {k: data[k] for k in data.files if k != "__meta__"}
        if meta["case_sha256"] not in (case_sha256, *accepted):
            raise KanatError(f"{path} was written for a different case (the case file changed since); "
                             "run without --resume to start afresh")
        if meta.get("scheme") != scheme:
            raise KanatError(f"{path} was written by scheme {meta.get('scheme')}, not {scheme}: one result "
                             f"file holds one scheme; resume with the scheme it was started with, or run "
                             "without --resume to start afresh")
        return cls(meta["time"], meta["outputs"], meta["case_sha256"], meta["scheme"], state, meta["info"])
