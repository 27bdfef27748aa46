"""A MoorDyn file's waves and current from its water-kinematics files (``WaveKin``, ``Currents``).

MoorDyn-C v2 (``moordyn`` 2.x, ``Waves.cpp`` and ``Waves/*.cpp``) reads its water kinematics
from fixed file names in the folder of the input file. What each option does and what kanat
makes of it (``environment.waves`` of ``type: components``, ``environment.current.profile``):

* ``WaveKin 0``: still water. ``WaveKin 1``: the driving program sets the kinematics at the
  nodes through MoorDyn's API (``ExternalWaveKinSet``): no file holds them, so the importer
  refuses it and says to give ``environment.waves`` in the imported case.
* ``WaveKin 7`` (components summed at the nodes): ``wave_frequencies.txt``, rows ``omega re
  im [beta]`` (rad/s, m, m, rad; the first at 0 rad/s). MoorDyn sums ``|A| sin(omega t - k
  (x cos beta + y sin beta) + arg A)`` with ``A = re + i im``, which is kanat's component
  ``a cos(k l - omega t + phi)`` with ``a = |A|``, ``phi = pi/2 - arg A`` and heading
  ``beta``: the importer writes the rows so, one for one.
* ``WaveKin 2`` (FFT grid): the same file, interpolated linearly (real, imaginary parts and
  ``beta``) to the frequencies ``j dw`` (``dw`` the smallest spacing in the file, up to the
  last), inverse-FFT'd (``nt = 2 (n - 1)`` samples of ``A_j (n - 1)``) onto the grid of
  ``water_grid.txt``. Its sum is :func:`grid_components` of ``X_j = A_j (n - 1)``.
* ``WaveKin 3`` (elevation grid): ``wave_elevation.txt``, rows ``t eta`` (s, m): resampled
  linearly at ``dtWave`` (default 0.25 s) from 0 to the last time, the last sample dropped
  when their number is odd, FFT'd (``X = rfft(eta)``), components above 0.5 Hz zeroed, and
  inverse-FFT'd onto the grid as in mode 2 (heading 0: along +x): :func:`grid_components`.
  The sea repeats every ``nt dtWave``, as MoorDyn's grid does.
* ``WaveKin 4, 5, 6`` are not implemented by MoorDyn-C itself: refused.
* ``Currents 1``: ``current_profile.txt`` (three header lines, then ``z ux [uy [uz]]``) is
  kanat's ``current.profile`` (linear between rows, constant beyond, as in both codes).
  ``Currents 2`` to ``5`` (time-varying, 4-D) have no kanat counterpart: refused.

:func:`grid_components` turns the one-sided spectrum of MoorDyn's inverse FFT into kanat's
components, exactly at the grid's sample times: with ``Z_j = X_j e^{-i k_j l_j}``,
``eta_n = (Re Z_0 + 2 sum_{0<j<M} Re(Z_j e^{i w_j t_n}) + Re(Z_M) cos(pi n)) / nt``
(``M = nt / 2``, kiss_fftr's real inverse). Component ``0 < j < M`` has amplitude ``2 |X_j|
/ nt`` and phase ``-arg X_j``; the highest (``j = M``) is the standing wave ``|X_M| / nt
cos(arg X_M - k l) cos(w t)``, written as two components of half that amplitude travelling
opposite ways; the mean ``Re X_0 / nt`` is a shift of the still water level that kanat
cannot express (a warning gives it).

MoorDyn stretches the kinematics to the instantaneous surface (Wheeler: a node at ``z`` takes
those at ``h (z + h) / (h + eta) - h``, a node above the surface those of the surface): the
importer writes ``stretching: wheeler``, which does the same (:mod:`kanat.physics.waves` eq. 7;
tests/physics/test_wave_stretching.py checks it against MoorDyn's ``WaveKin 7`` to 1e-7). Where kanat
differs: in modes 2 and 3 MoorDyn interpolates the kinematics linearly in a grid of points and
times (holding them at the grid's edges), kanat sums the components at each node. The importer
says so in a warning, and warns when the structure reaches beyond the grid in x or y, where
MoorDyn's waves stop changing along x or y.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path as FilePath

import numpy as np

from ..errors import Problem

DT_WAVE = 0.25
"""MoorDyn-C's default ``dtWave`` [s] (``WaterKinOptions``)."""
ELEVATION_CUTOFF = math.pi
"""Highest angular frequency [rad/s] MoorDyn-C keeps of a ``wave_elevation.txt`` FFT (0.5 Hz)."""
MODE_FILES = {2: ("wave_frequencies.txt", "water_grid.txt"), 3: ("wave_elevation.txt", "water_grid.txt"),
              7: ("wave_frequencies.txt",)}
