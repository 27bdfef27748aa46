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
from kanat.io.schema import COORDINATE_NAMES, VARIABLES, netcdf_attr


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
    directly, as :class:`kanat.io.stream.ResultStream` writes a run's file (xarray's own
    writer asks dask for a scheduler, which costs a quarter of a second of imports), and
    reads back with :func:`read_result` as the same dataset: non-index coordinates are
    named in each variable's CF ``coordinates`` attribute.
    """
    import h5netcdf

    from kanat.io.outputs import atomic_path

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    extra = [name for name in ds.coords if name not in ds.dims]
    with atomic_path(path) as tmp, h5netcdf.File(tmp, "w") as f:
        f.dimensions = dict(ds.sizes)
        for name, var in ds.variables.items():
            values = np.asarray(var.values)
            text = values.dtype.kind in "OUS"
            created = f.create_variable(name, var.dims, dtype=_string_dtype() if text else values.dtype)
            if values.size:
                created[...] = values.astype(object) if text else values
            attrs = {k: netcdf_attr(v) for k, v in var.attrs.items()}
            near = [c for c in extra if c != name and set(ds[c].dims) <= set(var.dims) and ds[c].dims]
            if near and name not in ds.coords:
                attrs["coordinates"] = " ".join(near)
            created.attrs.update(attrs)
        f.attrs.update({k: netcdf_attr(v) for k, v in ds.attrs.items()})
    return path


def _string_dtype():
    import h5py

    return h5py.string_dtype()


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
    """The result file of a statics run (case-format.md: the dynamic names, no ``time``).

    Parameters
    ----------
    result : kanat.statics.StaticsResult
    wall_time_s : float
        Solve time recorded in the provenance [s].
    """
    attrs = provenance(result.case, model="statics", scheme=result.method, wall_time_s=wall_time_s, status="ok")
    if result.sphere is not None:
        return annotate(_sphere_dataset(result.sphere, attrs))
    names, s, position, tension, angle = [], [], [], [], []
    for name, sol in result.cables.items():
        names += [name] * len(sol.s)
        s.append(sol.s)
        position.append(sol.position)
        tension.append(sol.tension)
        angle.append(sol.angle)
        attrs[f"method_{name}"] = sol.method
        attrs[f"grounded_length_{name}_m"] = sol.grounded_length
    position = np.concatenate(position)
    bodies = list(result.bodies)
    ds = xr.Dataset(
        {
            "position": (("node", "xyz"), position),
            "velocity": (("node", "xyz"), np.tile(result.vessel_velocity, (len(position), 1))),
            "tension": ("node", np.concatenate(tension)),
            "angle": ("node", np.concatenate(angle)),
            "body_position": (("body", "xyz"), np.array([result.bodies[b] for b in bodies]).reshape(-1, 3)),
            "vessel_position": ("xyz", np.asarray(result.case.vessel.tow_point, dtype=float)),
            "vessel_heading": ((), 0.0),
        },
        coords={"body": np.array(bodies, dtype=object), "s": ("node", np.concatenate(s)),
                "cable": ("node", np.array(names, dtype=object))},       # along node, as in the dynamic results
        attrs=attrs,
    )
    return annotate(ds.assign(_mooring_variables(result, bodies)))


def _mooring_variables(result, bodies: list) -> dict:
    """Statics results of moorings (case-format.md): seabed contact, forces on anchors and
    bodies, and, from network statics, body attitudes and moments, points and stiffness."""
    from kanat.io.schema import VARIABLES

    def var(name, dims, values, **coords):
        return xr.DataArray(np.asarray(values, dtype=float).reshape([len(c) for c in coords.values()] or []),
                            dims=dims, coords={k: np.array(v, dtype=object) for k, v in coords.items()},
                            attrs=VARIABLES[name].attrs())
    xyz = {"xyz": ["x", "y", "z"]}
    cables = list(result.cables)
    out = {"seabed_contact_length": xr.DataArray(        # dimension 'cable' in the cables' order
        np.array([result.cables[c].grounded_length for c in cables], dtype=float), dims="cable",
        attrs=VARIABLES["seabed_contact_length"].attrs())}
    anchors = dict(getattr(result, "anchor_forces", {}))
    out["anchor_force"] = var("anchor_force", ("anchor", "xyz"), [anchors[a] for a in anchors],
                              anchor=list(anchors), **xyz)
    forces = getattr(result, "body_forces", {})
    out["body_force"] = var("body_force", ("body", "xyz"), [forces.get(b, np.zeros(3)) for b in bodies],
                            body=bodies, **xyz)
    if hasattr(result, "attitudes"):
        out["body_moment"] = var("body_moment", ("body", "xyz"), [result.body_moments.get(b, np.zeros(3))
                                                                 for b in bodies], body=bodies, **xyz)
        out["body_attitude"] = var("body_attitude", ("body", "xyz"), [result.attitudes[b] for b in bodies],
                                   body=bodies, **xyz)
        points = list(result.points)
        out["point_position"] = var("point_position", ("point", "xyz"), [result.points[p] for p in points],
                                    point=points, **xyz)
        if result.stiffness:                                  # the catenary network's, not the fallback's
            dofs = ["surge", "sway", "heave", "roll", "pitch", "yaw"]
            out["body_stiffness"] = var("body_stiffness", ("body", "dof", "dof_j"),
                                        [result.stiffness[b] for b in bodies], body=bodies, dof=dofs, dof_j=dofs)
            out["point_stiffness"] = var("point_stiffness", ("point", "xyz", "xyz_j"),
                                         [result.stiffness[p] for p in points], point=points,
                                         xyz_j=xyz["xyz"], **xyz)
    return out


def _sphere_dataset(sol, attrs: dict) -> xr.Dataset:
    attrs.update(alpha0_deg=float(np.degrees(sol.alpha0)), tau0=float(sol.tau0),
                 eps1_percent=float(sol.eps1_percent), eps2_percent=float(sol.eps2_percent),
                 convention=sol.convention, method=sol.method, line_tension_tau=float(sol.tau_line),
                 physical_warnings="; ".join(sol.physical_warnings),
                 **{f"group_{k}": float(v) for k, v in vars(sol.groups).items()})
    data = {"alpha": ("node", sol.alpha), "tau": ("node", sol.tau), "x": ("node", sol.x), "y": ("node", sol.y),
            "sigma": ("node", sol.sigma, {"units": "1", "long_name": "dimensionless arclength S / L from A"})}
    if sol.scales is not None:
        xyz = np.column_stack([sol.X, np.zeros_like(sol.X), sol.Y])
        data.update(s=("node", sol.s), tension=("node", sol.T), position=(("node", "xyz"), xyz),
                    cable=("node", np.array(["AOB"] * len(sol.s), dtype=object)))
        attrs.update(k1_N_per_m=sol.scales.k1, cable_length_m=sol.scales.L, line_tension_N=float(sol.T_line))
    return xr.Dataset(data, attrs=attrs)


def failed_dataset(case, message: str, model: str = "statics", scheme: str = "", wall_time_s: float = 0.0):
    """A result holding no solution, only the provenance and ``status`` saying why."""
    return xr.Dataset(attrs=provenance(case, model=model, scheme=scheme, wall_time_s=wall_time_s,
                                       status=f"failed: {message}"))


def pitch_dataset(result, case, wall_time_s: float = 0.0) -> xr.Dataset:
    """The result file of a pitch run (case-format.md; SPEC §6.2, seed 003).

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
    return annotate(ds)
