"""Two coupled bodies sharing a line, each driven by its own six components through
``kanat.Coupling(file, rigid_vessel=True)`` (eq. (2b) of :mod:`kanat.coupling`, MoorDyn-C's
coupled bodies), the file written by MoorPy (tests/peers/test_shared_bodies.py).

Oracles:

* the same coupling driven point by point (``rigid_vessel=False``, itself the prescribed-motion run
  to round-off: tests/lumped/test_coupling.py) with the points placed by eq. (2b) in the test: the same
  forces, and each body's resultant and moment, to round-off: at an equilibrium with both bodies
  turned, and over steps of each body drifting on its own;
* MoorDyn-C's own coupling of the same file (PyPI ``moordyn``, RK2 at the file's 1 ms) driven by the
  same motions: each body surging, swaying, heaving, pitching and yawing from rest over 30 s.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

pytest.importorskip("moorpy")

import kanat  # noqa: E402
from kanat.coupling import moordyn_rotations  # noqa: E402
from kanat.errors import KanatError  # noqa: E402

from helpers_moordyn import run_moordyn, secant  # noqa: E402
from test_shared_bodies import LAYOUTS, write_shared_array  # noqa: E402

OFFSETS = {"body1": np.array([[8.0, 2.0, -12.0], [-8.0, 0.0, -12.0]]),      # the points in each body's axes,
           "body2": np.array([[6.0, -3.0, -12.0], [-8.0, 0.0, -12.0]])}     # as written by write_shared_array


def _rest(layout: str) -> np.ndarray:
    """Both bodies' ``(x, y, z, roll, pitch, yaw)`` (2, 6) at rest, as in the file."""
    return np.array([[*r6[:3], *np.radians(r6[3:])] for r6 in LAYOUTS[layout]], float)


def _coupling(path, rigid: bool) -> kanat.Coupling:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.Coupling(path, rigid_vessel=rigid)


def _placed(q: np.ndarray, coupling: kanat.Coupling) -> np.ndarray:
    """The point-by-point coupling's points (in its ``points`` order) for the bodies at ``q`` (2, 6):
    ``X + Rx Ry Rz o``, matched to the points by their place at rest."""
    rest = _rest("turned")
    placed_now, placed_rest = [], []
    for b, name in enumerate(("body1", "body2")):
        placed_now.append(q[b, :3] + OFFSETS[name] @ moordyn_rotations(q[b, 3:][None])[0].T)
        placed_rest.append(rest[b, :3] + OFFSETS[name] @ moordyn_rotations(rest[b, 3:][None])[0].T)
    now, at_rest = np.concatenate(placed_now), np.concatenate(placed_rest)
    arms = coupling.net.vessel_offset
    order = [int(np.argmin(np.linalg.norm(at_rest - arm, axis=1))) for arm in arms]
    return now[order]


def _body_loads(forces, points, q) -> np.ndarray:
    """Each body's resultant and moment about its reference point (2, 6) from the points' forces."""
    out = np.zeros((2, 6))
    for f, r in zip(forces, points):
        b = int(np.argmin(np.linalg.norm(q[:, :3] - r, axis=1)))          # the nearer reference point
        out[b] += np.concatenate([f, np.cross(r - q[b, :3], f)])
    return out


@pytest.fixture(scope="module")
def turned(tmp_path_factory):
    path = tmp_path_factory.mktemp("array") / "turned.dat"
    write_shared_array("turned", path, segments=20)
    return path


def test_each_body_is_driven_by_its_own_six_components(turned):
    coupling = _coupling(turned, rigid=True)
    assert coupling.points == ["body1", "body2"]
    with pytest.raises(KanatError, match=r"shape \(2, 6\)"):
        coupling.initialize(np.zeros((1, 6)))


