"""Clamped ends in the lumped model (kanat.lumped.clamps): a cantilever against Euler-Bernoulli, a
tensioned beam clamped at both ends or at one against the tensioned-beam equation, a clamp that turns
with the vessel, the anchor's reaction, and the ends that cannot be clamped."""
import math
import warnings
from typing import ClassVar

import numpy as np
import pytest
import yaml

from kanat import api
from kanat.errors import CaseError
from kanat.io import load_case
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.integrators import RK4
from kanat.lumped.mooring_outputs import anchor_forces
from kanat.lumped.network import build_network
from kanat.model import Case
from kanat.physics.motion import rotation_matrix

from helpers import quiet

LENGTH, WEIGHT, EI = 10.0, 1.0, 1.0e4          # m, N/m, N m^2: the cantilever's tip deflects 1.25 % of L


def case_of(tmp_path, cable: dict, line: dict, name="beam", **extra):
    """A lumped case of one cable of line type ``line`` in 200 m of still water."""
    case = {"name": name, "model": "lumped", "environment": {"depth": 200.0},
            "line_types": {"beam": {"diameter": 0.05, "mass": 0.5, "drag_normal": 1.0, **line}},
            "cables": [{"name": "beam", "line_type": "beam", **cable}],
            "simulation": {"duration": 1.0, "output_dt": 0.1}, **extra}
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump(case, sort_keys=False))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path)


def cantilever(tmp_path, segments, top=None, motion=None, direction=(1.0, 0.0, 0.0)):
    """A beam clamped along ``direction`` (horizontal along x) at an anchor 5 m down (or at the vessel
    point ``top``), free tip."""
    root = {"anchor": [0.0, 0.0, -5.0]} if top is None else {"vessel": top}
    extra = {} if motion is None else {"vessel": {"motion": motion}}
    return case_of(tmp_path, {"length": LENGTH, "segments": segments, "from": root, "to": "free",
                              "end_a": {"clamped": True, "direction": [float(c) for c in direction]}},
                   {"weight_in_water": WEIGHT, "axial_stiffness": 1e9, "bending_stiffness": EI}, **extra)


def solved(case):
    net = build_network(case)
    x, info = equilibrium(net, case)
    return net, x, info


@pytest.mark.parametrize("segments", [10, 20, 40])
def test_a_cantilever_deflects_as_euler_bernoulli(tmp_path, segments):
    """Tip deflection ``w L^4 / (8 EI)`` (Timoshenko & Gere, Mechanics of Materials, cantilever under a
    uniform load). The clamp's spring ``2 EI / l0`` converges at second order: measured +0.99 %, +0.24 %,
    +0.050 % at 10, 20, 40 segments (and +0.003 % at 80: Richardson's limit -1.3e-4, the geometric
    nonlinearity of a 1.25 % deflection, as the continuum model's cantilever in tests/continuum/test_bending.py);
    the spring ``EI / l0`` of an interior node would give +21 %, +10 %, +5 %."""
    net, x, _ = solved(cantilever(tmp_path, segments))
    exact = WEIGHT * LENGTH**4 / (8 * EI)
    tip = x[net.node_index][-1]
    error = (-5.0 - tip[2]) / exact - 1.0
    assert error == pytest.approx(0.0099 * (10 / segments) ** 2, abs=1.5e-4)
    assert abs(tip[1]) < 1e-9


def test_the_clamped_anchor_carries_the_weight_and_the_moment(tmp_path):
    """Force balance: the line's pull on the anchor (its guide node's share included) is the beam's
    weight ``w L`` down; moment balance: the weight's moment about the root, ``w L^2 / 2`` (less the
    deflection's arm), reaches the clamp as the couple of the guide's and the root's forces."""
    net, x, info = solved(cantilever(tmp_path, 20))
    force = anchor_forces(net, info["loads"], np.zeros(net.n_nodes), np.zeros(1, bool))[0]
    np.testing.assert_allclose(force, [0.0, 0.0, -WEIGHT * LENGTH], atol=1e-6 * WEIGHT * LENGTH)
    guide = net.anchor_nodes[1]
    root = x[net.anchors[0]]
    arm = x[guide] - root
    moment = np.cross(arm, info["loads"][guide])[1]
    cable = x[net.node_index]
    lever = np.sum((0.5 * (cable[1:, 0] + cable[:-1, 0]) - root[0]) * WEIGHT * np.diff(net.node_s))
    assert moment == pytest.approx(lever, rel=1e-6)
    assert lever == pytest.approx(WEIGHT * LENGTH**2 / 2, rel=1e-3)


