"""A current step on the subsurface mooring: start from the steady state in one current, run in another.

    python examples/python/subsurface_current_step.py [PICTURE.png]

examples/subsurface_mooring.yaml holds an anchor - wire - float - nylon - top buoy mooring in a
current sheared in depth and turning with it. Here the current doubles at t = 0: the run starts
from the steady state of the case's own current (``kanat.run(doubled, start=case)``) and
steps in the doubled one, so the line leans over to its new steady state (which the 3-D statics
of the doubled current give: the run's last output is compared with it).
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import kanat  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1]


def main(picture: str = "subsurface_current_step.png") -> None:
    base = kanat.load_case(EXAMPLES / "subsurface_mooring.yaml")
    rows = [[z, 2 * ux, 2 * uy, uz] for z, ux, uy, uz in base.environment.current.profile]
    stepped = base.replace({"environment.current.profile": rows, "simulation.duration": 1500,
                            "simulation.output_dt": 10})
    outcome = kanat.run(stepped, start=base)
    ds = outcome.dataset
    steady = kanat.solve_statics(stepped.replace({"model": "statics"}))
    buoy = ds.body_position.sel(body="top_buoy")
    final = steady.body_position.sel(body="top_buoy").values
    print(f"status: {outcome.status}; top buoy from {buoy.values[0].round(2)} m to {buoy.values[-1].round(2)} m; "
          f"statics of the doubled current: {final.round(2)} m (difference "
          f"{np.linalg.norm(buoy.values[-1] - final):.3f} m)")

    fig, (plan, depth) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    for t in (0, 60, 120, 300, 1500):
        at = ds.sel(time=t)
        plan.plot(at.position.sel(xyz="x"), at.position.sel(xyz="z"), label=f"t = {t} s")
        depth.plot(at.position.sel(xyz="y"), at.position.sel(xyz="z"), label=f"t = {t} s")
    plan.set(title="mooring seen from -y", xlabel="x [m]", ylabel="z [m]")
    depth.set(title="mooring seen from +x", xlabel="y [m]", ylabel="z [m]")
    plan.legend()
    fig.savefig(picture, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:2])
