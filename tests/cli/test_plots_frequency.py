"""``kanat run --plot`` of a frequency-domain result: the mean tension and the dynamic tension
along every cable, read back from the figure's lines against the result (and the result file
carries the provenance every result carries)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.report.frequency_plot import plot_frequency

CASE = """
name: surging-chain
model: lumped
environment: {depth: 60, seabed: {}}
line_types:
  chain: {diameter: 0.0766, mass: 113.35, axial_stiffness: 7.536e8, drag_normal: 2.0, added_mass: 1.0}
vessel:
  motion: [{dof: surge, amplitude: 0.1, period: 30.0}, {dof: surge, amplitude: 0.05, period: 12.0}]
cables:
  - {name: leg, line_type: chain, length: 300, segments: 10, from: "anchor:[-270, 0, -60]", to: {vessel: [0, 0, -5]}}
simulation: {method: frequency, duration: 600}
"""


def test_the_frequency_picture_draws_the_result(tmp_path):
    case = tmp_path / "case.yaml"
    case.write_text(CASE)
    out, picture = tmp_path / "out.nc", tmp_path / "out.png"
    done = subprocess.run([str(Path(sys.executable).with_name("kanat")), "run", str(case), "-o", str(out),
                           "--plot", str(picture)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-2000:]
    assert picture.stat().st_size > 10_000
    with xr.open_dataset(out) as ds:
        ds = ds.load()
    assert ds.attrs["case_name"] == "surging-chain" and ds.attrs["case_yaml"]
    figure = plot_frequency(ds)
    lines = {line.get_gid(): line for ax in figure.axes for line in ax.get_lines()}
    order = np.argsort(ds["s"].values, kind="stable")
    np.testing.assert_allclose(lines["mean/leg"].get_ydata(), ds["mean_tension"].values[order] / 1e3, rtol=1e-12)
    assert ds.sizes["frequency"] == 2
    for j in range(2):
        np.testing.assert_allclose(lines[f"dynamic/leg/{j}"].get_ydata(),
                                   ds["tension_amplitude"].values[j, order] / 1e3, rtol=1e-12)
    legend = [text.get_text() for text in figure.axes[1].get_legend().get_texts()]
    assert legend == ["leg, 30 s", "leg, 12 s"] or legend == ["leg, 12 s", "leg, 30 s"]
