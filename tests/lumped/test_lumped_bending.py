"""Bending stiffness in the lumped model (kanat.lumped.bending): forces as the energy's gradient,
a tensioned beam's natural frequencies, the continuum model's steady shape, and the compiled
path against the Python one."""
import math
import warnings
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest
import yaml

from kanat import api
from kanat.io import load_case
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.bending import bending_energy, bending_forces, bending_triples
from kanat.lumped.equilibrium import starting_state
from kanat.lumped.integrators import RK4

from helpers import quiet


def test_the_forces_are_the_energy_s_gradient():
    """Eq. (3) against central differences of eq. (1) on a bent, unevenly stretched line."""
    rng = np.random.default_rng(3)
    x = np.cumsum(rng.normal(size=(7, 3)) + [1.0, 0.0, 0.0], axis=0)
    el_i, el_j = np.arange(6), np.arange(1, 7)
    triples = bending_triples(el_i, el_j, np.array(["a"] * 6, dtype=object), rng.uniform(1e3, 2e3, 6),
                              rng.uniform(0.8, 1.2, 6))[:4]
    F = np.zeros_like(x)
    bending_forces(x, *triples, F)
    step, numeric = 1e-6, np.zeros_like(x)
    for node in range(7):
        for r in range(3):
            up, down = x.copy(), x.copy()
            up[node, r] += step
            down[node, r] -= step
            numeric[node, r] = -(bending_energy(up, *triples) - bending_energy(down, *triples)) / (2 * step)
    np.testing.assert_allclose(F, numeric, rtol=1e-6, atol=1e-6 * np.abs(F).max())
    np.testing.assert_allclose(F.sum(axis=0), 0.0, atol=1e-9 * np.abs(F).max())


def beam_case(tmp_path, bending_stiffness, tension=1e4, length=100.0, segments=100, mass=10.0, **extra):
    """A neutrally buoyant line between two anchors, pulled to ``tension`` (its unstretched length
    shortened by ``T / EA``), without drag or added mass."""
    axial = 1e8
    case = {"name": "beam", "model": "lumped", "environment": {"depth": 200.0},
            "line_types": {"rod": {"diameter": 0.1, "mass": mass, "weight_in_water": 0.0, "axial_stiffness": axial,
                                   "bending_stiffness": bending_stiffness, "added_mass": 0.0, "drag_normal": 0.0,
                                   "drag_tangential": 0.0}},
            "cables": [{"name": "beam", "line_type": "rod", "length": length / (1 + tension / axial),
                        "segments": segments, "from": {"anchor": [0.0, 0.0, -50.0]},
                        "to": {"anchor": [length, 0.0, -50.0]}}],
            "simulation": {"duration": 1.0, "output_dt": 0.1, **extra}}
    path = tmp_path / "beam.yaml"
    path.write_text(yaml.safe_dump(case, sort_keys=False))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(path)


@pytest.mark.parametrize("bending_stiffness", [0.0, 1e5, 1e6])
def test_a_tensioned_beam_vibrates_at_its_natural_frequencies(tmp_path, bending_stiffness):
    """Transverse modes of a pinned-pinned beam under tension ``T`` (Clough & Penzien, Dynamics of
    Structures, 2nd ed., §18-4): ``omega_n = (n pi / L) sqrt(T / mu) sqrt(1 + (n pi / L)^2 EI / T)``,
    against the eigenvalues of the lumped model linearized (central differences of its forces) about
    its equilibrium; modes 1-3 within 0.1 % (100 elements)."""
    T, L, mu = 1e4, 100.0, 10.0
    case = beam_case(tmp_path, bending_stiffness, tension=T, length=L, mass=mu)
    model = LumpedModel(case)
    system = model.system
    x = starting_state(model.net, case, system)[0]
    free = system.free_index
    xf = x[free].copy()

    def lateral(q):
        full, v, _, heading = system.full(0.0, q, np.zeros_like(q))
        return system.loads(0.0, full, v, heading)[0][free, 1].copy()

    n, step = len(free), 1e-6
    K = np.zeros((n, n))
    for k in range(n):
        up, down = xf.copy(), xf.copy()
        up[k, 1] += step
        down[k, 1] -= step
        K[:, k] = -(lateral(up) - lateral(down)) / (2 * step)
    net = model.net
    mass = np.zeros(net.n_nodes)
    np.add.at(mass, net.el_i, 0.5 * net.el_mass * net.el_length)
    np.add.at(mass, net.el_j, 0.5 * net.el_mass * net.el_length)
    omega = np.sqrt(np.sort(np.linalg.eigvals(K / mass[free][:, None]).real))
    for mode in (1, 2, 3):
        wave = mode * math.pi / L
        exact = wave * math.sqrt(T / mu) * math.sqrt(1 + wave**2 * bending_stiffness / T)
        assert omega[mode - 1] == pytest.approx(exact, rel=1e-3)