"""The files MoorDyn-C reads for each supported ``WaveKin``, in the input file's folder."""
NOT_IN_MOORDYN = (4, 5, 6)
"""``WaveKin`` values MoorDyn-C defines but does not implement."""
LEVEL_TOL = 1e-9
"""Mean level [m] below which a zero-frequency term is taken as zero."""
GRID = ("MoorDyn interpolates its wave kinematics linearly in the points and times of water_grid.txt; "
        "kanat sums the components at each node (both stretched to the surface, Wheeler): they differ by "
        "the interpolation's error")


@dataclass(frozen=True)
class WaveFileError(Exception):
    """A problem in one of MoorDyn's water-kinematics files, at a line of it."""

    file: str
    line: int | None
    message: str


def _rows(path: FilePath, widths: tuple[int, int], skip: int = 0) -> list[tuple[int, list[float]]]:
    """``(line, numbers)`` of the non-blank lines of ``path`` after ``skip`` header lines."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise WaveFileError(str(path), None, "not found: MoorDyn reads it from the input file's folder "
                            "under this name") from None
    except (OSError, UnicodeDecodeError) as error:
        raise WaveFileError(str(path), None, f"cannot read it ({error})") from None
    rows = []
    for number, raw in enumerate(text.splitlines(), 1):
        words = raw.split()
        if number <= skip or not words:
            continue
        if not widths[0] <= len(words) <= widths[1]:
            expect = f"{widths[0]} to {widths[1]}" if widths[1] < 99 else f"at least {widths[0]}"
            raise WaveFileError(str(path), number, f"{len(words)} values; this file has {expect} "
                                "numbers per row")
        try:
            values = [float(w) for w in words]
        except ValueError:
            raise WaveFileError(str(path), number, f"'{raw.strip()}' is not a row of numbers") from None
        if not all(math.isfinite(v) for v in values):
            raise WaveFileError(str(path), number, f"'{raw.strip()}' has a value that is not finite")
        rows.append((number, values))
    if not rows:
        raise WaveFileError(str(path), None, "has no rows of numbers")
    return rows


def read_frequencies(path: FilePath) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``wave_frequencies.txt``: angular frequencies [rad/s], complex amplitudes [m], directions
    [rad] (0 where the fourth column is absent), checked as MoorDyn-C checks them."""
    rows = _rows(path, (3, 4))
    if len(rows) < 2:
        raise WaveFileError(str(path), rows[0][0], "MoorDyn needs at least 2 rows (the first at 0 rad/s)")
    if rows[0][1][0] != 0.0:
        raise WaveFileError(str(path), rows[0][0], f"the first frequency is {rows[0][1][0]:g} rad/s; "
                            "MoorDyn requires the first row at 0 rad/s")
    for line, values in rows:
        if values[0] < 0:
            raise WaveFileError(str(path), line, f"frequency {values[0]:g} rad/s: frequencies are >= 0")
        if len(values) == 4 and abs(values[3]) > 2 * math.pi:
            raise WaveFileError(str(path), line, f"direction {values[3]:g}: MoorDyn takes radians "
                                "between -2 pi and 2 pi")
    omega = np.array([v[0] for _, v in rows])
    amplitude = np.array([complex(v[1], v[2]) for _, v in rows])
    beta = np.array([v[3] if len(v) == 4 else 0.0 for _, v in rows])
    return omega, amplitude, beta


