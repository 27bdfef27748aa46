"""Spherical inline floats in the lumped model (``bodies.<name>.diameter``): their buoyancy follows
their immersion, :mod:`kanat.physics.immersion` eq. (1), in the equilibrium and in a run.

The case: a 0.5 m spherical float (10 kg) clamped 20 m up a soft vertical tether from an anchor
20.25 m down, a 0.5 m tail above it to a small body pulled up by 5 N. The tether's stretch puts the
float at the surface, where its immersed share balances the tension. Oracle, in closed form (one
equation solved by brentq): the float's height ``z = -depth + s_f + (T_f s_f - w s_f^2 / 2) / EA``
with the tension under it ``T_f = f(z) B_f - m g + F - m_e g - W_tail``, ``f`` the cap's share of the
sphere (written out here), and the tail's weight ``W_tail = (w + (1 - phi) rho g A) l_tail`` with
``phi`` its wetted fraction (the lumped model's law for an element through the surface: the share of
its height, widened by its diameter, under the surface). The lumped elements give the exact stretch
of the continuous line here: their tensions are the line's at their midpoints, linear in ``s``.
"""
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import kanat

from helpers_float import AREA_WEIGHT, D, DEPTH, DL, EA, FE, FULL, G, ME, MF, SF, TOP, W, tethered_float


def cap_share(z, eta):
    """The submerged cap's share of the float: cap height h = clip(eta - z + a, 0, D) holds
    pi h^2 (3a - h) / 3 of the sphere's 4 pi a^3 / 3."""
    a = D / 2
    h = min(max(eta - z + a, 0.0), D)
    return h * h * (3 * a - h) / (4 * a**3)


def waterline(eta=0.0):
    """The float's height [m] (module docstring)."""
    def gap(z):
        tail_tension = FE - ME * G                                   # about: the tail's stretch is ~1e-5 m
        for _ in range(3):
            top_z = z + TOP * (1.0 + tail_tension / EA)
            phi = min(max((eta - (z - DL / 2)) / (top_z - z + DL), 0.0), 1.0)
            tail = (W + (1.0 - phi) * AREA_WEIGHT) * TOP
            tail_tension = FE - ME * G - tail / 2
        below = FULL * cap_share(z, eta) - MF * G + FE - ME * G - tail
        return -DEPTH + SF + (below * SF - W * SF**2 / 2) / EA - z
    return brentq(gap, -2.0, 2.0, xtol=1e-14)


def run(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                    # the small pulling body above the water
        return kanat.simulate(case)


def test_lumped_float_floats_at_its_waterline():
    z = waterline()
    assert 0.0 < cap_share(z, 0.0) < 1.0                              # at the surface, partly immersed
    ds = run(tethered_float("lumped"))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    assert float(ds["body_position"].sel(body="float").values[0, 2]) == pytest.approx(z, abs=1e-9)   # 2e-16 m


def test_lumped_float_without_a_diameter_is_refused_above_the_water():
    """Without its diameter the float keeps its full net buoyancy out of the water, and the tether's
    stretch under it puts it ~0.26 m above the surface (``z = -depth + s_f + (T_f s_f - w s_f^2 / 2) /
    EA`` with all of ``B_f`` and the tail in the air, to 1 mm: the element under the float is half out
    of the water too): the run refuses that
    state at t = 0, naming the float and where it is, and what to give it instead."""
    case = tethered_float("lumped")
    bodies = {n: b.model_dump(exclude_none=True) for n, b in case.bodies.items()}
    bodies["float"].pop("diameter")
    status = run(case.replace({"bodies": bodies})).attrs["status"]
    tail = (W + AREA_WEIGHT) * TOP                                 # in the air
    z = -DEPTH + SF + ((FULL - MF * G + FE - ME * G - tail) * SF - W * SF**2 / 2) / EA
    assert status.startswith("failed: bodies: body 'float' at (0, 0, ")
    assert "above the water surface" in status and "a float with a diameter" in status
    height = float(status.split(") m is ")[1].split(" ")[0])
    assert height == pytest.approx(z, abs=1e-3)     # the element under it: half of it (0.8 N) in the air
    assert z - waterline() > 0.25


@pytest.mark.slow
def test_lumped_float_follows_a_long_wave():
    """A 0.1 m, 40 s wave: the float (heave period ~0.5 s) rides it quasi-statically, at the waterline
    of the wave's elevation over it, ``eta = 0.05 cos(2 pi t / 40)`` at x = 0, once the start's
    transient (the run starts from the still-water state) has died out: the compiled kernels' floats."""
    waves = {"type": "regular", "height": 0.1, "period": 40.0, "heading_deg": 0}
    ds = run(tethered_float("lumped", 20.0, 0.05, waves))
    assert ds.attrs["status"] == "ok", ds.attrs["status"]
    z = ds["body_position"].sel(body="float").values[:, 2]
    late = ds.time.values >= 15.0
    expected = np.array([waterline(0.05 * math.cos(2 * math.pi * t / 40.0)) for t in ds.time.values[late]])
    assert np.max(np.abs(z[late] - expected)) < 2e-3      # 0.6 mm
    assert np.min(np.abs(expected - waterline())) > 0.02     # the still-water height is 10x that away


@pytest.mark.parametrize("lift", [-0.3, 0.0, 0.2, 0.6])
def test_compiled_float_loads_match_the_python_twin(lift):
    """The compiled right-hand side (:func:`kanat.lumped.fast.float_loads`) against the Python path's
    (:meth:`kanat.lumped.system.LumpedSystem.loads`) in a 1 m wave, with the tether lifted by ``lift``
    [m] so that the float is under, at and above the surface, its nodes stirred."""
    from kanat.lumped import fast
    from kanat.lumped.advance import FusedArrays, track_samples
    from kanat.lumped.equilibrium import equilibrium
    from kanat.lumped.network import build_network
    from kanat.lumped.system import LumpedSystem

    case = tethered_float("lumped", waves={"type": "regular", "height": 1.0, "period": 6.0, "heading_deg": 30.0})
    net = build_network(case)
    x = equilibrium(net, case)[0]
    x[net.free, 2] += lift
    system = LumpedSystem(net, case)
    v = np.random.default_rng(2).normal(0.0, 0.3, x.shape)
    arrays, free = FusedArrays(system), system.free_index
    for t in (0.7, 2.9):
        y = np.concatenate([x[free].ravel(), v[free].ravel()])
        dy = np.zeros_like(y)
        fast.derivative_at(t, y, 0, track_samples(system, np.array([t])), arrays.nodes, arrays.el, arrays.bodies,
                           arrays.env, arrays.work, dy)
        want = system.rhs(t, y)
        np.testing.assert_allclose(dy, want, rtol=1e-11, atol=1e-11 * np.max(np.abs(want)))
