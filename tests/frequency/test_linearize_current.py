"""``kanat.linearize`` in a current with a start-up ramp: about the steady state after the ramp.

A taut horizontal string across a uniform current ``U`` (along y): at an interior node the drag's
slope about the mean flow is ``rho C_n d l U`` along the flow and ``rho C_n d l U / 2`` across it
in the normal plane (``d/dv (|v| v) = 2 |U|`` along ``U``, ``|U|`` across), ``l`` the node's length
of line (the two half elements lumped to it). A ramped current linearises as the unramped one, not
as still water (whose ``C`` has no drag).
"""
import warnings

import numpy as np
import pytest

import kanat
from kanat.model import Case

RHO, CD, DIAMETER, SPEED, SEGMENTS, LENGTH = 1025.0, 1.2, 0.05, 1.0, 10, 100.0


def string(ramp: float, speed: float = SPEED) -> Case:
    return Case.model_validate({
        "name": "string", "model": "lumped",
        "environment": {"water_density": RHO, "current": {"velocity": [0.0, speed, 0.0],
                                                          "ramp": ramp}},
        "line_types": {"s": {"diameter": DIAMETER, "mass": 5.0, "weight_in_water": 0.0, "axial_stiffness": 1e7,
                             "drag_normal": CD, "drag_tangential": 0.0, "added_mass": 0.0}},
        "cables": [{"name": "string", "line_type": "s", "length": LENGTH, "segments": SEGMENTS,
                    "from": {"anchor": [0.0, 0.0, -50.0]}, "to": {"anchor": [1.01 * LENGTH, 0.0, -50.0]}}],
        "simulation": {"duration": 100.0}})


def test_a_ramped_current_linearises_at_its_full_speed():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ramped, steady, still = (kanat.linearize(string(ramp, speed)) for ramp, speed in
                                 ((20.0, SPEED), (0.0, SPEED), (0.0, 0.0)))
    C = ramped.damping.toarray()
    np.testing.assert_allclose(C, steady.damping.toarray(), atol=1e-9 * np.abs(C).max())
    assert np.abs(still.damping.toarray()).max() < 1e-3 * np.abs(C).max()
    middle = np.flatnonzero(ramped.node == ramped.node[len(ramped.node) // 2])        # an interior node's DOFs
    along = RHO * CD * DIAMETER * LENGTH / SEGMENTS * SPEED
    assert C[middle[1], middle[1]] == pytest.approx(along, rel=0.02)       # y: along the flow
    assert C[middle[2], middle[2]] == pytest.approx(along / 2, rel=0.02)   # z: across it, normal to the line
