"""Load a case, vary one parameter, run each variant in memory and plot with xarray.

    python examples/python/vary_and_plot.py [PICTURE.png]

The towed body of examples/speed_step_2d.yaml steps from 6 to 10 kn; here its cable's normal
drag coefficient is 1.2 and then 1.8 (a faired cable against a bare one). Nothing is written
but the picture: ``kanat.simulate`` keeps each result in memory as an ``xarray.Dataset``.
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import kanat  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1]


def main(picture: str = "vary_and_plot.png") -> None:
    base = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace({"simulation.duration": 240})
    results = {cn: kanat.simulate(base.replace({"line_types.towcable.drag_normal": cn})) for cn in (1.2, 1.8)}

    fig, (top, depth, shape) = plt.subplots(1, 3, figsize=(15, 4.2), layout="constrained")
    for cn, ds in results.items():
        label = f"C_n = {cn}"
        (ds.tension.isel(node=0) / 1e3).plot(ax=top, label=label)
        ds.body_position.sel(body="sled", xyz="z").plot(ax=depth, label=label)
        end = ds.isel(time=-1)
        shape.plot(end.position.sel(xyz="x") - end.vessel_position.sel(xyz="x"), end.position.sel(xyz="z"),
                   label=f"{label}, t = {float(end.time):g} s")
        print(f"C_n = {cn}: top tension up to {float(ds.tension.isel(node=0).max()) / 1e3:.3f} kN, "
              f"body from {float(ds.body_position.sel(body='sled', xyz='z')[0]):.2f} m "
              f"to {float(ds.body_position.sel(body='sled', xyz='z')[-1]):.2f} m")
    top.set(title="tension at the tow point", ylabel="tension [kN]")
    depth.set(title="towed body", ylabel="z [m]")
    shape.set(title="cable at the end", xlabel="x behind the tow point [m]", ylabel="z [m]", aspect="equal")
    for ax in (top, depth, shape):
        ax.legend()
    fig.savefig(picture, dpi=90)
    print(f"wrote {picture}")


if __name__ == "__main__":
    main(*sys.argv[1:])
