"""Result datasets (xarray) and their netCDF files: the output contract of case-format.md.

The only place that knows the result variable names, units and attributes. Solvers
return typed results; these functions turn them into ``xarray.Dataset`` objects and
back to disk (h5netcdf).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from kanat.errors import KanatError
from kanat.io.provenance import case_sha256, case_yaml, provenance  # noqa: F401 - their home is provenance
from kanat.io.result_table import write_netcdf
from kanat.io.schema import COORDINATE_NAMES, VARIABLES


def annotate(ds: xr.Dataset) -> xr.Dataset:
    """Attach units and long names (:data:`kanat.io.schema.VARIABLES`) to every known variable,
    make ``s``, ``cable`` and ``segment_cable`` coordinates, and label ``xyz``."""
    for name, var in ds.variables.items():
        if name in VARIABLES:
            for key, value in VARIABLES[name].attrs().items():
                var.attrs.setdefault(key, value)
    ds = ds.set_coords([name for name in COORDINATE_NAMES if name in ds.data_vars])
    if "xyz" in ds.dims and "xyz" not in ds.coords:
        ds = ds.assign_coords(xyz=["x", "y", "z"])
    return ds


def write_result(ds: xr.Dataset, path) -> Path:
    """Write a result dataset to netCDF, atomically.

    The file is written next to its destination and renamed, so a crash never leaves a
    half-written result where a complete one is expected. It is written with h5netcdf
    directly (:func:`kanat.io.result_table.write_netcdf`), as :class:`kanat.io.stream.ResultStream`
    writes a run's file (xarray's own writer asks dask for a scheduler, which costs a quarter
    of a second of imports), and reads back with :func:`read_result` as the same dataset:
    non-index coordinates are named in each variable's CF ``coordinates`` attribute.
    """
    variables = ((name, var.dims, var.values, var.attrs) for name, var in ds.variables.items())
    return write_netcdf(path, dict(ds.sizes), variables, list(ds.coords), ds.attrs)


SOUND_VARIABLES = ("time", "position", "velocity", "tension", "segment_tension", "body_position")
"""Variables that are finite in every sound result (others may hold NaN by design: "not computed")."""


def read_result(path) -> xr.Dataset:
    """Read a result file (fully loaded, file closed).

    Raises
    ------
    kanat.errors.KanatError
        For a missing or unreadable file, and for a file whose ``status`` is ``ok`` although
        one of :data:`SOUND_VARIABLES` holds a non-finite value: such a file cannot be a
        sound result (``xarray.open_dataset`` still opens it for inspection).
    """
    path = Path(path)
    try:
        with xr.open_dataset(path, engine="h5netcdf") as ds:
            ds = ds.load()
    except FileNotFoundError:
        raise KanatError(f"{path}: no such result file") from None
    except OSError as error:
        raise KanatError(f"{path}: not a readable result file ({error})") from None
    if ds.attrs.get("status") == "ok":
        for name in SOUND_VARIABLES:
            if name in ds and ds[name].size and not np.all(np.isfinite(ds[name].values)):
                raise KanatError(f"{path} says status ok but its {name} holds non-finite values: it is not a "
                                 "sound result (the file was altered, or written by a faulty tool)")
    return ds


def statics_dataset(result, wall_time_s: float = 0.0) -> xr.Dataset:
    """The result of a statics run as a dataset (case-format.md: the dynamic names, no ``time``):
    :func:`kanat.io.statics_table.statics_table`, the table ``kanat statics`` writes.

    Parameters
    ----------
    result : kanat.statics.StaticsResult
    wall_time_s : float
        Solve time recorded in the provenance [s].
    """
    from kanat.io.statics_table import statics_table

    return statics_table(result, wall_time_s).to_dataset()


def failed_dataset(case, message: str, model: str = "statics", scheme: str = "", wall_time_s: float = 0.0):
    """A result holding no solution, only the provenance and ``status`` saying why."""
    from kanat.io.statics_table import failed_table

    return failed_table(case, message, model, scheme, wall_time_s).to_dataset()


def pitch_dataset(result, case, wall_time_s: float = 0.0) -> xr.Dataset:
    """The result file of a pitch run (case-format.md; theory/vessel.md §2, Gaisha).

    Variables ``pitch(mode, time)``, ``stabilizer_moment(mode, time)``, ``amplitude(mode)``,
    ``max_abs(mode)`` of the case format, and ``wave_moment(time)``, ``mean_pitch(mode)``,
    the reductions against ``off`` and the Fourier-vs-shooting difference (NaN where a
    mode has one path only).

    Parameters
    ----------
    result : kanat.vessel.PitchResult
    case : kanat.model.Case
    wall_time_s : float
        Solve time recorded in the provenance [s].
    """
    from kanat.model.problems import RESONANCE_RTOL

    modes = list(result.responses)
    rows = [result.responses[m] for m in modes]
    system = result.system
    time = rows[0].time
    has_off = "off" in result.responses

    def reduction(metric):
        return [result.reduction(m, metric) if has_off else np.nan for m in modes]
    attrs = provenance(case, model="pitch", scheme="fourier+shooting", wall_time_s=wall_time_s, status="ok",
                       inertia_kg_m2=system.inertia, natural_frequency_rad_s=system.natural_frequency,
                       wave_frequency_rad_s=system.wave_frequency, wave_period_s=system.period,
                       wave_moment_amplitude_N_m=system.wave_moment_amplitude,
                       damping_ratio=system.damping_ratio, max_moment_N_m=result.max_moment,
                       harmonics=result.harmonics, resonance_rtol=RESONANCE_RTOL,
                       **{f"method_{m}": r.method for m, r in zip(modes, rows)})
    ds = xr.Dataset(
        {
            "pitch": (("mode", "time"), np.array([r.pitch for r in rows])),
            "stabilizer_moment": (("mode", "time"), np.array([r.moment for r in rows])),
            "wave_moment": ("time", system.wave_moment(time)),
            "amplitude": ("mode", [r.amplitude for r in rows]),
            "max_abs": ("mode", [r.max_abs for r in rows]),
            "mean_pitch": ("mode", [r.mean for r in rows]),
            "amplitude_reduction": ("mode", reduction("amplitude")),
            "max_abs_reduction": ("mode", reduction("max_abs")),
            "fourier_vs_shooting": ("mode", [result.agreement.get(m, np.nan) for m in modes]),
        },
        coords={"mode": ("mode", np.array(modes, dtype=object), {"long_name": "stabilizer control mode"}),
                "time": ("time", time, {"units": "s", "long_name": "time within one steady wave period"})},
        attrs=attrs,
    )
    _say_not_applicable(ds, "amplitude_reduction", "max_abs_reduction",
                        why="the reduction compares a mode with 'off', which was not among the modes solved")
    _say_not_applicable(ds, "fourier_vs_shooting",
                        why="the mode was solved one way only (a feedback law has no open-loop shooting "
                            "twin), so there is no difference to measure")
    return annotate(ds)


def _say_not_applicable(ds: xr.Dataset, *names: str, why: str) -> None:
    """Name the modes where ``names`` hold NaN, and why, in their attributes (CF ``comment``)."""
    for name in names:
        missing = [str(m) for m, value in zip(ds["mode"].values, ds[name].values) if np.isnan(value)]
        if missing:
            ds[name].attrs["comment"] = f"NaN means not applicable: {why}"
            ds[name].attrs["not_applicable_modes"] = ", ".join(missing)
