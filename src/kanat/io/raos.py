"""Displacement RAOs of a vessel, read when the case is loaded (``vessel.motion: {rao: FILE}``).

Three formats, told apart by the file's suffix; each becomes rows
``(omega, heading_deg, dof, amplitude, phase_deg)`` in the case file's convention
(``case-format.md``: the motion is ``amplitude x wave amplitude x cos(omega t - phase)`` for the
wave crest at the vessel origin at t = 0; amplitude in m/m for surge, sway, heave and deg/m for
roll, pitch, yaw; ``heading_deg`` the direction the waves travel, from the vessel's +x towards
its +y):

* ``.csv``: columns ``omega`` [rad/s], ``heading_deg``, ``dof``, ``amplitude``, ``phase_deg``,
  in any order, a header row naming them; lines starting with ``#`` are comments.
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

import csv
import math
from pathlib import Path as FilePath

from ..model.operations import DOFS

RAO_COLUMNS = ("omega", "heading_deg", "dof", "amplitude", "phase_deg")
"""Columns of a RAO CSV file."""
MAX_RAO_BYTES = 64 * 1024**2
"""Largest RAO file read [bytes]."""


class RaoError(ValueError):
    """A RAO file that cannot be read; the message names the file, the row and the column."""


def read_raos(path: str | FilePath, ulen: float = 1.0) -> list[tuple[float, float, str, float, float]]:
    """Rows ``(omega, heading_deg, dof, amplitude, phase_deg)`` of a RAO file (module docstring).

    Raises
    ------
    OSError
        When the file cannot be read.
    RaoError
        With the file, the row and the column of the first bad entry.
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


def _number(text: str, where: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise RaoError(f"{where}: {text.strip()[:20]!r} is not a number") from None
    if not math.isfinite(value):
        raise RaoError(f"{where}: {text.strip()[:20]!r} is not a finite number")
    return value


def _read_csv(path: FilePath) -> list:
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            lines = [(n, row) for n, row in enumerate(csv.reader(handle), 1)
                     if row and not row[0].lstrip().startswith("#")]
    except UnicodeDecodeError:
        raise RaoError(f"{path.name}: not a text file (it is not UTF-8)") from None
    if not lines:
        raise RaoError(f"{path.name}: empty; the first row names the columns {', '.join(RAO_COLUMNS)}")
    header = [h.strip().lower() for h in lines[0][1]]
    missing = [c for c in RAO_COLUMNS if c not in header]
    if missing:
        raise RaoError(f"{path.name}: the header row lacks the column(s) {', '.join(missing)}; "
                       f"a RAO table's columns are {', '.join(RAO_COLUMNS)}")
    index = [header.index(c) for c in RAO_COLUMNS]
    rows = []
    for number, row in lines[1:]:
        if len(row) != len(header):
            raise RaoError(f"{path.name}, line {number}: {len(row)} values for {len(header)} columns")
        where = f"{path.name}, line {number}, column"
        dof = row[index[2]].strip().lower()
        if dof not in DOFS:
            raise RaoError(f"{where} dof: {dof[:20]!r} is not one of {', '.join(DOFS)}")
        omega, heading, amplitude, phase = (_number(row[index[k]], f"{where} {RAO_COLUMNS[k]}")
                                            for k in (0, 1, 3, 4))
        rows.append((_positive(omega, f"{where} omega"), heading, dof,
                     _not_negative(amplitude, f"{where} amplitude"), phase))
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
            period, heading, mode, modulus, phase = (_number(w, where) for w in words[:5])
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


__all__ = ["MAX_RAO_BYTES", "RAO_COLUMNS", "RaoError", "read_raos"]
