"""Results written as a run goes, and checkpoints to resume a killed run.

A dynamic run opens a :class:`ResultStream`: the time-independent variables are written
at once, then every output step appends one slice along the unlimited ``time``
dimension and flushes it, so a killed run leaves a readable file with everything up to
its last output. ``status`` says ``running`` until the run closes the stream with ``ok``
or its failure message.

A :class:`Checkpoint` is the solver's full state at an output time, written atomically
beside the result (``OUT.nc.ckpt.npz``). Resuming truncates the result to the
checkpoint's output count and continues from its state, so a resumed run gives the same
answer as an uninterrupted one. The checkpoint records the case's SHA-256 and refuses a
changed case.
"""
from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass
from pathlib import Path

import h5netcdf
import numpy as np
import xarray as xr

from kanat.errors import KanatError
from kanat.io.results import _netcdf_attr, annotate


class ResultStream:
    """Append-as-you-go netCDF result (h5netcdf, unlimited ``time``).

    Slices are buffered in memory and written in blocks, at the latest ``FLUSH_WALL_S``
    seconds of wall time after the first unwritten one, and always by :meth:`flush`
    (called before every checkpoint) and :meth:`close`.

    Parameters
    ----------
    path : path-like
        Result file; created (or, with ``resume_at``, reopened and truncated).
    static : xarray.Dataset or None
        Time-independent variables and the global attributes (None when resuming).
    time_vars : dict of str to (tuple of str, str)
        Time-dependent variables: dimensions after ``time`` and units.
    resume_at : int, optional
        Number of output slices to keep when resuming a run.
    """

    FLUSH_WALL_S = 1.0

    def __init__(self, path, static: xr.Dataset | None, time_vars: dict, resume_at: int | None = None):
        self.path = Path(path)
        self.time_vars = dict(time_vars)
        if resume_at is None:
            self._create(static)
        self._file = h5netcdf.File(self.path, "a")
        if resume_at is not None:
            self._file.resize_dimension("time", resume_at)
        self._file.attrs["status"] = "running"
        self._sync()
        self._buffer: list[tuple[float, dict]] = []
        self._oldest = 0.0

    def _create(self, static: xr.Dataset) -> None:
        ds = static.copy()
        ds["time"] = ("time", np.zeros(0), {"units": "s", "long_name": "simulated time"})
        for name, (dims, units) in self.time_vars.items():
            shape = (0,) + tuple(ds.sizes[d] for d in dims)
            ds[name] = (("time",) + tuple(dims), np.zeros(shape), {"units": units})
        ds = annotate(ds)
        ds.attrs = {k: _netcdf_attr(v) for k, v in ds.attrs.items()}
        self.path.parent.mkdir(parents=True, exist_ok=True)
        ds.to_netcdf(self.path, engine="h5netcdf", unlimited_dims=["time"])

    @property
    def count(self) -> int:
        """Slices appended so far (written or buffered)."""
        return self._file.dimensions["time"].size + len(self._buffer)

    def append(self, t: float, **values) -> None:
        """Add one output slice at time ``t`` [s]; every time variable must be given."""
        missing = set(self.time_vars) - set(values)
        if missing:
            raise ValueError(f"missing time variables: {sorted(missing)}")
        if not self._buffer:
            self._oldest = time.perf_counter()
        self._buffer.append((t, {k: np.array(v, dtype=float) for k, v in values.items()}))
        if time.perf_counter() - self._oldest > self.FLUSH_WALL_S:
            self.flush()

    def flush(self) -> None:
        """Write the buffered slices to the file as one block and flush it to disk."""
        if not self._buffer:
            return
        n, m = self._file.dimensions["time"].size, len(self._buffer)
        self._file.resize_dimension("time", n + m)
        self._file.variables["time"][n:n + m] = [t for t, _ in self._buffer]
        for name in self.time_vars:
            self._file.variables[name][n:n + m, ...] = np.stack([values[name] for _, values in self._buffer])
        self._sync()
        self._buffer.clear()

    def _sync(self) -> None:
        """Push everything written so far to disk, HDF5 metadata included.

        ``h5netcdf.File.flush`` writes only the netCDF attributes; the HDF5 file beneath
        must be flushed too, or a killed run leaves datasets of length 0 on disk.
        """
        self._file.flush()
        self._file._h5file.flush()

    def close(self, status: str = "ok", **attrs) -> None:
        """Write what is buffered, record the final status and attributes, and close the file.

        A run closed with ``ok`` needs no resuming, so its checkpoint is removed; an interrupted
        or failed run keeps it for ``--resume``.
        """
        self.flush()
        for key, value in {"status": status, **attrs}.items():
            self._file.attrs[key] = _netcdf_attr(value)
        self._file.close()
        if status == "ok":
            Checkpoint.path_for(self.path).unlink(missing_ok=True)


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
    state : dict of str to ndarray
        The solver's arrays (positions, velocities, multistep history, ...).
    info : dict
        Small JSON-able extras (step counters, statistics).
    """

    time: float
    outputs: int
    case_sha256: str
    state: dict
    info: dict

    @staticmethod
    def path_for(result_path) -> Path:
        return Path(str(result_path) + ".ckpt.npz")

    def save(self, result_path) -> Path:
        """Write atomically beside the result file."""
        path = self.path_for(result_path)
        tmp = path.with_name(path.name + ".part.npz")
        meta = json.dumps({"time": self.time, "outputs": self.outputs, "case_sha256": self.case_sha256,
                           "info": self.info})
        np.savez(tmp, __meta__=np.array(meta), **self.state)
        os.replace(tmp, path)
        return path

    @classmethod
    def load(cls, result_path, case_sha256: str) -> Checkpoint:
        """Read the checkpoint of ``result_path``; refuse one written for another case."""
        path = cls.path_for(result_path)
        if not path.exists():
            raise KanatError(f"no checkpoint {path} to resume from; run without --resume to start afresh")
        with np.load(path) as data:
            meta = json.loads(str(data["__meta__"]))
            state = {k: data[k] for k in data.files if k != "__meta__"}
        if meta["case_sha256"] != case_sha256:
            raise KanatError(f"{path} was written for a different case (the case file changed since); "
                             "run without --resume to start afresh")
        return cls(meta["time"], meta["outputs"], meta["case_sha256"], state, meta["info"])