def test_a_turned_equilibrium_is_the_point_by_point_one(turned):
    q = _rest("turned") + np.array([[2.0, -1.0, 0.3, 0.02, -0.01, 0.05], [-3.0, 1.5, -0.2, -0.01, 0.03, -0.04]])
    bodies, points = _coupling(turned, rigid=True), _coupling(turned, rigid=False)
    where = _placed(q, points)
    loads = bodies.initialize(q)
    forces = points.initialize(where)
    expected = _body_loads(forces, where, q)
    np.testing.assert_allclose(loads, expected, rtol=0, atol=1e-9 * np.max(np.abs(expected)))
    np.testing.assert_allclose(bodies.nodes()[0], points.nodes()[0], rtol=0, atol=1e-9)


def test_bodies_drifting_apart_are_the_point_by_point_run_to_round_off(turned):
    """Body 1 drifts at (0.2, -0.1, 0.05) m/s, body 2 at (-0.15, 0.1, 0) m/s: the points of each move
    with it (eq. (1) and (2b) agree for a translation), 10 steps of 0.1 s."""
    rate = np.array([[0.2, -0.1, 0.05, 0.0, 0.0, 0.0], [-0.15, 0.1, 0.0, 0.0, 0.0, 0.0]])
    bodies, points = _coupling(turned, rigid=True), _coupling(turned, rigid=False)
    q0, dt = _rest("turned"), 0.1
    start = _placed(q0, points)
    velocity = _placed(q0 + rate, points) - start
    bodies.initialize(q0, rate)
    points.initialize(start, velocity)
    for k in range(10):
        q = q0 + k * dt * rate
        loads = bodies.step(k * dt, dt, q, rate)
        forces = points.step(k * dt, dt, start + k * dt * velocity, velocity)
        expected = _body_loads(forces, start + (k + 1) * dt * velocity, q + dt * rate)
        np.testing.assert_allclose(loads, expected, rtol=0, atol=1e-9 * np.max(np.abs(expected)))
    np.testing.assert_allclose(bodies.nodes()[0], points.nodes()[0], rtol=0, atol=1e-9)


@pytest.mark.slow
def test_two_bodies_agree_with_moordyns_own_coupling(turned, tmp_path):
    """Body 1 (heading 30 deg) surges 4 m, heaves 0.5 m and yaws 2 deg; body 2 (heading 200 deg) sways
    3 m, heaves 0.8 m and pitches 1 deg (half cosines of periods 10 to 25 s, from rest), every 0.05 s
    for 30 s, in kanat and in MoorDyn-C: each force component within 1 % of the largest force, each
    moment within 1 % of the largest moment (measured: 0.39 % and 0.45 %)."""
    moordyn = pytest.importorskip("moordyn")
    copy = tmp_path / turned.name                            # MoorDyn writes its outputs beside its input
    copy.write_text(turned.read_text())
    amplitude = np.array([[4.0, 0.0, 0.5, 0.0, 0.0, math.radians(2.0)],
                          [0.0, 3.0, 0.8, 0.0, math.radians(1.0), 0.0]])
    period = np.array([[20.0, 1.0, 10.0, 1.0, 1.0, 15.0], [1.0, 25.0, 12.0, 1.0, 14.0, 1.0]])
    rest, dt, steps = _rest("turned"), 0.05, 600

    def q(t):
        return rest + amplitude * (1.0 - np.cos(2.0 * math.pi * t / period)) / 2.0

    coupling = _coupling(turned, rigid=True)
    coupling.initialize(q(0.0))
    rate = secant(q, dt)
    ours = np.array([coupling.step(k * dt, dt, q(k * dt), rate(k * dt)) for k in range(steps)])
    _, theirs = run_moordyn(moordyn, copy, steps * dt, dt, point=lambda t: q(t).ravel(), forces=True)
    theirs = theirs[:, 1:].reshape(-1, 2, 6)
    force, moment = np.max(np.abs(theirs[..., :3])), np.max(np.abs(theirs[..., 3:]))
    difference = np.max(np.abs(ours - theirs), axis=0)
    assert np.all(difference[:, :3] < 0.01 * force)
    assert np.all(difference[:, 3:] < 0.01 * moment)
    assert np.ptp(theirs[:, 1, 4]) > 0.05 * moment                   # body 2's pitch moment was exercised
