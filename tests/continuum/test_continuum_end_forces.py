"""The continuum model's ``anchor_force`` and ``body_force`` (the cable's force ``T t + S`` at its ends,
:mod:`kanat.continuum.outputs`) against independent oracles:

* the closed-form elastic catenary resting on a frictionless seabed (the grounded chain of
  examples/mooring_current.yaml in still water): the horizontal tension ``H`` on the anchor on the
  seabed, whose vertical part is zero but for the elastic seabed's boundary layer
  ``w sqrt(H / (k_b d))``, and ``(-H, 0, -w L_s)`` on the fairlead's anchor, at three grids;
* the lumped model run side by side on the same cases, within its discretization error;
* a towed body in steady tow, 2-D and 3-D (a cross current): its weight less its buoyancy and its
  drag at the tow speed, to the box method's second order;
* the subsurface mooring's float (inline) and top buoy at rest in a sheared current: their net
  buoyancy and their drag in the current at their depth.
"""
import re
import warnings

import numpy as np
import pytest

import kanat

from helpers import EXAMPLES, grounded_catenary

SPAN, RISE, LENGTH, WEIGHT, STIFFNESS = 600.0, 145.0, 700.0, 981.0, 5.1e8      # the example's chain
DIAMETER, SEABED_STIFFNESS = 0.137, 3.0e6                                       # and its seabed contact
KNOT = 1852.0 / 3600.0


def catenary() -> tuple[float, float]:
    """Horizontal tension ``H`` [N] and suspended length ``L_s`` [m] of the example's chain as an elastic
    catenary with a grounded part (:func:`helpers.grounded_catenary`)."""
    return grounded_catenary(SPAN, RISE, LENGTH, WEIGHT, STIFFNESS)


def grounded_chain(segments: int, model: str = "continuum"):
    """The chain of examples/mooring_current.yaml in still water on an explicit seabed, a short run."""
    text = (EXAMPLES / "mooring_current.yaml").read_text()
    text = re.sub(r"  current:\n    profile:.*?\n(line_types)", r"\1", text, flags=re.S)
    text = text.replace("  depth: 150\n", "  depth: 150\n  seabed: {stiffness: 3.0e6, damping: 3.0e5}\n")
    text = text.replace("model: statics", f"model: {model}").replace("segments: 70", f"segments: {segments}")
    simulation = "{duration: 1, dt: 0.5, output_dt: 0.5}" if model == "continuum" else "{duration: 1, output_dt: 0.5}"
    return run(kanat.load_case(text + f"simulation: {simulation}\n"))