def jumper(tmp_path, bending_stiffness, model="lumped", top="vessel"):
    """A steep jumper (170 m, 165 kg/m, d 0.396 m) from an anchor 100 m away at 55 m depth to a top end
    at 5 m depth, in 100 m of water."""
    top_end = {"vessel": [0.0, 0.0, -5.0]} if top == "vessel" else {"anchor": [0.0, 0.0, -5.0]}
    case = {"name": "jumper", "model": model, "environment": {"depth": 100.0},
            "line_types": {"flex": {"diameter": 0.396, "mass": 165.0, "axial_stiffness": 5e8,
                                    "bending_stiffness": bending_stiffness, "drag_normal": 1.0,
                                    "added_mass": 126.24}},
            "cables": [{"name": "jumper", "line_type": "flex", "length": 170.0, "segments": 34,
                        "from": {"anchor": [100.0, 0.0, -55.0]}, "to": top_end}],
            "simulation": {"duration": 10.0, "output_dt": 5.0, "dt": 0.5}}
    path = tmp_path / f"jumper_{model}.yaml"
    path.write_text(yaml.safe_dump(case, sort_keys=False))
    return load_case(path)


@pytest.mark.slow
def test_the_bent_jumper_rests_where_the_continuum_model_settles(tmp_path):
    """The lumped equilibrium with EI 2e7 N m^2 moves the jumper as the continuum model's run settled to
    rest moves it (the continuum's bending: kanat.continuum, pinned ends): the two models' shifts
    from their flexible shapes (3 m at the sag) agree within 3 % of the largest."""
    shapes = {}
    for stiffness in (0.0, 2e7):
        lumped = jumper(tmp_path, stiffness)
        model = LumpedModel(lumped)
        x = starting_state(model.net, lumped, model.system)[0]
        with quiet():
            ds = api.run(jumper(tmp_path, stiffness, model="continuum", top="anchor")).dataset
        assert ds.attrs["status"] == "ok"
        shapes[stiffness] = x[model.net.node_index], ds.position.values[-1]
    lumped_shift = shapes[2e7][0] - shapes[0.0][0]
    continuum_shift = shapes[2e7][1] - shapes[0.0][1]
    biggest = np.abs(continuum_shift).max()
    assert biggest > 1.0
    assert np.abs(lumped_shift - continuum_shift).max() < 0.03 * biggest


class PythonRK4(RK4):
    """The built-in rk4 by another name: a user's scheme, so the run takes the Python path."""

    name: ClassVar[str] = "python-rk4"


def test_the_compiled_runs_bend_as_the_python_path_does(tmp_path):
    """The beam (EI 1e6, in still water with drag) driven sideways at one end (sway 1 m in 5 s): the
    fused rk4 kernels and the Python right-hand side give the same states, and the implicit scheme
    with the bending tangent converges in a few iterations to rk4's answer."""
    case = beam_case(tmp_path, 1e6, segments=20, duration=2.0, output_dt=0.1)
    case = case.replace({"cables[0].to": {"vessel": [100.0, 0.0, -50.0]}, "line_types.rod.drag_normal": 1.0,
                         "vessel.motion": [{"dof": "sway", "amplitude": 1.0, "period": 5.0, "phase_deg": -90.0}]})
    with quiet():
        fused = api.run(case, scheme="rk4").dataset
        python = api.run(case, scheme=PythonRK4()).dataset
        implicit = api.run(case.replace({"simulation.dt": 0.01}), scheme="generalized-alpha-lumped").dataset
    assert np.abs(fused.position.values[-1, :, 1]).max() > 0.1                 # it moved sideways
    np.testing.assert_allclose(fused.position.values, python.position.values, rtol=0, atol=1e-9)
    assert implicit.attrs["newton_iterations_mean"] < 3.0
    np.testing.assert_allclose(implicit.position.values[-1], fused.position.values[-1], atol=5e-3)


def tether(tmp_path, bending_stiffness):
    """A 10 m tether with EI from an anchor in 20 m of water to a buoy (20 N up) in a 0.2 m/s current."""
    case = {"name": "tether", "model": "statics", "environment": {"depth": 20.0, "current": {"velocity": [0.2, 0, 0]}},
            "line_types": {"teth": {"diameter": 0.02, "mass": 0.5, "axial_stiffness": 1e6,
                                    "bending_stiffness": bending_stiffness, "drag_normal": 1.2,
                                    "drag_tangential": 0.01}},
            "bodies": {"buoy": {"mass": 5.0, "net_buoyancy": 20.0, "drag_area": 0.05}},
            "cables": [{"name": "tether", "line_type": "teth", "length": 10.0, "segments": 40,
                        "from": {"anchor": [0, 0, -20.0]}, "to": "buoy"}],
            "simulation": {"duration": 120.0, "output_dt": 10.0, "dt": 0.2}}
    path = tmp_path / "tether.yaml"
    path.write_text(yaml.safe_dump(case, sort_keys=False))
    return load_case(path)


@pytest.mark.slow
def test_statics_gives_the_shape_a_run_with_bending_settles_to(tmp_path):
    """``kanat statics`` of a tether with EI 100 N m^2 (the lumped equilibrium, which includes the
    bending) against the continuum model's run settled to rest: within 2 mm, where the flexible
    shape's buoy lies 0.35 m away; a method that finds flexible lines says so instead."""
    case = tether(tmp_path, 100.0)
    steady = api.solve_statics(case)
    with quiet():
        settled = api.run(case.replace({"model": "continuum"})).dataset.position.values
    assert np.abs(settled[-1] - settled[-2]).max() < 1e-9                        # at rest
    assert np.abs(steady.position.values - settled[-1]).max() < 2e-3
    flexible = api.solve_statics(tether(tmp_path, 0.0)).position.values
    assert np.abs(flexible[-1] - settled[-1]).max() > 0.3
    with pytest.raises(Exception, match="bending_stiffness; use method auto"):
        api.solve_statics(case, method="shooting")
