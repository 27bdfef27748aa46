"""Wheeler stretching (``environment.waves.stretching: wheeler``, kanat.physics.waves eq. 7)
against its definition and against MoorDyn-C's own summed components (``WaveKin 7``), which
stretch the kinematics so; and its way into both models' water."""
import math
import warnings
from dataclasses import replace

import numpy as np
import pytest

from kanat.continuum import kernels2d as k
from kanat.continuum.model2d import planar_cable
from kanat.continuum.water import planar_water
from kanat.io import load_case
from kanat.model import Case
from kanat.physics.waves import regular_wave, sea_from_model

from helpers import EXAMPLES, quiet

WAVES_FOLDER = EXAMPLES / "moordyn" / "waves"
DEPTH = 30.0


@pytest.mark.parametrize("depth", [DEPTH, None])
@pytest.mark.parametrize("t", [0.0, 1.3, 4.1])
def test_the_column_under_the_surface_is_stretched_onto_the_still_one(depth, t):
    """Eq. (7): the surface takes the z = 0 kinematics, the seabed (or, in deep water, a point a
    fixed distance under the surface) its own, a point between them those of the point as far
    between z = 0 and the seabed; above the surface, the surface's."""
    plain = regular_wave(4.0, 6.0, 30.0, depth=depth)
    wheeler = replace(plain, stretching="wheeler")
    x, y = np.array([3.0, -7.0]), np.array([1.0, 12.0])
    eta = plain.elevation(x, y, t)
    h = 1e4 if depth is None else depth

    def at(sea, z):
        return sea.velocity(np.column_stack([x, y, z]), t), sea.acceleration(np.column_stack([x, y, z]), t)

    fraction = 0.3                                     # of the way down from the surface to the seabed
    pairs = [(eta, np.zeros(2)), (eta + 2.5, np.zeros(2)),
             (eta - fraction * (h + eta), np.full(2, -fraction * h))]
    if depth is not None:
        pairs.append((np.full(2, -h), np.full(2, -h)))
    else:
        pairs.append((eta - 12.0, np.full(2, -12.0)))
    for z, z_still in pairs:
        for ours, want in zip(at(wheeler, z), at(plain, z_still)):
            np.testing.assert_allclose(ours, want, rtol=1e-12, atol=1e-12)


def test_wheeler_stretching_is_moordyns_summed_components(moordyn, moordyn_folder):
    """kanat's import of a WaveKin 7 file (``stretching: wheeler``) against MoorDyn's own
    kinematics (``GetWavesKin``) at points under crests and troughs, at several times."""
    path = moordyn_folder(*(WAVES_FOLDER / name for name in ("taut_line_in_waves.dat", "wave_frequencies.txt")))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                   # a taut line between fixed points must stretch
        case = load_case(path)
    assert case.environment.waves.stretching == "wheeler"     # as the importer writes it
    sea = sea_from_model(case.environment)
    points = [(2.0, 1.0, z) for z in (0.5, 0.0, -1.0, -5.0, -20.0, -60.0)] + [(-13.0, 4.0, -0.8)]
    dt, compared = 0.1, 0
    with quiet():
        system = moordyn.Create(str(path))
        moordyn.Init(system, [], [])
        waves = moordyn.GetWaves(system)
        t = 0.0
        for target in (3.3, 7.1, 11.9):
            while t < target - 1e-9:
                moordyn.Step(system, [], [], t, dt)
                t += dt
            for point in points:
                u, ud, zeta, _ = moordyn.GetWavesKin(waves, *point)
                p = np.array([point])
                assert zeta == pytest.approx(sea.elevation(p[:, 0], p[:, 1], t)[0], abs=1e-9)
                np.testing.assert_allclose(sea.velocity(p, t)[0], u, rtol=1e-7, atol=1e-9)
                np.testing.assert_allclose(sea.acceleration(p, t)[0], ud, rtol=1e-7, atol=1e-9)
                compared += 1
        moordyn.Close(system)
    assert compared == 3 * len(points)


def test_the_continuum_water_is_stretched():
    """A continuum cable's water (kanat.continuum.water) takes the stretched kinematics: at a node
    on the surface, those of z = 0."""
    case = Case.model_validate(dict(
        model="continuum", environment={"depth": DEPTH, "waves": {"type": "regular", "height": 4.0, "period": 6.0,
                                                                   "stretching": "wheeler"}},
        line_types={"c": dict(diameter=0.05, mass=4.0, axial_stiffness=1e6, drag_normal=1.2)},
        cables=[dict(name="c", line_type="c", length=40.0, segments=8, **{"from": "anchor:[0, 0, -30]"},
                     to="anchor:[10, 0, -1]")],
        simulation=dict(duration=1.0, dt=0.1)))
    cable = planar_cable(case)
    t = 2.2
    eta = regular_wave(4.0, 6.0, depth=DEPTH).elevation(np.array([4.0]), np.array([0.0]), t)[0]
    xz = np.array([[4.0, eta], [4.0, -DEPTH], [4.0, eta + 1.0]])
    env = planar_water(cable, xz, np.zeros_like(xz), t, 0.0, (0.0, 0.0, 1.0))
    plain = regular_wave(4.0, 6.0, depth=DEPTH)
    still = plain.velocity(np.array([[4.0, 0.0, 0.0], [4.0, 0.0, -DEPTH], [4.0, 0.0, 0.0]]), t)
    np.testing.assert_allclose(env[:, [k.UX, k.UZ]], still[:, [0, 2]], rtol=1e-12, atol=1e-12)
    assert abs(still[0, 0]) > 0.1 and not math.isclose(eta, 0.0, abs_tol=0.1)   # a crest or trough, moving water