def run(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(case)
    assert ds.attrs["status"] == "ok"
    return ds


def boundary_layer(horizontal: float) -> float:
    """Downward pull [N] of a taut line resting on an elastic seabed on an anchor held at the seabed's plane:
    the line sinks ``w / (k_b d)`` over ``l = sqrt(H / (k_b d))`` (a string on a Winkler foundation,
    ``H z'' = k_b d z + w``), so its slope at the anchor is ``w / (k_b d l)`` and the pull ``H`` times it."""
    return WEIGHT * np.sqrt(horizontal / (SEABED_STIFFNESS * DIAMETER))


@pytest.mark.slow
@pytest.mark.parametrize("segments, rtol, top_rtol, layer_rtol",
                         [(35, 0.025, 0.02, 0.15), (70, 2.5e-3, 1e-3, 0.02), (140, 5e-4, 6e-4, 5e-3)])
def test_anchor_forces_are_the_elastic_catenarys(segments, rtol, top_rtol, layer_rtol):
    horizontal, suspended = catenary()                       # 28.0 kN, 171 m of 700 m suspended
    ds = grounded_chain(segments)
    force = ds.anchor_force
    assert force.dims == ("time", "anchor", "xyz") and force.attrs["units"] == "N"
    assert list(ds.anchor.values) == ["mooring.from", "mooring.to"]
    assert np.ptp(force.values, axis=0).max() <= 1e-6 * horizontal                 # steady in still water
    on_seabed, fairlead = force.values[-1]
    assert on_seabed[0] == pytest.approx(horizontal, rel=rtol)              # pulled towards the fairlead
    assert on_seabed[1] == 0.0
    assert -0.011 * horizontal < on_seabed[2] < 0.0                               # no uplift: the line rests
    assert -on_seabed[2] == pytest.approx(boundary_layer(horizontal), rel=layer_rtol)
    expected = np.array([-horizontal, 0.0, -WEIGHT * suspended])                  # -T t at the top
    assert np.linalg.norm(fairlead - expected) <= top_rtol * np.linalg.norm(expected)


@pytest.mark.slow
@pytest.mark.parametrize("segments, rtol", [(70, 7e-3), (140, 5e-4)])
def test_anchor_forces_agree_with_the_lumped_models(segments, rtol):
    continuum, lumped = grounded_chain(segments), grounded_chain(segments, "lumped")
    assert list(lumped.anchor.values) == list(continuum.anchor.values)
    (c_seabed, c_top), (l_seabed, l_top) = continuum.anchor_force.values[-1], lumped.anchor_force.values[-1]
    assert np.linalg.norm(c_top - l_top) <= rtol * np.linalg.norm(l_top)
    assert c_seabed[0] == pytest.approx(l_seabed[0], rel=rtol)
    # vertically the lumped elements (5 to 10 m) do not resolve the seabed's 0.26 m boundary layer
    assert abs(c_seabed[2] - l_seabed[2]) <= 1.05 * boundary_layer(l_seabed[0])


def towed_body(segments: int, dimensions: int, cross_current: float, bending: float):
    """The sled of examples/towed_body.yaml towed steadily at 6 kn along +x, a uniform current along +y, the
    cable given a bending stiffness [N m^2] (a rod: its shear ``S`` on the body too)."""
    case = kanat.load_case(EXAMPLES / "towed_body.yaml")
    changes = {"model": "continuum", "simulation.dt": 1.0, "simulation.duration": 2.0, "simulation.output_dt": 1.0,
               "simulation.dimensions": dimensions, "cables[0].segments": segments,
               "line_types.towcable.bending_stiffness": bending}
    if cross_current:
        changes["environment.current"] = {"profile": [[0, 0, cross_current, 0], [-2000, 0, cross_current, 0]]}
    return case, run(case.replace(changes))


@pytest.mark.parametrize("dimensions, cross_current, bending", [
    (2, 0.0, 0.0), pytest.param(3, 0.5, 0.0, marks=pytest.mark.slow),
    pytest.param(2, 0.0, 500.0, marks=pytest.mark.slow), pytest.param(3, 0.5, 500.0, marks=pytest.mark.slow)])
def test_a_towed_body_carries_its_weight_and_drag(dimensions, cross_current, bending):
    """Line force on the body = -(net buoyancy z + 0.5 rho C_D S |U_r| U_r), ``U_r`` the water's velocity
    relative to the body, ``(-6 kn, current, 0)``: the box method's error falls as ds^2."""
    errors = []
    for segments in (40, 80, 160):
        case, ds = towed_body(segments, dimensions, cross_current, bending)
        body = case.bodies["sled"]
        relative = np.array([-6.0 * KNOT, cross_current, 0.0])
        drag = 0.5 * case.environment.water_density * body.drag_area * np.linalg.norm(relative) * relative
        expected = -(np.array([0.0, 0.0, body.net_buoyancy]) + drag)       # 1.6 kN forward, 6.7 kN up
        assert list(ds.body.values) == ["sled"] and ds.body_force.dims == ("time", "body", "xyz")
        errors.append(np.linalg.norm(ds.body_force.values[-1, 0] - expected) / np.linalg.norm(expected))
    assert errors[0] < 2e-3
    assert errors[1] < errors[0] / 3.5 and errors[2] < errors[1] / 3.5               # second order


@pytest.mark.slow
def test_the_subsurface_moorings_bodies_carry_their_buoyancy_and_drag():
    """Float (inline) and top buoy at rest in a sheared current (3-D): the line force on each is
    ``-(B z + 0.5 rho C_D S |u| u)`` with ``u`` the current at its depth (the case's profile, linear)."""
    case = kanat.load_case(EXAMPLES / "subsurface_mooring.yaml")
    ds = run(case.replace({"simulation.duration": 1.0, "simulation.output_dt": 0.5}))
    profile = np.array([[0, 0.6, 0.3, 0], [-100, 0.45, 0.2, 0], [-300, 0.2, 0.05, 0], [-500, 0.05, 0.0, 0]])
    assert list(ds.body.values) == ["top_buoy", "glass_balls"] and list(ds.anchor.values) == ["mooring.from"]
    for b, name in enumerate(ds.body.values):
        body = case.bodies[str(name)]
        z = ds.body_position.values[-1, b, 2]
        current = np.array([np.interp(z, profile[::-1, 0], profile[::-1, j]) for j in (1, 2, 3)])
        expected = -(np.array([0.0, 0.0, body.net_buoyancy]) + 0.5 * 1025.0 * body.drag_area
                     * np.linalg.norm(current) * current)
        assert np.linalg.norm(ds.body_force.values[-1, b] - expected) <= 1e-9 * abs(body.net_buoyancy)
    assert ds.anchor_force.values[-1, 0, 2] > 0.0                                   # the anchor is lifted


@pytest.mark.slow
def test_the_subsurface_moorings_anchor_force_agrees_with_the_lumped_models():
    """Side by side in 3-D: the anchor's force within half an element's weight in water (5 m of wire)."""
    case = kanat.load_case(EXAMPLES / "subsurface_mooring.yaml").replace(
        {"simulation.duration": 1.0, "simulation.output_dt": 0.5})
    continuum = run(case)
    lumped = run(case.replace({"model": "lumped", "simulation.scheme": None, "simulation.dt": None}))
    assert list(lumped.anchor.values) == list(continuum.anchor.values)
    gap = continuum.anchor_force.values[-1, 0] - lumped.anchor_force.values[-1, 0]
    assert np.linalg.norm(gap) <= 0.5 * 3.5 * 5.0                                    # 6.4 kN of uplift


def test_a_cable_without_anchors_or_bodies_writes_neither():
    """A towed cable with a free end (speed_step_2d.yaml without its sled)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                     # the sled, now attached to nothing
        case = kanat.load_case(EXAMPLES / "speed_step_2d.yaml").replace(
            {"simulation.duration": 1, "cables[0].to": "free", "cables[0].segments": 20})
    ds = run(case)
    assert "anchor_force" not in ds and "body_force" not in ds and "anchor" not in ds.dims
