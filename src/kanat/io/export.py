"""Result files for other tools: a VTK time series for ParaView and tidy CSV tables.

:func:`export_vtk` writes, for every output time, one VTK unstructured-grid file (``.vtu``)
of the cables and one of the bodies, and a ``.pvd`` collection that ParaView opens as one
time series (File > Open, then Play). The files are written by `meshio
<https://github.com/nschloe/meshio>`_ (the ``vtk`` extra), a maintained reader and writer of
mesh formats; the collection file, a few lines of XML that meshio does not write, is
written here.

* ``STEM_cables_NNNNN.vtu``: the nodes of every cable as points, each cable a chain of line
  cells (one per segment, in the order of ``s``); point data ``tension`` [N], ``s`` [m],
  ``velocity`` [m/s] (when the result has it) and ``cable`` (the cable's index in
  ``cable_names``); cell data ``cable`` and, for the lumped model, ``segment_tension`` [N].
* ``STEM_bodies_NNNNN.vtu``: one vertex cell per body at its position; point data ``body``
  (the body's index).
* ``STEM.pvd``: every time with its two files (``part`` 0 and 1), the cable and body
  names in a comment.

:func:`export_csv` writes one CSV per variable in long ("tidy") form: one row per value,
a column per dimension and coordinate, the value last; headers carry the units
(``time [s]``, ``tension [N]``). The global attributes go to ``attributes.csv`` and the
embedded case to ``case.yaml``.

Both estimate what they will write (:func:`vtk_bytes`, :func:`csv_bytes`) and refuse before
writing anything when the disk cannot hold it (:func:`kanat.io.space.require_room`). Each file is
written atomically; a disk that fills up during the export all the same ends it with one
:class:`~kanat.errors.OutputWriteError`, and the files this export had written are removed, so a
directory never holds half a time series or half the tables.
"""
from __future__ import annotations

import contextlib
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from kanat.errors import KanatError, OutputWriteError
from kanat.io.outputs import atomic_path, write_text_atomic
from kanat.io.space import require_room

FRAME_DIGITS = 5
"""Digits of the output index in the ``.vtu`` file names (100 000 outputs)."""
VTU_BYTES_PER_VALUE = 8 * 4 / 3
"""Bytes of one value in a ``.vtu`` file: 8 of a float64, base64-encoded (4 characters per 3 bytes);
meshio also compresses them (zlib), so the estimate errs on the safe side."""
VTU_FILE_BYTES = 2048
"""The XML of one ``.vtu`` file around its data arrays [bytes]."""
CSV_BYTES_PER_FIELD = 24
"""Characters of one field of a tidy CSV row with its comma: a float as pandas writes it (up to
17 significant digits, a sign, a point and an exponent)."""
ADVICE = "free some space or export to another disk"


def _meshio():
    try:
        import meshio
    except ImportError:
        raise KanatError("VTK export needs meshio: pip install 'kanat[vtk]'") from None
    return meshio


def cable_cells(cable_of_node) -> tuple[list[str], np.ndarray, np.ndarray]:
    """Line cells joining consecutive nodes of the same cable.

    Parameters
    ----------
    cable_of_node : array_like of str, shape (n,)
        Cable name of every node (nodes are stored cable after cable, each from ``s = 0``).

    Returns
    -------
    names : list of str
        Cable names in order of appearance.
    cells : ndarray of int, shape (m, 2)
        Node pairs ``(i, i + 1)`` within one cable.
    cell_cable : ndarray of int, shape (m,)
        Index into ``names`` of each cell.
    """
    cable = np.asarray(cable_of_node).astype(str)
    names = list(dict.fromkeys(cable.tolist()))
    index = np.array([names.index(c) for c in cable], dtype=int)
    same = index[1:] == index[:-1]
    first = np.nonzero(same)[0]
    return names, np.column_stack([first, first + 1]), index[first]


