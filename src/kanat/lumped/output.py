"""The lumped model's result file (case-format.md): static variables, output slices and the
snap events.

Node tension (``tension(time, node)``) is the mean of the two adjacent element tensions
at interior nodes, and extrapolated linearly from the first two elements at cable ends
(``1.5 T_0 - 0.5 T_1``, clipped at 0), second-order accurate like the elements' own
midpoint values. Snap events are written at close on an unlimited ``event`` dimension:
``event_time``, ``event_segment``, ``event_peak_tension``, ``event_rise_rate``.
"""
from __future__ import annotations

import h5netcdf
import numpy as np
import xarray as xr

TIME_VARS = {
    "position": (("node", "xyz"), "m"),
    "velocity": (("node", "xyz"), "m/s"),
    "tension": (("node",), "N"),
    "segment_tension": (("segment",), "N"),
    "body_position": (("body", "xyz"), "m"),
    "vessel_position": (("xyz",), "m"),
    "vessel_heading": ((), "rad"),
}
EVENT_VARS = {
    "event_time": ("s", "time at which a slack element became taut"),
    "event_segment": ("1", "segment index of the snap event"),
    "event_peak_tension": ("N", "peak tension of the snap event"),
    "event_rise_rate": ("N/s", "largest rate of rise of tension during the snap event"),
}


class NodeTension:
    """Weights mapping element tensions to the output nodes (module docstring)."""

    def __init__(self, net):
        ia, ib, wa, wb = [], [], [], []
        for c, first in enumerate(net.cable_first_element):
            n = int(np.count_nonzero(net.segment_cable == net.cable_names[c]))
            e = first + np.arange(n)
            if n == 1:
                ia += [e[0], e[0]]
                ib += [e[0], e[0]]
                wa += [1.0, 1.0]
                wb += [0.0, 0.0]
                continue
            ia += [e[0], *e[:-1], e[-1]]
            ib += [e[1], *e[1:], e[-2]]
            wa += [1.5, *([0.5] * (n - 1)), 1.5]
            wb += [-0.5, *([0.5] * (n - 1)), -0.5]
        self.ia, self.ib = np.array(ia, np.int64), np.array(ib, np.int64)
        self.wa, self.wb = np.array(wa), np.array(wb)

    def __call__(self, T: np.ndarray) -> np.ndarray:
        return np.maximum(0.0, self.wa * T[self.ia] + self.wb * T[self.ib])


def static_dataset(net, attrs: dict) -> xr.Dataset:
    """Time-independent variables of the result."""
    return xr.Dataset(
        {"s": ("node", net.node_s), "cable": ("node", net.node_cable.astype(str).astype(object)),
         "segment_cable": ("segment", net.segment_cable.astype(str).astype(object),
                           {"units": "1", "long_name": "cable name of each segment"}),
         "segment_length": ("segment", net.el_length, {"units": "m", "long_name": "unstretched length"})},
        coords={"xyz": ["x", "y", "z"], "body": np.array(net.body_names, dtype=object)},
        attrs=attrs)


def output_slice(net, node_tension, x, v, T, vessel_position, heading) -> dict:
    """One output slice of :data:`TIME_VARS` from all nodes' ``x, v`` and element ``T``."""
    idx = net.node_index
    return {"position": x[idx], "velocity": v[idx], "tension": node_tension(T), "segment_tension": T,
            "body_position": x[net.body_node].reshape(-1, 3), "vessel_position": vessel_position,
            "vessel_heading": heading}


def write_events(path, events: dict) -> None:
    """Write the snap events to an (already closed) result file, replacing earlier ones."""
    n = len(events["time"])
    names = {"event_time": "time", "event_segment": "element", "event_peak_tension": "peak_tension",
             "event_rise_rate": "rise_rate"}
    with h5netcdf.File(path, "a") as f:
        if "event" not in f.dimensions:
            f.dimensions["event"] = None
            for var, (units, long_name) in EVENT_VARS.items():
                dtype = "i8" if var == "event_segment" else "f8"
                created = f.create_variable(var, ("event",), dtype)
                created.attrs["units"], created.attrs["long_name"] = units, long_name
        f.resize_dimension("event", n)
        for var, key in names.items():
            if n:
                f.variables[var][:] = events[key]
        f.attrs["snap_events"] = n
