"""The statics result (case-format.md: the dynamic names, no ``time``) as a :class:`ResultTable`.

``kanat statics`` writes this table to its file directly; :func:`kanat.io.results.statics_dataset`
(the Python API's ``xarray.Dataset``) is the same table through :meth:`ResultTable.to_dataset`,
so the file and the dataset hold the same names, dimensions, attributes and values.
"""
from __future__ import annotations

import numpy as np

from kanat.io.provenance import provenance
from kanat.io.result_table import ResultTable
from kanat.io.schema import COORDINATE_NAMES, VARIABLES

XYZ = ("x", "y", "z")
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


def _names(values) -> np.ndarray:
    """Labels as an object array of ``str`` (how netCDF strings read back)."""
    out = np.empty(len(values), dtype=object)
    out[:] = list(values)
    return out


def _known(name: str, dims: tuple, values, attrs: dict | None = None) -> tuple:
    """``(dims, values, attrs)`` with the units and long name of :data:`VARIABLES` (``attrs`` first)."""
    known = VARIABLES[name].attrs() if name in VARIABLES else {}
    return tuple(dims), values, {**(attrs or {}), **{k: v for k, v in known.items() if k not in (attrs or {})}}


def _label(name: str, values) -> tuple:
    return (name,), _names(values), {}


def statics_table(result, wall_time_s: float = 0.0, status: str = "ok", warnings=()) -> ResultTable:
    """The result file of a statics run.

    Parameters
    ----------
    result : kanat.statics.StaticsResult or kanat.statics.network_result.NetworkResult
    wall_time_s : float
        Solve time recorded in the provenance [s].
    status : str
        ``ok``, or ``failed: <check>: ...`` for a solution that fails the checks of a steady
        state (:mod:`kanat.statics.steady_checks`): written all the same, to show what went wrong.
    warnings : sequence of str
        The checks' warnings (a tension above the breaking load), kept one a line in the
        ``warnings`` attribute when there are any.
    """
    attrs = provenance(result.case, model="statics", scheme=result.method, wall_time_s=wall_time_s, status=status)
    if warnings:
        attrs["warnings"] = "\n".join(warnings)
    if getattr(result, "notes", ()):                           # network statics: friction on anchors, ...
        attrs["notes"] = "; ".join(result.notes)
    if result.sphere is not None:
        return _sphere_table(result.sphere, attrs)
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
    placed = {**result.bodies, **getattr(result, "coupled_bodies", {})}     # free, then coupled bodies
    bodies = list(placed)
    v = {
        "position": _known("position", ("node", "xyz"), position),
        "velocity": _known("velocity", ("node", "xyz"), np.tile(result.vessel_velocity, (len(position), 1))),
        "tension": _known("tension", ("node",), np.concatenate(tension)),
        "angle": _known("angle", ("node",), np.concatenate(angle)),
        "body_position": _known("body_position", ("body", "xyz"),
                                np.array([placed[b] for b in bodies]).reshape(-1, 3)),
        "vessel_position": _known("vessel_position", ("xyz",),
                                  np.asarray(result.case.vessel.tow_point, dtype=float)),
        "vessel_heading": _known("vessel_heading", (), np.array(0.0)),
        "body": _label("body", bodies),
        "s": _known("s", ("node",), np.concatenate(s)),
        "cable": _known("cable", ("node",), _names(names)),        # along node, as in the dynamic results
        "xyz": _label("xyz", XYZ),
    }
    v.update(_mooring_variables(result, bodies))
    return ResultTable(v, tuple(n for n in v if n in COORDINATE_NAMES or v[n][0] == (n,)), attrs)


def _forces(values, rows: int, *shape: int) -> np.ndarray:
    return np.asarray(values, dtype=float).reshape((rows, *shape))