def _frames(ds) -> list[tuple[float, dict]]:
    """``(time, {variable: values at that time})`` for every output (one for statics)."""
    names = [n for n in ("position", "tension", "velocity", "segment_tension", "body_position") if n in ds]
    if "time" not in ds.dims:
        return [(0.0, {n: ds[n].values for n in names})]
    return [(float(t), {n: ds[n].values[i] for n in names}) for i, t in enumerate(ds["time"].values)]


def _write_mesh(meshio, path: Path, mesh) -> None:
    with atomic_path(path) as tmp:
        meshio.write(tmp, mesh, file_format="vtu")


def _cables_mesh(meshio, frame: dict, cells, cell_cable, node_cable, s):
    points = np.asarray(frame["position"], dtype=float)
    point_data = {"tension": np.asarray(frame["tension"], dtype=float), "s": np.asarray(s, dtype=float),
                  "cable": node_cable}
    if "velocity" in frame:
        point_data["velocity"] = np.asarray(frame["velocity"], dtype=float)
    cell_data = {"cable": [cell_cable]}
    segment = frame.get("segment_tension")
    if segment is not None and len(segment) == len(cells):
        cell_data["segment_tension"] = [np.asarray(segment, dtype=float)]
    return meshio.Mesh(points, [("line", cells)], point_data=point_data, cell_data=cell_data)


def export_vtk(ds, directory, stem: str | None = None) -> Path:
    """Write a result as a VTK time series for ParaView (module docstring).

    Parameters
    ----------
    ds : xarray.Dataset
        A result with ``position`` and ``tension`` (dynamic or statics).
    directory : path-like
        Created if missing (its parent must exist).
    stem : str, optional
        File name stem; default: the case name, else ``kanat``.

    Returns
    -------
    pathlib.Path
        The ``.pvd`` collection.
    """
    meshio = _meshio()
    if "position" not in ds or "tension" not in ds:
        raise KanatError("this result has no cable positions and tensions to export (a pitch or "
                         "Naumov & Agievich result? export those with --csv)")
    directory = Path(directory)
    directory.mkdir(exist_ok=True)
    stem = _stem(stem or ds.attrs.get("case_name") or "kanat")
    names, cells, cell_cable = cable_cells(ds["cable"].values)
    node_cable = np.array([names.index(c) for c in np.asarray(ds["cable"].values).astype(str)])
    bodies = [str(b) for b in ds["body"].values] if "body" in ds.dims else []
    frames = _frames(ds)
    require_room(directory / f"{stem}.pvd", vtk_bytes(ds), f"the VTK export of {len(frames)} outputs to {directory}",
                 ADVICE)
    entries = []
    with _whole(directory, "the VTK export", entries, len(frames)):
        for i, (time, frame) in enumerate(frames):
            cable_file = f"{stem}_cables_{i:0{FRAME_DIGITS}d}.vtu"
            _write_mesh(meshio, directory / cable_file,
                        _cables_mesh(meshio, frame, cells, cell_cable, node_cable, ds["s"].values))
            entries.append((time, 0, cable_file))
            if bodies:
                body_file = f"{stem}_bodies_{i:0{FRAME_DIGITS}d}.vtu"
                mesh = meshio.Mesh(np.asarray(frame["body_position"], dtype=float),
                                   [("vertex", np.arange(len(bodies))[:, None])],
                                   point_data={"body": np.arange(len(bodies))})
                _write_mesh(meshio, directory / body_file, mesh)
                entries.append((time, 1, body_file))
        return write_text_atomic(directory / f"{stem}.pvd", pvd_text(entries, names, bodies))


def vtk_bytes(ds) -> float:
    """Estimated size of :func:`export_vtk`'s files for ``ds`` [bytes]: per output, every node's
    position, tension, s, cable and velocity, every segment's two nodes, cable and tension, every
    body's position and index (:data:`VTU_BYTES_PER_VALUE` each), and the XML of two files."""
    outputs = ds.sizes.get("time", 1)
    nodes, bodies = ds.sizes.get("node", 0), ds.sizes.get("body", 0)
    values = nodes * (3 + 1 + 1 + 1 + 3) + max(nodes - 1, 0) * (2 + 1 + 1) + bodies * 4
    return outputs * (values * VTU_BYTES_PER_VALUE + 2 * VTU_FILE_BYTES)


