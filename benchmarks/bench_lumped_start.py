"""Lumped equilibrium of examples/surface_mooring_waves.yaml (in its current and in still water) from
three starts: the default (``equilibrium(net, case)``: statics, else network statics' catenaries), the
network's own guess (``net.x_guess``: no statics), and the former default guess (the buoy 0.9 L astern
and down from the anchor, on the seabed) given as ``x0``. Prints iterations, taut iterations, first
guess, wall time, or the failure and its time. Run: ``python benchmarks/bench_lumped_start.py``."""
import time
import warnings
from pathlib import Path

import numpy as np

import kanat
from kanat.errors import SolverError
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import VESSEL_GUESS_DIRECTION, build_network, sagged_line

TEXT = ((Path(__file__).parents[1] / "examples" / "surface_mooring_waves.yaml").read_text()
        .replace("model: continuum", "model: lumped").replace("scheme: generalized-alpha", "scheme: rk4"))


def former_guess(net, case):
    """The guess before the floating-end rule: the buoy 0.9 L astern and down, on the seabed."""
    anchor = np.asarray(case.cables[0].from_.position, float)
    buoy = anchor + 0.9 * case.cables[0].length * VESSEL_GUESS_DIRECTION
    x = net.x_guess.copy()
    x[net.node_index] = sagged_line(anchor, buoy, case.cables[0].length, len(net.node_index) - 1, net.node_s)
    x[net.node_index, 2] = np.maximum(x[net.node_index, 2], -100.0)
    return x


def main():
    warnings.simplefilter("ignore")
    warm = kanat.load_case(TEXT)
    equilibrium(build_network(warm), warm)                          # compile once
    for label, text in (("current", TEXT), ("still water", TEXT.replace("  current: {velocity: [0.5, 0, 0]}\n", ""))):
        case = kanat.load_case(text)
        net = build_network(case)
        for start, x0 in (("default", None), ("network guess", net.x_guess), ("former guess", former_guess(net, case))):
            t = time.perf_counter()
            try:
                x, info = equilibrium(net, case, x0)
                print(f"{label}, {start}: {info['iterations']} iterations ({info['taut_iterations']} taut, "
                      f"{info.get('continuation_stages', 0)} stiffness stages, first guess {info['first_guess']}), "
                      f"{time.perf_counter() - t:.2f} s; buoy at {np.round(x[net.body_node[0]], 4)}")
            except SolverError as error:
                print(f"{label}, {start}: fails after {time.perf_counter() - t:.2f} s ({str(error)[:90]})")


if __name__ == "__main__":
    main()
