"""Seabed contact in the continuum model (theory/moorings.md §3; MoorDyn's kbot/cbot law, as the lumped model's):
the grounded catenary against its closed form, converging with the grid; the static sink
w / (k_b d); friction holding a line; a node falling through stops the run and says so."""
import re
import warnings

import numpy as np
import pytest

import kanat
from kanat.continuum import kernels2d as k
from kanat.continuum.models import model_for
from kanat.statics.catenary import elastic_catenary

from helpers import EXAMPLES

MOORING = (EXAMPLES / "mooring_current.yaml").read_text()


def grounded_chain(segments=70, extra=""):
    """The chain mooring of examples/mooring_current.yaml in still water, as a continuum case."""
    text = re.sub(r"  current:\n    profile:.*?\n(line_types)", r"\1", MOORING, flags=re.S)
    text = text.replace("model: statics", "model: continuum").replace("segments: 70", f"segments: {segments}")
    return text + "simulation: {duration: 10, dt: 0.5, output_dt: 5}\n" + extra


def test_grounded_catenary_against_the_closed_form_converging_with_the_grid():
    cat = elastic_catenary(600.0, 145.0, 700.0, 981.0, 5.1e8, seabed=True, n_points=2)
    errors = []
    for segments in (35, 70, 140):
        state = model_for(kanat.load_case(grounded_chain(segments))).initial()
        T = state.y[:, 0]
        errors.append(max(abs(T[-1] / cat.tension_upper - 1), abs(T[0] / cat.horizontal_tension - 1)))
    assert errors[1] < 2e-3 and errors[2] < errors[1] < errors[0]


def test_the_grounded_chain_sinks_by_its_static_penetration_and_stays_steady():
    """The box method balances each interval: the interval means of the penetration are the static sink
    w / (k_b d); the nodes alternate about it (within 0 to 2.5 times it) from where the line meets the
    seabed at a node (the anchor, held at zero penetration) and from the touchdown."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(grounded_chain()))
    assert ds.attrs["status"] == "ok"
    depth = -150.0 - ds.position.isel(time=0).sel(xyz="z").values
    sink = 981.0 / (3.0e6 * 0.137)                                    # w / (k_b d)
    means = 0.5 * (depth[1:] + depth[:-1])[10:50]                     # grounded part, off the anchor
    assert np.max(np.abs(means / sink - 1)) < 0.05
    assert np.all((depth[1:50] > -0.1 * sink) & (depth[1:50] < 2.5 * sink))
    assert np.max(np.abs(ds.tension.values[-1] - ds.tension.values[0])) < 1e-9 * ds.tension.values.max()


def test_friction_holds_a_grounded_line_that_a_frictionless_seabed_lets_slide():
    """Pull the fairlead 1 m towards the anchor... seen the other way: a slope that would make the
    grounded chain slide down is held by friction above the friction angle's tangent."""
    model = model_for(kanat.load_case(grounded_chain(extra="")))
    p = model.cable.rows()[0].copy()
    p[k.SB_MUA] = 0.5
    p[k.PRED], p[k.INERTIA] = 0.0, 1.0
    env = np.zeros(k.NENV)
    env[k.RZ] = -150.0 - 0.001                                            # 1 mm into the seabed
    slide = 0.02                                                         # m/s along the seabed
    ft, fn = k.extra_load(0.0, slide, 0.0, 0.0, env, p)
    normal = 0.137 * (3.0e6 * 0.001)
    assert fn == pytest.approx(normal, rel=1e-9)
    assert ft == pytest.approx(-0.5 * normal * np.tanh(slide / k.FRICTION_SPEED), rel=1e-9)


def test_a_node_falling_through_the_seabed_stops_the_run_and_says_where():
    """Kaliukh & Vusatiuk's factorized schemes apply no seabed contact: the grounded chain falls through."""
    text = grounded_chain().replace("simulation: {duration: 10, dt: 0.5, output_dt: 5}",
                                    "simulation: {scheme: factorized, duration: 1, dt: 0.005, output_dt: 0.5}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = kanat.simulate(kanat.load_case(text))
    status = ds.attrs["status"]
    assert status.startswith("failed") and "below the seabed" in status and "static penetration" in status
    assert "applies no seabed contact" in status


def test_a_steady_state_too_large_for_its_dense_matrices_is_refused_before_allocating_them(monkeypatch):
    """The steady Newton on the seabed holds two dense ``n nv x n dim`` matrices (6,000 segments: 7 GB,
    which once crowded the machine out in a fuzz round); above MAX_DENSE_BYTES it says so and what to
    do instead of allocating them. The bound is lowered here to what 70 segments need."""
    from kanat.continuum import steady

    monkeypatch.setattr(steady, "MAX_DENSE_BYTES", 2 * (71 * 4) * (71 * 2) * 8 - 1)    # nv 4, dim 2
    with pytest.raises(Exception, match=r"steady state on the seabed of 70 segments needs 1 MiB of dense "
                                        r"matrices .*fewer segments on the seabed part, or model: lumped"):
        model_for(kanat.load_case(grounded_chain())).initial()