def summed_components(omega, amplitude, beta) -> tuple[list[list[float]], float]:
    """``WaveKin 7``: kanat's rows ``[omega, a, phase_deg, heading_deg]`` (module docstring) and
    the still-level shift [m] of the zero-frequency rows (``sum Im A``, dropped)."""
    rows, level = [], 0.0
    for w, a, b in zip(omega, amplitude, beta):
        if w == 0.0:
            level += a.imag                      # |A| sin(arg A): a constant elevation
            continue
        if abs(a) > 0:
            rows.append([float(w), float(abs(a)), math.degrees(math.pi / 2 - np.angle(a)), math.degrees(b)])
    return rows, level


def even_spectrum(omega, amplitude, beta) -> tuple[np.ndarray, np.ndarray, float]:
    """``WaveKin 2``: the file's spectrum at ``j dw`` (MoorDyn-C's ``interpEvenlySpaced``):
    complex amplitudes, directions, and ``dw``."""
    spacing = np.diff(omega)
    if np.any(spacing <= 0):
        raise ValueError("with WaveKin 2 the frequencies must increase from row to row")
    dw = float(spacing.min())
    grid = np.arange(int(math.floor(omega[-1] / dw)) + 1) * dw
    values = np.interp(grid, omega, amplitude.real) + 1j * np.interp(grid, omega, amplitude.imag)
    return values, np.interp(grid, omega, beta), dw


def elevation_spectrum(times, elevations, dt_wave: float) -> tuple[np.ndarray, float]:
    """``WaveKin 3``: MoorDyn-C's FFT of the elevation resampled at ``dt_wave``, components above
    0.5 Hz zeroed: the one-sided ``X`` (length ``nt / 2 + 1``) and ``dw`` [rad/s]."""
    count = int(math.floor(times[-1] / dt_wave)) + 1
    count -= count % 2                                   # kiss_fftr takes an even length
    if count < 2:
        raise ValueError(f"the series ends at {times[-1]:g} s: shorter than two samples of dtWave "
                         f"= {dt_wave:g} s")
    samples = np.interp(np.arange(count) * dt_wave, times, elevations)
    spectrum = np.fft.rfft(samples)
    dw = 2 * math.pi / (count * dt_wave)
    spectrum[np.arange(len(spectrum)) * dw > ELEVATION_CUTOFF] = 0.0
    return spectrum, dw


def grid_components(spectrum, beta, dw: float) -> tuple[list[list[float]], float]:
    """The sum MoorDyn-C's inverse FFT of the one-sided ``spectrum`` (``M + 1`` values, ``nt =
    2 M`` samples) stands for, as kanat's component rows (module docstring), and the mean level
    ``Re X_0 / nt`` [m] (dropped)."""
    spectrum, beta = np.asarray(spectrum, complex), np.asarray(beta, float)
    top = len(spectrum) - 1
    nt = 2 * top
    rows = []
    for j in range(1, top + 1):
        x = spectrum[j]
        if abs(x) == 0:
            continue
        heading = math.degrees(beta[j])
        if j < top:
            rows.append([j * dw, 2 * abs(x) / nt, -math.degrees(np.angle(x)), heading])
        else:                                            # standing: two halves, opposite ways
            psi = math.degrees(np.angle(x))
            rows += [[j * dw, abs(x) / (2 * nt), -psi, heading], [j * dw, abs(x) / (2 * nt), psi, heading + 180.0]]
    return rows, float(spectrum[0].real) / nt