def _mooring_variables(result, bodies: list) -> dict:
    """Statics results of moorings (case-format.md): seabed contact, forces on anchors and
    bodies, and, from network statics, body attitudes and moments, points and stiffness."""
    cables = list(result.cables)
    anchors = dict(getattr(result, "anchor_forces", {}))
    forces = getattr(result, "body_forces", {})
    out = {
        "seabed_contact_length": _known("seabed_contact_length", ("cable",),       # in the cables' order
                                        np.array([result.cables[c].grounded_length for c in cables], dtype=float)),
        "anchor": _label("anchor", anchors),
        "anchor_force": _known("anchor_force", ("anchor", "xyz"),
                               _forces([anchors[a] for a in anchors], len(anchors), 3)),
        "body_force": _known("body_force", ("body", "xyz"),
                             _forces([forces.get(b, np.zeros(3)) for b in bodies], len(bodies), 3)),
    }
    if not hasattr(result, "attitudes"):
        return out
    located = {**result.points, **getattr(result, "coupled_points", {})}     # free, then coupled points
    points = list(located)
    out.update({
        "body_moment": _known("body_moment", ("body", "xyz"),
                              _forces([result.body_moments.get(b, np.zeros(3)) for b in bodies], len(bodies), 3)),
        "body_attitude": _known("body_attitude", ("body", "xyz"),
                                _forces([result.attitudes.get(b, np.zeros(3)) for b in bodies], len(bodies), 3)),
        "point": _label("point", points),
        "point_position": _known("point_position", ("point", "xyz"),
                                 _forces([located[p] for p in points], len(points), 3)),
    })
    if result.stiffness:                                  # the catenary network's, not the fallback's
        out.update({
            "dof": _label("dof", DOFS),
            "dof_j": _label("dof_j", DOFS),
            "body_stiffness": _known("body_stiffness", ("body", "dof", "dof_j"),
                                     _forces([result.stiffness[b] for b in bodies], len(bodies), 6, 6)),
            "xyz_j": _label("xyz_j", XYZ),
            "point_stiffness": _known("point_stiffness", ("point", "xyz", "xyz_j"),
                                      _forces([result.stiffness[p] for p in points], len(points), 3, 3)),
        })
    matrix = getattr(result, "coupled_matrix", None)
    if matrix is not None:
        labels = [f"{b}.{d}" for b in result.coupled_bodies for d in DOFS]
        out.update({"coupled_dof": _label("coupled_dof", labels), "coupled_dof_j": _label("coupled_dof_j", labels),
                    "coupled_stiffness": _known("coupled_stiffness", ("coupled_dof", "coupled_dof_j"), matrix)})
    return out


def _sphere_table(sol, attrs: dict) -> ResultTable:
    """The Naumov & Agievich problem (theory/statics.md §3): dimensionless shape and tension, and with its scales the
    dimensional ones."""
    attrs.update(alpha0_deg=float(np.degrees(sol.alpha0)), tau0=float(sol.tau0),
                 eps1_percent=float(sol.eps1_percent), eps2_percent=float(sol.eps2_percent),
                 convention=sol.convention, method=sol.method, line_tension_tau=float(sol.tau_line),
                 physical_warnings="; ".join(sol.physical_warnings),
                 **{f"group_{k}": float(v) for k, v in vars(sol.groups).items()})
    v = {name: _known(name, ("node",), np.asarray(values, dtype=float))
         for name, values in (("alpha", sol.alpha), ("tau", sol.tau), ("x", sol.x), ("y", sol.y))}
    v["sigma"] = _known("sigma", ("node",), np.asarray(sol.sigma, dtype=float),
                        {"units": "1", "long_name": "dimensionless arclength S / L from A"})
    if sol.scales is not None:
        v["s"] = _known("s", ("node",), np.asarray(sol.s, dtype=float))
        v["tension"] = _known("tension", ("node",), np.asarray(sol.T, dtype=float))
        v["position"] = _known("position", ("node", "xyz"), np.column_stack([sol.X, np.zeros_like(sol.X), sol.Y]))
        v["cable"] = _known("cable", ("node",), _names(["AOB"] * len(sol.s)))
        v["xyz"] = _label("xyz", XYZ)
        attrs.update(k1_N_per_m=sol.scales.k1, cable_length_m=sol.scales.L, line_tension_N=float(sol.T_line))
    return ResultTable(v, tuple(n for n in v if n in COORDINATE_NAMES or v[n][0] == (n,)), attrs)


def failed_table(case, message: str, model: str = "statics", scheme: str = "", wall_time_s: float = 0.0):
    """A result holding no solution, only the provenance and ``status`` saying why."""
    return ResultTable({}, (), provenance(case, model=model, scheme=scheme, wall_time_s=wall_time_s,
                                          status=f"failed: {message}"))
