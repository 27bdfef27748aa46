"""Most probable maxima: a narrow-band Gaussian record against ``sigma sqrt(2 ln N)`` and
against the maxima of many simulated records; the Weibull and Gumbel fits against samples of
known distributions (scipy.stats)."""
import math

import numpy as np
import pytest
from scipy import stats

from kanat.analysis import extremes
from kanat.errors import KanatError

OMEGA0 = 1.0        # rad/s, centre of the band
BANDWIDTH = 0.1     # relative half-width of the band
COMPONENTS = 64
DT = 0.25           # s


def _frequencies() -> np.ndarray:
    """Evenly spaced over [w0 (1 - b), w0 (1 + b)]: over one beat period 2 pi / dw the
    components are orthogonal, so a record of that length has variance exactly 1."""
    return np.linspace(OMEGA0 * (1 - BANDWIDTH), OMEGA0 * (1 + BANDWIDTH), COMPONENTS)


def _record_length() -> float:
    w = _frequencies()
    return 2.0 * math.pi / (w[1] - w[0])


def narrow_band(rng, t, mean=10.0) -> np.ndarray:
    """A Gaussian process of unit variance (random phases), mean ``mean``."""
    w = _frequencies()
    phase = rng.uniform(0.0, 2.0 * math.pi, w.size)
    return mean + math.sqrt(2.0 / w.size) * np.cos(np.outer(t, w) + phase).sum(axis=1)


def zero_upcrossing_period() -> float:
    """``T_z = 2 pi sqrt(m0 / m2)`` of the discrete spectrum."""
    w = _frequencies()
    return 2.0 * math.pi / math.sqrt(np.mean(w**2))


def test_rayleigh_mpm_of_a_narrow_band_record_is_sigma_sqrt_2_ln_n():
    t = np.arange(0.0, _record_length(), DT)
    x = narrow_band(np.random.default_rng(3), t)
    duration = 10800.0
    n = duration / zero_upcrossing_period()
    result = extremes.mpm(x, t, duration, method="rayleigh")
    assert x.std() == pytest.approx(1.0, rel=2e-3)
    assert result.parameters["N"] == pytest.approx(n, rel=0.02)
    assert result.value == pytest.approx(10.0 + math.sqrt(2.0 * math.log(n)), rel=2e-3)
    assert result.method == "rayleigh" and math.isnan(result.spread)


@pytest.mark.slow
def test_rayleigh_and_gumbel_mpm_agree_with_the_maxima_of_simulated_records():
    """200 records of ~200 cycles: the mode of their maxima (a Gumbel fit, or the sample
    median minus the Gumbel median offset) is the MPM of one record."""
    rng = np.random.default_rng(11)
    t = np.arange(0.0, _record_length(), DT)
    seeds = np.array([narrow_band(rng, t) for _ in range(200)])
    length = t[-1] - t[0]
    rayleigh = extremes.mpm(seeds, t, length, method="rayleigh")
    gumbel = extremes.mpm(seeds, t, length, method="gumbel")
    n = length / zero_upcrossing_period()
    assert rayleigh.value == pytest.approx(10.0 + math.sqrt(2.0 * math.log(n)), rel=0.01)
    # the maxima's mode lies just below the narrow-band estimate (measured 1.9 %): a finite
    # band's peaks are not independent and its largest are thinner than Rayleigh's, so the
    # Rayleigh MPM errs on the safe side
    assert 0.0 < (rayleigh.value - gumbel.value) / rayleigh.value < 0.03
    assert gumbel.parameters["scale"] == pytest.approx(1.0 / math.sqrt(2.0 * math.log(n)), rel=0.25)
    # a storm four times longer: the maximum of four records
    longer = extremes.mpm(seeds, t, 4 * length, method="gumbel")
    assert longer.value - gumbel.value == pytest.approx(gumbel.parameters["scale"] * math.log(4.0), rel=1e-12)
    four = seeds.reshape(50, 4, -1).max(axis=2).max(axis=1)
    assert np.median(four) - 0.3665 * gumbel.parameters["scale"] == pytest.approx(longer.value, rel=0.02)


