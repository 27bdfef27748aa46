"""Displacement RAOs of a vessel, read when the case is loaded (``vessel.motion: {rao: FILE}``).

Three formats, told apart by the file's suffix; each becomes rows
``(omega, heading_deg, dof, amplitude, phase_deg)`` in the case file's convention
(``case-format.md``: the motion is ``amplitude x wave amplitude x cos(omega t - phase)`` for the
wave crest at the vessel origin at t = 0; amplitude in m/m for surge, sway, heave and deg/m for
roll, pitch, yaw; ``heading_deg`` the direction the waves travel, from the vessel's +x towards
its +y):

* ``.csv``: columns ``omega`` [rad/s], ``heading_deg``, ``dof``, ``amplitude``, ``phase_deg``,
  in any order, a header row naming them; lines starting with ``#`` are comments (read by
  :func:`kanat.io.csv_rows.read_rows`, as the case's other tables).
* WAMIT ``.4`` (motion RAOs; WAMIT manual, "Output files", option 4): rows ``PER BETA I MOD PHA
  RE IM`` with the period [s], the heading [deg], the mode 1-6 and the modulus and phase [deg]
  of ``xi / A`` (rotations ``xi L / A`` with WAMIT's length ``ULEN``, given as ``motion.ulen``,
  in rad/m). WAMIT's motion is ``Re(xi e^{i omega t})`` for the wave ``Re(A e^{i omega t})`` at
  the origin, so its phase is minus ours; rows with a period of 0 or below (zero or infinite
  frequency) are skipped.
* Capytaine (``.nc``): a dataset with a complex ``RAO`` variable over ``omega`` [rad/s],
  ``wave_direction`` [rad] and ``radiating_dof`` (``Surge`` ... ``Yaw``), complex values
  stored as Capytaine writes them (a ``complex`` dimension ``re, im``) or as complex numbers.
  Capytaine's motion is ``Re(X e^{-i omega t})`` for the wave ``Re(A e^{-i omega t})``: its
  phase ``arg X`` is ours; rotations are in rad/m.
"""
from __future__ import annotations

import math
from pathlib import Path as FilePath

from ..model.operations import DOFS
from .csv_rows import TableError, TableSpec, finite_number, read_rows

RAO_COLUMNS = ("omega", "heading_deg", "dof", "amplitude", "phase_deg")
"""Columns of a RAO CSV file."""
MAX_RAO_BYTES = 64 * 1024**2
"""Largest RAO file read [bytes]."""
RAO_TABLE = TableSpec("RAO table", RAO_COLUMNS, RAO_COLUMNS, "raos.csv", max_bytes=MAX_RAO_BYTES)
"""A RAO CSV file, read by :func:`kanat.io.csv_rows.read_rows` as every table of a case is."""


class RaoError(TableError):
    """A RAO file that cannot be read; the message names the file, the row and the column."""


def read_raos(path: str | FilePath, ulen: float = 1.0) -> list[tuple[float, float, str, float, float]]:
    """Rows ``(omega, heading_deg, dof, amplitude, phase_deg)`` of a RAO file (module docstring).

    Raises
    ------
    OSError
        When the file cannot be read.
    TableError
        With the file, the row and the column of the first bad entry (a :class:`RaoError` but
        for the faults every CSV table can have, :mod:`kanat.io.csv_rows`).
    """
    path = FilePath(path)
    size = path.stat().st_size
    if not path.is_file():
        raise RaoError(f"{path.name}: not a regular file")
    if size > MAX_RAO_BYTES:
        raise RaoError(f"{path.name}: {size / 1024**2:.0f} MiB, more than the "
                       f"{MAX_RAO_BYTES / 1024**2:.0f} MiB a RAO file may hold")
    readers = {".csv": lambda: _read_csv(path), ".4": lambda: _read_wamit(path, ulen),
               ".nc": lambda: _read_capytaine(path)}
    reader = readers.get(path.suffix.lower())
    if reader is None:
        raise RaoError(f"'{path.name}': a RAO file is a .csv table (columns "
                       f"{', '.join(RAO_COLUMNS)}), a WAMIT .4 file or a Capytaine .nc dataset")
    rows = reader()
    if not rows:
        raise RaoError(f"{path.name}: holds no RAO")
    return rows