TENSION, SPAN, AXIAL = 1e4, 100.0, 1e8        # N, m, N: a taut beam, its sag 0.08-0.09 m


def beam_string(tmp_path, segments, clamped_b):
    cable = {"length": SPAN / (1 + TENSION / AXIAL), "segments": segments,
             "from": {"anchor": [0.0, 0.0, -50.0]}, "to": {"anchor": [SPAN, 0.0, -50.0]},
             "end_a": {"clamped": True, "direction": [1.0, 0.0, 0.0]},
             "end_b": {"clamped": True, "direction": [-1.0, 0.0, 0.0]} if clamped_b else {}}
    return case_of(tmp_path, cable, {"weight_in_water": 1.0, "axial_stiffness": AXIAL, "bending_stiffness": 1e6,
                                     "diameter": 0.1, "mass": 5.0})


def tensioned_beam(x, weight, tension, stiffness, span, clamped_b):
    """Deflection of a beam under axial tension ``H`` and weight ``w``, ``EI y'''' - H y'' = -w``
    (Timoshenko & Gere, Theory of Elastic Stability, §1.11, beam-columns in tension), clamped at
    ``x = 0`` and clamped (``y' = 0``) or pinned (``y'' = 0``) at ``x = span``: ``y = a + b x + c
    cosh(lambda x) + d sinh(lambda x) + w x^2 / (2 H)``, ``lambda = sqrt(H / EI)``."""
    lam = math.sqrt(tension / stiffness)

    def row(at, order):
        c, s = math.cosh(lam * at), math.sinh(lam * at)
        return [([1.0, at, c, s], weight * at**2 / (2 * tension)),
                ([0.0, 1.0, lam * s, lam * c], weight * at / tension),
                ([0.0, 0.0, lam**2 * c, lam**2 * s], weight / tension)][order]

    rows = [row(0.0, 0), row(0.0, 1), row(span, 0), row(span, 1 if clamped_b else 2)]
    a, b, c, d = np.linalg.solve(np.array([r[0] for r in rows]), -np.array([r[1] for r in rows]))
    return a + b * x + c * np.cosh(lam * x) + d * np.sinh(lam * x) + weight * x**2 / (2 * tension)


@pytest.mark.parametrize("clamped_b", [True, False], ids=["clamped-clamped", "clamped-pinned"])
def test_a_tensioned_beam_clamped_at_its_ends_bends_as_the_beam_equation_says(tmp_path, clamped_b):
    """The taut beam (EI 1e6 N m^2, w 1 N/m, about 10 kN: sqrt(EI / H) = 10 m) against the tensioned-beam
    equation with the horizontal pull ``H`` the model's far anchor resists (slopes 0.004: the linear
    equation holds to 1e-5). Largest difference in height over the sag, measured at 20, 40, 80
    segments: 2.0 %, 0.50 %, 0.12 % clamped-clamped (sag 7.5 cm); 1.4 %, 0.37 %, 0.089 % clamped-pinned
    (9.2 cm): second order."""
    errors = []
    for segments in (20, 40, 80):
        net, x, info = solved(beam_string(tmp_path, segments, clamped_b))
        pull = -info["loads"][net.anchors[1], 0]
        line = x[net.node_index]
        exact = tensioned_beam(line[:, 0], 1.0, pull, 1e6, SPAN, clamped_b)
        errors.append(np.abs(line[:, 2] + 50.0 - exact).max() / np.abs(exact).max())
    assert errors[-1] < 1.5e-3
    assert errors[0] / errors[1] > 3.5 and errors[1] / errors[2] > 3.5
    other = tensioned_beam(line[:, 0], 1.0, pull, 1e6, SPAN, not clamped_b)
    assert np.abs(other - exact).max() > 0.15 * np.abs(exact).max()     # the far end's fixity matters: 19 %


