"""Measure the statics validation rows of docs/validation.md (SPEC §7 cases 1, 4, 5).

Run: python scripts/validation_statics.py  — prints the measured value of each row.
"""
from pathlib import Path

import numpy as np

from kanat.io import load_case
from kanat.statics import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties, solve_statics
from kanat.statics.collocation import solve_collocation
from kanat.statics.guess import solve_catenary
from kanat.statics.shooting import solve_shooting
from kanat.statics.sphere import SphereGroups
from kanat.statics.sphere_solvers import solve_sphere

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SOLVERS = {"shooting": solve_shooting, "collocation": solve_collocation}


def seed001():
    one = {m: solve_sphere(SphereGroups(0.02, 2.0, -1.732, 0.45, 0.4), "published", m) for m in SOLVERS}
    two = solve_sphere(SphereGroups(0.01, 2.0, -1.732, 0.225, 0.4), "published", "shooting")
    for m, sol in one.items():
        print(f"seed 001 case 1 ({m}): alpha(0) = {np.degrees(sol.alpha0):.4f} deg, tau(0) = {sol.tau0:.6f}, "
              f"eps1 = {sol.eps1_percent:.1e} %, eps2 = {sol.eps2_percent:.1e} %")
    a, b = one["shooting"], one["collocation"]
    print(f"seed 001 shooting vs collocation: |d alpha0| = {abs(a.alpha0 - b.alpha0):.1e} rad, "
          f"|d tau0| = {abs(a.tau0 - b.tau0):.1e}")
    print(f"seed 001 case 2 vs case 1: y_A {two.y_A:.4f} vs {a.y_A:.4f}; alpha(0) {np.degrees(two.alpha0):.2f} vs "
          f"{np.degrees(a.alpha0):.2f} deg; alpha(1) {np.degrees(two.alpha[-1]):.2f} vs {np.degrees(a.alpha[-1]):.2f} deg")


def catenary():
    line = lambda w, ea: LineProperties(weight=w, axial_stiffness=ea, diameter=0.1)  # noqa: E731
    cases = [CableBVP(line(1000.0, 5e8), 1000.0, FixedEnd((0.0, -300.0)), FixedEnd((900.0, 0.0)), seabed_z=-300.0),
             CableBVP(line(100.0, 1e7), 500.0, FixedEnd((0.0, -400.0)), FixedEnd((300.0, 0.0))),
             CableBVP(line(500.0, 1e8), 200.0, FixedEnd((0.0, -199.9)), FixedEnd((1.0, 0.0))),
             CableBVP(line(10.0, 1e7), 100.0, FixedEnd((0.0, 0.0)), FixedEnd((99.99, 0.2)))]
    for name, solver in SOLVERS.items():
        worst = 0.0
        for problem in cases:
            s = np.linspace(0.0, problem.length, 41)
            exact, num = solve_catenary(problem, s), solver(problem, s)
            worst = max(worst, np.max(np.abs(num.force - exact.force)) / exact.tension.max(),
                        np.max(np.hypot(num.x - exact.x, num.z - exact.z)) / problem.length)
        print(f"elastic catenary, 4 configurations, {name}: worst relative difference {worst:.1e}")


def critical_angle():
    worst = 0.0
    for speed, ct in [(1.5, 0.0), (3.0, 0.01), (5.0, 0.02)]:
        lt = LineProperties(8.89, 1.2717e8, 0.0173, 1.5, ct, 1025.0)
        problem = CableBVP(lt, 3000.0, FixedEnd((0.0, 0.0)), BodyEnd(-2000.0, 0.2), FlowProfile.uniform(-speed, 0.0))
        r = 0.5 * 1025.0 * 0.0173 * 1.5 * speed**2
        exact = np.degrees(np.arccos((-8.89 + np.sqrt(8.89**2 + 4 * r**2)) / (2 * r)))
        for solver in SOLVERS.values():
            sol = solver(problem)
            worst = max(worst, abs(np.degrees(np.arctan2(-sol.force[0, 1], -sol.force[0, 0])) - exact))
    print(f"critical angle, 3 speeds x 2 solvers: worst |difference| {worst:.4f} deg")


def examples():
    worst = 0.0
    for path in sorted(EXAMPLES.glob("*.yaml")):
        case = load_case(path)
        a, b = solve_statics(case, "shooting"), solve_statics(case, "collocation")
        if a.sphere is not None:
            worst = max(worst, abs(a.sphere.tau0 - b.sphere.tau0), abs(a.sphere.alpha0 - b.sphere.alpha0))
            continue
        for name in a.cables:
            sa, sb = a.cables[name], b.cables[name]
            worst = max(worst, np.max(np.abs(sa.tension - sb.tension)) / sa.tension.max(),
                        np.max(np.hypot(sa.x - sb.x, sa.z - sb.z)) / sa.s[-1])
    print(f"shooting vs collocation on every example: worst relative difference {worst:.1e}")


if __name__ == "__main__":
    seed001()
    catenary()
    critical_angle()
    examples()
