"""Network statics of a yawed 6-DOF buoy on its waterplane side by side with MoorPy 1.3, run live.

The buoy of examples/mooring_3leg.yaml (frictionless: MoorPy's ``System`` applies none), pushed
sideways by a constant force so that it rolls and pitches by degrees, with its anchors, its force
and its hydrostatic reference turned by 0, 30, 45 and -45 deg about the vertical (MoorPy 1.3's
``solveEquilibrium`` stops short of its tolerance on this body from 60 deg on, measured; the turns
to 90, 180 and 270 deg are tests/statics/test_network_yaw.py's, against the unturned system). MoorPy restores
roll and pitch by the turning weight and buoyancy, its ``rM`` at the metacentre
(tests/moorpy_systems.py): ``C44 (z_b x e_z)``, the righting moment of the body's actual tilt
whatever its yaw, which is kanat's restoring (kanat.physics.hydrostatics); its heave spring is
``rho g A_w z``. The equilibria (reference point, roll, pitch, yaw) and the fairlead tensions
agree to round-off (measured: 3.5e-10 m, 2.4e-11 rad, tensions 1.3e-11).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from kanat.statics import solve_statics

from helpers import turned_mooring_buoy
from moorpy_systems import assert_body_is_moorpys

pytest.importorskip("moorpy")

PUSH = np.array([1.5e5, 0.6e5, 0.0])      # N: a constant force on the buoy, off the legs' axes


def turned_buoy(degrees: float):
    """The frictionless, pushed buoy with everything turned by ``degrees`` about the vertical."""
    return turned_mooring_buoy(degrees, {"environment.seabed.friction": 0.0, "bodies.buoy.force": PUSH})[0]


@pytest.mark.parametrize("degrees", [0.0, 30.0, 45.0, -45.0])
def test_a_yawed_buoy_is_moorpys(degrees):
    case = turned_buoy(degrees)
    result = solve_statics(case)
    attitude = result.attitudes["buoy"]
    assert abs(attitude[1]) > math.radians(3.0)                    # a tilt worth the name
    assert_body_is_moorpys(case, result)
