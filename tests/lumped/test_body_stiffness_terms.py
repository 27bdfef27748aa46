"""Every term of a body's 6x6 ``hydrostatic_stiffness`` acts, in network statics and in the lumped
model's equilibrium alike, and a roll-pitch block kanat would have to guess at is refused.

Oracle (linear hydrostatics, closed form): a 6-DOF body whose weight equals its buoyancy, held by a
weightless vertical line of stiffness ``k_c = EA / L`` under its reference point and pushed by a
small constant force ``F`` at that point, settles where ``K q = [F, 0, 0, 0]``, ``q`` its
displacement and small rotation (roll, pitch, yaw), ``K = C + k_c e_z e_z^T + L_WB`` with the levers
of weight and buoyancy ``L_WB = W (z_B - z_G)`` on roll and pitch when ``C`` has no roll and pitch
restoring (weight and buoyancy then turn the body at their centres), none when it has (``C`` holds
them, as a metacentric height does; :mod:`kanat.physics.hydrostatics` eq. 3). The line's own tilt
stiffness ``T / L`` is second order in ``F``; the rotations are 1e-6 to 1e-4 rad, so the closed form
holds to about 1e-4 of ``q``.
"""
import re

import numpy as np
import pytest

from kanat import api, load_case
from kanat.errors import CaseError

G, MASS, LINE_STIFFNESS, LINE_LENGTH = 9.81, 1000.0, 1.0e6, 40.0
FORCE = np.array([200.0, -100.0, 300.0])


def coupled_matrix(tilt: bool) -> np.ndarray:
    """A full 6x6, not symmetric (yaw couplings as WAMIT gives them, ``C46`` without ``C64``), with or
    without its roll-pitch block ``C44, C45, C54, C55``."""
    rng = np.random.default_rng(7)
    a = rng.normal(size=(6, 6))
    C = (a @ a.T + 6.0 * np.eye(6)) * 1.0e5
    C[3:, 3:] *= 100.0
    C[:3, 3:] *= 10.0
    C[3:, :3] *= 10.0
    C[3, 5] += 4.0e6                               # roll-yaw and pitch-yaw, one way only
    C[4, 5] -= 3.0e6
    if not tilt:
        C[3:5, 3:5] = 0.0
    return C


def body_case(model, stiffness, centre_of_gravity=(0.0, 0.0, 0.0), centre_of_buoyancy=(0.0, 0.0, 0.0)):
    return load_case({
        "name": "body-stiffness", "model": model,
        "line_types": {"rope": {"diameter": 0.05, "mass": 2.0, "weight_in_water": 0.0,
                                "axial_stiffness": LINE_STIFFNESS}},
        "bodies": {"buoy": {"dof": 6, "mass": MASS, "net_buoyancy": 0.0, "inertia": [1e4, 1e4, 1e4],
                            "center_of_gravity": list(centre_of_gravity),
                            "center_of_buoyancy": list(centre_of_buoyancy), "position": [0.0, 0.0, -10.0],
                            "hydrostatic_stiffness": np.asarray(stiffness).tolist(), "force": FORCE.tolist()}},
        "cables": [{"name": "leg", "line_type": "rope", "length": LINE_LENGTH, "segments": 2,
                    "from": "anchor:[0, 0, -50]", "to": {"body": "buoy"}}],
        "simulation": {"duration": 1.0, "dt": 0.1}})


def settled(case):
    """``q`` (6,): the body's displacement [m] and its roll, pitch, yaw [rad], by network statics for
    ``model: statics``, else by the lumped model's initial equilibrium."""
    if case.model == "statics":
        ds = api.solve_statics(case)
        position, attitude = ds["body_position"].values[0], ds["body_attitude"].values[0]
    else:
        model = api.dynamic_model(case)
        out = model.outputs(model.initial())
        position, attitude = out["body_position"][0], out["body_attitude"][0]
    return np.concatenate([position - [0.0, 0.0, -10.0], attitude])


def closed_form(C, levers=0.0):
    K = np.array(C, dtype=float)
    K[2, 2] += LINE_STIFFNESS / LINE_LENGTH
    K[3, 3] += levers
    K[4, 4] += levers
    return np.linalg.solve(K, np.concatenate([FORCE, np.zeros(3)]))


CASES = {"full matrix with tilt restoring": (True, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 0.0),
         "couplings without tilt restoring": (False, (0.0, 0.0, -2.0), (0.0, 0.0, 1.0), MASS * G * 3.0)}


@pytest.mark.parametrize("model", ["statics", "lumped"])
@pytest.mark.parametrize("tilt, cog, cob, levers", CASES.values(), ids=CASES.keys())
def test_every_term_of_the_stiffness_moves_the_body_as_the_linear_closed_form(model, tilt, cog, cob, levers):
    C = coupled_matrix(tilt)
    expected = closed_form(C, levers)
    q = settled(body_case(model, C, cog, cob))
    assert np.all(np.abs(expected[3:]) > 1e-7)                     # every rotation is there to see
    np.testing.assert_allclose(q[:3], expected[:3], rtol=0, atol=2e-4 * np.max(np.abs(expected[:3])))
    np.testing.assert_allclose(q[3:], expected[3:], rtol=0, atol=2e-4 * np.max(np.abs(expected[3:])))


def _matrix_with(**terms) -> list[list[float]]:
    """A 6x6 with a heave spring and ``terms`` such as ``C44=2e6`` (1-based indices, as the docs write them)."""
    C = np.zeros((6, 6))
    C[2, 2] = 1.0e5
    for name, value in terms.items():
        C[int(name[1]) - 1, int(name[2]) - 1] = value
    return C.tolist()


REFUSED = {"roll without pitch": (_matrix_with(C44=2.0e6), r"C44 \(roll\) = 2000000 N m/rad but C55 \(pitch\) = 0"),
           "pitch without roll": (_matrix_with(C55=3.0e6, C36=1.0e4), r"C55 \(pitch\) = 3000000 N m/rad but C44"),
           "roll-pitch terms alone": (_matrix_with(C45=5.0e5, C54=5.0e5),
                                      r"roll-pitch terms \(C45 = 500000, C54 = 500000\) without roll and pitch")}


@pytest.mark.parametrize("matrix, words", REFUSED.values(), ids=REFUSED.keys())
def test_a_roll_pitch_block_the_lever_switch_would_misread_is_refused_naming_the_key_and_terms(matrix, words):
    with pytest.raises(CaseError, match="hydrostatic_stiffness") as error:
        body_case("lumped", matrix)
    assert re.search(words, str(error.value)), str(error.value)
