"""Write tests/data/moorpy/reference.json: MoorPy's answers for the network statics tests.

Run from the repository root with MoorPy installed (``pip install moorpy==1.3.0``)::

    python tests/data/moorpy/make_reference.py

README.md beside this file says what each entry is and how it was made.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import sys
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
sys.path.insert(0, str(ROOT / "tests"))

from moorpy_systems import moorpy_system, solve  # noqa: E402

SYSTEMS = {
    "buoy_spread_mooring": ROOT / "examples" / "moordyn" / "buoy_spread_mooring.dat",
    "three_leg_vessel_v1": ROOT / "examples" / "moordyn" / "three_leg_vessel_v1.dat",
    "buoy_two_line_types_clumps": HERE / "buoy_two_line_types_clumps.yaml",
    "platform_4leg": HERE / "platform_4leg.yaml",
}
"""Multi-line systems with seabed contact, by name: the case each is built from."""

# single lines: (span, rise, length, weight, axial stiffness, friction CB, seabed slope [deg])
CHAIN = (900.0, (140.0 - 1025.0 * math.pi / 4 * 0.15**2) * 9.81, 9.0e8)
CATENARIES = [
    (600.0, 145.0, 700.0, 981.0, 5.1e8, 0.3, 0.0),    # friction, anchor tension zero
    (650.0, 100.0, 700.0, 981.0, 5.1e8, 0.3, 0.0),
    (690.0, 50.0, 700.0, 981.0, 5.1e8, 0.3, 0.0),     # friction, anchor holds tension
    (690.0, 50.0, 700.0, 981.0, 5.1e8, 1.0, 0.0),
    (600.0, 145.0, 700.0, 981.0, 5.1e8, 5.0, 0.0),
    (820.0, 150.0, *CHAIN, 0.0, 2.0),                 # sloped seabed, anchor holds tension
    (800.0, 170.0, *CHAIN, 0.0, 2.0),
    (820.0, 150.0, *CHAIN, 0.0, -2.0),
    (840.0, 120.0, *CHAIN, 0.0, -2.0),
]


def kanat_case(path: Path):
    from kanat.api import load_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path, solver="statics")


def moorpy_of(name: str, path: Path):
    """MoorPy's system: read from the MoorDyn file where MoorPy 1.3 can read it (a copy with
    the body's two drag areas reduced to one, which MoorPy's reader requires and statics
    does not use), else built from the kanat case (:mod:`moorpy_systems`)."""
    import moorpy as mp

    if name == "buoy_spread_mooring":
        copy = HERE / "_moorpy_reads_this.dat"
        copy.write_text(path.read_text().replace(" 20|10 ", " 20    "))
        try:
            with contextlib.redirect_stdout(io.StringIO()):
                ms = mp.System(file=str(copy))
                ms.initialize()
        finally:
            copy.unlink()
        names = {"lines": {f"line{i + 1}": [i + 1] for i in range(len(ms.lineList))},
                 "bodies": {"body1": 1}, "points": {},
                 "anchors": {f"line{i + 1}.from": i + 1 for i in range(len(ms.lineList))}}
        return ms, names
    return moorpy_system(kanat_case(path))


def condensed_stiffness(ms, names, node: str) -> np.ndarray:
    """MoorPy's analytic lines-only stiffness at ``node``, the other free DOFs condensed."""
    K_lines = ms.getSystemStiffnessA(DOFtype="free", lines_only=True)
    K_all = ms.getSystemStiffnessA(DOFtype="free", lines_only=False)
    if node in names["bodies"]:
        keep = 6 * (names["bodies"][node] - 1) + np.arange(6)
    else:
        free = [p.number for p in ms.pointList if p.type == 0]
        keep = 6 * len(ms.bodyList) + 3 * free.index(names["points"][node]) + np.arange(3)
    other = np.setdiff1d(np.arange(len(K_all)), keep)
    K = K_lines[np.ix_(keep, keep)]
    if len(other):
        K = K - K_all[np.ix_(keep, other)] @ np.linalg.solve(K_all[np.ix_(other, other)], K_all[np.ix_(other, keep)])
    return K


def system_reference(name: str, path: Path) -> dict:
    ms, names = moorpy_of(name, path)
    solve(ms, tol=1e-8, max_iterations=5000)
    cables = {}
    for cable, numbers in names["lines"].items():
        first, last = ms.lineList[numbers[0] - 1], ms.lineList[numbers[-1] - 1]
        cables[cable] = {"tension_from": first.TA, "tension_to": last.TB,
                         "grounded_length": sum(ms.lineList[n - 1].LBot for n in numbers)}
    anchors = {label: ms.lineList[names["lines"][label.split(".")[0]][0] - 1].fA.tolist()
               for label in names["anchors"]}
    nodes = {body: ms.bodyList[n - 1].r6.tolist() for body, n in names["bodies"].items()}
    nodes.update({point: ms.pointList[n - 1].r.tolist() for point, n in names["points"].items()})
    stiffness = {node: condensed_stiffness(ms, names, node).tolist() for node in nodes}
    return {"case": str(path.relative_to(ROOT)), "cables": cables, "anchors": anchors, "nodes": nodes,
            "stiffness": stiffness}


def catenary_reference(span, rise, length, weight, stiffness, friction, slope_deg) -> dict:
    from moorpy.Catenary import catenary

    fAH, fAV, fBH, fBV, info = catenary(span, rise, length, stiffness, weight, CB=friction, alpha=slope_deg,
                                        Tol=1e-12, MaxIter=500)
    return {"span": span, "rise": rise, "length": length, "weight": weight, "axial_stiffness": stiffness,
            "friction": friction, "slope_deg": slope_deg, "horizontal_tension": -fBH,
            "vertical_tension": -fBV, "anchor_force": [fAH, fAV], "grounded_length": info["LBot"],
            "stiffness": np.asarray(info["stiffnessB"]).tolist()}


def main() -> None:
    import moorpy

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        data = {"moorpy_version": getattr(moorpy, "__version__", "1.3.0"),
                "systems": {name: system_reference(name, path) for name, path in SYSTEMS.items()},
                "catenaries": [catenary_reference(*row) for row in CATENARIES]}
    (HERE / "reference.json").write_text(json.dumps(data, indent=1) + "\n")
    print(f"wrote {HERE / 'reference.json'}")


if __name__ == "__main__":
    main()