def test_the_clamp_turns_with_the_vessel(tmp_path):
    """The cantilever clamped along the vessel's x axis at the vessel point (0, 0, -5), the vessel pitched
    10 deg at t = 0 (a harmonic pitch at its crest): the beam leaves along the pitched axis ``t = R e_x``,
    its tip at ``L t`` from the root plus the Euler-Bernoulli deflection of the weight's normal part
    ``w cos(10 deg) L^4 / (8 EI)``: measured -0.17 % (the weight's axial part pulls the beam taut, by
    about ``w L sin(10 deg) L^2 / EI`` of the deflection, 0.2 %) and 0.9 mm short along ``t`` (the
    deflection's foreshortening)."""
    motion = [{"dof": "pitch", "amplitude": 10.0, "period": 20.0, "phase_deg": 90.0}]
    net, x, _ = solved(cantilever(tmp_path, 40, top=[0.0, 0.0, -5.0], motion=motion))
    R = rotation_matrix(0.0, math.radians(10.0), 0.0)
    root, t = R @ [0.0, 0.0, -5.0], R @ [1.0, 0.0, 0.0]
    normal = np.cross(t, [0.0, 1.0, 0.0])
    normal *= -np.sign(normal[2])                                    # downward, across the beam
    deflection = WEIGHT * abs(t[0]) * LENGTH**4 / (8 * EI)
    line = x[net.node_index]
    np.testing.assert_allclose(line[0], root, atol=1e-12)
    tip = line[-1] - root
    assert tip @ normal == pytest.approx(deflection, rel=3e-3)
    assert tip @ t == pytest.approx(LENGTH, abs=2e-3)


def test_the_statics_front_door_takes_a_clamped_case(tmp_path):
    """``kanat statics`` of the clamped-clamped beam is the lumped equilibrium (bending and clamps), and
    the continuum model, whose case ends are pinned, refuses the clamp at its key."""
    case = beam_string(tmp_path, 20, True)
    net, x, _ = solved(case)
    with quiet():
        result = api.solve_statics(case)
    np.testing.assert_allclose(result.position.values, x[net.node_index], atol=1e-9)
    with pytest.raises(CaseError, match=r"cables\[0\]\.end_a\.clamped[\s\S]*clamped cable end"):
        api.run(case.replace({"model": "continuum"}))


@pytest.mark.parametrize("end, message", [
    ("free", "a clamped end needs something that holds a direction"),
    ("point", "point 'joint'"),
])
def test_an_end_that_holds_no_direction_cannot_be_clamped(tmp_path, end, message):
    """Refused where the case is validated, at its key, and by the network itself."""
    to = "free" if end == "free" else {"point": "joint"}
    data = {"name": "beam", "model": "lumped", "environment": {"depth": 200.0},
            "line_types": {"beam": {"diameter": 0.05, "mass": 0.5, "weight_in_water": 1.0, "axial_stiffness": 1e6,
                                    "bending_stiffness": 10.0}},
            "points": {} if end == "free" else {"joint": {"mass": 1.0}},
            "cables": [{"name": "beam", "line_type": "beam", "length": 10.0, "segments": 5,
                        "from": {"anchor": [0.0, 0.0, -5.0]}, "to": to, "end_b": {"clamped": True}}],
            "simulation": {"duration": 1.0, "output_dt": 0.1}}
    path = tmp_path / "beam.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    for attempt in (lambda: load_case(path), lambda: build_network(Case.model_validate(data))):
        with pytest.raises(CaseError, match=message) as caught:
            attempt()
        assert "cables[0].end_b.clamped" in str(caught.value)


def test_a_clamp_without_bending_stiffness_is_a_warning(tmp_path):
    path = tmp_path / "beam.yaml"
    path.write_text(yaml.safe_dump({
        "name": "beam", "model": "lumped", "environment": {"depth": 200.0},
        "line_types": {"beam": {"diameter": 0.05, "mass": 0.5, "weight_in_water": 1.0, "axial_stiffness": 1e6}},
        "cables": [{"name": "beam", "line_type": "beam", "length": 10.0, "segments": 5,
                    "from": {"anchor": [0.0, 0.0, -5.0]}, "to": {"anchor": [9.0, 0.0, -5.0]},
                    "end_a": {"clamped": True}}],
        "simulation": {"duration": 1.0, "output_dt": 0.1}}, sort_keys=False))
    with pytest.warns(UserWarning, match=r"cables\[0\]\.end_a\.clamped.*no bending_stiffness, so the clamp holds nothing"):
        case = load_case(path)
    assert len(build_network(case).bend[1]) == 0


def test_a_direction_needs_a_clamp(tmp_path):
    with pytest.raises(CaseError, match="a direction needs clamped: true"):
        case_of(tmp_path, {"length": 10.0, "segments": 5, "from": {"anchor": [0.0, 0.0, -5.0]}, "to": "free",
                           "end_a": {"direction": [1.0, 0.0, 0.0]}}, {"axial_stiffness": 1e6})


class PythonRK4(RK4):
    """The built-in rk4 by another name: a user's scheme, so the run takes the Python path."""

    name: ClassVar[str] = "python-rk4"


