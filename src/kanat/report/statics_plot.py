"""Pictures of a steady state: cable shapes in the x–z plane and tension along the cables."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure


def plot_statics(result, path=None) -> Figure:
    """Draw a :class:`kanat.statics.StaticsResult`; save to ``path`` (PNG) when given.

    Left: cable shapes, bodies, tow point and seabed (equal axes). Right: tension
    along the unstretched arclength of each cable. A seed 001 result is drawn as the
    paper's figures 4 and 5 (:func:`kanat.report.sphere_plot.plot_sphere`).
    """
    if result.sphere is not None:
        from kanat.report.sphere_plot import plot_sphere

        return plot_sphere([result.sphere], path)
    fig = Figure(figsize=(11, 4.5), layout="constrained")
    shape, tension = fig.subplots(1, 2, width_ratios=[1.6, 1])
    for name, sol in result.cables.items():
        shape.plot(sol.x, sol.z, lw=1.8, label=f"{name} ({sol.method})")
        tension.plot(sol.s, sol.tension / 1e3, lw=1.8, label=name)
    for name, position in result.bodies.items():
        shape.plot(position[0], position[2], "o", ms=9, label=f"body {name}")
    case = result.case
    for cable in case.cables:
        for end in (cable.from_, cable.to):
            if end.kind == "anchor":
                shape.plot(end.position[0], end.position[2], "^", ms=9, color="dimgray")
            elif end.kind == "vessel":
                shape.plot(case.vessel.tow_point[0], case.vessel.tow_point[2], "v", ms=10, color="k")
    z_all = np.concatenate([sol.z for sol in result.cables.values()])
    x_all = np.concatenate([sol.x for sol in result.cables.values()])
    z_span = max(np.ptp(z_all), 1e-3 * max(np.ptp(x_all), 1.0))
    depth = case.environment.depth
    if depth is not None and -depth > z_all.min() - 0.3 * z_span:
        shape.axhline(-depth, color="saddlebrown", lw=2, label="seabed")
    shape.axhline(0.0, color="tab:blue", lw=0.8, ls=":")
    speed = result.vessel_velocity[0]
    aspect_ratio = np.ptp(x_all) / z_span
    shape.set(xlabel="x [m]", ylabel="z [m]", aspect="equal" if 0.2 < aspect_ratio < 5 else "auto",
              title=f"{case.name or 'statics'}" + (f" — tow speed {speed:.3g} m/s" if speed else ""))
    shape.legend(fontsize=8, loc="best")
    shape.grid(alpha=0.3)
    tension.set(xlabel="s [m] (unstretched, from the first end)", ylabel="tension [kN]", title="tension")
    tension.grid(alpha=0.3)
    if path is not None:
        fig.savefig(Path(path), dpi=120)
    return fig
