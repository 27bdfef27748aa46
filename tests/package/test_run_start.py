"""kanat.run(case, start=...): a dynamic run from another case's steady state or a result's last output."""
import numpy as np
import pytest

import kanat
from kanat.errors import CaseError, KanatError


def hanging(segments=10, **keys):
    """One chain from a vessel point to an anchor 110 m off and 45 m down, 120 m long, 10 segments,
    starting from the given straight geometry (it falls into its sag): nothing in it depends on time,
    so a run continued from its state at t is the run after t."""
    case = kanat.load_case({
        "name": "hanging", "model": "lumped", "environment": {},
        "line_types": {"chain": {"diameter": 0.1, "mass": 100.0, "axial_stiffness": 1e8, "axial_damping": 1e5}},
        "cables": [{"name": "chain", "line_type": "chain", "length": 120.0, "segments": segments,
                    "from": {"vessel": [0.0, 0.0, -5.0]}, "to": {"anchor": [110.0, 0.0, -50.0]}}],
        "simulation": {"duration": 2.0, "output_dt": 0.5, "scheme": "rk4", "initial_state": "as_given"}})
    return case.replace(keys) if keys else case


def test_a_run_from_a_results_last_output_is_the_longer_run():
    """rk4's state is the nodes' positions and velocities, which a result keeps: 1 s, then 1 s more from
    its last output, is the 2 s run to round-off at every output."""
    whole = kanat.simulate(hanging())
    first = kanat.simulate(hanging(**{"simulation.duration": 1.0}))
    second = kanat.simulate(hanging(**{"simulation.duration": 1.0}), start=first)
    assert second.attrs["status"] == "ok"
    moved = np.max(np.abs(whole.position.values[2] - whole.position.values[0]))
    assert moved > 0.5                                          # the chain falls by a metre
    scale = np.max(np.abs(whole.position.values))
    np.testing.assert_allclose(second.position.values, whole.position.values[2:], rtol=0, atol=1e-10 * scale)
    np.testing.assert_allclose(second.tension.values, whole.tension.values[2:], rtol=1e-8,
                               atol=1e-8 * np.max(whole.tension.values))


def test_a_run_from_another_cases_steady_state_starts_there():
    """A current from t = 0 on the chain at rest in still water: the run's first output is the still
    water run's (its equilibrium), and the current then carries the chain off it in +y."""
    still = hanging(**{"simulation.initial_state": "equilibrium", "simulation.duration": 1.0})
    current = still.replace({"environment.current": {"velocity": [0.0, 1.0, 0.0]}})
    calm = kanat.simulate(still)
    stepped = kanat.simulate(current, start=still)
    np.testing.assert_array_equal(stepped.position.values[0], calm.position.values[0])
    assert np.max(stepped.position.values[-1, :, 1]) > 0.05


def test_start_is_refused_where_it_cannot_apply():
    case = hanging()
    other = hanging(segments=12)
    with pytest.raises(CaseError, match="same network"):
        kanat.simulate(case, start=other)
    with pytest.raises(KanatError, match="steady state"):
        kanat.run(case, start=case, model="statics")
