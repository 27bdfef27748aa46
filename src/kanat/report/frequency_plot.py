"""The picture of a frequency-domain result (``kanat run --plot`` with ``simulation.method:
frequency``): along every cable's unstretched arclength, the mean tension and the dynamic
tension about it, each cable in its own colour and named in the legend.

The dynamic tension is what the result gives (:func:`kanat.frequency.solve_frequency`): for a
spectral (irregular) excitation the standard deviation ``tension_std``; for harmonic excitation
the amplitude ``tension_amplitude`` at each excitation frequency (one curve per frequency).
Lines carry ``gid`` ``mean/CABLE`` and ``dynamic/CABLE[/k]`` so tests can read what was drawn.
"""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from kanat.report.geometry import KN

DPI = 120


def plot_frequency(ds, path=None) -> Figure:
    """Draw a frequency-domain result (module docstring); save it to ``path`` (PNG) when given."""
    fig = Figure(figsize=(11, 7.5), layout="constrained")
    mean_ax, dynamic_ax = fig.subplots(2, 1, sharex=True)
    cables = ds["cable"].values.astype(str)
    s = ds["s"].values
    spectral = "tension_amplitude" not in ds                 # harmonic results carry amplitudes
    for k, cable in enumerate(dict.fromkeys(cables)):
        nodes = np.flatnonzero(cables == cable)
        nodes = nodes[np.argsort(s[nodes], kind="stable")]
        colour = f"C{k % 10}"
        mean_ax.plot(s[nodes], ds["mean_tension"].values[nodes] / KN, color=colour, label=cable, gid=f"mean/{cable}")
        if spectral:
            dynamic_ax.plot(s[nodes], ds["tension_std"].values[nodes] / KN, color=colour, label=cable,
                            gid=f"dynamic/{cable}")
            continue
        amplitude = ds["tension_amplitude"].values                   # (frequency, node)
        for j, omega in enumerate(ds["frequency"].values):
            label = cable if amplitude.shape[0] == 1 else f"{cable}, {2 * np.pi / omega:.3g} s"
            dynamic_ax.plot(s[nodes], amplitude[j, nodes] / KN, color=colour, label=label,
                            linestyle=("-", "--", ":", "-.")[j % 4], gid=f"dynamic/{cable}/{j}")
    mean_ax.set_ylabel("mean tension [kN]")
    dynamic_ax.set_ylabel("tension standard deviation [kN]" if spectral else "tension amplitude [kN]")
    dynamic_ax.set_xlabel("unstretched arclength from the cable's first end [m]")
    for ax in (mean_ax, dynamic_ax):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    status = ds.attrs.get("status", "")
    fig.suptitle(f"{ds.attrs.get('case_name', '')}: frequency domain"
                 + ("" if status == "ok" else f" ({status[:80]})"))
    if path is not None:
        fig.savefig(path, dpi=DPI)
    return fig