def _read_csv(path: FilePath) -> list:
    rows = []
    for row in read_rows(path, RAO_TABLE):
        dof = row.text("dof").lower()
        if dof not in DOFS:
            raise RaoError(f"{row.where('dof')}: {dof[:20]!r} is not one of {', '.join(DOFS)}")
        rows.append((_positive(row.number("omega"), row.where("omega")), row.number("heading_deg"), dof,
                     _not_negative(row.number("amplitude"), row.where("amplitude")), row.number("phase_deg")))
    return rows


def _positive(value, where):
    if value <= 0.0:
        raise RaoError(f"{where}: {value:g} must be positive")
    return value


def _not_negative(value, where):
    if value < 0.0:
        raise RaoError(f"{where}: {value:g} must be 0 or more (give the sign as a phase of 180 deg)")
    return value


def _read_wamit(path: FilePath, ulen: float) -> list:
    rows = []
    with path.open(encoding="utf-8", errors="replace") as handle:
        for number, line in enumerate(handle, 1):
            words = line.split()
            if not words:
                continue
            if len(words) < 5:
                raise RaoError(f"{path.name}, line {number}: {len(words)} values; a WAMIT .4 row is "
                               "PER BETA I MOD PHA RE IM")
            where = f"{path.name}, line {number}"
            period, heading, mode, modulus, phase = (finite_number(w, where, RaoError) for w in words[:5])
            if period <= 0.0:
                continue
            if mode not in (1, 2, 3, 4, 5, 6):
                raise RaoError(f"{where}: mode {words[2]!r} is not 1-6")
            dof = DOFS[int(mode) - 1]
            amplitude = modulus if mode <= 3 else math.degrees(modulus / ulen)
            rows.append((2.0 * math.pi / period, heading, dof, amplitude, -phase))
    return rows


def _read_capytaine(path: FilePath) -> list:
    import numpy as np
    import xarray as xr

    try:
        ds = xr.open_dataset(path)
    except Exception as error:                          # noqa: BLE001 - any reader's refusal
        raise RaoError(f"{path.name}: not a netCDF dataset xarray can open ({error})") from None
    with ds:
        if "RAO" not in ds:
            raise RaoError(f"{path.name}: no 'RAO' variable (a Capytaine dataset holds it after "
                           "capytaine.post_pro.rao; save it with capytaine.io.xarray.separate_complex_values)")
        rao = ds["RAO"]
        if "complex" in rao.dims:
            rao = rao.sel(complex="re") + 1j * rao.sel(complex="im")
        need = {"omega", "wave_direction", "radiating_dof"}
        if not need <= set(rao.dims):
            raise RaoError(f"{path.name}: RAO's dimensions are {', '.join(rao.dims)}; expected "
                           f"{', '.join(sorted(need))}")
        rao = rao.transpose("omega", "wave_direction", "radiating_dof")
        values = np.asarray(rao.values, dtype=complex)
        omegas = np.asarray(rao["omega"].values, float)
        headings = np.degrees(np.asarray(rao["wave_direction"].values, float))
        names = [str(n).lower() for n in rao["radiating_dof"].values]
    rows = []
    for k, name in enumerate(names):
        if name not in DOFS:
            raise RaoError(f"{path.name}: radiating_dof '{name}' is not one of {', '.join(DOFS)}")
        for i, omega in enumerate(omegas):
            for j, heading in enumerate(headings):
                x = values[i, j, k]
                amplitude = abs(x) if DOFS.index(name) < 3 else math.degrees(abs(x))
                rows.append((float(omega), float(heading), name, float(amplitude), math.degrees(np.angle(x))))
    return [r for r in rows if r[0] > 0.0]


__all__ = ["MAX_RAO_BYTES", "RAO_COLUMNS", "RAO_TABLE", "RaoError", "read_raos"]
