"""Statics checks (theory/validation-cases.md cases 1, 4, 5): Naumov & Agievich, the critical angle, the elastic catenary.

The same comparisons as the statics tests, each reduced to one number against its oracle.
"""
from __future__ import annotations

import numpy as np

from kanat.validation.core import Tolerance, check

SEED001 = (0.02, 2.0, -1.732, 0.45, 0.4)          # Psi, L/L, x_C, Q/kL, R/kL (Naumov & Agievich's control example)
SEED001_CASE2 = (0.01, 2.0, -1.732, 0.225, 0.4)    # flow speed squared doubled


def _sphere(groups=SEED001, method="shooting"):
    from kanat.statics.sphere import SphereGroups
    from kanat.statics.sphere_solvers import solve_sphere

    return solve_sphere(SphereGroups(*groups), "published", method)


@check("sphere-alpha0", "7.1", "Naumov & Agievich published case: cable angle at the anchor",
       "alpha(0) = 46.9 deg (Naumov & Agievich's control example)", Tolerance(abs=0.1), "deg")
def sphere_alpha0():
    return np.degrees(_sphere().alpha0), 46.9


@check("sphere-tau0", "7.1", "Naumov & Agievich published case: dimensionless tension at the anchor",
       "tau(0) = 0.6066 (Naumov & Agievich's control example)", Tolerance(abs=5e-4))
def sphere_tau0():
    return _sphere().tau0, 0.6066


@check("sphere-methods", "7.1", "Naumov & Agievich: shooting and collocation agree",
       "the two methods solve the same problem: |alpha0 difference| = 0", Tolerance(abs=1e-6), "rad")
def sphere_methods():
    return abs(_sphere(method="shooting").alpha0 - _sphere(method="collocation").alpha0), 0.0


@check("sphere-case2", "7.1", "Naumov & Agievich second case, qualitatively",
       "deeper sphere, top angle down, bottom angle up (3 of 3 relations hold; Naumov & Agievich)", Tolerance(), "relations")
def sphere_case2():
    one, two = _sphere(), _sphere(SEED001_CASE2)
    held = (two.y_A < one.y_A) + (two.alpha0 < one.alpha0) + (two.alpha[-1] > one.alpha[-1])
    return held, 3


@check("critical-angle", "7.4", "long towed cable reaches the critical angle",
       "cos(phi_c) = (-w + sqrt(w^2 + 4 R^2)) / (2 R), R = 0.5 rho d C_n U^2; worst of "
       "3 speeds × 2 solvers", Tolerance(abs=0.1), "deg")
def critical_angle():
    from kanat.statics import BodyEnd, CableBVP, FixedEnd, FlowProfile, LineProperties
    from kanat.statics.collocation import solve_collocation
    from kanat.statics.shooting import solve_shooting

    worst = 0.0
    for speed, ct in [(1.5, 0.0), (3.0, 0.01), (5.0, 0.02)]:
        line = LineProperties(8.89, 1.2717e8, 0.0173, 1.5, ct, 1025.0)
        problem = CableBVP(line, 3000.0, FixedEnd((0.0, 0.0)), BodyEnd(-2000.0, 0.2), FlowProfile.uniform(-speed, 0.0))
        r = 0.5 * 1025.0 * 0.0173 * 1.5 * speed**2
        exact = np.degrees(np.arccos((-8.89 + np.sqrt(8.89**2 + 4 * r**2)) / (2 * r)))
        for solver in (solve_shooting, solve_collocation):
            sol = solver(problem)
            worst = max(worst, abs(np.degrees(np.arctan2(-sol.force[0, 1], -sol.force[0, 0])) - exact))
    return worst, 0.0


@check("elastic-catenary", "7.5", "numerical statics against the closed-form elastic catenary",
       "Irvine's closed form; worst relative difference in force and position over 4 configurations "
       "(slack with seabed, taut, near-vertical, nearly horizontal) × 2 solvers", Tolerance(abs=1e-6))
def elastic_catenary_statics():
    from kanat.statics import CableBVP, FixedEnd, LineProperties
    from kanat.statics.collocation import solve_collocation
    from kanat.statics.guess import solve_catenary
    from kanat.statics.shooting import solve_shooting

    def line(w, ea):
        return LineProperties(weight=w, axial_stiffness=ea, diameter=0.1)
    cases = [CableBVP(line(1000.0, 5e8), 1000.0, FixedEnd((0.0, -300.0)), FixedEnd((900.0, 0.0)), seabed_z=-300.0),
             CableBVP(line(100.0, 1e7), 500.0, FixedEnd((0.0, -400.0)), FixedEnd((300.0, 0.0))),
             CableBVP(line(500.0, 1e8), 200.0, FixedEnd((0.0, -199.9)), FixedEnd((1.0, 0.0))),
             CableBVP(line(10.0, 1e7), 100.0, FixedEnd((0.0, 0.0)), FixedEnd((99.99, 0.2)))]
    worst = 0.0
    for solver in (solve_shooting, solve_collocation):
        for problem in cases:
            s = np.linspace(0.0, problem.length, 41)
            exact, num = solve_catenary(problem, s), solver(problem, s)
            worst = max(worst, np.max(np.abs(num.force - exact.force)) / exact.tension.max(),
                        np.max(np.hypot(num.x - exact.x, num.z - exact.z)) / problem.length)
    return worst, 0.0


@check("lumped-catenary", "7.5", "lumped-model equilibrium of a hanging line against the elastic catenary",
       "closed-form elastic catenary (kanat.statics.catenary); largest element tension error / top tension, "
       "40 elements", Tolerance(abs=5e-3))
def lumped_catenary():
    from kanat.lumped.equilibrium import equilibrium
    from kanat.lumped.network import build_network
    from kanat.model import Case
    from kanat.statics.catenary import elastic_catenary

    span, rise, length, weight, ea, segments = 80.0, 60.0, 120.0, 150.0, 5e6, 40
    line = dict(diameter=0.05, mass=20.0, weight_in_water=weight, axial_stiffness=ea)
    case = Case.model_validate(dict(model="lumped", line_types={"c": line}, simulation=dict(duration=1, dt=0.01),
                                    cables=[{"name": "line", "line_type": "c", "length": length,
                                             "segments": segments, "from": "anchor:[0,0,-200]",
                                             "to": f"anchor:[{span},0,{rise - 200}]"}]))   # under water
    net = build_network(case)
    x, _ = equilibrium(net, case)
    exact = elastic_catenary(span, rise, length, weight, ea, n_points=2 * segments + 1)
    tension = ea * (np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1) / net.el_length - 1.0)
    return np.max(np.abs(tension - exact.tension[1::2])) / exact.tension_upper, 0.0
