"""Froude–Krylov force and partial submergence of lumped elements (kernels eqs. 6-8):

* a vertical element in a regular wave feels ``rho V a_w`` — checked against the gradient of
  Airy's dynamic pressure ``p = rho g a cosh(k (z + h)) / cosh(k h) cos(theta)``, differenced
  numerically here (an independent calculation: ``F = -V grad p`` for a small submerged body);
  its tangential part is what MoorDyn and OrcaFlex add and kanat once left out;
* an element crossing the still surface keeps the buoyancy of its wetted part only
  (Archimedes on the submerged length).
"""
import math

import numpy as np
import pytest

from kanat.lumped.network import build_network
from kanat.lumped.system import LumpedSystem
from kanat.model import Case

RHO, G = 1025.0, 9.81
DIAMETER, DEPTH = 0.5, 60.0


def element_case(z_low, z_high, waves=None, x=0.0):
    line = dict(diameter=DIAMETER, mass=200.0, axial_stiffness=1e9, drag_normal=0.0, drag_tangential=0.0,
                added_mass=0.0)
    env = {"depth": DEPTH, **({"waves": waves} if waves else {})}
    return Case.model_validate(dict(
        model="lumped", environment=env, line_types={"c": line},
        cables=[dict(name="e", line_type="c", length=z_high - z_low, segments=1,
                     **{"from": f"anchor:[{x}, 0, {z_low}]"}, to=f"anchor:[{x}, 0, {z_high}]")],
        simulation={"duration": 1.0, "dt": 0.01}))


def fluid_force(case, t):
    """The element's total load (both nodes), at rest and unstretched, less its weight in water."""
    net = build_network(case)
    system = LumpedSystem(net, case)
    x = net.x_guess.copy()
    F = system.loads(t, x, np.zeros_like(x), 0.0)[0]
    weight = net.el_weight[0] * net.el_length[0]
    return F.sum(axis=0) + np.array([0.0, 0.0, weight]), net


def pressure_gradient(point, t, height, period):
    """``-grad p`` [Pa/m] of Airy's dynamic pressure at ``point``, by central differences."""
    omega = 2 * math.pi / period
    k = omega**2 / G
    for _ in range(100):                                     # finite-depth dispersion, by fixed point
        k = omega**2 / (G * math.tanh(k * DEPTH))
    a = height / 2

    def p(x, z):
        return RHO * G * a * math.cosh(k * (z + DEPTH)) / math.cosh(k * DEPTH) * math.cos(k * x - omega * t)

    h = 1e-4
    x, _, z = point
    return -np.array([(p(x + h, z) - p(x - h, z)) / (2 * h), 0.0, (p(x, z + h) - p(x, z - h)) / (2 * h)])


@pytest.mark.parametrize("t", [0.0, 1.1, 2.9])
def test_a_vertical_element_feels_the_pressure_gradient_force(t):
    waves = {"type": "regular", "height": 3.0, "period": 7.0, "heading_deg": 0.0}
    case = element_case(-12.0, -10.0, waves, x=3.0)
    force, net = fluid_force(case, t)
    volume = math.pi * DIAMETER**2 / 4 * 2.0
    want = volume * pressure_gradient((3.0, 0.0, -11.0), t, 3.0, 7.0)
    assert abs(want[2]) > 100.0                                 # a real vertical (axial) force
    np.testing.assert_allclose(force, want, rtol=2e-3, atol=1e-3 * np.abs(want).max())


@pytest.mark.parametrize("low, high", [(-5.0, 5.0), (-8.0, 2.0), (-0.5, 9.5)])
def test_an_element_crossing_the_surface_keeps_the_buoyancy_of_its_wetted_part(low, high):
    force, net = fluid_force(element_case(low, high), 0.0)
    force[2] -= net.el_weight[0] * net.el_length[0]            # the total vertical load again
    area = math.pi * DIAMETER**2 / 4
    submerged = -low                                            # centreline length below z = 0
    want = RHO * G * area * submerged - 200.0 * G * (high - low)     # buoyancy of the wet part, full weight
    # kanat counts the element's vertical extent from half a diameter below to half above
    assert abs(force[2] - want) <= 0.5 * DIAMETER * RHO * G * area + 1e-6 * abs(want)
    if low == -5.0:
        assert force[2] == pytest.approx(want, rel=1e-12)        # symmetric: exact