def test_weibull_fit_recovers_a_known_distribution():
    c, s = 1.7, 2.0
    peaks = stats.weibull_min.rvs(c, scale=s, size=5000, random_state=np.random.default_rng(5))
    shape, scale = extremes.weibull_fit(peaks)
    assert shape == pytest.approx(c, rel=0.03) and scale == pytest.approx(s, rel=0.02)
    # the most probable largest of N: exceedance 1 / N of one peak
    n = 1000.0
    x = extremes.weibull_mpm(shape, scale, n)
    assert stats.weibull_min.sf(x, shape, scale=scale) == pytest.approx(1.0 / n, rel=1e-9)
    assert x == pytest.approx(s * math.log(n) ** (1 / c), rel=0.02)


def test_weibull_mpm_of_a_narrow_band_record_is_rayleigh():
    t = np.arange(0.0, 3 * _record_length(), DT)
    rng = np.random.default_rng(2)
    seeds = np.array([narrow_band(rng, t) for _ in range(3)])
    weibull = extremes.mpm(seeds, t, 10800.0, method="weibull")
    rayleigh = extremes.mpm(seeds, t, 10800.0, method="rayleigh")
    assert weibull.parameters["shape"] == pytest.approx(2.0, rel=0.1)
    assert weibull.value == pytest.approx(rayleigh.value, rel=0.03)
    assert weibull.per_seed.shape == (3,) and weibull.spread > 0


def test_gumbel_fit_recovers_a_known_distribution_and_its_law_for_longer_storms():
    mu, beta = 5.0, 0.5
    size = 3000
    maxima = stats.gumbel_r.rvs(mu, beta, size=size, random_state=np.random.default_rng(0))
    location, scale = extremes.gumbel_fit(maxima)
    # within 3 standard errors of the maximum-likelihood estimates (1.05 beta and 0.78 beta / sqrt(n))
    assert location == pytest.approx(mu, abs=3 * 1.05 * beta / math.sqrt(size))
    assert scale == pytest.approx(beta, abs=3 * 0.78 * beta / math.sqrt(size))
    # the law mpm uses for a storm k times the record: max of k Gumbel(mu, beta) is Gumbel(mu + beta ln k, beta)
    x = np.linspace(4.0, 9.0, 11)
    k = 6.0
    shifted = stats.gumbel_r.cdf(x, mu + beta * math.log(k), beta)
    np.testing.assert_allclose(stats.gumbel_r.cdf(x, mu, beta) ** k, shifted, rtol=1e-12)
    # through mpm: records whose maxima are these samples (a flat record with one spike each)
    t = np.arange(0.0, 101.0)
    records = np.zeros((60, t.size))
    records[:, 50] = maxima[:60]
    result = extremes.mpm(records, t, 100.0 * k, method="gumbel")
    loc60, scale60 = stats.gumbel_r.fit(maxima[:60])
    assert result.value == pytest.approx(loc60 + scale60 * math.log(k), rel=1e-9)
    assert result.spread == pytest.approx(math.pi * scale60 / math.sqrt(6.0), rel=1e-9)


def test_bad_inputs_say_what_to_do():
    t = np.arange(0.0, 100.0, 0.5)
    x = np.sin(t)
    with pytest.raises(KanatError, match="rayleigh, weibull, gumbel"):
        extremes.mpm(x, t, 1000.0, method="frechet")
    with pytest.raises(KanatError, match="at least 3 seeds"):
        extremes.mpm(np.vstack([x, x]), t, 1000.0, method="gumbel")
    with pytest.raises(KanatError, match="positive"):
        extremes.mpm(x, t, 0.0)
    with pytest.raises(KanatError, match="shape"):
        extremes.mpm(x[:-1], t, 1000.0)
    assert extremes.mpm(np.full(t.size, 3.0), t, 1000.0).value == 3.0