def csv_bytes(ds) -> float:
    """Estimated size of :func:`export_csv`'s tables for ``ds`` [bytes]: a row per value of every
    variable, with a field per dimension and coordinate (:data:`CSV_BYTES_PER_FIELD` each), and
    the attributes and the case as they are."""
    fields = sum(var.size * (1 + var.ndim + sum(1 for c in var.coords if c not in var.dims))
                 for var in ds.data_vars.values())
    return fields * CSV_BYTES_PER_FIELD + sum(len(str(v)) + len(k) + 4 for k, v in ds.attrs.items())


@contextlib.contextmanager
def _whole(directory: Path, what: str, written: list, total: int):
    """Remove the files of ``written`` (paths, or entries ending with a file name in ``directory``)
    when the block ends in an :class:`OutputWriteError` (a disk that filled up), and say so."""
    try:
        yield
    except OutputWriteError as error:
        files = [directory / (entry[-1] if isinstance(entry, tuple) else entry) for entry in written]
        for path in files:
            Path(path).unlink(missing_ok=True)
        raise OutputWriteError(f"{what} to {directory} ({total} outputs or tables) stopped after writing "
                               f"{len(files)} files, which were removed: {error}") from None


def pvd_text(entries, cables, bodies) -> str:
    """A ParaView collection: ``entries`` of ``(time, part, file)``."""
    rows = [f'    <DataSet timestep="{time!r}" group="" part="{part}" file={quoteattr(name)}/>'
            for time, part, name in entries]
    note = ("part 0: cables " + ", ".join(f"{i}={n}" for i, n in enumerate(cables))
            + "; part 1: bodies " + (", ".join(f"{i}={n}" for i, n in enumerate(bodies)) or "none"))
    return "\n".join(['<?xml version="1.0"?>',
                      '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
                      f"  <!-- {note.replace('--', '- -')} -->", "  <Collection>", *rows,
                      "  </Collection>", "</VTKFile>", ""])


def _stem(name: str) -> str:
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in name).strip(".") or "kanat"


def _header(name: str, units) -> str:
    return f"{name} [{units}]" if units not in (None, "", "1", "–") else name


def tidy_table(ds, name: str):
    """One variable as a long table: a column per dimension and coordinate, the value last.

    Returns
    -------
    pandas.DataFrame
        Columns named with their units (``time [s]``, ``s [m]``, ``tension [N]``).
    """
    import pandas as pd

    var = ds[name]
    if var.ndim == 0:
        frame = pd.DataFrame({name: [var.values.item()]})
    else:
        frame = var.to_dataframe(name=name).reset_index()
    columns = [c for c in frame.columns if c != name] + [name]
    frame = frame[columns]
    units = {c: ds[c].attrs.get("units") if c in ds.variables else None for c in columns}
    return frame.rename(columns={c: _header(c, units[c]) for c in columns})


def export_csv(ds, directory) -> list[Path]:
    """Write every variable of a result as a tidy CSV (module docstring); return the files."""
    import csv
    import io

    directory = Path(directory)
    directory.mkdir(exist_ok=True)
    require_room(directory / "attributes.csv", csv_bytes(ds),
                 f"the CSV export of {len(ds.data_vars)} variables to {directory}", ADVICE)
    written = []
    with _whole(directory, "the CSV export", written, len(ds.data_vars) + 2):
        for name in ds.data_vars:
            path = directory / f"{name}.csv"
            with atomic_path(path) as tmp:
                tidy_table(ds, name).to_csv(tmp, index=False)
            written.append(path)
        buffer = io.StringIO()
        writer = csv.writer(buffer)
        writer.writerow(["name", "value"])
        writer.writerows([k, v] for k, v in ds.attrs.items() if k != "case_yaml")
        written.append(write_text_atomic(directory / "attributes.csv", buffer.getvalue()))
        if ds.attrs.get("case_yaml"):
            written.append(write_text_atomic(directory / "case.yaml", str(ds.attrs["case_yaml"])))
    return written
