"""The generalized-α family (SPEC §2.4, §7 case 2): amplification at infinite frequency and
the order of accuracy in time measured on the cable itself."""
import numpy as np
import pytest

from kanat.continuum.schemes import BackwardEuler, Box, GeneralizedAlpha, GeneralizedTrapezoidal
from kanat.continuum.stepper import step
from kanat.schemes import get_scheme, scheme_classes

from kanat.validation.checks_dynamics import straight_cable


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
    names = set(scheme_classes("continuum"))
    assert {"generalized-alpha", "box", "backward-euler", "generalized-trapezoidal", "factorized",
            "factorized-4", "wave-factorized", "wave-factorized-2", "wave-factorized-3"} <= names
    assert not names & set(scheme_classes("lumped"))                      # one registry, no clashes
    assert get_scheme("generalized-alpha", "continuum", lambda_inf=-0.7).lambda_inf == -0.7
    with pytest.raises(Exception, match="unknown continuum scheme 'runge-kutta'; valid: backward-euler, box, "
                                        "factorized"):
        get_scheme("runge-kutta", "continuum")


class SmoothDrive:
    """First end pulled and swung from rest with velocity ``A (1 - cos(2 pi t / tau)) / 2``."""

    def velocities(self, t):
        ramp = 0.5 * (1.0 - np.cos(2 * np.pi * t / 1.5))
        return (-0.05 * ramp, 0.1 * ramp), (0.0, 0.0)

    def origin(self, t):
        return np.zeros(2)


def driven(scheme, dt, t_end=0.6):
    """A taut cable at rest driven smoothly from t = 0 (zero initial rate is exact); state at ``t_end``.

    Soft (EA = 1e4 N) and coarse (10 segments) so that the step sizes of the test are in the
    asymptotic range for every resolved wave.
    """
    cable, state = straight_cable(50.0, 10, 1000.0, 1e4, 1.0, 0.5)
    coefficients, drive = scheme.coefficients(), SmoothDrive()
    for _ in range(int(round(t_end / dt))):
        state, _ = step(cable, state, dt, coefficients, drive)
    return state.y


SCHEMES = [GeneralizedAlpha(-1.0), GeneralizedAlpha(-0.7), GeneralizedAlpha(-0.5), GeneralizedAlpha(-0.3),
           Box(), BackwardEuler(), GeneralizedTrapezoidal(0.5), GeneralizedTrapezoidal(0.6)]


@pytest.mark.parametrize("scheme", SCHEMES, ids=str)
def test_observed_order_in_time(scheme):
    expected = 2 if isinstance(scheme, GeneralizedTrapezoidal) and scheme.gamma == 0.5 else scheme.order
    steps = np.array([0.004, 0.002, 0.001, 0.0005])
    reference = driven(scheme, 0.0005 / 8)
    scale = np.array([1000.0, 0.1, 0.1, 1e-3])
    errors = [np.max(np.abs(driven(scheme, dt) - reference) / scale) for dt in steps]
    slope = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    assert slope == pytest.approx(expected, abs=0.15)
