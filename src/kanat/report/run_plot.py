"""Pictures of a dynamic result: top tension and body depth in time, and cable snapshots."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure


def plot_run(ds, path=None, snapshots: int = 6) -> Figure:
    """Draw a dynamic result dataset (case-format.md names); save to ``path`` when given.

    Left: tension at the first node of each cable against time, and the depth of each
    body. Right: the cables in the vertical plane of the tow (x–z, relative to the tow
    point) at ``snapshots`` evenly spaced times.
    """
    fig = Figure(figsize=(12, 5), layout="constrained")
    left, right = fig.subplots(1, 2, width_ratios=[1.1, 1])
    time = ds["time"].values
    cables = ds["cable"].values
    firsts = [int(np.argmax(cables == name)) for name in dict.fromkeys(cables)]
    for index in firsts:
        left.plot(time, ds["tension"].values[:, index] / 1e3, lw=1.5, label=f"tension at {cables[index]} s = 0")
    left.set(xlabel="time [s]", ylabel="tension [kN]", title=ds.attrs.get("case_name", ""))
    left.grid(alpha=0.3)
    if "body" in ds.dims and ds.sizes["body"]:
        depth_axis = left.twinx()
        for k, name in enumerate(ds["body"].values):
            depth_axis.plot(time, ds["body_position"].values[:, k, 2], "--", lw=1.5, color=f"C{k + 3}",
                            label=f"{name} z")
        depth_axis.set_ylabel("body z [m]")
        depth_axis.legend(loc="lower right", fontsize=8)
    left.legend(loc="upper right", fontsize=8)
    picks = np.unique(np.linspace(0, len(time) - 1, snapshots).astype(int))
    origin = ds["vessel_position"].values
    for colour, i in enumerate(picks):
        xyz = ds["position"].values[i] - origin[i]
        horizontal = np.hypot(xyz[:, 0], xyz[:, 1]) * np.sign(xyz[:, 0] + 1e-300)
        right.plot(horizontal, xyz[:, 2], color=f"C{colour}", lw=1.3, label=f"t = {time[i]:g} s")
    right.set(xlabel="horizontal distance from the tow point [m]", ylabel="z [m]", title="cable snapshots")
    right.legend(fontsize=8)
    right.grid(alpha=0.3)
    if path is not None:
        fig.savefig(Path(path), dpi=110)
    return fig
