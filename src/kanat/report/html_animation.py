"""The animated 3-D view of a dynamic result: cables, bodies, the vessel and its track.

The page gets at most :data:`MAX_FRAMES` evenly spaced output times and at most
:data:`MAX_NODES` nodes per frame (every cable keeps its two ends; interior nodes are
thinned evenly), as float32 arrays in base64. A small script (``templates/player.js``)
replaces the traces' coordinates with ``Plotly.restyle`` on play and on the slider, and
keeps the frame shown in the plot's ``data-frame`` attribute.
"""
from __future__ import annotations

import base64

import numpy as np
import xarray as xr

from kanat.analysis.select import cable_names
from kanat.report.html import macros, plot_text

MAX_FRAMES = 200
MAX_NODES = 3000
MAX_TRACK = 2000
FRAME_MS = 100
"""Frames per second of playback: 1000 / FRAME_MS."""


def _b64(array: np.ndarray) -> str:
    return base64.b64encode(np.ascontiguousarray(array, dtype="<f4").tobytes()).decode("ascii")


def thin(count: int, keep: int) -> np.ndarray:
    """At most ``keep`` (>= 2) evenly spaced indices of ``range(count)``, both ends included."""
    if count <= keep:
        return np.arange(count)
    return np.unique(np.linspace(0, count - 1, max(keep, 2)).round().astype(int))


