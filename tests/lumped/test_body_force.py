"""The lumped model's ``body_force``: the force the line ends exert on a point body itself, eq. (O1) of
:mod:`kanat.lumped.mooring_outputs` (``M_b a - F_b``), not the load of the node that also carries half
of each element next to the body.

Oracles:

* closed form at rest: a body held in a current by its lines carries ``-(B z + 0.5 rho C_D S |u| u)``
  (net buoyancy and drag in the current at its depth), to round-off: the subsurface mooring's
  bodies, and a tethered float with a clump, submerged or, as a sphere, at the surface (its
  buoyancy the immersed cap's share);
* the continuum model side by side (whose ``body_force`` is the line's end force ``T t + S``): the
  subsurface mooring's two bodies;
* closed form in motion: a weight hanging on a short stiff wire under a heaving vessel moves with the
  vessel, so the wire pulls it with ``(m + m_a) a_z - B + 0.5 rho C_D S |v_z| v_z``.
"""
import math
import warnings

import numpy as np
import pytest

import kanat
from kanat.model import Case

from helpers import EXAMPLES

PROFILE = np.array([[0, 0.6, 0.3, 0], [-100, 0.45, 0.2, 0], [-300, 0.2, 0.05, 0], [-500, 0.05, 0.0, 0]])


def quietly(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args, **kwargs)


def held_force(body, z, density=1025.0):
    """``-(B z + 0.5 rho C_D S |u| u)``, ``u`` the subsurface mooring's current at height ``z``."""
    current = np.array([np.interp(z, PROFILE[::-1, 0], PROFILE[::-1, j]) for j in (1, 2, 3)])
    return -(np.array([0.0, 0.0, body.net_buoyancy]) + 0.5 * density * body.drag_area * np.linalg.norm(current)
             * current)


@pytest.mark.slow
def test_the_subsurface_moorings_bodies_carry_their_buoyancy_and_drag_in_both_models():
    """At rest in the sheared current: the lumped figure is the closed form to 1e-9 of the net
    buoyancy (the half elements' weight and drag, 6-10 N, are no longer in it; measured 8e-9 N), and
    the continuum model's within 0.01 N (measured 2e-4 N: the bodies sit 0.15 m apart in the two
    models, in a current that changes 1.5e-3 m/s per metre)."""
    case = kanat.load_case(EXAMPLES / "subsurface_mooring.yaml").replace(
        {"simulation.duration": 1.0, "simulation.output_dt": 0.5})
    lumped = quietly(kanat.simulate, case.replace({"model": "lumped", "simulation.scheme": None,
                                                   "simulation.dt": None}))
    continuum = quietly(kanat.simulate, case)
    assert lumped.attrs["status"] == "ok" and continuum.attrs["status"] == "ok"
    for name in ("glass_balls", "top_buoy"):
        body = case.bodies[name]
        force = lumped.body_force.sel(body=name).values
        z = lumped.body_position.sel(body=name).values[:, 2]
        for k in range(len(z)):
            assert np.linalg.norm(force[k] - held_force(body, z[k])) <= 1e-9 * body.net_buoyancy
        gap = force[-1] - continuum.body_force.sel(body=name).values[-1]
        assert np.linalg.norm(gap) < 0.01, (name, gap)


def heaving_weight(amplitude, period):
    wire = dict(diameter=0.03, mass=8.0, weight_in_water=60.0, axial_stiffness=1e8, axial_damping=1e5,
                drag_normal=1.2, drag_tangential=0.01, added_mass=0.7)
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 100.0}, line_types={"wire": wire},
        bodies={"weight": {"mass": 500.0, "added_mass": 250.0, "net_buoyancy": -4000.0, "drag_area": 0.5}},
        vessel={"motion": [{"dof": "heave", "amplitude": amplitude, "period": period, "phase_deg": 90.0}]},
        cables=[dict(name="hoist", line_type="wire", length=20.0, segments=4, **{"from": {"vessel": [0.0, 0.0, 0.0]}},
                     to="weight")],
        simulation={"duration": 12.0, "output_dt": 0.25, "dt": 0.01}))


