"""The frequency domain under nine motion harmonics at once (kanat.frequency.drag eq. 4: the eight
largest as sinusoids, the rest as a Gaussian) against kanat's time domain.

``examples/lazy_wave.yaml`` (heave 2 m in 10 s, surge 3 m in 60 s; a buoyant section of 0.9 m
diameter moving through the water, so drag matters) with seven small heaves of 0.15 m added at
60/k s (k = 2, 3, 4, 5, 7, 8, 9). The two large harmonics are compared with a joint harmonic fit
of the time domain's last 60 s of 180 s: every node's tension amplitude at 10 s within 6 %
(measured 3.7 %) and at 60 s within 8 % (5.7 %). The Gaussian rule for the whole sum (what more
than four harmonics took before) is 31 % off at 10 s. The small harmonics are not compared: their
frequencies are the 10 s and 60 s motions' combination tones (1/12 = 1/10 - 1/60 Hz, ...), which
the time domain's drag puts there and a linear model cannot.
"""
import warnings

import numpy as np
import pytest

import kanat
from helpers import EXAMPLES, frequency_and_time, harmonic_fit
from kanat.frequency import drag

SMALL = (2, 3, 4, 5, 7, 8, 9)


def nine_harmonics():
    motion = [{"dof": "heave", "amplitude": 2.0, "period": 10.0, "phase_deg": -90},
              {"dof": "surge", "amplitude": 3.0, "period": 60.0, "phase_deg": -90}]
    motion += [{"dof": "heave", "amplitude": 0.15, "period": 60.0 / k, "phase_deg": 40.0 * k} for k in SMALL]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kanat.load_case(EXAMPLES / "lazy_wave.yaml").replace({
            "simulation.method": "frequency", "vessel.motion": motion, "simulation.duration": 180.0})


def gaussian_sum(pairs, amplitudes, sinusoids=None):
    """The stochastic rule for the sum of all the harmonics, one ``D`` at every frequency."""
    covariance = 0.5 * np.einsum("fpr,fpq->prq", amplitudes, amplitudes.conj()).real
    return np.broadcast_to(drag.stochastic(pairs, covariance)[None], (len(amplitudes), *covariance.shape))


@pytest.mark.slow
def test_nine_harmonics_on_the_lazy_wave_against_the_time_domain(monkeypatch):
    case = nine_harmonics()
    fd, td = frequency_and_time(case)
    assert fd.attrs["status"] == "ok" and td.attrs["status"] == "ok"
    omega = fd.frequency.values
    assert len(omega) == 2 + len(SMALL)
    t = td.time.values
    keep = t >= t[-1] - 60.0
    _, reference = harmonic_fit(t[keep], td.tension.values[keep], omega)
    periods = 2 * np.pi / omega
    errors = np.abs(fd.tension_amplitude.values - np.abs(reference)) / np.abs(reference)
    ten, sixty = int(np.argmin(np.abs(periods - 10.0))), int(np.argmin(np.abs(periods - 60.0)))
    assert np.max(errors[ten]) < 0.06
    assert np.max(errors[sixty]) < 0.08
    monkeypatch.setattr(drag, "harmonic_describing", gaussian_sum)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        gaussian = kanat.solve_frequency(case)
    assert np.max(np.abs(gaussian.tension_amplitude.values[ten] - np.abs(reference[ten]))
                  / np.abs(reference[ten])) > 0.2