def animation_data(ds: xr.Dataset, plot_id: str, max_frames: int = MAX_FRAMES, max_nodes: int = MAX_NODES) -> dict:
    """What the player needs: thinned frames and nodes as base64 float32, axis ranges, the trace layout."""
    frames = thin(ds.sizes["time"], max_frames)
    cable_of = ds["cable"].values
    per_cable = max(2, max_nodes // max(1, len(cable_names(ds))))
    cables, index = [], []
    for name in cable_names(ds):
        nodes = np.flatnonzero(cable_of == name)
        kept = nodes[thin(len(nodes), per_cable)]
        cables.append({"name": name, "count": int(len(kept))})
        index.append(kept)
    index = np.concatenate(index)
    positions = ds["position"].values[frames][:, index]
    n_bodies = ds.sizes.get("body", 0)
    bodies = ds["body_position"].values[frames] if n_bodies else np.zeros((len(frames), 0, 3))
    vessel = ds["vessel_position"].values
    moving = len(cables) + (1 if n_bodies else 0)
    return {"plot": plot_id, "times": ds["time"].values[frames].round(6).tolist(), "nodes": int(len(index)),
            "cables": cables, "n_bodies": int(n_bodies), "positions": _b64(positions), "bodies": _b64(bodies),
            "vessel": _b64(vessel[frames]), "track": _b64(vessel[thin(len(vessel), MAX_TRACK)]),
            "interval_ms": FRAME_MS, "traces": list(range(moving + 2)),
            "earth_ranges": axis_ranges(ds, follow=False), "follow_ranges": axis_ranges(ds, follow=True)}


def _points(ds: xr.Dataset, follow: bool) -> np.ndarray:
    """Every cable node, body and tow point position over the run, relative to the vessel when following."""
    vessel = ds["vessel_position"].values
    groups = [ds["position"].values] + ([ds["body_position"].values] if ds.sizes.get("body", 0) else [])
    groups.append(vessel[:, None, :])
    if follow:
        shift = np.concatenate([vessel[:, :2], np.zeros((len(vessel), 1))], axis=1)[:, None, :]
        groups = [g - shift for g in groups]
    return np.concatenate([g.reshape(-1, 3) for g in groups])


def axis_ranges(ds: xr.Dataset, follow: bool) -> list:
    """x and y ranges and the aspect ratio of the scene (z keeps its range; true to scale up to 5:1)."""
    points = _points(ds, follow)
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.maximum(hi - lo, 1e-3)
    pad = 0.05 * span.max()
    ratio = np.maximum(span / span.max(), 0.2)
    return [[float(lo[0] - pad), float(hi[0] + pad)], [float(lo[1] - pad), float(hi[1] + pad)],
            dict(zip("xyz", map(float, ratio)))]


def follows_by_default(ds: xr.Dataset) -> bool:
    """Follow the vessel when it travels more than twice the size of the network around it."""
    vessel = ds["vessel_position"].values[:, :2]
    travel = float(np.ptp(vessel, axis=0).max()) if len(vessel) else 0.0
    relative = _points(ds, follow=True)[:, :2]
    return travel > 2.0 * float(np.ptp(relative, axis=0).max())


def _scene(ds: xr.Dataset) -> dict:
    """Fixed axis ranges over the whole run, so the view never jumps (earth frame)."""
    x, y, ratio = axis_ranges(ds, follow=False)
    z = _points(ds, follow=False)[:, 2]
    pad = 0.05 * max(float(np.ptp(z)), 1e-3)
    ranges = {"x": x, "y": y, "z": [float(z.min() - pad), float(z.max() + pad)]}
    axes = {f"{a}axis": {"range": ranges[a], "title": {"text": f"{a} [m]"}} for a in "xyz"}
    return {**axes, "aspectmode": "manual", "aspectratio": ratio,
            "camera": {"eye": {"x": 0.15, "y": -1.25, "z": 0.45}}}


def animation_figure(ds: xr.Dataset):
    """The 3-D figure at the first output time (the player moves it)."""
    import plotly.graph_objects as go

    fig = go.Figure()
    cable_of, x = ds["cable"].values, ds["position"].values[0]
    for k, name in enumerate(cable_names(ds)):
        p = x[cable_of == name]
        fig.add_trace(go.Scatter3d(x=p[:, 0], y=p[:, 1], z=p[:, 2], mode="lines", name=plot_text(f"cable {name}"),
                                   line={"width": 5, "color": f"hsl({(210 + 67 * k) % 360},60%,35%)"}))
    if ds.sizes.get("body", 0):
        b = ds["body_position"].values[0]
        fig.add_trace(go.Scatter3d(x=b[:, 0], y=b[:, 1], z=b[:, 2], mode="markers+text", name="bodies",
                                   text=[plot_text(n) for n in ds["body"].values], marker={"size": 5, "color": "#d95f02"}))
    v = ds["vessel_position"].values
    fig.add_trace(go.Scatter3d(x=v[:1, 0], y=v[:1, 1], z=v[:1, 2], mode="markers", name="vessel (tow point)",
                               marker={"size": 6, "symbol": "diamond", "color": "#1b9e77"}))
    track = v[thin(len(v), MAX_TRACK)]
    fig.add_trace(go.Scatter3d(x=track[:, 0], y=track[:, 1], z=track[:, 2], mode="lines", name="vessel track",
                               line={"width": 2, "color": "#1b9e77", "dash": "dash"}))
    fig.update_layout(scene=_scene(ds), margin={"l": 0, "r": 0, "t": 30, "b": 0}, height=620,
                      legend={"x": 0, "y": 1}, title={"text": "cable network, bodies and vessel track"})
    return fig


def animation_section(page, ds: xr.Dataset, plot_id: str = "plot-animation"):
    """Add the animated view to ``page`` (figure, data, player); return its markup."""
    data = animation_data(ds, plot_id)
    page.data["kanat-animation"] = data
    page.script("player.js")
    plot = page.figure(animation_figure(ds), plot_id, height=620, attributes=(("data-frame", "0"),))
    controls = {"last": len(data["times"]) - 1, "first_time": f"{data['times'][0]:.1f}", "follow": follows_by_default(ds),
                "frames": len(data["times"]), "times": ds.sizes["time"], "shown_nodes": data["nodes"],
                "nodes": ds.sizes["node"]}
    return macros("result.html.j2").animation(plot, controls)
