"""An output's loads in one compiled call (:func:`kanat.lumped.output_loads.output_loads`).

* ``LumpedSystem.output_loads`` gives, to the bit, the forces, mass blocks, element tensions and
  strains, wetted fractions and seabed normal forces of ``LumpedSystem.loads`` and the tensions of
  :func:`kanat.lumped.kernels.tensions`, the calls it replaces in an output: for a network with a
  point body, a 6-DOF buoy, a chain on a seabed with friction in a current profile, a trawl in
  waves, a lazy wave on the seabed, and a line with bending stiffness, each with elements crossing
  the surface;
* the compiled kernel agrees with its NumPy twin (:func:`kanat.lumped.oracle_numpy.output_loads_numpy`,
  written apart: vectorized, ``np.add.at``) to round-off;
* the strain check reads the call's strains: the same to the bit as worked out from the positions.
"""
from pathlib import Path

import numpy as np
import pytest

from kanat.io import load_case
from kanat.lumped import entries
from kanat.lumped.adapter import LumpedModel
from kanat.lumped.integrators import state_positions
from kanat.lumped.oracle_numpy import calm_wetted_numpy, output_loads_numpy

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CASES = {"point body": ("subsurface_mooring.yaml", {"model": "lumped", "simulation.scheme": "rk4"}),
         "6-DOF body": ("mooring_buoy_decay.yaml", {}),
         "seabed friction, current profile": ("mooring_current.yaml", {"model": "lumped"}),
         "trawl in waves": ("trawl_head_8s_1to2.yaml", {}),
         "lazy wave": ("lazy_wave.yaml", {}),
         "bending stiffness": ("lazy_wave.yaml", {"line_types.flowline.bending_stiffness": 2.0e5})}


def model_of(name):
    file, changes = CASES[name]
    case = load_case(EXAMPLES / file).replace({**changes, "simulation.duration": 0.5, "simulation.output_dt": 0.5})
    return LumpedModel(case)


def moved(model):
    """All nodes' x, v of the model's initial state with the free nodes moving (drag) and every
    other free node raised so that elements cross the still surface and some stand out of it."""
    state = model.initial()
    xf, vf = state_positions(state.scheme)
    vf = vf + 0.3 * np.sin(np.arange(vf.size)).reshape(vf.shape)
    xf = xf.copy()
    xf[::7, 2] = 0.4                                          # above the surface, or across it
    return model.system.full(0.2, xf, vf)


@pytest.mark.parametrize("name", CASES)
def test_one_call_gives_the_loads_and_tensions_of_the_calls_it_replaces_to_the_bit(name):
    model = model_of(name)
    system = model.system
    x, v, _, heading = moved(model)
    T = np.zeros(model.net.n_elements)
    entries.tensions(x, v, system.el_args, T)
    F, M = (part.copy() for part in system.loads(0.2, x, v, heading))
    keys = ("tension", "strain", "wet", "normal_force") if system.contact is not None else ("tension", "strain", "wet")
    kept = {key: getattr(system, key).copy() for key in keys}
    for key in kept:
        getattr(system, key)[:] = np.nan
    system._F[:], system._M[:] = np.nan, np.nan
    got_F, got_M, got_T = system.output_loads(0.2, x, v, heading, masses=True)
    assert got_F.tobytes() == F.tobytes() and got_M.tobytes() == M.tobytes() and got_T.tobytes() == T.tobytes()
    for key, value in kept.items():
        assert getattr(system, key).tobytes() == value.tobytes(), key
    assert 0.0 < kept["wet"].min() < 1.0 or kept["wet"].min() == 0.0        # the surface is crossed
    if name == "seabed friction, current profile":
        assert np.any(kept["normal_force"] > 0.0)


@pytest.mark.parametrize("name", CASES)
def test_the_kernel_agrees_with_its_numpy_twin(name):
    model = model_of(name)
    system = model.system
    x, v, _, heading = moved(model)
    system.output_loads(0.2, x, v, heading)                  # the record made, the water and waves' wet filled
    out = system._outputs
    entries.output_loads(x, v, system.el_args, system.contact, out)      # the kernel alone: no body loads
    keys = ("force", "mass", "tension", "strain", "line_tension", "wet")
    if system.contact is not None:                           # no seabed: not written
        keys += ("normal_force",)
    compiled = {key: np.array(getattr(out, key)) for key in keys}
    twin = out._replace(**{key: np.full_like(value, np.nan) for key, value in compiled.items()})
    if not twin.calm:
        twin.wet[:] = compiled["wet"]                       # the waves' wetted fractions are an input
    output_loads_numpy(x, v, system.el_args, system.contact, twin)
    for key, value in compiled.items():
        scale = max(np.abs(value).max(), 1.0)
        np.testing.assert_allclose(getattr(twin, key), value, rtol=0, atol=1e-12 * scale, err_msg=key)


def test_the_calm_wetted_fractions_cross_the_surface():
    model = model_of("lazy wave")
    x, v, _, heading = moved(model)
    model.system.output_loads(0.2, x, v, heading)
    wet = model.system.wet
    expected = calm_wetted_numpy(model.system.el_args, x)
    np.testing.assert_allclose(wet, expected, rtol=0, atol=1e-15)
    assert np.any((wet > 0.0) & (wet < 1.0)) and np.any(wet == 1.0)


@pytest.mark.parametrize("name", ["seabed friction, current profile", "bending stiffness"])
def test_the_strain_check_reads_the_strains_of_the_call(name):
    model = model_of(name)
    state = model.initial()
    model.outputs(state)
    x, strain = model._positions(state)
    model._seen = None
    x_again, worked_out = model._positions(state)
    assert x.tobytes() == x_again.tobytes() and strain.tobytes() == worked_out.tobytes()
