"""The result schema: every output name, its dimensions, units and meaning (case-format.md).

One table, :data:`VARIABLES`, is the only place that knows the result names; the run
loop's observers (the streamed netCDF file of :mod:`kanat.io.stream`, the in-memory
recorder of :mod:`kanat.dynamics`) and the statics and pitch datasets of
:mod:`kanat.io.results` all take their dimensions, units and long names from it, so a
result held in memory and the same result read back from its file are the same
``xarray.Dataset``.

Coordinates: ``time`` (a dimension coordinate), ``s`` and ``cable`` along ``node``,
``segment_cable`` along ``segment``, ``xyz`` and ``body`` (names) — so that
``ds.tension.isel(time=-1).plot(x="s")`` draws tension against arclength.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Variable:
    """One result variable.

    Attributes
    ----------
    dims : tuple of str
        Dimensions, without ``time`` for the time series (the loop prepends it).
    units : str
        CF units string (``"1"`` for dimensionless).
    long_name : str
    standard_name : str or None
        CF standard name where one exists.
    positive : str or None
        ``"up"`` for positions and velocities, whose z axis points up (z = 0 at the mean surface).
    """

    dims: tuple[str, ...]
    units: str
    long_name: str
    standard_name: str | None = None
    positive: str | None = None

    def attrs(self) -> dict:
        """The variable's netCDF attributes."""
        out = {"units": self.units, "long_name": self.long_name}
        if self.standard_name:
            out["standard_name"] = self.standard_name
        if self.positive:
            out["positive"] = self.positive
        return out


VARIABLES: dict[str, Variable] = {
    # along the cables, time-independent
    "s": Variable(("node",), "m", "unstretched arclength within its cable"),
    "cable": Variable(("node",), "1", "cable name of each node"),
    "segment_cable": Variable(("segment",), "1", "cable name of each segment"),
    "segment_length": Variable(("segment",), "m", "unstretched segment length"),
    # the time series of the dynamic models (and statics without time)
    "position": Variable(("node", "xyz"), "m", "node positions (z up, z = 0 at the mean free surface)",
                         positive="up"),
    "velocity": Variable(("node", "xyz"), "m/s", "node velocities", positive="up"),
    "tension": Variable(("node",), "N", "effective tension at nodes"),
    "angle": Variable(("node",), "rad", "angle of the cable tangent above the horizontal"),
    "segment_tension": Variable(("segment",), "N", "element tension"),
    "body_position": Variable(("body", "xyz"), "m", "body positions", positive="up"),
    "vessel_position": Variable(("xyz",), "m", "tow point position", positive="up"),
    "vessel_heading": Variable((), "rad", "vessel heading, counter-clockwise from +x"),
    "vessel_pitch": Variable((), "rad", "vessel pitch, bow up positive"),
    "newton_iterations": Variable((), "1", "Newton iterations of the steps since the previous output"),
    "winch_tension": Variable((), "N", "effective tension at the winch (the first cable's 'from' end)"),
    "winch_length": Variable((), "m", "unstretched length of the first cable paid out from the winch "
                             "(its length in the water)"),
    # moorings (statics; the dynamic models may add time)
    "seabed_contact_length": Variable(("cable",), "m", "unstretched length of each cable resting on the seabed"),
    "anchor_force": Variable(("anchor", "xyz"), "N", "force of the line on each anchor, named by cable end "
                             "(uplift is its +z part)"),
    "body_force": Variable(("body", "xyz"), "N", "resultant force of the lines on each body"),
    "body_moment": Variable(("body", "xyz"), "N m", "moment of the lines' forces about each body's reference point"),
    "body_attitude": Variable(("body", "xyz"), "rad", "roll, pitch, yaw of each body (R = Rz(yaw) Ry(pitch) Rx(roll))"),
    "point_position": Variable(("point", "xyz"), "m", "network point positions"),
    "body_stiffness": Variable(("body", "dof", "dof_j"), "N/m, N/rad, N m/m, N m/rad",
                               "mooring stiffness at each body about its reference point, -dF/dq of the lines "
                               "with the other free nodes in equilibrium (statics)"),
    "coupled_stiffness": Variable(("coupled_dof", "coupled_dof_j"), "N/m, N/rad, N m/m, N m/rad",
                                  "mooring stiffness of several coupled bodies together (MoorPy's "
                                  "getCoupledStiffness), each body's surge, sway, heave, roll, pitch, yaw about "
                                  "its reference point, labelled body.dof (statics)"),
    "point_stiffness": Variable(("point", "xyz", "xyz_j"), "N/m",
                                "mooring stiffness at each network point, -dF/dx of the lines with the other "
                                "free nodes in equilibrium (statics)"),
    # snap events (lumped model), written once at the end of a run
    "event_time": Variable(("event",), "s", "time at which a slack element became taut"),
    "event_segment": Variable(("event",), "1", "segment index of the snap event"),
    "event_peak_tension": Variable(("event",), "N", "peak tension of the snap event"),
    "event_rise_rate": Variable(("event",), "N/s", "largest rate of rise of tension during the snap event"),
    # Naumov & Agievich (dimensionless statics)
    "alpha": Variable(("node",), "rad", "local cable angle of Naumov & Agievich (dX/ds = cos alpha)"),
    "tau": Variable(("node",), "1", "dimensionless tension T / (k1 L)"),
    "x": Variable(("node",), "1", "dimensionless abscissa X / L"),
    "y": Variable(("node",), "1", "dimensionless height Y / L"),
    "sigma": Variable(("node",), "1", "dimensionless arclength S / L from A"),
    # Gaisha (pitch)
    "pitch": Variable(("mode", "time"), "rad", "steady pitch angle over one period, bow up positive"),
    "stabilizer_moment": Variable(("mode", "time"), "N m", "stabilizer moment, 0 <= f <= M0"),
    "wave_moment": Variable(("time",), "N m", "wave moment M_m sin(omega t + pi)"),
    "amplitude": Variable(("mode",), "rad", "pitch amplitude, half the peak-to-peak"),
    "max_abs": Variable(("mode",), "rad", "largest absolute pitch"),
    "mean_pitch": Variable(("mode",), "rad", "period mean of the pitch (trim)"),
    "amplitude_reduction": Variable(("mode",), "1", "amplitude without stabilizer / amplitude of the mode"),
    "max_abs_reduction": Variable(("mode",), "1", "largest |pitch| without stabilizer / that of the mode"),
    "fourier_vs_shooting": Variable(("mode",), "1", "max |pitch_fourier - pitch_shooting| / amplitude"),
}
"""Every result variable by name."""

