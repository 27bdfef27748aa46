"""The generalized-α family (theory/time-schemes.md §1, theory/validation-cases.md case 2): amplification at infinite frequency, and the
scheme registry (the order of accuracy of every scheme: test_scheme_order.py)."""
import numpy as np
import pytest

from kanat import api
from kanat.continuum.schemes import SCHEMES, BackwardEuler, Box, GeneralizedAlpha, GeneralizedTrapezoidal
from kanat.lumped.integrators import SCHEMES as LUMPED
from kanat.schemes import get_scheme


def amplification(coefficients, kappa_h):
    """Amplification matrix of ``ydot + kappa y = 0`` over one step for the family (2x2)."""
    am, ak, gamma = coefficients
    # unknowns (y1, ydot1): (1-am) ydot1 + am ydot0 + kh[(1-ak) y1 + ak y0] = 0 (with h = 1),
    #                       ydot1 - y1 / gamma = -y0 / gamma - (1-gamma)/gamma ydot0
    lhs = np.array([[kappa_h * (1 - ak), 1 - am], [-1 / gamma, 1.0]])
    rhs = np.array([[-kappa_h * ak, -am], [-1 / gamma, -(1 - gamma) / gamma]])
    return np.linalg.solve(lhs, rhs)


@pytest.mark.parametrize("scheme, expected", [
    (Box(), (-1.0, -1.0)), (BackwardEuler(), (0.0, 0.0)), (GeneralizedTrapezoidal(0.6), (0.0, -0.4 / 0.6)),
    (GeneralizedAlpha(-1.0), (-1.0, -1.0)), (GeneralizedAlpha(-0.7), (-0.7, -0.7)),
    (GeneralizedAlpha(-0.5), (-0.5, -0.5)), (GeneralizedAlpha(-0.3), (-0.3, -0.3)),
    (GeneralizedAlpha(0.0), (0.0, 0.0))], ids=str)
def test_amplification_at_infinite_frequency(scheme, expected):
    """Generalized-α: double eigenvalue lambda_inf; generalized trapezoidal: 0 and (gamma-1)/gamma."""
    eigenvalues = np.sort(np.linalg.eigvals(amplification(scheme.coefficients(), 1e10)).real)
    np.testing.assert_allclose(eigenvalues, np.sort(expected), atol=1e-4)


def test_registry_names_and_errors():
    names = set(SCHEMES)
    assert {"generalized-alpha", "box", "backward-euler", "generalized-trapezoidal", "factorized",
            "factorized-4", "wave-factorized", "wave-factorized-2", "wave-factorized-3"} == names
    assert not names & set(LUMPED)                                       # one registry, no clashes
    assert set(api.SCHEMES) == names | set(LUMPED)
    assert get_scheme("generalized-alpha", SCHEMES, lambda_inf=-0.7).lambda_inf == -0.7
    with pytest.raises(Exception, match="unknown continuum scheme 'runge-kutta'; valid: backward-euler, box, "
                                        "factorized"):
        get_scheme("runge-kutta", SCHEMES)