def read_grid(path: FilePath) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``water_grid.txt``: the x, y, z coordinates of MoorDyn's kinematics grid (lines 4-9: a
    type, 0 one point at 0, 1 a list, 2 ``first last count``, then its values)."""
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except FileNotFoundError:
        raise WaveFileError(str(path), None, "not found: MoorDyn needs it (the grid of its wave "
                            "kinematics) beside the input file") from None
    except (OSError, UnicodeDecodeError) as error:
        raise WaveFileError(str(path), None, f"cannot read it ({error})") from None
    if len(lines) < 9:
        raise WaveFileError(str(path), len(lines) or None, f"{len(lines)} lines; MoorDyn needs 9 "
                            "(3 header lines, then a type line and a values line for x, y and z)")
    axes = []
    for axis, first in zip("xyz", (4, 6, 8)):
        kind_words, values = lines[first - 1].split(), lines[first].split()
        try:
            kind = int(kind_words[0]) if kind_words else -1
            numbers = [float(v) for v in values]
        except ValueError:
            raise WaveFileError(str(path), first, f"the {axis} axis: '{lines[first - 1].strip()}' / "
                                f"'{lines[first].strip()}' are not a type (0, 1, 2) and numbers") from None
        if kind == 0:
            axes.append(np.zeros(1))
        elif kind == 1 and numbers:
            axes.append(np.array(numbers))
        elif kind == 2 and len(numbers) >= 3 and numbers[2] >= 2:
            axes.append(np.linspace(numbers[0], numbers[1], int(numbers[2])))
        else:
            raise WaveFileError(str(path), first, f"the {axis} axis: type '{lines[first - 1].strip()}' "
                                "with these values is not one MoorDyn reads (0: one point at 0; 1: a "
                                "list; 2: first, last, number of points)")
    return axes[0], axes[1], axes[2]


def read_elevation(path: FilePath) -> tuple[np.ndarray, np.ndarray]:
    """``wave_elevation.txt``: times [s] (increasing) and elevations [m] (extra columns ignored,
    as by MoorDyn)."""
    rows = _rows(path, (2, 99))
    times = np.array([v[0] for _, v in rows])
    for (line, values), step in zip(rows[1:], np.diff(times)):
        if step <= 0:
            raise WaveFileError(str(path), line, f"time {values[0]:g} s does not follow the previous "
                                "row's: times must increase")
    return times, np.array([v[1] for _, v in rows])


def read_current(path: FilePath) -> list[list[float]]:
    """``current_profile.txt`` (``Currents 1``): kanat's profile rows ``[z, ux, uy, uz]``."""
    rows = _rows(path, (2, 4), skip=3)
    seen: dict[float, int] = {}
    out = []
    for line, values in rows:
        if values[0] in seen:
            raise WaveFileError(str(path), line, f"z = {values[0]:g} m is also on line {seen[values[0]]}")
        seen[values[0]] = line
        out.append((values + [0.0, 0.0])[:4])
    return out


def import_water(reader, positions) -> dict:
    """``environment`` keys (``waves``, ``current``) of a MoorDyn file's ``WaveKin`` and
    ``Currents`` (module docstring); problems go to ``reader`` (a
    :class:`kanat.io.moordyn_map.Reader`), with the file and line of the wave file they are in.

    Parameters
    ----------
    reader : kanat.io.moordyn_map.Reader
        The file's reader, its OPTIONS read.
    positions : array_like, shape (n, 3)
        Initial positions of the structure's points [m] (for the grid's extent).
    """
    out: dict = {}
    waves = _waves(reader, np.asarray(positions, float).reshape(-1, 3))
    if waves:
        out["waves"] = waves
        reader.lines[("environment", "waves")] = reader.option_lines["wave_kin"]
    current = _current(reader)
    if current:
        out["current"] = {"profile": current}
        reader.lines[("environment", "current")] = reader.option_lines["currents"]
    return out


def _whole(reader, option: str, key: str) -> int | None:
    value = reader.options.get(option, 0.0)
    if not math.isfinite(value):
        return None                                  # reported where the option was read
    if value != int(value):
        reader.error(reader.option_lines[option], f"OPTIONS.{key}", f"{value:g} is not a whole number")
        return None
    return int(value)


def _file_error(reader, key: str, error: WaveFileError) -> None:
    reader.problems.append(Problem(key, error.message, error.file, error.line, "error"))