TIME_COORD = Variable(("time",), "s", "simulated time", standard_name="time")
NODE_COORDS = ("s", "cable")
"""Non-index coordinates along ``node`` (CF ``coordinates`` attribute of node variables)."""
SEGMENT_COORDS = ("segment_cable",)
COORDINATE_NAMES = frozenset(NODE_COORDS + SEGMENT_COORDS)
LABELS = {"xyz": ("x", "y", "z")}
"""Fixed labels of label dimensions."""


def attributes(name: str, dims: tuple[str, ...]) -> dict:
    """netCDF attributes of variable ``name`` with dimensions ``dims``: units, long name, and
    the CF ``coordinates`` it is to be read with."""
    known = VARIABLES.get(name)
    out = known.attrs() if known is not None else {}
    coords = [c for d, cs in (("node", NODE_COORDS), ("segment", SEGMENT_COORDS)) if d in dims
              for c in cs if c != name]
    if coords and name not in COORDINATE_NAMES:
        out["coordinates"] = " ".join(coords)
    return out


def time_dims(name: str) -> tuple[str, ...]:
    """Dimensions of time variable ``name`` in a result (``time`` first)."""
    return ("time",) + VARIABLES[name].dims


def netcdf_attr(value):
    """An attribute value netCDF can hold: numbers and strings only."""
    if isinstance(value, bool):
        return int(value)
    if value is None:
        return ""
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    if isinstance(value, (list, tuple)) and not value:
        return ""
    return value


def text_array(values) -> np.ndarray:
    """Names as a NumPy unicode array (what xarray reads back from a netCDF string variable)."""
    values = list(values)
    return np.array(values, dtype=str) if values else np.zeros(0, dtype="<U1")


@dataclass(frozen=True)
class Layout:
    """What a dynamic result holds before its first time step.

    Attributes
    ----------
    static : dict of str to (tuple of str, ndarray)
        Time-independent variables: ``name -> (dims, values)`` (``s``, ``cable``, ...).
    labels : dict of str to ndarray
        Label dimensions and their names (``xyz``, ``body``): dimension coordinates.
    time_variables : tuple of str
        Names (of :data:`VARIABLES`) of the time series, one slice per output.
    attrs : dict
        Global attributes (provenance; ``status`` is set by the run).
    """

    static: dict
    labels: dict
    time_variables: tuple
    attrs: dict

    def sizes(self) -> dict[str, int]:
        """Size of every dimension the static variables and labels define."""
        out = {name: len(values) for name, values in self.labels.items()}
        for dims, values in self.static.values():
            out.update(zip(dims, np.shape(values)))
        return out


def to_dataset(layout: Layout, times, series: dict, final: dict | None = None, attrs: dict | None = None):
    """An ``xarray.Dataset`` of a result held in memory, laid out as its netCDF file.

    Parameters
    ----------
    layout : Layout
    times : array_like, shape (k,)
        Output times [s].
    series : dict of str to ndarray
        Each time variable stacked over the outputs, shape ``(k, ...)``.
    final : dict of str to (tuple of str, ndarray), optional
        Variables written once at the end (snap events).
    attrs : dict, optional
        Global attributes added at the end (status, timings).
    """
    import xarray as xr

    coords = {"time": ("time", np.asarray(times, float), TIME_COORD.attrs())}
    coords.update({name: (name, text_array(values)) for name, values in layout.labels.items()})
    data = {}
    for name, (dims, values) in layout.static.items():
        values = text_array(values) if name in ("cable", "segment_cable") else np.asarray(values)
        target = coords if name in COORDINATE_NAMES else data
        target[name] = (dims, values, attributes(name, dims))
    for name in layout.time_variables:
        dims = time_dims(name)
        data[name] = (dims, np.asarray(series[name], float), attributes(name, dims))
    for name, (dims, values) in (final or {}).items():
        data[name] = (dims, np.asarray(values), attributes(name, dims))
    ds = xr.Dataset(data, coords=coords)
    ds.attrs = {k: netcdf_attr(v) for k, v in {**layout.attrs, **(attrs or {})}.items()}
    for name, var in ds.variables.items():
        if "coordinates" in var.attrs:                 # held as coordinates in memory, as xarray reads files
            del var.attrs["coordinates"]
    return ds