@pytest.mark.slow
def test_a_weight_under_a_heaving_vessel_is_pulled_with_its_inertia_buoyancy_and_drag():
    """Heave ``A cos(w t)`` (1 m, 8 s) of a 500 kg weight (250 kg added mass, 4 kN in water, C_D S
    0.5 m^2) on 20 m of stiff wire: after the start's axial ringing (4 s), ``body_force_z`` is
    ``(m + m_a) a_z - B + 0.5 rho C_D S |v_z| v_z`` with the vessel's ``a_z, v_z`` to 1 N of its 925 N
    swing (measured 0.16 N); the wire's end tension, which also carries the half element next to the
    weight (40 kg of wire and its drag), is 160 N off."""
    amplitude, period = 1.0, 8.0
    ds = quietly(kanat.simulate, heaving_weight(amplitude, period))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    t = ds.time.values
    w = 2.0 * math.pi / period
    a_z, v_z = -amplitude * w * w * np.cos(w * t), -amplitude * w * np.sin(w * t)
    expected = 750.0 * a_z + 4000.0 + 0.5 * 1025.0 * 0.5 * np.abs(v_z) * v_z
    force = ds.body_force.sel(body="weight").values[:, 2]
    settled = t > 4.0
    assert np.ptp(expected) > 900.0
    assert np.max(np.abs(force - expected)[settled]) < 1.0
    end_tension = ds.segment_tension.values[:, -1]
    assert np.max(np.abs(end_tension - expected)[settled]) > 100.0              # the half element's share


def float_on_a_tether(with_diameter):
    """A 40 m tether (8 elements) from an anchor 50 m down to a float, a clump at its middle, in a
    0.5 m/s current. With ``with_diameter`` the float is a 1 m sphere whose buoyancy follows its
    immersion, inline at s = 52 m (at the surface: the 780 N it holds up take a sixth of its
    buoyancy), and the clump hangs from it on a 6 m tail."""
    tether = dict(diameter=0.02, mass=1.5, weight_in_water=10.0, axial_stiffness=1e6, drag_normal=1.2,
                  drag_tangential=0.01)
    buoy = {"mass": 20.0, "net_buoyancy": 600.0, "drag_area": 0.3}
    cable = dict(name="tether", line_type="tether", length=40.0, segments=8, **{"from": "anchor:[0, 0, -50]"},
                 to="buoy", attachments=[{"body": "clump", "s": 20.0}])
    if with_diameter:                   # full buoyancy: the sphere's displaced water, 5265 N
        buoy.update(diameter=1.0, net_buoyancy=1025.0 * 9.81 * math.pi / 6 - 20.0 * 9.81)
        cable.update(length=58.0, segments=10, to="clump", attachments=[{"body": "buoy", "s": 52.0}])
    return Case.model_validate(dict(
        model="lumped", environment={"depth": 50.0, "current": {"velocity": [0.5, 0.0, 0.0]}},
        line_types={"tether": tether},
        bodies={"buoy": buoy, "clump": {"mass": 30.0, "net_buoyancy": -200.0, "drag_area": 0.05}},
        cables=[cable], simulation={"duration": 0.1, "output_dt": 0.1, "dt": 0.1}))


@pytest.mark.parametrize("with_diameter", [False, True], ids=["submerged", "at-the-surface"])
def test_a_tethered_floats_lines_hold_its_buoyancy_and_drag(with_diameter):
    """At rest in the current, the line ends' force on the float and on the clump is
    ``-(B z + 0.5 rho C_D S |u| u)``, with, for the spherical float at the surface, ``B`` its net
    buoyancy less the share ``1 - f`` of its full buoyancy out of the water (``f`` the cap's volume
    fraction, :mod:`kanat.physics.immersion` eq. 1, computed here from the float's height), to 1e-6 N
    (the equilibrium's residual)."""
    case = float_on_a_tether(with_diameter)
    ds = quietly(kanat.simulate, case)
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    for name in ("buoy", "clump"):
        body = case.bodies[name]
        z = float(ds.body_position.sel(body=name).values[0, 2])
        lift = body.net_buoyancy
        if body.diameter is not None:
            h = min(max(0.5 - z, 0.0), 1.0)                  # the submerged cap's height, diameter 1 m
            share = h * h * (1.5 - h) / 0.5                  # pi h^2 (3a - h) / 3 over 4 pi a^3 / 3, a = 0.5
            assert 0.0 < share < 1.0                          # it floats at the surface
            lift -= (1.0 - share) * body.buoyancy(9.81)
        expected = -np.array([0.5 * 1025.0 * body.drag_area * 0.25, 0.0, lift])
        assert np.linalg.norm(ds.body_force.sel(body=name).values[0] - expected) < 1e-6, name