def _waves(reader, positions: np.ndarray) -> dict | None:
    mode = _whole(reader, "wave_kin", "WaveKin")
    line = reader.option_lines.get("wave_kin")
    dt_line = reader.option_lines.get("dt_wave")
    if dt_line and mode != 3:
        reader.warn(dt_line, "OPTIONS.dtWave", "dtWave acts only with WaveKin 3 (the time step of the "
                    "resampled elevation); not imported")
    if not mode:
        return None
    key = "OPTIONS.WaveKin"
    if mode == 1:
        reader.error(line, key, "WaveKin = 1 means the program driving MoorDyn sets the wave kinematics "
                     "through its API (ExternalWaveKinSet), so no file holds waves to import: set WaveKin "
                     "to 0, import the file, then give environment.waves in the YAML case")
        return None
    if mode in NOT_IN_MOORDYN or mode not in MODE_FILES:
        reader.error(line, key, f"WaveKin = {mode}: MoorDyn-C does not implement it (it takes 0, 1, 2, 3 "
                     "and 7); nothing to import")
        return None
    folder = reader.base
    try:
        rows, level, highest = _mode_rows(reader, mode, folder)
        if mode in (2, 3):
            _grid_extent(reader, line, read_grid(folder / "water_grid.txt"), positions)
    except WaveFileError as error:
        _file_error(reader, key, error)
        return None
    except ValueError as error:                      # a file's content that MoorDyn cannot use
        reader.error(line, key, f"WaveKin = {mode}: {MODE_FILES[mode][0]}: {error}")
        return None
    if abs(level) > LEVEL_TOL:
        reader.warn(line, key, f"{MODE_FILES[mode][0]} raises the still water level by {level:.4g} m "
                    "(its zero-frequency term); kanat's still water stays at z = 0: not imported")
    if highest > LEVEL_TOL:
        reader.warn(line, key, f"the highest frequency of MoorDyn's inverse FFT carries {highest:.4g} m: "
                    "MoorDyn keeps its real part alone, a standing wave (imported as such) whose "
                    "vertical velocity it does not derive from the elevation; give that row a zero "
                    "amplitude (or add a higher frequency) for the two codes to agree")
    if not rows:
        reader.warn(line, key, f"{MODE_FILES[mode][0]} holds no wave of nonzero amplitude: still water")
        return None
    if mode in (2, 3):
        reader.warn(line, key, f"WaveKin = {mode}: {GRID}")
    return {"type": "components", "components": rows, "stretching": "wheeler"}


def _mode_rows(reader, mode: int, folder: FilePath) -> tuple[list[list[float]], float, float]:
    """Component rows, still-level shift [m] and the amplitude [m] of the inverse FFT's highest
    (standing) term, of a supported ``WaveKin``."""
    if mode == 3:
        dt_wave = reader.options.get("dt_wave", DT_WAVE)
        if not dt_wave > 0:
            raise ValueError(f"dtWave = {dt_wave:g} s; it must be > 0")
        spectrum, dw = elevation_spectrum(*read_elevation(folder / "wave_elevation.txt"), dt_wave)
        betas = np.zeros(len(spectrum))
    else:
        omega, amplitude, beta = read_frequencies(folder / "wave_frequencies.txt")
        if mode == 7:
            return (*summed_components(omega, amplitude, beta), 0.0)
        values, betas, dw = even_spectrum(omega, amplitude, beta)
        spectrum = values * (len(values) - 1)
    rows, level = grid_components(spectrum, betas, dw)
    return rows, level, abs(spectrum[-1]) / (2 * (len(spectrum) - 1))


def _grid_extent(reader, line: int, grid, positions: np.ndarray) -> None:
    if not len(positions):
        return
    for axis, (name, values) in enumerate(zip("xyz", grid)):
        low, high = positions[:, axis].min(), positions[:, axis].max()
        if name == "z":
            high = min(high, 0.0)                    # the grid ends at the surface
        if low < values.min() - 1e-9 or high > values.max() + 1e-9:
            reader.warn(line, "OPTIONS.WaveKin", f"the structure spans {name} = {low:g} to {high:g} m, "
                        f"water_grid.txt's {name} axis {values.min():g} to {values.max():g} m: beyond "
                        "the grid MoorDyn holds the kinematics of its edge, kanat computes them everywhere")


def _current(reader) -> list[list[float]] | None:
    mode = _whole(reader, "currents", "Currents")
    if not mode:
        return None
    line = reader.option_lines["currents"]
    if mode != 1:
        reader.error(line, "OPTIONS.Currents", f"Currents = {mode}: only a steady profile (Currents 1, "
                     "current_profile.txt) can be imported; kanat's current does not vary in time or "
                     "along x and y: give environment.current in the YAML case instead")
        return None
    try:
        return read_current(reader.base / "current_profile.txt")
    except WaveFileError as error:
        _file_error(reader, "OPTIONS.Currents", error)
        return None