@pytest.mark.slow
def test_the_clamp_holds_the_root_along_the_pitching_vessel(tmp_path):
    """The cantilever (20 elements, EA 1e6 N) clamped 45 deg down along the vessel's x-z axis ``c`` at the
    vessel point while the vessel pitches 2 deg in 10 s (from rest at -2 deg), 5 s: the root element stays
    along ``R(t) c`` within the static turning angle ``w cos(45 deg) L^2 l0 / (4 EI)`` (8.8e-4 rad) and a
    little more from the swing (measured at most 9.1e-4 rad, where the axis turns 0.07 rad); the fused rk4
    kernels move the guide node as the Python path does (0.3 s, 1e-9 m) and the implicit scheme follows
    rk4 (measured 1.1e-5 m). A livelier swing breaks the beam: pitching 5 deg in 4 s, the root's
    inertia (2.5 kg/m with added mass, 1 m/s^2) outweighs its weight's axial pull (0.7 N/m), the root
    element goes slack, shortens freely and the run fails with a non-finite state (the lumped model's
    elements carry no compression; docs/lumped.md)."""
    motion = [{"dof": "pitch", "amplitude": 2.0, "period": 10.0, "phase_deg": -90.0}]
    down = np.array([1.0, 0.0, -1.0]) / math.sqrt(2.0)
    case = cantilever(tmp_path, 20, top=[0.0, 0.0, -5.0], motion=motion, direction=down).replace(
        {"simulation.duration": 5.0, "simulation.output_dt": 0.1, "line_types.beam.axial_stiffness": 1e6})
    short = case.replace({"simulation.duration": 0.3})
    with quiet():
        fused = api.run(case, scheme="rk4").dataset
        python = api.run(short, scheme=PythonRK4()).dataset
        implicit = api.run(case.replace({"simulation.dt": 0.01}), scheme="generalized-alpha-lumped").dataset
    assert fused.attrs["status"] == "ok" and implicit.attrs["status"] == "ok"
    np.testing.assert_allclose(python.position.values, fused.position.values[:len(python.time)], rtol=0, atol=1e-9)
    pitch = np.radians(-2.0 * np.cos(2 * np.pi * fused.time.values / 10.0))
    axis = np.array([rotation_matrix(0.0, p, 0.0) @ down for p in pitch])
    root = fused.position.values[:, 1] - fused.position.values[:, 0]
    root /= np.linalg.norm(root, axis=1)[:, None]
    angle = np.arccos(np.clip(np.sum(root * axis, axis=1), -1.0, 1.0))
    assert np.ptp(pitch) > 0.06
    assert angle.max() < 1.5e-3
    np.testing.assert_allclose(implicit.position.values, fused.position.values, atol=1e-4)


def test_a_clamp_on_a_rigid_body_is_a_fairlead_of_the_body(tmp_path):
    """At a ``dof: 6`` body (pitched 10 deg) a clamp along the body's x axis puts its guide node among the
    body's fairleads at the end's offset less ``l0 e_x`` in body axes, so it turns with the body and the
    clamp's moment reaches it; at t = 0 the guide lies ``l0 R e_x`` behind the end."""
    body = {"dof": 6, "mass": 100.0, "net_buoyancy": 0.0, "position": [0.0, 0.0, -10.0], "inertia": [10.0, 10.0, 10.0],
            "orientation_deg": [0.0, 10.0, 0.0]}
    offset = [1.0, 0.0, 0.0]
    case = case_of(tmp_path, {"length": 10.0, "segments": 10, "from": {"body": "b", "offset": offset},
                              "to": {"anchor": [12.0, 0.0, -20.0]}, "end_a": {"clamped": True, "direction": [1.0, 0, 0]}},
                   {"weight_in_water": 1.0, "axial_stiffness": 1e6, "bending_stiffness": 100.0}, bodies={"b": body})
    net = build_network(case)
    rigid = net.rigid
    guide = int(np.flatnonzero(net.kinds == "clamp")[0])
    row = int(np.flatnonzero(rigid.fairlead_node == guide)[0])
    np.testing.assert_allclose(rigid.fairlead_offset[row], [0.0, 0.0, 0.0], atol=1e-12)     # offset - 1 m e_x
    R = rotation_matrix(0.0, math.radians(10.0), 0.0)
    end = net.node_index[0]
    np.testing.assert_allclose(net.x_guess[end] - net.x_guess[guide], R @ [1.0, 0.0, 0.0], atol=1e-12)
    before, node, after = (part[-1] for part in net.bend[:3])
    assert (before, node, after) == (guide, end, net.node_index[1])
    assert net.bend[3][-1] == pytest.approx(2 * 100.0 / 1.0)                                # 2 EI / l0
