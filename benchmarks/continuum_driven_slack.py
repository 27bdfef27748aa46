"""The continuum model driven at its top (``vessel.motion``) and through slack, against its oracles.

Prints the figures docs/continuum.md quotes, from the cases of the tests (tests/continuum/test_continuum_motion.py,
tests/continuum/test_continuum_slack.py):

* a 160 m wire from a tow point 5 m deep to an anchor, driven in surge and heave, and in surge and
  sway (3-D): top tension mean and range against the lumped model's ``rk4``;
* the same line in slow surge and heave (1000 s): the largest error of the top tension against the
  elastic catenary at each displaced top;
* a buoy tethered in waves that goes slack for a moment in each wave: slack events, the lowest
  tension, the buoy-end tension's mean, maximum and minimum against the lumped model's ``rk4``;
* a chain lying slack on the seabed under a buoy in still water: its start (from a small pull)
  against the elastic catenary on the seabed, and its top tension after 20 s.

Run: ``PYTHONPATH=src python benchmarks/continuum_driven_slack.py`` (about a minute).
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from kanat.statics.catenary import elastic_catenary  # noqa: E402
from test_continuum_motion import ANCHOR, EA, LENGTH, SURGE_HEAVE, SURGE_SWAY, WEIGHT, mooring  # noqa: E402
from test_continuum_motion import run as run_ok  # noqa: E402
from test_continuum_slack import grounded_buoy, simulate, tethered_buoy  # noqa: E402


def driven() -> None:
    for name, motion in (("surge-heave", SURGE_HEAVE), ("surge-sway", SURGE_SWAY)):
        ours = run_ok(mooring("continuum", motion)).tension.values[:, 0]
        theirs = run_ok(mooring("lumped", motion, dt=0.001, scheme="rk4")).tension.values[:, 0]
        print(f"driven {name}: top tension mean {100 * (ours.mean() / theirs.mean() - 1):+.3f} %, "
              f"range {100 * (np.ptp(ours) / np.ptp(theirs) - 1):+.3f} % against lumped rk4")
    slow = [{"dof": "surge", "amplitude": 3.0, "period": 1000.0}, {"dof": "heave", "amplitude": 2.0, "period": 1000.0}]
    ds = run_ok(mooring("continuum", slow, duration=500.0, dt=1.0, output_dt=25.0))
    errors = []
    for k in range(len(ds.time)):
        top = ds.position.values[k, 0]
        exact = elastic_catenary(top[0] - ANCHOR[0], top[2] - ANCHOR[2], LENGTH, WEIGHT, EA)
        errors.append(abs(ds.tension.values[k, 0] / exact.tension_upper - 1))
    print(f"slow surge and heave: largest top tension error against the elastic catenary {100 * max(errors):.4f} %")


def slack() -> None:
    ours, theirs = simulate(tethered_buoy("continuum")), simulate(tethered_buoy("lumped", scheme="rk4"))
    a, b = ours.dataset.tension.values[:, -1], theirs.dataset.tension.values[:, -1]
    print(f"tethered buoy: {ours.summary.status}, {ours.dataset.attrs['slack_events']} slack events, lowest "
          f"{ours.dataset.slack_tension.values.min():.2f} N; buoy-end tension against lumped rk4: mean "
          f"{100 * (a.mean() / b.mean() - 1):+.2f} %, max {100 * (a.max() / b.max() - 1):+.2f} %, "
          f"min {100 * (a.min() / b.min() - 1):+.2f} %")
    ds = simulate(grounded_buoy("continuum")).dataset
    buoy = ds.body_position.values[0, 0]
    exact = elastic_catenary(buoy[0] + 40.0, buoy[2] + 50.0, 80.0, 77.0, 8.0e7, seabed=True)
    print(f"grounded slack chain: start H {exact.horizontal_tension:.2f} N (pull 61.6 N), top tension "
          f"{ds.tension.values[0, -1]:.1f} N against the catenary's {exact.tension_upper:.1f} N "
          f"({100 * (ds.tension.values[0, -1] / exact.tension_upper - 1):+.2f} %); after 20 s "
          f"{ds.tension.values[-1, -1]:.1f} N (buoyancy 2000 N), lowest tension {ds.tension.values.min():.1f} N")


if __name__ == "__main__":
    driven()
    slack()
