"""The lumped model's compiled force evaluation, part by part, two source trees side by side.

Each tree runs in a process of its own (``PYTHONPATH`` set to it, ``KANAT_AOT=0``: numba's kernels,
compiled in the process, so that its parts can be called in loops of their own) on three cases:

* ``three-leg``: ``bench_mooring_moordyn.kanat_case`` (three chains on the seabed, no friction,
  still water), its state after 100 s;
* ``WD0050``: ``bench_wd0050_moordyn.kanat_case`` (a chain with seabed friction 0.5), after 40 s;
* ``current``: the three-leg case in a current profile (1, 0.7 and 0.2 m/s at 0, -50 and -120 m),
  after 100 s.

At that state it times, per call (best of 3 loops of 20 000 calls inside one compiled function):
``loads`` (a whole force evaluation: ``kanat.lumped.fast.loads``), ``tensions_at`` (the end-of-step
tensions the snap tracking reads), ``element_forces``, ``contact_forces`` and ``water`` (the current
and waves at the elements' midpoints), and the state after 100 more outputs, which must be the same
in both trees.

Run: ``python benchmarks/bench_kernel_parts.py OLD_SRC NEW_SRC`` (about 3 minutes a tree, most of it
numba compiling the timing loops).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent

CHILD = r"""
import json, sys, time, warnings
import numpy as np
warnings.simplefilter("ignore")
from numba import njit
from kanat.io import load_case
from kanat.lumped import advance as adv, fast, kernels
from kanat.lumped.adapter import LumpedModel
from kanat.physics import contact

@njit
def loop_loads(n, t, y, vp, vv, vh, nodes, el, bodies, env, work):
    for i in range(n):
        fast.loads(t, y, vp, vv, vh, nodes, el, bodies, env, work)

@njit
def loop_tensions_at(n, y, track, nodes, el, bodies, work):
    for i in range(n):
        fast.tensions_at(y, 0, track, nodes, el, bodies, work)

@njit
def loop_element_forces(n, x, v, uw, aw, wet, force, mass, el, F, M, T, strain):
    for i in range(n):
        kernels.element_forces(x, v, uw, aw, wet, force, mass, el, F, M, T, strain)

@njit
def loop_contact_forces(n, x, v, el, c, tangent, F, N):
    for i in range(n):
        if c is not None:
            contact.contact_forces(x, v, el.first_node, el.second_node, c.area, c.seabed, c.law, c.laid, tangent,
                                   F, N)

@njit
def loop_water(n, points, t, env, u, a):
    for i in range(n):
        fast.water(points, t, env.current_depths, env.current_velocities, env.current_ramp, env.sea, u, a)

def best(call, count=20000):
    call(1)
    times = []
    for _ in range(3):
        start = time.perf_counter()
        call(count)
        times.append((time.perf_counter() - start) / count * 1e6)
    return min(times)

out = {}
for label, path, outputs in json.loads(sys.argv[1]):
    model = LumpedModel(load_case(path))
    state = model.initial()
    for k in range(1, outputs + 1):
        state, _ = model.advance(state, k * model.output_interval)
    arrays = adv._arrays(model.system)
    scheme = state.scheme
    t = float(scheme.t)
    y = np.concatenate([np.ravel(scheme.x), np.ravel(scheme.v)])
    track = adv.track_samples(model.system, np.array([t]))
    nodes, el, bodies, env, work = arrays.nodes, arrays.el, arrays.bodies, arrays.env, arrays.work
    loads = (t, y, track.position[0], track.velocity[0], track.heading[0], nodes, el, bodies, env, work)
    row = {"loads": best(lambda n: loop_loads(n, *loads)),
           "tensions_at": best(lambda n: loop_tensions_at(n, y, track, nodes, el, bodies, work))}
    loop_loads(1, *loads)                  # the work arrays at the state again
    F, M, T, strain = work.force.copy(), work.mass.copy(), work.tension.copy(), work.strain.copy()
    row["element_forces"] = best(lambda n: loop_element_forces(n, work.x, work.v, work.water_velocity,
                                                               work.water_acceleration, work.wet, nodes.force,
                                                               nodes.mass, el, F, M, T, strain))
    normal = work.normal_force.copy()
    row["contact_forces"] = best(lambda n: loop_contact_forces(n, work.x, work.v, el, bodies.contact,
                                                               work.line_tangent.copy(), F, normal))
    u, a = work.water_velocity.copy(), work.water_acceleration.copy()
    row["water"] = best(lambda n: loop_water(n, work.midpoint, t, env, u, a))
    for k in range(outputs + 1, outputs + 101):
        state, _ = model.advance(state, k * model.output_interval)
    row["state"] = [float(v) for v in np.concatenate([np.ravel(state.scheme.x), np.ravel(state.scheme.v)])]
    out[label] = row
print(json.dumps(out))
"""


def cases(folder: Path) -> list:
    """``[label, case path, outputs before the timings]`` of the three cases (module docstring)."""
    import yaml

    sys.path.insert(0, str(HERE))
    import bench_mooring_moordyn
    import bench_wd0050_moordyn

    three = bench_mooring_moordyn.kanat_case(folder, "default", None, 600.0)
    wd = bench_wd0050_moordyn.kanat_case(folder, "default", 200.0)
    data = yaml.safe_load(three.read_text())
    data["environment"]["current"] = {"profile": [[0.0, 1.0, 0.0, 0.0], [-50.0, 0.7, 0.0, 0.0],
                                                  [-120.0, 0.2, 0.0, 0.0]]}
    current = folder / "three_leg_current.yaml"
    current.write_text(yaml.safe_dump(data, sort_keys=False))
    return [["three-leg", str(three), 200], ["WD0050", str(wd), 400], ["current", str(current), 200]]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("old")
    parser.add_argument("new")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        listed = json.dumps(cases(Path(tmp)))
        results = {}
        for name, tree in (("before", args.old), ("after", args.new)):
            env = {**os.environ, "PYTHONPATH": str(Path(tree).resolve()), "KANAT_AOT": "0"}
            done = subprocess.run([sys.executable, "-c", CHILD, listed], env=env, capture_output=True, text=True,
                                  check=True)
            results[name] = json.loads(done.stdout.strip().splitlines()[-1])
    parts = ("loads", "tensions_at", "element_forces", "contact_forces", "water")
    print("| case | " + " | ".join(f"{p} [us] before / after" for p in parts) + " | same state after 100 outputs |")
    print("|---|" + "---|" * (len(parts) + 1))
    for label in results["before"]:
        old, new = results["before"][label], results["after"][label]
        cells = [f"{old[p]:.2f} / {new[p]:.2f}" for p in parts]
        print(f"| {label} | " + " | ".join(cells) + f" | {old['state'] == new['state']} |")


if __name__ == "__main__":
    main()
